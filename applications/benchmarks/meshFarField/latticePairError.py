#!/usr/bin/env python3
"""The mesh far field's pair force at a few cells per shape radius, on a
model of meshPoisson's discretisation on a uniform cubic mesh: the 7-point
finite-volume Laplacian, the central-difference gradient (what the
least-squares gradient is on a uniform mesh), S2 weights (R - r) V at the
cell centres for the deposition and the same weights for the average over
the partner's shape. One shape at a random sub-cell offset in a block of
(2N+1)^3 cells with the exact S2 potential on its boundary; the pair force
at separations s in random directions against the exact S2-S2 force
(1 - shapedCorrection(s/R)) k q^2/s^2 (Hockney & Eastwood Eq. 8-73).

Prints, per separation, the radial error's mean, standard deviation and
largest magnitude, and the tangential error, over offsets and directions:
the scatter with the position in the cell that a mean (tabulated)
correction cannot remove. This is a model of the operator, not the code:
it isolates the operator's truncation error from walls and meshes.

    latticePairError.py R [N] [trials] [--weights sampled|moments|integrated]

R: shape radius in cells; N: half width of the block (default 18);
trials: random offsets (default 4), 8 directions each.
"""
import argparse
import numpy as np
import scipy.sparse as sp
import scipy.sparse.linalg as sla


def shaped_correction(xi):
    """1 - f(xi): exact minus the S2-S2 force over Coulomb (meshPoisson.H)"""
    if xi >= 2:
        return 0.0
    x2 = xi*xi
    if xi < 1:
        return 1 - x2*xi*(224 + x2*(-224 + xi*(70 + xi*(48 - 21*xi))))/140
    return 1 - (12 + x2*(-224 + xi*(896 + xi*(-840 + xi*(224 + xi*(
        70 + xi*(-48 + 7*xi)))))))/140


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("R", type=float)
    ap.add_argument("N", type=int, nargs="?", default=18)
    ap.add_argument("trials", type=int, nargs="?", default=4)
    ap.add_argument("--weights", default="sampled",
                    choices=["sampled", "moments", "integrated"])
    a = ap.parse_args()
    R, N = a.R, a.N
    rng = np.random.default_rng(1)
    n = 2*N + 1
    idx = np.arange(n) - N
    X, Y, Z = np.meshgrid(idx, idx, idx, indexing="ij")
    I = sp.identity(n, format="csr")
    D = sp.diags([np.ones(n - 1), -2*np.ones(n), np.ones(n - 1)], [-1, 0, 1])
    L = (sp.kron(sp.kron(D, I), I) + sp.kron(sp.kron(I, D), I)
         + sp.kron(sp.kron(I, I), D)).tocsc()
    lu = sla.splu(-L)
    k = 1/(4*np.pi)

    def weights(x):
        if a.weights == "integrated":
            g = (np.arange(4) + 0.5)/4 - 0.5
            w = np.zeros(X.shape)
            for p in g:
                for q in g:
                    for s in g:
                        r = np.sqrt((X + p - x[0])**2 + (Y + q - x[1])**2
                                    + (Z + s - x[2])**2)
                        w += np.where(r < R, R - r, 0.0)
            return w/w.sum()
        r = np.sqrt((X - x[0])**2 + (Y - x[1])**2 + (Z - x[2])**2)
        w = np.where(r < R, R - r, 0.0)
        if a.weights == "moments":
            # zero dipole moment about x: w (1 + a.d)
            m = w > 0
            d = np.stack([X[m] - x[0], Y[m] - x[1], Z[m] - x[2]], 1)
            ww = w[m]
            M = (ww[:, None, None]*d[:, :, None]*d[:, None, :]).sum(0)
            c = np.linalg.solve(M, -(ww[:, None]*d).sum(0))
            w[m] = ww*(1 + d @ c)
        return w/w.sum()

    def potential(x):
        w = weights(x)
        b = w.copy()
        for ax in range(3):
            for side in (-1, 1):
                sl = [slice(None)]*3
                sl[ax] = 0 if side < 0 else n - 1
                pos = [X[tuple(sl)].astype(float), Y[tuple(sl)].astype(float),
                       Z[tuple(sl)].astype(float)]
                pos[ax] = pos[ax] + side
                r = np.sqrt((pos[0] - x[0])**2 + (pos[1] - x[1])**2
                            + (pos[2] - x[2])**2)
                b[tuple(sl)] += k/r
        return lu.solve(b.ravel()).reshape(n, n, n), w

    separations = (1.2, 1.6, 2.0, 2.56, 3.2)
    res = {s: [] for s in separations}
    for _ in range(a.trials):
        o = rng.random(3) - 0.5
        phi, w = potential(o)
        E = [-(np.roll(phi, -1, ax) - np.roll(phi, 1, ax))/2 for ax in range(3)]
        self_force = np.linalg.norm([(w*E[ax]).sum() for ax in range(3)])
        print(f"offset {o}: self force {self_force/(k/R**2):.2e} k/R^2")
        for sR in separations:
            s = sR*R
            for _ in range(8):
                u = rng.normal(size=3)
                u /= np.linalg.norm(u)
                wb = weights(o + s*u)
                F = np.array([(wb*E[ax]).sum() for ax in range(3)])
                Fex = (1 - shaped_correction(s/R))*k/s**2
                d = F - Fex*u
                res[sR].append((d @ u/Fex, np.linalg.norm(d - (d @ u)*u)/Fex))
    print(f"\nR = {R} cells, weights {a.weights}: pair force error [%]")
    print("| s/R | radial mean | std | largest | tangential mean | largest |")
    print("|---|---|---|---|---|---|")
    for sR, v in res.items():
        v = 100*np.array(v)
        print(f"| {sR} | {v[:, 0].mean():.2f} | {v[:, 0].std():.2f} "
              f"| {np.abs(v[:, 0]).max():.2f} | {v[:, 1].mean():.2f} "
              f"| {v[:, 1].max():.2f} |")


if __name__ == "__main__":
    main()
