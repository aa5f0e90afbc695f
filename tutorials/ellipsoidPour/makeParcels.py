#!/usr/bin/env python3
"""Write constant/parcels: N prolate ellipsoids (semi-axes 1, 0.5, 0.5 mm)
on a 5 x 5 lattice of layers (spacing 2.4 mm) in the 12 mm box, in uniformly
random orientations (Shoemake's quaternions) with small random velocities.

    makeParcels.py [N] [seed]
"""
import sys

import numpy as np

N = int(sys.argv[1]) if len(sys.argv) > 1 else 300
rng = np.random.default_rng(int(sys.argv[2]) if len(sys.argv) > 2 else 1)
lines = []
for i in range(N):
    layer, k = divmod(i, 25)
    x = 1.2e-3 + 2.4e-3*(k % 5)
    y = 1.2e-3 + 2.4e-3*(k//5)
    z = 3e-3 + 2.4e-3*layer
    u1, u2, u3 = rng.random(3)
    q = (np.sqrt(u1)*np.cos(2*np.pi*u3), np.sqrt(1 - u1)*np.sin(2*np.pi*u2),
         np.sqrt(1 - u1)*np.cos(2*np.pi*u2), np.sqrt(u1)*np.sin(2*np.pi*u3))
    U = 0.05*(rng.random(3) - 0.5)
    lines.append(f"    {{ position ({x:.6e} {y:.6e} {z:.6e}); U ({U[0]:.4f} {U[1]:.4f} {U[2]:.4f}); "
                 f"semiAxes (1e-3 5e-4 5e-4); quaternion ({q[0]:.12f} {q[1]:.12f} {q[2]:.12f} {q[3]:.12f}); q 0; }}")
open("constant/parcels", "w").write(
    "// Written by makeParcels.py\nparcels\n(\n" + "\n".join(lines) + "\n);\n")
print(f"wrote constant/parcels: {N} ellipsoids up to z = {3e-3 + 2.4e-3*((N - 1)//25):.4f} m")
