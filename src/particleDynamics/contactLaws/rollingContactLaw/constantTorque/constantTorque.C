/*---------------------------------------------------------------------------*\
    chargedFoam: charged dielectric particles for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "constantTorque.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace rollingContactLaws
{
    defineTypeNameAndDebug(constantTorque, 0);
    addToRunTimeSelectionTable(rollingContactLaw, constantTorque, dictionary);
}
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::vector Foam::rollingContactLaws::constantTorque::torque
(
    const contactProperties& p,
    const scalar Fn,
    const scalar R,
    const vector& w,
    const scalar Ieff,
    const scalar dt,
    scalar& dissipated
) const
{
    const scalar wMag = mag(w);
    if (p.muR <= 0 || wMag < VSMALL)
    {
        return Zero;
    }

    // Limited so that w is not reversed: a half kick dt/2 M/I must not
    // exceed |w| (both kicks of a step)
    const scalar Mmag = min(p.muR*R*Fn, Ieff*wMag/dt);

    dissipated += Mmag*wMag*dt;

    return -Mmag*w/wMag;
}


// ************************************************************************* //
