/*---------------------------------------------------------------------------*\
    chargedFoam: charged dielectric particles for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "EllipsoidDragForce.H"
#include "ellipsoidDrag.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

template<class CloudType>
Foam::EllipsoidDragForce<CloudType>::EllipsoidDragForce
(
    CloudType& owner,
    const fvMesh& mesh,
    const dictionary& dict
)
:
    ParticleForce<CloudType>(owner, mesh, dict, typeName, false)
{}


template<class CloudType>
Foam::EllipsoidDragForce<CloudType>::EllipsoidDragForce
(
    const EllipsoidDragForce& df
)
:
    ParticleForce<CloudType>(df)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class CloudType>
Foam::scalar Foam::EllipsoidDragForce<CloudType>::CdRe
(
    const typename CloudType::parcelType& p,
    const vector& slip,
    const scalar Re
)
{
    if (p.isSphere())
    {
        return ellipsoidDrag::CdReSphere(Re);
    }

    // Flow direction in the body frame (x_in = R & x_body). Without slip
    // the force is zero whatever Cd: any direction does.
    const scalar magSlip = mag(slip);
    const vector uBody =
        magSlip > VSMALL
      ? (p.orientation().R().T() & slip)/magSlip
      : vector(1, 0, 0);

    return ellipsoidDrag::CdReHolzerSommerfeld
    (
        Re,
        ellipsoidDrag::sphericity(p.semiAxes()),
        ellipsoidDrag::crosswiseSphericity(p.semiAxes(), uBody)
    );
}


template<class CloudType>
Foam::forceSuSp Foam::EllipsoidDragForce<CloudType>::calcCoupled
(
    const typename CloudType::parcelType& p,
    const typename CloudType::parcelType::trackingData& td,
    const scalar dt,
    const scalar mass,
    const scalar Re,
    const scalar muc
) const
{
    forceSuSp value(Zero);

    // F = 1/2 rho_c Cd (pi d^2/4) |u| u = Sp u with Re = rho_c |u| d/mu_c:
    // the expression of OpenFOAM's SphereDragForce (bit-identical for spheres)
    value.Sp() =
        mass*0.75*muc*CdRe(p, td.Uc() - p.U(), Re)/(p.rho()*sqr(p.d()));

    return value;
}


// ************************************************************************* //
