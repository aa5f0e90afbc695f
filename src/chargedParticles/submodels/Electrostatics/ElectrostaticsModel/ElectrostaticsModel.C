/*---------------------------------------------------------------------------*\
    chargedFoam: charged dielectric particles for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "ElectrostaticsModel.H"
#include "ListListOps.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

template<class CloudType>
Foam::dictionary Foam::ElectrostaticsModel<CloudType>::withCoeffs
(
    const dictionary& dict,
    const word& type
)
{
    // All coefficients have defaults: <type>Coeffs may be omitted
    dictionary d(dict);
    if (!d.found(type + "Coeffs"))
    {
        d.add(word(type + "Coeffs"), dictionary());
    }
    return d;
}


// * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * //

template<class CloudType>
void Foam::ElectrostaticsModel<CloudType>::gatherCharges
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
        x[i] = p.centre();
        q[i] = p.q();
        ++i;
    }

    Pstream::gatherList(allX);
    Pstream::scatterList(allX);
    Pstream::gatherList(allQ);
    Pstream::scatterList(allQ);
}



template<class CloudType>
void Foam::ElectrostaticsModel<CloudType>::combine
(
    const List<pointField>& allX,
    const List<scalarField>& allQ,
    pointField& x,
    scalarField& q,
    label& myStart
)
{
    myStart = 0;
    for (label proci = 0; proci < Pstream::myProcNo(); ++proci)
    {
        myStart += allX[proci].size();
    }
    x = ListListOps::combine<pointField>(allX, accessOp<pointField>());
    q = ListListOps::combine<scalarField>(allQ, accessOp<scalarField>());
}


template<class CloudType>
void Foam::ElectrostaticsModel<CloudType>::gatherCharges
(
    pointField& x,
    scalarField& q,
    label& myStart
) const
{
    List<pointField> allX;
    List<scalarField> allQ;
    gatherCharges(allX, allQ, x, q, myStart);
}


template<class CloudType>
void Foam::ElectrostaticsModel<CloudType>::gatherCharges
(
    List<pointField>& allX,
    List<scalarField>& allQ,
    pointField& x,
    scalarField& q,
    label& myStart
) const
{
    gatherCharges(allX, allQ);
    combine(allX, allQ, x, q, myStart);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

template<class CloudType>
Foam::ElectrostaticsModel<CloudType>::ElectrostaticsModel(CloudType& owner)
:
    CloudSubModelBase<CloudType>(owner)
{}


template<class CloudType>
Foam::ElectrostaticsModel<CloudType>::ElectrostaticsModel
(
    const dictionary& dict,
    CloudType& owner,
    const word& type
)
:
    CloudSubModelBase<CloudType>(owner, withCoeffs(dict, type), typeName, type)
{}


template<class CloudType>
Foam::ElectrostaticsModel<CloudType>::ElectrostaticsModel
(
    const ElectrostaticsModel<CloudType>& em
)
:
    CloudSubModelBase<CloudType>(em)
{}


// * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * * //

template<class CloudType>
Foam::autoPtr<Foam::ElectrostaticsModel<CloudType>>
Foam::ElectrostaticsModel<CloudType>::New
(
    const dictionary& dict,
    CloudType& owner
)
{
    const word modelType
    (
        dict.template lookupOrDefault<word>("electrostaticsModel", "none")
    );

    Info<< "Selecting electrostatics model " << modelType << endl;

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(modelType);

    if (!cstrIter.found())
    {
        FatalIOErrorInLookup
        (
            dict,
            "electrostaticsModel",
            modelType,
            *dictionaryConstructorTablePtr_
        ) << exit(FatalIOError);
    }

    return autoPtr<ElectrostaticsModel<CloudType>>(cstrIter()(dict, owner));
}


// ************************************************************************* //
