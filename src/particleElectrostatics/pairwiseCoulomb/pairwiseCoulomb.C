/*---------------------------------------------------------------------------*\
    chargedFoam: charged dielectric particles for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "pairwiseCoulomb.H"
#include "cutoffPairs.H"
#include "mathematicalConstants.H"
#include "error.H"

// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * * //

void Foam::pairwiseCoulomb::coincident
(
    const label i,
    const label j,
    const point& x
)
{
    FatalErrorInFunction
        << "Charges " << i << " and " << j << " coincide at " << x
        << ": the Coulomb force between them is infinite." << nl
        << "    Check the parcels' initial positions (entries position of"
        << " the injection models: overlapping or repeated parcels?)"
        << exit(FatalError);

    ::abort();  // not reached
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::pairwiseCoulomb::pairwiseCoulomb(const scalar epsilonR)
:
    epsilonR_(epsilonR),
    k_
    (
        1.0
       /(
            4*constant::mathematical::pi
           *vacuumPermittivity
           *epsilonR
        )
    )
{
    if (!(epsilonR > 0) || !std::isfinite(epsilonR))
    {
        FatalErrorInFunction
            << "Relative permittivity epsilonR = " << epsilonR
            << " is out of range: it must be finite and > 0"
            << exit(FatalError);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::vector Foam::pairwiseCoulomb::pairForce
(
    const point& xi,
    const scalar qi,
    const point& xj,
    const scalar qj
) const
{
    const vector rij = xi - xj;
    const scalar r2 = magSqr(rij);
    if (r2 == 0)
    {
        coincident(0, 1, xi);
    }
    return force(rij, r2, qi*qj);
}


Foam::vector Foam::pairwiseCoulomb::pairField
(
    const point& xi,
    const point& xj,
    const scalar qj
) const
{
    const vector rij = xi - xj;
    const scalar r2 = magSqr(rij);
    if (r2 == 0)
    {
        coincident(0, 1, xi);
    }
    return force(rij, r2, qj);
}


void Foam::pairwiseCoulomb::addFields
(
    const UList<point>& x,
    const UList<scalar>& q,
    UList<vector>& E
) const
{
    const label n = x.size();
    for (label i = 0; i < n; ++i)
    {
        const point& xi = x[i];
        const scalar qi = q[i];
        vector Ei(Zero);

        for (label j = i + 1; j < n; ++j)
        {
            const vector rij = xi - x[j];
            const scalar r2 = magSqr(rij);
            if (r2 == 0)
            {
                coincident(i, j, xi);
            }
            // k r/r^3 once for both ends of the pair
            const vector g = force(rij, r2, 1);
            Ei += q[j]*g;
            E[j] -= qi*g;
        }
        E[i] += Ei;
    }
}


void Foam::pairwiseCoulomb::addFields
(
    const UList<point>& xT,
    const UList<point>& xS,
    const UList<scalar>& qS,
    UList<vector>& ET
) const
{
    forAll(xT, i)
    {
        const point& xi = xT[i];
        vector Ei(Zero);
        forAll(xS, j)
        {
            const vector rij = xi - xS[j];
            const scalar r2 = magSqr(rij);
            if (r2 == 0)
            {
                coincident(i, j, xi);
            }
            Ei += force(rij, r2, qS[j]);
        }
        ET[i] += Ei;
    }
}


void Foam::pairwiseCoulomb::addFieldsWithinCutoff
(
    const UList<point>& xT,
    const UList<point>& xS,
    const UList<scalar>& qS,
    const scalar rCut,
    UList<vector>& ET,
    const label selfOffset
) const
{
    forPairsWithinCutoff
    (
        xT, xS, rCut, selfOffset,
        [&](const label t, const label s, const vector& r, const scalar r2)
        {
            if (r2 == 0)
            {
                coincident(t, s, xT[t]);
            }
            ET[t] += force(r, r2, qS[s]);
        }
    );
}


void Foam::pairwiseCoulomb::addForces
(
    const UList<point>& x,
    const UList<scalar>& q,
    UList<vector>& f
) const
{
    // Not q*addFields: the pair force q_i q_j g is formed once and given
    // to both ends, so that Newton's third law holds bit for bit
    const label n = x.size();
    for (label i = 0; i < n; ++i)
    {
        const point& xi = x[i];
        const scalar qi = q[i];
        vector fi(Zero);

        for (label j = i + 1; j < n; ++j)
        {
            const vector rij = xi - x[j];
            const scalar r2 = magSqr(rij);
            if (r2 == 0)
            {
                coincident(i, j, xi);
            }
            const vector fij = force(rij, r2, qi*q[j]);
            fi += fij;
            f[j] -= fij;
        }
        f[i] += fi;
    }
}


void Foam::pairwiseCoulomb::addForces
(
    const UList<point>& x,
    const UList<scalar>& q,
    const UList<labelPair>& pairs,
    UList<vector>& f
) const
{
    for (const labelPair& ij : pairs)
    {
        const label i = ij.first();
        const label j = ij.second();
        const vector rij = x[i] - x[j];
        const scalar r2 = magSqr(rij);
        if (r2 == 0)
        {
            coincident(i, j, x[i]);
        }
        const vector fij = force(rij, r2, q[i]*q[j]);
        f[i] += fij;
        f[j] -= fij;
    }
}


void Foam::pairwiseCoulomb::addForces
(
    const UList<point>& xT,
    const UList<scalar>& qT,
    const UList<point>& xS,
    const UList<scalar>& qS,
    UList<vector>& fT
) const
{
    forAll(xT, i)
    {
        const point& xi = xT[i];
        vector fi(Zero);
        forAll(xS, j)
        {
            const vector rij = xi - xS[j];
            const scalar r2 = magSqr(rij);
            if (r2 == 0)
            {
                coincident(i, j, xi);
            }
            fi += force(rij, r2, qS[j]);
        }
        fT[i] += qT[i]*fi;
    }
}


Foam::scalar Foam::pairwiseCoulomb::energy
(
    const UList<point>& x,
    const UList<scalar>& q
) const
{
    scalar e = 0;
    const label n = x.size();
    for (label i = 0; i < n; ++i)
    {
        for (label j = i + 1; j < n; ++j)
        {
            const scalar r = mag(x[i] - x[j]);
            if (r == 0)
            {
                coincident(i, j, x[i]);
            }
            e += q[i]*q[j]/r;
        }
    }
    return k_*e;
}


Foam::scalar Foam::pairwiseCoulomb::energy
(
    const UList<point>& xT,
    const UList<scalar>& qT,
    const UList<point>& xS,
    const UList<scalar>& qS
) const
{
    scalar e = 0;
    forAll(xT, i)
    {
        forAll(xS, j)
        {
            const scalar r = mag(xT[i] - xS[j]);
            if (r == 0)
            {
                coincident(i, j, xT[i]);
            }
            e += qT[i]*qS[j]/r;
        }
    }
    return k_*e;
}


// ************************************************************************* //
