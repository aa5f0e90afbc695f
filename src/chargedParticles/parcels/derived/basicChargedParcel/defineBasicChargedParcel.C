/*---------------------------------------------------------------------------*\
    chargedFoam: charged dielectric particles for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "basicChargedParcel.H"
#include "Cloud.H"

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

namespace Foam
{
    defineTemplateTypeNameAndDebug(basicChargedParcel, 0);
    defineTemplateTypeNameAndDebug(Cloud<basicChargedParcel>, 0);
}

// ************************************************************************* //
