/*---------------------------------------------------------------------------*\
    chargedFoam: charged dielectric particles for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "DirectCoulomb.H"
#include "Pstream.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

template<class CloudType>
Foam::DirectCoulomb<CloudType>::DirectCoulomb
(
    const dictionary& dict,
    CloudType& owner
)
:
    CoulombElectrostatics<CloudType>(dict, owner, typeName)
{
    Info<< "    Direct pairwise Coulomb sum, medium epsilonR = "
        << this->coulomb_.epsilonR() << endl;
}


template<class CloudType>
Foam::DirectCoulomb<CloudType>::DirectCoulomb
(
    const DirectCoulomb<CloudType>& em
)
:
    CoulombElectrostatics<CloudType>(em)
{}


// * * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * //

template<class CloudType>
void Foam::DirectCoulomb<CloudType>::calculate()
{
    List<pointField> allX;
    List<scalarField> allQ;
    this->gatherCharges(allX, allQ);

    const label me = Pstream::myProcNo();
    const pointField& x = allX[me];
    const scalarField& q = allQ[me];

    // The field first (contact charging needs it, also for neutral
    // parcels), then the force q E
    vectorField E(x.size(), Zero);
    this->coulomb_.addFields(x, q, E);

    forAll(allX, proci)
    {
        if (proci != me)
        {
            this->coulomb_.addFields(x, allX[proci], allQ[proci], E);
        }
    }

    this->setFields(allX, allQ, E);
}


template<class CloudType>
Foam::scalar Foam::DirectCoulomb<CloudType>::energy() const
{
    List<pointField> allX;
    List<scalarField> allQ;
    this->gatherCharges(allX, allQ);

    const label me = Pstream::myProcNo();
    scalar e = this->coulomb_.energy(allX[me], allQ[me]);

    // Each cross-processor pair once: with the higher processors only
    for (label proci = me + 1; proci < allX.size(); ++proci)
    {
        e += this->coulomb_.energy
        (
            allX[me], allQ[me], allX[proci], allQ[proci]
        );
    }

    return returnReduce(e, sumOp<scalar>());
}


// ************************************************************************* //
