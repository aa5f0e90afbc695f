"""Physics shared by every code of the settling-bed benchmark: material,
box, lattice, time step and the dashpot calibration that makes the codes'
damping laws identical.

All codes use the Hertz normal spring with a dashpot
    F_n = 4/3 E* sqrt(R) delta^3/2 + eta_n v_n,
    eta_n = 2 sqrt(5/6) |beta| sqrt(2 E* sqrt(R delta) m*)
(LIGGGHTS `model hertz`, chargedFoam `ellipsoidCollision`; OpenFOAM's
`pairSpringSliderDashpot` writes eta_n = alpha sqrt(m* 4/3 E* sqrt(R))
delta^1/4, the same law with alpha = sqrt(5) |beta|). They differ only in
how beta follows from the restitution coefficient e:
  - chargedFoam integrates the Hertz impact and inverts it, so that a head-on
    impact restitutes exactly e (hertzDashpot::calibratedDampingRatio);
  - LIGGGHTS uses the linear-spring closed form
    beta = ln e / sqrt(ln^2 e + pi^2) of its `coefficientRestitution`;
  - OpenFOAM takes alpha directly.
To compare equal physics, beta is computed here exactly as chargedFoam does,
OpenFOAM gets alpha = sqrt(5)|beta| and LIGGGHTS the coefficientRestitution
e_L whose closed form gives the same beta: e_L = exp(pi beta/sqrt(1 - beta^2)).
"""
import math

import numpy as np

# Material (particles and walls alike) and gravity
D = 1e-3            # sphere diameter [m]
RHO = 2500.0        # [kg/m3]
E = 5e6             # Young's modulus [Pa]
NU = 0.3            # Poisson's ratio
REST = 0.5          # restitution coefficient e
MU = 0.3            # friction coefficient
G = 9.81            # gravity along -z [m/s2]

# Ellipsoids: prolate, aspect ratio 2, as in tutorials/ellipsoidPour
SEMI_AXES_ELLIPSOID = (1e-3, 5e-4, 5e-4)

# chargedFoam's buffer layer (collision shell) of ellipsoids: its default
DELTABL_RATIO_ELLIPSOID = 0.05

# Box: square base of side BASE (default; the benchmark's configurations
# set it per bed), the height follows from the lattice
BASE = 30e-3
# OpenFOAM mesh: cubic cells. Their size sets the broad phase of the
# OpenFOAM-based codes (candidate pairs: the parcels of cells closer than
# the interaction distance); 1.5 d was the fastest for spheres of the sizes
# tried (Allrun -cells), 2 mm (as tutorials/ellipsoidPour) for ellipsoids
CELL_SPHERE = 1.5e-3
CELL_ELLIPSOID = 2e-3

# Lattice spacing: bounding diameter plus a gap
SPACING_SPHERE = 1.5e-3
SPACING_ELLIPSOID = 2.3e-3
UJITTER = 0.05      # random velocity components in +-UJITTER/2 [m/s]
STEPS_PER_COLLISION = 20


def mass_sphere():
    return RHO*math.pi/6*D**3


def estar():
    """Effective modulus of two equal materials, 1/E* = 2 (1 - nu^2)/E."""
    return E/(2*(1 - NU**2))


def hertz_collision_time(v, mstar, R, Es):
    """Hertz contact duration (Johnson 1985) at approach speed v."""
    return 2.868*(mstar**2/(R*Es**2*v))**0.2


def restitution(beta, h=2e-4):
    """Restitution of the dimensionless Hertz impact with dashpot ratio beta,
    RK4 exactly as EllipsoidCollision::restitution (chargedFoam)."""
    gamma = math.sqrt(5.0)*abs(beta)

    def acc(x, v):
        xp = max(x, 0.0)
        return -max(xp*math.sqrt(xp) + gamma*math.sqrt(math.sqrt(xp))*v, 0.0)

    x, v = 0.0, 1.0
    for _ in range(1000000):
        k1x, k1v = v, acc(x, v)
        k2x, k2v = v + 0.5*h*k1v, acc(x + 0.5*h*k1x, v + 0.5*h*k1v)
        k3x, k3v = v + 0.5*h*k2v, acc(x + 0.5*h*k2x, v + 0.5*h*k2v)
        k4x, k4v = v + h*k3v, acc(x + h*k3x, v + h*k3v)
        x += h/6*(k1x + 2*k2x + 2*k3x + k4x)
        v += h/6*(k1v + 2*k2v + 2*k3v + k4v)
        if x <= 0 or (v < 0 and acc(x, v) == 0):
            return max(-v, 0.0)
    return 0.0


def damping_ratio(e, iterations=45):
    """beta (< 0) of the Hertz dashpot restituting e (bisection as in
    hertzDashpot::calibratedDampingRatio; 45 halvings of [0, 1] reach 3e-14)."""
    if e >= 1:
        return 0.0
    lo, hi = 0.0, 1.0
    while restitution(-hi) > e and hi < 1e3:
        hi *= 2
    for _ in range(iterations):
        mid = 0.5*(lo + hi)
        if restitution(-mid) > e:
            lo = mid
        else:
            hi = mid
    return -0.5*(lo + hi)


def resolution_steps(dt, vmax):
    """collisionResolutionSteps that keep every code at one sub-cycle:
    returns (OpenFOAM, chargedFoam).

    The time step resolves the head-on Hertz impact at the largest fall
    speed vmax with STEPS_PER_COLLISION steps. The codes check a more
    pessimistic case every step (chargedFoam: the fastest parcel head-on
    against a copy of itself at twice its speed; OpenFOAM: the same with
    the rotation speed added and its own, shorter, collision-time formula);
    the resolutions are the largest whole numbers that keep that check at
    one sub-cycle for speeds up to 1.3 vmax."""
    v = 1.3*vmax
    m = mass_sphere()
    # chargedFoam (EllipsoidCollision::nSubCycles): m* = m/2, R* = R/2,
    # speed 2|U|; the sphere is the worst case of the two shapes
    tc_cf = hertz_collision_time(2*v, m/2, D/4, estar())
    # OpenFOAM (PairSpringSliderDashpot::nSubCycles):
    # 5.429675 R_min (rho/(E* sqrt(2 U)))^0.4 with R_min = d/4
    tc_of = 5.429675*D/4*(RHO/(estar()*math.sqrt(2*v)))**0.4
    return max(1, int(tc_of/dt)), max(1, int(tc_cf/dt))


def liggghts_restitution(beta):
    """coefficientRestitution whose LIGGGHTS closed form gives beta."""
    return math.exp(math.pi*beta/math.sqrt(1 - beta**2))


def lattice(n, spacing, base=BASE, z0=None, seed=1):
    """n sites of a simple cubic lattice filling the base x base floor layer
    by layer (x fastest), first layer at z0, and random velocities."""
    nx = int(base/spacing + 1e-9)
    ny = nx
    ox = 0.5*(base - (nx - 1)*spacing)
    oy = 0.5*(base - (ny - 1)*spacing)
    if z0 is None:
        z0 = 0.5*spacing + 0.25e-3
    i = np.arange(n)
    layer, k = np.divmod(i, nx*ny)
    x = np.stack([ox + spacing*(k % nx), oy + spacing*(k//nx), z0 + spacing*layer], 1)
    rng = np.random.default_rng(seed)
    U = UJITTER*(rng.random((n, 3)) - 0.5)
    # Orientations for ellipsoids: uniformly random unit quaternions (Shoemake)
    u1, u2, u3 = rng.random((3, n))
    q = np.stack([np.sqrt(u1)*np.cos(2*np.pi*u3), np.sqrt(1 - u1)*np.sin(2*np.pi*u2),
                  np.sqrt(1 - u1)*np.cos(2*np.pi*u2), np.sqrt(u1)*np.sin(2*np.pi*u3)], 1)
    return x, U, q


def box_height(n, spacing, base, cell):
    """Height of the box: the lattice's top site plus a bit, rounded up to a
    whole number of cells."""
    x, _, _ = lattice(n, spacing, base)
    top = x[:, 2].max() + spacing
    return float(f"{cell*math.ceil(top/cell - 1e-9):.12g}")


def time_step(n, spacing, base=BASE):
    """DEM time step: Hertz collision time of two spheres, head-on at the
    largest impact speed of the run (the top layer falling to the floor),
    over STEPS_PER_COLLISION, rounded down to two significant digits.
    Returns (deltaT, collision time, impact speed)."""
    x, _, _ = lattice(n, spacing, base)
    vmax = math.sqrt(2*G*x[:, 2].max()) + UJITTER
    m = mass_sphere()
    tc = hertz_collision_time(vmax, m/2, D/4, estar())
    dt = tc/STEPS_PER_COLLISION
    p = 10**math.floor(math.log10(dt)) / 10
    return float(f"{math.floor(dt/p + 1e-9)*p:.2g}"), tc, vmax


_BETA_CACHE = {}


def damping_ratio_cached(e):
    if e not in _BETA_CACHE:
        _BETA_CACHE[e] = damping_ratio(e)
    return _BETA_CACHE[e]
