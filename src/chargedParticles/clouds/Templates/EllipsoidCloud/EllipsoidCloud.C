/*---------------------------------------------------------------------------*\
    chargedFoam: charged dielectric particles for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "EllipsoidCloud.H"
#include "cpuTime.H"
#include "CollisionModel.H"
#include "EllipsoidCollision.H"
#include "subCycleTime.H"

// * * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * //

template<class CloudType>
template<class TrackCloudType>
void Foam::EllipsoidCloud<CloudType>::moveCollide
(
    TrackCloudType& cloud,
    typename parcelType::trackingData& td,
    const scalar deltaT
)
{
    // The last half kick does not move parcels through the mesh: a plain
    // loop, not Cloud::move (whose tracking set-up and processor transfer
    // exchange would be for nothing)
    auto inPlace = [&](const typename parcelType::trackingData::trackPart part)
    {
        td.part() = part;
        for (parcelType& p : *this)
        {
            td.keepParticle = true;
            td.switchProcessor = false;
            p.move(cloud, td, deltaT);
        }
    };

    cloud.initialiseForces();

    // The first half kick, the drift and the rotation in one pass
    // (EllipsoidParcel::move); ellipsoidCollision gathers its contact
    // bodies as the parcels finish
    typedef EllipsoidCollision<typename CloudType::collidingCloudType>
        ellipsoidCollisionType;
    gatherer_ =
        this->collision().active()
      ? dynamic_cast<ellipsoidCollisionType*>(&this->collision())
      : nullptr;
    if (gatherer_)
    {
        gatherer_->beginGather();
    }
    td.part() = parcelType::trackingData::tpLinearTrack;
    kickInMove_ = true;
    CloudType::move(cloud, td, deltaT);
    kickInMove_ = false;
    gatherer_ = nullptr;

    this->updateCellOccupancy();

    cloud.calculateForces();

    inPlace(parcelType::trackingData::tpVelocityHalfStep);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

template<class CloudType>
Foam::EllipsoidCloud<CloudType>::EllipsoidCloud
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
    trackingTolerance_
    (
        this->solution().dict().template lookupOrDefault<scalar>
        (
            "trackingTolerance",
            1e-3
        )
    ),
    logInterval_
    (
        this->solution().dict().template lookupOrDefault<label>
        (
            "logInterval",
            1
        )
    ),
    gatherer_(nullptr),
    kickInMove_(false),
    contactTime_(0)
{
    if (logInterval_ < 1)
    {
        FatalIOErrorInFunction(this->solution().dict())
            << "Entry logInterval = " << logInterval_
            << " is out of range: >= 1 (time steps)" << exit(FatalIOError);
    }
    if (!(trackingTolerance_ >= 0 && trackingTolerance_ <= 0.5))
    {
        FatalIOErrorInFunction(this->solution().dict())
            << "Entry trackingTolerance = " << trackingTolerance_
            << " is out of range [0, 0.5] (fraction of a cell; 0: track"
            << " every step)" << exit(FatalIOError);
    }
    if (this->mesh().nSolutionD() != 3 && trackingTolerance_ > 0)
    {
        // The deviation from the mesh centre of 1-D/2-D cases is applied
        // by the tracking
        trackingTolerance_ = 0;
    }
    if
    (
        trackingTolerance_ > 0
     && this->solution().active()
     && this->collision().active()
     && this->collision().type() != "ellipsoidCollision"
    )
    {
        // Other collision models (OpenFOAM's pairCollision) read the
        // tracked positions, not the centres
        Info<< "    Lazy tracking off: collision model "
            << this->collision().type() << " reads the tracked positions"
            << endl;
        trackingTolerance_ = 0;
    }

    if (this->solution().active() && readFields)
    {
        parcelType::readFields(*this);
        this->deleteLostParticles();
    }
}


template<class CloudType>
Foam::EllipsoidCloud<CloudType>::EllipsoidCloud
(
    EllipsoidCloud<CloudType>& c,
    const word& name
)
:
    CloudType(c, name),
    constProps_(c.constProps_),
    trackingTolerance_(c.trackingTolerance_),
    logInterval_(c.logInterval_),
    gatherer_(nullptr),
    kickInMove_(false),
    contactTime_(0)
{}


template<class CloudType>
Foam::EllipsoidCloud<CloudType>::EllipsoidCloud
(
    const fvMesh& mesh,
    const word& name,
    const EllipsoidCloud<CloudType>& c
)
:
    CloudType(mesh, name, c),
    constProps_(c.constProps_),
    trackingTolerance_(c.trackingTolerance_),
    logInterval_(c.logInterval_),
    gatherer_(nullptr),
    kickInMove_(false),
    contactTime_(0)
{}


// * * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * //

template<class CloudType>
void Foam::EllipsoidCloud<CloudType>::checkParcelProperties
(
    parcelType& parcel,
    const scalar lagrangianDt,
    const bool fullyDescribed
)
{
    CloudType::checkParcelProperties(parcel, lagrangianDt, fullyDescribed);

    // Injection models that give a diameter only: equal-volume shape
    if (parcel.semiAxes() == vector::zero)
    {
        parcel.setShapeFromDiameter(constProps_.shape());
    }
}


template<class CloudType>
bool Foam::EllipsoidCloud<CloudType>::logThisStep() const
{
    const Time& time = this->db().time();
    const label step = time.timeIndex() - time.startTimeIndex();
    return
        logInterval_ == 1
     || step % logInterval_ == 0
     || step == 1
     || time.writeTime();
}


template<class CloudType>
void Foam::EllipsoidCloud<CloudType>::calculateForces()
{
    cpuTime timer;
    this->collision().collide();
    contactTime_ += timer.cpuTimeIncrement();
}


template<class CloudType>
void Foam::EllipsoidCloud<CloudType>::storeState()
{
    cloudCopyPtr_.reset
    (
        static_cast<EllipsoidCloud<CloudType>*>
        (
            clone(this->name() + "Copy").ptr()
        )
    );
}


template<class CloudType>
void Foam::EllipsoidCloud<CloudType>::restoreState()
{
    this->cloudReset(cloudCopyPtr_());
    cloudCopyPtr_.clear();
}


template<class CloudType>
void Foam::EllipsoidCloud<CloudType>::evolve()
{
    if (this->solution().canEvolve())
    {
        typename parcelType::trackingData td(*this);

        // Injected parcels start at their given state: the move that
        // InjectionModel::inject gives them is made a (null) velocity kick
        // (their forces are zero), the whole first step is taken by motion()
        td.part() = parcelType::trackingData::tpVelocityHalfStep;

        this->solve(*this, td);
    }
}


template<class CloudType>
template<class TrackCloudType>
void Foam::EllipsoidCloud<CloudType>::motion
(
    TrackCloudType& cloud,
    typename parcelType::trackingData& td
)
{
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
            moveCollide(cloud, td, this->db().time().deltaTValue());
        }

        moveCollideSubCycle.endSubCycle();
    }
    else
    {
        moveCollide(cloud, td, this->db().time().deltaTValue());
    }

    // Ready for the next injection (see evolve)
    td.part() = parcelType::trackingData::tpVelocityHalfStep;

    // Lazy tracking: the written positions are the tracked ones
    if (this->db().time().writeTime())
    {
        for (parcelType& p : *this)
        {
            p.trackDrift();
        }
    }
}


template<class CloudType>
void Foam::EllipsoidCloud<CloudType>::info()
{
    // The kinematic information; CollidingCloud::info() would add the
    // rotational energy of spheres, replaced here by the ellipsoids' one
    CloudType::cloudType::info();

    // Contacts: counted by ellipsoidCollision (it writes the collision
    // records only when they are read); other models keep the records of
    // the current contacts only
    typedef EllipsoidCollision<typename CloudType::collidingCloudType>
        ellipsoidCollisionType;
    const auto* ecPtr =
        dynamic_cast<const ellipsoidCollisionType*>(&this->collision());

    scalar nPair = 0, nWall = 0;
    const scalar nParcels = returnReduce(scalar(this->size()), sumOp<scalar>());
    if (ecPtr)
    {
        nPair = ecPtr->nPairContactSides();
        nWall = ecPtr->nWallContacts();
    }
    else
    {
        for (const parcelType& p : *this)
        {
            nPair += p.collisionRecords().pairRecords().size();
            nWall += p.collisionRecords().wallRecords().size();
        }
        reduce(nPair, sumOp<scalar>());
        reduce(nWall, sumOp<scalar>());
    }

    // Potential energy in gravity, -m g.x
    scalar potential = 0;
    for (const parcelType& p : *this)
    {
        potential -= p.nParticle()*p.mass()*(this->g().value() & p.centre());
    }
    reduce(potential, sumOp<scalar>());

    Info<< "    Rotational kinetic energy (ellipsoids) = "
        << rotationalKineticEnergyOfEllipsoids() << nl
        << "    Potential energy (gravity)      = " << potential << nl
        << "    Contacts: particle-particle     = " << label(nPair/2 + 0.5)
        << ", particle-wall = " << label(nWall) << nl
        << "    Coordination number             = "
        << (nParcels > 0 ? nPair/nParcels : 0) << nl;

    if (ecPtr)
    {
        Info<< "    Contact elastic energy          = "
            << ecPtr->elasticEnergy() << nl
            << "    Contact dissipated energy       = "
            << ecPtr->dissipatedEnergy() << nl;
    }
}


// ************************************************************************* //
