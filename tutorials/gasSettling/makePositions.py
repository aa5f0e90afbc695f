#!/usr/bin/env python3
"""Write constant/cloudPositions: N random parcel positions (fixed seed) in
the box  x0 < x < x1, y0 < y < y1, z0 < z < z1  [m], no two closer than
dmin (rejection sampling; default 0: independent points); or with
--lattice NX NY NZ the centres of an NX x NY x NZ division of the box.

    makePositions.py [--n 300] [--box x0 x1 y0 y1 z0 z1] [--dmin D]
                     [--lattice NX NY NZ]
"""
import argparse

import numpy as np

ap = argparse.ArgumentParser(description=__doc__)
ap.add_argument("--n", type=int, default=300)
ap.add_argument("--box", type=float, nargs=6,
                default=[0.5e-3, 4.5e-3, 0.5e-3, 9.5e-3, 10e-3, 18e-3])
ap.add_argument("--dmin", type=float, default=0)
ap.add_argument("--lattice", type=int, nargs=3)
ap.add_argument("--out", default="constant/cloudPositions")
a = ap.parse_args()

rng = np.random.default_rng(20080625)
lo, hi = np.array(a.box[0::2]), np.array(a.box[1::2])
if a.lattice:
    n = np.array(a.lattice)
    ijk = np.stack(np.meshgrid(*[np.arange(k) for k in n], indexing="ij"),
                   axis=-1).reshape(-1, 3)
    x = lo + (ijk + 0.5)*(hi - lo)/n
    a.n = len(x)
elif a.dmin > 0:
    x = np.empty((a.n, 3))
    n, tries = 0, 0
    while n < a.n:
        p = lo + (hi - lo)*rng.random(3)
        tries += 1
        if tries > 1000*a.n:
            raise SystemExit(f"makePositions: cannot place {a.n} points"
                             f" {a.dmin} apart in the box")
        if n == 0 or np.min(np.sum((x[:n] - p)**2, axis=1)) >= a.dmin**2:
            x[n] = p
            n += 1
else:
    x = lo + (hi - lo)*rng.random((a.n, 3))

with open(a.out, "w") as f:
    f.write("""FoamFile
{
    version     2.0;
    format      ascii;
    class       vectorField;
    location    "constant";
    object      cloudPositions;
}

""")
    f.write(f"{a.n}\n(\n")
    for p in x:
        f.write("(%.9g %.9g %.9g)\n" % tuple(p))
    f.write(")\n")
