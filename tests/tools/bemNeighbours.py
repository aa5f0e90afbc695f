#!/usr/bin/env python3
"""Static check of what BEM clusters and the parcels near them see of each
other (nearField bem, entry neighbours), against all-particle BEM.

Triads of charged dielectric prolates (semi-axes 100 x 50 x 50 um, random
orientations), 20 mm apart, held for one step: two members at a surface gap
of 0.2 b form a cluster, a third parcel sits at a gap of 1.2-3 b from one
of them (outside the cluster, inside the near-field radius). Far field
directCoulomb. Runs: neighbours multipoles (the default), neighbours
pointCharges, and all-particle BEM (clusterGap 1e6: every parcel in one
cluster), the reference. Relative RMS errors of the forces and torques of
the members and of the third parcels against the reference.

  bemNeighbours.py write <case> multipoles|pointCharges|allBem|dilute
  bemNeighbours.py compare <dir with the three cases> [--tol 0.01]
      -> markdown table, PASS/FAIL lines
"""
import argparse
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.environ.get("CHARGEDFOAM_DIR", ""), "etc", "python"))
from foamLagrangian import read_particle_history  # noqa: E402
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import heldCloud  # noqa: E402

S = np.array([1e-4, 5e-5, 5e-5])
B = S.min()
GAPS = (1.2, 1.6, 2.0, 3.0)          # third parcel, x b
KAPPAS = (10.0, 100.0)
NEAR = {
    "multipoles": "nearField { type bem; }",
    "pointCharges": "nearField { type bem; neighbours pointCharges; }",
    "allBem": "nearField { type bem; clusterGap 1e6; }",
}


def rotation(qw):
    w, x, y, z = qw
    return np.array([[1 - 2*(y*y + z*z), 2*(x*y - w*z), 2*(x*z + w*y)],
                     [2*(x*y + w*z), 1 - 2*(x*x + z*z), 2*(y*z - w*x)],
                     [2*(x*z - w*y), 2*(y*z + w*x), 1 - 2*(x*x + y*y)]])


def extent(Rm, u):
    ub = Rm.T @ u
    return np.sqrt(((S*ub)**2).sum())


def triads():
    """[(kappa, [(x, quaternion, q), x 3])] with the third parcel's centre-
    line gaps to both members above the cluster threshold (1 b)"""
    rng = np.random.default_rng(3)
    out = []
    t = 0
    while len(out) < len(GAPS)*len(KAPPAS):
        g3 = GAPS[len(out) % len(GAPS)]
        kappa = KAPPAS[len(out) // len(GAPS)]
        c = np.array([0.0, -0.045 + 0.02*(t % 5), -0.045 + 0.02*(t // 5 % 5)])
        quats = [q/np.linalg.norm(q) for q in rng.normal(size=(3, 4))]
        Rs = [rotation(q) for q in quats]
        u = rng.normal(size=3)
        u /= np.linalg.norm(u)
        d12 = extent(Rs[0], u) + extent(Rs[1], u) + 0.2*B
        x1, x2 = c - 0.5*d12*u, c + 0.5*d12*u
        v = rng.normal(size=3)
        v -= (v @ u)*u
        v /= np.linalg.norm(v)
        x3 = x2 + (extent(Rs[1], v) + extent(Rs[2], v) + g3*B)*v
        r13 = x3 - x1
        g13 = np.linalg.norm(r13) - extent(Rs[0], r13/np.linalg.norm(r13)) \
            - extent(Rs[2], r13/np.linalg.norm(r13))
        if g13 < 1.2*B:
            continue
        qs = rng.choice([-1, 1], 3)*rng.uniform(0.5, 1.5, 3)*1e-13
        if len(out) % 3 == 2:
            qs[2] = 0          # a neutral third parcel: its induced dipole only
        out.append((kappa, [(x1, quats[0], qs[0]), (x2, quats[1], qs[1]),
                            (x3, quats[2], qs[2])]))
        t += 1
    return out


def write(case, variant):
    """variant: a key of NEAR, or dilute: multipoles with 8 more parcels
    far from every triad (in no cluster and near none: not gathered),
    solved every third step"""
    lines = []
    for kappa, parcels in triads():
        for x, qw, q in parcels:
            lines.append("                { position (%.17g %.17g %.17g); semiAxes (%g %g %g);"
                         " quaternion (%.17g %.17g %.17g %.17g); epsilonR %g; q %.17g; }"
                         % (*x, *S, *qw, kappa, q))
    if variant == "dilute":
        for k in range(8):
            x = (0.025*(1 if k & 1 else -1), (0.025 if k & 2 else -0.035), (0.025 if k & 4 else -0.035))
            lines.append("                { position (%g %g %g); semiAxes (%g %g %g);"
                         " quaternion (1 0 0 0); epsilonR 10; q %g; }"
                         % (*x, *S, (1 if k % 3 else -1)*(0.5 + 0.1*k)*1e-13))
    # dilute: solved every 3rd step, the bound charge carried in between
    near = "nearField { type bem; solveInterval 3; }" if variant == "dilute" else NEAR[variant]
    es = ("    electrostaticsModel directCoulomb;\n"
          "    directCoulombCoeffs { %s }\n" % near)
    open(os.path.join(case, "constant/cloudProperties"), "w").write(
        heldCloud.cloudProperties(es, "\n".join(lines)))


def fields(case):
    h, col = read_particle_history(case)
    h = h[h[:, col["time"]] == h[:, col["time"]].min()]
    h = h[np.argsort(h[:, col["origId"]])]
    get = lambda k: h[:, [col[k + c] for c in "xyz"]]
    return get("fE"), get("tE")


def compare(top, tol):
    res = {v: fields(os.path.join(top, v)) for v in NEAR}
    F0, T0 = res["allBem"]
    member = np.tile([True, True, False], len(F0)//3)
    rms = lambda d, r: np.sqrt((d**2).sum()/(r**2).sum())
    print("| neighbours | force, members | torque, members | force, third parcels | torque, third parcels |")
    print("| --- | --- | --- | --- | --- |")
    err = {}
    for v in ("multipoles", "pointCharges"):
        F, T = res[v]
        err[v] = [rms(F[s] - F0[s], F0[s]) for s in (member, ~member)] \
            + [rms(T[s] - T0[s], T0[s]) for s in (member, ~member)]
        print("| %s | %.2f %% | %.2f %% | %.2f %% | %.2f %% |"
              % (v, 100*err[v][0], 100*err[v][2], 100*err[v][1], 100*err[v][3]))
    # Momentum: the summed force of a triad over its summed magnitudes
    # (the BEM's collocation does not conserve it exactly either)
    for v in ("multipoles", "pointCharges", "allBem"):
        F = res[v][0].reshape(-1, 3, 3)
        print("%s: net force of the triads / sum |F|: %.2e"
              % (v, np.linalg.norm(F.sum(1), axis=1).sum()/np.linalg.norm(F, axis=2).sum()))
    m, p = err["multipoles"], err["pointCharges"]
    ok = m[0] <= tol and m[2] <= tol
    print("%s: bemClusters.neighbours.members (%d clusters with a parcel at 1.2-3 b: member forces"
          " %.2e, torques %.2e of all-particle BEM's (RMS), tol %g; point charges: %.2e, %.2e)"
          % ("PASS" if ok else "FAIL", len(F0)//3, m[0], m[2], tol, p[0], p[2]))
    ok3 = m[1] < 0.5*p[1] and m[3] < 0.5*p[3]
    print("%s: bemClusters.neighbours.third (forces %.2e, torques %.2e of all-particle BEM's (RMS);"
          " point charges %.2e, %.2e: at least halved)"
          % ("PASS" if ok3 else "FAIL", m[1], m[3], p[1], p[3]))
    return 0 if ok and ok3 else 1


if __name__ == "__main__":
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("what", choices=("write", "compare"))
    ap.add_argument("case")
    ap.add_argument("variant", nargs="?", choices=tuple(NEAR) + ("dilute",))
    ap.add_argument("--tol", type=float, default=0.01)
    a = ap.parse_args()
    if a.what == "write":
        sys.exit(write(a.case, a.variant))
    sys.exit(compare(a.case, a.tol))
