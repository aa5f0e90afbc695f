#!/usr/bin/env python3
"""Write constant/parcels: N neutral PTFE spheres of diameter d, placed at
random without overlap in the shaker (a cylinder of radius 30 mm, height
60 mm, 0.5 mm clear of the walls and of each other), with small random
velocities; the random numbers from the seed (a run's repetition).

    makeParcels.py N seed [d]       d in metres, default 12.7e-3
"""
import sys

import numpy as np

N = int(sys.argv[1])
rng = np.random.default_rng(int(sys.argv[2]))
d = float(sys.argv[3]) if len(sys.argv) > 3 else 12.7e-3
R, H, gap = 30e-3, 60e-3, 0.5e-3
r = 0.5*d
placed = []
for attempt in range(200000):
    if len(placed) == N:
        break
    rho = (R - r - gap)*np.sqrt(rng.random())
    phi = 2*np.pi*rng.random()
    x = np.array([rho*np.cos(phi), rho*np.sin(phi), r + gap + (H - d - 2*gap)*rng.random()])
    if all(np.linalg.norm(x - y) > d + gap for y in placed):
        placed.append(x)
if len(placed) < N:
    # Dense packings (about 40 spheres) are beyond random placement: the
    # sites of a square lattice of spacing d + gap inside the capsule, N of
    # them at random
    s = d + gap
    m = int((R - r - gap)//s) + 1
    sites = [np.array([i*s + 0.5*s*(m % 2 == 0), j*s + 0.5*s*(m % 2 == 0), r + gap + k*s])
             for i in range(-m, m + 1) for j in range(-m, m + 1)
             for k in range(int((H - d - 2*gap)//s) + 1)]
    sites = [x for x in sites if np.hypot(x[0], x[1]) <= R - r - gap]
    if len(sites) < N:
        sys.exit(f"makeParcels.py: room for {len(sites)} of {N} spheres")
    placed = [sites[i] for i in rng.choice(len(sites), N, replace=False)]

lines = []
for x in placed:
    U = 0.05*(2*rng.random(3) - 1)
    lines.append("    { position (%.9e %.9e %.9e); U (%.6e %.6e %.6e); d %g; q 0; }"
                 % (*x, *U, d))
open("constant/parcels", "w").write("parcels\n(\n" + "\n".join(lines) + "\n);\n")
print(f"{N} spheres of {d*1e3:g} mm, volume fraction "
      f"{N*np.pi/6*d**3/(np.pi*R**2*H):.4f}")
