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

    pipe_blockmesh(a, length, n) blockMeshDict body: a pipe of radius a
                                 about the z axis, an O-grid (inner square
                                 with n x n cells, four outer blocks with
                                 arc edges), cyclic ends; patch walls

    graded_box_blockmesh(L, n, g) blockMeshDict body: the box [0, L]^3,
                                 n^3 cells graded g:1 in each direction

The pipe's exact field is tests/tools/groundedCylinder.py (the grounded
infinite cylinder, periodic along z; two independent series, checked by its
--selftest), the box's tests/tools/groundedBox.py (image sums).

    curvedCavities.py [--cavity sphere|pipe|gradedBox] [--n 12 16 24] [--radius 0.2]
                      [--coeffs "ENTRIES"] [--cloud N] [--work DIR]
        prints the force error of meshPoisson for single charges at several
        distances from the centre (the axis), a pair of opposite charges and,
        with --cloud, N random charges (median |E exact| and error; the
        pipe's series reference takes 30 s for 10 charges, growing as N^2)
"""
import argparse
import os
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(HERE, "..", "..", "..", "tests", "tools"))
from groundedCylinder import field as cylinder_field   # noqa: E402
from groundedBox import field as box_field             # noqa: E402
K_COULOMB = 1.0/(4.0*np.pi*8.8541878128e-12)


def _point(p):
    """A blockMeshDict point (x y z), exact to the last bit."""
    return "(%r %r %r)" % tuple(float(t) for t in p)


def sphere_blockmesh(a, n):
    c = 0.3*a
    m = max(1, int(round(n*(a - c)/(2*c))))
    v = a/np.sqrt(3.0)
    inner = [(-c, -c, -c), (c, -c, -c), (c, c, -c), (-c, c, -c),
             (-c, -c, c), (c, -c, c), (c, c, c), (-c, c, c)]
    outer = [(-v, -v, -v), (v, -v, -v), (v, v, -v), (-v, v, -v),
             (-v, -v, v), (v, -v, v), (v, v, v), (-v, v, v)]
    verts = "\n".join("    " + _point(p) for p in inner) + "\n" \
        + "\n".join("    project %s (sphere)" % _point(p) for p in outer)
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


def pipe_blockmesh(a, length, n):
    """blockMeshDict body: a pipe of radius a about the z axis, 0 <= z <=
    length, meshed as an O-grid (an inner square of half-size 0.5 a/sqrt(2)
    with n x n cells, four outer blocks with arc edges and about the same
    radial spacing), cyclic ends; patch walls."""
    s = 0.5*a/np.sqrt(2.0)
    c = a/np.sqrt(2.0)
    # radial cells: the outer blocks span 0.5 a along the diagonal
    m = max(1, int(round(n*0.5*a/(2*s))))
    nz = max(1, int(round(n*length/(2*s))))
    layer = [(-s, -s), (s, -s), (s, s), (-s, s), (-c, -c), (c, -c), (c, c), (-c, c)]
    verts = "\n".join("    " + _point((x, y, z)) for z in (0.0, length) for x, y in layer)
    hexes = [("0 1 2 3", (n, n, nz)), ("4 5 1 0", (n, m, nz)), ("5 6 2 1", (n, m, nz)),
             ("6 7 3 2", (n, m, nz)), ("7 4 0 3", (n, m, nz))]
    up = lambda h: " ".join(str(int(v) + 8) for v in h.split())
    bl = "\n".join(f"    hex ({h} {up(h)}) ({k[0]} {k[1]} {k[2]}) simpleGrading (1 1 1)"
                   for h, k in hexes)
    arcs = []
    for z, o in ((0.0, 0), (length, 8)):
        for (i, j), mid in zip(((4, 5), (5, 6), (6, 7), (7, 4)),
                               ((0, -a), (a, 0), (0, a), (-a, 0))):
            arcs.append(f"    arc {i + o} {j + o} {_point((mid[0], mid[1], z))}")
    walls = " ".join(f"({i} {j} {j + 8} {i + 8})" for i, j in ((4, 5), (5, 6), (6, 7), (7, 4)))
    ends = lambda o: " ".join("(" + " ".join(str(int(v) + o) for v in h.split()) + ")"
                              for h, _ in hexes)
    return f"""
scale 1;
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
""" + "\n".join(arcs) + f"""
);
boundary
(
    walls {{ type wall; faces ({walls}); }}
    z0 {{ type cyclic; neighbourPatch z1; faces ({ends(0)}); }}
    z1 {{ type cyclic; neighbourPatch z0; faces ({ends(8)}); }}
);
"""


def graded_box_blockmesh(L, n, grading):
    """blockMeshDict body: the box [0, L]^3 with n^3 cells, each direction
    graded by `grading` (last cell / first cell); patch walls."""
    g = float(grading)
    return f"""
scale 1;
vertices
(
    (0 0 0) ({L!r} 0 0) ({L!r} {L!r} 0) (0 {L!r} 0)
    (0 0 {L!r}) ({L!r} 0 {L!r}) ({L!r} {L!r} {L!r}) (0 {L!r} {L!r})
);
blocks
(
    hex (0 1 2 3 4 5 6 7) ({n} {n} {n}) simpleGrading ({g!r} {g!r} {g!r})
);
edges ();
boundary
(
    walls {{ type wall; faces ((0 4 7 3) (1 2 6 5) (0 1 5 4) (3 7 6 2) (0 3 2 1) (4 5 6 7)); }}
);
"""


def main():
    from farFieldCase import FarFieldCase
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--n", type=int, nargs="+", default=[12, 16, 24])
    ap.add_argument("--radius", type=float, default=0.2)
    ap.add_argument("--cavity", choices=("sphere", "pipe", "gradedBox"), default="sphere")
    ap.add_argument("--work", default=None)
    ap.add_argument("--coeffs", default="", help="further meshPoisson entries")
    ap.add_argument("--cloud", type=int, default=0,
                    help="also a random cloud of this many charges of +-1 nC within 0.85 of "
                         "the centre (axis): median and largest force error")
    ap.add_argument("--pairs", type=int, default=0,
                    help="also this many pairs of opposite charges (+-1 nC) at random places "
                         "within 0.85 of the centre (the pipe: of its axis, anywhere along it; "
                         "its first pair 0.85 apart across the cyclic end): the larger force error")
    a = ap.parse_args()
    work = a.work or os.path.join(HERE, "runs", a.cavity)
    rng = np.random.default_rng(5)
    pipe = a.cavity == "pipe"
    box = a.cavity == "gradedBox"
    # the pipe: radius 1, period 2 along z, charges about z = 1; the box:
    # [0, 2]^3 graded 3:1, charges about its centre
    length = 2.0
    centre = np.array([0, 0, 1.0]) if pipe else np.ones(3) if box else np.zeros(3)
    cases = []
    for rr in (0.0, 0.3, 0.6, 0.8, 0.9):
        u = rng.normal(size=3)
        if pipe:
            u[2] = 0
        cases.append((f"single r = {rr}", np.array([centre + rr*u/np.linalg.norm(u)]), np.array([1e-9])))
    u = rng.normal(size=3)
    if pipe:
        u[2] = 0
    u /= np.linalg.norm(u)
    side = np.cross(u, [1, 0, 0] if pipe else [0, 0, 1])
    side /= np.linalg.norm(side)
    cases.append(("pair 0.2 apart at r = 0.5", np.array([centre + 0.5*u, centre + 0.5*u + 0.2*side]),
                  np.array([1e-9, -1e-9])))
    if a.cloud:
        cr = np.random.default_rng(1)
        u = cr.normal(size=(a.cloud, 3))
        if pipe:
            u[:, 2] = 0
        u /= np.linalg.norm(u, axis=1)[:, None]
        xc = centre + 0.85*u*cr.random(a.cloud)[:, None]**(1/2 if pipe else 1/3)
        if pipe:
            xc[:, 2] = centre[2] + 0.85*(2*cr.random(a.cloud) - 1)
        if box:
            xc = centre + 0.85*(2*cr.random((a.cloud, 3)) - 1)
        cases.append((f"cloud of {a.cloud}", xc, cr.choice([-1e-9, 1e-9], a.cloud)))
    pr = np.random.default_rng(5)
    for k in range(a.pairs):
        if pipe and k == 0:
            x = np.array([[0.3, 0.4, 0.1], [-0.5, 0.2, 1.95]])
        else:
            while True:
                x = pr.uniform(-0.85, 0.85, size=(2, 3))
                if pipe:
                    x[:, 2] = pr.uniform(0, length, 2)
                    if np.all(np.hypot(x[:, 0], x[:, 1]) < 0.85):
                        break
                elif np.all(np.linalg.norm(x, axis=1) < 0.85):
                    x += centre
                    break
        cases.append((f"pair {k}", x, np.array([1e-9, -1e-9])))
    print("| case | |E exact| [V/m] | " + " | ".join(f"error n = {n}" for n in a.n) + " |")
    print("|---|--:|" + "--:|"*len(a.n))
    for name, x, q in cases:
        ref = cylinder_field(x, q, 1.0, length) if pipe \
            else box_field(x, q, 2.0) if box else kelvin_field(x, q, 1.0)
        errs = []
        for n in a.n:
            mesh = pipe_blockmesh(1.0, length, n) if pipe \
                else graded_box_blockmesh(2.0, n, 3) if box else sphere_blockmesh(1.0, n)
            c = FarFieldCase(os.path.join(work, f"{name.replace(' ', '_')}_{n}"), x, q, 1.0, n,
                             "meshPoisson", f"radius {a.radius}; {a.coeffs}", blockMesh=mesh)
            c.run()
            E = c.fields()[0]
            scale = np.linalg.norm(ref, axis=1)
            if name.startswith("cloud"):
                e = np.linalg.norm(E - ref, axis=1)/scale
                errs.append(f"median {np.median(e):.2e}, largest {e.max():.2e}")
            elif np.all(scale < 1e-12*K_COULOMB*1e-9):
                errs.append(f"{np.abs(E).max()/(K_COULOMB*1e-9/a.radius**2):.1e} (abs)")
            else:
                errs.append(f"{np.max(np.linalg.norm(E - ref, axis=1)/scale):.2e}")
        magRef = np.median(np.linalg.norm(ref, axis=1)) if name.startswith("cloud") \
            else np.linalg.norm(ref[0])
        print(f"| {name} | {magRef:.3e} | " + " | ".join(errs) + " |", flush=True)


if __name__ == "__main__":
    main()
