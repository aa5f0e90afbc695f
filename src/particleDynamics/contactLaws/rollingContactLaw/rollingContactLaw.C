/*---------------------------------------------------------------------------*\
    chargedFoam: charged dielectric particles for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "rollingContactLaw.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(rollingContactLaw, 0);
    defineRunTimeSelectionTable(rollingContactLaw, dictionary);
}


// ************************************************************************* //
