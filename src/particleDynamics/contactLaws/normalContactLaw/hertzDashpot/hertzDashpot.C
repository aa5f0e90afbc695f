/*---------------------------------------------------------------------------*\
    chargedFoam: charged dielectric particles for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "hertzDashpot.H"
#include "hertzOnset.H"
#include "addToRunTimeSelectionTable.H"

#include <map>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace normalContactLaws
{
    defineTypeNameAndDebug(hertzDashpot, 0);
    addToRunTimeSelectionTable(normalContactLaw, hertzDashpot, dictionary);
}
}


// * * * * * * * * * * * * * * * Static Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::normalContactLaws::hertzDashpot::restitution
(
    const scalar beta
)
{
    // x'' = -max(0, x^3/2 + gamma x^1/4 x'), x(0) = 0, x'(0) = 1; the
    // force never pulls, so once it vanishes while separating the body
    // flies off freely and e = -x' (see Description)
    const scalar gamma = Foam::sqrt(5.0)*mag(beta);

    auto accel = [gamma](const scalar x, const scalar v)
    {
        const scalar xp = max(x, scalar(0));
        return -max(xp*Foam::sqrt(xp) + gamma*Foam::sqrt(Foam::sqrt(xp))*v, 0.0);
    };

    // RK4; the contact lasts ~3.2 time units
    const scalar h = 2e-4;
    scalar x = 0, v = 1;
    for (label i = 0; i < 1000000; ++i)
    {
        const scalar k1x = v, k1v = accel(x, v);
        const scalar k2x = v + 0.5*h*k1v, k2v = accel(x + 0.5*h*k1x, v + 0.5*h*k1v);
        const scalar k3x = v + 0.5*h*k2v, k3v = accel(x + 0.5*h*k2x, v + 0.5*h*k2v);
        const scalar k4x = v + h*k3v, k4v = accel(x + h*k3x, v + h*k3v);
        x += h/6*(k1x + 2*k2x + 2*k3x + k4x);
        v += h/6*(k1v + 2*k2v + 2*k3v + k4v);

        if (x <= 0 || (v < 0 && accel(x, v) == 0))
        {
            return max(-v, scalar(0));
        }
    }
    return 0;
}


Foam::scalar Foam::normalContactLaws::hertzDashpot::calibratedDampingRatio
(
    const scalar e
)
{
    if (e >= 1)
    {
        return 0;
    }

    // Each calibration integrates about 60 impacts (about 80 million
    // instructions): a run asks for the same e for its pairs and its
    // walls, and for its material pairs, so the results are kept
    // (std::map: a handful of entries)
    static std::map<scalar, scalar> calibrated;
    const auto known = calibrated.find(e);
    if (known != calibrated.end())
    {
        return known->second;
    }

    // restitution(beta) falls monotonically with |beta|: bracket, bisect
    scalar lo = 0, hi = 1;
    while (restitution(-hi) > e && hi < 1e3)
    {
        hi *= 2;
    }
    for (label iter = 0; iter < 60; ++iter)
    {
        const scalar mid = 0.5*(lo + hi);
        if (restitution(-mid) > e)
        {
            lo = mid;
        }
        else
        {
            hi = mid;
        }
    }
    const scalar beta = -0.5*(lo + hi);
    calibrated[e] = beta;
    return beta;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::normalContactLaws::hertzDashpot::force
(
    const contactProperties& p,
    const contactKick& k,
    scalar& dUdR,
    contactWork& work
) const
{
    // contactLawLanes.H repeats these operations for the batches of
    // contacts in SIMD lanes: a change here goes there too (the batches'
    // unit tests compare the two bit for bit)
    const scalar delta = k.delta;
    const scalar vn = k.vn;
    const scalar dt = k.dt;

    // Hertz (Ruan Eq. 36) + dashpot (Rasera Eq. 9), no tension
    const scalar Sn = 2*p.Estar*k.sqrtRdelta;                // dF/d delta
    const scalar etaN =
        2*Foam::sqrt(5.0/6.0)*mag(p.beta)*Foam::sqrt(Sn*k.mStar);
    const scalar kHertz = (4.0/3.0)*p.Estar*k.sqrtR;
    const scalar delta32 = delta*Foam::sqrt(delta);
    scalar kick32 = delta32;
    scalar kick52 = delta*delta32;

    // The kicks' impulse missed where the contact begins between steps
    // (the last drift, at vn, started from no overlap) or ends (the next
    // drift, at the speed this kick leaves, ends in none): see Description
    auto correct = [&](const scalar w)
    {
        const hertzOnset::correction dc = hertzOnset::onsetCorrection(delta, w);
        kick32 -= dc.delta32;
        kick52 -= dc.delta52;
    };
    if (delta <= vn*dt)
    {
        correct(vn*dt);
    }
    const scalar vnNext =
        vn - dt*max(kHertz*kick32 + etaN*vn, scalar(0))*k.invMassNormal;
    if (delta + vnNext*dt <= 0)
    {
        correct(-vnNext*dt);
    }
    const scalar Fe = kHertz*kick32;
    const scalar Fn = max(Fe + etaN*vn, scalar(0));

    // Books: the elastic energy changes by Fe vn dt, the contact force does
    // -Fn vn dt of work: the difference (Fn - Fe) vn dt >= 0 is dissipated
    // (dashpot, or the released energy under the no-tension cut). On the
    // first and last step of a contact Fe carries the onset correction, so
    // there the books hold to that correction's impulse
    work.dissipated += (Fn - Fe)*vn*dt;
    work.elastic += 0.4*kHertz*delta*delta32;

    dUdR = k.R > 0 ? (4.0/15.0)*p.Estar*kick52/k.sqrtR : 0;

    return Fn;
}


// ************************************************************************* //
