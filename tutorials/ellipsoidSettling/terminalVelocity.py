#!/usr/bin/env python3
"""Terminal settling velocities of an ellipsoidSettling run against the
drag correlations solved here independently, one PASS:/FAIL: line each.

    terminalVelocity.py <case> [--tol 1e-6]

For every parcel of the last time: the drag-gravity balance

    (pi/8) mu d CdRe(Re) v = m g (1 - rho_c/rho_p),   Re = rho_c v d/mu

is solved for v by a bracketing root finder, with CdRe of Hölzer &
Sommerfeld 2008 Eq. (9) (sphericity from the ellipsoid's surface area by
Gauss-Legendre quadrature, crosswise sphericity from the projected area
seen along the vertical in the body frame of the written orientation
quaternion), or Schiller-Naumann (OpenFOAM's sphereDrag) for spheres.
The simulated |U| must match within tol (relative; after 13 response
times the approach to terminal velocity is below 1e-7) and be vertical.
"""
import argparse
import glob
import math
import os
import re

import numpy as np
from scipy.optimize import brentq

from ellipsoids import rotation
from foamLagrangian import read_field, read_positions


def entry(path, key):
    m = re.search(r"^\s*%s\s+([^;]+);" % re.escape(key), open(path).read(), re.M)
    return m.group(1).strip()


def surface_area(a, b, c, n=200):
    """Ellipsoid surface area by Gauss-Legendre (cos theta) x trapezoid
    (phi, periodic: spectral) quadrature of |r_theta x r_phi|."""
    x, w = np.polynomial.legendre.leggauss(n)          # x = cos theta
    phi = np.linspace(0, 2*np.pi, 2*n, endpoint=False)
    ct, ph = np.meshgrid(x, phi, indexing="ij")
    st = np.sqrt(1 - ct**2)
    # r = (a st cp, b st sp, c ct); dA = |r_t x r_p| dtheta dphi, and
    # dtheta = dct/st
    rt = np.stack([a*ct*np.cos(ph), b*ct*np.sin(ph), -c*st])
    rp = np.stack([-a*st*np.sin(ph), b*st*np.cos(ph), 0*ph])
    J = np.linalg.norm(np.cross(rt, rp, axis=0), axis=0)/st
    return float(np.sum(w[:, None]*J)*(2*np.pi/(2*n)))


def cdre_hs(Re, phi, phi_perp):
    """Cd Re, Hölzer & Sommerfeld 2008, Eq. (9)."""
    return (8/math.sqrt(phi_perp) + 16/math.sqrt(phi)
            + 3*math.sqrt(Re)/phi**0.75
            + 0.42*10**(0.4*(-math.log10(phi))**0.2)*Re/phi_perp)


def cdre_sn(Re):
    """Cd Re of OpenFOAM's sphereDrag."""
    return 0.424*Re if Re > 1000 else 24*(1 + Re**(2/3)/6)


ap = argparse.ArgumentParser(description=__doc__)
ap.add_argument("case")
ap.add_argument("--tol", type=float, default=1e-6)
a = ap.parse_args()
os.chdir(a.case)

rhoc = float(entry("constant/carrierProperties", "rho"))
mu = float(entry("constant/carrierProperties", "mu"))
g = np.array(entry("constant/g", "value").strip("()").split(), dtype=float)
t = max((d for d in glob.glob("[0-9]*") if os.path.isdir(d + "/lagrangian/cloud")),
        key=float)
lag = t + "/lagrangian/cloud/"
U = read_field(lag + "U")
d = read_field(lag + "d")
rho = read_field(lag + "rho")
axes = read_field(lag + "semiAxes")
eps = read_field(lag + "orientationEps")
eta = read_field(lag + "orientationEta")
x = read_positions(lag + "positions")

print(f"t = {t} s; carrier rho = {rhoc}, mu = {mu}")
vt = {}
for i in np.argsort(x[:, 0]):
    ab = axes[i]
    R = rotation(eta[i], *eps[i])
    gdir = g/np.linalg.norm(g)
    u = R.T @ gdir                                  # slip direction, body frame
    m = rho[i]*math.pi/6*d[i]**3
    W = m*np.linalg.norm(g)*(1 - rhoc/rho[i])
    sphere = ab[0] == ab[1] == ab[2]
    if sphere:
        name, cdre = "sphere", cdre_sn
    else:
        dv = 2*np.prod(ab)**(1/3)
        phi = math.pi*dv**2/surface_area(*ab)
        A = math.pi*math.sqrt((ab[1]*ab[2]*u[0])**2 + (ab[0]*ab[2]*u[1])**2
                              + (ab[0]*ab[1]*u[2])**2)
        phi_perp = math.pi*dv**2/4/A
        k = 2 if ab[0] == ab[1] else 0      # the distinct axis
        tilt = math.degrees(math.acos(min(1, abs(R[:, k] @ gdir))))
        name = (f"ellipsoid {ab[0]/ab[2]:.3g}:{ab[1]/ab[2]:.3g}:1, {'xyz'[k]}-axis"
                f" {tilt:.0f} deg from vertical, Phi = {phi:.5f},"
                f" Phi_perp = {phi_perp:.5f}")
        cdre = (lambda Re, phi=phi, pp=phi_perp: cdre_hs(Re, phi, pp))
    f = lambda v: math.pi/8*mu*d[i]*cdre(rhoc*v*d[i]/mu)*v - W
    v = brentq(f, 1e-9, 100, xtol=1e-15, rtol=1e-14)
    vs = float(U[i] @ gdir)
    lateral = float(np.linalg.norm(U[i] - vs*gdir))
    err = abs(vs - v)/v
    ok = err <= a.tol and lateral <= a.tol*v
    vt[i] = vs
    print(("PASS" if ok else "FAIL")
          + f": terminalVelocity.{i} ({name}: simulated {vs:.6g} m/s,"
          f" correlation {v:.6g} m/s, Re = {rhoc*v*d[i]/mu:.3g}; relative"
          f" error {err:.2e}, lateral {lateral:.1e} m/s; tol {a.tol})")
