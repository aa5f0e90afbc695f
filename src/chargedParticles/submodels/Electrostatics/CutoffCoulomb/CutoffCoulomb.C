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
    // All charges as the sources, and per processor (the contact
    // correction wants those)
    List<pointField> allX;
    List<scalarField> allQ;
    pointField xS;
    scalarField qS;
    label offset = 0;
    this->gatherCharges(allX, allQ, xS, qS, offset);

    const pointField& x = allX[Pstream::myProcNo()];
    vectorField E(x.size(), Zero);
    this->coulomb_.addFieldsWithinCutoff(x, xS, qS, rCut_, E, offset);

    this->setFields(allX, allQ, E);
}


// ************************************************************************* //
