#!/usr/bin/env python3
"""Exact electrostatics of two charged dielectric spheres (independent reference).

Two spheres of radii a1, a2, relative permittivities k1, k2 (math.inf: a
conductor), free charges Q1, Q2 spread uniformly on their surfaces, centre
distance d, in a medium of relative permittivity k0. Axisymmetric multipole
solution, no mesh and no point-dipole truncation: outside both spheres
  phi = sum_n A_n a1^(n+1) r1^-(n+1) P_n(cos t1) + B_n a2^(n+1) r2^-(n+1) P_n(cos t2),
each angle measured from the line towards the other sphere, so that near
sphere 1 (addition theorem, on the axis the binomial series)
  r2^-(n+1) P_n(cos t2) = sum_m C(n+m, m) r1^m / d^(n+m+1) P_m(cos t1).
Continuity of phi and the jump k_out dphi/dr - k_in dphi/dr = -sigma_f/eps0 at
r1 = a1 give A_0 = Q1/(4 pi eps0 k0 a1) and, for n >= 1,
  A_n = f_n(k1) sum_m C(n+m, m) a1^n a2^(m+1)/d^(n+m+1) B_m,
  f_n(k) = -n (k - k0)/(n k + (n + 1) k0)     (-1 for a conductor),
and the same for sphere 2. The energy at fixed free charges is
U = 1/2 (Q1 phibar_1 + Q2 phibar_2), phibar_i the n = 0 part of phi on sphere
i, and the force on sphere 2 along the line from 1 to 2 is F = -dU/dd
(positive: repulsion). The number of terms is doubled until U changes by less
than 1e-13 relative; the force is the
central difference of the d-dependent part of U (step 1e-4 of the gap).

Used by tutorials/bemValidation, tutorials/dielectricSpheres and
applications/benchmarks/polarisation; checked by tests/cases/twoDielectricSpheres.sh.
"""
import math
import numpy as np

eps0 = 8.8541878128e-12


def _f(n, k, k0):
    if math.isinf(k):
        return np.where(n == 0, 0.0, -1.0)
    return np.where(n == 0, 0.0, -n * (k - k0) / (n * k + (n + 1) * k0))


def _interactionEnergy(N, Q1, Q2, a1, a2, d, k1, k2, k0):
    n = np.arange(N)
    lf = np.array([math.lgamma(i + 1) for i in range(2 * N)])
    i, j = np.meshgrid(n, n, indexing="ij")
    logC = lf[i + j] - lf[i] - lf[j]
    # G12[n, m] = C(n+m, m) a1^n a2^(m+1)/d^(n+m+1), G21 with a1 <-> a2
    G12 = np.exp(logC + i * math.log(a1 / d) + (j + 1) * math.log(a2 / d))
    G21 = np.exp(logC + i * math.log(a2 / d) + (j + 1) * math.log(a1 / d))
    F1 = _f(n, k1, k0)[:, None] * G12
    F2 = _f(n, k2, k0)[:, None] * G21
    M = np.block([[np.eye(N), -F1], [-F2, np.eye(N)]])
    rhs = np.zeros(2 * N)
    rhs[0] = Q1 / (4 * math.pi * eps0 * k0 * a1)
    rhs[N] = Q2 / (4 * math.pi * eps0 * k0 * a2)
    x = np.linalg.solve(M, rhs)
    A, B = x[:N], x[N:]
    # phibar_i minus the isolated sphere's own A_0: the d-dependent part of U
    return 0.5 * (Q1 * (G12[0] @ B) + Q2 * (G21[0] @ A))


def interactionEnergy(Q1, Q2, a1, a2, d, k1, k2, k0=1.0, tol=1e-13, Nmax=2048):
    """Energy [J] at fixed free charges minus the isolated spheres' energies
    (the part that depends on d), converged in the number of terms."""
    if not d > a1 + a2:
        raise ValueError("spheres overlap or touch: d = %g <= a1 + a2 = %g" % (d, a1 + a2))
    N = 16
    U = _interactionEnergy(N, Q1, Q2, a1, a2, d, k1, k2, k0)
    while True:
        N *= 2
        if N > Nmax:
            raise RuntimeError("series not converged with %d terms (gap %g)" % (Nmax, d - a1 - a2))
        Un = _interactionEnergy(N, Q1, Q2, a1, a2, d, k1, k2, k0)
        if abs(Un - U) <= tol * max(abs(Un), 1e-300):
            return Un
        U = Un


def energy(Q1, Q2, a1, a2, d, k1, k2, k0=1.0):
    """Electrostatic energy [J] at fixed free charges."""
    return (interactionEnergy(Q1, Q2, a1, a2, d, k1, k2, k0)
            + (Q1 * Q1 / a1 + Q2 * Q2 / a2) / (8 * math.pi * eps0 * k0))


def force(Q1, Q2, a1, a2, d, k1, k2, k0=1.0):
    """Force [N] on sphere 2 along the line from sphere 1 to 2 (+: repulsion)."""
    h = 1e-4 * (d - a1 - a2)
    return -(interactionEnergy(Q1, Q2, a1, a2, d + h, k1, k2, k0)
             - interactionEnergy(Q1, Q2, a1, a2, d - h, k1, k2, k0)) / (2 * h)


if __name__ == "__main__":
    import sys
    if len(sys.argv) != 9:
        sys.exit("usage: twoDielectricSpheres.py Q1 Q2 a1 a2 d k1 k2 k0"
                 "   (k = inf: conductor)")
    Q1, Q2, a1, a2, d, k1, k2, k0 = map(float, sys.argv[1:])
    print("U %.16g J  F %.16g N" % (energy(Q1, Q2, a1, a2, d, k1, k2, k0),
                                     force(Q1, Q2, a1, a2, d, k1, k2, k0)))
