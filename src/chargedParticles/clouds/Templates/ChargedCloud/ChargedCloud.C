/*---------------------------------------------------------------------------*\
    chargedFoam: charged dielectric particles for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "ChargedCloud.H"
#include "ElectrostaticsModel.H"
#include "CollisionModel.H"
#include "subCycleTime.H"

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
template<class TrackCloudType>
void Foam::ChargedCloud<CloudType>::moveCollideCharged
(
    TrackCloudType& cloud,
    typename parcelType::trackingData& td,
    const scalar deltaT
)
{
    if (forcesStale_)
    {
        electrostatics().calculate();
    }

    td.part() = parcelType::trackingData::tpVelocityHalfStep;
    CloudType::move(cloud, td, deltaT);

    td.part() = parcelType::trackingData::tpLinearTrack;
    CloudType::move(cloud, td, deltaT);

    this->updateCellOccupancy();

    this->collision().collide();
    electrostatics().calculate();
    forcesStale_ = false;

    td.part() = parcelType::trackingData::tpVelocityHalfStep;
    CloudType::move(cloud, td, deltaT);
}


template<class CloudType>
template<class TrackCloudType>
void Foam::ChargedCloud<CloudType>::motion
(
    TrackCloudType& cloud,
    typename parcelType::trackingData& td
)
{
    if (!electrostatics().active())
    {
        // Contact only (or nothing): the CollidingCloud leapfrog
        CloudType::motion(cloud, td);
    }
    else
    {
        // Contact and electrostatic forces in one leapfrog, sub-cycled at
        // the collision time step
        const label nSubCycles = this->collision().nSubCycles();

        if (nSubCycles > 1)
        {
            Info<< "    " << nSubCycles << " move-collide subCycles" << endl;

            subCycleTime moveCollideSubCycle
            (
                const_cast<Time&>(this->db().time()),
                nSubCycles
            );

            while (!(++moveCollideSubCycle).end())
            {
                moveCollideCharged(cloud, td, this->db().time().deltaTValue());
            }

            moveCollideSubCycle.endSubCycle();
        }
        else
        {
            moveCollideCharged(cloud, td, this->db().time().deltaTValue());
        }
    }

    // Leave the tracking data ready for the next injection (see evolve)
    td.part() = parcelType::trackingData::tpVelocityHalfStep;
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
