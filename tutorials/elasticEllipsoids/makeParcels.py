#!/usr/bin/python3
"""Write constant/parcels for elasticEllipsoids: for each aspect ratio
(1.5, 2, 5, 10; prolate, minor semi-axis 0.25 mm) nPairs pairs of
ellipsoids in uniformly random orientations with random spins (up to
200 rad/s), meeting at 1 m/s with a random off-centre offset, and nWall
ellipsoids falling at 1 m/s (with a random sliding velocity) onto the floor
z = 0. Each pair starts 20 um (along the approach) from touching, found with
the Perram-Wertheim test by bisection; sites are 12 mm apart so that
different pairs never meet.

    makeParcels.py [nPairs] [nWall] [seed]
"""
import sys
import numpy as np
from ellipsoidGeometry import perram_wertheim, shape_inverse

nPairs = int(sys.argv[1]) if len(sys.argv) > 1 else 6
nWall = int(sys.argv[2]) if len(sys.argv) > 2 else 6
seed = int(sys.argv[3]) if len(sys.argv) > 3 else 1
ratios = [1.5, 2, 5, 10]
b, gap, spacing, spin = 0.25e-3, 20e-6, 12e-3, 200.0
rng = np.random.default_rng(seed)


def random_quaternion():
    """Uniform random rotation (Shoemake 1992)."""
    u1, u2, u3 = rng.random(3)
    return np.array([np.sqrt(u1)*np.cos(2*np.pi*u3),
                     np.sqrt(1 - u1)*np.sin(2*np.pi*u2),
                     np.sqrt(1 - u1)*np.cos(2*np.pi*u2),
                     np.sqrt(u1)*np.sin(2*np.pi*u3)])


def random_spin():
    v = rng.normal(size=3)
    return spin*rng.random()*v/np.linalg.norm(v)


def touching_distance(M1, M2, offset, smax):
    """Centre distance along x at which the pair touches, for the lateral
    offset (0, y, z); None if it never overlaps."""
    def overlap(s):
        return perram_wertheim(M1, M2, np.array([s, *offset])) < 1
    if not overlap(0.0):
        return None
    lo, hi = 0.0, smax
    for _ in range(60):
        mid = 0.5*(lo + hi)
        lo, hi = (mid, hi) if overlap(mid) else (lo, mid)
    return hi


def parcel(x, U, axes, q, omega):
    f = lambda v: "(" + " ".join(f"{c:.17g}" for c in v) + ")"
    return (f"    {{ position {f(x)}; U {f(U)}; semiAxes {f(axes)};"
            f" quaternion {f(q)}; omega {f(omega)}; q 0; }}\n")


lines = []
site = 0
for ar in ratios:
    axes = np.array([ar*b, b, b])
    for _ in range(nPairs):
        while True:
            q1, q2 = random_quaternion(), random_quaternion()
            M1, M2 = shape_inverse(axes, q1), shape_inverse(axes, q2)
            offset = rng.uniform(-1, 1, 2)*0.8*axes[0]
            s = touching_distance(M1, M2, offset, 2.5*axes[0])
            if s is not None:
                break
        c1 = np.array([6e-3 + spacing*(site % 6), 6e-3 + spacing*(site//6), 18e-3])
        c2 = c1 + np.array([s + gap, *offset])
        lines.append(parcel(c1, (0.5, 0, 0), axes, q1, random_spin()))
        lines.append(parcel(c2, (-0.5, 0, 0), axes, q2, random_spin()))
        site += 1
wallSite = 0
for ar in ratios:
    axes = np.array([ar*b, b, b])
    for _ in range(nWall):
        q = random_quaternion()
        h = np.sqrt(shape_inverse(axes, q)[2, 2])    # support distance along z
        c = np.array([6e-3 + spacing*(wallSite % 6), 6e-3 + spacing*(wallSite//6), h + gap])
        U = (*rng.uniform(-0.3, 0.3, 2), -1.0)
        lines.append(parcel(c, U, axes, q, random_spin()))
        wallSite += 1

with open("constant/parcels", "w") as f:
    f.write(f"// Written by makeParcels.py: {len(ratios)*nPairs} pairs"
            f" ({nPairs} per aspect ratio {ratios}), then"
            f" {len(ratios)*nWall} wall impacts\nparcels\n(\n")
    f.writelines(lines)
    f.write(");\n")
print(f"constant/parcels: {len(ratios)*nPairs} pairs, {len(ratios)*nWall} wall impacts")
