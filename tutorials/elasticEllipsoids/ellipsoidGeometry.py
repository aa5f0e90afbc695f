"""Ellipsoid geometry for the elasticEllipsoids scripts, independent of the
code under test: rotation of a unit quaternion, the Perram-Wertheim overlap
test, masses and moments of inertia."""
import numpy as np


def rotation(q):
    """Rotation matrix (body -> inertial) of the unit quaternion (w, x, y, z)."""
    w, x, y, z = q
    return np.array([
        [1 - 2*(y*y + z*z), 2*(x*y - w*z), 2*(x*z + w*y)],
        [2*(x*y + w*z), 1 - 2*(x*x + z*z), 2*(y*z - w*x)],
        [2*(x*z - w*y), 2*(y*z + w*x), 1 - 2*(x*x + y*y)]])


def shape_inverse(axes, q):
    """S^-1 = Q diag(a^2, b^2, c^2) Q^T: x^T S x = 1 on the centred surface."""
    Q = rotation(q)
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


def mass(axes, rho):
    a, b, c = axes
    return rho*4/3*np.pi*a*b*c


def kinetic_energy(axes, rho, U, omega_body):
    """Translational + rotational energy; principal moments
    m/5 (b^2 + c^2, c^2 + a^2, a^2 + b^2) about the body axes."""
    a, b, c = axes
    m = mass(axes, rho)
    I = m/5*np.array([b*b + c*c, c*c + a*a, a*a + b*b])
    return 0.5*m*np.dot(U, U) + 0.5*np.dot(I, np.asarray(omega_body)**2)
