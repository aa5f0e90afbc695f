#!/usr/bin/env python3
"""Exact electrostatics of two charged dielectric spheres (independent check).

Axisymmetric multipole solution (medium kappa 1, spheres radius R, kappa kp,
uniform free surface charge sigma_1, sigma_2, centre distance D). Outside:
  phi = sum_n a_n r1^-(n+1) P_n(cos t1) + b_n r2^-(n+1) P_n(cos t2),
t2 measured from the direction towards sphere 1, so that near sphere 1
  r2^-(n+1) P_n(cos t2) = sum_m C(n+m, m) r1^m / D^(n+m+1) P_m(cos t1).
Boundary conditions at r1 = R (continuity of phi, jump of kappa dphi/dr =
-sigma_f/eps0) give a_0 = sigma_1 R^2/eps0 and, for n >= 1,
  a_n = -n (kp - 1)/(n (kp + 1) + 1) R^(2n+1) e_n,
  e_n = sum_m b_m C(n+m, m)/D^(n+m+1),
and the same for sphere 2. Energy with fixed free charges U = 1/2 sum_i Q_i
phibar_i (phibar = n = 0 part of phi on sphere i), force on sphere 2 along
the line F = -dU/dD (central difference).
"""
import math
import numpy as np

eps0 = 8.8541878128e-12


def energy(D, kp, s1, s2, R=1.0, N=None):
    if N is None:
        N = int(min(1500, max(40, 25 / math.log(D / (D - 2 * R)) if D > 2 * R else 1500)))
    n = np.arange(N)
    # G[n, m] = C(n+m, m) R^(n+m+1) / D^(n+m+1), scaled coefficients
    # A_n = a_n / R^(n+1), B_n = b_n / R^(n+1): e_m R^m = sum_n B_n G[n, m]
    lg = np.array([[math.lgamma(i + j + 1) - math.lgamma(i + 1) - math.lgamma(j + 1)
                    + (i + j + 1) * math.log(R / D) for j in range(N)] for i in range(N)])
    G = np.exp(lg)
    f = np.where(n == 0, 0.0, -n * (kp - 1) / (n * (kp + 1) + 1))
    # A = A0 + diag(f) G^T B,  B = B0 + diag(f) G^T A
    A0 = np.zeros(N); A0[0] = s1 * R / eps0
    B0 = np.zeros(N); B0[0] = s2 * R / eps0
    M = np.block([[np.eye(N), -np.diag(f) @ G.T], [-np.diag(f) @ G.T, np.eye(N)]])
    x = np.linalg.solve(M, np.concatenate([A0, B0]))
    A, B = x[:N], x[N:]
    phi1 = A[0] + (B @ G[:, 0])        # n = 0 part on sphere 1 (x R^0)
    phi2 = B[0] + (A @ G[:, 0])
    Q1 = 4 * math.pi * R * R * s1
    Q2 = 4 * math.pi * R * R * s2
    return 0.5 * (Q1 * phi1 + Q2 * phi2)


def force(gap, kp, s1, s2, R=1.0):
    D = 2 * R + gap
    h = 1e-4 * gap
    return -(energy(D + h, kp, s1, s2, R) - energy(D - h, kp, s1, s2, R)) / (2 * h)


if __name__ == "__main__":
    F0 = math.pi / eps0
    for kp in (1, 10, 100):
        for s2 in (1, -1):
            print(kp, s2, [round(force(g, kp, 1, s2) / F0, 4) for g in (0.05, 0.5, 2.0)])
