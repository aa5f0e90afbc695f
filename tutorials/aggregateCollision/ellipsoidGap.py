#!/usr/bin/env python3
"""Surface gap of two ellipsoids (negative: overlap), for the plots and the
initial placement of the aggregateCollision tutorial; independent of the
solver's contact detection (Ruan 2022 Eqs. 21-31).

The gap is the smallest signed distance from points of ellipsoid A's
surface to ellipsoid B, d(x) ~ (g_B(x) - 1)/|grad g_B(x)| with
g_B(x) = |S_B^-1 R_B^T (x - x_B)| (first order in the distance, exact for
touching surfaces); the surface of A is sampled on a (theta, phi) grid
that is refined around the best point until the patch is below 1e-4 of A's
smallest semi-axis.
"""
import numpy as np


def _distance_to(x, c, R, s):
    """Signed first-order distance of points x (n x 3) to the ellipsoid."""
    y = (x - c) @ R                 # body frame
    u = y/s
    g = np.sqrt((u*u).sum(axis=1))
    grad = (u/s)/g[:, None]         # d g / d y (body frame; |.| is frame-free)
    return (g - 1)/np.sqrt((grad*grad).sum(axis=1))


def _points(c, R, s, th, ph):
    th, ph = np.meshgrid(th, ph, indexing="ij")
    y = np.stack([s[0]*np.cos(th), s[1]*np.sin(th)*np.cos(ph),
                  s[2]*np.sin(th)*np.sin(ph)], axis=-1).reshape(-1, 3)
    return c + y @ R.T, th.ravel(), ph.ravel()


def gap(cA, RA, sA, cB, RB, sB):
    """Signed surface gap of ellipsoids A and B (centres c, rotations R body
    -> inertial, semi-axes s)."""
    cA, cB, sA, sB = (np.asarray(v, float) for v in (cA, cB, sA, sB))
    th = np.linspace(0, np.pi, 61)
    ph = np.linspace(-np.pi, np.pi, 121)
    dth, dph = th[1] - th[0], ph[1] - ph[0]
    while True:
        x, t, p = _points(cA, RA, sA, th, ph)
        d = np.minimum(_distance_to(x, cB, RB, sB),
                       np.inf)
        k = int(np.argmin(d))
        if max(dth, dph)*max(sA) < 1e-4*min(sA):
            return d[k]
        dth, dph = dth/4, dph/4
        th = np.clip(t[k] + dth*np.arange(-8, 9), 0, np.pi)
        ph = p[k] + dph*np.arange(-8, 9)


if __name__ == "__main__":
    # Two spheres of radius 1, centres 2.5 apart: gap 0.5
    I = np.eye(3)
    print(gap([0, 0, 0], I, [1, 1, 1], [2.5, 0, 0], I, [1, 1, 1]))
    # Prolates (2, 1, 1) side by side 2.2 apart: gap 0.2; tip to tip 4.3: 0.3
    print(gap([0, 0, 0], I, [2, 1, 1], [0, 2.2, 0], I, [2, 1, 1]))
    print(gap([0, 0, 0], I, [2, 1, 1], [4.3, 0, 0], I, [2, 1, 1]))
