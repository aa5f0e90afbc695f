/*---------------------------------------------------------------------------*\
    chargedFoam: charged dielectric particles for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "ExplicitParcelInjection.H"
#include "mathematicalConstants.H"
#include "rigidBodyRotation.H"
#include "inputLimits.H"

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
    const scalar* deflt,
    const scalar lo,
    const scalar hi,
    const string& unit
) const
{
    scalar value = deflt ? *deflt : 0;
    const bool found = dict.readIfPresent(key, value);
    const bool bounded = positive && hi > 0;

    if
    (
        (!found && !deflt)
     || !std::isfinite(value)
     || (positive && !(value > 0))
     || (bounded && !(value >= lo && value <= hi))
    )
    {
        FatalIOErrorInFunction(dict)
            << "Entry " << key << " of parcel " << i << " in "
            << this->coeffDict().name().c_str() << "/parcels is "
            << (found ? "out of range (" + Foam::name(value) + ")" : "missing").c_str()
            << ": it must be given"
            << (positive ? ", finite and > 0" : " and finite");
        if (bounded)
        {
            const std::string from(lo > VSMALL ? "[" + Foam::name(lo) : "(0");
            FatalIOError
                << ", in " << from.c_str() << ", " << hi << "]"
                << (unit.size() ? " " + unit : std::string()).c_str();
        }
        FatalIOError << exit(FatalIOError);
    }
    return value;
}


template<class CloudType>
void Foam::ExplicitParcelInjection<CloudType>::checkFinite
(
    const dictionary& dict,
    const label i,
    const word& key,
    const vector& value,
    const scalar maxMag,
    const string& why
) const
{
    if (!inputLimits::finite(value))
    {
        FatalIOErrorInFunction(dict)
            << "Entry " << key << " of parcel " << i << " in "
            << this->coeffDict().name().c_str() << "/parcels is out of"
            << " range (" << value << "): all components must be finite"
            << exit(FatalIOError);
    }
    if (maxMag > 0 && !inputLimits::magBelow(value, maxMag))
    {
        FatalIOErrorInFunction(dict)
            << "Entry " << key << " of parcel " << i << " in "
            << this->coeffDict().name().c_str() << "/parcels is out of"
            << " range (" << value << "): its magnitude must be below "
            << maxMag << " (" << why.c_str() << ")" << exit(FatalIOError);
    }
}


template<class CloudType>
Foam::quaternion Foam::ExplicitParcelInjection<CloudType>::readOrientation
(
    const dictionary& pd,
    const label i
) const
{
    const bool euler = pd.found("eulerAngles");
    const bool quat = pd.found("quaternion");
    if (euler && quat)
    {
        FatalIOErrorInFunction(pd)
            << "Parcel " << i << " in " << this->coeffDict().name().c_str()
            << "/parcels gives both eulerAngles and quaternion: give one"
            << exit(FatalIOError);
    }
    if (euler)
    {
        const vector angles(pd.get<vector>("eulerAngles"));
        checkFinite(pd, i, "eulerAngles", angles);
        const scalar deg = constant::mathematical::pi/180;
        return rigidBodyRotation::fromEulerAngles
        (
            deg*angles.x(), deg*angles.y(), deg*angles.z()
        );
    }
    if (quat)
    {
        const FixedList<scalar, 4> c(pd.lookup("quaternion"));
        // Any finite, non-zero quaternion is a rotation: one of extreme
        // size is scaled by its largest component first (its norm would
        // overflow or underflow)
        scalar cMax = 0;
        bool finite = true;
        for (const scalar ci : c)
        {
            finite = finite && std::isfinite(ci);
            cMax = max(cMax, mag(ci));
        }
        if (!finite || !(cMax > 0))
        {
            FatalIOErrorInFunction(pd)
                << "Entry quaternion of parcel " << i << " = " << c
                << " is out of range: it must be finite and non-zero"
                << exit(FatalIOError);
        }
        const scalar s = (cMax > 1e100 || cMax < 1e-100) ? 1/cMax : 1;
        const quaternion q(s*c[0], vector(s*c[1], s*c[2], s*c[3]));
        return q.normalized();
    }
    return quaternion::I;
}


template<class CloudType>
void Foam::ExplicitParcelInjection<CloudType>::readParcelSize
(
    const dictionary& pd,
    const label i,
    const scalar sizeMax
)
{
    const string sizeUnit
    (
        "m (1 nm to the diagonal of the mesh's bounding box)"
    );
    // Size: a sphere's diameter or an ellipsoid's semi-axes
    semiAxes_[i] = Zero;
    if (pd.readIfPresent("semiAxes", semiAxes_[i]))
    {
        if (pd.found("d"))
        {
            FatalIOErrorInFunction(pd)
                << "Parcel " << i << " in "
                << this->coeffDict().name().c_str()
                << "/parcels gives both d and semiAxes: give one"
                << exit(FatalIOError);
        }
        const vector& s = semiAxes_[i];
        if
        (
            !inputLimits::finite(s)
         || !(cmptMin(s) >= 0.5*inputLimits::sizeMin)
         || !(cmptMax(s) <= sizeMax)
         || !(cmptMax(s) <= inputLimits::aspectRatioMax*cmptMin(s))
        )
        {
            FatalIOErrorInFunction(pd)
                << "Entry semiAxes of parcel " << i << " in "
                << this->coeffDict().name().c_str()
                << "/parcels is out of range (" << s
                << "): all must be finite and > 0, in ["
                << 0.5*inputLimits::sizeMin << ", " << sizeMax
                << "] m (0.5 nm to the diagonal of the mesh's bounding"
                << " box), the longest at most "
                << inputLimits::aspectRatioMax << " times the shortest"
                << exit(FatalIOError);
        }
        d_[i] = 2*cbrt(s.x()*s.y()*s.z());
    }
    else if (pd.found("d"))
    {
        d_[i] = readParcelScalar
        (
            pd, i, "d", true, nullptr, inputLimits::sizeMin, sizeMax,
            sizeUnit
        );
    }
    else
    {
        FatalIOErrorInFunction(pd)
            << "Entry d of parcel " << i << " in "
            << this->coeffDict().name().c_str() << "/parcels is missing:"
            << " give the diameter d of a sphere or the semiAxes of an"
            << " ellipsoid" << exit(FatalIOError);
    }
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
    epsilonR_.setSize(n);
    material_.setSize(n);
    semiAxes_.setSize(n);
    orientation_.setSize(n);
    omegaBody_.setSize(n);

    // The defaults are checked where constantProperties is read
    const particleMaterials& materials =
        this->owner().constProps().materials();
    word material0(materials.name(0));
    this->coeffDict().readIfPresent("material", material0);
    materials.find(material0, this->coeffDict(), "material");
    const scalar epsilonR0 = this->owner().constProps().epsilonR0();

    // Positions inside the mesh's bounding box (slightly inflated: the
    // cell search decides at the boundary), sizes up to its diagonal
    const boundBox& meshBb = this->owner().mesh().bounds();
    const scalar sizeMax = mag(meshBb.span());
    const boundBox bb
    (
        meshBb.min() - vector::uniform(1e-6*sizeMax),
        meshBb.max() + vector::uniform(1e-6*sizeMax)
    );
    const string densityUnit("kg/m3");

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
        checkFinite(pd, i, "position", positions_[i]);
        if (!bb.contains(positions_[i]))
        {
            FatalIOErrorInFunction(pd)
                << "Entry position of parcel " << i << " in "
                << this->coeffDict().name().c_str() << "/parcels is out of"
                << " range (" << positions_[i] << "): it must lie in the"
                << " mesh's bounding box " << meshBb
                << exit(FatalIOError);
        }
        U_[i] = pd.lookupOrDefault<vector>("U", Zero);
        checkFinite
        (
            pd, i, "U", U_[i], inputLimits::speedOfLight,
            "the speed of light [m/s]"
        );

        readParcelSize(pd, i, sizeMax);
        orientation_[i] = readOrientation(pd, i);

        // Surface speed |omega| a below the speed of light
        omegaBody_[i] = pd.lookupOrDefault<vector>("omega", Zero);
        const scalar aMax =
            semiAxes_[i] != vector::zero ? cmptMax(semiAxes_[i]) : 0.5*d_[i];
        checkFinite
        (
            pd, i, "omega", omegaBody_[i], inputLimits::speedOfLight/aMax,
            "[rad/s]: its surface speed |omega| a, a = " + Foam::name(aMax)
          + " m the largest semi-axis, below the speed of light"
        );

        word material(material0);
        pd.readIfPresent("material", material);
        material_[i] = materials.find(material, pd, "material");
        const scalar rho0 =
            materials.dict(material_[i]).template get<scalar>("rho0");
        rho_[i] = readParcelScalar
        (
            pd, i, "rho", true, &rho0,
            inputLimits::densityMin, inputLimits::densityMax, densityUnit
        );
        epsilonR_[i] = readParcelScalar
        (
            pd, i, "epsilonR", true, &epsilonR0,
            VSMALL, inputLimits::large, string::null
        );

        q_[i] = readParcelScalar(pd, i, "q", false);
        if (!(mag(q_[i]) <= inputLimits::chargeMax))
        {
            FatalIOErrorInFunction(pd)
                << "Entry q of parcel " << i << " in "
                << this->coeffDict().name().c_str() << "/parcels is out of"
                << " range (" << q_[i] << "): |q| must be at most "
                << inputLimits::chargeMax << " C" << exit(FatalIOError);
        }
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
    epsilonR_(im.epsilonR_),
    material_(im.material_),
    semiAxes_(im.semiAxes_),
    orientation_(im.orientation_),
    omegaBody_(im.omegaBody_),
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
    if (semiAxes_[parcelI] != vector::zero)
    {
        parcel.setSemiAxes(semiAxes_[parcelI]);
    }
    else
    {
        parcel.setSemiAxes(vector::uniform(0.5*d_[parcelI]));
    }
    parcel.rho() = rho_[parcelI];
    parcel.q() = q_[parcelI];
    parcel.epsilonR() = epsilonR_[parcelI];
    parcel.material() = material_[parcelI];
    parcel.orientation() = orientation_[parcelI];
    parcel.angularMomentum() = rigidBodyRotation::angularMomentum
    (
        parcel.orientation(),
        omegaBody_[parcelI],
        parcel.principalMoments()
    );
}


// ************************************************************************* //
