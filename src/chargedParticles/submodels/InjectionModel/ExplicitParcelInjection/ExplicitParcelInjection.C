/*---------------------------------------------------------------------------*\
    chargedFoam: charged dielectric particles for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "ExplicitParcelInjection.H"
#include "mathematicalConstants.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

template<class CloudType>
Foam::dictionary Foam::ExplicitParcelInjection<CloudType>::implyBasis
(
    const dictionary& dict
)
{
    // One particle per parcel; the base class needs these entries
    dictionary d(dict);
    d.add("parcelBasisType", word("fixed"), true);
    d.add("nParticle", scalar(1), true);
    if (!d.found("massTotal"))
    {
        d.add("massTotal", scalar(0));
    }
    return d;
}


template<class CloudType>
Foam::scalar Foam::ExplicitParcelInjection<CloudType>::readParcelScalar
(
    const dictionary& dict,
    const label i,
    const word& key,
    const bool positive,
    const scalar* deflt
) const
{
    scalar value = deflt ? *deflt : 0;
    const bool found = dict.readIfPresent(key, value);

    if ((!found && !deflt) || !std::isfinite(value) || (positive && !(value > 0)))
    {
        FatalIOErrorInFunction(dict)
            << "Entry " << key << " of parcel " << i << " in "
            << this->coeffDict().name().c_str() << "/parcels is "
            << (found ? "out of range (" + Foam::name(value) + ")" : "missing").c_str()
            << ": it must be given"
            << (positive ? ", finite and > 0" : " and finite")
            << exit(FatalIOError);
    }
    return value;
}


template<class CloudType>
void Foam::ExplicitParcelInjection<CloudType>::readParcels()
{
    const PtrList<dictionary> parcels
    (
        this->coeffDict().lookup("parcels")
    );

    const label n = parcels.size();
    positions_.setSize(n);
    U_.setSize(n);
    d_.setSize(n);
    rho_.setSize(n);
    q_.setSize(n);

    const scalar rho0 =
        this->owner().constProps().dict().template get<scalar>("rho0");

    forAll(parcels, i)
    {
        const dictionary& pd = parcels[i];
        if (!pd.readIfPresent("position", positions_[i]))
        {
            FatalIOErrorInFunction(pd)
                << "Entry position of parcel " << i << " in "
                << this->coeffDict().name().c_str() << "/parcels is missing"
                << exit(FatalIOError);
        }
        U_[i] = pd.lookupOrDefault<vector>("U", Zero);
        d_[i] = readParcelScalar(pd, i, "d", true);
        rho_[i] = readParcelScalar(pd, i, "rho", true, &rho0);
        q_[i] = readParcelScalar(pd, i, "q", false);
    }

    this->volumeTotal_ = constant::mathematical::pi/6*sum(pow3(d_));
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

template<class CloudType>
Foam::ExplicitParcelInjection<CloudType>::ExplicitParcelInjection
(
    const dictionary& dict,
    CloudType& owner,
    const word& modelName
)
:
    InjectionModel<CloudType>(implyBasis(dict), owner, modelName, typeName)
{
    readParcels();
    updateMesh();
    Info<< "    " << positions_.size() << " explicit parcels" << endl;
}


template<class CloudType>
Foam::ExplicitParcelInjection<CloudType>::ExplicitParcelInjection
(
    const ExplicitParcelInjection<CloudType>& im
)
:
    InjectionModel<CloudType>(im),
    positions_(im.positions_),
    U_(im.U_),
    d_(im.d_),
    rho_(im.rho_),
    q_(im.q_),
    injectorCells_(im.injectorCells_),
    injectorTetFaces_(im.injectorTetFaces_),
    injectorTetPts_(im.injectorTetPts_)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class CloudType>
void Foam::ExplicitParcelInjection<CloudType>::updateMesh()
{
    const label n = positions_.size();
    injectorCells_.setSize(n);
    injectorTetFaces_.setSize(n);
    injectorTetPts_.setSize(n);

    forAll(positions_, i)
    {
        // Not found on any processor: error naming the position
        this->findCellAtPosition
        (
            injectorCells_[i],
            injectorTetFaces_[i],
            injectorTetPts_[i],
            positions_[i],
            true
        );
    }
}


template<class CloudType>
Foam::scalar Foam::ExplicitParcelInjection<CloudType>::timeEnd() const
{
    return this->SOI_ + ROOTVSMALL;
}


template<class CloudType>
Foam::label Foam::ExplicitParcelInjection<CloudType>::parcelsToInject
(
    const scalar time0,
    const scalar time1
)
{
    return (0 >= time0 && 0 < time1) ? positions_.size() : 0;
}


template<class CloudType>
Foam::scalar Foam::ExplicitParcelInjection<CloudType>::volumeToInject
(
    const scalar time0,
    const scalar time1
)
{
    return (0 >= time0 && 0 < time1) ? this->volumeTotal_ : 0;
}


template<class CloudType>
void Foam::ExplicitParcelInjection<CloudType>::setPositionAndCell
(
    const label parcelI,
    const label,
    const scalar,
    vector& position,
    label& cellOwner,
    label& tetFacei,
    label& tetPti
)
{
    position = positions_[parcelI];
    cellOwner = injectorCells_[parcelI];
    tetFacei = injectorTetFaces_[parcelI];
    tetPti = injectorTetPts_[parcelI];
}


template<class CloudType>
void Foam::ExplicitParcelInjection<CloudType>::setProperties
(
    const label parcelI,
    const label,
    const scalar,
    typename CloudType::parcelType& parcel
)
{
    parcel.U() = U_[parcelI];
    parcel.d() = d_[parcelI];
    parcel.rho() = rho_[parcelI];
    parcel.q() = q_[parcelI];
}


// ************************************************************************* //
