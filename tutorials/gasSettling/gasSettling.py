#!/usr/bin/env python3
"""Checks of a gasSettling run (chargedDPMFoam), one PASS:/FAIL: line each.

    gasSettling.py <case> [--momentum U0 TOL | --weight TOL]

Always: the run ended, no NaN in the log, no parcel lost (the log's parcel
count at the end equals the number of positions injected).

Closed box (default): the gas is dragged down where the particles are and
comes back up elsewhere: the mean vertical gas velocity under the particle
column (x < 5 mm) is < 0 and in the other half > 0.

--momentum U0 TOL (fully periodic box, no gravity, all parcels injected
with velocity U0 = 'ux uy uz'): the momentum the particles lost is found in
the gas: |P_gas + P_p - P_p0| <= TOL |P_p0 - P_p| with
P_gas = sum rho_c alpha_c U_c V (cells), P_p = sum n m U of the parcels
written at that time, P_p0 = N n m U0.

--weight TOL (closed box, gravity, a suspension settling at its terminal
velocity, no parcel at a wall): the walls' pressure carries the weight of
the gas and the particles, -rho_c sum V grad(p) (Gauss gradient of the
kinematic p: the walls' pressure force) = -(rho_c (V_box - V_p) + M_p) g
within TOL of the weight (needs grad(p) and V written at the last time).
"""
import argparse
import glob
import math
import os
import re

import numpy as np

from foamLagrangian import read_field, read_internal_field


def parcel_volumes_masses(t):
    """Volume and mass of the particles of each parcel written at time t
    (n pi d^3/6, times rho)."""
    lag = os.path.join(t, "lagrangian", "cloud")
    v = (read_field(os.path.join(lag, "nParticle"))
         * math.pi/6*read_field(os.path.join(lag, "d"))**3)
    return v, v*read_field(os.path.join(lag, "rho"))


def vec(s):
    return np.array(s.strip("()").split(), dtype=float)


ap = argparse.ArgumentParser(description=__doc__)
ap.add_argument("case")
ap.add_argument("--momentum", nargs=2, metavar=("U0", "TOL"))
ap.add_argument("--weight", type=float, metavar="TOL")
a = ap.parse_args()
os.chdir(a.case)

log = open("log.chargedDPMFoam").read()
nInj = int(re.search(r"^(\d+)\s*$", open("constant/cloudPositions").read(), re.M).group(1))
counts = re.findall(r"Current number of parcels\s*=\s*(\d+)", log)
ended = log.rstrip().endswith("End")
nan = re.search(r"\bnan\b", log, re.I) is not None
print(("PASS" if ended and not nan else "FAIL")
      + f": gasSettling.run (ended: {ended}, NaN in log: {nan})")
last = int(counts[-1]) if counts else -1
print(("PASS" if last == nInj else "FAIL")
      + f": gasSettling.parcels ({last} parcels at the end of {nInj} injected)")

times = sorted((d for d in glob.glob("[0-9]*") if d != "0"
                and os.path.isfile(os.path.join(d, "U.air"))), key=float)
if not times:
    print("FAIL: gasSettling.fields (no time with U.air written)")
    raise SystemExit(1)
t = times[-1]
U = read_internal_field(os.path.join(t, "U.air"))
V = read_internal_field(os.path.join(t, "V"))
alpha = read_internal_field(os.path.join(t, "alpha.air"))
rho = float(re.search(r"rho.air\s+([-+0-9.eE]+)",
                      open("constant/transportProperties").read()).group(1))
finite = bool(np.all(np.isfinite(U)))

if a.weight is not None:
    g = vec(re.search(r"value\s+(\([^)]*\))", open("constant/g").read()).group(1))
    vp, mp = parcel_volumes_masses(t)
    Vp, Mp = float(np.sum(vp)), float(np.sum(mp))
    F = -rho*np.sum(V[:, None]*read_internal_field(os.path.join(t, "grad(p)")), axis=0)
    W = -(rho*(float(np.sum(V)) - Vp) + Mp)*g
    err = float(np.linalg.norm(F - W)/np.linalg.norm(W))
    print(("PASS" if finite and err <= a.weight else "FAIL")
          + f": gasSettling.weight (t = {t} s: walls' pressure force"
          f" {np.array2string(F, precision=5)} N, weight of gas and particles"
          f" {np.array2string(W + 0.0, precision=5)} N (particles"
          f" {Mp*float(np.linalg.norm(g)):.4g} N); relative difference"
          f" {err:.3g} <= {a.weight})")
elif a.momentum is None:
    C = read_internal_field(os.path.join(t, "C"))
    left = C[:, 0] < 5e-3
    wLeft = float(np.average(U[left, 2], weights=V[left]))
    wRight = float(np.average(U[~left, 2], weights=V[~left]))
    ok = finite and wLeft < 0 < wRight
    print(("PASS" if ok else "FAIL")
          + f": gasSettling.gasDragged (t = {t} s: mean U_z = {wLeft:.4g} m/s"
          f" under the particles, {wRight:.4g} m/s beside them)")
else:
    U0 = vec(a.momentum[0])
    tol = float(a.momentum[1])
    cp = open("constant/cloudProperties").read()
    rho0 = float(re.search(r"rho0\s+([-+0-9.eE]+)", cp).group(1))
    nParticle = float(re.search(r"nParticle\s+([-+0-9.eE]+)", cp).group(1))
    d = float(re.search(r"value\s+([-+0-9.eE]+)", cp).group(1))
    P0 = nInj*nParticle*rho0*math.pi/6*d**3*U0
    # The parcels as written at t (after the step's coupling correction)
    _, mp = parcel_volumes_masses(t)
    Pp = np.sum(mp[:, None]*read_field(os.path.join(t, "lagrangian", "cloud", "U")),
                axis=0)
    Pg = rho*np.sum((alpha*V)[:, None]*U, axis=0)
    lost = P0 - Pp
    err = float(np.linalg.norm(Pg - lost)/np.linalg.norm(lost))
    ok = finite and err <= tol
    print(("PASS" if ok else "FAIL")
          + f": gasSettling.momentum (t = {t} s: particles lost"
          f" {np.array2string(lost, precision=4)} kg m/s, gas gained"
          f" {np.array2string(Pg, precision=4)}; relative mismatch"
          f" {err:.3g} <= {tol})")
