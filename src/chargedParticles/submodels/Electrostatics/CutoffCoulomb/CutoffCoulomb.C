/*---------------------------------------------------------------------------*\
    chargedFoam: charged dielectric particles for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "CutoffCoulomb.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

template<class CloudType>
Foam::CutoffCoulomb<CloudType>::CutoffCoulomb
(
    const dictionary& dict,
    CloudType& owner,
    const word& type
)
:
    DirectCoulomb<CloudType>(dict, owner, type),
    rCut_
    (
        this->coeffDict().found("rCut")
      ? this->coeffDict().template get<scalar>("rCut")
      : -1
    )
{
    if (!(rCut_ > 0) || !std::isfinite(rCut_))
    {
        FatalIOErrorInFunction(this->coeffDict())
            << "Entry rCut (cutoff radius [m]) in "
            << this->coeffDict().name().c_str() << " is "
            << (this->coeffDict().found("rCut") ? "out of range" : "missing")
            << ": it must be given, finite and > 0" << exit(FatalIOError);
    }
}


template<class CloudType>
Foam::CutoffCoulomb<CloudType>::CutoffCoulomb
(
    const dictionary& dict,
    CloudType& owner
)
:
    CutoffCoulomb<CloudType>(dict, owner, typeName)
{
    Info<< "    Pairwise Coulomb sum within rCut = " << rCut_
        << " m (cell list), medium epsilonR = "
        << this->coulomb_.epsilonR() << endl;
}


template<class CloudType>
Foam::CutoffCoulomb<CloudType>::CutoffCoulomb
(
    const CutoffCoulomb<CloudType>& em
)
:
    DirectCoulomb<CloudType>(em),
    rCut_(em.rCut_)
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
    this->gatherHalo
    (
        this->contactCorrection_ != 0
      ? max(rCut_, this->contactRange())
      : rCut_,
        xS, qS, ids
    );

    const label n = this->owner().size();
    const pointField x(SubList<point>(xS, n));
    vectorField E(n, Zero);
    this->coulomb_.addFieldsWithinCutoff(x, xS, qS, rCut_, E, 0);

    this->setFields(xS, qS, ids, E);
}


// ************************************************************************* //
