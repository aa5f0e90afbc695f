/*---------------------------------------------------------------------------*\
    chargedFoam: charged dielectric particles for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "EllipsoidCloud.H"
#include "cpuTime.H"
#include "CollisionModel.H"
#include "ContactModel.H"
#include "inputLimits.H"
#include "checkedEntry.H"
#include "subCycleTime.H"
#include "Enum.H"
#include "fvMatrices.H"
#include "fvmSup.H"
#include "IOdictionary.H"
#include "IFstream.H"
#include "OSspecific.H"
#include "cutoffPairs.H"
#include "ellipsoidContact.H"
#include "GravityForce.H"
#include "prefetch.H"

#include <algorithm>

// * * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * //

template<class CloudType>
template<class TrackCloudType>
void Foam::EllipsoidCloud<CloudType>::serialMove
(
    TrackCloudType& cloud,
    typename parcelType::trackingData& td,
    const scalar deltaT
)
{
    // Cloud::move's serial part with its pass that zeroes the step
    // fractions folded into the move pass (a pass over a large cloud is a
    // walk through memory: 4 % of the step at 10^5 parcels). Cloud::move
    // also drops its stored global positions, which only a mesh change
    // stores and reads at once (autoMap). The moved parcels are listed for
    // the last kick's loop, in place of the last step's list, whose entry
    // four ahead is, unless the cloud changed since, the parcel four
    // ahead: it is asked for (prefetch; a stale entry costs a useless
    // fetch, never a fault), and so is the next parcel of the linked list
    td.switchProcessor = false;
    const label nLast = moved_.size();
    label nMoved = 0;
    for (parcelType& p : *this)
    {
        prefetch(static_cast<const parcelType*>(p.next_));
        if (nMoved + 4 < nLast)
        {
            prefetch(moved_[nMoved + 4]);
        }
        p.stepFraction() = 0;
        if (p.move(cloud, td, deltaT))
        {
            if (nMoved < nLast)
            {
                moved_[nMoved] = &p;
            }
            else
            {
                moved_.append(&p);
            }
            ++nMoved;
        }
        else
        {
            this->deleteParticle(p);
        }
    }
    moved_.setSize(nMoved);
}


template<class CloudType>
template<class TrackCloudType>
void Foam::EllipsoidCloud<CloudType>::lastKicks
(
    TrackCloudType& cloud,
    typename parcelType::trackingData& td,
    const scalar deltaT
)
{
    // The last half kick does not move parcels through the mesh: a plain
    // loop over the parcels' kicks, not Cloud::move (whose tracking set-up
    // and processor transfer exchange would be for nothing) nor the
    // parcels' moves (their layers' tests of the tracking part)
    td.part() = parcelType::trackingData::tpVelocityHalfStep;
    td.keepParticle = true;
    td.switchProcessor = false;
    contactModelType* kicked =
        this->collision().active() ? this->contactModel() : nullptr;
    auto kick = [&cloud, kicked, deltaT](parcelType& p)
    {
        p.lastKick(cloud, deltaT);
        if (kicked)
        {
            kicked->parcelKicked(p);
        }
    };
    if (kicked)
    {
        kicked->beginKicks();
    }
    if (moved_.size() == this->size())
    {
        // In cloud order (moved_ is filled by the serial move pass only),
        // the parcel four ahead asked for
        const label n = moved_.size();
        for (label k = 0; k < n; ++k)
        {
            if (k + 4 < n)
            {
                prefetch(moved_[k + 4]);
            }
            kick(*moved_[k]);
        }
    }
    else
    {
        for (parcelType& p : *this)
        {
            kick(p);
        }
    }
    if (kicked)
    {
        kicked->endKicks();
    }
}


template<class CloudType>
template<class TrackCloudType>
void Foam::EllipsoidCloud<CloudType>::moveCollide
(
    TrackCloudType& cloud,
    typename parcelType::trackingData& td,
    const scalar deltaT
)
{
    cloud.initialiseForces();

    // The first half kick, the drift and the rotation in one pass
    // (EllipsoidParcel::move); a contact model gathers its contact
    // bodies as the parcels finish
    gatherer_ = this->collision().active() ? this->contactModel() : nullptr;
    if (gatherer_)
    {
        gatherer_->beginGather();
    }
    td.part() = parcelType::trackingData::tpLinearTrack;
    kickInMove_ = true;
    if (Pstream::parRun())
    {
        CloudType::move(cloud, td, deltaT);
    }
    else
    {
        serialMove(cloud, td, deltaT);
    }
    kickInMove_ = false;
    gatherer_ = nullptr;

    this->updateCellOccupancy();

    // Lazy tracking: the positions of a write step's forces are the
    // tracked ones that are written, whose round-off differs from the
    // lazy centres': a restart evaluates its first forces (and charging
    // fields) at the written positions, and continues only so exactly
    if (trackBeforeForces_)
    {
        this->trackDrifts();
    }

    cloud.calculateForces();

    lastKicks(cloud, td, deltaT);
}


template<class CloudType>
const typename Foam::EllipsoidCloud<CloudType>::parcelType*
Foam::EllipsoidCloud<CloudType>::firstInjected() const
{
    // (first() and last() of an empty list are errors)
    if (this->size() == 0)
    {
        return nullptr;
    }
    if (checkAllInjected_)
    {
        return this->first();
    }
    const parcelType* first = nullptr;
    for
    (
        const parcelType* p = this->last();
        p && p->age() == 0;
        p = p == this->first() ? nullptr
          : static_cast<const parcelType*>(p->prev_)
    )
    {
        first = p;
    }
    return first;
}


template<class CloudType>
void Foam::EllipsoidCloud<CloudType>::sortParcels()
{
    DynamicList<parcelType*> order(this->size());
    for (parcelType& p : *this)
    {
        order.append(&p);
    }
    auto byCell = [](const parcelType* a, const parcelType* b)
    {
        return a->cell() < b->cell();
    };
    if (std::is_sorted(order.begin(), order.end(), byCell))
    {
        return;
    }
    std::stable_sort(order.begin(), order.end(), byCell);

    // All copies before the originals are freed: allocated together
    List<parcelType*> copies(order.size());
    forAll(order, i)
    {
        copies[i] = new parcelType(*order[i]);
    }
    for (parcelType* p : order)
    {
        this->deleteParticle(*p);
    }
    for (parcelType* p : copies)
    {
        this->addParticle(p);
    }
    this->updateCellOccupancy();
}


template<class CloudType>
Foam::scalar Foam::EllipsoidCloud<CloudType>::bodyOverlap
(
    const parcelType& pA,
    const point& xA,
    const parcelType& pB,
    const point& xB,
    const scalar r2,
    const scalar b
)
{
    // Coincident centres (r2 = 0) have no contact normal: the deepest
    // overlap
    if (!(r2 > 0))
    {
        return 2*b;
    }
    const ellipsoidContact::result c =
        pA.isSphere() && pB.isSphere()
      ? ellipsoidContact::sphereSphere
        (
            xA, pA.semiAxes().x(), xB, pB.semiAxes().x()
        )
      : ellipsoidContact::contact
        (
            ellipsoid(pA.semiAxes(), xA, pA.orientation()),
            ellipsoid(pB.semiAxes(), xB, pB.orientation())
        );
    return c.contact ? c.overlap : 0;
}


template<class CloudType>
void Foam::EllipsoidCloud<CloudType>::checkInjectionOverlaps() const
{
    // The parcels injected this step have not moved yet (age 0); called
    // only in steps that injected some (motion)
    DynamicList<point> xAll(this->size());
    DynamicList<const parcelType*> pAll(this->size());
    DynamicList<point> xNew;
    DynamicList<label> newOfAll(this->size());
    scalar rMax = 0;
    for (const parcelType& p : *this)
    {
        if (p.age() == 0)
        {
            newOfAll.append(xNew.size());
            xNew.append(p.centre());
        }
        else
        {
            newOfAll.append(-1);
        }
        xAll.append(p.centre());
        pAll.append(&p);
        rMax = max(rMax, cmptMax(p.semiAxes()));
    }

    // Each new parcel against every parcel within two bounding radii:
    // bounding spheres, then the bodies' overlap
    label nOverlaps = 0;
    scalar worst = -1;
    const parcelType* worstA = nullptr;
    const parcelType* worstB = nullptr;
    scalar worstOverlap = 0, worstSemiAxis = 0;
    List<label> allOfNew(xNew.size());
    forAll(newOfAll, i)
    {
        if (newOfAll[i] >= 0)
        {
            allOfNew[newOfAll[i]] = i;
        }
    }
    forPairsWithinCutoff
    (
        xNew, xAll, 2*rMax*(1 + SMALL), -1,
        [&](const label t, const label s, const vector& r, const scalar r2)
        {
            // A pair of new parcels once, a parcel not with itself
            if (newOfAll[s] >= 0 && newOfAll[s] <= t)
            {
                return;
            }
            const parcelType& pA = *pAll[allOfNew[t]];
            const parcelType& pB = *pAll[s];
            if (r2 >= sqr(cmptMax(pA.semiAxes()) + cmptMax(pB.semiAxes())))
            {
                return;
            }
            const scalar b =
                min(cmptMin(pA.semiAxes()), cmptMin(pB.semiAxes()));
            const scalar overlap = bodyOverlap(pA, xNew[t], pB, xAll[s], r2, b);

            // Touching to round-off (1e-6 b) is not an overlap
            if (overlap > max(maxInjectionOverlap_, 1e-6)*b)
            {
                ++nOverlaps;
                if (overlap/b > worst)
                {
                    worst = overlap/b;
                    worstA = &pA;
                    worstB = &pB;
                    worstOverlap = overlap;
                    worstSemiAxis = b;
                }
            }
        }
    );

    if (nOverlaps)
    {
        const dictionary& solDict = this->solution().dict();
        FatalIOErrorInFunction(solDict)
            << nOverlaps << " parcel pair(s) overlap at their injection at t = "
            << this->db().time().value() << " s, the deepest: parcel (origProc "
            << worstA->origProc() << ", origId " << worstA->origId() << ") at "
            << worstA->centre() << " and parcel (origProc "
            << worstB->origProc() << ", origId " << worstB->origId() << ") at "
            << worstB->centre() << " overlap by " << worstOverlap << " m = "
            << worst << " of the smaller semi-axis " << worstSemiAxis
            << " m, more than maxInjectionOverlap = " << maxInjectionOverlap_
            << " in " << solDict.name().c_str() << " allows (range [0, 0.5];"
            << " overlaps up to it are pushed apart by the contact, which"
            << " releases their elastic energy). Check the injection models'"
            << " positions and sizes" << exit(FatalIOError);
    }
}


template<class CloudType>
Foam::IOobject Foam::EllipsoidCloud<CloudType>::fieldsRecordIO
(
    const word& timeName
) const
{
    // Beside the cloud's uniform properties: written also without parcels,
    // where the parcels' directory is not
    return IOobject
    (
        "cloudFieldsRecord",
        timeName,
        "uniform"/cloud::prefix/this->name(),
        this->db(),
        IOobject::NO_READ,
        IOobject::NO_WRITE,
        false
    );
}


template<class CloudType>
void Foam::EllipsoidCloud<CloudType>::writeFieldsRecord
(
    const bool complete
) const
{
    IOdictionary record(fieldsRecordIO(this->time().timeName()));
    record.add("complete", Switch(complete));
    record.add("nProcs", Pstream::nProcs());
    if (complete)
    {
        const fileName dir =
            this->time().timePath()/cloud::prefix/this->name();
        DynamicList<word> files;
        for (const fileName& f : readDir(dir, fileName::FILE))
        {
            files.append(f);
        }
        Foam::sort(files);
        record.add("files", wordList(files));
        record.add("nParcels", label(this->size()));
    }
    record.regIOobject::writeObject
    (
        IOstream::ASCII,
        IOstream::currentVersion,
        IOstream::UNCOMPRESSED,
        true
    );
}


template<class CloudType>
void Foam::EllipsoidCloud<CloudType>::checkWrittenFields() const
{
    const Time& time = this->time();
    const word timeName = time.timeName();
    const fileName cloudDir = time.timePath()/cloud::prefix/this->name();

    // The record of a time: absent, copied by decomposePar/reconstructPar
    // (another number of processors: not about these files), incomplete,
    // or complete with the files missing from it
    enum class state { none, foreign, cut, missing, complete };
    auto read = [&](const word& t, wordList& missing)
    {
        const fileName file = fieldsRecordIO(t).objectPath();
        if (!isFile(file))
        {
            return state::none;
        }
        // A record cut while it was written reads as cut
        dictionary record;
        const bool throwing = FatalIOError.throwExceptions(true);
        try
        {
            IFstream is(file);
            record = dictionary(is);
        }
        catch (const Foam::error&)
        {
            record.clear();
        }
        FatalIOError.throwExceptions(throwing);

        const label nProcs = record.lookupOrDefault<label>("nProcs", -1);
        if (nProcs < 0 || !record.found("complete"))
        {
            return state::cut;
        }
        if (nProcs != Pstream::nProcs())
        {
            return state::foreign;
        }
        if (!record.get<Switch>("complete") || !record.found("files"))
        {
            return state::cut;
        }
        DynamicList<word> absent;
        for (const word& f : record.get<wordList>("files"))
        {
            const fileName path = time.path()/t/cloud::prefix/this->name()/f;
            if (!isFile(path) || fileSize(path) == 0)
            {
                absent.append(f);
            }
        }
        missing = absent;
        return missing.empty() ? state::complete : state::missing;
    };

    wordList missing;
    const state s = read(timeName, missing);
    if
    (
        s == state::complete
     || s == state::foreign
     || (s == state::none && isDir(cloudDir))
    )
    {
        return;
    }

    // The latest earlier time whose record is complete
    word earlier;
    const instantList times = Time::findTimes(time.path(), time.constant());
    forAllReverse(times, i)
    {
        wordList m;
        if
        (
            times[i].value() < time.value()
         && read(times[i].name(), m) == state::complete
        )
        {
            earlier = times[i].name();
            break;
        }
    }

    // No record and no parcels' directory: a time without parcels, unless
    // an earlier one has a record (every write leaves one, also without
    // parcels): then the run stopped before it wrote them
    if (s == state::none && earlier.empty())
    {
        return;
    }

    FatalErrorInFunction
        << "The parcels of cloud " << this->name() << " at time " << timeName
        << " were not completely written (" << cloudDir << "): ";
    if (s == state::missing)
    {
        FatalError<< "missing or empty " << missing;
    }
    else
    {
        FatalError
            << "the run stopped while writing them (killed?)";
    }
    FatalError<< ". Restart from ";
    if (earlier.empty())
    {
        FatalError<< "an earlier time";
    }
    else
    {
        FatalError
            << "time " << earlier << ", the latest complete one"
            << " (system/controlDict: startFrom startTime; startTime "
            << earlier << ";)";
    }
    FatalError<< ", or delete time " << timeName << exit(FatalError);
}


template<class CloudType>
void Foam::EllipsoidCloud<CloudType>::readSolutionControls()
{
    const dictionary& solDict = this->solution().dict();
    maxInjectionOverlap_ = getCheckedOrDefault<scalar>
    (
        solDict, "maxInjectionOverlap", 0,
        [](const scalar f) { return f >= 0 && f <= 0.5; },
        ": it must be in [0, 0.5] (the largest overlap of a parcel injected"
        " into another, as a fraction of the pair's smallest semi-axis;"
        " default 0)"
    );
    sortInterval_ = getCheckedOrDefault<label>
    (
        solDict, "sortInterval", 1000,
        [](const label n) { return n >= 0; },
        ": it must be >= 0 (time steps between sorts of the parcels by"
        " cell; 0: never; default 1000)"
    );
    sphereOrientation_ =
        solDict.template getOrDefault<bool>("sphereOrientation", false);
    if (sphereOrientation_)
    {
        Info<< "    Sphere orientations: integrated (sphereOrientation yes)"
            << endl;
    }
    sortMinParcels_ = getCheckedOrDefault<label>
    (
        solDict, "sortMinParcels", 5000,
        [](const label n) { return n >= 0; },
        ": it must be >= 0 (the fewest parcels of a processor that are"
        " sorted by cell; default 5000)"
    );
    enum class momentumCoupling { sourceTerms, conservativeImplicit };
    static const Enum<momentumCoupling> couplings
    ({
        {momentumCoupling::sourceTerms, "sourceTerms"},
        {momentumCoupling::conservativeImplicit, "conservativeImplicit"},
    });
    const word coupling
    (
        solDict.template lookupOrDefault<word>
        (
            "momentumCoupling",
            couplings[momentumCoupling::sourceTerms]
        )
    );
    if (!couplings.found(coupling))
    {
        FatalIOErrorInFunction(solDict)
            << "Entry momentumCoupling = " << coupling << " is not one"
            << " of: conservativeImplicit (drag implicit and momentum"
            << " conserved on both sides), sourceTerms (OpenFOAM's"
            << " sourceTerms/schemes/U)" << exit(FatalIOError);
    }
    conservativeCoupling_ =
        couplings[coupling] == momentumCoupling::conservativeImplicit
     && this->solution().coupled();
    if (conservativeCoupling_)
    {
        if (this->solution().steadyState())
        {
            FatalIOErrorInFunction(solDict)
                << "Entry momentumCoupling = conservativeImplicit needs"
                << " a transient cloud (transient yes)"
                << exit(FatalIOError);
        }
        const scalar relax = this->solution().relaxCoeff("U");
        if (relax != 1)
        {
            FatalIOErrorInFunction(solDict)
                << "Entry sourceTerms/schemes/U has the relaxation "
                << relax << "; momentumCoupling conservativeImplicit"
                << " needs 1 (a relaxed source does not conserve"
                << " momentum)" << exit(FatalIOError);
        }
        Info<< "    Momentum coupling: conservativeImplicit" << endl;
    }

    // The parcels' moves are split into segments of at most maxCo of a
    // cell (EllipsoidParcel::move): maxCo <= 0 never ends a move
    const scalar maxCo = this->solution().maxCo();
    if (!(maxCo >= inputLimits::maxCoMin && maxCo <= 1))
    {
        FatalIOErrorInFunction(solDict)
            << "Entry maxCo (tracking Courant number) = " << maxCo
            << " in " << solDict.name().c_str()
            << " is out of range [" << inputLimits::maxCoMin << ", 1]"
            << " (fraction of a cell a parcel moves per tracking segment)"
            << exit(FatalIOError);
    }
}


template<class CloudType>
void Foam::EllipsoidCloud<CloudType>::setGravityOnly()
{
    // Exactly OpenFOAM's gravity (isType: a force derived from it may read
    // more of the carrier). Only MPPIC clouds switch the force list's
    // non-coupled forces off, not this cloud
    typedef GravityForce<typename CloudType::kinematicCloudType> gravityType;

    const typename CloudType::forceType& forces = this->forces();
    gravityOnly_ =
        !this->solution().coupled()
     && !this->solution().cellValueSourceCorrection()
     && !this->dispersion().active();
    gravity_.setSize(forces.size());
    forAll(forces, i)
    {
        if (isType<gravityType>(forces[i]))
        {
            gravity_[i] = refCast<const gravityType>(forces[i]).g();
        }
        else
        {
            gravityOnly_ = false;
        }
    }
    if (gravityOnly_)
    {
        Info<< "    Carrier forces: gravity alone (the parcels' kick skips"
            << " the force list)" << endl;
    }
    else
    {
        gravity_.clear();
    }
}


template<class CloudType>
void Foam::EllipsoidCloud<CloudType>::setLogAndTracking()
{
    if
    (
        this->solution().active()
     && this->collision().active()
     && !this->contactModel()
    )
    {
        // Contact models read the centres (gatherBody); other collision
        // models (OpenFOAM's pairCollision) read the tracked positions
        this->trackEveryStep
        (
            "collision model " + this->collision().type()
          + " reads the tracked positions"
        );
    }
}


template<class CloudType>
void Foam::EllipsoidCloud<CloudType>::integrateSphereOrientation
(
    const word& reader
)
{
    if (!sphereOrientation_)
    {
        sphereOrientation_ = true;
        Info<< "    Sphere orientations: integrated (read by " << reader
            << ")" << endl;
    }
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
    logInterval_
    (
        getCheckedOrDefault<label>
        (
            this->solution().dict(), "logInterval", 1,
            [](const label n) { return n >= 1; }, ": >= 1 (time steps)"
        )
    ),
    gatherer_(nullptr),
    kickInMove_(false),
    trackBeforeForces_(false),
    contactTime_(0),
    maxInjectionOverlap_(0),
    conservativeCoupling_(false),
    sortInterval_(0),
    sortMinParcels_(0),
    checkAllInjected_(true),
    gravityOnly_(false),
    sphereOrientation_(false)
{
    if (this->solution().active())
    {
        readSolutionControls();
        setGravityOnly();
    }
    setLogAndTracking();

    if (this->solution().active() && readFields)
    {
        checkWrittenFields();
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
    logInterval_(c.logInterval_),
    gatherer_(nullptr),
    kickInMove_(false),
    trackBeforeForces_(false),
    contactTime_(0),
    conservativeCoupling_(c.conservativeCoupling_),
    sortInterval_(c.sortInterval_),
    sortMinParcels_(c.sortMinParcels_),
    checkAllInjected_(true),
    gravityOnly_(c.gravityOnly_),
    gravity_(c.gravity_),
    sphereOrientation_(c.sphereOrientation_)
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
    logInterval_(c.logInterval_),
    gatherer_(nullptr),
    kickInMove_(false),
    trackBeforeForces_(false),
    contactTime_(0),
    conservativeCoupling_(c.conservativeCoupling_),
    sortInterval_(c.sortInterval_),
    sortMinParcels_(c.sortMinParcels_),
    checkAllInjected_(true),
    gravityOnly_(false),
    sphereOrientation_(c.sphereOrientation_)
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
    if (contactModelType* model = this->contactModel())
    {
        model->velocitiesChanged();
    }
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
void Foam::EllipsoidCloud<CloudType>::postEvolve()
{
    if (conservativeCoupling_)
    {
        // The velocity response of each parcel to its carrier velocity over
        // the step, from the coupled forces at the end of the step (their
        // cached fields are released by the base's postEvolve)
        const scalar dt = this->db().time().deltaTValue();
        typename parcelType::trackingData td(*this);
        couplingResponse_.clear();
        couplingCoeff_.setSize(this->mesh().nCells());
        couplingCoeff_ = 0;
        for (parcelType& p : *this)
        {
            p.setCellValues(*this, td);
            const scalar mass = p.mass();
            const forceSuSp Fcp =
                this->forces().calcCoupled
                (
                    p, td, dt, mass, p.Re(td), td.muc()
                );
            const scalar massEff = this->forces().massEff(p, td, mass);
            const scalar beta = Fcp.Sp()/massEff;

            // dU/du = beta dtEff: the U integration scheme's response of
            // dU/dt = beta (u - U) + a to u (Euler: beta dt/(1 + beta dt),
            // analytical: 1 - exp(-beta dt))
            const scalar f =
                beta*dt > SMALL
              ? beta*this->UIntegrator().dtEff(dt, beta)
              : beta*dt;
            couplingResponse_.append(f);
            couplingCoeff_[p.cell()] += p.nParticle()*massEff*f;
        }
    }

    CloudType::postEvolve();
}


template<class CloudType>
Foam::tmp<Foam::fvVectorMatrix>
Foam::EllipsoidCloud<CloudType>::SU(volVectorField& U)
{
    if (!conservativeCoupling_)
    {
        return CloudType::SU(U);
    }

    if (couplingCoeff_.size() != this->mesh().nCells())
    {
        // Not evolved yet (SU before the first evolve)
        couplingCoeff_.setSize(this->mesh().nCells(), 0);
    }
    couplingU0_ = U.primitiveField();

    const volScalarField::Internal Vdt
    (
        this->mesh().V()*this->db().time().deltaT()
    );
    volScalarField::Internal CbyVdt
    (
        IOobject
        (
            this->name() + ":couplingCoeff",
            this->db().time().timeName(),
            this->mesh()
        ),
        this->mesh(),
        dimensionedScalar(dimMass, Zero)
    );
    CbyVdt.field() = couplingCoeff_;
    CbyVdt /= Vdt;

    // The carrier gains UTrans (taken by the parcels at U0) and
    // -C (U - U0): the parcels get +C (U - U0) in correctCoupling
    return this->UTrans()/Vdt - fvm::Sp(CbyVdt, U) + CbyVdt*U;
}


template<class CloudType>
void Foam::EllipsoidCloud<CloudType>::correctCoupling(const volVectorField& U)
{
    if (!conservativeCoupling_)
    {
        return;
    }
    if
    (
        couplingResponse_.size() != this->size()
     || couplingU0_.size() != U.size()
    )
    {
        FatalErrorInFunction
            << "correctCoupling for " << this->size() << " parcels with "
            << couplingResponse_.size() << " responses and "
            << couplingU0_.size() << " old carrier velocities: the solver"
            << " must call SU(U) after evolve() and before correctCoupling"
            << abort(FatalError);
    }

    label i = 0;
    for (parcelType& p : *this)
    {
        const label celli = p.cell();
        p.U() += couplingResponse_[i++]*(U[celli] - couplingU0_[celli]);
    }
    couplingResponse_.clear();
    if (contactModelType* model = this->contactModel())
    {
        model->velocitiesChanged();
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
    // OpenFOAM's injection models set nParticle after checkParcelProperties
    // (from their entry nParticle, or the mass and basis): a non-finite one,
    // or one whose particles fill more than the mesh's bounding box, would
    // reach the cloud's sums and the carrier's sources. Checked in steps
    // that injected parcels (most inject none)
    if (const parcelType* injected = firstInjected())
    {
        const vector span(this->mesh().bounds().span());
        const scalar bbVolume = span.x()*span.y()*span.z();
        for
        (
            const parcelType* pp = injected;
            ;
            pp = static_cast<const parcelType*>(pp->next_)
        )
        {
            const parcelType& p = *pp;
            if (!(p.nParticle() > 0 && p.nParticle()*p.volume() <= bbVolume))
            {
                const dictionary& inj =
                    this->subModelProperties().subDict("injectionModels");
                FatalIOErrorInFunction(inj)
                    << "A parcel (origProc " << p.origProc() << ", origId "
                    << p.origId() << ") of the injection models "
                    << inj.toc() << " carries nParticle = " << p.nParticle()
                    << " particles of " << p.volume() << " m3: out of range,"
                    << " it must be finite and > 0, the particles' volume at"
                    << " most the mesh's bounding box, " << bbVolume
                    << " m3: check the entries nParticle, massTotal and"
                    << " parcelBasisType in " << inj.name().c_str()
                    << exit(FatalIOError);
            }
            if (pp == this->last())
            {
                break;
            }
        }

        if (this->collision().active())
        {
            checkInjectionOverlaps();
        }
    }
    checkAllInjected_ = false;

    // Lazy tracking: the written positions are the tracked ones, tracked
    // in the last move of the step, before its forces (moveCollide)
    const bool writeStep = this->db().time().writeTime();

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
            trackBeforeForces_ =
                writeStep && moveCollideSubCycle.index() == nSubCycles;
            moveCollide(cloud, td, this->db().time().deltaTValue());
        }
        trackBeforeForces_ = false;

        moveCollideSubCycle.endSubCycle();
    }
    else
    {
        trackBeforeForces_ = writeStep;
        moveCollide(cloud, td, this->db().time().deltaTValue());
        trackBeforeForces_ = false;
    }

    // Sorted after the step (the first, then every sortInterval-th) and
    // in write steps: the written parcels are in the order of their cells,
    // which a restart reads, as the uninterrupted run has it (same sums)
    if
    (
        sortInterval_ > 0
     && this->size() >= sortMinParcels_
     && (writeStep || (this->db().time().timeIndex() - 1) % sortInterval_ == 0)
    )
    {
        sortParcels();
    }

    // Ready for the next injection (see evolve)
    td.part() = parcelType::trackingData::tpVelocityHalfStep;
}


template<class CloudType>
void Foam::EllipsoidCloud<CloudType>::writeFields() const
{
    // Also without parcels: a time without a record after one with a
    // record was cut before its parcels were written
    writeFieldsRecord(false);
    CloudType::writeFields();
    writeFieldsRecord(true);
}


template<class CloudType>
void Foam::EllipsoidCloud<CloudType>::info()
{
    // The kinematic information; CollidingCloud::info() would add the
    // rotational energy of spheres, replaced here by the ellipsoids' one
    CloudType::collidingCloudType::cloudType::info();

    // Contacts: counted by a contact model (it writes the collision
    // records only when they are read); other models keep the records of
    // the current contacts only
    const contactModelType* ecPtr = this->contactModel();

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
