/*---------------------------------------------------------------------------*\
    chargedFoam: charged dielectric particles for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "ChargedCloud.H"
#include "ElectrostaticsModel.H"
#include "TriboChargingModel.H"
#include "ContactModel.H"
#include "SceneCheck.H"
#include "inputLimits.H"
#include "checkedEntry.H"

#include <algorithm>

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
        contactModelType* ec = this->contactModel();
        if (!ec)
        {
            FatalIOErrorInFunction(this->subModelProperties())
                << "Entry triboChargingModel "
                << triboCharging().modelType()
                << " needs collisionModel ellipsoidCollision (a model that"
                << " lists its contacts), not "
                << this->collision().type() << exit(FatalIOError);
        }
        ec->recordContacts();
    }

    // The pairs in contact for the electrostatics (Ruan Eq. 44)
    if (electrostatics().active() && electrostatics().readsContacts())
    {
        contactModelType* ec = this->contactModel();
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
void Foam::ChargedCloud<CloudType>::checkInjectors() const
{
    // Read by OpenFOAM's InjectionModel; NaN or inf reach the parcels'
    // injection times and masses, and the carrier's sources
    forAll(this->injectors(), i)
    {
        const auto& injector = this->injectors()[i];
        const dictionary& d = injector.coeffDict();
        if (!std::isfinite(injector.volumeTotal()))
        {
            FatalIOErrorInFunction(d)
                << "The parcels of injection model " << injector.modelName()
                << " in " << d.name().c_str() << " have a total volume of "
                << injector.volumeTotal() << " m3: check its size entries"
                << " (sizeDistribution, d, semiAxes)" << exit(FatalIOError);
        }
        getCheckedOrDefault<scalar>
        (
            d, "SOI", 0,
            [](const scalar t) { return std::isfinite(t); },
            ": it must be finite", " (start of injection [s])"
        );
    }
}


template<class CloudType>
void Foam::ChargedCloud<CloudType>::checkPatchInteraction() const
{
    // OpenFOAM's rebound scales the normal velocity by -e and the
    // tangential by (1 - mu), whatever their values
    if (this->patchInteraction().type() != "standardWallInteraction")
    {
        return;
    }
    const dictionary& d = this->patchInteraction().coeffDict();
    auto unitInterval = [](const scalar v) { return v >= 0 && v <= 1; };
    getCheckedOrDefault<scalar>
    (
        d, "e", 0, unitInterval, " [0, 1]", " (restitution coefficient)"
    );
    getCheckedOrDefault<scalar>
    (
        d, "mu", 0, unitInterval, " [0, 1]", " (friction)"
    );
}


template<class CloudType>
void Foam::ChargedCloud<CloudType>::checkCoincident() const
{
    // Positions sorted lexicographically: equal ones are neighbours
    List<const parcelType*> parcels(this->size());
    pointField x(this->size());
    label n = 0;
    for (const parcelType& p : *this)
    {
        parcels[n] = &p;
        x[n++] = p.position();
    }
    labelList order(identity(n));
    std::sort
    (
        order.begin(),
        order.end(),
        [&x](const label a, const label b)
        {
            return
                x[a].x() < x[b].x()
             || (x[a].x() == x[b].x() && x[a].y() < x[b].y())
             || (x[a].x() == x[b].x() && x[a].y() == x[b].y()
              && x[a].z() < x[b].z());
        }
    );
    for (label k = 1; k < n; ++k)
    {
        const label a = order[k - 1];
        const label b = order[k];
        if (x[a] == x[b])
        {
            const dictionary& inj =
                this->subModelProperties().subDict("injectionModels");
            FatalIOErrorInFunction(inj)
                << "Parcels (origProc " << parcels[a]->origProc()
                << ", origId " << parcels[a]->origId() << ") and (origProc "
                << parcels[b]->origProc() << ", origId "
                << parcels[b]->origId() << ") are both at " << x[a]
                << ": the Coulomb force between them is infinite." << nl
                << "    The parcels' positions must differ: check the"
                << " injection models " << inj.toc() << " in "
                << inj.name().c_str() << " (two models alike, or a position"
                << " given twice?), or the parcels of the start time"
                << exit(FatalIOError);
        }
    }
}


template<class CloudType>
void Foam::ChargedCloud<CloudType>::readInjectorMaterials()
{
    const particleMaterials& materials = constProps_.materials();
    forAll(this->injectors(), i)
    {
        const auto& injector = this->injectors()[i];
        const dictionary& d = injector.coeffDict();
        if (!d.found("material") || injector.type() == "explicitParcels")
        {
            continue;
        }
        const label m = materials.find(d.get<word>("material"), d, "material");
        const label id = d.lookupOrDefault<label>("injectorID", -1);
        if (id < 0)
        {
            FatalIOErrorInFunction(d)
                << "Entry material of injection model "
                << injector.modelName() << " in " << d.name().c_str()
                << " needs an entry injectorID, a number >= 0 of its own"
                << " (OpenFOAM gives it to the model's parcels as their"
                << " typeId, which names their material)" << exit(FatalIOError);
        }
        const auto iter = injectorMaterial_.cfind(id);
        if (iter.found() && iter.val() != m)
        {
            FatalIOErrorInFunction(d)
                << "Entry injectorID " << id << " of injection model "
                << injector.modelName() << " in " << d.name().c_str()
                << " is also the id of a model of material "
                << materials.name(iter.val()) << ": give each material's"
                << " models their own injectorID" << exit(FatalIOError);
        }
        injectorMaterial_.set(id, m);
        injectorMassBasis_.set
        (
            id,
            d.lookupOrDefault<word>("parcelBasisType", "mass") == "mass"
        );
        Info<< "    injection model " << injector.modelName()
            << ": material " << materials.name(m) << " (injectorID " << id
            << ")" << endl;
    }
}


template<class CloudType>
void Foam::ChargedCloud<CloudType>::assignInjectedMaterials()
{
    if (injectorMaterial_.empty())
    {
        return;
    }
    const particleMaterials& materials = constProps_.materials();
    for (parcelType& p : *this)
    {
        if (p.material() != -1)
        {
            continue;
        }
        const auto iter = injectorMaterial_.cfind(p.typeId());
        const label m = iter.found() ? iter.val() : 0;
        p.material() = m;
        const scalar rho = materials.dict(m).template get<scalar>("rho0");
        const auto massBasis = injectorMassBasis_.cfind(p.typeId());
        if (massBasis.found() && massBasis.val())
        {
            // The model's mass per parcel, of particles of this density
            p.nParticle() *= p.rho()/rho;
        }
        p.rho() = rho;
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
    electrostaticForces_(false),
    // One entry per patch that is not a processor patch: the same list on
    // every processor (processor patches differ in number between them)
    escapedCharge0_(this->mesh().boundaryMesh().nNonProcessor(), Zero),
    escapedChargeLocal_(this->mesh().boundaryMesh().nNonProcessor(), Zero),
    injectorMaterial_(),
    injectorMassBasis_()
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
        checkInjectors();
        readInjectorMaterials();
        checkPatchInteraction();
        setModels();

        if (readFields)
        {
            this->checkWrittenFields();
            parcelType::readFields(*this);
            this->deleteLostParticles();
        }

        // Electrostatics off: no stale force from a restart may act
        electrostaticForces_ = electrostatics().active();
        if (!electrostaticForces_)
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
    forcesStale_(c.forcesStale_),
    electrostaticForces_(c.electrostaticForces_)
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
    forcesStale_(true),
    electrostaticForces_(false)
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

    // The first material, or pending (-1) when injection models have
    // their own: the model is known from the parcel's typeId only after
    // the injection (assignInjectedMaterials); explicitParcels sets its
    // own. The first material's density until then
    parcel.material() = injectorMaterial_.empty() ? 0 : -1;
    parcel.rho() =
        constProps_.materials().dict(0).template get<scalar>("rho0");
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
    if (parcel.material() != -1)
    {
        constProps_.materials().check
        (
            parcel.material(),
            this->subModelProperties().subDict("injectionModels")
        );
    }

    // Whatever the injection model (explicitParcels names the parcel and
    // its entry before this): a value out of range is reported with the
    // injection models' dictionary, where it came from
    const vector& s = parcel.semiAxes();
    const scalar sizeMax = mag(this->mesh().bounds().span());
    string what;
    if (!inputLimits::finite(parcel.U()))
    {
        what = "U = " + Foam::name(parcel.U()) + ": all components must"
            " be finite (velocity entries such as U0)";
    }
    else if (!inputLimits::magBelow(parcel.U(), inputLimits::speedOfLight))
    {
        what = "U = " + Foam::name(parcel.U()) + ": its magnitude must be"
            " below the speed of light [m/s] (velocity entries such as U0)";
    }
    else if
    (
        !inputLimits::finite(s)
     || !(cmptMin(s) >= 0.5*inputLimits::sizeMin)
     || !(cmptMax(s) <= sizeMax)
     || !(cmptMax(s) <= inputLimits::aspectRatioMax*cmptMin(s))
    )
    {
        what = "d = " + Foam::name(parcel.d()) + ", semi-axes "
            + Foam::name(s) + ": the semi-axes must be finite and > 0, in ["
            + Foam::name(0.5*inputLimits::sizeMin) + ", "
            + Foam::name(sizeMax) + "] m (0.5 nm to the diagonal of the"
            " mesh's bounding box), the longest at most "
            + Foam::name(inputLimits::aspectRatioMax) + " times the shortest"
            " (size entries such as sizeDistribution)";
    }
    else if
    (
        !(
            parcel.rho() >= inputLimits::densityMin
         && parcel.rho() <= inputLimits::densityMax
        )
    )
    {
        what = "rho = " + Foam::name(parcel.rho()) + ": it must be finite"
            " and in [" + Foam::name(inputLimits::densityMin) + ", "
            + Foam::name(inputLimits::densityMax) + "] kg/m3";
    }
    else if (!(mag(parcel.q()) <= inputLimits::chargeMax))
    {
        what = "q = " + Foam::name(parcel.q()) + ": |q| must be at most "
            + Foam::name(inputLimits::chargeMax) + " C (entry q0 of"
            " constantProperties, or the injection model's)";
    }
    if (what.size())
    {
        const dictionary& inj =
            this->subModelProperties().subDict("injectionModels");
        FatalIOErrorInFunction(inj)
            << "A parcel injected at t = " << this->db().time().value()
            << " by one of the injection models " << inj.toc() << " in "
            << inj.name().c_str() << " is out of range: " << what.c_str()
            << exit(FatalIOError);
    }
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
        // The first evaluation with newly injected (or read) parcels: a
        // failure of the pairwise sums on two parcels at one position is
        // reported with the injection models they came from (the mesh
        // models take coincident charges, so no check beforehand)
        const bool throwing = FatalError.throwExceptions();
        try
        {
            electrostatics().update();
        }
        catch (const Foam::error& err)
        {
            FatalError.throwExceptions(throwing);
            checkCoincident();

            Foam::error original(err);
            original.throwExceptions(throwing);
            original.exit();
        }
        FatalError.throwExceptions(throwing);
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
        const contactModelType& ec = *this->contactModel();
        triboCharging().transfer(ec.contacts(), ec.referralNeighbours());
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

        // Boutsikakis 2023 statistics (all processors; primes: fluctuations
        // about the cloud means, a = fE/m): <|fE|/m> (Eq. 28), the power
        // <a'.u'> of the agitation's balance (Eq. 29) and the covariance
        // <fE' fE'> over its mean diagonal F^2 (Eq. 10: isotropic = I)
        scalar n = this->size(), sumA = 0, sumAU = 0;
        vector sumAvec(Zero), sumU(Zero), sumF(Zero);
        symmTensor sumFF(Zero);
        for (const parcelType& p : *this)
        {
            const vector a = p.fE()/p.mass();
            sumA += mag(a);
            sumAU += a & p.U();
            sumAvec += a;
            sumU += p.U();
            sumF += p.fE();
            sumFF += sqr(p.fE());
        }
        reduce(n, sumOp<scalar>());
        reduce(sumA, sumOp<scalar>());
        reduce(sumAU, sumOp<scalar>());
        reduce(sumAvec, sumOp<vector>());
        reduce(sumU, sumOp<vector>());
        reduce(sumF, sumOp<vector>());
        reduce(sumFF, sumOp<symmTensor>());
        if (n > 0)
        {
            const symmTensor covF = sumFF/n - sqr(sumF/n);
            const scalar F2 = tr(covF)/3;
            Info<< "    Particle agitation q_p^2        = " << agitation() << nl
                << "    Mean electrostatic acceleration = " << sumA/n << nl
                << "    Electrostatic power <a'.u'>     = "
                << sumAU/n - ((sumAvec/n) & (sumU/n)) << nl
                << "    Force covariance <F'F'>/F^2     = "
                << (F2 > 0 ? covF/F2 : symmTensor::zero)
                << " (F^2 = " << F2 << ")" << nl;
        }
    }
}


// ************************************************************************* //
