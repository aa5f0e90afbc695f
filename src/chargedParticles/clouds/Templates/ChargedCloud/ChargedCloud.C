/*---------------------------------------------------------------------------*\
    chargedFoam: charged dielectric particles for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "ChargedCloud.H"
#include "ElectrostaticsModel.H"
#include "TriboChargingModel.H"
#include "EllipsoidCollision.H"
#include "SceneCheck.H"

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

    triboChargingModel_.reset
    (
        TriboChargingModel<ChargedCloud<CloudType>>::New
        (
            this->subModelProperties(),
            *this
        ).ptr()
    );

    sceneCheck_.reset
    (
        new SceneCheck<ChargedCloud<CloudType>>
        (
            this->particleProperties(),
            *this
        )
    );

    // Contact charging acts on the contacts the collision model lists
    if (triboCharging().active())
    {
        collisionModelType* ec =
            dynamic_cast<collisionModelType*>(&this->collision());
        if (!ec)
        {
            FatalIOErrorInFunction(this->subModelProperties())
                << "Entry triboChargingModel "
                << triboCharging().modelType()
                << " needs collisionModel "
                << collisionModelType::typeName << ", not "
                << this->collision().type() << exit(FatalIOError);
        }
        ec->recordContacts();
    }

    // The pairs in contact for the electrostatics (Ruan Eq. 44)
    if (electrostatics().active() && electrostatics().readsContacts())
    {
        collisionModelType* ec =
            dynamic_cast<collisionModelType*>(&this->collision());
        if (ec)
        {
            ec->keepCollisionRecords();
        }
    }
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
    triboChargingModel_.reset(c.triboChargingModel_.ptr());
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
    triboChargingModel_(nullptr),
    forcesStale_(true),
    // One entry per patch that is not a processor patch: the same list on
    // every processor (processor patches differ in number between them)
    escapedCharge0_(this->mesh().boundaryMesh().nNonProcessor(), Zero),
    escapedChargeLocal_(this->mesh().boundaryMesh().nNonProcessor(), Zero)
{
    // Charge that left in an earlier run (restart)
    scalarField q0;
    this->outputProperties().readIfPresent("escapedCharge", q0);
    forAll(escapedCharge0_, patchi)
    {
        escapedCharge0_[patchi] = patchi < q0.size() ? q0[patchi] : 0;
    }

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
            electrostatics().update();
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
    triboChargingModel_(c.triboChargingModel_->clone()),
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
    triboChargingModel_(nullptr),
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
    parcel.epsilonR() = constProps_.epsilonR0();
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

        if (sceneCheck_.valid())
        {
            sceneCheck_->checkIfDue();
        }
    }
}


template<class CloudType>
Foam::scalarField Foam::ChargedCloud<CloudType>::escapedCharge() const
{
    scalarField q(escapedChargeLocal_);
    Pstream::listCombineGather(q, plusEqOp<scalar>());
    Pstream::listCombineScatter(q);
    return escapedCharge0_ + q;
}


template<class CloudType>
void Foam::ChargedCloud<CloudType>::postEvolve()
{
    // Before the base writes the cloud's output properties (the wall
    // and escaped charges are kept there for a restart)
    this->outputProperties().set("escapedCharge", escapedCharge());
    if (triboCharging().active())
    {
        triboCharging().writeBalance();
    }

    CloudType::postEvolve();
}


template<class CloudType>
void Foam::ChargedCloud<CloudType>::initialiseForces()
{
    CloudType::initialiseForces();

    if (forcesStale_ && electrostatics().active())
    {
        electrostatics().update();
    }
    forcesStale_ = false;
}


template<class CloudType>
void Foam::ChargedCloud<CloudType>::calculateForces()
{
    CloudType::calculateForces();

    // Charge moved by the contacts just found, before the electrostatic
    // forces of the new charges
    if (triboCharging().active())
    {
        const collisionModelType& ec =
            static_cast<const collisionModelType&>(this->collision());
        triboCharging().transfer(ec.contacts());
    }

    if (electrostatics().active())
    {
        electrostatics().update();
    }
    forcesStale_ = false;
}


template<class CloudType>
Foam::DynamicList<Foam::string>
Foam::ChargedCloud<CloudType>::checkScene() const
{
    return sceneCheck_->check();
}


template<class CloudType>
Foam::scalar Foam::ChargedCloud<CloudType>::agitation() const
{
    scalar n = this->size(), sumUU = 0;
    vector sumU(Zero);
    for (const parcelType& p : *this)
    {
        sumU += p.U();
        sumUU += magSqr(p.U());
    }
    reduce(n, sumOp<scalar>());
    reduce(sumU, sumOp<vector>());
    reduce(sumUU, sumOp<scalar>());
    return n > 0 ? 0.5*max(sumUU/n - magSqr(sumU/n), scalar(0)) : 0;
}


template<class CloudType>
void Foam::ChargedCloud<CloudType>::info()
{
    if (!this->logThisStep())
    {
        return;
    }

    CloudType::info();

    Info<< "    Total charge                    = " << totalCharge() << nl;
    {
        const scalarField qOut(escapedCharge());
        const polyBoundaryMesh& patches = this->mesh().boundaryMesh();
        forAll(qOut, patchi)
        {
            if (qOut[patchi] != 0)
            {
                Info<< "    Charge escaped through " << patches[patchi].name()
                    << " = " << qOut[patchi] << nl;
            }
        }
    }

    if (triboCharging().active())
    {
        const scalarField qWalls(triboCharging().wallCharge());
        const polyBoundaryMesh& patches = this->mesh().boundaryMesh();
        forAll(qWalls, patchi)
        {
            if (qWalls[patchi] != 0)
            {
                Info<< "    Charge into wall " << patches[patchi].name()
                    << " = " << qWalls[patchi] << nl;
            }
        }
    }

    if (electrostatics().active())
    {
        if (electrostatics().hasEnergy())
        {
            Info<< "    Electrostatic energy            = "
                << electrostatics().totalEnergy() << nl;
        }
        Info<< "    CPU time [s] since start        = contact "
            << this->contactTime() << ", far field "
            << electrostatics().farFieldTime() << ", near field "
            << electrostatics().nearFieldTime() << nl;
        electrostatics().nearField().info();

        // <|fE|/m> (Boutsikakis 2023 Eq. 28), all processors
        scalar n = this->size(), sumA = 0;
        for (const parcelType& p : *this)
        {
            sumA += mag(p.fE())/p.mass();
        }
        reduce(n, sumOp<scalar>());
        reduce(sumA, sumOp<scalar>());
        if (n > 0)
        {
            Info<< "    Particle agitation q_p^2        = " << agitation() << nl
                << "    Mean electrostatic acceleration = " << sumA/n << nl;
        }
    }
}


// ************************************************************************* //
