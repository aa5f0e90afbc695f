/*---------------------------------------------------------------------------*\
    chargedFoam: charged dielectric particles for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "TriboChargingModel.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

template<class CloudType>
Foam::TriboChargingModel<CloudType>::TriboChargingModel(CloudType& owner)
:
    CloudSubModelBase<CloudType>(owner)
{}


template<class CloudType>
Foam::TriboChargingModel<CloudType>::TriboChargingModel
(
    const dictionary& dict,
    CloudType& owner,
    const word& type
)
:
    CloudSubModelBase<CloudType>(owner, dict, typeName, type)
{}


template<class CloudType>
Foam::TriboChargingModel<CloudType>::TriboChargingModel
(
    const TriboChargingModel<CloudType>& tm
)
:
    CloudSubModelBase<CloudType>(tm)
{}


// * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * * //

template<class CloudType>
Foam::autoPtr<Foam::TriboChargingModel<CloudType>>
Foam::TriboChargingModel<CloudType>::New
(
    const dictionary& dict,
    CloudType& owner
)
{
    const word modelType
    (
        dict.template lookupOrDefault<word>("triboChargingModel", "none")
    );

    Info<< "Selecting tribocharging model " << modelType << endl;

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(modelType);

    if (!cstrIter.found())
    {
        FatalIOErrorInLookup
        (
            dict,
            "triboChargingModel",
            modelType,
            *dictionaryConstructorTablePtr_
        ) << exit(FatalIOError);
    }

    return autoPtr<TriboChargingModel<CloudType>>(cstrIter()(dict, owner));
}


// ************************************************************************* //
