/*---------------------------------------------------------------------------*\
    chargedFoam: charged dielectric particles for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "coulombCollision.H"
#include "mathematicalConstants.H"
#include "error.H"

#include <cmath>

using Foam::constant::mathematical::pi;

// * * * * * * * * * * * * * * * Local functions * * * * * * * * * * * * * * //

namespace
{

void positive(const char* name, const Foam::scalar v)
{
    if (!(v > 0) || !std::isfinite(v))
    {
        FatalErrorInFunction
            << name << " = " << v << " is out of range: it must be finite"
            << " and > 0" << Foam::exit(Foam::FatalError);
    }
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Functions * * * * * * * * * * * * * * * * //

Foam::scalar Foam::coulombCollision::meanRelativeSpeed(const scalar qp2)
{
    positive("agitation qp2", qp2);
    return std::sqrt(16/pi*2.0/3.0*qp2);
}


Foam::scalar Foam::coulombCollision::diameter
(
    const scalar k,
    const scalar Qp,
    const scalar Qq,
    const scalar mp,
    const scalar mq,
    const scalar w
)
{
    positive("mass mp", mp);
    positive("mass mq", mq);
    positive("relative speed w", w);
    const scalar mpq = mp*mq/(mp + mq);
    // Like charges repel: |Qp Qq| sets the deflection scale either way
    return k*std::abs(Qp*Qq)/(mpq*w*w);
}


Foam::scalar Foam::coulombCollision::maxTimeStep
(
    const scalar dC,
    const scalar w,
    const scalar cfl
)
{
    positive("Coulomb diameter dC", dC);
    positive("relative speed w", w);
    positive("cfl", cfl);
    return cfl*dC/w;
}


Foam::scalar Foam::coulombCollision::maxTimeStep
(
    const scalar k,
    const scalar Qp,
    const scalar Qq,
    const scalar mp,
    const scalar mq,
    const scalar qp2,
    const scalar cfl
)
{
    const scalar w = meanRelativeSpeed(qp2);
    return maxTimeStep(diameter(k, Qp, Qq, mp, mq, w), w, cfl);
}


Foam::label Foam::coulombCollision::minNv
(
    const label Ne,
    const scalar dC,
    const scalar L
)
{
    positive("box edge L", L);
    // (2 Nv + 1) L/Ne >= 10 dC
    return label(std::ceil(5*Ne*dC/L - 0.5));
}


Foam::scalar Foam::coulombCollision::agitationEstimate
(
    const scalar k,
    const scalar Q,
    const scalar m,
    const scalar n
)
{
    positive("mass m", m);
    positive("number density n", n);
    return k*Q*Q*std::cbrt(n)/m;
}


Foam::scalar Foam::coulombCollision::tauEl
(
    const scalar k,
    const scalar Q,
    const scalar m,
    const scalar n
)
{
    positive("charge |Q|", std::abs(Q));
    positive("mass m", m);
    positive("number density n", n);
    return std::sqrt(3*m/(2*k*n))/std::abs(Q);
}


Foam::scalar Foam::coulombCollision::diameterEstimate(const scalar n)
{
    positive("number density n", n);
    return 3*pi/16/std::cbrt(n);
}


Foam::scalar Foam::coulombCollision::meanAccelerationEstimate
(
    const scalar k,
    const scalar Q,
    const scalar m,
    const scalar n
)
{
    positive("mass m", m);
    positive("number density n", n);
    return 2.5*k*Q*Q*std::pow(n, 2.0/3.0)/m;
}


// ************************************************************************* //
