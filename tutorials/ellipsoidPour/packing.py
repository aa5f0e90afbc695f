#!/usr/bin/env python3
"""Settled bed of the ellipsoidPour tutorial: particles kept, finite state,
packing fraction and coordination number.

    packing.py <caseDir> [--expect N]

Packing fraction: Monte Carlo estimate of the solid fraction in the core of
the bed (1 mm from the side walls and the floor, 2 mm below the highest
particle top), points tested against every ellipsoid (body frame:
sum (x_i/a_i)^2 <= 1). Coordination number: contacts per particle from the
last 'Coordination number' line of the solver log. Prints PASS/FAIL lines.
"""
import argparse
import glob
import os
import re
import sys

import numpy as np

# etc/python of the project (on PYTHONPATH after etc/bashrc)
sys.path.insert(0, os.path.join(os.environ.get("CHARGEDFOAM_DIR", ""), "etc", "python"))
from ellipsoids import rotation  # noqa: E402
from foamLagrangian import read_field, read_positions  # noqa: E402


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("case")
    ap.add_argument("--expect", type=int)
    ap.add_argument("--samples", type=int, default=200000)
    ap.add_argument("--state-only", action="store_true",
                    help="check count and state only, not the settled bed")
    args = ap.parse_args()

    times = sorted((d for d in os.listdir(args.case) if re.fullmatch(r"[0-9.e-]+", d) and d != "0"), key=float)
    last = os.path.join(args.case, times[-1])
    d = os.path.join(last, "lagrangian", "cloud")
    x = read_positions(os.path.join(d, "positions"))
    s = read_field(os.path.join(d, "semiAxes")).reshape(-1, 3)
    eps = read_field(os.path.join(d, "orientationEps")).reshape(-1, 3)
    eta = read_field(os.path.join(d, "orientationEta"))
    U = read_field(os.path.join(d, "U")).reshape(-1, 3)
    n = len(x)
    ok = True

    def check(name, good, detail):
        nonlocal ok
        ok &= bool(good)
        print(f"{'PASS' if good else 'FAIL'}: ellipsoidPour.{name} {detail}")

    if args.expect is not None:
        check("count", n == args.expect, f"({n} particles at t = {times[-1]} s, {args.expect} injected)")
    finite = all(np.isfinite(a).all() for a in (x, s, eps, eta, U))
    check("finite", finite, "(positions, velocities, orientations all finite)")
    inside = ((x >= 0).all(1) & (x[:, :2] <= 12e-3).all(1) & (x[:, 2] <= 40e-3)).all()
    check("inBox", inside, "(every centre inside the box)")
    qnorm = np.abs(eta**2 + (eps**2).sum(1) - 1).max()
    check("unitQuaternions", qnorm < 1e-12, f"(max ||q| - 1| = {qnorm:.1e})")

    if args.state_only:
        return 0 if ok else 1

    R = rotation(eta, *eps.T)
    top = (x[:, 2] + s.max(1)).max()
    lo = np.array([1e-3, 1e-3, 1e-3])
    hi = np.array([11e-3, 11e-3, top - 2e-3])
    rng = np.random.default_rng(0)
    pts = lo + (hi - lo)*rng.random((args.samples, 3))
    solid = np.zeros(len(pts), bool)
    for i in range(n):
        b = (pts - x[i]) @ R[i]                   # body coordinates
        solid |= ((b/s[i])**2).sum(1) <= 1
    phi = solid.mean()

    log = open(os.path.join(args.case, "log.chargedParticleFoam")).read() if os.path.exists(os.path.join(args.case, "log.chargedParticleFoam")) else open(os.path.join(args.case, "log.solver")).read()
    z = re.findall(r"Coordination number\s*=\s*(\S+)", log)
    coord = float(z[-1]) if z else float("nan")
    vmax = np.linalg.norm(U, axis=1).max()

    print(f"particles {n}, bed top {top*1e3:.2f} mm, core {lo*1e3} - {hi*1e3} mm")
    print(f"packing fraction (core, {args.samples} samples) = {phi:.3f} +- {np.sqrt(phi*(1 - phi)/args.samples):.3f}")
    print(f"coordination number = {coord:.2f}, max |U| = {vmax:.2e} m/s")
    check("packingFraction", 0.4 < phi < 0.8, f"({phi:.3f}; random packings of aspect-ratio-2 ellipsoids: 0.6-0.7)")
    check("coordination", coord > 2, f"({coord:.2f} contacts per particle)")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
