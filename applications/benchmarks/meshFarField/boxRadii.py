#!/usr/bin/env python3
"""meshPoisson's force error against the exact image solution in the
grounded unit box at small shape radii (2 to 4 cells).

Single charges (interior, near a wall with the shape cut, edges, corners)
and pairs of opposite charges (in the middle and near an edge, 0.4 to 3.2
shape radii apart, random directions), each case alone in the box, at a
mesh of n^3 cells. Reference: tests/tools/groundedBox.py (Ewald sum of the
images), independent of the code under test. Prints the error of every
case and the largest per radius, with meshPoisson's lattice correction
(the default) and without it (latticeCorrectionSources 0).

    boxRadii.py [--n 32] [--cells 2 2.5 3 4] [--coeffs "..."] [--np P]
                [--work DIR]
"""
import argparse
import os
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(HERE, "..", "..", "..", "tests", "tools"))
from farFieldCase import FarFieldCase  # noqa: E402
import groundedBox as gb  # noqa: E402

# The single charges of tests/cases/meshFarField.sh (singleCharges)
SINGLES = np.array([[0.3, 0.55, 0.45], [0.62, 0.28, 0.7], [0.05, 0.5, 0.5],
                    [0.1, 0.4, 0.6], [0.1, 0.1, 0.5], [0.1, 0.1, 0.1],
                    [0.15, 0.15, 0.15], [0.2, 0.7, 0.85]])
# Pair separations in shape radii, and the pairs' midpoints
SEPARATIONS = (0.4, 1.2, 1.6, 3.2)
MIDPOINTS = np.array([[0.5, 0.45, 0.55], [0.22, 0.22, 0.6]])


def cases(R, seed=3):
    """(name, positions, charges) of every case at shape radius R"""
    rng = np.random.default_rng(seed)
    out = [(f"single {x}", x[None, :], np.array([1e-9])) for x in SINGLES]
    for m in MIDPOINTS:
        for s in SEPARATIONS:
            u = rng.normal(size=3)
            u /= np.linalg.norm(u)
            x = m + np.outer([-0.5, 0.5], s*R*u)
            out.append((f"pair {s} R at {m}", x, np.array([1e-9, -1e-9])))
    return out


def errors(name, x, q, n, R, coeffs, work, nProcs=1):
    """Largest relative force error of the case's charges"""
    c = FarFieldCase(work, x, q, 1.0, n, "meshPoisson", f"radius {R}; {coeffs}")
    c.run(nProcs)
    E = c.fields()[0]
    ref = gb.field(x, q, 1.0)
    return np.max(np.linalg.norm(E - ref, axis=1)/np.linalg.norm(ref, axis=1))


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--n", type=int, default=32, help="cells per side")
    ap.add_argument("--cells", type=float, nargs="+", default=[2, 2.5, 3, 4],
                    help="shape radii in cells")
    ap.add_argument("--coeffs", default="", help="more meshPoissonCoeffs entries")
    ap.add_argument("--work", default=os.path.join(HERE, "runs", "boxRadii"))
    ap.add_argument("--np", type=int, default=1, help="processors")
    a = ap.parse_args()
    print(f"grounded unit box, h = 1/{a.n}, meshPoisson {a.coeffs}", flush=True)
    variants = [("without", "latticeCorrectionSources 0;"), ("with", "")]
    summary = []
    for cells in a.cells:
        R = cells/a.n
        worst = {}
        for k, (name, x, q) in enumerate(cases(R)):
            kind = name.split()[0]
            line = []
            for label, extra in variants:
                e = errors(name, x, q, a.n, R, f"{a.coeffs} {extra}",
                           f"{a.work}/{label}/R{cells}_{k}", a.np)
                worst[(kind, label)] = max(worst.get((kind, label), 0.0), e)
                line.append(f"{label} {100*e:.2f} %")
            print(f"  R = {cells} cells, {name}: " + ", ".join(line), flush=True)
        summary.append((cells, worst))
    print("| shape radius [cells] | largest single, without / with the lattice "
          "correction | largest pair, without / with |")
    print("|---|---|---|")
    for cells, w in summary:
        print(f"| {cells} | {100*w[('single', 'without')]:.2f} / "
              f"{100*w[('single', 'with')]:.2f} % | {100*w[('pair', 'without')]:.2f} / "
              f"{100*w[('pair', 'with')]:.2f} % |")


if __name__ == "__main__":
    main()
