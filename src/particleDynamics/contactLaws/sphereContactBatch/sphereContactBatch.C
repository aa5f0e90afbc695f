/*---------------------------------------------------------------------------*\
    chargedFoam: charged dielectric particles for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "sphereContactBatch.H"

#include "contactLawLanes.H"

using namespace Foam::simd;

static_assert
(
    Foam::sphereContactBatch::width == Foam::simd::width,
    "one lane per contact of a batch"
);



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
    }
    law_.pad(n);
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
    const lanes mA = load(mA_), mB = load(mB_);
    const pairMotion p = pairMotionOf
    (
        x1, x2, xA, load3(UA_), load3(omegaA_), mA,
        xB, load3(UB_), load3(omegaB_), mB
    );
    const lanes invMassNormal = one/mA + one/mB;

    // contactLaw::force with the default parts
    lanes3 xi = load3(xi_);
    const kickLanes k =
        defaultLawKick
        (
            law_, n, delta, R, p.vRel, p.mStar, invMassNormal, broadcast(dt),
            xi
        );

    // Torques about the centres, no rolling resistance
    store3(F_, k.F);
    store3(torqueA_, torqueAbout(p.xc, xA, k.F));
    store3(torqueB_, torqueAbout(p.xc, xB, k.F));
    store3(xi_, xi);
    store(overlap_, overlap);
    store(dissipated_, k.dissipated);
    store(elastic_, k.elastic);
    for (label l = 0; l < nLanes; ++l)
    {
        contact_[l] = touching[l];
        needsScalar_[l] = k.corrected[l];
    }
}


// ************************************************************************* //
