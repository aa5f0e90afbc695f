#!/usr/bin/env python3
"""Curved grounded cavities for the mesh far field: a sphere meshed as users
mesh it (blockMesh, seven blocks, the outer vertices, edges and faces
projected onto the sphere) and the exact field of point charges inside it
(Kelvin's images), independent of the code under test.

    sphere_blockmesh(a, n)       blockMeshDict body (for FarFieldCase's
                                 blockMesh=): sphere of radius a about the
                                 origin, an inner cube of half-size 0.3 a
                                 with n^3 cells, six projected blocks with
                                 about the same radial spacing; patch walls
    kelvin_field(x, q, a)        (N,3) field [V/m] at each charge from all
                                 other charges and all images (its own
                                 included), eps_r = 1

    curvedCavities.py [--n 12 16 24] [--radius 0.2] [--work DIR]
        prints the force error of meshPoisson for single charges at several
        distances from the centre and a pair of opposite charges
"""
import argparse
import os
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
K_COULOMB = 1.0/(4.0*np.pi*8.8541878128e-12)


def sphere_blockmesh(a, n):
    c = 0.3*a
    m = max(1, int(round(n*(a - c)/(2*c))))
    v = a/np.sqrt(3.0)
    inner = [(-c, -c, -c), (c, -c, -c), (c, c, -c), (-c, c, -c),
             (-c, -c, c), (c, -c, c), (c, c, c), (-c, c, c)]
    outer = [(-v, -v, -v), (v, -v, -v), (v, v, -v), (-v, v, -v),
             (-v, -v, v), (v, -v, v), (v, v, v), (-v, v, v)]
    f = lambda p: "(%r %r %r)" % tuple(float(t) for t in p)
    verts = "\n".join("    " + f(p) for p in inner) + "\n" \
        + "\n".join("    project %s (sphere)" % f(p) for p in outer)
    # centre block, then one block per face of the inner cube (inner face
    # to projected outer face; right-handed, the third direction radial)
    blocks = [("0 1 2 3 4 5 6 7", (n, n, n))] + [(h, (n, n, m)) for h in (
        "8 9 10 11 0 1 2 3", "4 5 6 7 12 13 14 15", "8 12 13 9 0 4 5 1",
        "3 7 6 2 11 15 14 10", "8 11 15 12 0 3 7 4", "1 2 6 5 9 10 14 13")]
    bl = "\n".join(f"    hex ({h}) ({k[0]} {k[1]} {k[2]}) simpleGrading (1 1 1)"
                   for h, k in blocks)
    edges = ("8 9", "9 10", "10 11", "11 8", "12 13", "13 14", "14 15",
             "15 12", "8 12", "9 13", "10 14", "11 15")
    faces = ("(8 11 10 9)", "(12 13 14 15)", "(8 9 13 12)", "(11 15 14 10)",
             "(8 12 15 11)", "(9 10 14 13)")
    return f"""
scale 1;
geometry {{ sphere {{ type sphere; origin (0 0 0); radius {a!r}; }} }}
vertices
(
{verts}
);
blocks
(
{bl}
);
edges
(
""" + "\n".join(f"    project {e} (sphere)" for e in edges) + """
);
faces
(
""" + "\n".join(f"    project {x} sphere" for x in faces) + f"""
);
boundary
(
    walls {{ type wall; faces ({" ".join(faces)}); }}
);
"""


def kelvin_field(x, q, a):
    """Field at each charge in the grounded sphere of radius a about the
    origin: the other charges plus every charge's Kelvin image, charge
    -q a/|x| at a^2 x/|x|^2 (a charge at the centre: an image at infinity,
    no field)."""
    x = np.atleast_2d(np.asarray(x, float))
    q = np.atleast_1d(np.asarray(q, float))
    E = np.zeros_like(x)
    r = np.linalg.norm(x, axis=1)
    for i in range(len(x)):
        for j in range(len(x)):
            if j != i:
                d = x[i] - x[j]
                E[i] += q[j]*d/np.linalg.norm(d)**3
            if r[j] > 0:
                xi = a*a*x[j]/r[j]**2
                d = x[i] - xi
                E[i] += -q[j]*a/r[j]*d/np.linalg.norm(d)**3
    return K_COULOMB*E


def main():
    from farFieldCase import FarFieldCase
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--n", type=int, nargs="+", default=[12, 16, 24])
    ap.add_argument("--radius", type=float, default=0.2)
    ap.add_argument("--work", default=os.path.join(HERE, "runs", "sphere"))
    a = ap.parse_args()
    rng = np.random.default_rng(5)
    cases = []
    for rr in (0.0, 0.3, 0.6, 0.8, 0.9):
        u = rng.normal(size=3)
        cases.append((f"single r = {rr}", np.array([rr*u/np.linalg.norm(u)]), np.array([1e-9])))
    u = rng.normal(size=3); u /= np.linalg.norm(u)
    cases.append(("pair 0.2 apart at r = 0.5", np.array([0.5*u, 0.5*u + 0.2*np.cross(u, [0, 0, 1])/np.linalg.norm(np.cross(u, [0, 0, 1]))]), np.array([1e-9, -1e-9])))
    print(f"| case | |E exact| [V/m] | " + " | ".join(f"error n = {n}" for n in a.n) + " |")
    print("|---|--:|" + "--:|"*len(a.n))
    for name, x, q in cases:
        ref = kelvin_field(x, q, 1.0)
        errs = []
        for n in a.n:
            c = FarFieldCase(os.path.join(a.work, f"{name.replace(' ', '_')}_{n}"), x, q, 1.0, n,
                             "meshPoisson", f"radius {a.radius};", blockMesh=sphere_blockmesh(1.0, n))
            c.run()
            E = c.fields()[0]
            scale = np.linalg.norm(ref, axis=1)
            if np.all(scale == 0):
                errs.append(f"{np.abs(E).max()/(K_COULOMB*1e-9/a.radius**2):.1e} (abs)")
            else:
                errs.append(f"{np.max(np.linalg.norm(E - ref, axis=1)/scale):.2e}")
        print(f"| {name} | {np.linalg.norm(ref[0]):.3e} | " + " | ".join(errs) + " |", flush=True)


if __name__ == "__main__":
    main()
