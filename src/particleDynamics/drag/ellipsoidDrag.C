/*---------------------------------------------------------------------------*\
    chargedFoam: charged dielectric particles for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "ellipsoidDrag.H"
#include "ellipsoid.H"
#include "mathematicalConstants.H"

// * * * * * * * * * * * * * * * * Functions * * * * * * * * * * * * * * * //

Foam::scalar Foam::ellipsoidDrag::volumeEquivalentDiameter
(
    const vector& semiAxes
)
{
    return 2*cbrt(semiAxes.x()*semiAxes.y()*semiAxes.z());
}


Foam::scalar Foam::ellipsoidDrag::sphericity(const vector& semiAxes)
{
    const scalar dv = volumeEquivalentDiameter(semiAxes);
    return min
    (
        scalar(1),
        constant::mathematical::pi*sqr(dv)/ellipsoid::surfaceArea(semiAxes)
    );
}


Foam::scalar Foam::ellipsoidDrag::projectedArea
(
    const vector& semiAxes,
    const vector& uBody
)
{
    const scalar a2 = sqr(semiAxes.x());
    const scalar b2 = sqr(semiAxes.y());
    const scalar c2 = sqr(semiAxes.z());

    return constant::mathematical::pi*Foam::sqrt
    (
        b2*c2*sqr(uBody.x()) + a2*c2*sqr(uBody.y()) + a2*b2*sqr(uBody.z())
    );
}


Foam::scalar Foam::ellipsoidDrag::crosswiseSphericity
(
    const vector& semiAxes,
    const vector& uBody
)
{
    const scalar dv = volumeEquivalentDiameter(semiAxes);
    return
        0.25*constant::mathematical::pi*sqr(dv)
       /projectedArea(semiAxes, uBody);
}


Foam::scalar Foam::ellipsoidDrag::CdReHolzerSommerfeld
(
    const scalar Re,
    const scalar Phi,
    const scalar PhiPerp
)
{
    // H-S Eq. (9) times Re; -log10 Phi >= 0 since Phi <= 1
    const scalar minusLogPhi = max(scalar(0), -log10(Phi));

    return
        8/Foam::sqrt(PhiPerp)
      + 16/Foam::sqrt(Phi)
      + 3*Foam::sqrt(Re)/pow(Phi, 0.75)
      + 0.42*pow(scalar(10), 0.4*pow(minusLogPhi, 0.2))*Re/PhiPerp;
}


// ************************************************************************* //
