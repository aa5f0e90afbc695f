/*---------------------------------------------------------------------------*\
    chargedFoam: charged dielectric particles for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "ElectrostaticsSurvey.H"
#include "ElectrostaticsModel.H"
#include "ewaldSum.H"
#include "pairwiseCoulomb.H"
#include "meshPoisson.H"
#include "cyclicPolyPatch.H"
#include "processorHalo.H"
#include "emptyPolyPatch.H"
#include "wallPolyPatch.H"
#include "processorPolyPatch.H"
#include "clockTime.H"
#include "memInfo.H"
#include "Random.H"
#include "SortableList.H"
#include "ListListOps.H"
#include "Tuple2.H"
#include "OStringStream.H"
#include "checkedEntry.H"
#include <cstdio>

// * * * * * * * * * * * * * * * Static Data * * * * * * * * * * * * * * * //

template<class CloudType>
const Foam::Enum
<
    typename Foam::ElectrostaticsSurvey<CloudType>::sceneKind
>
Foam::ElectrostaticsSurvey<CloudType>::sceneKindNames
({
    { sceneKind::open, "open" },
    { sceneKind::periodic, "periodic" },
    { sceneKind::box, "box" },
    { sceneKind::mesh, "mesh" },
});


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

template<class CloudType>
void Foam::ElectrostaticsSurvey<CloudType>::readControls
(
    const dictionary& dict
)
{
    accuracy_ = getCheckedOrDefault<scalar>
    (
        dict, "accuracy", 0.05,
        [](const scalar a) { return a > 0 && a < 1; },
        ": the rms force error a rung must meet, in (0, 1), e.g. 0.05"
    );
    sampleSize_ = getCheckedOrDefault<label>
    (
        dict, "sampleSize", 1000,
        [](const label n) { return n >= 10; },
        ": it must be >= 10 (parcels compared)"
    );
    repeats_ = getCheckedOrDefault<label>
    (
        dict, "repeats", 3,
        [](const label n) { return n >= 1; },
        ": it must be >= 1 (timed evaluations per rung)"
    );
}


template<class CloudType>
void Foam::ElectrostaticsSurvey<CloudType>::scanBoundary
(
    const boundBox& bb,
    bool& isBox,
    FixedList<label, 3>& axisBits,
    bool& anyGrounded,
    bool& anyCyclic,
    bool& anyElectrode
)
{
    // Phi's boundary conditions: the case's (at the current time) or
    // meshPoisson's defaults
    const fvMesh& mesh = cloud_.mesh();
    const wordList patchKinds(meshPoisson::patchKinds(mesh));

    // Per axis, the kinds of the boundary faces on its two planes (bits
    // 1 << faceKind); a face off the bounding box makes it no box
    const scalar tol = 1e-6*mag(L_);
    isBox = true;
    axisBits = 0;
    anyGrounded = false;
    anyCyclic = false;
    anyElectrode = false;
    anyWall_ = false;

    const polyBoundaryMesh& pbm = mesh.boundaryMesh();
    forAll(pbm, patchi)
    {
        const polyPatch& pp = pbm[patchi];
        if (isA<processorPolyPatch>(pp))
        {
            continue;
        }
        if (isA<emptyPolyPatch>(pp))
        {
            isBox = false;
            continue;
        }
        boxImages::faceKind kind = boxImages::faceKind::insulating;
        if (patchKinds[patchi] == "cyclic")
        {
            kind = boxImages::faceKind::periodic;
            anyCyclic = true;
        }
        else if
        (
            patchKinds[patchi] == "grounded"
         || patchKinds[patchi] == "electrode"
        )
        {
            // The charges' own field vanishes on an electrode too
            kind = boxImages::faceKind::grounded;
            anyGrounded = true;
            anyElectrode =
                anyElectrode || patchKinds[patchi] == "electrode";
        }
        if (isA<wallPolyPatch>(pp))
        {
            anyWall_ = true;
        }

        forAll(pp, facei)
        {
            const vector n = pp.faceNormals()[facei];
            const point& c = pp.faceCentres()[facei];
            label axis = -1;
            for (direction d = 0; d < 3; ++d)
            {
                if
                (
                    mag(n[d]) > 1 - 1e-6
                 && (
                        mag(c[d] - bb.min()[d]) < tol
                     || mag(c[d] - bb.max()[d]) < tol
                    )
                )
                {
                    axis = d;
                }
            }
            if (axis < 0)
            {
                isBox = false;
                break;
            }
            axisBits[axis] |= (1 << label(kind));
        }
    }
}


template<class CloudType>
typename Foam::ElectrostaticsSurvey<CloudType>::sceneKind
Foam::ElectrostaticsSurvey<CloudType>::classify()
{
    const fvMesh& mesh = cloud_.mesh();
    const boundBox bb(mesh.points(), true);
    origin_ = bb.min();
    L_ = bb.span();

    bool isBox, anyGrounded, anyCyclic, anyElectrode;
    FixedList<label, 3> axisBits;
    scanBoundary(bb, isBox, axisBits, anyGrounded, anyCyclic, anyElectrode);
    reduce(isBox, andOp<bool>());
    reduce(anyGrounded, orOp<bool>());
    reduce(anyCyclic, orOp<bool>());
    reduce(anyElectrode, orOp<bool>());
    reduce(anyWall_, orOp<bool>());
    for (direction d = 0; d < 3; ++d)
    {
        reduce(axisBits[d], bitOrOp<label>());
        // One kind per axis
        const label b = axisBits[d];
        if (b != 1 && b != 2 && b != 4)
        {
            isBox = false;
        }
        else
        {
            faceKinds_[d] =
                boxImages::faceKind(b == 1 ? 0 : (b == 2 ? 1 : 2));
        }
    }
    hasElectrodes_ = anyElectrode;

    const fvSolution& fvSol = mesh;
    hasPhiSolver_ = fvSol.subDict("solvers").found("Phi");
    epsilonR_ = cloud_.electrostatics().mediumEpsilonR();

    const scalar V = gSum(mesh.V());
    const label nCells = returnReduce(mesh.nCells(), sumOp<label>());
    nParcels_ = returnReduce(cloud_.size(), sumOp<label>());
    spacing_ = Foam::cbrt(V/max(nParcels_, 1));
    cellSize_ = Foam::cbrt(V/max(nCells, 1));

    bool allPeriodic = isBox;
    bool anyPeriodicAxis = false;
    for (direction d = 0; d < 3; ++d)
    {
        if (isBox && faceKinds_[d] == boxImages::faceKind::periodic)
        {
            anyPeriodicAxis = true;
        }
        else
        {
            allPeriodic = false;
        }
    }

    if (allPeriodic)
    {
        kind_ = sceneKind::periodic;
        referenceName_ = "ewald";
    }
    else if (isBox && (anyGrounded || anyPeriodicAxis))
    {
        kind_ = sceneKind::box;
        referenceName_ = "boxImages";
    }
    else if (!anyGrounded && !anyCyclic)
    {
        kind_ = sceneKind::open;
        referenceName_ = "freeSpaceSum";
    }
    else
    {
        kind_ = sceneKind::mesh;
        referenceName_ =
            hasPhiSolver_ ? "meshPoisson(radius=6h)" : "directCoulomb";
    }
    return kind_;
}


template<class CloudType>
Foam::dictionary Foam::ElectrostaticsSurvey<CloudType>::rungDict
(
    const word& type,
    const dictionary& coeffs
)
{
    dictionary d;
    d.add("electrostaticsModel", type);
    d.add(word(type + "Coeffs"), coeffs);
    return d;
}


template<class CloudType>
bool Foam::ElectrostaticsSurvey<CloudType>::listedRung
(
    const UList<Tuple2<word, dictionary>>& c,
    const word& caseType,
    const dictionary& coeffs
)
{
    // The same rung: each of the case's entries the same there
    bool listed = false;
    for (const auto& cand : c)
    {
        const dictionary& cc =
            cand.second().subOrEmptyDict(caseType + "Coeffs");
        if
        (
            cand.second().get<word>("electrostaticsModel") != caseType
        )
        {
            continue;
        }
        bool same = true;
        for (const entry& e : coeffs)
        {
            const entry* ce = cc.findEntry(e.keyword(), keyType::LITERAL);
            OStringStream a, b;
            if (ce)
            {
                a << e;
                b << *ce;
            }
            if (!ce || a.str() != b.str())
            {
                same = false;
                break;
            }
        }
        listed = listed || same;
    }
    return listed;
}


template<class CloudType>
Foam::List<Foam::Tuple2<Foam::word, Foam::dictionary>>
Foam::ElectrostaticsSurvey<CloudType>::candidates
(
    const dictionary& caseModels
) const
{
    DynamicList<Tuple2<word, dictionary>> c;
    dictionary eps;
    eps.add("epsilonR", epsilonR_);

    c.append({"none", rungDict("none", dictionary())});

    const bool periodic = (kind_ == sceneKind::periodic);
    // The cutoff sums take the copies through cyclic patches one period
    // away: rCut at most the shortest period
    const scalar minPeriod =
        processorHalo::shortestCyclicPeriod(cloud_.mesh());
    if (!periodic)
    {
        // The O(N^2) sum only where it takes seconds, not hours
        if (nParcels_ <= 50000)
        {
            c.append({"directCoulomb", rungDict("directCoulomb", eps)});
        }
        for (const label m : {2, 4, 8})
        {
            // A cutoff beyond the domain is directCoulomb
            if (m*spacing_ < mag(L_) && m*spacing_ <= minPeriod)
            {
                dictionary d(eps);
                d.add("rCut", m*spacing_);
                c.append
                ({
                    word("cutoffCoulomb(rCut=" + Foam::name(m) + "l)"),
                    rungDict("cutoffCoulomb", d)
                });
            }
        }
    }
    if (kind_ == sceneKind::box && anyWall_)
    {
        dictionary d(eps);
        d.add("rCut", 4*spacing_);
        if (4*spacing_ <= minPeriod)
        {
            c.append({"imageCoulomb(rCut=4l)", rungDict("imageCoulomb", d)});
        }
        const scalar edge = min(cmptMin(L_), minPeriod);
        if (edge > 4*spacing_)
        {
            d.set("rCut", edge);
            c.append
            ({
                "imageCoulomb(rCut=minEdge)",
                rungDict("imageCoulomb", d)
            });
        }
    }
    if (periodic)
    {
        for (const scalar a : {1e-3, 1e-5})
        {
            dictionary d(eps);
            d.add("method", "p3m");
            d.add("accuracy", a);
            c.append
            ({
                word("periodic(p3m,accuracy=" + Foam::name(a) + ")"),
                rungDict("periodic", d)
            });
        }
        dictionary d(eps);
        d.add("method", "pseudoParticle");
        c.append({"periodic(pseudoParticle)", rungDict("periodic", d)});
    }
    if (hasPhiSolver_ && kind_ != sceneKind::open)
    {
        for (const label m : {2, 4})
        {
            dictionary d(eps);
            d.add("radius", m*cellSize_);
            c.append
            ({
                word("meshPoisson(radius=" + Foam::name(m) + "h)"),
                rungDict("meshPoisson", d)
            });
        }
    }

    // The case's own rung, without its layers (applied and near field)
    const word caseType
    (
        caseModels.lookupOrDefault<word>("electrostaticsModel", "none")
    );
    if (caseType != "none" && caseType != "auto")
    {
        dictionary coeffs(caseModels.subOrEmptyDict(caseType + "Coeffs"));
        coeffs.remove("nearField");

        // Not again if a candidate is the same rung
        const bool listed = listedRung(c, caseType, coeffs);
        if (!listed)
        {
            c.append({word("case:" + caseType), rungDict(caseType, coeffs)});
        }
    }

    return c;
}


template<class CloudType>
void Foam::ElectrostaticsSurvey<CloudType>::gather
(
    pointField& x,
    scalarField& q,
    vectorField& fSample
) const
{
    List<pointField> allX(Pstream::nProcs());
    List<scalarField> allQ(Pstream::nProcs());
    List<vectorField> allF(Pstream::nProcs());
    pointField& myX = allX[Pstream::myProcNo()];
    scalarField& myQ = allQ[Pstream::myProcNo()];
    vectorField& myF = allF[Pstream::myProcNo()];
    myX.setSize(cloud_.size());
    myQ.setSize(cloud_.size());
    myF.setSize(cloud_.size());
    label i = 0;
    for (const auto& p : cloud_)
    {
        myX[i] = p.centre();
        myQ[i] = p.q();
        myF[i] = p.fE();
        ++i;
    }
    Pstream::gatherList(allX);
    Pstream::gatherList(allQ);
    Pstream::gatherList(allF);
    if (Pstream::master())
    {
        x = ListListOps::combine<pointField>(allX, accessOp<pointField>());
        q = ListListOps::combine<scalarField>(allQ, accessOp<scalarField>());
        const vectorField f
        (
            ListListOps::combine<vectorField>(allF, accessOp<vectorField>())
        );
        fSample = vectorField(f, sample_);
    }
}


template<class CloudType>
Foam::vectorField Foam::ElectrostaticsSurvey<CloudType>::referenceForces()
{
    if (kind_ == sceneKind::mesh && hasPhiSolver_)
    {
        dictionary d;
        d.add("epsilonR", epsilonR_);
        d.add("radius", 6*cellSize_);
        scalar cost, memory;
        return evaluate(rungDict("meshPoisson", d), cost, memory, true);
    }

    pointField x;
    scalarField q;
    vectorField f;
    gather(x, q, f);
    List<vector> fRef(sample_.size(), Zero);
    if (Pstream::master())
    {
        if (kind_ == sceneKind::periodic)
        {
            const ewaldSum ewald(L_, epsilonR_, 1e-10);
            ewald.forces(x, q, sample_, fRef);
        }
        else if (kind_ == sceneKind::box)
        {
            boxImages::forces
            (
                x, q, origin_, L_, faceKinds_, epsilonR_, sample_, fRef
            );
        }
        else
        {
            // Free space (O(sample N): the reference of the sample only)
            const pairwiseCoulomb coulomb(epsilonR_);
            forAll(sample_, k)
            {
                const label i = sample_[k];
                vector E(Zero);
                forAll(x, j)
                {
                    if (j != i)
                    {
                        E += coulomb.pairField(x[i], x[j], q[j]);
                    }
                }
                fRef[k] = q[i]*E;
            }
        }
    }
    return vectorField(std::move(fRef));
}


template<class CloudType>
Foam::vectorField Foam::ElectrostaticsSurvey<CloudType>::evaluate
(
    const dictionary& dict,
    scalar& cost,
    scalar& memory,
    const bool chargesOnly
)
{
    memInfo mem;
    const label rss0 = mem.update().rss();

    autoPtr<ElectrostaticsModel<CloudType>> model
    (
        ElectrostaticsModel<CloudType>::New(dict, cloud_)
    );

    // Warm-up (caches, plans, the first solve), then the timed repeats; a
    // rung that solves every n-th evaluation (meshPoisson solveInterval)
    // is timed over n evaluations per repeat, its solve's share included
    const word type(dict.get<word>("electrostaticsModel"));
    const label n = max
    (
        dict.subOrEmptyDict(type + "Coeffs").lookupOrDefault<label>
        (
            "solveInterval",
            1
        ),
        label(1)
    );
    clockTime warmUp;
    model->update();
    const scalar tFirst = returnReduce(warmUp.elapsedTime(), maxOp<scalar>());
    // The forces of this first evaluation are the rung's: the timed ones
    // after it start their iterative solves (BEM, induced dipoles) from
    // the last solution, and how many there are depends on the wall time
    // (below), so forces taken after them would depend on the machine's
    // load in their last bits
    pointField x;
    scalarField q;
    vectorField f;
    gather(x, q, f);
    // A rung whose first evaluation takes more than 10 s is timed by it
    // alone (its caches built, so an upper bound): the survey stays
    // affordable on large clouds
    const bool slow = tFirst > 10;
    scalarField times(slow ? 1 : repeats_);
    if (slow)
    {
        times[0] = tFirst;
    }
    else forAll(times, r)
    {
        // A mesh solve starts from the last potential: on unchanged
        // charges it would not iterate at all, so each timed solve starts
        // from zero (an upper bound of a run's solves from the previous
        // step's potential)
        model->forgetWarmStart();
        clockTime timer;
        for (label i = 0; i < n; ++i)
        {
            model->update();
        }
        times[r] = returnReduce(timer.elapsedTime()/n, maxOp<scalar>());
    }
    std::sort(times.begin(), times.end());
    cost = times[times.size()/2];
    memory = returnReduce
    (
        scalar(max(mem.update().rss() - rss0, label(0)))/1024,
        maxOp<scalar>()
    );

    // The field of the electrodes of a mesh rung (all charges zero) is not
    // the charges' own
    if (chargesOnly && type == "meshPoisson" && hasElectrodes_)
    {
        scalarField q0(cloud_.size());
        label i = 0;
        for (auto& p : cloud_)
        {
            q0[i++] = p.q();
            p.q() = 0;
        }
        model->update();
        List<vectorField> allE(Pstream::nProcs());
        vectorField& myE = allE[Pstream::myProcNo()];
        myE.setSize(cloud_.size());
        i = 0;
        for (auto& p : cloud_)
        {
            myE[i] = p.E();
            p.q() = q0[i++];
        }
        Pstream::gatherList(allE);
        if (Pstream::master())
        {
            const vectorField E0
            (
                ListListOps::combine<vectorField>(allE, accessOp<vectorField>())
            );
            forAll(sample_, k)
            {
                f[k] -= q[sample_[k]]*E0[sample_[k]];
            }
        }
    }

    return f;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

template<class CloudType>
Foam::ElectrostaticsSurvey<CloudType>::ElectrostaticsSurvey
(
    CloudType& cloud,
    const dictionary& dict
)
:
    cloud_(cloud),
    accuracy_(0.05),
    sampleSize_(1000),
    repeats_(3),
    kind_(sceneKind::open),
    origin_(Zero),
    L_(Zero),
    faceKinds_(boxImages::faceKind::grounded),
    anyWall_(false),
    hasElectrodes_(false),
    hasPhiSolver_(false),
    epsilonR_(1),
    nParcels_(0),
    spacing_(0),
    cellSize_(0),
    referenceName_(),
    sample_(),
    anyForce_(false),
    rungs_(),
    recommended_(-1),
    nearFarField_(),
    nearReferenceName_(),
    nearRungs_(),
    nearRecommended_(-1)
{
    readControls(dict);
}


// * * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * //

template<class CloudType>
void Foam::ElectrostaticsSurvey<CloudType>::run(const dictionary& caseModels)
{
    classify();

    // The sample: all parcels, or a fixed-seed random choice (the same on
    // every processor count: global indices in processor order)
    const label N = returnReduce(cloud_.size(), sumOp<label>());
    labelList all(identity(N));
    if (N > sampleSize_)
    {
        Random rnd(1234);
        for (label k = 0; k < sampleSize_; ++k)
        {
            const label j = k + rnd.position<label>(0, N - 1 - k);
            std::swap(all[k], all[j]);
        }
        all.setSize(sampleSize_);
        Foam::sort(all);
    }
    sample_.transfer(all);

    const vectorField fRef(referenceForces());
    measure(candidates(caseModels), fRef, true, rungs_);
    recommended_ = cheapestWithin(rungs_);

    // The near field on the recommended (or most accurate) far field, for
    // scenes with polarisable parcels: none, induced dipoles and BEM
    // clusters against BEM clusters at twice the patches
    nearRungs_.clear();
    nearRecommended_ = -1;
    bool polarisable = false;
    for (const auto& p : cloud_)
    {
        polarisable =
            polarisable || mag(p.epsilonR() - epsilonR_) > 1e-9*epsilonR_;
    }
    if (!returnReduce(polarisable, orOp<bool>()))
    {
        return;
    }
    const rung& far =
        rungs_[recommended_ >= 0 ? recommended_ : mostAccurate()];
    nearFarField_ = far.name;
    const word farType(far.dict.template get<word>("electrostaticsModel"));
    const bool bemAllowed = (farType != "periodic");

    auto withNearField = [&](const dictionary& nearField)
    {
        dictionary d(far.dict);
        d.subDict(farType + "Coeffs").set("nearField", nearField);
        return d;
    };

    List<Tuple2<word, dictionary>> c;
    {
        dictionary none;
        none.add("type", "none");
        c.append({"nearField:none", withNearField(none)});
        dictionary dip;
        dip.add("type", "inducedDipole");
        c.append({"nearField:inducedDipole", withNearField(dip)});
    }
    vectorField fNearRef;
    if (bemAllowed)
    {
        dictionary bem;
        bem.add("type", "bem");
        c.append({"nearField:bem", withNearField(bem)});
        bem.add("nPatches", 2400);
        nearReferenceName_ = "bem(nPatches=2400)";
        scalar cost, memory;
        fNearRef = evaluate(withNearField(bem), cost, memory, false);
    }
    else
    {
        // The bem near field refuses periodic boxes: dipoles at a tight
        // tolerance are the most accurate there
        dictionary dip;
        dip.add("type", "inducedDipole");
        dip.add("tolerance", 1e-12);
        nearReferenceName_ = "inducedDipole(tolerance=1e-12)";
        scalar cost, memory;
        fNearRef = evaluate(withNearField(dip), cost, memory, false);
    }
    measure(c, fNearRef, false, nearRungs_);
    nearRecommended_ = cheapestWithin(nearRungs_);
}


template<class CloudType>
void Foam::ElectrostaticsSurvey<CloudType>::measure
(
    const List<Tuple2<word, dictionary>>& c,
    const vectorField& fRef,
    const bool chargesOnly,
    List<rung>& rungs
)
{
    rungs.setSize(c.size());
    forAll(c, k)
    {
        rung& r = rungs[k];
        r.name = c[k].first();
        r.dict = c[k].second();
        const vectorField f(evaluate(r.dict, r.cost, r.memory, chargesOnly));

        r.rmsError = 0;
        r.p95Error = 0;
        if (Pstream::master())
        {
            scalar dd = 0, rr = 0;
            DynamicList<scalar> rel(sample_.size());
            forAll(fRef, i)
            {
                const scalar d2 = magSqr(f[i] - fRef[i]);
                const scalar r2 = magSqr(fRef[i]);
                dd += d2;
                rr += r2;
                if (r2 > 0)
                {
                    rel.append(Foam::sqrt(d2/r2));
                }
            }
            r.rmsError = rr > 0 ? Foam::sqrt(dd/rr) : (dd > 0 ? 1 : 0);
            anyForce_ = anyForce_ || rr > 0;
            if (rel.size())
            {
                Foam::sort(rel);
                r.p95Error =
                    rel[max(label(std::ceil(0.95*rel.size())) - 1, label(0))];
            }
        }
        Pstream::scatter(anyForce_);
        Pstream::scatter(r.rmsError);
        Pstream::scatter(r.p95Error);
    }
    // The cloud's own model sets the forces again at its next evaluation
}


template<class CloudType>
Foam::label Foam::ElectrostaticsSurvey<CloudType>::cheapestWithin
(
    const List<rung>& rungs
) const
{
    label best = -1;
    forAll(rungs, k)
    {
        if
        (
            rungs[k].rmsError <= accuracy_
         && (best < 0 || rungs[k].cost < rungs[best].cost)
        )
        {
            best = k;
        }
    }
    return best;
}


template<class CloudType>
Foam::label Foam::ElectrostaticsSurvey<CloudType>::mostAccurate() const
{
    label best = -1;
    forAll(rungs_, k)
    {
        if (best < 0 || rungs_[k].rmsError < rungs_[best].rmsError)
        {
            best = k;
        }
    }
    return best;
}


template<class CloudType>
Foam::scalar Foam::ElectrostaticsSurvey<CloudType>::cheapestCost() const
{
    scalar cheapest = GREAT;
    for (const rung& r : rungs_)
    {
        if (r.name != "none" && r.cost > 0)
        {
            cheapest = min(cheapest, r.cost);
        }
    }
    return cheapest;
}


template<class CloudType>
void Foam::ElectrostaticsSurvey<CloudType>::write(Ostream& os) const
{
    const scalar cheapest = cheapestCost();

    os  << "Electrostatics rungs measured on the parcels: scene "
        << sceneKindNames[kind_];
    if (kind_ == sceneKind::box || kind_ == sceneKind::periodic)
    {
        os  << " (" << L_ << " m; faces";
        for (direction d = 0; d < 3; ++d)
        {
            os  << ' ' << "xyz"[d] << ' '
                << boxImages::faceKindNames[faceKinds_[d]];
        }
        os  << ')';
    }
    os  << ", reference " << referenceName_;
    if (kind_ == sceneKind::mesh)
    {
        os  << " (not independent of the meshPoisson rungs)";
    }
    os  << nl << "    " << sample_.size() << " parcels compared, spacing l = "
        << spacing_ << " m, cell size h = " << cellSize_ << " m, epsilonR "
        << epsilonR_ << nl;

    // OpenFOAM's Ostream has no column alignment: format with snprintf
    char line[256];
    std::snprintf
    (
        line, sizeof(line), "    %-34s %9s %9s %10s %9s %8s",
        "rung", "rms %", "p95 %", "cost ms", "x cheap", "mem MB"
    );
    os  << line << nl;
    forAll(rungs_, k)
    {
        const rung& r = rungs_[k];
        std::snprintf
        (
            line, sizeof(line), "  %s %-34s %9.3g %9.3g %10.3g %9.3g %8.1f",
            k == recommended_ ? "*" : " ", r.name.c_str(),
            100*r.rmsError, 100*r.p95Error, 1e3*r.cost,
            r.name == "none" ? 0.0 : r.cost/cheapest, r.memory
        );
        os  << line << nl;
    }
    if (!anyForce_)
    {
        os  << "    No parcel has a force (no charges): every rung agrees"
            << nl;
    }
    if (recommended_ >= 0)
    {
        const rung& r = rungs_[recommended_];
        os  << "    Recommended (*): " << r.name << ", the cheapest with rms"
            << " error <= " << 100*accuracy_ << " %: in the cloud's subModels"
            << nl << r.dict;
    }
    else
    {
        const label b = mostAccurate();
        os  << "    No rung meets rms error <= " << 100*accuracy_ << " %;"
            << " the most accurate: " << rungs_[b].name << " ("
            << 100*rungs_[b].rmsError << " %)" << nl;
    }

    if (nearRungs_.size())
    {
        os  << nl << "Near field on " << nearFarField_
            << " (polarisable parcels), reference " << nearReferenceName_
            << nl;
        forAll(nearRungs_, k)
        {
            const rung& r = nearRungs_[k];
            std::snprintf
            (
                line, sizeof(line),
                "  %s %-34s %9.3g %9.3g %10.3g %9.3g %8.1f",
                k == nearRecommended_ ? "*" : " ", r.name.c_str(),
                100*r.rmsError, 100*r.p95Error, 1e3*r.cost,
                r.cost/nearRungs_[0].cost, r.memory
            );
            os  << line << nl;
        }
        if (nearRecommended_ >= 0)
        {
            const rung& r = nearRungs_[nearRecommended_];
            os  << "    Recommended (*): " << r.name << ", the cheapest with"
                << " rms error <= " << 100*accuracy_ << " % (x cheap: cost"
                << " relative to point charges)" << nl << r.dict;
        }
        else
        {
            os  << "    No near field meets rms error <= " << 100*accuracy_
                << " %" << nl;
        }
    }
    os  << endl;
}


template<class CloudType>
void Foam::ElectrostaticsSurvey<CloudType>::writeTable(Ostream& os) const
{
    const scalar cheapest = cheapestCost();
    os  << "# scene " << sceneKindNames[kind_] << nl
        << "# reference " << referenceName_ << nl
        << "# accuracy " << accuracy_ << nl
        << "# parcelsCompared " << sample_.size() << nl
        << "# spacing " << spacing_ << nl
        << "# cellSize " << cellSize_ << nl
        << "# recommended "
        << (recommended_ >= 0 ? rungs_[recommended_].name : word("none"))
        << nl
        << "# rung rmsError p95Error cost[s] costRatio memory[MB]"
        << " recommended" << nl;
    forAll(rungs_, k)
    {
        const rung& r = rungs_[k];
        os  << r.name << ' ' << r.rmsError << ' ' << r.p95Error << ' '
            << r.cost << ' ' << (r.name == "none" ? 0 : r.cost/cheapest)
            << ' ' << r.memory << ' ' << (k == recommended_ ? 1 : 0) << nl;
    }
    if (nearRungs_.size())
    {
        // The near-field rows: cost relative to point charges
        os  << "# nearFieldOn " << nearFarField_ << nl
            << "# nearFieldReference " << nearReferenceName_ << nl
            << "# nearFieldRecommended "
            << (
                   nearRecommended_ >= 0
                 ? nearRungs_[nearRecommended_].name
                 : word("none")
               )
            << nl;
        forAll(nearRungs_, k)
        {
            const rung& r = nearRungs_[k];
            os  << r.name << ' ' << r.rmsError << ' ' << r.p95Error << ' '
                << r.cost << ' ' << r.cost/nearRungs_[0].cost << ' '
                << r.memory << ' ' << (k == nearRecommended_ ? 1 : 0) << nl;
        }
    }
}


// ************************************************************************* //
