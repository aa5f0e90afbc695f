/*---------------------------------------------------------------------------*\
    chargedFoam: charged dielectric particles for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "CutoffCoulomb.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

template<class CloudType>
Foam::CutoffCoulomb<CloudType>::CutoffCoulomb
(
    const dictionary& dict,
    CloudType& owner
)
:
    CoulombElectrostatics<CloudType>(dict, owner, typeName, true)
{
    Info<< "    Pairwise Coulomb sum within rCut = " << this->rCut_
        << " m (cell list), medium epsilonR = "
        << this->coulomb_.epsilonR() << endl;
}


template<class CloudType>
Foam::CutoffCoulomb<CloudType>::CutoffCoulomb
(
    const CutoffCoulomb<CloudType>& em
)
:
    CoulombElectrostatics<CloudType>(em)
{}


// * * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * //

template<class CloudType>
void Foam::CutoffCoulomb<CloudType>::calculate()
{
    // The local parcels and the halo of the other processors' parcels
    // within the cutoff (and within reach of a contact partner for the
    // reduced-stiffness correction): the same pairs as in serial
    pointField xS;
    scalarField qS;
    labelList ids;
    this->gatherPairHalo(xS, qS, ids);

    const label n = this->owner().size();
    const pointField x(SubList<point>(xS, n));
    vectorField E(n, Zero);
    this->coulomb_.addFieldsWithinCutoff(x, xS, qS, this->rCut_, E, 0);

    this->setFields(xS, qS, ids, E);
}


// ************************************************************************* //
