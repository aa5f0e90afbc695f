#!/usr/bin/env python3
"""Error and cost of the electrostatics rungs on the flagship scene.

The charged parcels of tutorials/chargedDuct at one time (positions and
charges of a finished run) in the same grounded duct (walls at 0 V, open
ends insulating). Each rung computes the field at the parcels (chargedParticle-
Foam, resting point charges, a few steps); the reference is the exact field
of the charges in that duct (tests/tools/groundedBox.py with insulating ends:
the Ewald sum of the image lattice, odd across the grounded sides, even
across the ends), independent of every rung. Printed: rms force error
relative to the rms reference field, and the time per step relative to
directCoulomb in the same run.

    ductRungs.py [--case tutorials/chargedDuct] [--time latest] [--steps 20]
                 [--out table.md] [--work DIR]
"""
import argparse
import os
import re
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
TOP = os.path.abspath(os.path.join(HERE, "..", "..", ".."))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(TOP, "etc", "python"))
sys.path.insert(0, os.path.join(TOP, "tests", "tools"))
from farFieldCase import FarFieldCase  # noqa: E402
import groundedBox as gb  # noqa: E402
from foamLagrangian import read_field, read_positions  # noqa: E402
from study import step_time  # noqa: E402

L = (0.6, 0.02, 0.02)
MESH = (240, 8, 8)
BOUNDARY = """
    inlet  { type patch; faces ((0 4 7 3)); }
    outlet { type patch; faces ((1 2 6 5)); }
    walls  { type wall; faces ((0 1 5 4) (3 7 6 2) (0 3 2 1) (4 5 6 7)); }"""
PHI = """    walls  { type fixedValue; value uniform 0; }
    inlet  { type zeroGradient; }
    outlet { type zeroGradient; }"""


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--case", default=os.path.join(TOP, "tutorials",
                                                   "chargedDuct"))
    ap.add_argument("--time", default="latest")
    ap.add_argument("--steps", type=int, default=20)
    ap.add_argument("--out", default=None)
    ap.add_argument("--work", default=os.path.join(HERE, "runs", "duct"))
    a = ap.parse_args()

    if a.time == "latest":
        ts = [d for d in os.listdir(a.case)
              if re.fullmatch(r"[0-9.eE+-]+", d) and float(d) > 0
              and os.path.isdir(os.path.join(a.case, d, "lagrangian"))]
        if not ts:
            sys.exit(f"ductRungs: no lagrangian time in {a.case}: run its "
                     "Allrun first")
        a.time = max(ts, key=float)
    c = os.path.join(a.case, a.time, "lagrangian", "cloud")
    x = read_positions(os.path.join(c, "positions"))
    q = read_field(os.path.join(c, "q"))
    print(f"{len(x)} parcels of {a.case} at t = {a.time} s, total charge "
          f"{q.sum():.3e} C", flush=True)

    fine = tuple(2*m for m in MESH)
    # Grounded sides (y, z), insulating ends (x): the inlet and outlet
    # patches are zeroGradient in PHI
    ref = gb.field(x, q, L, parity=(1, -1, -1))
    scale = np.sqrt(np.mean(np.sum(ref**2, axis=1)))
    print(f"  exact duct field: rms {scale:.3e} V/m", flush=True)
    rungs = [
        ("none", "none", "", MESH),
        ("cutoffCoulomb rCut 6 mm", "cutoffCoulomb", "rCut 6e-3;", MESH),
        ("cutoffCoulomb rCut 20 mm", "cutoffCoulomb", "rCut 2e-2;", MESH),
        ("imageCoulomb rCut 6 mm", "imageCoulomb", "rCut 6e-3;", MESH),
        ("imageCoulomb rCut 20 mm", "imageCoulomb", "rCut 2e-2;", MESH),
        ("directCoulomb (no walls)", "directCoulomb", "", MESH),
        ("meshPoisson cellCentroid (Eq. 31), rCut 6 mm", "meshPoisson",
         "correction cellCentroid; rCut 6e-3;", MESH),
        ("meshPoisson shaped R 6 mm", "meshPoisson",
         "radius 6e-3;", MESH),
        ("meshPoisson shaped R 6 mm, solveInterval 20 (tutorial)", "meshPoisson",
         "radius 6e-3; solveInterval 20;", MESH),
        ("meshPoisson 480x16x16, R 6 mm", "meshPoisson", "radius 6e-3;",
         fine),
        ("meshPoisson 480x16x16, R 7.5 mm", "meshPoisson",
         "radius 7.5e-3;", fine),
    ]

    rows = []
    tDirect = None
    for label, model, coeffs, n in rungs:
        name = re.sub(r"[^A-Za-z0-9]+", "_", label)[:60]
        case = FarFieldCase(os.path.join(a.work, name), x, q, L, n, model,
                            coeffs, steps=a.steps, boundary=BOUNDARY, Phi=PHI)
        try:
            case.run()
        except RuntimeError as e:
            print(f"  {label}: {e}", flush=True)
            continue
        E = case.fields()[0]
        t = step_time(case.log(), a.steps)
        if model == "directCoulomb":
            tDirect = t
        err = np.sqrt(np.mean(np.sum((E - ref)**2, axis=1)))/scale
        rows.append((label, n, err, t))
        print(f"  {label}: error {err:.2e}, {t*1e3:.1f} ms/step", flush=True)

    lines = [
        f"Flagship scene: the {len(x)} charged parcels of tutorials/"
        f"chargedDuct at t = {a.time} s in the grounded duct "
        f"(`applications/benchmarks/meshFarField/ductRungs.py`); rms force "
        "error against the exact field in the duct (image lattice, Ewald), "
        "relative to its rms; time per step (one "
        "force evaluation, chargedParticleFoam, serial) relative to "
        "directCoulomb in the same run.",
        "",
        "| rung | mesh | rms error | ms/step | time / directCoulomb |",
        "|---|---|---|---|---|",
    ]
    for label, n, err, t in rows:
        ratio = t/tDirect if tDirect else float("nan")
        e = f"{err:.2e}"
        lines.append(f"| {label} | {n[0]}x{n[1]}x{n[2]} | {e} | "
                     f"{t*1e3:.1f} | {ratio:.2f} |")
    text = "\n".join(lines)
    print("\n" + text)
    if a.out:
        with open(a.out, "w") as f:
            f.write(text + "\n")


if __name__ == "__main__":
    main()
