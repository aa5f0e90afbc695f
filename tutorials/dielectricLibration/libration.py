#!/usr/bin/env python3
"""Libration of a neutral dielectric prolate spheroid in a uniform field.

The induced dipole p = alpha E (Ruan 2022 Eqs. 49-50) gives the energy
U(theta) = const + 1/4 E^2 (alpha_par - alpha_perp)(1 - cos 2 theta), theta the
angle of the major axis to the field, so phi = 2 theta is a pendulum:
    phi'' = -w0^2 sin(phi),  w0^2 = E^2 (alpha_par - alpha_perp)/I_perp,
with period T = (2 pi/w0) (2/pi) K(sin(phi0/2)) at amplitude phi0. The
depolarisation factors come from the closed form of a prolate spheroid
(Landau & Lifshitz, Electrodynamics of Continuous Media, section 4), not from
the solver's quadrature. Checks: the simulated period within 1 % of T, and the
total energy (rotational kinetic + electrostatic) constant to 1e-3 of the
energy exchanged. Writes libration.png.

Usage: libration.py <caseDir>; last line PASS: ... or FAIL: ...
"""
import glob
import math
import os
import re
import sys

import numpy as np

EPS0 = 8.8541878128e-12

# The case (constant/cloudProperties of the tutorial)
a, b = 3e-4, 1e-4           # semi-axes [m], prolate a > b = c
kappa = 2.5                 # epsilonR of the particle, vacuum around
rho = 1000.0
E = 1e6                     # applied field [V/m]
theta0 = math.radians(5.0)


def prolate_depolarisation(a, b):
    """L_par, L_perp of a prolate spheroid (closed form)."""
    e = math.sqrt(1 - (b/a)**2)
    Lpar = (1 - e*e)/e**3*(math.atanh(e) - e)
    return Lpar, (1 - Lpar)/2


def ellipk(k):
    """Complete elliptic integral of the first kind K(k) by the AGM."""
    x, y = 1.0, math.sqrt(1 - k*k)
    while abs(x - y) > 1e-16*x:
        x, y = (x + y)/2, math.sqrt(x*y)
    return math.pi/(2*x)


def predicted_period():
    V = 4/3*math.pi*a*b*b
    Lpar, Lperp = prolate_depolarisation(a, b)
    alpha = lambda L: EPS0*V*(kappa - 1)/(1 + (kappa - 1)*L)
    dAlpha = alpha(Lpar) - alpha(Lperp)
    I = rho*V*(a*a + b*b)/5
    w0 = math.sqrt(E*E*dAlpha/I)
    phi0 = 2*theta0
    return 2*math.pi/w0*(2/math.pi)*ellipk(math.sin(phi0/2)), w0


def read_history(case):
    files = sorted(glob.glob(os.path.join(
        case, "postProcessing/lagrangian/cloud/particleHistory/*/particleHistory.dat")))
    header = open(files[0]).readlines()[1].lstrip("# ").split()
    data = np.vstack([np.loadtxt(f, ndmin=2) for f in files])
    return {h: data[:, i] for i, h in enumerate(header)}


def angle(h):
    """Angle of the body x axis (major axis) to the field (x), in the xy plane."""
    w, x, y, z = h["qw"], h["qx"], h["qy"], h["qz"]
    ex = 1 - 2*(y*y + z*z)
    ey = 2*(x*y + w*z)
    return np.arctan2(ey, ex)


def crossings(t, th):
    """Times of the downward and upward zero crossings (linear interpolation)."""
    s = np.sign(th)
    i = np.nonzero(s[:-1]*s[1:] < 0)[0]
    return t[i] - th[i]*(t[i + 1] - t[i])/(th[i + 1] - th[i])


def energies(case):
    log = open(os.path.join(case, "log.chargedParticleFoam")).read()
    ke = [float(v) for v in re.findall(r"Rotational kinetic energy \(ellipsoids\) = (\S+)", log)]
    ue = [float(v) for v in re.findall(r"Electrostatic energy\s*=\s*(\S+)", log)]
    n = min(len(ke), len(ue))
    return np.array(ke[:n]), np.array(ue[:n])


def main(case):
    h = read_history(case)
    t, th = h["time"], angle(h)
    tc = crossings(t, th)
    # Crossings alternate in direction: one period per two crossings
    periods = tc[2:] - tc[:-2]
    T = periods.mean()
    Tp, w0 = predicted_period()
    err = T/Tp - 1

    ke, ue = energies(case)
    tot = ke + ue
    exchanged = ke.max() - ke.min()
    drift = np.abs(tot - tot[0]).max()/exchanged

    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        fig, ax = plt.subplots(2, 1, figsize=(7, 6), sharex=False)
        ax[0].plot(t*1e3, np.degrees(th), label="chargedParticleFoam")
        ax[0].plot(t*1e3, np.degrees(theta0*np.cos(2*math.pi*t/Tp)), "--",
                   label="harmonic, period of Eqs. 49-50 (%.3f ms)" % (Tp*1e3))
        ax[0].set_xlabel("t [ms]")
        ax[0].set_ylabel("angle to the field [deg]")
        ax[0].legend(loc="upper right", fontsize=8)
        ax[0].set_title("Dielectric prolate (a/b = 3, epsilonR 2.5) in E = 1 MV/m")
        ax[1].plot(ke/exchanged, label="rotational kinetic")
        ax[1].plot((ue - ue.min())/exchanged, label="electrostatic - min")
        ax[1].plot((tot - tot[0])/exchanged*1e3, label="total drift x 1e3")
        ax[1].set_xlabel("log step")
        ax[1].set_ylabel("energy / energy exchanged")
        ax[1].legend(fontsize=8)
        fig.tight_layout()
        fig.savefig(os.path.join(case, "libration.png"), dpi=110)
    except ImportError:
        pass

    print("periods measured: %d, mean %.6g s, predicted %.6g s (w0 %.6g rad/s),"
          " relative error %.3e" % (len(periods), T, Tp, w0, err))
    print("energy: exchanged %.4g J, max |total - initial| / exchanged %.3e"
          % (exchanged, drift))
    ok = len(periods) >= 2 and abs(err) < 0.01 and drift < 1e-3
    print("%s: period error %.2e (tol 1e-2), energy drift %.2e (tol 1e-3)"
          % ("PASS" if ok else "FAIL", err, drift))
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1] if len(sys.argv) > 1 else "."))
