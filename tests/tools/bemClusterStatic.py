#!/usr/bin/env python3
"""Static check of the cloud's BEM clusters (nearField bem) against the
exact two-sphere force (etc/python/twoDielectricSpheres.py).

Many pairs of dielectric spheres, 20 mm apart from each other (far field
none: each pair is its own cluster and sees nothing else), held in place
for one step; the force on each sphere along the line against the exact
multipole series. Radii 50 um and ratio x 50 um, gaps 0.05-0.5 of the
smaller radius, epsilonR 2, 10 and 1000, like and opposite charges.

  bemClusterStatic.py write <case> [--ratio 2] [--patches 1200]
                            [--far none|directCoulomb|cutoffCoulomb] [--pairs N]
  bemClusterStatic.py compare <case> [--ratio 2] [--tol005 0.02] [--tol01 0.01]
      -> markdown table, PASS/FAIL line
  both: [--gaps 0.05,0.1,0.2,0.5] [--kappas 2,10,1000] (the same for both)

--far directCoulomb: the far field counts the pair's point charges, which
the cluster must take out again; --far cutoffCoulomb (rCut 1e-4 m, below
every pair's distance): it does not, and the cluster must not either;
--pairs N: only the first N pairs.

The error is |F_bem - F_exact| over max(|F_exact|, |F_Coulomb|): like
charges of unequal size attract at close range, and where the Coulomb
repulsion and the polarisation attraction cancel, F_exact -> 0 and its own
relative error is meaningless; the scale of the parts that cancel is.
"""
import argparse
import glob
import math
import os
import re
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.environ.get("CHARGEDFOAM_DIR", ""), "etc", "python"))
import twoDielectricSpheres as tds  # noqa: E402
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import heldCloud  # noqa: E402

A1 = 5e-5
GAPS = (0.05, 0.1, 0.2, 0.5)
KAPPAS = (2.0, 10.0, 1000.0)
CHARGES = {"like": (1e-13, 3e-13), "opposite": (1e-13, -2e-13)}


def pairs():
    out = []
    for k in KAPPAS:
        for name, (q1, q2) in CHARGES.items():
            for g in GAPS:
                out.append((k, name, q1, q2, g))
    return out


ELECTROSTATICS = """    electrostaticsModel %s;
    %sCoeffs { nearField { type bem; isolated none; nPatches %d; } }
"""


def layout(A2):
    """(x1, x2) of each pair: along x, pairs spaced along y and z (the
    line of centres tilted, so that the mesh is not aligned with the axes)"""
    out = []
    for i, (k, name, q1, q2, g) in enumerate(pairs()):
        c = np.array([0.0, -0.045 + 0.02*(i % 5), -0.045 + 0.02*(i // 5 % 5)])
        u = np.array([1.0, 0.3, -0.2])
        u /= np.linalg.norm(u)
        d = A1 + A2 + g*A1
        out.append((c - 0.5*d*u, c + 0.5*d*u))
    return out


def write(case, A2, n=1200, far="none", nPairs=None):
    lines = []
    for (k, name, q1, q2, g), (x1, x2) in list(zip(pairs(), layout(A2)))[:nPairs]:
        for x, a, q in ((x1, A1, q1), (x2, A2, q2)):
            lines.append("                { position (%.17g %.17g %.17g); d %.17g; epsilonR %g; q %g; }"
                         % (x[0], x[1], x[2], 2*a, k, q))
    open(os.path.join(case, "constant/cloudProperties"), "w").write(
        heldCloud.cloudProperties(ELECTROSTATICS % (far, far, n), "\n".join(lines)))
    if far == "cutoffCoulomb":
        # A cutoff below every pair's distance: the far field has no pair
        p = os.path.join(case, "constant/cloudProperties")
        text = open(p).read().replace("cutoffCoulombCoeffs {", "cutoffCoulombCoeffs { rCut 1e-4;")
        open(p, "w").write(text)


def compare(case, A2, tol005=0.02, tol01=0.01):
    f = sorted(glob.glob(os.path.join(
        case, "postProcessing/lagrangian/cloud/particleHistory/*/particleHistory.dat")))[0]
    header = open(f).readlines()[1].lstrip("# ").split()
    h = np.loadtxt(f, ndmin=2)
    h = h[h[:, 0] == h[0, 0]]
    col = {k: i for i, k in enumerate(header)}
    X = h[:, [col["x"], col["y"], col["z"]]]
    F = h[:, [col["fEx"], col["fEy"], col["fEz"]]]
    print("| epsilonR | charges | gap/a1 | F_exact [N] | F_exact/F_Coulomb | F_bem/F_exact - 1 | error (sphere 2) | error (sphere 1) | |F1 + F2|/|F| |")
    print("| --- | --- | --- | --- | --- | --- | --- | --- | --- |")
    worst = {0.05: 0.0, 0.1: 0.0}
    for (k, name, q1, q2, g), (x1, x2) in zip(pairs(), layout(A2)):
        i1 = int(np.argmin(np.linalg.norm(X - x1, axis=1)))
        i2 = int(np.argmin(np.linalg.norm(X - x2, axis=1)))
        d = np.linalg.norm(x2 - x1)
        u = (x2 - x1)/d
        Fe = tds.force(q1, q2, A1, A2, d, k, k)
        Fc = q1*q2/(4*math.pi*tds.eps0*d*d)
        scale = max(abs(Fe), abs(Fc))
        e2 = (F[i2] @ u - Fe)/scale
        e1 = (-(F[i1] @ u) - Fe)/scale
        e3 = np.linalg.norm(F[i1] + F[i2])/scale
        key = 0.05 if g < 0.1 else 0.1
        worst[key] = max(worst[key], abs(e1), abs(e2))
        print("| %g | %s | %g | %+.4e | %+.3f | %+.4f | %+.4f | %+.4f | %.1e |"
              % (k, name, g, Fe, Fe/Fc, (F[i2] @ u)/Fe - 1, e2, e1, e3))
    # The energy books: the log's electrostatic energy (far field none: the
    # clusters' alone) against the exact interaction energies, over the
    # energy scale sum |U_exact|
    Uex = [tds.interactionEnergy(q1, q2, A1, A2, np.linalg.norm(x2 - x1), k, k)
           for (k, name, q1, q2, g), (x1, x2) in zip(pairs(), layout(A2))]
    log = open(os.path.join(case, "log.solver")).read()
    Ulog = float(re.search(r"Electrostatic energy\s+= (\S+)", log).group(1))
    eU = abs(Ulog - sum(Uex))/sum(abs(u) for u in Uex)
    print("%s: bemClusters.energy%g (the log's energy %.6e J vs the exact interaction energies"
          " %.6e J: error %.1e of sum |U|, tol 5e-3)"
          % ("PASS" if eU < 5e-3 else "FAIL", A2/A1, Ulog, sum(Uex), eU))
    ok = worst[0.05] <= tol005 and worst[0.1] <= tol01
    print("%s: bemClusters.exactTwoSpheres%g (%d pairs, radii 1:%g, epsilonR 2-1000: max force error"
          " %.2e at gap 0.05 a1 (tol %g), %.2e at gaps 0.1-0.5 a1 (tol %g))"
          % ("PASS" if ok else "FAIL", A2/A1, len(pairs()), A2/A1, worst[0.05], tol005, worst[0.1], tol01))
    return 0 if ok and eU < 5e-3 else 1


if __name__ == "__main__":
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("what", choices=("write", "compare"))
    ap.add_argument("case")
    ap.add_argument("--ratio", type=float, default=2)
    ap.add_argument("--patches", type=int, default=1200)
    ap.add_argument("--far", default="none")
    ap.add_argument("--pairs", type=int, default=None)
    ap.add_argument("--tol005", type=float, default=0.02)
    ap.add_argument("--tol01", type=float, default=0.01)
    ap.add_argument("--gaps", help="comma-separated gaps/a1 (default 0.05,0.1,0.2,0.5)")
    ap.add_argument("--kappas", help="comma-separated epsilonR (default 2,10,1000)")
    a = ap.parse_args()
    if a.gaps:
        GAPS = tuple(float(x) for x in a.gaps.split(","))
    if a.kappas:
        KAPPAS = tuple(float(x) for x in a.kappas.split(","))
    if a.what == "write":
        sys.exit(write(a.case, a.ratio*A1, a.patches, a.far, a.pairs))
    sys.exit(compare(a.case, a.ratio*A1, a.tol005, a.tol01))
