/*---------------------------------------------------------------------------*\
    chargedFoam: charged dielectric particles for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "BemNearField.H"
#include "processorHalo.H"
#include "ElectrostaticsModel.H"
#include "cutoffPairs.H"
#include "cpuTime.H"
#include "pointMultipole.H"
#include "pairwiseCoulomb.H"

#include <algorithm>
#include <numeric>
#include <set>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace Foam
{
namespace bemNearFieldDetail
{

//- Extent of an ellipsoid (semi-axes s, rotation R body -> world) along
//  the unit vector u: sqrt(u . R diag(s^2) R^T . u)
inline scalar extent(const vector& s, const tensor& R, const vector& u)
{
    const vector ub = R.T() & u;
    return Foam::sqrt
    (
        sqr(s.x()*ub.x()) + sqr(s.y()*ub.y()) + sqr(s.z()*ub.z())
    );
}

//- Centre-line gap of the ellipsoids a and b (semi-axes s, rotations R),
//  r = x_a - x_b, r2 = |r|^2
inline scalar centreLineGap
(
    const vector& sa,
    const tensor& Ra,
    const vector& sb,
    const tensor& Rb,
    const vector& r,
    const scalar r2
)
{
    const scalar d = Foam::sqrt(r2);
    const vector u = -r/d;      // from a to b
    return d - extent(sa, Ra, u) - extent(sb, Rb, u);
}

//- A rotation taking (1 0 0) to the unit vector u
inline tensor rotationFromX(const vector& u)
{
    // Rodrigues from (1 0 0) to v with c = v.x >= 0 (well conditioned):
    // I + [k]x + [k]x^2/(1 + c), k = (1 0 0) x v
    auto rodrigues = [](const vector& v)
    {
        const vector k(0, -v.z(), v.y());
        const tensor K(0, -k.z(), k.y(), k.z(), 0, -k.x(), -k.y(), k.x(), 0);
        return tensor(tensor::I + K + (K & K)/(1 + v.x()));
    };
    if (u.x() >= 0)
    {
        return rodrigues(u);
    }
    // Through the half turn H about z (H (1 0 0) = -(1 0 0), H = H^T =
    // H^-1): R = H R2, R2 taking (1 0 0) to H u
    const tensor H(-1, 0, 0, 0, -1, 0, 0, 0, 1);
    return H & rodrigues(H & u);
}

//- Direction k of n on the Fibonacci sphere
inline vector fibonacciDirection(const label k, const label n)
{
    const scalar golden = constant::mathematical::pi*(3 - Foam::sqrt(5.0));
    const scalar z = 1 - (2*k + 1)/scalar(n);
    const scalar r = Foam::sqrt(max(1 - z*z, scalar(0)));
    return vector(r*Foam::cos(golden*k), r*Foam::sin(golden*k), z);
}

//- Index of the nearest of n Fibonacci-sphere directions to unit u
inline label directionBin(const vector& u, const label n, vector& dir)
{
    label best = 0;
    scalar bestDot = -2;
    for (label k = 0; k < n; ++k)
    {
        const vector d = fibonacciDirection(k, n);
        if ((d & u) > bestDot)
        {
            bestDot = d & u;
            best = k;
            dir = d;
        }
    }
    return best;
}

//- Focus directions of the ellipsoids' meshes
constexpr label nFocusDirections = 64;

//- Union-find root with path halving
inline label root(labelList& parent, label i)
{
    while (parent[i] != i)
    {
        parent[i] = parent[parent[i]];
        i = parent[i];
    }
    return i;
}

//- The components of the links among the halo's points (its n own
//  points first): each linked point's key the smallest keyh of its
//  component (unlinked: -1), owner the processor and xMin the position
//  (in: the points) of that smallest one, propagated through the halo
//  until no processor changes (a cluster crossing k processor boundaries
//  takes about k + 1 rounds). Collective
inline void labelComponents
(
    const processorHalo& halo,
    const UList<labelPair>& links,
    const scalarField& keyh,
    const label n,
    scalarField& key,
    labelList& owner,
    pointField& xMin
)
{
    const label nh = keyh.size();
    for (const labelPair& l : links)
    {
        for (const label e : {l.first(), l.second()})
        {
            key[e] = keyh[e];
        }
    }
    for (label i = 0; i < n; ++i)
    {
        owner[i] = key[i] >= 0 ? Pstream::myProcNo() : -1;
    }
    halo.updateHalo(owner);
    while (true)
    {
        labelList parent(identity(nh));
        for (const labelPair& l : links)
        {
            const label ra = root(parent, l.first());
            const label rb = root(parent, l.second());
            parent[max(ra, rb)] = min(ra, rb);
        }
        // The smallest key of each component (at its root)
        labelList best(identity(nh));
        for (label e = 0; e < nh; ++e)
        {
            if (key[e] >= 0)
            {
                const label r = root(parent, e);
                if (key[e] < key[best[r]])
                {
                    best[r] = e;
                }
            }
        }
        bool changed = false;
        for (label i = 0; i < n; ++i)
        {
            const label b = best[root(parent, i)];
            if (key[i] >= 0 && key[b] < key[i])
            {
                key[i] = key[b];
                owner[i] = owner[b];
                xMin[i] = xMin[b];
                changed = true;
            }
        }
        if (!returnReduce(changed, orOp<bool>()))
        {
            break;
        }
        halo.updateHalo(key);
        halo.updateHalo(owner);
        halo.updateHaloPoints(xMin);
    }
}

//- The other processors whose boxes come within range of this one's,
//  directly or through the cyclic translations
inline labelList nearProcessors
(
    const List<boundBox>& boxes,
    const scalar range,
    const UList<vector>& translations
)
{
    DynamicList<label> near;
    forAll(boxes, proci)
    {
        if
        (
            processorHalo::reaches
            (
                boxes, Pstream::myProcNo(), proci, range, translations
            )
        )
        {
            near.append(proci);
        }
    }
    labelList result;
    result.transfer(near);
    return result;
}

//- Every processor's entries of a map by parcel id on the master, or on
//  every processor (toAll); holder: the processor each came from (an
//  entry's id is held by one processor). Collective
template<class First, class Second>
void gatherEntries
(
    std::map<labelPair, std::pair<First, Second>>& m,
    const bool toAll,
    std::map<labelPair, label>* holder = nullptr
)
{
    const label me = Pstream::myProcNo();
    List<List<labelPair>> ids(Pstream::nProcs());
    List<List<First>> firsts(Pstream::nProcs());
    List<List<Second>> seconds(Pstream::nProcs());
    for (const auto& entry : m)
    {
        ids[me].append(entry.first);
        firsts[me].append(entry.second.first);
        seconds[me].append(entry.second.second);
    }
    Pstream::gatherList(ids);
    Pstream::gatherList(firsts);
    Pstream::gatherList(seconds);
    if (toAll)
    {
        Pstream::scatterList(ids);
        Pstream::scatterList(firsts);
        Pstream::scatterList(seconds);
    }
    forAll(ids, proci)
    {
        forAll(ids[proci], k)
        {
            m.emplace
            (
                ids[proci][k],
                std::make_pair(firsts[proci][k], seconds[proci][k])
            );
            if (holder)
            {
                (*holder)[ids[proci][k]] = proci;
            }
        }
    }
}


//- Of a store of entries by parcel id, each kept by one processor (the
//  one that solved it last), the entries of the given ids: this
//  processor's, and the rest asked of the processors procs (those near:
//  a cluster's last solver was near it). Collective
template<class First, class Second>
std::map<labelPair, std::pair<First, Second>> fetchHeld
(
    const std::map<labelPair, std::pair<First, Second>>& store,
    const UList<labelPair>& wanted,
    const labelUList& procs
)
{
    std::map<labelPair, std::pair<First, Second>> found;
    DynamicList<labelPair> missing;
    for (const labelPair& id : wanted)
    {
        const auto iter = store.find(id);
        if (iter != store.end())
        {
            found.insert(*iter);
        }
        else
        {
            missing.append(id);
        }
    }
    if (!Pstream::parRun())
    {
        return found;
    }
    PstreamBuffers questions(Pstream::commsTypes::nonBlocking);
    if (missing.size())
    {
        for (const label proci : procs)
        {
            UOPstream os(proci, questions);
            os << List<labelPair>(missing);
        }
    }
    labelList sizes;
    questions.finishedSends(sizes);
    PstreamBuffers answers(Pstream::commsTypes::nonBlocking);
    forAll(sizes, proci)
    {
        if (!sizes[proci])
        {
            continue;
        }
        UIPstream is(proci, questions);
        const List<labelPair> ids(is);
        DynamicList<labelPair> have;
        DynamicList<First> firsts;
        DynamicList<Second> seconds;
        for (const labelPair& id : ids)
        {
            const auto iter = store.find(id);
            if (iter != store.end())
            {
                have.append(id);
                firsts.append(iter->second.first);
                seconds.append(iter->second.second);
            }
        }
        if (have.size())
        {
            UOPstream os(proci, answers);
            os  << List<labelPair>(have) << List<First>(firsts)
                << List<Second>(seconds);
        }
    }
    answers.finishedSends(sizes);
    forAll(sizes, proci)
    {
        if (!sizes[proci])
        {
            continue;
        }
        UIPstream is(proci, answers);
        const List<labelPair> ids(is);
        const List<First> firsts(is);
        const List<Second> seconds(is);
        forAll(ids, k)
        {
            found.emplace(ids[k], std::make_pair(firsts[k], seconds[k]));
        }
    }
    return found;
}

} // End namespace bemNearFieldDetail
} // End namespace Foam


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

template<class CloudType>
Foam::label Foam::BemNearField<CloudType>::shapeFor
(
    const vector& semiAxes,
    const vector& focus,
    const scalar lambda,
    const label nPatches
)
{
    const bool sphere = cmptMin(semiAxes) == cmptMax(semiAxes);
    vector dir(1, 0, 0);
    const label bin =
        (sphere || lambda == 1)
      ? -1
      : bemNearFieldDetail::directionBin
        (
            focus, bemNearFieldDetail::nFocusDirections, dir
        );
    meshKey key;
    key[0] = semiAxes.x();
    key[1] = semiAxes.y();
    key[2] = semiAxes.z();
    key[3] = bin;
    key[4] = lambda;
    key[5] = nPatches;
    const label now = this->owner().db().time().timeIndex();
    auto iter = shapeIndex_.find(key);
    if (iter == shapeIndex_.end())
    {
        const cpuTime timer;
        iter = shapeIndex_.emplace
        (
            key,
            bem_->shape(semiAxes, nPatches, dir, lambda)
        ).first;
        shapeKeys_.resize(max(label(shapeKeys_.size()), iter->second + 1));
        shapeKeys_[iter->second] = key;
        shapeLastUse_.resize(shapeKeys_.size(), now);
        setupTime_ += timer.elapsedCpuTime();
    }
    shapeLastUse_[iter->second] = now;
    return iter->second;
}


template<class CloudType>
Foam::label Foam::BemNearField<CloudType>::shapeOf(const meshKey& key)
{
    const label bin = std::lround(key[3]);
    return shapeFor
    (
        vector(key[0], key[1], key[2]),
        bin < 0
      ? vector(1, 0, 0)
      : bemNearFieldDetail::fibonacciDirection
        (
            bin, bemNearFieldDetail::nFocusDirections
        ),
        key[4],
        std::lround(key[5])
    );
}


template<class CloudType>
void Foam::BemNearField<CloudType>::trimCache()
{
    const label now = this->owner().db().time().timeIndex();
    // Several keys can name one mesh (bemSolver::shape reuses an equal
    // one, e.g. patch counts that round to the same even number)
    std::set<label> live;
    for (const auto& entry : shapeIndex_)
    {
        live.insert(entry.second);
    }
    std::vector<std::tuple<label, label, scalar>> unused;
    scalar bytes = 0;
    for (const label s : live)
    {
        const scalar b = bem_->shapeBytes(s);
        bytes += b;
        if (shapeLastUse_[s] < now)
        {
            unused.emplace_back(shapeLastUse_[s], s, b);
        }
    }
    if (bytes > meshCacheBytes_)
    {
        std::sort(unused.begin(), unused.end());
        for (const auto& u : unused)
        {
            if (bytes <= meshCacheBytes_)
            {
                break;
            }
            const label s = std::get<1>(u);
            bem_->releaseShape(s);
            bytes -= std::get<2>(u);
            for (auto it = shapeIndex_.begin(); it != shapeIndex_.end();)
            {
                it = it->second == s ? shapeIndex_.erase(it) : ++it;
            }
            for (auto it = selfEnergy_.begin(); it != selfEnergy_.end();)
            {
                it = it->first.first == s ? selfEnergy_.erase(it) : ++it;
            }
        }
    }
    stats_.cacheBytes = bytes;
    live.clear();
    for (const auto& entry : shapeIndex_)
    {
        live.insert(entry.second);
    }
    stats_.nShapes = live.size();
}


template<class CloudType>
Foam::scalar Foam::BemNearField<CloudType>::selfEnergy
(
    const label shapeI,
    const scalar kappa
)
{
    const auto key = std::make_pair(shapeI, kappa);
    auto iter = selfEnergy_.find(key);
    if (iter == selfEnergy_.end())
    {
        // The member alone with a unit charge, no external field
        bem_->clearParticles();
        bem_->setExternalField(bemSolver::fieldFunction());
        bem_->addParticle(shapeI, Zero, tensor::I, kappa, 1.0);
        bem_->setWithEnergy(true);
        bem_->solve();
        iter = selfEnergy_.emplace(key, bem_->energy()).first;
    }
    return iter->second;
}


template<class CloudType>
void Foam::BemNearField<CloudType>::writeState() const
{
    // Each processor writes the members it holds (solved last) and the
    // moments they were solved with; the master writes every processor's
    // (reconstructPar takes the master's uniform files), each with the
    // processor that holds it, so that a restart on as many processors
    // gives each its own back and any decomposition finds its parcels'
    // state. The moments (a few numbers a member) are gathered on every
    // processor, the bound charge on the master only
    boundChargeMap all(lastSigmaB_);
    momentsMap used(usedMoments_);
    std::map<labelPair, label> holder;
    bemNearFieldDetail::gatherEntries(all, false, &holder);
    bemNearFieldDetail::gatherEntries(used, true);

    labelList ids(2*all.size());
    List<meshKey> meshes(all.size());
    List<scalarField> sigmaB(all.size());
    vectorField dipoles(all.size(), Zero);
    symmTensorField quadrupoles(all.size(), Zero);
    labelList hasMoments(all.size(), 0);
    labelList holders(all.size());
    label k = 0;
    for (const auto& entry : all)
    {
        holders[k] = holder.at(entry.first);
        ids[2*k] = entry.first.first();
        ids[2*k + 1] = entry.first.second();
        meshes[k] = entry.second.first;
        sigmaB[k] = entry.second.second;
        const auto m = used.find(entry.first);
        if (m != used.end())
        {
            dipoles[k] = m->second.first;
            quadrupoles[k] = m->second.second;
            hasMoments[k] = 1;
        }
        ++k;
    }
    dictionary state;
    state.add("ids", ids);
    state.add("meshes", meshes);
    state.add("sigmaB", sigmaB);
    state.add("hasMoments", hasMoments);
    state.add("dipoles", dipoles);
    state.add("quadrupoles", quadrupoles);
    state.add("holders", holders);
    state.add("nProcs", Pstream::nProcs());
    state.add("remeshOffset", remeshOffset_);
    this->owner().outputProperties().set("bemNearField", state);
}


template<class CloudType>
const Foam::symmTensor& Foam::BemNearField<CloudType>::unitQuadrupole
(
    const vector& s
) const
{
    const std::array<scalar, 3> key{{s.x(), s.y(), s.z()}};
    auto iter = unitQuadrupole_.find(key);
    if (iter == unitQuadrupole_.end())
    {
        iter = unitQuadrupole_.emplace(key, uniformSurfaceQuadrupole(s)).first;
    }
    return iter->second;
}


template<class CloudType>
void Foam::BemNearField<CloudType>::readState()
{
    stateRead_ = true;
    const dictionary& props = this->owner().outputProperties();
    if (!props.isDict("bemNearField"))
    {
        return;
    }
    const dictionary& state = props.subDict("bemNearField");
    remeshOffset_ =
        state.template lookupOrDefault<scalar>("remeshOffset", 0);
    const labelList ids(state.lookup("ids"));
    const List<meshKey> meshes(state.lookup("meshes"));
    const List<scalarField> sigmaB(state.lookup("sigmaB"));
    const vectorField dipoles
    (
        state.lookupOrDefault("dipoles", vectorField(meshes.size(), Zero))
    );
    const symmTensorField quadrupoles
    (
        state.lookupOrDefault
        (
            "quadrupoles", symmTensorField(meshes.size(), Zero)
        )
    );
    const labelList hasMoments
    (
        state.lookupOrDefault("hasMoments", labelList(meshes.size(), 0))
    );
    const label nProcsWritten =
        state.template lookupOrDefault<label>("nProcs", -1);
    const labelList holders
    (
        state.lookupOrDefault("holders", labelList(meshes.size(), -1))
    );
    // Each processor keeps what it held when the state was written (on
    // as many processors) and its own parcels' (the solvers of the first
    // step ask the processors near them for the rest)
    typename NearFieldModel<CloudType>::parcelIdSet own;
    for (const auto& p : this->owner())
    {
        own.insert(labelPair(p.origProc(), p.origId()));
    }
    forAll(meshes, k)
    {
        const labelPair id(ids[2*k], ids[2*k + 1]);
        if
        (
            own.found(id)
         || (
                nProcsWritten == Pstream::nProcs()
             && holders[k] == Pstream::myProcNo()
            )
        )
        {
            lastSigmaB_.emplace(id, std::make_pair(meshes[k], sigmaB[k]));
            if (hasMoments[k])
            {
                lastMoments_.emplace
                (
                    id, bodyMoments(dipoles[k], quadrupoles[k])
                );
            }
        }
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

template<class CloudType>
Foam::BemNearField<CloudType>::BemNearField
(
    const dictionary& dict,
    CloudType& owner
)
:
    NearFieldModel<CloudType>(dict, owner),
    dipoles_(dict, owner, 4),
    clusterGap_
    (
        getCheckedOrDefault<scalar>
        (
            dict, "clusterGap", 1,
            [](const scalar g) { return g >= 0 && std::isfinite(g); },
            ": finite and >= 0 (in units of the smaller semi-axis of a pair)"
        )
    ),
    nPatches_
    (
        getCheckedOrDefault<label>
        (
            dict, "nPatches", 1200,
            [](const label n) { return n >= 8; },
            ": >= 8 (patches per parcel)"
        )
    ),
    isolated_
    (
        dict.template lookupOrDefault<word>("isolated", "inducedDipole")
    ),
    solveInterval_
    (
        getCheckedOrDefault<label>
        (
            dict, "solveInterval", 1,
            [](const label n) { return n >= 1; },
            ": >= 1 (time steps between BEM solves)"
        )
    ),
    // Given in MB, finite in bytes as well
    meshCacheBytes_
    (
        1048576*getCheckedOrDefault<scalar>
        (
            dict, "meshCache", 2000,
            [](const scalar mb) { return mb > 0 && std::isfinite(1048576*mb); },
            ": > 0 (MB of meshes and factorised blocks kept per processor)"
        )
    ),
    multipoleNeighbours_
    (
        dict.template lookupOrDefault<word>("neighbours", "multipoles")
     == "multipoles"
    ),
    controls_
    (
        [&dict]()
        {
            dictionary solverDict(dict.subOrEmptyDict("solver"));
            if (!solverDict.found("tolerance"))
            {
                // Forces to ~1e-6: well below the mesh error, and smooth
                // in time for the leapfrog
                solverDict.add("tolerance", 1e-6);
            }
            return bemSolverControls::read(solverDict);
        }()
    ),
    stats_(),
    gmresIterationsTotal_(0),
    dipoleTime_(0),
    clusterTime_(0),
    setupTime_(0),
    remeshOffset_(0),
    stateRead_(false)
{
    const word neighbours
    (
        dict.template lookupOrDefault<word>("neighbours", "multipoles")
    );
    if (neighbours != "multipoles" && neighbours != "pointCharges")
    {
        FatalIOErrorInFunction(dict)
            << "Entry neighbours " << neighbours << " in "
            << dict.name().c_str() << " is not one of: multipoles"
            << " pointCharges" << exit(FatalIOError);
    }
    if (isolated_ != "inducedDipole" && isolated_ != "none")
    {
        FatalIOErrorInFunction(dict)
            << "Entry isolated " << isolated_ << " in " << dict.name().c_str()
            << " is not one of: inducedDipole none" << exit(FatalIOError);
    }
    Info<< "    BEM clusters: surface gaps below " << clusterGap_
        << " x the smaller semi-axis, " << nPatches_ << " patches per parcel,"
        << " isolated parcels: " << isolated_ << ", parcels near a cluster: "
        << neighbours << endl;

    // The surface meshes are placed by the parcels' orientations,
    // spheres' included: their patches turn with the surface
    owner.integrateSphereOrientation(typeName);
}


template<class CloudType>
Foam::BemNearField<CloudType>::BemNearField
(
    const BemNearField<CloudType>& nf
)
:
    NearFieldModel<CloudType>(nf),
    dipoles_(nf.dipoles_),
    clusterGap_(nf.clusterGap_),
    nPatches_(nf.nPatches_),
    isolated_(nf.isolated_),
    solveInterval_(nf.solveInterval_),
    meshCacheBytes_(nf.meshCacheBytes_),
    multipoleNeighbours_(nf.multipoleNeighbours_),
    controls_(nf.controls_),
    stats_(),
    gmresIterationsTotal_(0),
    dipoleTime_(0),
    clusterTime_(0),
    setupTime_(0),
    remeshOffset_(0),
    stateRead_(false)
{}


// * * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * //

template<class CloudType>
Foam::DynamicList<Foam::labelPair>
Foam::BemNearField<CloudType>::clusterLinks
(
    const pointField& xh,
    const tensorField& Rh,
    const vectorField& Sh,
    const scalarField& Kh,
    const scalarField& keyh,
    const scalar rCut,
    const scalar kappa0
) const
{
    // A link across processors is seen by both (each end lies in the
    // other's halo); the gap is computed with the pair in id order, so
    // that both decide alike to the last bit
    DynamicList<labelPair> links;
    if (rCut > 0)
    {
        forPairsWithinCutoff
        (
            xh, xh, rCut, 0,
            [&](const label a, const label b, const vector&, const scalar r2)
            {
                if (a >= b || (Kh[a] == kappa0 && Kh[b] == kappa0))
                {
                    return;
                }
                const label i = keyh[a] < keyh[b] ? a : b;
                const label j = i == a ? b : a;
                const scalar g = bemNearFieldDetail::centreLineGap
                (
                    Sh[i], Rh[i], Sh[j], Rh[j], xh[i] - xh[j], r2
                );
                if (g < clusterGap_*min(cmptMin(Sh[a]), cmptMin(Sh[b])))
                {
                    links.append(labelPair(a, b));
                }
            }
        );
    }
    return links;
}


template<class CloudType>
Foam::boolList Foam::BemNearField<CloudType>::nearClusters
(
    const pointField& x,
    const tensorField& R,
    const vectorField& S,
    const scalarField& K,
    const scalarField& keys,
    const scalar kappa0,
    scalar& dMax,
    scalarField& clusterKey,
    labelList& solver,
    scalar& reach
)
{
    using namespace bemNearFieldDetail;

    // The reach of a close pair (as formClusters searches them) and the
    // near-field radius, over all processors
    scalar sMax = 0;
    dMax = 0;
    forAll(S, k)
    {
        sMax = max(sMax, cmptMax(S[k]));
        if (K[k] != kappa0)
        {
            dMax = max(dMax, 2*cmptMax(S[k]));
        }
    }
    reduce(sMax, maxOp<scalar>());
    reduce(dMax, maxOp<scalar>());
    const scalar rCut = sMax*(2 + clusterGap_);
    const scalar rNear = multipoleNeighbours_ ? dipoles_.rNearFor(dMax) : 0;

    // This processor's parcels and the others' within reach of its box,
    // and their copies through the cyclic patches
    const polyMesh& mesh = this->owner().mesh();
    const processorHalo halo
    (
        processorHalo::processorBoxes(mesh),
        x,
        max(rCut, rNear),
        processorHalo::cyclicTranslations(mesh),
        true
    );
    const pointField& xh = halo.points();
    const label n = x.size();
    const label nh = xh.size();
    tensorField Rh(R);
    vectorField Sh(S);
    scalarField Kh(K);
    scalarField keyh(keys);
    halo.gather(Rh);
    halo.gather(Sh);
    halo.gather(Kh);
    halo.gather(keyh);

    // Members: a close partner (the test of formClusters); each member's
    // cluster: the smallest id key of its component, the processor of that
    // member and its position
    const DynamicList<labelPair> links
    (
        clusterLinks(xh, Rh, Sh, Kh, keyh, rCut, kappa0)
    );
    scalarField key(nh, -1);
    labelList owner(nh, -1);
    pointField xMin(xh);
    labelComponents(halo, links, keyh, n, key, owner, xMin);
    clusterKey = SubField<scalar>(key, n);
    solver = SubList<label>(owner, n);
    reach = 0;
    for (label i = 0; i < n; ++i)
    {
        if (key[i] >= 0)
        {
            reach = max(reach, mag(x[i] - xMin[i]));
        }
    }
    reduce(reach, maxOp<scalar>());
    reach += rNear;

    // Needed: the members and the parcels within rNear of one
    List<bool> member(nh, false);
    forAll(key, e)
    {
        member[e] = key[e] >= 0;
    }
    halo.updateHalo(member);
    boolList needed(SubList<bool>(member, n));
    if (rNear > 0)
    {
        forPairsWithinCutoff
        (
            xh, xh, rNear, 0,
            [&](const label a, const label b, const vector&, const scalar)
            {
                if (member[b] && a < n)
                {
                    needed[a] = true;
                }
                if (member[a] && b < n)
                {
                    needed[b] = true;
                }
            }
        );
    }
    return needed;
}


template<class CloudType>
void Foam::BemNearField<CloudType>::gatherParcels
(
    const scalar kappa0,
    gatheredParcels& gp
)
{
    const CloudType& cloud = this->owner();
    const label n = cloud.size();
    gp.kC =
        1/(4*constant::mathematical::pi
           *pairwiseCoulomb::vacuumPermittivity*kappa0);

    // Geometry and charges of this processor's parcels
    pointField myX(n);
    tensorField myR(n);
    vectorField myS(n);
    scalarField myQ(n);
    scalarField myK(n);
    scalarField myKey(n);
    List<labelPair> myId(n);
    label i = 0;
    for (const auto& p : cloud)
    {
        myX[i] = p.centre();
        myR[i] = p.orientation().R();
        myS[i] = p.semiAxes();
        myQ[i] = p.q();
        myK[i] = p.epsilonR();
        myId[i] = labelPair(p.origProc(), p.origId());
        myKey[i] = idKey(p.origProc(), p.origId());
        ++i;
    }
    // Only the parcels in or near clusters enter the cluster solves: each
    // processor marks its own from a halo, and the solvers receive those
    // within reach of their boxes (a second halo, of those only)
    scalarField myClusterKey;
    labelList mySolver;
    scalar reach = 0;
    const boolList needed
    (
        nearClusters
        (
            myX, myR, myS, myK, myKey, kappa0, gp.dMax,
            myClusterKey, mySolver, reach
        )
    );
    DynamicList<label> sel;
    forAll(needed, k)
    {
        if (needed[k])
        {
            sel.append(k);
        }
    }
    gp.sel.transfer(sel);
    const List<vector>& cyclic =
        processorHalo::cyclicTranslations(cloud.mesh());
    gp.halo.reset
    (
        new processorHalo
        (
            processorHalo::processorBoxes(cloud.mesh()),
            gp.own(myX),
            // the halo takes points within the range of a box: a margin
            // for round-off at its edge
            reach*(1 + 1e-9) + SMALL,
            cyclic,
            true
        )
    );
    const processorHalo& halo = *gp.halo;
    // The processors near this one: a cluster solved here was last solved
    // by one of them (its smallest member then in their box)
    gp.nearProcs = bemNearFieldDetail::nearProcessors
    (
        processorHalo::processorBoxes(cloud.mesh()), 2*reach, cyclic
    );
    gp.x = halo.points();
    gp.R = gp.own(myR);
    gp.S = gp.own(myS);
    gp.q = gp.own(myQ);
    gp.K = gp.own(myK);
    gp.clusterKey = gp.own(myClusterKey);
    gp.solver = gp.own(mySolver);
    List<labelPair> ids(UIndirectList<labelPair>(myId, gp.sel));
    halo.gather(gp.R);
    halo.gather(gp.S);
    halo.gather(gp.q);
    halo.gather(gp.K);
    halo.gather(gp.clusterKey);
    halo.gather(gp.solver);
    halo.gather(ids);
    gp.ids.setSize(2*ids.size());
    forAll(ids, k)
    {
        gp.ids[2*k] = ids[k].first();
        gp.ids[2*k + 1] = ids[k].second();
    }
    stats_.nGathered = returnReduce(gp.sel.size(), sumOp<label>());
    stats_.nCopies =
        returnReduce(halo.size() - halo.nLocal(), sumOp<label>());
    stats_.nParcels = returnReduce(n, sumOp<label>());
    gp.gathered.setSize(n);
    gp.gathered = -1;
    forAll(gp.sel, k)
    {
        gp.gathered[gp.sel[k]] = k;
    }
    gp.order = this->idOrder(gp.ids);
    gp.rank.setSize(gp.x.size());
    forAll(gp.order, k)
    {
        gp.rank[gp.order[k]] = k;
    }
}


template<class CloudType>
void Foam::BemNearField<CloudType>::nearestLinked
(
    const gatheredParcels& gp,
    const scalar kappa0,
    labelList& nearest,
    scalarField& nearestGap
) const
{
    const label N = gp.x.size();
    const pointField& x = gp.x;
    const tensorField& R = gp.R;
    const vectorField& S = gp.S;
    const scalarField& K = gp.K;
    const labelList& rank = gp.rank;

    // A linked pair is in one cluster: the members of the clusters solved
    // here have all their partners among the gathered parcels
    scalar rCut = 0;
    for (label k = 0; k < N; ++k)
    {
        rCut = max(rCut, cmptMax(S[k])*(2 + clusterGap_));
    }
    nearest.setSize(N);
    nearest = -1;
    nearestGap.setSize(N);
    nearestGap = GREAT;
    if (N > 1 && rCut > 0)
    {
        forPairsWithinCutoff
        (
            x, x, rCut, 0,
            [&](const label a, const label b, const vector&, const scalar r2)
            {
                if (a >= b || (K[a] == kappa0 && K[b] == kappa0))
                {
                    return;
                }
                // In id order (as nearClusters): the same bits on every
                // processor
                const label i = rank[a] < rank[b] ? a : b;
                const label j = i == a ? b : a;
                const scalar g = bemNearFieldDetail::centreLineGap
                (
                    S[i], R[i], S[j], R[j], x[i] - x[j], r2
                );
                const scalar aMin = min(cmptMin(S[a]), cmptMin(S[b]));
                if (g < clusterGap_*aMin)
                {
                    if (g < nearestGap[a] || (g == nearestGap[a] && rank[b] < rank[nearest[a]]))
                    {
                        nearestGap[a] = g;
                        nearest[a] = b;
                    }
                    if (g < nearestGap[b] || (g == nearestGap[b] && rank[a] < rank[nearest[b]]))
                    {
                        nearestGap[b] = g;
                        nearest[b] = a;
                    }
                }
            }
        );
    }
}


template<class CloudType>
void Foam::BemNearField<CloudType>::formClusters
(
    const gatheredParcels& gp,
    const scalar kappa0,
    clusterSet& cs
) const
{
    using namespace bemNearFieldDetail;

    const label N = gp.x.size();
    const pointField& x = gp.x;
    nearestLinked(gp, kappa0, cs.nearest, cs.nearestGap);

    // Clusters by key (the smallest member id: their sorted order), the
    // members in sorted order; those solved here first, then one index
    // for each cluster solved elsewhere
    std::map<scalar, DynamicList<label>> mine;
    std::map<scalar, label> elsewhere;
    for (label k = 0; k < N; ++k)
    {
        const label g = gp.order[k];
        if (gp.clusterKey[g] < 0)
        {
            continue;
        }
        if (gp.solver[g] == Pstream::myProcNo())
        {
            mine[gp.clusterKey[g]].append(g);
        }
        else
        {
            elsewhere.emplace(gp.clusterKey[g], 0);
        }
    }
    cs.members.clear();
    cs.clusters.setSize(mine.size());
    cs.clusterOf.setSize(N);
    cs.clusterOf = -1;
    // Across cyclic patches a member may be here more than once (itself
    // and its copies, adjacent in id order): the instance nearest to the
    // cluster's smallest member, which is this processor's own, solves;
    // the others count as members of a cluster solved elsewhere
    DynamicList<label> otherInstances;
    label c = 0;
    for (auto& entry : mine)
    {
        const DynamicList<label>& all = entry.second;
        label anchor = -1;
        for (const label g : all)
        {
            const labelPair id(gp.id(g));
            if
            (
                g < gp.halo->nLocal()
             && idKey(id.first(), id.second()) == entry.first
            )
            {
                anchor = g;
            }
        }
        if (anchor < 0)
        {
            FatalErrorInFunction
                << "BEM cluster " << entry.first << " to be solved here "
                << "without its smallest member" << abort(FatalError);
        }
        DynamicList<label> members(all.size());
        forAll(all, k)
        {
            const label g = all[k];
            if
            (
                members.size()
             && gp.id(members.last()) == gp.id(g)
            )
            {
                if
                (
                    magSqr(x[g] - x[anchor])
                  < magSqr(x[members.last()] - x[anchor])
                )
                {
                    otherInstances.append(members.last());
                    members.last() = g;
                }
                else
                {
                    otherInstances.append(g);
                }
                continue;
            }
            members.append(g);
        }
        for (const label g : members)
        {
            cs.clusterOf[g] = c;
        }
        cs.clusters[c++].transfer(members);
    }
    for (auto& entry : elsewhere)
    {
        entry.second = c++;
    }
    for (const label g : otherInstances)
    {
        cs.clusterOf[g] = c++;
    }
    for (label g = 0; g < N; ++g)
    {
        if (gp.clusterKey[g] >= 0)
        {
            cs.members.insert(gp.id(g));
            if (cs.clusterOf[g] < 0)
            {
                cs.clusterOf[g] = elsewhere.at(gp.clusterKey[g]);
            }
        }
    }
}


template<class CloudType>
void Foam::BemNearField<CloudType>::setNeighbourMultipoles
(
    const gatheredParcels& gp,
    clusterSet& cs
)
{
    // Parcels near each cluster (centre within the near-field radius of a
    // member's) and what they see of each other beyond point charges, as
    // multipoles (pointMultipole): a member of another cluster its charge
    // as of its last solve (carried in the body frame), any other parcel
    // its free charge (uniform over its surface: a quadrupole) and its
    // induced dipole. Members see them at their patches in the BEM; the
    // others get the reaction (Newton's third law between the patch
    // charges and the multipole) and see the members' dipoles and
    // quadrupoles in their dipole solve.
    const label N = gp.x.size();
    const label nC = cs.clusters.size();
    const pointField& x = gp.x;
    const tensorField& R = gp.R;
    const labelList& clusterOf = cs.clusterOf;
    cs.neighbours.assign(nC, std::vector<label>());
    cs.multipoles.setSize(N);
    cs.Qfree.setSize(N);
    cs.Qfree = Zero;
    if (!multipoleNeighbours_)
    {
        return;
    }

    // The members' last moments, from their last solvers
    DynamicList<labelPair> memberIds;
    forAll(clusterOf, g)
    {
        if (clusterOf[g] >= 0)
        {
            memberIds.append(gp.id(g));
        }
    }
    const momentsMap last
    (
        bemNearFieldDetail::fetchHeld(lastMoments_, memberIds, gp.nearProcs)
    );

    std::vector<std::set<label>> near(nC);
    if (nC)
    {
        forPairsWithinCutoff
        (
            x, x, dipoles_.rNearFor(gp.dMax), 0,
            [&](const label a, const label b, const vector&, const scalar)
            {
                if (a < b && clusterOf[a] != clusterOf[b])
                {
                    if (clusterOf[a] >= 0 && clusterOf[a] < nC)
                    {
                        near[clusterOf[a]].insert(gp.rank[b]);
                    }
                    if (clusterOf[b] >= 0 && clusterOf[b] < nC)
                    {
                        near[clusterOf[b]].insert(gp.rank[a]);
                    }
                }
            }
        );
    }
    for (label c = 0; c < nC; ++c)
    {
        for (const label r : near[c])
        {
            cs.neighbours[c].push_back(gp.order[r]);
        }
    }
    forAll(cs.multipoles, g)
    {
        pointMultipole& m = cs.multipoles[g];
        m.x0 = x[g];
        m.q = gp.q[g];
        cs.Qfree[g] = gp.q[g]*transform(R[g], unitQuadrupole(gp.S[g]));
        const auto iter =
            clusterOf[g] < 0 ? last.end() : last.find(gp.id(g));
        if (iter != last.end())
        {
            m.p = R[g] & iter->second.first;
            m.Q = transform(R[g], iter->second.second);
        }
        else
        {
            m.Q = cs.Qfree[g];
        }
    }

    // The members' dipoles and quadrupoles at the other parcels near
    // their clusters (their charges are the far field's), summed to the
    // parcels' processors
    const scalar kC = gp.kC;
    vectorField Emembers(N, Zero);
    for (label c = 0; c < nC; ++c)
    {
        for (const label j : cs.neighbours[c])
        {
            if (clusterOf[j] < 0)
            {
                for (const label h : cs.clusters[c])
                {
                    pointMultipole m(cs.multipoles[h]);
                    m.q = 0;
                    Emembers[j] += kC*m.fieldOverK(x[j]);
                }
            }
        }
    }
    gp.halo->sumToOwners(Emembers);
    label i = 0;
    for (auto& p : this->owner())
    {
        const label g = gp.gathered[i++];
        if (g >= 0)
        {
            p.E() += Emembers[g];
        }
    }
}


template<class CloudType>
void Foam::BemNearField<CloudType>::memberMeshes
(
    const gatheredParcels& gp,
    const clusterSet& cs,
    const labelUList& mem,
    const boundChargeMap& known,
    labelList& shapes,
    tensorField& poses
)
{
    using namespace bemNearFieldDetail;

    const pointField& x = gp.x;
    const tensorField& R = gp.R;
    const vectorField& S = gp.S;
    shapes.setSize(mem.size());
    poses.setSize(mem.size());
    forAll(mem, m)
    {
        const label g = mem[m];
        const label nb = cs.nearest[g];
        const vector u = (x[nb] - x[g])/mag(x[nb] - x[g]);
        const scalar aMin = min(cmptMin(S[g]), cmptMin(S[nb]));
        // Grading towards the neighbour, measured against the exact
        // two-sphere force (radii 1:1, 1:2, 1:5, epsilonR 2-1000,
        // gaps 0.05-0.5 a): lambda = (0.5 + 0.5 rho^2) sqrt(g/a),
        // rho = a/a_other <= 1 the size ratio of the pair, in
        // [0.1, 1] and rounded down to a power of 2^(-1/4) (meshes
        // reused); patches in proportion to the member's size over
        // the pair's smaller (its gap region is ~sqrt(g a) wide), at
        // most the largest block the preconditioner factorises
        const scalar rho = aMin/max(cmptMin(S[g]), cmptMin(S[nb]));
        const scalar lam0 = min
        (
            max
            (
                (0.5 + 0.5*sqr(rho))
               *Foam::sqrt(max(cs.nearestGap[g], scalar(0))/aMin),
                0.1
            ),
            1.0
        );
        const scalar lambda = Foam::pow
        (
            2.0,
            -0.25*std::ceil(-4*Foam::log(lam0)/Foam::log(2.0) - 1e-9)
        );
        const label nP = min
        (
            label(std::round(nPatches_*cmptMin(S[g])/aMin)),
            max(nPatches_, controls_.maxPreconditionerPatches)
        );
        const bool sphere = cmptMin(S[g]) == cmptMax(S[g]);
        // Hysteresis: a member keeps its last mesh while that is at
        // most one grading level finer than its gap asks for and (an
        // ellipsoid) graded within 0.3 rad of the neighbour's
        // direction (the 64 directions are ~0.45 rad apart), so that
        // a gap or a direction oscillating about a level's edge does
        // not remesh (and re-solve) every step
        const auto last = known.find(gp.id(g));
        bool keep = false;
        if (last != known.end())
        {
            const meshKey& k = last->second.first;
            keep =
                k[0] == S[g].x() && k[1] == S[g].y() && k[2] == S[g].z()
             && k[5] == nP
             && k[4] <= lambda*(1 + 1e-9)
             && lambda <= k[4]*Foam::pow(2.0, 0.25)*(1 + 1e-9);
            if (keep && !sphere && k[3] >= 0)
            {
                const vector dir = fibonacciDirection
                (
                    std::lround(k[3]), nFocusDirections
                );
                keep = (dir & (R[g].T() & u)) > Foam::cos(0.3);
            }
        }
        shapes[m] =
            keep
          ? shapeOf(last->second.first)
          : sphere
          ? shapeFor(S[g], vector(1, 0, 0), lambda, nP)
          : shapeFor(S[g], R[g].T() & u, lambda, nP);
        poses[m] = sphere ? rotationFromX(u) : R[g];
        selfEnergy(shapes[m], gp.K[g]);
    }
}


template<class CloudType>
Foam::scalar Foam::BemNearField<CloudType>::externalFields
(
    const gatheredParcels& gp,
    const clusterSet& cs,
    const label clusterI,
    const vectorField& E,
    const scalar rDipole2,
    const ElectrostaticsModel<CloudType>& farField,
    vectorField& Eext
) const
{
    // External field of each member: everything but the cluster's own
    // charges; the far field's energy of the pairs inside, q_i
    // E_q,j.r_ij (a Coulomb pair), is taken out of the books as well
    // (returned)
    const labelUList& mem = cs.clusters[clusterI];
    const pointField& x = gp.x;
    const scalarField& q = gp.q;
    Eext.setSize(mem.size());
    scalar Uout = 0;
    forAll(mem, m)
    {
        const label g = mem[m];
        Eext[m] = E[g];
        for (const label h : mem)
        {
            if (h != g)
            {
                const vector Eh = farField.pointChargeField(x[g], x[h], q[h]);
                Eext[m] -= Eh;
                Uout += 0.5*q[g]*(Eh & (x[g] - x[h]));
            }
        }
    }

    // The parcels near the cluster are seen as multipoles at the patches,
    // in place of what E holds of them at the centres (the far field's
    // point charge, the dipole solve's dipole field)
    const scalar kC = gp.kC;
    for (const label j : cs.neighbours[clusterI])
    {
        forAll(mem, m)
        {
            const label g = mem[m];
            Eext[m] -= farField.pointChargeField(x[g], x[j], q[j]);
            if (cs.clusterOf[j] < 0 && magSqr(x[g] - x[j]) < rDipole2)
            {
                pointMultipole d;
                d.x0 = x[j];
                d.p = cs.multipoles[j].p;
                Eext[m] -= kC*d.fieldOverK(x[g]);
            }
        }
    }
    return Uout;
}


template<class CloudType>
Foam::label Foam::BemNearField<CloudType>::setUpCluster
(
    const gatheredParcels& gp,
    const labelUList& mem,
    const labelList& meshes,
    const tensorField& poses,
    const vectorField& Eext,
    const boundChargeMap& known,
    const bemSolver::fieldFunction& Enear
)
{
    // The cluster on the given meshes, GMRES started from each member's
    // last bound charge on the same mesh; returns how many members have
    // one
    bem_->clearParticles();
    bem_->setExternalField(Enear);
    label carried = 0;
    forAll(mem, m)
    {
        const label g = mem[m];
        const label k =
            bem_->addParticle(meshes[m], gp.x[g], poses[m], gp.K[g], gp.q[g]);
        bem_->setParticleField(k, Eext[m]);
        const auto last = known.find(gp.id(g));
        if (last != known.end() && last->second.first == shapeKeys_[meshes[m]])
        {
            bem_->setInitialGuess(k, last->second.second);
            ++carried;
        }
    }
    return carried;
}


template<class CloudType>
void Foam::BemNearField<CloudType>::runCluster
(
    const label nMembers,
    const bool solve
)
{
    const bemSolver::solveInfo& info = solve ? bem_->solve() : bem_->evaluate();
    stats_.nSolved += solve;
    if (!info.converged)
    {
        FatalErrorInFunction
            << "BEM cluster of " << nMembers << " parcels not"
            << " converged: relative residual " << info.residual
            << " after " << info.iterations << " GMRES iterations ("
            << this->dict().name().c_str() << "/solver: tolerance "
            << controls_.tolerance << ", maxIter " << controls_.maxIter
            << ")" << exit(FatalError);
    }
    stats_.gmresIterations += info.iterations;
    setupTime_ += info.setupTime;
    stats_.gmresResidual = max(stats_.gmresResidual, info.residual);
}


template<class CloudType>
Foam::List<Foam::scalarField>
Foam::BemNearField<CloudType>::memberCharges(const label nMembers) const
{
    List<scalarField> c(nMembers);
    forAll(c, m)
    {
        c[m] = bem_->mediumCharges(m);
    }
    return c;
}


template<class CloudType>
Foam::scalar Foam::BemNearField<CloudType>::clusterEnergy
(
    const gatheredParcels& gp,
    const clusterSet& cs,
    const label clusterI,
    const labelList& meshes,
    const vectorField& Eext,
    const scalar Uout
) const
{
    // Energy (Eq. 51) beyond the far field's, of the last solve: the
    // cluster's minus its members alone minus the far field's internal
    // pairs, and the bound charge in the external field, -1/2 p_b.E_ext
    const labelUList& mem = cs.clusters[clusterI];
    const pointField& x = gp.x;
    const scalarField& q = gp.q;
    scalar U = bem_->energy() - Uout;
    forAll(mem, m)
    {
        const label g = mem[m];
        U -= sqr(q[g])*selfEnergy_.at(std::make_pair(meshes[m], gp.K[g]));
        U -= 0.5*(bem_->boundDipole(m) & Eext[m]);
    }
    // The neighbours (linear media: 1/2 sum of free charge x potential,
    // Jackson, Classical Electrodynamics, Sec. 4.7): with f the free and
    // b the bound charges, U(fA, fj) + 1/2 U(fA, bj) + 1/2 U(bA, fj),
    // less the far field's point-charge pairs. An isolated parcel's
    // dipole has its 1/2 U(bj, A) in the dipole solve's energy; a pair of
    // clusters is counted half from each side
    const scalar kC = gp.kC;
    const List<scalarField> cMem(memberCharges(mem.size()));
    for (const label j : cs.neighbours[clusterI])
    {
        const bool member = cs.clusterOf[j] >= 0;
        const scalar w = member ? 0.5 : 1;
        pointMultipole fj, bj;
        fj.x0 = bj.x0 = x[j];
        fj.q = q[j];
        fj.Q = cs.Qfree[j];
        if (member)
        {
            bj.p = cs.multipoles[j].p;
            bj.Q = cs.multipoles[j].Q - cs.Qfree[j];
        }
        forAll(mem, m)
        {
            const scalarField& a = bem_->mesh(meshes[m]).areas();
            const scalarField& sf = bem_->sigmaF(m);
            const scalarField& c = cMem[m];
            const SubList<point> y(bem_->centres(m));
            scalar Um = 0;
            forAll(c, k)
            {
                const scalar f = a[k]*sf[k];
                const scalar phiF = fj.potentialOverK(y[k]);
                Um += f*phiF + 0.5*(c[k] - f)*phiF;
                if (member)
                {
                    Um += 0.5*f*bj.potentialOverK(y[k]);
                }
            }
            const label h = mem[m];
            U += w*kC*(Um - q[h]*q[j]/mag(x[h] - x[j]));
            if (!member)
            {
                // The dipole solve's -1/2 p_j . E holds the member's
                // bound moments too (they induce p_j), but the energy
                // has no bound-bound term
                pointMultipole bh(cs.multipoles[h]);
                bh.q = 0;
                bh.Q -= cs.Qfree[h];
                U += 0.5*kC*(cs.multipoles[j].p & bh.fieldOverK(x[j]));
            }
        }
    }
    return U;
}


template<class CloudType>
void Foam::BemNearField<CloudType>::addReactions
(
    const gatheredParcels& gp,
    const clusterSet& cs,
    const label clusterI,
    const scalar rDipole2,
    const ElectrostaticsModel<CloudType>& farField,
    clusterResults& res
) const
{
    // Reaction on the other parcels near the cluster: minus the force and
    // moment of their multipoles on the members' patch charges, in place
    // of the far field's point-charge pair force, the dipole solve's
    // dipole-charge pair force and the torque p x E of what their E holds
    // of the members
    const labelUList& mem = cs.clusters[clusterI];
    const pointField& x = gp.x;
    const scalarField& q = gp.q;
    const scalar kC = gp.kC;
    const List<scalarField> cMem(memberCharges(mem.size()));
    for (const label j : cs.neighbours[clusterI])
    {
        if (cs.clusterOf[j] >= 0)
        {
            continue;
        }
        const pointMultipole& mj = cs.multipoles[j];
        forAll(mem, m)
        {
            const scalarField& c = cMem[m];
            const SubList<point> y(bem_->centres(m));
            forAll(c, k)
            {
                const vector f = (kC*c[k])*mj.fieldOverK(y[k]);
                res.Fout[j] -= f;
                res.Mout[j] -= (y[k] - x[j]) ^ f;
            }
            const label h = mem[m];
            const vector Eq = farField.pointChargeField(x[j], x[h], q[h]);
            res.Fout[j] -= q[j]*Eq;
            const vector r = x[j] - x[h];
            const scalar r2 = magSqr(r);
            if (r2 < rDipole2)
            {
                const scalar ir3 = 1/(r2*Foam::sqrt(r2));
                res.Fout[j] -=
                    mj.p & ((kC*q[h]*ir3)*(symmTensor::I - 3*sqr(r)/r2));
            }
            pointMultipole mh(cs.multipoles[h]);
            mh.q = 0;
            res.Mout[j] -= mj.p ^ (Eq + kC*mh.fieldOverK(x[j]));
        }
    }
}


template<class CloudType>
void Foam::BemNearField<CloudType>::solveCluster
(
    const gatheredParcels& gp,
    const clusterSet& cs,
    const label clusterI,
    const boundChargeMap& known,
    const vectorField& E,
    const scalar rDipole2,
    const bool solveNow,
    const ElectrostaticsModel<CloudType>& farField,
    clusterResults& res
)
{
    const labelUList& mem = cs.clusters[clusterI];
    labelList shapes;
    tensorField poses;
    memberMeshes(gp, cs, mem, known, shapes, poses);
    vectorField Eext;
    const scalar Uout =
        externalFields(gp, cs, clusterI, E, rDipole2, farField, Eext);

    // The neighbours' multipoles at the patches
    std::vector<pointMultipole> sources;
    for (const label j : cs.neighbours[clusterI])
    {
        sources.push_back(cs.multipoles[j]);
    }
    const scalar kC = gp.kC;
    const bemSolver::fieldFunction Enear =
        sources.empty()
      ? bemSolver::fieldFunction()
      : [&sources, kC](const point& y)
        {
            vector E(Zero);
            for (const pointMultipole& s : sources)
            {
                E += s.fieldOverK(y);
            }
            return vector(kC*E);
        };

    // Members whose mesh changed since the last step: the energy on the
    // old meshes at this configuration too, so that the books carry the
    // difference across the mesh change (a discretisation jump, not work
    // of the forces)
    labelList oldShapes(shapes);
    bool remeshed = false;
    forAll(mem, m)
    {
        const label g = mem[m];
        const auto last = known.find(gp.id(g));
        if (last != known.end() && last->second.first != shapeKeys_[shapes[m]])
        {
            oldShapes[m] = shapeOf(last->second.first);
            selfEnergy(oldShapes[m], gp.K[g]);
            remeshed = true;
        }
    }
    if (remeshed)
    {
        setUpCluster(gp, mem, oldShapes, poses, Eext, known, Enear);
        bem_->setWithEnergy(true);
        runCluster(mem.size(), true);
        res.remeshDelta += clusterEnergy(gp, cs, clusterI, oldShapes, Eext, Uout);
    }

    // Between solves (solveInterval) the bound charge is carried in the
    // members' body frames, when every member has one on its mesh. The
    // energy (its potential sums: a third of the cost of a step between
    // solves) only for the log and across a mesh change
    const label carried =
        setUpCluster(gp, mem, shapes, poses, Eext, known, Enear);
    const bool withEnergy = remeshed || this->owner().logThisStep();
    bem_->setWithEnergy(withEnergy);
    runCluster(mem.size(), solveNow || carried < mem.size());
    if (withEnergy)
    {
        const scalar U = clusterEnergy(gp, cs, clusterI, shapes, Eext, Uout);
        if (remeshed)
        {
            res.remeshDelta -= U;
        }
        stats_.energy += U;
    }
    forAll(mem, m)
    {
        const label g = mem[m];
        res.F[g] = bem_->forces()[m];
        res.M[g] = bem_->torques()[m];
        res.P[g] = bem_->boundDipole(m);
        const pointMultipole mm(bem_->multipole(m));
        const tensor& Rg = gp.R[g];
        res.moments.emplace
        (
            gp.id(g),
            bodyMoments(Rg.T() & mm.p, transform(Rg.T(), mm.Q))
        );
        res.sigmaB.emplace
        (
            gp.id(g),
            std::make_pair(shapeKeys_[shapes[m]], scalarField(bem_->sigmaB(m)))
        );
    }
    addReactions(gp, cs, clusterI, rDipole2, farField, res);
}


template<class CloudType>
Foam::vectorField Foam::BemNearField<CloudType>::gatherFields
(
    const gatheredParcels& gp,
    clusterSet& cs
) const
{
    // The field at every centre after the far field, applied field and
    // isolated dipoles; the isolated parcels' induced dipoles into their
    // multipoles
    const CloudType& cloud = this->owner();
    vectorField myE(cloud.size());
    label i = 0;
    for (const auto& p : cloud)
    {
        myE[i++] = p.E();
    }
    vectorField E(gp.own(myE));
    gp.halo->gather(E);
    if (multipoleNeighbours_)
    {
        i = 0;
        for (const auto& p : cloud)
        {
            myE[i++] = p.dipole();
        }
        vectorField Pd(gp.own(myE));
        gp.halo->gather(Pd);
        forAll(cs.multipoles, g)
        {
            if (cs.clusterOf[g] < 0)
            {
                cs.multipoles[g].p = Pd[g];
            }
        }
    }
    return E;
}


template<class CloudType>
void Foam::BemNearField<CloudType>::solveClusters
(
    const gatheredParcels& gp,
    const clusterSet& cs,
    const vectorField& E,
    const ElectrostaticsModel<CloudType>& farField,
    clusterResults& res
)
{
    // The clusters of this processor (each cluster's inputs are in the
    // order of the parcels' ids, so the result does not depend on which
    // processor solves it); results by gathered index. The last bound
    // charge of the members comes from their last solvers. Isolated parcels'
    // dipoles enter as pair terms within the dipole solve's radius
    const scalar rDipole2 =
        (isolated_ == "inducedDipole" && dipoles_.nPolarisable())
      ? sqr(dipoles_.rNear()) : -1;
    const label N = gp.x.size();
    for (vectorField* f : {&res.F, &res.M, &res.P, &res.Fout, &res.Mout})
    {
        f->setSize(N, Zero);
    }
    DynamicList<labelPair> mine;
    forAll(cs.clusters, c)
    {
        stats_.maxClusterSize = max(stats_.maxClusterSize, cs.clusters[c].size());
        for (const label g : cs.clusters[c])
        {
            mine.append(gp.id(g));
        }
    }
    const boundChargeMap known
    (
        bemNearFieldDetail::fetchHeld(lastSigmaB_, mine, gp.nearProcs)
    );
    const bool solveNow =
        this->owner().db().time().timeIndex() % solveInterval_ == 0;
    forAll(cs.clusters, c)
    {
        solveCluster(gp, cs, c, known, E, rDipole2, solveNow, farField, res);
    }
}


template<class CloudType>
void Foam::BemNearField<CloudType>::shareResults
(
    const gatheredParcels& gp,
    clusterResults& res
)
{
    // Every entry of F, M, P is set by one processor and zero on the
    // others' copies: those sums are exact; a neighbour's reactions from
    // clusters solved on several processors add up
    for (vectorField* f : {&res.F, &res.M, &res.P, &res.Fout, &res.Mout})
    {
        gp.halo->sumToOwners(*f);
    }
    reduce(stats_.maxClusterSize, maxOp<label>());
    reduce(stats_.gmresIterations, sumOp<label>());
    reduce(stats_.gmresResidual, maxOp<scalar>());
    reduce(stats_.energy, sumOp<scalar>());
    reduce(stats_.nSolved, sumOp<label>());
    reduce(res.remeshDelta, sumOp<scalar>());
    remeshOffset_ += res.remeshDelta;
    gmresIterationsTotal_ += stats_.gmresIterations;
    // Each solver keeps what it solved (the next step's solver of a
    // cluster is most often the same processor)
    lastSigmaB_.swap(res.sigmaB);
    usedMoments_.swap(lastMoments_);
    lastMoments_.swap(res.moments);
}


template<class CloudType>
void Foam::BemNearField<CloudType>::applyResults
(
    const gatheredParcels& gp,
    const clusterResults& res
)
{
    // Members in contact with another parcel: chi^(2/5) (Ruan Eq. 44)
    const scalar w = dipoles_.contactWeight();
    label i = 0;
    for (auto& p : this->owner())
    {
        const label g = gp.gathered[i++];
        if (g >= 0 && gp.clusterKey[g] >= 0)
        {
            const bool inContact =
                w != 1 && p.collisionRecords().pairRecords().size();
            stats_.nInContact += inContact;
            p.fE() = (inContact ? w : 1)*res.F[g];
            p.tE() = (inContact ? w : 1)*res.M[g];
            p.dipole() = res.P[g];
        }
        else if (g >= 0)
        {
            p.fE() += res.Fout[g];
            p.tE() += res.Mout[g];
        }
    }
    reduce(stats_.nInContact, sumOp<label>());
}


template<class CloudType>
void Foam::BemNearField<CloudType>::correct
(
    const ElectrostaticsModel<CloudType>& farField
)
{
    CloudType& cloud = this->owner();
    const scalar kappa0 = farField.mediumEpsilonR();

    if (cmptMax(farField.periodicBox()) > 0)
    {
        FatalIOErrorInFunction(this->dict())
            << "nearField type bem in " << this->dict().name().c_str()
            << " does not support periodic far fields yet"
            << exit(FatalIOError);
    }
    if (!bem_)
    {
        bem_.reset(new bemSolver(kappa0, controls_));
        shapeIndex_.clear();
        shapeKeys_.clear();
        shapeLastUse_.clear();
    }
    if (!stateRead_)
    {
        readState();
    }
    const bool writeTime = this->owner().db().time().writeTime();

    gatheredParcels gp;
    gatherParcels(kappa0, gp);
    clusterSet cs;
    formClusters(gp, kappa0, cs);
    setNeighbourMultipoles(gp, cs);

    // Isolated parcels: dipoles (cluster members unpolarisable there) or
    // point charges
    cpuTime timer;
    if (isolated_ == "inducedDipole")
    {
        dipoles_.solveDipoles(farField, cs.members);
        dipoleTime_ += timer.cpuTimeIncrement();
    }
    else
    {
        for (auto& p : cloud)
        {
            p.tE() = Zero;
            p.dipole() = Zero;
        }
    }

    stats_.nClusters = returnReduce(cs.clusters.size(), sumOp<label>());
    stats_.nInClusters = 0;
    forAll(gp.sel, k)
    {
        stats_.nInClusters += gp.clusterKey[k] >= 0;
    }
    reduce(stats_.nInClusters, sumOp<label>());
    stats_.maxClusterSize = 0;
    stats_.gmresIterations = 0;
    stats_.gmresResidual = 0;
    stats_.energy = 0;
    stats_.nSolved = 0;
    stats_.nInContact = 0;
    if (!stats_.nClusters)
    {
        trimCache();
        lastSigmaB_.clear();
        lastMoments_.clear();
        usedMoments_.clear();
        if (writeTime)
        {
            writeState();
        }
        return;
    }

    const vectorField E(gatherFields(gp, cs));
    clusterResults res;
    solveClusters(gp, cs, E, farField, res);
    shareResults(gp, res);
    trimCache();
    reduce(stats_.nShapes, maxOp<label>());
    reduce(stats_.cacheBytes, maxOp<scalar>());
    if (writeTime)
    {
        writeState();
    }
    applyResults(gp, res);
    clusterTime_ += timer.cpuTimeIncrement();
}


template<class CloudType>
void Foam::BemNearField<CloudType>::info() const
{
    if (isolated_ == "inducedDipole")
    {
        dipoles_.info();
    }
    Info<< "    BEM clusters                    = " << stats_.nClusters
        << " (" << stats_.nInClusters << " parcels, largest "
        << stats_.maxClusterSize << "; " << stats_.nSolved << " solved), "
        << stats_.gmresIterations << " GMRES iterations ("
        << gmresIterationsTotal_ << " since the start; residual "
        << stats_.gmresResidual << "), " << stats_.nShapes << " meshes ("
        << std::round(stats_.cacheBytes/1048576) << " MB)" << nl;
    if (dipoles_.contactWeight() != 1)
    {
        Info<< "    BEM members in contact (x chi^0.4) = "
            << stats_.nInContact << nl;
    }
    Info<< "    BEM parcels in or near clusters = " << stats_.nGathered
        << " of " << stats_.nParcels;
    if (Pstream::parRun())
    {
        Info<< " (" << stats_.nCopies << " halo copies on other"
            << " processors)";
    }
    Info<< nl;
    Info<< "    BEM remeshing energy carried    = " << remeshOffset_ << nl;
    Info<< "    CPU time [s] since start        = dipoles " << dipoleTime_
        << ", BEM clusters " << clusterTime_ << " (set-up of meshes and"
        << " blocks " << setupTime_ << ")" << nl;
}


// ************************************************************************* //
