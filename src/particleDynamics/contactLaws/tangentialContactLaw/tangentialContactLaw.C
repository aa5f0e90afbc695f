/*---------------------------------------------------------------------------*\
    chargedFoam: charged dielectric particles for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "tangentialContactLaw.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(tangentialContactLaw, 0);
    defineRunTimeSelectionTable(tangentialContactLaw, dictionary);
}


// ************************************************************************* //
