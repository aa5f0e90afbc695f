#!/usr/bin/env python3
"""Two like-charged dielectric spheres that attract: the simulated gap
against two references integrated here (RK4, fine steps):

  - the monopole + mutually induced point-dipole model the solver uses
    (Ruan 2022 Eqs. 45-48; for two spheres on a line a 2x2 solve, written
    out below independently of the C++ kernel): the check, tolerance 1e-4 of
    the gap's change;
  - the exact force of two dielectric spheres (multipole series,
    etc/python/twoDielectricSpheres.py): reported, not checked; it is the
    dipole model's error.

Also checks that the total momentum stays zero (Newton's third law of the
pair terms). Writes attraction.png.

Usage: attraction.py <caseDir>; last line PASS: ... or FAIL: ...
"""
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.environ.get("CHARGEDFOAM_DIR", ""), "etc", "python"))
import twoDielectricSpheres as tds  # noqa: E402
from foamLagrangian import read_particle_history  # noqa: E402

EPS0 = 8.8541878128e-12
KC = 1/(4*math.pi*EPS0)

# The case (constant/cloudProperties)
a1, a2 = 50e-6, 100e-6
q1, q2 = 1e-14, 3e-13
k1 = k2 = 10.0
rho = 1000.0
m1, m2 = rho*4/3*math.pi*a1**3, rho*4/3*math.pi*a2**3


def dipole_force(d):
    """Force on sphere 2 (at +d from sphere 1) along the axis, positive =
    repulsion, of charges at the centres plus mutually induced dipoles
    p_i = alpha_i E(x_i), alpha_i = 4 pi eps0 a^3 (k - 1)/(k + 2)."""
    A1 = (k1 - 1)/(k1 + 2)*a1**3/KC
    A2 = (k2 - 1)/(k2 + 2)*a2**3/KC
    # E at 1: -KC q2/d^2 + 2 KC p2/d^3; E at 2: KC q1/d^2 + 2 KC p1/d^3
    M = np.array([[1, -A1*2*KC/d**3], [-A2*2*KC/d**3, 1]])
    b = np.array([-A1*KC*q2/d**2, A2*KC*q1/d**2])
    p1, p2 = np.linalg.solve(M, b)
    E1 = KC*q1/d**2 + 2*KC*p1/d**3          # field of sphere 1 at 2
    dE1 = -2*KC*q1/d**3 - 6*KC*p1/d**4      # its derivative along the axis
    return q2*E1 + p2*dE1


def integrate(force, d0, times, dMin=0.0):
    """Relative motion from rest: d'' = F(d)/mu; RK4, 20 substeps per sample.
    NaN from the first sample with d < dMin on (contact)."""
    mu = m1*m2/(m1 + m2)
    y = np.array([d0, 0.0])
    out = [d0]
    f = lambda y: np.array([y[1], force(y[0])/mu])
    for t0, t1 in zip(times[:-1], times[1:]):
        h = (t1 - t0)/20
        if y[0] < dMin or out[-1] != out[-1]:
            out.append(float("nan"))
            continue
        for _ in range(20):
            s1 = f(y)
            s2 = f(y + h/2*s1)
            s3 = f(y + h/2*s2)
            s4 = f(y + h*s3)
            y = y + h/6*(s1 + 2*s2 + 2*s3 + s4)
        out.append(y[0])
    return np.array(out)


def read_history(case):
    data, col = read_particle_history(case)
    p1, p2 = data[data[:, 2] == 0], data[data[:, 2] == 1]
    return p1[:, 0], p1, p2, col


def main(case):
    t, p1, p2, c = read_history(case)
    d = p2[:, c["x"]] - p1[:, c["x"]]
    # The history starts after the first step: prepend the release
    d0 = 9e-5 + 7.5e-5
    times = np.concatenate([[0.0], t])
    dSim = np.concatenate([[d0], d])
    dDip = integrate(dipole_force, d0, times)
    travel = d0 - dDip[-1]
    err = np.abs(dSim - dDip).max()/travel

    P = m1*p1[:, c["Ux"]] + m2*p2[:, c["Ux"]]
    pScale = np.abs(m2*p2[:, c["Ux"]]).max()
    pErr = np.abs(P).max()/pScale

    # The exact force on a fine grid of gaps (log-spaced), interpolated
    gaps = np.geomspace(0.02*a1, max(2*(d0 - a1 - a2), a1), 160)
    Fex = np.array([tds.force(q1, q2, a1, a2, a1 + a2 + g, k1, k2) for g in gaps])
    fexact = lambda dd: np.interp(math.log(dd - a1 - a2), np.log(gaps), Fex)
    dEx = integrate(fexact, d0, times, dMin=a1 + a2 + 0.05*a1)

    gap = lambda dd: (dd - a1 - a2)/a1
    print("gap/a1: released at %.4f, at %.4g s: simulated %.6f, dipole model %.6f"
          % (gap(d0), times[-1], gap(dSim[-1]), gap(dDip[-1])))
    # The model's error on the trajectory: when the gap has closed to
    # gStar (the smallest gap both reach), simulated against exact
    valid = np.isfinite(dEx)
    gStar = max(gap(dSim.min()), gap(dEx[valid].min()))
    tClose = lambda dd: times[np.argmax(gap(dd) <= gStar + 1e-12)]
    print("time to close the gap to %.3f a1: simulated (dipole rung) %.4g s, exact"
          " two-sphere force %.4g s: ratio %.3f" % (gStar, tClose(dSim),
                                                    tClose(np.where(valid, dEx, 0)),
                                                    tClose(dSim)/tClose(np.where(valid, dEx, 0))))
    print("force at release [N]: Coulomb %+.4e, dipole model %+.4e, exact %+.4e"
          % (KC*q1*q2/d0**2, dipole_force(d0), tds.force(q1, q2, a1, a2, d0, k1, k2)))
    print("gap/a1   F_dipole/F_exact")
    for g in [0.05, 0.1, 0.2, 0.3, 0.5, 1.0]:
        print("%6.2f   %.4f" % (g, dipole_force(a1 + a2 + g*a1)/tds.force(q1, q2, a1, a2, a1 + a2 + g*a1, k1, k2)))

    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        fig, ax = plt.subplots(1, 2, figsize=(11, 4.2))
        ax[0].plot(times*1e3, gap(dSim), lw=3, alpha=0.5, label="chargedParticleFoam (inducedDipole)")
        ax[0].plot(times*1e3, gap(dDip), "--", label="dipole model, integrated")
        ax[0].plot(times*1e3, gap(dEx), ":", label="exact two-sphere force")
        ax[0].set_xlabel("t [ms]")
        ax[0].set_ylabel("gap / a1")
        ax[0].legend(fontsize=8)
        ax[0].set_title("Like charges attract (a2 = 2 a1, epsilonR 10)")
        g = np.geomspace(0.02, 1.0, 100)
        ax[1].semilogx(g, [dipole_force(a1 + a2 + x*a1)*1e9 for x in g], "--", label="dipole model")
        ax[1].semilogx(g, [KC*q1*q2/(a1 + a2 + x*a1)**2*1e9 for x in g], "-.", label="Coulomb (point charges)")
        ax[1].semilogx(gaps/a1, Fex*1e9, ":", label="exact")
        ax[1].axhline(0, color="k", lw=0.5)
        ax[1].set_xlabel("gap / a1")
        ax[1].set_ylabel("force on sphere 2 [nN] (> 0: repulsion)")
        ax[1].legend(fontsize=8)
        fig.tight_layout()
        fig.savefig(os.path.join(case, "attraction.png"), dpi=110)
    except ImportError:
        pass

    ok = err < 1e-4 and pErr < 1e-10 and dSim[-1] < d0
    print("%s: gap vs the integrated dipole model: max difference %.2e of the"
          " travel (tol 1e-4); total momentum %.1e of the largest (tol 1e-10)"
          % ("PASS" if ok else "FAIL", err, pErr))
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1] if len(sys.argv) > 1 else "."))
