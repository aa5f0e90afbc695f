/*---------------------------------------------------------------------------*\
    chargedFoam: charged dielectric particles for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "basicChargedParcel.H"
#include "Cloud.H"

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

namespace Foam
{
    // The layers below ChargedParcel that OpenFOAM does not define
    typedef LazyTrackingParcel<CollidingParcel<KinematicParcel<particle>>>
        basicLazyTrackingParcel;
    defineTemplateTypeNameAndDebug(basicLazyTrackingParcel, 0);

    typedef EllipsoidParcel<basicLazyTrackingParcel> basicEllipsoidParcel;
    defineTemplateTypeNameAndDebug(basicEllipsoidParcel, 0);

    defineTemplateTypeNameAndDebug(basicChargedParcel, 0);
    defineTemplateTypeNameAndDebug(Cloud<basicChargedParcel>, 0);
}

// ************************************************************************* //
