/*---------------------------------------------------------------------------*\
    chargedFoam: charged dielectric particles for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "mindlinSpring.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace tangentialContactLaws
{
    defineTypeNameAndDebug(mindlinSpring, 0);
    addToRunTimeSelectionTable
    (
        tangentialContactLaw,
        mindlinSpring,
        dictionary
    );
}
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::tangentialContactLaws::mindlinSpring::addForce
(
    const contactProperties& p,
    const contactKick& k,
    const scalar Fn,
    vector& xi,
    vector& F,
    contactWork& work
) const
{
    // contactLawLanes.H repeats these operations for the batches of
    // contacts in SIMD lanes: a change here goes there too (the batches'
    // unit tests compare the two bit for bit)
    const vector& n = k.n;
    const vector& vt = k.vt;
    const scalar dt = k.dt;

    // Keep xi in the current tangent plane with its length, then stretch
    // it (squared lengths: one square root per contact, none for the
    // friction test of a sticking contact)
    const scalar xiMag2 = magSqr(xi);
    if (xiMag2 > 0)
    {
        xi -= (xi & n)*n;
        const scalar xiProjMag2 = magSqr(xi);
        if (xiProjMag2 > 0)
        {
            xi *= Foam::sqrt(xiMag2/xiProjMag2);
        }
    }

    const scalar kT = 8*p.Gstar*k.sqrtRdelta;
    const vector xi0 = xi;
    const scalar springBefore = 0.5*kT*magSqr(xi0);
    xi += vt*dt;
    const scalar etaT =
        2*Foam::sqrt(5.0/6.0)*mag(p.beta)*Foam::sqrt(kT*k.mStar);
    vector Ft = -kT*xi - etaT*vt;
    const scalar FtMag2 = magSqr(Ft);
    const scalar FtMax = p.mu*Fn;
    if (FtMag2 > sqr(FtMax))
    {
        // Slip: the friction limit carries the spring and the dashpot in
        // parallel, both in series with the slider, so the dashpot acts at
        // the spring's rate: Ft = -kT xi - etaT (xi - xi0)/dt. The slip
        // (trial minus new spring length) is then (Ft - Ft_trial)/(kT +
        // etaT/dt), opposite to Ft, and the slider, the dashpot and the
        // spring's discrete update each dissipate >= 0. (Setting
        // -kT xi = Ft instead puts the dashpot's share into the spring:
        // energy from nothing.) Undamped (etaT = 0) this is xi = -Ft/kT
        Ft *= FtMax/Foam::sqrt(FtMag2);
        const scalar kRate = kT + etaT/dt;
        xi = kRate > VSMALL ? (etaT/dt*xi0 - Ft)/kRate : vector(Zero);
    }
    F += Ft;

    // Books: the work taken from the relative motion, -Ft.vt dt, goes into
    // the spring or is dissipated (dashpot, slip): >= 0 by the slip rule
    const scalar springAfter = 0.5*kT*magSqr(xi);
    work.dissipated += -(Ft & vt)*dt - (springAfter - springBefore);
    work.elastic += springAfter;
}


// ************************************************************************* //
