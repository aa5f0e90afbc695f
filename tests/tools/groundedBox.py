#!/usr/bin/env python3
"""Exact electrostatics of point charges inside a grounded rectangular box.

A grounded conducting box [0,Lx]x[0,Ly]x[0,Lz] (phi = 0 on all six walls)
around point charges q_j at x_j in a uniform medium of relative permittivity
eps_r. The method of images solves it exactly: reflecting a charge across the
walls, over and over, gives the 8 charges

    (s_x x, s_y y, s_z z) with charge q s_x s_y s_z,   s_* in {+1, -1},

repeated periodically with the period 2L = (2Lx, 2Ly, 2Lz). That cell of 8N
charges is neutral with zero dipole moment and odd under each reflection
x -> -x, y -> -y, z -> -z. Its Ewald sum (zero-mean periodic Green's function,
no surface term) is therefore the exact grounded-box solution: the field sum
converges absolutely, and the Ewald potential is odd across every wall, so it
is exactly zero there (no additive constant to fix). Real space (erfc) plus
reciprocal space (Gaussian-damped k-sum), vectorised numpy, parameters
chosen from tol (default 1e-13: about 1e-11 relative accuracy of the field,
checked by --selftest against tol = 1e-16).

SI units throughout: x, L in m, q in C, E in V/m, phi in V; the force on
charge i is q_i E_i. eps0 = 8.8541878128e-12 F/m (CODATA 2018, as
pairwiseCoulomb).

Insulating walls (zero normal field) on one axis: parity (+1, -1, -1) makes
the images across that axis of the same sign, so the sum is even there (the
rectangular duct with grounded sides and insulating ends); at least two axes
must be grounded (a neutral cell without dipole).

Python interface (import from tests/tools; every function also takes
parity=(px, py, pz), default (-1, -1, -1): all walls grounded):

    field(x, q, L, eps_r=1, tol=1e-13, origin=0)
        (N,3) field at each charge from all the other charges and all images
        (its own images included: the attraction to the walls), not itself.
    potential(x, q, L, ...)          (N,) the same for the potential
    field_at(points, x, q, L, ...)   (M,3) field at arbitrary points inside
                                     the box (none may coincide with a charge)
    potential_at(points, x, q, L, ...)  (M,) potential there
    image_sum(x, q, L, shells, ...)  (N,3) brute-force reference: the plain
                                     image sum over the (2 shells + 1)^3 cells
                                     of 8 images around the box, self excluded
                                     (converges to field(); observed ~ shells^-4)

    x: (N,3) positions strictly inside the box; q: (N,) charges; L: scalar or
    (Lx, Ly, Lz); origin: the box's lower corner (scalar or 3-vector).

Command line:

    groundedBox.py --L Lx[,Ly,Lz] [--origin x0[,y0,z0]] [--eps-r 1] [--tol 1e-13]
                   [--points pts.txt] [--potential] charges.txt [out.txt]

    charges.txt: lines 'x y z q'. Writes 'Ex Ey Ez' per charge (or, with
    --points, per line 'x y z' of pts.txt), plus a 4th column phi with
    --potential, to out.txt or stdout.

    groundedBox.py --selftest   checks (PASS:/FAIL: lines): centre symmetry,
                                single-plane image limit O((d/L)^2), zero
                                potential on the walls, tol convergence,
                                brute-force image shells converging to Ewald.

Example: field(np.array([[0.01, 0.5, 0.5]]), [1e-9], 1.0)[0] ~ (-2.247e4, 0, 0)
V/m (the image -q at 0.02 m: -k q/(2d)^2 = -2.247e4 V/m).
"""
import argparse
import math
import sys

import numpy as np

try:
    from scipy.special import erfc as _erfc
except ImportError:  # pragma: no cover - plain numpy fallback
    _erfc = np.vectorize(math.erfc, otypes=[float])

EPS0 = 8.8541878128e-12
_COST = 60.0            # relative cost of a k-vector term vs a real-space pair
K_COULOMB = 1.0/(4.0*math.pi*EPS0)


def _box(L, origin):
    L = np.broadcast_to(np.asarray(L, dtype=float), (3,)).copy()
    o = np.broadcast_to(np.asarray(origin, dtype=float), (3,)).copy()
    if np.any(L <= 0):
        raise ValueError(f"box lengths must be > 0, got {L}")
    return L, o


def _inside(x, L, what):
    if x.size and (np.any(x <= 0) or np.any(x >= L)):
        bad = np.nonzero(np.any((x <= 0) | (x >= L), axis=1))[0]
        raise ValueError(f"{what} {bad[:5].tolist()} not strictly inside the box (0, {L.tolist()})")


def _parity(parity):
    p = np.broadcast_to(np.asarray(parity, dtype=int), (3,))
    if np.any((p != 1) & (p != -1)) or np.count_nonzero(p == -1) < 2:
        raise ValueError(f"parity must be +1 (insulating) or -1 (grounded) per axis, "
                         f"with at least two grounded pairs of walls, got {parity}")
    return p


def images(x, q, L, parity=(-1, -1, -1)):
    """The 8N charges of one period (2L) of the image lattice.

    parity per axis: -1 for a pair of grounded walls (the image across one
    has the opposite charge), +1 for insulating walls (the same charge).
    With two or three grounded axes the cell is neutral with zero dipole.
    Returns (y, s, ident): positions (8N,3), charges (8N,), and for each
    original charge the index of its unreflected copy (= its own index).
    """
    p = _parity(parity)
    y, s = [], []
    for sx in (1, -1):
        for sy in (1, -1):
            for sz in (1, -1):
                sg = np.array([sx, sy, sz], dtype=float)
                y.append(x*sg)
                s.append(q*np.prod(np.where(p < 0, sg, 1.0)))
    return np.concatenate(y), np.concatenate(s), np.arange(len(x))


def _ewald(t, y, s, Lp, self_idx, tol):
    """Potential and field (without the Coulomb constant) at targets t of the
    periodic charges (y, s), period Lp. self_idx[i] >= 0: source self_idx[i]
    in the home cell is target i itself and is left out."""
    V = float(np.prod(Lp))
    T, S = len(t), len(y)
    p = math.sqrt(math.log(1.0/tol))
    # alpha balances the real-space pairs (~ T S rc^3/V) against the k-sum
    # (~ (T + S) kmax^3 V): alpha V^(1/3) ~ (T S/(T + S))^(1/6)
    alpha = max(math.sqrt(math.pi), (_COST*T*S/(T + S))**(1.0/6.0))/V**(1.0/3.0)
    rc = p/alpha
    kmax = 2.0*alpha*p
    phi = np.zeros(T)
    E = np.zeros((T, 3))

    # Real space: minimum-image displacement plus lattice shifts within rc
    nmax = np.ceil(rc/Lp).astype(int) + 1
    g = [np.arange(-n, n + 1) for n in nmax]
    sh = np.stack(np.meshgrid(*g, indexing="ij"), -1).reshape(-1, 3)*Lp
    sh = sh[np.linalg.norm(sh, axis=1) <= rc + 0.5*np.linalg.norm(Lp)]
    c2a = 2.0*alpha/math.sqrt(math.pi)
    chunk = max(1, int(2e5//max(1, S)))
    for a in range(0, T, chunk):
        b = min(T, a + chunk)
        d = t[a:b, None, :] - y[None, :, :]
        d -= Lp*np.round(d/Lp)
        own = self_idx[a:b]
        rows = np.nonzero(own >= 0)[0]
        for v in sh:
            r = d + v
            r2 = np.einsum("ijk,ijk->ij", r, r)
            if not np.any(v):
                r2[rows, own[rows]] = np.inf
            ii, jj = np.nonzero(r2 < rc*rc)
            if not len(ii):
                continue
            rv = r[ii, jj]
            rr = np.sqrt(r2[ii, jj])
            sm = s[jj]
            e = _erfc(alpha*rr)
            w = sm*(e/rr + c2a*np.exp(-(alpha*rr)**2))/(rr*rr)
            n = b - a
            phi[a:b] += np.bincount(ii, sm*e/rr, n)
            for c in range(3):
                E[a:b, c] += np.bincount(ii, w*rv[:, c], n)

    # Reciprocal space: half the k-space (k and -k alike), k != 0
    mm = np.ceil(kmax*Lp/(2.0*math.pi)).astype(int)
    g = [np.arange(-n, n + 1) for n in mm]
    m = np.stack(np.meshgrid(*g, indexing="ij"), -1).reshape(-1, 3)
    half = (m[:, 0] > 0) | ((m[:, 0] == 0) & (m[:, 1] > 0)) \
        | ((m[:, 0] == 0) & (m[:, 1] == 0) & (m[:, 2] > 0))
    kv = 2.0*math.pi*m[half]/Lp
    k2 = np.einsum("ij,ij->i", kv, kv)
    keep = k2 <= kmax*kmax
    kv, k2 = kv[keep], k2[keep]
    ak = 2.0*(4.0*math.pi/V)*np.exp(-k2/(4.0*alpha*alpha))/k2
    Sk = np.exp(-1j*(y @ kv.T)).T @ s                 # sum_j s_j e^{-ik.y_j}
    for a in range(0, T, 256):
        b = min(T, a + 256)
        z = np.exp(1j*(t[a:b] @ kv.T))*Sk             # (T,K)
        phi[a:b] += z.real @ ak
        E[a:b] += (z.imag*ak) @ kv

    # Own Gaussian screening cloud of an excluded charge (potential only;
    # its field at the charge is zero by symmetry). Neutral: no background.
    rows = np.nonzero(self_idx >= 0)[0]
    phi[rows] -= c2a*s[self_idx[rows]]
    return phi, E


def _evaluate(t, x, q, L, eps_r, tol, origin, at_charges, parity=(-1, -1, -1)):
    L, o = _box(L, origin)
    x = np.atleast_2d(np.asarray(x, dtype=float)) - o
    q = np.atleast_1d(np.asarray(q, dtype=float))
    if x.shape != (len(q), 3):
        raise ValueError("x must be (N,3) and q (N,)")
    _inside(x, L, "charges")
    y, s, ident = images(x, q, L, parity)
    if at_charges:
        t, self_idx = x, ident
    else:
        t = np.atleast_2d(np.asarray(t, dtype=float)) - o
        _inside(t, L, "points")
        for i, ti in enumerate(t):
            if np.any(np.all(ti == x, axis=1)):
                raise ValueError(f"point {i} coincides with a charge: no finite field")
        self_idx = -np.ones(len(t), dtype=int)
    phi, E = _ewald(t, y, s, 2.0*L, self_idx, tol)
    k = K_COULOMB/eps_r
    return k*phi, k*E


def field(x, q, L, eps_r=1.0, tol=1e-13, origin=0.0, parity=(-1, -1, -1)):
    """Field [V/m] at each charge: all other charges and all images, not self."""
    return _evaluate(None, x, q, L, eps_r, tol, origin, True, parity)[1]


def potential(x, q, L, eps_r=1.0, tol=1e-13, origin=0.0, parity=(-1, -1, -1)):
    """Potential [V] at each charge: all other charges and all images, not self."""
    return _evaluate(None, x, q, L, eps_r, tol, origin, True, parity)[0]


def field_at(points, x, q, L, eps_r=1.0, tol=1e-13, origin=0.0, parity=(-1, -1, -1)):
    """Field [V/m] at arbitrary points strictly inside the box."""
    return _evaluate(points, x, q, L, eps_r, tol, origin, False, parity)[1]


def potential_at(points, x, q, L, eps_r=1.0, tol=1e-13, origin=0.0, parity=(-1, -1, -1)):
    """Potential [V] at arbitrary points strictly inside the box."""
    return _evaluate(points, x, q, L, eps_r, tol, origin, False, parity)[0]


def image_sum(x, q, L, shells, eps_r=1.0, origin=0.0, parity=(-1, -1, -1)):
    """Brute force: the image sum over the (2 shells + 1)^3 periods of 8N
    image charges nearest the box (a cube of whole neutral cells), self
    excluded. Converges to field() as shells grows."""
    L, o = _box(L, origin)
    x = np.atleast_2d(np.asarray(x, dtype=float)) - o
    q = np.atleast_1d(np.asarray(q, dtype=float))
    y, s, ident = images(x, q, L, parity)
    n = np.arange(-shells, shells + 1)
    sh = np.stack(np.meshgrid(n, n, n, indexing="ij"), -1).reshape(-1, 3)*(2.0*L)
    Y = (y[None, :, :] + sh[:, None, :]).reshape(-1, 3)
    S = np.tile(s, len(sh))
    home = int(np.nonzero(~np.any(sh, axis=1))[0][0])*len(y)
    E = np.zeros_like(x)
    for i in range(len(x)):
        r = x[i] - Y
        r2 = np.einsum("ij,ij->i", r, r)
        r2[home + ident[i]] = np.inf
        E[i] = ((S/(r2*np.sqrt(r2)))[:, None]*r).sum(axis=0)
    return K_COULOMB/eps_r*E


# ---------------------------------------------------------------------------

def selftest():
    ok = True

    def check(name, good, detail):
        nonlocal ok
        ok &= bool(good)
        print(f"{'PASS' if good else 'FAIL'}: groundedBox.{name} ({detail})")

    qe = 1e-9
    # 1. Exact centre of a box: zero field by symmetry
    L = np.array([1.0, 1.3, 0.8])
    E = field([0.5*L], [qe], L)
    scale = K_COULOMB*qe/L.min()**2
    err = np.abs(E).max()/scale
    check("centre", err < 1e-11, f"|E| at the centre / (k q/L^2) = {err:.1e}, tol 1e-11")

    # 2. Charge at distance d from the face x = 0 of a large box: the single
    #    image -q at 2d, to O((d/L)^2) (observed (d/L)^3: the far walls'
    #    images come in opposite pairs, dipoles)
    d = 0.01
    rel = []
    for Lb in (0.2, 0.4, 0.8):
        E = field([[d, 0.5*Lb, 0.5*Lb]], [qe], Lb)[0]
        Ef = -K_COULOMB*qe/(2*d)**2
        rel.append(np.linalg.norm(E - [Ef, 0, 0])/abs(Ef))
    rel = np.array(rel)
    ratios = rel[:-1]/rel[1:]
    good = np.all(rel < 2*(d/np.array([0.2, 0.4, 0.8]))**2) and np.all(ratios > 3.5)
    check("singlePlane", good,
          "rel. deviation from -k q^2/(2d)^2 for d/L = 0.05, 0.025, 0.0125: "
          + ", ".join(f"{r:.2e}" for r in rel)
          + f"; ratios {ratios[0]:.2f}, {ratios[1]:.2f} (O((d/L)^2): >= 4)")

    # 3. Random charges: tol convergence, zero potential on the walls
    rng = np.random.default_rng(1)
    L = np.array([1.0, 0.7, 1.2])
    x = L*(0.05 + 0.9*rng.random((12, 3)))
    q = qe*(2*rng.random(12) - 1)
    E13 = field(x, q, L)
    E16 = field(x, q, L, tol=1e-16)
    err = np.abs(E13 - E16).max()/np.abs(E16).max()
    check("tolerance", err < 1e-10, f"tol 1e-13 vs 1e-16: max |dE|/max|E| = {err:.1e}, tol 1e-10")
    w = L*rng.random((30, 3))
    for k in range(30):
        w[k, k % 3] = 1e-12*L[k % 3] if k % 2 else (1 - 1e-12)*L[k % 3]
    phiW = potential_at(w, x, q, L)
    phiS = np.abs(potential(x, q, L)).max()
    err = np.abs(phiW).max()/phiS
    check("wallPotential", err < 1e-9, f"max |phi| on 30 wall points / max |phi| at charges = {err:.1e}, tol 1e-9")

    # 4. Brute-force image shells converge to the Ewald value (O(M^-2))
    xs, qs = x[:5], q[:5]
    Eref = field(xs, qs, L)
    errs = []
    for M in (1, 2, 4, 8, 16):
        Eb = image_sum(xs, qs, L, M)
        errs.append(np.abs(Eb - Eref).max()/np.abs(Eref).max())
    errs = np.array(errs)
    rates = np.log2(errs[:-1]/errs[1:])
    good = np.all(np.diff(errs) < 0) and errs[-1] < 2e-3 and rates[-1] > 1.5
    check("imageShells", good,
          "max rel. |E_shells - E_Ewald| for shells 1,2,4,8,16: "
          + ", ".join(f"{e:.2e}" for e in errs)
          + "; observed orders " + ", ".join(f"{r:.2f}" for r in rates))

    # 5. Duct (insulating ends x = 0, Lx; grounded sides): zero potential on
    #    the sides, zero normal field on the ends, image shells converge
    P = (1, -1, -1)
    L = np.array([3.0, 0.4, 0.5])
    x = L*(0.05 + 0.9*rng.random((10, 3)))
    q = qe*(2*rng.random(10) - 1)
    w = L*rng.random((40, 3))
    for k in range(40):
        a = 1 + k % 2
        w[k, a] = 1e-12*L[a] if k % 4 < 2 else (1 - 1e-12)*L[a]
    phiS = np.abs(potential(x, q, L, parity=P)).max()
    errS = np.abs(potential_at(w, x, q, L, parity=P)).max()/phiS
    e = L*rng.random((20, 3))
    e[:, 0] = np.where(np.arange(20) % 2, 1e-12, 1 - 1e-12)*L[0]
    Ee = field_at(e, x, q, L, parity=P)
    errE = np.abs(Ee[:, 0]).max()/np.abs(Ee).max()
    Eref = field(x[:4], q[:4], L, parity=P)
    Eb = image_sum(x[:4], q[:4], L, 16, parity=P)
    errB = np.abs(Eb - Eref).max()/np.abs(Eref).max()
    check("duct", errS < 1e-9 and errE < 1e-9 and errB < 2e-3,
          f"parity (+1, -1, -1): max |phi| on the sides / max |phi| {errS:.1e}, "
          f"max |E_x| on the ends / max |E| {errE:.1e} (tol 1e-9); "
          f"16 image shells vs Ewald {errB:.1e} (< 2e-3)")
    return ok


def _vec(text):
    v = [float(c) for c in text.replace(",", " ").split()]
    if len(v) not in (1, 3):
        raise argparse.ArgumentTypeError(f"need 1 or 3 numbers, got '{text}'")
    return v


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("charges", nargs="?", help="text file of 'x y z q' lines")
    ap.add_argument("out", nargs="?", help="output file (default stdout)")
    ap.add_argument("--L", type=_vec, help="box lengths 'Lx' or 'Lx,Ly,Lz'")
    ap.add_argument("--origin", type=_vec, default=[0.0], help="lower corner 'x0' or 'x0,y0,z0'")
    ap.add_argument("--eps-r", type=float, default=1.0)
    ap.add_argument("--tol", type=float, default=1e-13)
    ap.add_argument("--points", help="evaluate at these 'x y z' points instead")
    ap.add_argument("--potential", action="store_true", help="add a phi column")
    ap.add_argument("--selftest", action="store_true")
    a = ap.parse_args()
    if a.selftest:
        return 0 if selftest() else 1
    if not a.charges or not a.L:
        ap.error("need charges.txt and --L Lx[,Ly,Lz]")
    d = np.loadtxt(a.charges, ndmin=2)
    x, q = d[:, :3], d[:, 3]
    if a.points:
        t = np.loadtxt(a.points, ndmin=2)[:, :3]
        phi, E = _evaluate(t, x, q, a.L, a.eps_r, a.tol, a.origin, False)
    else:
        phi, E = _evaluate(None, x, q, a.L, a.eps_r, a.tol, a.origin, True)
    out = np.column_stack([E, phi]) if a.potential else E
    np.savetxt(a.out if a.out else sys.stdout, out, fmt="%.16e")
    return 0


if __name__ == "__main__":
    sys.exit(main())
