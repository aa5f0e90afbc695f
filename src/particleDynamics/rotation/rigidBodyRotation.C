/*---------------------------------------------------------------------------*\
    chargedFoam: charged dielectric particles for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "rigidBodyRotation.H"
#include "error.H"

#include <cmath>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

// Out-of-class definitions: C++11 needs them once the constants are bound
// to references (e.g. by Foam::max or a test macro)
constexpr Foam::scalar Foam::rigidBodyRotation::sphereTolerance;
constexpr Foam::scalar Foam::rigidBodyRotation::unitTolerance;


namespace Foam
{
namespace
{

// cos x and sin(x)/x of the half angle x of a rotation, from x^2. Where
// x < 1e-3 (every body of a settled bed: |omega| dt ~ 1e-4) by their
// series, whose first omitted terms, x^6/720 and x^6/5040, are below
// round-off: the same rotation without libm's sin and cos (measured on the
// settling beds, whose bodies rotate every step)
inline void cosAndSinc(const scalar x2, scalar& c, scalar& sinc)
{
    if (x2 < 1e-6)
    {
        c = 1 - 0.5*x2*(1 - x2/12);
        sinc = 1 - x2/6*(1 - x2/20);
    }
    else
    {
        const scalar x = std::sqrt(x2);
        c = std::cos(x);
        sinc = std::sin(x)/x;
    }
}

// Axis k of the body in the inertial frame: column k of q.R()
inline vector bodyAxis(const quaternion& q, const direction k)
{
    const scalar w = q.w();
    const vector& v = q.v();
    switch (k)
    {
        case 0:
            return vector
            (
                sqr(w) + sqr(v.x()) - sqr(v.y()) - sqr(v.z()),
                2*(v.x()*v.y() + w*v.z()),
                2*(v.x()*v.z() - w*v.y())
            );
        case 1:
            return vector
            (
                2*(v.x()*v.y() - w*v.z()),
                sqr(w) - sqr(v.x()) + sqr(v.y()) - sqr(v.z()),
                2*(v.y()*v.z() + w*v.x())
            );
        default:
            return vector
            (
                2*(v.x()*v.z() + w*v.y()),
                2*(v.y()*v.z() - w*v.x()),
                sqr(w) - sqr(v.x()) - sqr(v.y()) + sqr(v.z())
            );
    }
}

// A product of unit quaternions, normalised against round-off: |q|^2 =
// 1 + e with e ~ 1e-16, and (3 - |q|^2)/2 is 1/|q| to O(e^2) (a Newton
// step for 1/sqrt)
inline void renormalise(quaternion& q)
{
    q *= 0.5*(3 - magSqr(q));
}

} // End anonymous namespace
} // End namespace Foam


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * * //

void Foam::rigidBodyRotation::stopMoments
(
    const vector& I,
    const char* caller
)
{
    FatalErrorIn(caller)
        << "Principal moments of inertia " << I
        << " are out of range: each must be finite and > 0"
        << exit(FatalError);
}


void Foam::rigidBodyRotation::stopOrientation
(
    const quaternion& q,
    const char* caller
)
{
    FatalErrorIn(caller)
        << "Orientation quaternion " << q << " of magnitude " << mag(q)
        << " is not a finite unit quaternion (tolerance "
        << unitTolerance << ")" << nl
        << "    Build it with rigidBodyRotation::fromEulerAngles or"
        << " normalise it once when reading it"
        << exit(FatalError);
}


void Foam::rigidBodyRotation::stopNotFinite
(
    const vector& v,
    const char* name,
    const char* caller
)
{
    FatalErrorIn(caller)
        << name << " = " << v << " is not finite" << exit(FatalError);
}


void Foam::rigidBodyRotation::axisRotation
(
    const direction i,
    const scalar h,
    const vector& I,
    quaternion& q,
    vector& Lp
)
{
    // Flow of H_i = Lp_i^2/(2 I_i): Lp_i is constant, so the body spins
    // about its axis i at the constant rate Lp_i/I_i and the sub-step is
    // an exact rotation by alpha
    const scalar alpha = Lp[i]/I[i]*h;
    scalar c, sinc;
    cosAndSinc(sqr(0.5*alpha), c, sinc);
    const scalar s = 0.5*alpha*sinc;

    // Body-frame rotation composes on the right (Ruan Eq. 18:
    // dq/dt = q*(0, Omega_p)/2)
    vector e(Zero);
    e[i] = s;
    q = q*quaternion(c, e);

    // Seen from the body, the fixed inertial L turns by -alpha about the
    // axis i (torque-free Euler equations, Ruan Eq. 20:
    // dLp/dt = Lp ^ Omega_p). (i, j, k) is a cyclic permutation.
    const direction j = (i + 1) % 3;
    const direction k = (i + 2) % 3;

    // cos(alpha), sin(alpha) from the half angle: no further trigonometry
    const scalar ca = (c - s)*(c + s);
    const scalar sa = 2*s*c;

    const scalar Lj = Lp[j];
    const scalar Lk = Lp[k];
    Lp[j] = ca*Lj + sa*Lk;
    Lp[k] = ca*Lk - sa*Lj;
}


// * * * * * * * * * * * * * * * * Orientation * * * * * * * * * * * * * * * //

Foam::quaternion Foam::rigidBodyRotation::fromEulerAngles
(
    const scalar phi,
    const scalar theta,
    const scalar psi
)
{
    checkFinite(vector(phi, theta, psi), "Euler angles", FUNCTION_NAME);

    // Ruan Eq. (17)
    const scalar cd = std::cos(0.5*(phi - psi));
    const scalar sd = std::sin(0.5*(phi - psi));
    const scalar cs = std::cos(0.5*(phi + psi));
    const scalar ss = std::sin(0.5*(phi + psi));
    const scalar ct = std::cos(0.5*theta);
    const scalar st = std::sin(0.5*theta);

    const scalar eps1 = cd*st;
    const scalar eps2 = sd*st;
    const scalar eps3 = ss*ct;
    const scalar eta = cs*ct;

    return quaternion(eta, vector(eps1, eps2, eps3));
}


Foam::tensor Foam::rigidBodyRotation::inertialToParticle(const quaternion& q)
{
    checkOrientation(q, FUNCTION_NAME);

    // Ruan's R of Eq. (16) is the transpose of the body-to-inertial
    // rotation of q = (eta, eps)
    return q.R().T();
}


Foam::vector Foam::rigidBodyRotation::toInertial
(
    const quaternion& q,
    const vector& vp
)
{
    checkOrientation(q, FUNCTION_NAME);
    return q.R() & vp;
}


Foam::vector Foam::rigidBodyRotation::toBody
(
    const quaternion& q,
    const vector& vin
)
{
    checkOrientation(q, FUNCTION_NAME);

    // R^T & v without forming the transpose
    return vin & q.R();
}


// * * * * * * * * * * * * * * * * * Inertia * * * * * * * * * * * * * * * * //

Foam::vector Foam::rigidBodyRotation::principalMoments
(
    const scalar mass,
    const vector& semiAxes
)
{
    if (!(mass > 0) || !std::isfinite(mass))
    {
        FatalErrorInFunction
            << "Particle mass " << mass
            << " is out of range: it must be finite and > 0"
            << exit(FatalError);
    }
    for (direction i = 0; i < vector::nComponents; ++i)
    {
        if (!(semiAxes[i] > 0) || !std::isfinite(semiAxes[i]))
        {
            FatalErrorInFunction
                << "Ellipsoid semi-axes " << semiAxes
                << " are out of range: each must be finite and > 0"
                << exit(FatalError);
        }
    }

    const scalar a2 = sqr(semiAxes.x());
    const scalar b2 = sqr(semiAxes.y());
    const scalar c2 = sqr(semiAxes.z());

    // Ruan, below Eq. (20)
    return (mass/5)*vector(b2 + c2, c2 + a2, a2 + b2);
}


// * * * * * * * * * * * * * Angular momentum and velocity * * * * * * * * * //

Foam::vector Foam::rigidBodyRotation::omegaBody
(
    const quaternion& q,
    const vector& Lin,
    const vector& I
)
{
    // Principal axes: Lp = diag(I) Omega_p
    return vector
    (
        cmptDivide(Lin & checkedRotation(q, Lin, I, FUNCTION_NAME), I)
    );
}


Foam::vector Foam::rigidBodyRotation::omegaInertial
(
    const quaternion& q,
    const vector& Lin,
    const vector& I
)
{
    const tensor R = checkedRotation(q, Lin, I, FUNCTION_NAME);
    return R & vector(cmptDivide(Lin & R, I));
}


Foam::vector Foam::rigidBodyRotation::angularMomentum
(
    const quaternion& q,
    const vector& omegaBody,
    const vector& I
)
{
    checkOrientation(q, FUNCTION_NAME);
    checkMoments(I, FUNCTION_NAME);
    checkFinite(omegaBody, "Body angular velocity", FUNCTION_NAME);

    return q.R() & vector(cmptMultiply(I, omegaBody));
}


Foam::scalar Foam::rigidBodyRotation::kineticEnergy
(
    const quaternion& q,
    const vector& Lin,
    const vector& I
)
{
    const vector Lp = Lin & checkedRotation(q, Lin, I, FUNCTION_NAME);
    return 0.5*(Lp & vector(cmptDivide(Lp, I)));
}


// * * * * * * * * * * * * * * * Time integration  * * * * * * * * * * * * * //

void Foam::rigidBodyRotation::freeRotation
(
    quaternion& q,
    const vector& Lin,
    const vector& I,
    const scalar dt
)
{
    checkOrientation(q, FUNCTION_NAME);
    checkMoments(I, FUNCTION_NAME);
    checkFinite(Lin, "Angular momentum", FUNCTION_NAME);
    if (!std::isfinite(dt))
    {
        FatalErrorInFunction
            << "Time step dt = " << dt << " is not finite"
            << exit(FatalError);
    }

    const scalar Imax = max(I.x(), max(I.y(), I.z()));
    const scalar Imin = min(I.x(), min(I.y(), I.z()));

    // The axis of a spheroid (two moments equal): the one that differs
    direction axis = 3;
    for (direction k = 0; k < 3; ++k)
    {
        const scalar Ij = I[(k + 1) % 3], Il = I[(k + 2) % 3];
        if (mag(Ij - Il) <= sphereTolerance*Imax)
        {
            axis = k;
        }
    }

    if (Imax - Imin <= sphereTolerance*Imax)
    {
        sphereRotation(q, Lin, (I.x() + I.y() + I.z())/3, dt);
    }
    else if (axis < 3)
    {
        // Spheroid: H = |L|^2/(2 I_perp) + Lp_k^2 (1/I_k - 1/I_perp)/2,
        // two commuting terms (|L| and Lp_k are constants of both flows),
        // each an exact rotation: about the fixed inertial L at |L|/I_perp
        // (on the left) and about the body axis k at
        // Lp_k (1/I_k - 1/I_perp) (on the right). Exact for any dt (the
        // regular precession of a symmetric top), two rotations where the
        // splitting below takes five. Lp_k from the start, the two
        // rotations side by side (independent chains of operations)
        const scalar Iperp = 0.5*(I[(axis + 1) % 3] + I[(axis + 2) % 3]);
        const scalar Lpk = Lin & bodyAxis(q, axis);
        const scalar halfAngle = 0.5*Lpk*(1/I[axis] - 1/Iperp)*dt;
        scalar c, sinc;
        cosAndSinc(sqr(halfAngle), c, sinc);
        vector e(Zero);
        e[axis] = halfAngle*sinc;

        // About L: sphereRotation's quaternion
        const scalar h = 0.5*dt/Iperp;
        scalar cL, sincL;
        cosAndSinc(sqr(h)*magSqr(Lin), cL, sincL);
        q = quaternion(cL, (sincL*h)*Lin)*q*quaternion(c, e);
    }
    else
    {
        // Symmetric (Strang) composition X(dt/2) Y(dt/2) Z(dt) Y(dt/2)
        // X(dt/2) of exact axis rotations (NO_SQUISH, Miller et al. 2002):
        // symplectic, reversible, second order. The body-frame L is
        // carried through the sub-steps, not recomputed, so that each
        // sub-step is the exact flow of its term of H.
        vector Lp = Lin & q.R();

        const scalar h = 0.5*dt;
        axisRotation(vector::X, h, I, q, Lp);
        axisRotation(vector::Y, h, I, q, Lp);
        axisRotation(vector::Z, dt, I, q, Lp);
        axisRotation(vector::Y, h, I, q, Lp);
        axisRotation(vector::X, h, I, q, Lp);
    }

    // Round-off control only: every sub-step is a unit quaternion product
    renormalise(q);
}


void Foam::rigidBodyRotation::sphereRotation
(
    quaternion& q,
    const vector& Lin,
    const scalar I,
    const scalar dt
)
{
    checkFinite(Lin, "Angular momentum", FUNCTION_NAME);
    if (!(I > 0) || !std::isfinite(I) || !std::isfinite(dt))
    {
        FatalErrorInFunction
            << "Moment of inertia " << I << " (must be finite and > 0) or"
            << " time step " << dt << " (finite) out of range"
            << exit(FatalError);
    }

    // Omega = L/I is constant in the inertial frame, so the motion is one
    // exact rotation about the fixed axis L/|L| by theta = |L| dt/I,
    // composed on the left (an inertial-frame rotation): the quaternion
    // (cos(x), sin(x)/x (dt/2I) L), x = theta/2
    const scalar h = 0.5*dt/I;
    const scalar x2 = sqr(h)*magSqr(Lin);
    if (x2 == 0)
    {
        return;
    }
    // cosAndSinc takes x^2: no square root of |L| where x is small
    scalar c, sinc;
    cosAndSinc(x2, c, sinc);
    q = quaternion(c, (sinc*h)*Lin)*q;
    renormalise(q);
}


// ************************************************************************* //
