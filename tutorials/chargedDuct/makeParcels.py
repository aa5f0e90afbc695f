#!/usr/bin/python3
"""Write constant/parcels for the chargedDuct tutorial (and shortDuct): N
PTFE ellipsoids (semi-axes 1 x 0.5 x 0.5 mm) at random, non-overlapping
positions (their bounding spheres 2.1 mm apart) in the upstream end of the
duct (5 mm < x < xMax), random orientations, velocity (2, 0, 0) m/s plus a
uniform random +-1 m/s per component (as from a feeder), uncharged.

    makeParcels.py [N] [seed] [xMax]     default 2000, 1, 0.15 m
"""
import sys
import numpy as np

N = int(sys.argv[1]) if len(sys.argv) > 1 else 2000
rng = np.random.default_rng(int(sys.argv[2]) if len(sys.argv) > 2 else 1)
xMax = float(sys.argv[3]) if len(sys.argv) > 3 else 0.15
lo = np.array([0.005, 1.2e-3, 1.2e-3])
hi = np.array([xMax, 0.02 - 1.2e-3, 0.02 - 1.2e-3])
dmin = 2.1e-3

# Random sequential addition on a cell grid
h = dmin
cells = {}
x = []
tries = 0
while len(x) < N:
    tries += 1
    if tries > 200*N:
        sys.exit(f"makeParcels: only {len(x)} of {N} parcels fit")
    p = lo + (hi - lo)*rng.random(3)
    c = tuple((p//h).astype(int))
    ok = True
    for dx in (-1, 0, 1):
        for dy in (-1, 0, 1):
            for dz in (-1, 0, 1):
                for j in cells.get((c[0] + dx, c[1] + dy, c[2] + dz), ()):
                    if np.sum((x[j] - p)**2) < dmin*dmin:
                        ok = False
    if ok:
        cells.setdefault(c, []).append(len(x))
        x.append(p)

with open("constant/parcels", "w") as f:
    for p in x:
        U = np.array([2.0, 0, 0]) + rng.uniform(-1, 1, 3)
        e = rng.uniform(0, 360, 3)
        f.write("{ position (%.9g %.9g %.9g); U (%.6g %.6g %.6g); "
                "semiAxes (1e-3 5e-4 5e-4); eulerAngles (%.3f %.3f %.3f); "
                "q 0; }\n" % (*p, *U, *e))
print(f"makeParcels: {N} parcels in constant/parcels")
