#!/usr/bin/env python3
"""Compare two lagrangian clouds written by OpenFOAM (ASCII), particle by
particle: e.g. a serial run and the reconstructed parallel run of one case.

    compareClouds.py <timeDirA> <timeDirB> [--cloud cloud] [--tol 1e-10]

Particles are matched by position (nearest neighbour, which must be a
one-to-one map); the counts must agree. Checks, printed as PASS:/FAIL:
lines: particle count, max |xA - xB| / max|xA| (positions, Cartesian
'positions' file), max |UA - UB| / max|UA|, charges identical; with
--rotation also the orientations (max difference of the quaternions, sign
fixed) and the angular momenta (relative).
"""
import argparse
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "etc", "python"))
from foamLagrangian import read_field, read_positions  # noqa: E402


def load(time_dir, cloud):
    d = os.path.join(time_dir, "lagrangian", cloud)
    x = read_positions(os.path.join(d, "positions"))
    U = read_field(os.path.join(d, "U")).reshape(-1, 3)
    q = read_field(os.path.join(d, "q"))
    return x, U, q


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("a")
    ap.add_argument("b")
    ap.add_argument("--cloud", default="cloud")
    ap.add_argument("--tol", type=float, default=1e-10)
    ap.add_argument("--name", default="clouds")
    ap.add_argument("--rotation", action="store_true",
                    help="also compare orientations and angular momenta")
    ap.add_argument("--qtol", type=float, default=0,
                    help="relative tolerance of the charges (default: identical)")
    args = ap.parse_args()

    xa, Ua, qa = load(args.a, args.cloud)
    xb, Ub, qb = load(args.b, args.cloud)
    ok = True

    def check(name, good, detail):
        nonlocal ok
        ok &= bool(good)
        print(f"{'PASS' if good else 'FAIL'}: {args.name}.{name} {detail}")

    check("count", len(xa) == len(xb) and len(xa) > 0,
          f"({len(xa)} vs {len(xb)} particles)")
    if len(xa) != len(xb) or len(xa) == 0:
        return 1

    dist = np.linalg.norm(xa[:, None, :] - xb[None, :, :], axis=2)
    match = dist.argmin(axis=1)
    check("matching", len(set(match)) == len(match), "(one-to-one by position)")

    scale_x = np.abs(xa).max()
    ex = np.linalg.norm(xa - xb[match], axis=1).max()/scale_x
    check("positions", ex <= args.tol, f"(max rel. difference {ex:.3e}, tol {args.tol:g})")

    scale_U = np.linalg.norm(Ua, axis=1).max()
    eU = np.linalg.norm(Ua - Ub[match], axis=1).max()/scale_U if scale_U > 0 else 0.0
    check("velocities", eU <= args.tol, f"(max rel. difference {eU:.3e}, tol {args.tol:g})")

    if args.qtol == 0:
        check("charges", np.array_equal(qa, qb[match]),
              f"(total {qa.sum():.6e} vs {qb.sum():.6e} C)")
    else:
        scale_q = np.abs(qa).max()
        eq = np.abs(qa - qb[match]).max()/scale_q if scale_q > 0 else 0.0
        check("charges", eq <= args.qtol,
              f"(max rel. difference {eq:.3e}, tol {args.qtol:g})")

    if args.rotation:
        def rot(time_dir):
            d = os.path.join(time_dir, "lagrangian", args.cloud)
            eps = read_field(os.path.join(d, "orientationEps")).reshape(-1, 3)
            eta = read_field(os.path.join(d, "orientationEta")).reshape(-1, 1)
            L = read_field(os.path.join(d, "angularMomentum")).reshape(-1, 3)
            o = np.hstack([eta, eps])
            return o*np.where(o[:, :1] < 0, -1, 1), L
        oa, La = rot(args.a)
        ob, Lb = rot(args.b)
        eo = np.abs(oa - ob[match]).max()
        check("orientations", eo <= args.tol,
              f"(max quaternion difference {eo:.3e}, tol {args.tol:g})")
        scale_L = np.linalg.norm(La, axis=1).max()
        eL = np.linalg.norm(La - Lb[match], axis=1).max()/scale_L if scale_L > 0 else 0.0
        check("angularMomenta", eL <= args.tol and scale_L > 0,
              f"(max rel. difference {eL:.3e}, tol {args.tol:g})")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
