#!/usr/bin/env python3
"""Cost and error of meshPoisson's pair corrections, with and without them.

The lattice correction on uniform cubic meshes, the patch pair correction
on others (both under latticeCorrectionSources):
- the flagship's duct (tutorials/chargedDuct's mesh, 240 x 8 x 8 cubic
  cells, radius 6 mm = 2.4 cells) with 20000 random charges: a dense cloud,
  about 600 sources within 2R of each charge, so no charge is corrected and
  the correction costs its count of sources only;
- a sparse cloud: 200 random charges in the grounded unit box, h = 1/32,
  radius 2 cells (a few sources within 2R of each), where most charges
  are corrected; its rms force error against the exact image solution
  (tests/tools/groundedBox.py) with and without;
- the same on a curved mesh: 200 random charges in the grounded O-grid pipe
  of curvedCavities.py (n = 14, radius 2 mean cells), the patch pair
  correction (one patch solve per corrected charge; made here for every
  charge that needs it, patchPairCorrectionCharges 1000, where the default
  16 would skip it), against the exact grounded cylinder
  (tests/tools/groundedCylinder.py).
The runs with and without alternate (rounds in turns on a shared machine);
printed: the time per step (a solve and the near field) of each pair and
the median ratio with / without.

    latticeCost.py [--rounds 3] [--steps 10] [--work DIR] [--only pipe]
"""
import argparse
import os
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(HERE, "..", "..", "..", "tests", "tools"))
from farFieldCase import FarFieldCase  # noqa: E402
from ductRungs import BOUNDARY, PHI, L as DUCT, MESH  # noqa: E402
from study import step_time  # noqa: E402
import groundedBox as gb  # noqa: E402
import curvedCavities as cc  # noqa: E402


def scenes():
    rng = np.random.default_rng(5)
    duct = np.asarray(DUCT)
    xd = 1e-3 + (duct - 2e-3)*rng.random((20000, 3))
    qd = 1e-14*(1 + rng.random(20000))
    xb = 0.05 + 0.9*rng.random((200, 3))
    qb = 1e-9*(2*rng.random(200) - 1)
    # The pipe: radius 1, period 2 along z; charges within 0.85 of the axis
    u = rng.normal(size=(200, 2))
    u *= (0.85*np.sqrt(rng.random(200))/np.linalg.norm(u, axis=1))[:, None]
    xp = np.column_stack([u, 2*rng.random(200)])
    qp = 1e-9*(2*rng.random(200) - 1)
    return [
        ("flagship duct, 20000 charges, R = 2.4 cells", xd, qd, DUCT, MESH,
         "radius 6e-3;", dict(boundary=BOUNDARY, Phi=PHI), None),
        ("unit box, 200 charges, R = 2 cells", xb, qb, 1.0, 32,
         "radius 0.0625;", {}, lambda x, q: gb.field(x, q, 1.0)),
        ("O-grid pipe, 200 charges, R = 2 mean cells", xp, qp, 1.0, 14,
         "radius 0.125; patchPairCorrectionCharges 1000;",
         dict(blockMesh=cc.pipe_blockmesh(1.0, 2.0, 14)),
         lambda x, q: cc.cylinder_field(x, q, 1.0, 2.0)),
    ]


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--rounds", type=int, default=3)
    ap.add_argument("--steps", type=int, default=10)
    ap.add_argument("--work", default=os.path.join(HERE, "runs", "latticeCost"))
    ap.add_argument("--only", default="", help="the scenes whose name holds this")
    a = ap.parse_args()
    for name, x, q, Lx, n, coeffs, kw, exact in scenes():
        if a.only not in name:
            continue
        print(name, flush=True)
        ratios, E = [], {}
        for r in range(a.rounds):
            t = {}
            for label, extra in (("without", "latticeCorrectionSources 0;"),
                                 ("with", "")):
                c = FarFieldCase(f"{a.work}/{name.split(',')[0].replace(' ', '_')}_{label}",
                                 x, q, Lx, n, "meshPoisson", coeffs + extra,
                                 steps=a.steps, **kw)
                c.run()
                t[label] = step_time(c.log(), a.steps)
                E[label] = c.fields()[0]
            ratios.append(t["with"]/t["without"])
            print(f"  round {r}: time per step without {t['without']:.3g} s, "
                  f"with {t['with']:.3g} s, ratio {ratios[-1]:.2f}", flush=True)
        print(f"  median ratio with / without: {np.median(ratios):.2f}", flush=True)
        if exact:
            ref = exact(x, q)
            for label in ("without", "with"):
                err = np.sqrt(np.mean(np.sum((E[label] - ref)**2, axis=1))
                              / np.mean(np.sum(ref**2, axis=1)))
                worst = np.max(np.linalg.norm(E[label] - ref, axis=1)
                               / np.linalg.norm(ref, axis=1))
                print(f"  {label} the pair correction: rms force error "
                      f"{err:.2e}, largest {worst:.2e}", flush=True)


if __name__ == "__main__":
    main()
