/*---------------------------------------------------------------------------*\
    chargedFoam: charged dielectric particles for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "coulombFriction.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace tangentialContactLaws
{
    defineTypeNameAndDebug(coulombFriction, 0);
    addToRunTimeSelectionTable
    (
        tangentialContactLaw,
        coulombFriction,
        dictionary
    );
}
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::tangentialContactLaws::coulombFriction::addForce
(
    const contactProperties& p,
    const contactKick& k,
    const scalar Fn,
    vector&,
    vector& F,
    contactWork& work
) const
{
    // Ruan Eq. (39): sliding friction against the slip velocity
    const scalar vtMag = mag(k.vt);
    if (vtMag > VSMALL)
    {
        F -= p.mu*Fn*k.vt/vtMag;
    }
    work.dissipated += p.mu*Fn*vtMag*k.dt;
}


// ************************************************************************* //
