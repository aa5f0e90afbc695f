#!/usr/bin/env python3
"""Ellipsoids (aspect ratio 3) dropped on the floor in four orientations:
energy bookkeeping and final resting state.

Energy: E(t) = kinetic (translation + rotation) + potential (gravity) +
elastic energy stored in the contacts + energy dissipated by the contacts
(the contact model's dashpots, no-tension cut and friction, accumulated
in the solver) must stay at its initial value; the closure error is
reported relative to the dissipated energy. It is a time-discretisation
error of the contact events (first order: a contact starts inside a step).

Rest: every ellipsoid ends on its flat side: long axis (body x)
horizontal within 2 degrees, centre at the minor semi-axis above the floor
within 2 % of it, at rest (|U| < 1e-3 m/s).

    drop.py <caseDir> [--tol 0.05] [--plot drop.png]
"""
import argparse
import os
import re
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.environ.get("CHARGEDFOAM_DIR", ""), "etc", "python"))
from foamLagrangian import read_field, read_positions  # noqa: E402


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("case")
    ap.add_argument("--tol", type=float, default=0.05)
    ap.add_argument("--plot")
    args = ap.parse_args()
    ok = True

    def check(name, good, detail):
        nonlocal ok
        ok &= bool(good)
        print(f"{'PASS' if good else 'FAIL'}: ellipsoidDrop.{name} {detail}")

    log = open(os.path.join(args.case, "log.chargedParticleFoam")).read()

    def f(key):
        return np.array([float(x) for x in re.findall(key + r"\s*=\s*(\S+)", log)])
    t = np.array([float(x) for x in re.findall(r"^Time = (\S+)", log, re.M)])
    ke = f("Linear kinetic energy") + f(r"Rotational kinetic energy \(ellipsoids\)")
    pe, el, d = f(r"Potential energy \(gravity\)"), f("Contact elastic energy"), f("Contact dissipated energy")
    E = ke + pe + el + d
    closure = np.abs(E - E[0]).max()/d[-1]
    print(f"initial energy {E[0]:.6e} J, dissipated {d[-1]:.6e} J, final mechanical {ke[-1] + pe[-1] + el[-1]:.6e} J")
    check("energyClosure", closure < args.tol,
          f"(max |E(t) - E(0)| = {closure:.2%} of the dissipated energy, tol {args.tol:.0%})")
    check("dissipationMonotone", (np.diff(d) >= -1e-12*d[-1]).all(), "(dissipated energy never decreases)")

    times = sorted((x for x in os.listdir(args.case) if re.fullmatch(r"[0-9.e-]+", x) and x != "0"), key=float)
    c = os.path.join(args.case, times[-1], "lagrangian", "cloud")
    x = read_positions(os.path.join(c, "positions"))
    s = read_field(os.path.join(c, "semiAxes")).reshape(-1, 3)
    eps = read_field(os.path.join(c, "orientationEps")).reshape(-1, 3)
    eta = read_field(os.path.join(c, "orientationEta"))
    U = read_field(os.path.join(c, "U")).reshape(-1, 3)
    order = np.argsort(x[:, 0])
    for i in order:
        w, (a, b, cc) = eta[i], eps[i]
        axis = np.array([1 - 2*(b*b + cc*cc), 2*(a*b + w*cc), 2*(a*cc - w*b)])   # R e_x
        tilt = np.degrees(np.arcsin(min(1.0, abs(axis[2]))))
        zrel = x[i, 2]/s[i].min() - 1
        good = tilt < 2 and abs(zrel) < 0.02 and np.linalg.norm(U[i]) < 1e-3
        check(f"restFlat.x{x[i, 0]*1e3:.0f}mm", good,
              f"(long axis {tilt:.2f} deg from horizontal, centre height/minor semi-axis - 1 = {zrel:+.2e}, |U| = {np.linalg.norm(U[i]):.1e} m/s)")

    if args.plot:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        fig, ax = plt.subplots(figsize=(7, 4.5))
        ax.plot(t, ke, label="kinetic")
        ax.plot(t, pe - pe[-1], label="potential (above rest)")
        ax.plot(t, d, label="dissipated by contacts")
        ax.plot(t, E - pe[-1], "k--", label="total (incl. elastic)")
        ax.set_xlabel("time [s]"); ax.set_ylabel("energy [J]"); ax.grid(alpha=0.3); ax.legend()
        ax.set_title("Ellipsoids (aspect ratio 3) dropped on a wall: energy bookkeeping")
        fig.tight_layout(); fig.savefig(args.plot, dpi=110)
        print(f"wrote {args.plot}")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
