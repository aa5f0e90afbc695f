/*---------------------------------------------------------------------------*\
    chargedFoam: charged dielectric particles for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "DirectCoulomb.H"
#include "Pstream.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

template<class CloudType>
Foam::scalar Foam::DirectCoulomb<CloudType>::readEpsilonR
(
    const dictionary& coeffs
)
{
    const scalar epsilonR = coeffs.lookupOrDefault<scalar>("epsilonR", 1);
    if (!(epsilonR > 0) || !std::isfinite(epsilonR))
    {
        FatalIOErrorInFunction(coeffs)
            << "Entry epsilonR (relative permittivity of the medium) = "
            << epsilonR << " is out of range: it must be finite and > 0"
            << exit(FatalIOError);
    }
    return epsilonR;
}


template<class CloudType>
void Foam::DirectCoulomb<CloudType>::gatherCharges
(
    List<pointField>& allX,
    List<scalarField>& allQ
) const
{
    allX.setSize(Pstream::nProcs());
    allQ.setSize(Pstream::nProcs());

    pointField& x = allX[Pstream::myProcNo()];
    scalarField& q = allQ[Pstream::myProcNo()];
    x.setSize(this->owner().size());
    q.setSize(this->owner().size());
    label i = 0;
    for (const auto& p : this->owner())
    {
        x[i] = p.position();
        q[i] = p.q();
        ++i;
    }

    Pstream::gatherList(allX);
    Pstream::scatterList(allX);
    Pstream::gatherList(allQ);
    Pstream::scatterList(allQ);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

template<class CloudType>
Foam::DirectCoulomb<CloudType>::DirectCoulomb
(
    const dictionary& dict,
    CloudType& owner
)
:
    ElectrostaticsModel<CloudType>(dict, owner, typeName),
    coulomb_(readEpsilonR(this->coeffDict()))
{
    Info<< "    Direct pairwise Coulomb sum, medium epsilonR = "
        << coulomb_.epsilonR() << endl;
}


template<class CloudType>
Foam::DirectCoulomb<CloudType>::DirectCoulomb
(
    const DirectCoulomb<CloudType>& em
)
:
    ElectrostaticsModel<CloudType>(em),
    coulomb_(em.coulomb_)
{}


// * * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * //

template<class CloudType>
void Foam::DirectCoulomb<CloudType>::calculate()
{
    List<pointField> allX;
    List<scalarField> allQ;
    gatherCharges(allX, allQ);

    const label me = Pstream::myProcNo();
    const pointField& x = allX[me];
    const scalarField& q = allQ[me];

    vectorField f(x.size(), Zero);
    coulomb_.addForces(x, q, f);

    forAll(allX, proci)
    {
        if (proci != me)
        {
            coulomb_.addForces(x, q, allX[proci], allQ[proci], f);
        }
    }

    label i = 0;
    for (auto& p : this->owner())
    {
        p.fE() = f[i++];
    }
}


template<class CloudType>
Foam::scalar Foam::DirectCoulomb<CloudType>::energy() const
{
    List<pointField> allX;
    List<scalarField> allQ;
    gatherCharges(allX, allQ);

    const label me = Pstream::myProcNo();
    scalar e = coulomb_.energy(allX[me], allQ[me]);

    // Each cross-processor pair once: with the higher processors only
    for (label proci = me + 1; proci < allX.size(); ++proci)
    {
        e += coulomb_.energy(allX[me], allQ[me], allX[proci], allQ[proci]);
    }

    return returnReduce(e, sumOp<scalar>());
}


// ************************************************************************* //
