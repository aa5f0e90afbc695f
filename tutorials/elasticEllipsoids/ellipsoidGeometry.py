"""Ellipsoid geometry for the elasticEllipsoids scripts, independent of the
code under test: the shape matrix, the Perram-Wertheim overlap test and the
kinetic energy (rotations, masses and moments from etc/python/ellipsoids)."""
import numpy as np
from ellipsoids import mass, principal_moments, rotation


def shape_inverse(axes, q):
    """S^-1 = Q diag(a^2, b^2, c^2) Q^T: x^T S x = 1 on the centred surface;
    q the unit quaternion (w, x, y, z)."""
    Q = rotation(*q)
    return Q @ np.diag(np.asarray(axes)**2) @ Q.T


def perram_wertheim(M1, M2, r):
    """max over lambda of F(lambda) = lambda (1 - lambda) r^T ((1 - lambda)
    M1 + lambda M2)^-1 r (Perram & Wertheim 1985, J. Comput. Phys. 58:409),
    M = S^-1, r = c2 - c1: < 1 overlap, 1 touching, > 1 separated. F is
    concave in lambda: golden-section search."""
    def F(l):
        return l*(1 - l)*r @ np.linalg.solve((1 - l)*M1 + l*M2, r)
    a, b = 0.0, 1.0
    g = (np.sqrt(5) - 1)/2
    for _ in range(80):
        c, d = b - g*(b - a), a + g*(b - a)
        if F(c) > F(d):
            b = d
        else:
            a = c
    return F(0.5*(a + b))


def kinetic_energy(axes, rho, U, omega_body):
    """Translational + rotational energy."""
    m = mass(axes, rho)
    I = principal_moments(axes, m)
    return 0.5*m*np.dot(U, U) + 0.5*np.dot(I, np.asarray(omega_body)**2)
