"""Rigid ellipsoids for the tutorials' and tests' Python scripts: the
rotation of a unit quaternion (OpenFOAM's quaternion::R(), body -> inertial),
mass and principal moments of inertia. etc/bashrc puts this folder on
PYTHONPATH."""
import numpy as np


def rotation(w, x, y, z):
    """x_inertial = R x_body for the unit quaternion (w, x, y, z); scalars
    give a 3x3 matrix, arrays of N components an (N, 3, 3) stack."""
    w, x, y, z = (np.asarray(c, dtype=float) for c in (w, x, y, z))
    return np.stack([
        np.stack([1 - 2*(y*y + z*z), 2*(x*y - w*z), 2*(x*z + w*y)], -1),
        np.stack([2*(x*y + w*z), 1 - 2*(x*x + z*z), 2*(y*z - w*x)], -1),
        np.stack([2*(x*z - w*y), 2*(y*z + w*x), 1 - 2*(x*x + y*y)], -1)], -2)


def mass(axes, rho):
    """Mass of the ellipsoid with semi-axes (a, b, c) and density rho."""
    a, b, c = axes
    return rho*4/3*np.pi*a*b*c


def principal_moments(axes, m):
    """Moments of inertia about the body axes: m/5 (b^2 + c^2, c^2 + a^2,
    a^2 + b^2)."""
    a, b, c = axes
    return m/5*np.array([b*b + c*c, c*c + a*a, a*a + b*b])
