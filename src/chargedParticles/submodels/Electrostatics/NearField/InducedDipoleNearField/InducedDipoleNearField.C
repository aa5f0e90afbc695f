/*---------------------------------------------------------------------------*\
    chargedFoam: charged dielectric particles for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "InducedDipoleNearField.H"
#include "ElectrostaticsModel.H"
#include "inducedDipole.H"
#include "Pstream.H"
#include "processorHalo.H"
#include "keyedPoints.H"
#include "checkedEntry.H"

#include <algorithm>
#include <memory>

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

template<class CloudType>
Foam::vector Foam::InducedDipoleNearField<CloudType>::depolarisationFactors
(
    const vector& semiAxes
) const
{
    const scalar sMax = cmptMax(semiAxes);
    if (cmptMin(semiAxes) == sMax)
    {
        return vector::uniform(1.0/3.0);
    }
    const std::array<scalar, 3> key
    {{semiAxes.x()/sMax, semiAxes.y()/sMax, semiAxes.z()/sMax}};
    auto iter = depolarisation_.find(key);
    if (iter == depolarisation_.end())
    {
        iter = depolarisation_.emplace
        (
            key,
            inducedDipole::depolarisationFactors
            (
                vector(key[0], key[1], key[2])
            )
        ).first;
    }
    return iter->second;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

template<class CloudType>
Foam::InducedDipoleNearField<CloudType>::InducedDipoleNearField
(
    const dictionary& dict,
    CloudType& owner,
    const scalar rNearDiameters
)
:
    NearFieldModel<CloudType>(dict, owner),
    rNearGiven_
    (
        dict.found("rNear") ? getPositive(this->dict(), "rNear") : -1
    ),
    rNearDiameters_(rNearDiameters),
    tolerance_(getPositiveOrDefault(this->dict(), "tolerance", 1e-8)),
    // A label: a count given as 0.5 is an error, not truncated to 0
    maxIter_
    (
        getCheckedOrDefault<label>
        (
            this->dict(), "maxIter", 500,
            [](const label n) { return n >= 1; },
            ": >= 1"
        )
    ),
    contactWeight_
    (
        Foam::pow(owner.constProps().stiffnessRatio(), 0.4)
    ),
    dipoles_(1, tolerance_, maxIter_),
    energy_(0),
    rNear_(rNearGiven_),
    nPolarisable_(0),
    nPairs_(0),
    iterations_(0),
    residual_(0)
{
    Info<< "    Induced dipoles within rNear = "
        << (
               rNearGiven_ > 0
             ? std::string(Foam::name(rNearGiven_)) + " m"
             : std::string(Foam::name(rNearDiameters_))
             + " bounding diameters of the largest polarisable parcel"
           ).c_str()
        << ", tolerance " << tolerance_ << endl;
}


// * * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * //

template<class CloudType>
Foam::label Foam::InducedDipoleNearField<CloudType>::ownParcels
(
    const scalar kappa0,
    const parcelIdSet& excluded,
    pointField& x,
    scalarField& q,
    tensorField& A,
    vectorField& E,
    vectorField& P,
    List<labelPair>& keys,
    scalar& dMax
) const
{
    // This processor's parcels: centres, charges, polarisabilities (zero:
    // not polarisable or excluded), the far field at them, the last
    // dipoles and the ids; returns how many are polarisable
    const CloudType& cloud = this->owner();
    const label n = cloud.size();
    x.setSize(n);
    q.setSize(n);
    A.setSize(n);
    E.setSize(n);
    P.setSize(n);
    keys.setSize(n);
    dMax = 0;
    label nPolar = 0;
    label i = 0;
    for (const auto& p : cloud)
    {
        if (p.epsilonR() < kappa0)
        {
            FatalErrorInFunction
                << "Parcel (origProc " << p.origProc() << ", origId "
                << p.origId() << ") has epsilonR " << p.epsilonR()
                << " below the medium's " << kappa0 << ": the induced-"
                << "dipole near field needs epsilonR >= the far field's"
                << " epsilonR (" << this->dict().name().c_str() << ")"
                << exit(FatalError);
        }
        x[i] = p.centre();
        q[i] = p.q();
        E[i] = p.E();
        P[i] = p.dipole();
        keys[i] = labelPair(p.origProc(), p.origId());
        if
        (
            p.epsilonR() != kappa0
         && !excluded.found(labelPair(p.origProc(), p.origId()))
        )
        {
            A[i] = inducedDipole::polarisability
            (
                p.semiAxes(),
                depolarisationFactors(p.semiAxes()),
                p.orientation().R(),
                p.epsilonR(),
                kappa0
            );
            dMax = max(dMax, 2*cmptMax(p.semiAxes()));
            ++nPolar;
        }
        else
        {
            A[i] = Zero;
        }
        ++i;
    }
    return nPolar;
}


template<class CloudType>
void Foam::InducedDipoleNearField<CloudType>::setNearRadius
(
    const scalar dMax,
    const vector& L
)
{
    rNear_ = rNearFor(dMax);
    if (!(rNear_ >= dMax))
    {
        FatalIOErrorInFunction(this->dict())
            << "Entry rNear = " << rNear_ << " in "
            << this->dict().name().c_str() << " is below the bounding"
            << " diameter " << dMax << " of the largest polarisable parcel:"
            << " pairs in contact would be left out" << exit(FatalIOError);
    }
    const scalar period =
        cmptMax(L) > 0
      ? GREAT
      : processorHalo::shortestCyclicPeriod(this->owner().mesh());
    if (rNear_ > period)
    {
        FatalIOErrorInFunction(this->dict())
            << "Entry rNear = " << rNear_ << " in "
            << this->dict().name().c_str() << " exceeds the cyclic "
            << "period " << period << " of the mesh: it must be at most "
            << period << exit(FatalIOError);
    }
    if (cmptMax(L) > 0 && !(2*rNear_ < cmptMin(L)))
    {
        FatalIOErrorInFunction(this->dict())
            << "Entry rNear = " << rNear_ << " in "
            << this->dict().name().c_str() << " must be below half the"
            << " periodic box edge " << cmptMin(L)
            << (
                   rNearGiven_ > 0
                 ? std::string()
                 : " (the default, " + std::string(Foam::name(rNearDiameters_))
                 + " bounding diameters of the largest polarisable parcel:"
                   " give a smaller one)"
               ).c_str()
            << exit(FatalIOError);
    }
}


template<class CloudType>
std::unique_ptr<Foam::processorHalo>
Foam::InducedDipoleNearField<CloudType>::gatherHalo
(
    const vector& L,
    pointField& x,
    scalarField& q,
    tensorField& A,
    vectorField& E0,
    vectorField& P0,
    List<labelPair>& keys
) const
{
    // In parallel, copies of the other processors' parcels within rNear
    // of this processor's box appended (a halo: every pair of an own
    // parcel is here; through the periodic box's translations if the far
    // field is periodic, the kernel taking the nearest image). Otherwise
    // through the mesh's cyclic patches: their copies appended as well
    // (also in serial)
    const polyMesh& mesh = this->owner().mesh();
    const bool periodic = cmptMax(L) > 0;
    const List<vector> cyclic
    (
        periodic ? List<vector>() : processorHalo::cyclicTranslations(mesh)
    );
    std::unique_ptr<processorHalo> halo;
    if (Pstream::parRun() || cyclic.size())
    {
        halo.reset
        (
            new processorHalo
            (
                processorHalo::processorBoxes(mesh),
                x,
                rNear_,
                periodic ? processorHalo::boxTranslations(L) : cyclic,
                !periodic
            )
        );
        x = halo->points();
        halo->gather(q);
        halo->gather(A);
        halo->gather(E0);
        halo->gather(P0);
        halo->gather(keys);
    }
    return halo;
}


template<class CloudType>
void Foam::InducedDipoleNearField<CloudType>::setContactPairs
(
    const UList<point>& x,
    const UList<labelPair>& keys,
    const labelList& rank
)
{
    // Pairs in contact, from the collision records (Ruan Eq. 44): keys
    // and rank of the own parcels and the halo's copies (the nearest
    // instance: a partner across a cyclic patch is its copy)
    const keyedPoints where(x, keys);
    DynamicList<labelPair> contacts;
    label i = 0;
    for (const auto& p : this->owner())
    {
        const label gi = rank[i];
        for (const auto& record : p.collisionRecords().pairRecords())
        {
            const label j = where.nearest
            (
                labelPair(record.origProcOfOther(), record.origIdOfOther()),
                x[i]
            );
            if (j >= 0)
            {
                contacts.append(labelPair(gi, rank[j]));
            }
        }
        ++i;
    }
    // Every parcel's records name its partners (both sides keep one), so
    // the own parcels' records hold every pair this processor needs
    dipoles_.setPairWeights(contacts, contactWeight_);
}


template<class CloudType>
void Foam::InducedDipoleNearField<CloudType>::storeResults
(
    const labelList& rank,
    const boolList& owned
)
{
    const inducedDipole& dipoles = dipoles_;
    label i = 0;
    for (auto& p : this->owner())
    {
        const label g = rank[i];
        p.E() = dipoles.fields()[g];
        p.fE() += dipoles.forceIncrements()[g];
        p.tE() = dipoles.torques()[g];
        p.dipole() = dipoles.dipoles()[g];
        ++i;
    }

    energy_ = dipoles.externalEnergy();
    // Pairs of the whole cloud: a pair with a copy is on two processors
    scalar nPairs = 0;
    for (const inducedDipole::pair& ij : dipoles.pairs())
    {
        nPairs += 0.5*(owned[ij.i] + owned[ij.j]);
    }
    nPairs_ = label(returnReduce(nPairs, sumOp<scalar>()) + 0.5);
    iterations_ = dipoles.iterations();
    residual_ = dipoles.residual();
}


template<class CloudType>
void Foam::InducedDipoleNearField<CloudType>::solveDipoles
(
    const ElectrostaticsModel<CloudType>& farField,
    const parcelIdSet& excluded
)
{
    CloudType& cloud = this->owner();
    const scalar kappa0 = farField.mediumEpsilonR();
    const label n = cloud.size();

    // This processor's parcels and, in parallel, the halo's copies
    // (gathered below)
    pointField x;
    scalarField q;
    tensorField A;
    vectorField E0;
    vectorField P0;
    List<labelPair> keys;
    scalar dMax = 0;
    label nPolar = ownParcels(kappa0, excluded, x, q, A, E0, P0, keys, dMax);
    reduce(dMax, maxOp<scalar>());
    reduce(nPolar, sumOp<label>());
    nPolarisable_ = nPolar;

    // Nothing polarisable: no dipoles, no torques, the far field stands
    if (nPolar == 0)
    {
        for (auto& p : cloud)
        {
            p.tE() = Zero;
            p.dipole() = Zero;
        }
        energy_ = 0;
        nPairs_ = 0;
        iterations_ = 0;
        residual_ = 0;
        return;
    }
    const vector L(farField.periodicBox());
    setNearRadius(dMax, L);

    const std::unique_ptr<processorHalo> halo
    (
        gatherHalo(L, x, q, A, E0, P0, keys)
    );
    const label N = x.size();
    labelList ids(2*N);
    forAll(keys, k)
    {
        ids[2*k] = keys[k].first();
        ids[2*k + 1] = keys[k].second();
    }
    const labelList order(this->idOrder(ids));
    labelList rank(N);
    forAll(order, k)
    {
        rank[order[k]] = k;
    }
    const pointField xs(x, order);
    const scalarField qs(q, order);
    const tensorField As(A, order);
    const vectorField E0s(E0, order);
    const vectorField P0s(P0, order);
    boolList owned(N);
    forAll(order, k)
    {
        owned[k] = order[k] < n;
    }

    inducedDipole& dipoles = dipoles_;
    dipoles.setMediumPermittivity(kappa0);
    dipoles.setParticles(xs, qs, As, E0s);
    dipoles.countChargeFields(false);
    dipoles.setCutoff(rNear_);
    dipoles.setPeriod(L);
    dipoles.setInitialDipoles(P0s);
    if (halo)
    {
        // The CG on every processor's parcels at once: the copies' entries
        // from their owners before each operator application, dot
        // products summed over the processors
        dipoles.setDistribution
        (
            owned,
            [&](UList<vector>& v)
            {
                List<vector> h(N);
                forAll(order, k)
                {
                    h[order[k]] = v[k];
                }
                halo->updateHalo(h);
                forAll(order, k)
                {
                    if (!owned[k])
                    {
                        v[k] = h[order[k]];
                    }
                }
            },
            [](const scalar v)
            {
                return returnReduce(v, sumOp<scalar>());
            }
        );
    }

    if (contactWeight_ != 1)
    {
        setContactPairs(x, keys, rank);
    }

    dipoles.solve();
    // The communication above refers to this call's halo
    dipoles.setDistribution(boolList(), nullptr, nullptr);

    storeResults(rank, owned);
}


template<class CloudType>
void Foam::InducedDipoleNearField<CloudType>::correct
(
    const ElectrostaticsModel<CloudType>& farField
)
{
    solveDipoles(farField, parcelIdSet());
}


template<class CloudType>
void Foam::InducedDipoleNearField<CloudType>::info() const
{
    Info<< "    Induced dipoles                 = " << nPolarisable_
        << " polarisable, " << nPairs_ << " pairs within rNear " << rNear_
        << " m, " << iterations_ << " CG iterations (residual "
        << residual_ << ")" << nl;
}


// ************************************************************************* //
