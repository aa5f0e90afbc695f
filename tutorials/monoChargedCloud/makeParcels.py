#!/usr/bin/python3
"""Write constant/parcels and constant/carrierProperties of the mono-charged
cloud of Boutsikakis 2023 section 3: N particles (default 1e4) at uniformly
random positions, at rest, in the cube of edge L (default 2 pi m, scaled as
L = 2 pi (N/1e4)^(1/3) so the number density stays 40.3 /m^3), charge
Q = 5 nC, mass 1.8e-4 kg (section 3.3), density 2750 kg/m^3; the numerical
dissipation -u/tau_p, tau_p = 650 tau_el (section 3), is Stokes drag in a
carrier at rest with mu = rho d^2/(18 tau_p).

    makeParcels.py [N] [seed]
"""
import math, sys
import numpy as np

N = int(float(sys.argv[1])) if len(sys.argv) > 1 else 10000
seed = int(sys.argv[2]) if len(sys.argv) > 2 else 1
k = 8.9875517923e9
Q, m, rho = 5e-9, 1.8e-4, 2750.0
L = 2*math.pi*(N/1e4)**(1/3)
d = (6*m/(math.pi*rho))**(1/3)
n = N/L**3
tau_el = math.sqrt(3*m/(2*k*n))/Q                       # Eq. (26)
tau_p = 650*tau_el
mu = rho*d**2/(18*tau_p)

rng = np.random.default_rng(seed)
x = L*rng.random((N, 3))
with open("constant/parcels", "w") as f:
    f.write("// Written by makeParcels.py\nparcels\n(\n")
    for p in x:
        f.write("    { position (%.10g %.10g %.10g); d %.10g; q %g; }\n" % (p[0], p[1], p[2], d, Q))
    f.write(");\n")
with open("constant/carrierProperties", "w") as f:
    f.write("""FoamFile { version 2.0; format ascii; class dictionary; object carrierProperties; }
// Written by makeParcels.py: Stokes drag with tau_p = 650 tau_el = %.6g s
rho 0;
mu  %.10g;
U   (0 0 0);
""" % (tau_p, mu))
with open("system/blockMeshDict") as f:
    s = f.read()
import re
s = re.sub(r"^scale .*?;", "scale   %.16g;" % L, s, flags=re.M)
with open("system/blockMeshDict", "w") as f:
    f.write(s)
print("N = %d, L = %.6g m, n = %.6g /m3, d = %.6g m, tau_el = %.6g s, tau_p = %.6g s, mu = %.6g Pa s"
      % (N, L, n, d, tau_el, tau_p, mu))
