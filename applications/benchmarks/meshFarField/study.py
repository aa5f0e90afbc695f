#!/usr/bin/env python3
"""Error and cost of the electrostatics rungs in a grounded box.

N random point charges of both signs in a grounded unit box. Reference: the
exact image solution (tests/tools/groundedBox.py, Ewald sum of the images).
For each rung (none, cutoffCoulomb, directCoulomb, imageCoulomb, meshPoisson
with Rasera's Eq. 31 correction and with the shaped correction at several
meshes and radii) the case runs chargedParticleFoam for a few steps of
resting charges; printed: rms and 95th-percentile relative force error vs
the reference, and the wall time per step (one force evaluation) relative
to directCoulomb's, measured in the same run.

    study.py [--n N] [--steps S] [--quick] [--out table.md] [--work DIR]
"""
import argparse
import os
import re
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(HERE, "..", "..", "..", "tests", "tools"))
from farFieldCase import FarFieldCase  # noqa: E402
import groundedBox as gb  # noqa: E402


def step_time(log, steps):
    t = [float(v) for v in re.findall(r"ExecutionTime = ([0-9.eE+-]+) s", log)]
    if len(t) < 2:
        return float("nan")
    return (t[-1] - t[0])/(len(t) - 1)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--n", type=int, default=2000, help="number of charges")
    ap.add_argument("--steps", type=int, default=6)
    ap.add_argument("--quick", action="store_true", help="fewer rungs")
    ap.add_argument("--out", default=None, help="write the table here")
    ap.add_argument("--work", default=os.path.join(HERE, "runs"))
    a = ap.parse_args()

    rng = np.random.default_rng(7)
    x = 0.02 + 0.96*rng.random((a.n, 3))
    q = 1e-12*(2*rng.random(a.n) - 1)
    print(f"{a.n} charges in a grounded 1 m box; exact reference ...", flush=True)
    ref = gb.field(x, q, 1.0)
    refScale = np.sqrt(np.mean(np.sum(ref**2, axis=1)))

    rungs = [
        ("none", "none", "", 8),
        ("cutoffCoulomb rCut 0.1", "cutoffCoulomb", "rCut 0.1;", 8),
        ("cutoffCoulomb rCut 0.25", "cutoffCoulomb", "rCut 0.25;", 8),
        ("directCoulomb (no walls)", "directCoulomb", "", 8),
        ("imageCoulomb rCut 0.25", "imageCoulomb", "rCut 0.25;", 8),
        ("imageCoulomb rCut 1", "imageCoulomb", "rCut 1;", 8),
        ("meshPoisson cellCentroid h 1/32, rCut 0.1", "meshPoisson",
         "correction cellCentroid; rCut 0.1;", 32),
        ("meshPoisson shaped h 1/16, R 0.1", "meshPoisson", "radius 0.1;", 16),
        ("meshPoisson shaped h 1/32, R 0.1", "meshPoisson", "radius 0.1;", 32),
        ("meshPoisson shaped h 1/32, R 0.2", "meshPoisson", "radius 0.2;", 32),
        ("meshPoisson shaped h 1/64, R 0.1", "meshPoisson", "radius 0.1;", 64),
    ]
    if a.quick:
        rungs = [r for r in rungs if "1/64" not in r[0]]

    rows = []
    tDirect = None
    for label, model, coeffs, n in rungs:
        name = re.sub(r"[^A-Za-z0-9]+", "_", label)
        c = FarFieldCase(os.path.join(a.work, name), x, q, 1.0, n, model,
                         coeffs, steps=a.steps)
        try:
            c.run()
        except RuntimeError as e:
            print(f"  {label}: {e}", flush=True)
            continue
        E = c.fields()[0]
        d = np.linalg.norm(E - ref, axis=1)
        rel = d/np.maximum(np.linalg.norm(ref, axis=1), 1e-300)
        t = step_time(c.log(), a.steps)
        if model == "directCoulomb":
            tDirect = t
        rows.append((label, n, np.sqrt(np.mean(d**2))/refScale,
                     np.percentile(rel, 95), t))
        print(f"  {label}: rms {rows[-1][2]:.2e}, p95 {rows[-1][3]:.2e}, "
              f"{t*1e3:.1f} ms/step", flush=True)

    lines = [
        f"{a.n} charges in a grounded 1 m box (`applications/benchmarks/meshFarField/"
        f"study.py --n {a.n}`); force error vs the exact image solution "
        "(rms over charges relative to the rms field, and the 95th "
        "percentile of the per-charge relative error); time per step "
        "(one force evaluation, chargedParticleFoam) relative to "
        "directCoulomb in the same run.",
        "",
        "| rung | mesh cells | rms error | 95 % rel. error | ms/step "
        "| time / directCoulomb |",
        "|---|---|---|---|---|---|",
    ]
    for label, n, rms, p95, t in rows:
        ratio = t/tDirect if tDirect else float("nan")
        lines.append(f"| {label} | {n}^3 | {rms:.2e} | {p95:.2e} | "
                     f"{t*1e3:.1f} | {ratio:.2f} |")
    text = "\n".join(lines)
    print("\n" + text)
    if a.out:
        with open(a.out, "w") as f:
            f.write(text + "\n")


if __name__ == "__main__":
    main()
