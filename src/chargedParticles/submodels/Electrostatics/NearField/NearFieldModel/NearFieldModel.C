/*---------------------------------------------------------------------------*\
    chargedFoam: charged dielectric particles for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "NearFieldModel.H"
#include "Pstream.H"

#include <algorithm>

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

template<class CloudType>
Foam::NearFieldModel<CloudType>::NearFieldModel
(
    const dictionary& dict,
    CloudType& owner
)
:
    owner_(owner),
    dict_(dict)
{}


// * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * //

template<class CloudType>
Foam::labelList Foam::NearFieldModel<CloudType>::idOrder
(
    const labelList& ids
)
{
    // Stable: a parcel's cyclic copies follow it in the order they came
    labelList order(identity(ids.size()/2));
    std::stable_sort
    (
        order.begin(),
        order.end(),
        [&](const label a, const label b)
        {
            return
                ids[2*a] < ids[2*b]
             || (ids[2*a] == ids[2*b] && ids[2*a + 1] < ids[2*b + 1]);
        }
    );
    return order;
}


// * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * * //

template<class CloudType>
Foam::autoPtr<Foam::NearFieldModel<CloudType>>
Foam::NearFieldModel<CloudType>::New
(
    const dictionary& farFieldCoeffs,
    CloudType& owner
)
{
    if (farFieldCoeffs.found("nearField") && !farFieldCoeffs.isDict("nearField"))
    {
        FatalIOErrorInFunction(farFieldCoeffs)
            << "Entry nearField in " << farFieldCoeffs.name().c_str()
            << " must be a dictionary: nearField { type none|"
            << "inducedDipole|bem; }" << exit(FatalIOError);
    }
    const dictionary& dict = farFieldCoeffs.subOrEmptyDict("nearField");
    const word modelType(dict.template lookupOrDefault<word>("type", "none"));

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(modelType);

    if (!cstrIter.found())
    {
        FatalIOErrorInLookup
        (
            dict,
            "type",
            modelType,
            *dictionaryConstructorTablePtr_
        ) << exit(FatalIOError);
    }

    if (modelType != "none")
    {
        Info<< "    Near field " << modelType << endl;
    }

    return autoPtr<NearFieldModel<CloudType>>(cstrIter()(dict, owner));
}


// ************************************************************************* //
