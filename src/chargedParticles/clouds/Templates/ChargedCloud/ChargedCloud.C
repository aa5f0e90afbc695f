/*---------------------------------------------------------------------------*\
    chargedFoam: charged dielectric particles for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "ChargedCloud.H"
#include "ElectrostaticsModel.H"

// * * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * //

template<class CloudType>
void Foam::ChargedCloud<CloudType>::setModels()
{
    electrostaticsModel_.reset
    (
        ElectrostaticsModel<ChargedCloud<CloudType>>::New
        (
            this->subModelProperties(),
            *this
        ).ptr()
    );
}


template<class CloudType>
void Foam::ChargedCloud<CloudType>::checkConstProps() const
{
    const dictionary& dict = constProps_.dict();

    // rho0 is read on demand by KinematicParcel; check it up front
    scalar rho0 = 0;
    if (!dict.readIfPresent("rho0", rho0) || !(rho0 > 0) || !std::isfinite(rho0))
    {
        FatalIOErrorInFunction(dict)
            << "Entry rho0 (particle density [kg/m3]) in "
            << dict.name().c_str() << " is "
            << (dict.found("rho0") ? "out of range" : "missing")
            << ": it must be given, finite and > 0"
            << exit(FatalIOError);
    }
}


template<class CloudType>
void Foam::ChargedCloud<CloudType>::cloudReset(ChargedCloud<CloudType>& c)
{
    CloudType::cloudReset(c);
    electrostaticsModel_.reset(c.electrostaticsModel_.ptr());
    forcesStale_ = true;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

template<class CloudType>
Foam::ChargedCloud<CloudType>::ChargedCloud
(
    const word& cloudName,
    const volScalarField& rho,
    const volVectorField& U,
    const volScalarField& mu,
    const dimensionedVector& g,
    bool readFields
)
:
    CloudType(cloudName, rho, U, mu, g, false),
    constProps_(this->particleProperties()),
    electrostaticsModel_(nullptr),
    forcesStale_(true)
{
    if (this->solution().active())
    {
        checkConstProps();
        setModels();

        if (readFields)
        {
            parcelType::readFields(*this);
            this->deleteLostParticles();
        }

        // Electrostatics off: no stale force from a restart may act
        if (!electrostatics().active())
        {
            electrostatics().calculate();
        }
    }
}


template<class CloudType>
Foam::ChargedCloud<CloudType>::ChargedCloud
(
    ChargedCloud<CloudType>& c,
    const word& name
)
:
    CloudType(c, name),
    constProps_(c.constProps_),
    electrostaticsModel_(c.electrostaticsModel_->clone()),
    forcesStale_(c.forcesStale_)
{}


template<class CloudType>
Foam::ChargedCloud<CloudType>::ChargedCloud
(
    const fvMesh& mesh,
    const word& name,
    const ChargedCloud<CloudType>& c
)
:
    CloudType(mesh, name, c),
    constProps_(c.constProps_),
    electrostaticsModel_(nullptr),
    forcesStale_(true)
{}


// * * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * //

template<class CloudType>
void Foam::ChargedCloud<CloudType>::setParcelThermoProperties
(
    parcelType& parcel,
    const scalar lagrangianDt
)
{
    CloudType::setParcelThermoProperties(parcel, lagrangianDt);
    parcel.q() = constProps_.q0();
}


template<class CloudType>
void Foam::ChargedCloud<CloudType>::checkParcelProperties
(
    parcelType& parcel,
    const scalar lagrangianDt,
    const bool fullyDescribed
)
{
    CloudType::checkParcelProperties(parcel, lagrangianDt, fullyDescribed);
    forcesStale_ = true;
}


template<class CloudType>
void Foam::ChargedCloud<CloudType>::storeState()
{
    cloudCopyPtr_.reset
    (
        static_cast<ChargedCloud<CloudType>*>
        (
            clone(this->name() + "Copy").ptr()
        )
    );
}


template<class CloudType>
void Foam::ChargedCloud<CloudType>::restoreState()
{
    cloudReset(cloudCopyPtr_());
    cloudCopyPtr_.clear();
}


template<class CloudType>
void Foam::ChargedCloud<CloudType>::evolve()
{
    if (this->solution().canEvolve())
    {
        typename parcelType::trackingData td(*this);

        // Injected parcels start at their given state: the move that
        // InjectionModel::inject gives them is made a (null) velocity kick
        // (their forces are zero), and the whole first step is taken by
        // motion()
        td.part() = parcelType::trackingData::tpVelocityHalfStep;

        this->solve(*this, td);
    }
}


template<class CloudType>
void Foam::ChargedCloud<CloudType>::initialiseForces()
{
    CloudType::initialiseForces();

    if (forcesStale_ && electrostatics().active())
    {
        electrostatics().calculate();
    }
    forcesStale_ = false;
}


template<class CloudType>
void Foam::ChargedCloud<CloudType>::calculateForces()
{
    CloudType::calculateForces();

    if (electrostatics().active())
    {
        electrostatics().calculate();
    }
    forcesStale_ = false;
}


template<class CloudType>
void Foam::ChargedCloud<CloudType>::info()
{
    CloudType::info();

    Info<< "    Total charge                    = " << totalCharge() << nl;

    if (electrostatics().active())
    {
        Info<< "    Electrostatic energy            = "
            << electrostatics().energy() << nl;
    }
}


// ************************************************************************* //
