#!/usr/bin/python3
"""Write constant/parcels and constant/carrierProperties of the mono-charged
cloud of Boutsikakis 2023 section 3: N particles (default 1e4) at uniformly
random positions, at rest, in a cube whose edge L gives the number density n
(default 40.314 /m^3, the paper's 1e4 particles in the 2 pi m cube), charge
Q (default 5 nC), density rho (default 2750 kg/m^3) at the diameter of the
base point (m = 1.8e-4 kg at 2750 kg/m^3: d = 5 mm; section 3.3 varies m
through rho at constant d); the numerical dissipation -u/tau_p, tau_p = 650
tau_el (section 3), is Stokes drag in a carrier at rest with
mu = rho d^2/(18 tau_p).

    makeParcels.py [N] [seed] [--Q C] [--rho kg/m3] [--n 1/m3]
                   [--dt s | --ratio dC/dl] [--endTauEl T]

--ratio sets deltaT from the Coulomb diameter over the mean relative
displacement per step, d_C/delta_l (Eq. 23 asks >= 100), with q_p^2 of
Eq. 25; --endTauEl sets endTime in units of tau_el (Eq. 26). Without them
system/controlDict is left as it is.
"""
import argparse
import math
import re

import numpy as np

k = 8.9875517923e9
N_BASE, L_BASE = 1e4, 2*math.pi                 # the paper's base point
M_BASE, RHO_BASE = 1.8e-4, 2750.0

ap = argparse.ArgumentParser()
ap.add_argument("N", nargs="?", type=float, default=1e4)
ap.add_argument("seed", nargs="?", type=int, default=1)
ap.add_argument("--Q", type=float, default=5e-9, help="particle charge [C]")
ap.add_argument("--rho", type=float, default=RHO_BASE, help="particle density [kg/m3]")
ap.add_argument("--n", type=float, default=N_BASE/L_BASE**3, help="number density [1/m3]")
ap.add_argument("--dt", type=float, help="deltaT [s]")
ap.add_argument("--ratio", type=float, help="deltaT from d_C/delta_l (Eqs. 21-23, 25)")
ap.add_argument("--endTauEl", type=float, help="endTime in units of tau_el")
a = ap.parse_args()

N, Q, rho, n = int(a.N), a.Q, a.rho, a.n
L = (N/n)**(1/3)
d = (6*M_BASE/(math.pi*RHO_BASE))**(1/3)
m = rho*math.pi*d**3/6
tau_el = math.sqrt(3*m/(2*k*n))/Q                       # Eq. (26)
tau_p = 650*tau_el
mu = rho*d**2/(18*tau_p)
qp2 = k*Q**2*n**(1/3)/m                                 # Eq. (25)
w = math.sqrt(16/math.pi*2/3*qp2)                       # Eq. (22)
dC = k*Q*Q/(0.5*m*w**2)                                 # Eq. (21), m_pq = m/2

rng = np.random.default_rng(a.seed)
x = L*rng.random((N, 3))
with open("constant/parcels", "w") as f:
    f.write("// Written by makeParcels.py\nparcels\n(\n")
    for p in x:
        f.write("    { position (%.10g %.10g %.10g); d %.10g; rho %.10g; q %.10g; }\n"
                % (p[0], p[1], p[2], d, rho, Q))
    f.write(");\n")
with open("constant/carrierProperties", "w") as f:
    f.write("""FoamFile { version 2.0; format ascii; class dictionary; object carrierProperties; }
// Written by makeParcels.py: Stokes drag with tau_p = 650 tau_el = %.6g s
rho 0;
mu  %.10g;
U   (0 0 0);
""" % (tau_p, mu))


def setEntry(path, key, value):
    with open(path) as f:
        s = f.read()
    s, count = re.subn(r"^%s\s.*?;" % key, "%-15s %s;" % (key, value), s, flags=re.M)
    if count != 1:
        raise SystemExit("makeParcels.py: no entry '%s' in %s" % (key, path))
    with open(path, "w") as f:
        f.write(s)


setEntry("system/blockMeshDict", "scale", "%.16g" % L)
dt = a.dt if a.dt else (dC/(a.ratio*w) if a.ratio else None)
if dt:
    setEntry("system/controlDict", "deltaT", "%.10g" % dt)
if a.endTauEl:
    setEntry("system/controlDict", "endTime", "%.10g" % (a.endTauEl*tau_el))
print("N = %d, L = %.6g m, n = %.6g /m3, d = %.6g m, tau_el = %.6g s, tau_p = %.6g s, mu = %.6g Pa s"
      % (N, L, n, d, tau_el, tau_p, mu))
print("Q = %.6g C, m = %.6g kg, rho = %.6g kg/m3" % (Q, m, rho))
if dt:
    print("deltaT = %.6g s: d_C/delta_l = %.4g at q_p^2 of Eq. 25" % (dt, dC/(w*dt)))
