/*---------------------------------------------------------------------------*\
    chargedFoam: charged dielectric particles for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "sphereContactBatch.H"

#include <cmath>
#include <cstring>
#ifdef __AVX__
#include <immintrin.h>
#endif

// * * * * * * * * * * * * * * * Local Functions  * * * * * * * * * * * * * //

// Without AVX, GCC notes that 32-byte vectors passed by value change the
// ABI: these functions are internal to this file
#pragma GCC diagnostic ignored "-Wpsabi"

namespace
{

using Foam::scalar;
using Foam::label;

// The lanes: GCC's (and Clang's) vector types, whose operators act lane by
// lane as the scalar ones (AVX where the build has it, else SSE2 pairs).
// Not Eigen's Array4d: its select() runs lane by lane, and the contact law
// selects (max, stick or slip) throughout
typedef scalar lanes __attribute__((vector_size(32)));
typedef long long laneMask __attribute__((vector_size(32)));

static_assert
(
    sizeof(lanes) == Foam::sphereContactBatch::width*sizeof(scalar),
    "one lane per contact of a batch"
);

inline lanes load(const scalar* p)
{
    lanes v;
    std::memcpy(&v, p, sizeof(lanes));
    return v;
}

inline void store(scalar* p, const lanes& v)
{
    std::memcpy(p, &v, sizeof(lanes));
}

inline lanes broadcast(const scalar s)
{
    return lanes{s, s, s, s};
}

inline lanes sqrtOf(const lanes& x)
{
#ifdef __AVX__
    return _mm256_sqrt_pd(x);
#else
    return lanes
    {
        std::sqrt(x[0]), std::sqrt(x[1]), std::sqrt(x[2]), std::sqrt(x[3])
    };
#endif
}

// Foam::max(a, b) = a > b ? a : b
inline lanes maxOf(const lanes& a, const lanes& b)
{
    return a > b ? a : b;
}

// A vector per lane
struct lanes3
{
    lanes x, y, z;
};

inline lanes3 load3(const scalar v[3][Foam::sphereContactBatch::width])
{
    return {load(v[0]), load(v[1]), load(v[2])};
}

inline void store3
(
    scalar v[3][Foam::sphereContactBatch::width],
    const lanes3& a
)
{
    store(v[0], a.x);
    store(v[1], a.y);
    store(v[2], a.z);
}

// OpenFOAM's vector operations, component by component in their order
// (VectorI.H, VectorSpaceI.H): a & b (and magSqr), a ^ b, a + b, a - b,
// s*a, a*s, a/s
inline lanes dot(const lanes3& a, const lanes3& b)
{
    return a.x*b.x + a.y*b.y + a.z*b.z;
}

inline lanes3 cross(const lanes3& a, const lanes3& b)
{
    return {a.y*b.z - a.z*b.y, a.z*b.x - a.x*b.z, a.x*b.y - a.y*b.x};
}

inline lanes3 operator+(const lanes3& a, const lanes3& b)
{
    return {a.x + b.x, a.y + b.y, a.z + b.z};
}

inline lanes3 operator-(const lanes3& a, const lanes3& b)
{
    return {a.x - b.x, a.y - b.y, a.z - b.z};
}

inline lanes3 operator*(const lanes& s, const lanes3& a)
{
    return {s*a.x, s*a.y, s*a.z};
}

inline lanes3 operator*(const lanes3& a, const lanes& s)
{
    return {a.x*s, a.y*s, a.z*s};
}

inline lanes3 operator/(const lanes3& a, const lanes& s)
{
    return {a.x/s, a.y/s, a.z/s};
}

// m ? a : b per lane
inline lanes3 choose(const laneMask& m, const lanes3& a, const lanes3& b)
{
    return {m ? a.x : b.x, m ? a.y : b.y, m ? a.z : b.z};
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * Static Functions  * * * * * * * * * * * * * //

Foam::sphereContactBatch::lawConstants
Foam::sphereContactBatch::lawConstants::of(const contactProperties& p)
{
    // The products as hertzDashpot::force and mindlinSpring::addForce
    // form them (left to right): Ruan Eq. (36), Rasera Eqs. (9), (11)
    lawConstants c;
    c.twoEstar = 2*p.Estar;
    c.fourThirdsEstar = (4.0/3.0)*p.Estar;
    c.eightGstar = 8*p.Gstar;
    c.dampingFactor = 2*Foam::sqrt(5.0/6.0)*mag(p.beta);
    c.mu = p.mu;
    return c;
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::sphereContactBatch::pad(const label n)
{
    for (label l = n; l < width; ++l)
    {
        for (label d = 0; d < 3; ++d)
        {
            xA_[d][l] = xA_[d][0];
            xB_[d][l] = xB_[d][0];
            UA_[d][l] = UA_[d][0];
            UB_[d][l] = UB_[d][0];
            omegaA_[d][l] = omegaA_[d][0];
            omegaB_[d][l] = omegaB_[d][0];
            xi_[d][l] = xi_[d][0];
        }
        rA_[l] = rA_[0];
        rB_[l] = rB_[0];
        mA_[l] = mA_[0];
        mB_[l] = mB_[0];
        twoEstar_[l] = twoEstar_[0];
        fourThirdsEstar_[l] = fourThirdsEstar_[0];
        eightGstar_[l] = eightGstar_[0];
        dampingFactor_[l] = dampingFactor_[0];
        mu_[l] = mu_[0];
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::sphereContactBatch::evaluate(const label nLanes, const scalar dt)
{
    pad(nLanes);

    const lanes zero = broadcast(0);
    const lanes one = broadcast(1);
    const lanes rA = load(rA_), rB = load(rB_);
    const lanes3 xA = load3(xA_), xB = load3(xB_);

    // ellipsoidContact::sphereSphere
    const lanes3 d = xB - xA;
    const lanes dist = sqrtOf(dot(d, d));
    const lanes overlap = rA + rB - dist;
    const laneMask touching = overlap > zero;
    const laneMask apart = dist > zero;
    const lanes3 n =
        choose(apart, d/(apart ? dist : one), lanes3{one, zero, zero});
    const lanes3 x1 = xA + rA*n;
    const lanes3 x2 = xB - rB*n;
    const lanes R = rA*rB/(rA + rB);
    // Lanes out of contact go on with a positive overlap (discarded)
    const lanes delta = touching ? overlap : rA;

    // EllipsoidCollision::pairForce: the contact point, the relative
    // velocity there, the reduced mass and the normal mobility of spheres
    const lanes half = broadcast(0.5);
    const lanes3 xc = half*(x1 + x2);
    const lanes3 vRel =
        (load3(UA_) + cross(load3(omegaA_), xc - xA))
      - (load3(UB_) + cross(load3(omegaB_), xc - xB));
    const lanes mA = load(mA_), mB = load(mB_);
    const lanes mStar = mA*mB/(mA + mB);
    const lanes invMassNormal = one/mA + one/mB;

    // contactLaw::force: the kick
    const lanes vn = dot(vRel, n);
    const lanes3 vt = vRel - vn*n;
    const lanes sqrtR = sqrtOf(R);
    const lanes sqrtRdelta = sqrtR*sqrtOf(delta);

    // hertzDashpot::force without the onset correction (needsScalar):
    // Hertz, Ruan Eq. (36), and dashpot, Rasera Eqs. (9)-(10), no tension
    const lanes dt4 = broadcast(dt);
    const lanes dampingFactor = load(dampingFactor_);
    const lanes Sn = load(twoEstar_)*sqrtRdelta;
    const lanes etaN = dampingFactor*sqrtOf(Sn*mStar);
    const lanes kHertz = load(fourThirdsEstar_)*sqrtR;
    const lanes delta32 = delta*sqrtOf(delta);
    const lanes vnNext =
        vn - dt4*maxOf(kHertz*delta32 + etaN*vn, zero)*invMassNormal;
    const laneMask corrected =
        (delta <= vn*dt4) | (delta + vnNext*dt4 <= zero);
    const lanes Fe = kHertz*delta32;
    const lanes Fn = maxOf(Fe + etaN*vn, zero);
    lanes dissipated = zero + (Fn - Fe)*vn*dt4;
    lanes elastic = zero + broadcast(0.4)*kHertz*delta*delta32;
    lanes3 F = (-Fn)*n;

    // mindlinSpring::addForce (Rasera Eqs. 7, 8, 11, 12): xi kept in the
    // tangent plane with its length, stretched, limited by friction
    lanes3 xi = load3(xi_);
    const lanes xiMag2 = dot(xi, xi);
    const laneMask hasXi = xiMag2 > zero;
    const lanes3 xiProj = xi - dot(xi, n)*n;
    const lanes xiProjMag2 = dot(xiProj, xiProj);
    const laneMask rescale = hasXi & (xiProjMag2 > zero);
    const lanes3 xiScaled =
        xiProj
       *sqrtOf((rescale ? xiMag2 : one)/(rescale ? xiProjMag2 : one));
    xi = choose(hasXi, choose(rescale, xiScaled, xiProj), xi);

    const lanes kT = load(eightGstar_)*sqrtRdelta;
    const lanes3 xi0 = xi;
    const lanes springBefore = half*kT*dot(xi0, xi0);
    xi = xi + vt*dt4;
    const lanes etaT = dampingFactor*sqrtOf(kT*mStar);
    lanes3 Ft = (-kT)*xi - etaT*vt;
    const lanes FtMag2 = dot(Ft, Ft);
    const lanes FtMax = load(mu_)*Fn;
    const laneMask slip = FtMag2 > FtMax*FtMax;
    {
        // Slip: the spring and its dashpot in series with the slider
        // (mindlinSpring.C)
        const lanes3 FtSlip = Ft*(FtMax/sqrtOf(slip ? FtMag2 : one));
        const lanes kRate = kT + etaT/dt4;
        const laneMask rated = kRate > broadcast(VSMALL);
        const lanes3 xiSlip =
            choose
            (
                rated,
                ((etaT/dt4)*xi0 - FtSlip)/(rated ? kRate : one),
                lanes3{zero, zero, zero}
            );
        Ft = choose(slip, FtSlip, Ft);
        xi = choose(slip, xiSlip, xi);
    }
    F = F + Ft;
    const lanes springAfter = half*kT*dot(xi, xi);
    dissipated =
        dissipated + ((-dot(Ft, vt))*dt4 - (springAfter - springBefore));
    elastic = elastic + springAfter;

    // Torques about the centres (Ruan Eq. 40), no rolling resistance; the
    // zero added is pairForce's rolling torque Mr = 0 (it turns a -0 into
    // +0, as there)
    const lanes3 none{zero, zero, zero};
    store3(F_, F);
    store3(MA_, cross(xc - xA, F) + none);
    store3(MB_, cross(xc - xB, F) + none);
    store3(xi_, xi);
    store(overlap_, overlap);
    store(dissipated_, dissipated);
    store(elastic_, elastic);
    for (label l = 0; l < nLanes; ++l)
    {
        contact_[l] = touching[l];
        needsScalar_[l] = corrected[l];
    }
}


// ************************************************************************* //
