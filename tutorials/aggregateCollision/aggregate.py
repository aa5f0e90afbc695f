#!/usr/bin/env python3
"""Outcomes, plots and cost of the particle-aggregate collisions (Ruan 2022
Section 3.3.3, Figs. 12-15) run by Allrun: for each incident velocity v0
and electrostatics rung (point charges, induced dipoles, BEM clusters).

From each run's particle history (postProcessing/.../particleHistory.dat)
and log: the x velocities, the overlaps of the three pairs (outer shells,
semi-axes + deltaBl; ellipsoidGap.py, independent of the solver's contact
detection) and the electrostatic energy (the log's books). The outcome at
the end of a run:

    fragmentation   1 and 2 unbound: more than 0.1 c apart, and their
                    relative translational plus own rotational kinetic
                    energy exceeds the point-charge binding k q^2/r (the
                    dipole terms decay as r^-4; spin may turn into
                    separation in a later contact)
    rebound         1 and 2 bound, 3 more than 0.1 c from both and moving
                    away from their centre of mass
    sticking        every pair within 0.05 c (in contact or nearly)
    undecided       none of these

Usage: aggregate.py <run> ... [--plot prefix] [--expect rung:v0:outcome ...]
Runs are named <rung>-v<v0>. Prints a table; with --expect, PASS/FAIL
lines for the expected outcomes.
"""
import argparse
import os
import re
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.environ.get("CHARGEDFOAM_DIR", ""), "etc", "python"))
import ellipsoidGap as eg  # noqa: E402
from ellipsoids import mass, principal_moments, rotation  # noqa: E402
from foamLagrangian import read_particle_history  # noqa: E402

C = 100e-6                      # semi-minor axis [m]
SEMI = np.array([200e-6, C, C])
DBL = 5e-6                      # buffer layer [m]
RHO = 2500.0                    # [kg/m3]
KC = 8.9875517923e9             # 1/(4 pi eps0) [N m^2/C^2]
RUNGS = {"pointCharges": "point charges", "dipoles": "induced dipoles",
         "bem": "BEM clusters"}


def read_history(run):
    data, col = read_particle_history(run)
    parts = [data[data[:, 2] == k] for k in range(3)]
    n = min(len(p) for p in parts)
    return parts[0][:n, 0], [p[:n] for p in parts], col


def read_log(run):
    """Times, electrostatic energy, the final ExecutionTime and the number
    of time steps of the log."""
    t, U, exe, steps = [], [], 0.0, 0
    now = None
    for line in open(os.path.join(run, "log.chargedParticleFoam")):
        if line.startswith("Time = "):
            now = float(line.split()[2])
            steps += 1
        elif "Electrostatic energy" in line and now is not None:
            t.append(now)
            U.append(float(line.split("=")[1]))
        elif line.startswith("ExecutionTime"):
            exe = float(line.split()[2])
    return np.array(t), np.array(U), exe, steps


def pose(p, col, k):
    R = rotation(*(p[k, col[c]] for c in ("qw", "qx", "qy", "qz")))
    x = np.array([p[k, col[c]] for c in ("x", "y", "z")])
    return x, R


def gaps(parts, col, k):
    """Outer-shell gaps of the pairs (1,2), (1,3), (2,3) at sample k."""
    s = SEMI + DBL
    poses = [pose(p, col, k) for p in parts]
    out = []
    for a, b in ((0, 1), (0, 2), (1, 2)):
        out.append(eg.gap(poses[a][0], poses[a][1], s, poses[b][0], poses[b][1], s))
    return np.array(out)


def pair_energy(parts, col):
    """Energy of the pair (1, 2) at the end: relative translational and own
    rotational kinetic energy plus the point charges' Coulomb energy."""
    m = mass(SEMI, RHO)
    inertia = principal_moments(SEMI, m)
    x, v, rot, q = [], [], 0.0, []
    for p in parts[:2]:
        x.append(np.array([p[-1, col[c]] for c in ("x", "y", "z")]))
        v.append(np.array([p[-1, col[c]] for c in ("Ux", "Uy", "Uz")]))
        q.append(p[-1, col["q"]])
        R = pose(p, col, -1)[1]
        w = R.T @ np.array([p[-1, col[c]] for c in ("omegax", "omegay", "omegaz")])
        rot += 0.5*(inertia*w*w).sum()
    return (0.25*m*((v[0] - v[1])**2).sum() + rot
            + KC*q[0]*q[1]/np.linalg.norm(x[0] - x[1]))


def leaving(parts, col):
    """Does 3 move away from the centre of mass of 1 and 2 at the end?"""
    x = [np.array([p[-1, col[c]] for c in ("x", "y", "z")]) for p in parts]
    v = [np.array([p[-1, col[c]] for c in ("Ux", "Uy", "Uz")]) for p in parts]
    return np.dot(v[2] - 0.5*(v[0] + v[1]), x[2] - 0.5*(x[0] + x[1])) > 0


def analyse(run):
    t, parts, col = read_history(run)
    step = max(1, len(t)//400)          # ~400 samples for the plots
    ks = list(range(0, len(t), step))
    if ks[-1] != len(t) - 1:
        ks.append(len(t) - 1)
    g = np.array([gaps(parts, col, k) for k in ks])
    tU, U, exe, steps = read_log(run)
    # Outcome from the last sample
    g1 = g[-1]
    if g1[0] > 0.1*C and pair_energy(parts, col) > 0:
        outcome = "fragmentation"
    elif min(g1[1], g1[2]) > 0.1*C and leaving(parts, col):
        outcome = "rebound"
    elif (g1 < 0.05*C).all():
        outcome = "sticking"
    else:
        outcome = "undecided"
    return dict(t=t, tk=t[ks], parts=parts, col=col, gaps=g, tU=tU, U=U, exe=exe,
                outcome=outcome, maxOverlap=max(0.0, -g.min()), steps=steps)


def name_of(run):
    m = re.match(r"(\w+)-v([0-9.]+)$", os.path.basename(os.path.normpath(run)))
    return m.group(1), float(m.group(2))


def plot(results, prefix):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    for v0 in sorted({v for (_, v) in results}):
        rungs = [r for r in RUNGS if (r, v0) in results]
        fig, ax = plt.subplots(3, len(rungs), figsize=(4.2*len(rungs), 8.5),
                               sharex=True, squeeze=False)
        for j, r in enumerate(rungs):
            res = results[(r, v0)]
            tms = res["t"]*1e3
            for k, (p, c) in enumerate(zip(res["parts"], ("tab:red", "tab:blue", "tab:cyan"))):
                ax[0, j].plot(tms, p[:, res["col"]["Ux"]], color=c, label=f"particle {k + 1}")
            for k, (lab, c) in enumerate(zip(("1-2", "1-3", "2-3"),
                                             ("tab:orange", "tab:green", "tab:purple"))):
                ax[1, j].plot(res["tk"]*1e3, np.maximum(-res["gaps"][:, k], 0)*1e6, color=c,
                              label=f"pair {lab}")
            ax[2, j].plot(res["tU"]*1e3, res["U"]*1e12, color="k")
            ax[0, j].set_title(f"{RUNGS[r]}: {res['outcome']}")
            ax[2, j].set_xlabel("t [ms]")
        ax[0, 0].set_ylabel("U_x [m/s]")
        ax[1, 0].set_ylabel("overlap of the outer shells [um]")
        ax[2, 0].set_ylabel("electrostatic energy [pJ]")
        ax[0, 0].legend(fontsize=8)
        ax[1, 0].legend(fontsize=8)
        fig.suptitle(f"Neutral prolate hitting a charged aggregate, v0 = {v0} m/s "
                     "(Ruan 2022 Figs. 13 and 15)")
        fig.tight_layout()
        out = f"{prefix}-v{v0}.png"
        fig.savefig(out, dpi=90)
        print(f"wrote {out}")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("runs", nargs="+")
    ap.add_argument("--plot")
    ap.add_argument("--expect", nargs="*", default=[])
    a = ap.parse_args()
    results = {}
    for run in a.runs:
        results[name_of(run)] = analyse(run)
    print("| v0 [m/s] | rung | outcome | largest overlap / c | time steps | cost / point charges |")
    print("| --- | --- | --- | --- | --- | --- |")
    for (r, v0) in sorted(results, key=lambda k: (k[1], list(RUNGS).index(k[0]))):
        res = results[(r, v0)]
        ref = results.get(("pointCharges", v0))
        cost = f"{res['exe']/ref['exe']:.1f}" if ref and ref["exe"] > 0 else "-"
        print(f"| {v0} | {RUNGS[r]} | {res['outcome']} | {res['maxOverlap']/C:.4f} "
              f"| {res['steps']} | {cost} |")
    if a.plot:
        plot(results, a.plot)
    for e in a.expect:
        r, v0, outcome = e.split(":")
        res = results.get((r, float(v0)))
        got = res["outcome"] if res else "missing"
        print("%s: aggregateCollision.%s.v%s (%s at v0 = %s m/s: %s, expected %s)"
              % ("PASS" if got == outcome else "FAIL", r, v0, RUNGS[r], v0, got, outcome))


if __name__ == "__main__":
    sys.exit(main())
