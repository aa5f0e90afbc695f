#!/usr/bin/env python3
"""Exact electrostatics of point charges inside a grounded infinite cylinder.

A grounded conducting cylinder of radius a about the z axis (phi = 0 on
rho = a) around point charges in vacuum (eps_r = 1), optionally periodic
along z with a period (every charge repeated at z + k period). Two
independent series of the same Green's function:

    image_field   the wall's induced charge of a source, as the regular part
                  of Jackson (Classical Electrodynamics, 3rd ed.) Eq. 3.148
                  made zero on the wall:
                  -(1/(2 pi^2 eps0)) sum_m eps_m cos(m dphi)
                      int_0^inf cos(k dz) I_m(k rho) I_m(k rho') K_m(k a)/I_m(k a) dk
                  (scaled Bessel functions; the leading small-argument
                  terms where K_m overflows); valid at any dz, including the
                  charge's own image field (dz = 0);
    mode_field    the whole Green's function (charge and wall) by the
                  eigenfunctions of the cross-section,
                  (1/(2 pi eps0 a^2)) sum_m eps_m cos(m dphi) sum_n
                      J_m(k rho) J_m(k rho') exp(-k |dz|)/(k J_{m+1}(j_mn)^2),
                  k = j_mn/a (derived here: the point source expanded in
                  the cross-section's Fourier-Bessel functions, norm
                  a^2/2 J_{m+1}(j_mn)^2, times the one-dimensional Green's
                  function exp(-k |dz|)/(2k)); converges fast for |dz| of
                  order a, used for the periodic copies (their free-space
                  parts alone would not converge).

SI units: x, a in m, q in C, E in V/m.

Python interface (import from tests/tools):
    field(x, q, a, period=None, copies=6)
        (N,3) field at each charge from the other charges, every charge's
        wall charge and (with a period) the periodic copies

    groundedCylinder.py --selftest   checks (PASS:/FAIL: lines): the two
        series agree where both converge (random pairs, near the wall), the
        plane-wall limit near the wall, zero field on the axis (about 40 s)
"""
import argparse
import sys

import numpy as np

EPS0 = 8.8541878128e-12


def image_field(xt, xs, a):
    """eps0-free field factor at xt of the wall's induced charge for a unit
    point charge at xs, both inside the grounded infinite cylinder of
    radius a about the z axis (Jackson 3.148 with the grounded wall: the
    regular part -(1/(2 pi^2)) sum_m eps_m cos(m dphi) int_0^inf cos(k dz)
    I_m(k rho) I_m(k rho') K_m(k a)/I_m(k a) dk, times 1/eps0). Returns
    E/(q/eps0)."""
    from scipy import special
    rho, phi, z = np.hypot(xt[0], xt[1]), np.arctan2(xt[1], xt[0]), xt[2]
    rs, ps = np.hypot(xs[0], xs[1]), np.arctan2(xs[1], xs[0])
    dphi, dz = phi - ps, z - xs[2]
    Er = Ep = Ez = 0.0
    for m in range(0, 400):
        em = 1.0 if m == 0 else 2.0
        # scaled Bessel functions: the integrand is ~exp(k (rho + rs - 2a))
        def g(k, part):
            if k == 0:
                k = 1e-300
            Ir, Is, Ka, Ia = (special.ive(m, k*rho), special.ive(m, k*rs),
                              special.kve(m, k*a), special.ive(m, k*a))
            with np.errstate(all="ignore"):
                w = np.exp(k*(rho + rs - 2*a))*Is*Ka/Ia
            if not np.isfinite(w*Ir) or (Ir == 0 and m > 0):
                # K_m(k a) overflows or I_m underflows at k << m: the
                # leading small-argument terms (Abramowitz & Stegun 9.6.7,
                # 9.6.9), I_m(kr) I_m(ks) K_m(ka)/I_m(ka) = (r s/a^2)^m/(2m)
                # (relative error O(k^2 a^2/m))
                P = (rho*rs/a**2)**m/(2*m)
                dP = 0.5*(rs/a**2)*(rho*rs/a**2)**(m - 1)    # dP/drho
                return [dP, P, -P*k][part]
            if part == 0:     # d/drho
                dI = 0.5*(special.ive(m - 1, k*rho) + special.ive(m + 1, k*rho))*k
                return w*dI
            if part == 1:     # (1/rho) d/dphi (the m sin factor outside)
                return w*Ir
            return -w*Ir*k   # d/dz (times sin(k dz))
        top = 60.0/max(2*a - rho - rs, 1e-3*a)
        vals = [_oscillatory(g, top, p, dz) for p in range(3)]
        c = -em/(2*np.pi**2)
        dEr = -c*np.cos(m*dphi)*vals[0]
        dEp = c*m*np.sin(m*dphi)*vals[1]/rho if rho > 0 else 0.0
        dEz = -c*np.cos(m*dphi)*vals[2]
        Er, Ep, Ez = Er + dEr, Ep + dEp, Ez + dEz
        if m > 2 and max(abs(dEr), abs(dEp), abs(dEz)) < 1e-13*max(abs(Er), abs(Ez), 1e-300) \
                and (rho*rs/a**2)**m < 1e-14:
            break
    cp, sp = np.cos(phi), np.sin(phi)
    return np.array([Er*cp - Ep*sp, Er*sp + Ep*cp, Ez])


def _oscillatory(g, top, part, dz):
    """int_0^top g(k, part) cos(k dz) dk (sin for part 2) by QUADPACK's QAWO.
    Its round-off warnings (a mode's integral already at round-off against
    the sum) are silenced here only; the self-test's two-series check
    measures the accuracy."""
    import warnings
    from scipy import integrate
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", integrate.IntegrationWarning)
        return integrate.quad(g, 0, top, args=(part,), weight="sin" if part == 2 else "cos",
                              wvar=dz, limit=400, epsabs=0, epsrel=1e-10)[0]


def mode_field(xt, xs, a, nModes=200):
    """The same cylinder's whole Green's function (free charge and wall) by
    its eigenfunction series (J_m(j_mn rho/a) e^{-j_mn |dz|/a}), for
    |dz| > 0: E/(q/eps0)."""
    from scipy import special
    rho, phi, z = np.hypot(xt[0], xt[1]), np.arctan2(xt[1], xt[0]), xt[2]
    rs, ps = np.hypot(xs[0], xs[1]), np.arctan2(xs[1], xs[0])
    dphi, dz = phi - ps, z - xs[2]
    Er = Ep = Ez = 0.0
    for m in range(0, nModes):
        em = 1.0 if m == 0 else 2.0
        # zeros up to exp(-j_mn |dz|/a) ~ 1e-20 (j_mn ~ (m/2 + n) pi)
        x = special.jn_zeros(m, min(nModes, int(46*a/(np.pi*abs(dz))) + 5))
        k = x/a
        decay = np.exp(-k*abs(dz))
        if decay[0] < 1e-18:
            break
        w = decay*special.jv(m, k*rs)/(k*special.jv(m + 1, x)**2)
        c = em/(2*np.pi*a**2)
        Er -= c*np.cos(m*dphi)*np.sum(w*k*special.jvp(m, k*rho))
        if rho > 0:
            Ep += c*m*np.sin(m*dphi)*np.sum(w*special.jv(m, k*rho))/rho
        Ez += c*np.cos(m*dphi)*np.sign(dz)*np.sum(w*k*special.jv(m, k*rho))
    cp, sp = np.cos(phi), np.sin(phi)
    return np.array([Er*cp - Ep*sp, Er*sp + Ep*cp, Ez])


def field(x, q, a, period=None, copies=6):
    """(N,3) field [V/m] at each charge in the grounded cylinder of radius a
    about the z axis, eps_r = 1: the other charges (Coulomb) plus every
    charge's wall charge (the image integral), and with a period along z
    every periodic copy by the eigenfunction series."""
    x = np.atleast_2d(np.asarray(x, float))
    q = np.atleast_1d(np.asarray(q, float))
    E = np.zeros_like(x)
    for i in range(len(x)):
        for j in range(len(x)):
            if j != i:
                d = x[i] - x[j]
                E[i] += q[j]*d/(4*np.pi*np.linalg.norm(d)**3)
            E[i] += q[j]*image_field(x[i], x[j], a)
            if period:
                for k in range(1, copies + 1):
                    for s in (-1, 1):
                        E[i] += q[j]*mode_field(x[i], x[j] + [0, 0, s*k*period], a)
    return E/EPS0


# ---------------------------------------------------------------------------

def selftest():
    ok = True

    def check(name, good, detail):
        nonlocal ok
        ok &= bool(good)
        print(f"{'PASS' if good else 'FAIL'}: groundedCylinder.{name} ({detail})")

    a = 1.0
    # 1. Coulomb + the image integral against the eigenfunction series, for
    #    source/target pairs apart along z (random, and near the wall)
    rng = np.random.default_rng(1)
    pairs = [(np.array([*(0.56*rng.uniform(-1, 1, 2)), 0.0]),
              np.array([*(0.56*rng.uniform(-1, 1, 2)), dz])) for dz in (0.25, 0.5, 1.0)]
    pairs += [(np.array([0.9, 0, 0]), np.array([0.85, 0.2, 0.3])),
              (np.array([0.0, 0.95, 0.1]), np.array([0.1, 0.9, 0.4]))]
    err = 0.0
    for xs, xt in pairs:
        d = xt - xs
        Ea = d/(4*np.pi*np.linalg.norm(d)**3) + image_field(xt, xs, a)
        Eb = mode_field(xt, xs, a, 400)
        err = max(err, np.linalg.norm(Ea - Eb)/np.linalg.norm(Eb))
    check("twoSeries", err < 1e-10,
          f"Coulomb + image integral vs eigenfunction series, {len(pairs)} pairs: {err:.1e}, tol 1e-10")

    # 2. Near the wall the charge's image field tends to the plane wall's,
    #    1/(4 pi (2d)^2), from below (measured second order in d/a)
    rel = []
    for d in (0.2, 0.1, 0.05):
        E = image_field(np.array([a - d, 0, 0]), np.array([a - d, 0, 0]), a)
        rel.append(E[0]*4*np.pi*(2*d)**2 - 1)
    rel = np.array(rel)
    good = (np.all(np.abs(rel) < 0.5*np.array([0.2, 0.1, 0.05])**2)
            and np.all(np.abs(rel[:-1]/rel[1:]) > 3.5))
    check("planeLimit", good,
          "image field / plane wall's - 1 at d/a = 0.2, 0.1, 0.05: "
          + ", ".join(f"{r:.2e}" for r in rel) + " (tol 0.5 (d/a)^2, halving d: ratio >= 3.5)")

    # 3. A charge on the axis of a periodic pipe: no field by symmetry
    E = field([[0, 0, 0.3]], [1e-9], a, period=2.0)
    scale = 1e-9/(4*np.pi*EPS0*a**2)
    check("axis", np.abs(E).max() < 1e-12*scale,
          f"|E| on the axis / (q/(4 pi eps0 a^2)) = {np.abs(E).max()/scale:.1e}, tol 1e-12")
    return ok


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--selftest", action="store_true")
    a = ap.parse_args()
    if a.selftest:
        return 0 if selftest() else 1
    ap.print_help()
    return 0


if __name__ == "__main__":
    sys.exit(main())
