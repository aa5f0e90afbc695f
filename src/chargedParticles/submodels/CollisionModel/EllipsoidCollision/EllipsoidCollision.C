/*---------------------------------------------------------------------------*\
    chargedFoam: charged dielectric particles for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "EllipsoidCollision.H"
#include "mathematicalConstants.H"
#include "volFields.H"
#include "PstreamBuffers.H"
#include "mapDistribute.H"
#include "checkedEntry.H"
#include "Enum.H"
#include "hertzOnset.H"
#include "rigidBodyRotation.H"

#include <algorithm>
#include <type_traits>

// * * * * * * * * * * * * * * * Local Functions  * * * * * * * * * * * * * //

namespace
{

//- The record lists of a parcel, to change in place. They belong to the
//  (non-const) parcel; CollisionRecordList only has const accessors.
template<class Records>
auto mutablePairRecords(Records& records)
 -> typename std::decay<decltype(records.pairRecords())>::type&
{
    typedef typename std::decay<decltype(records.pairRecords())>::type list;
    return const_cast<list&>(records.pairRecords());
}

template<class Records>
auto mutableWallRecords(Records& records)
 -> typename std::decay<decltype(records.wallRecords())>::type&
{
    typedef typename std::decay<decltype(records.wallRecords())>::type list;
    return const_cast<list&>(records.wallRecords());
}

} // End anonymous namespace


namespace Foam
{
namespace
{

// The coefficients' maxInteractionDistance [m] (the interaction lists, the
// default skin and the reach checks read it)
scalar maxInteractionDistance(const dictionary& coeffs)
{
    return getPositive(coeffs, "maxInteractionDistance", inputLimits::large);
}

} // End anonymous namespace
} // End namespace Foam


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

template<class CloudType>
void Foam::EllipsoidCollision<CloudType>::makeLaws(const dictionary& coeffs)
{
    const particleMaterials& materials =
        this->owner().constProps().materials();
    const label n = nMaterials_;
    auto youngsModulus = [](const dictionary& d)
    {
        return getPositive(d, "youngsModulus", inputLimits::large);
    };
    auto poissonsRatio = [](const dictionary& d)
    {
        return getChecked<scalar>
        (
            d, "poissonsRatio",
            [](const scalar nu) { return nu > -1 && nu <= 0.5; },
            " (-1, 0.5]"
        );
    };

    // Reduced stiffness: all contact moduli scaled by chi
    particleE_.setSize(n);
    particleNu_.setSize(n);
    for (label m = 0; m < n; ++m)
    {
        particleE_[m] = chi_*youngsModulus(materials.dict(m));
        particleNu_[m] = poissonsRatio(materials.dict(m));
    }

    // Every pair: e, mu and rollingFriction of its materialPairs entry,
    // else of the coefficients
    const scalar e = coeffs.get<scalar>("e");
    const scalar mu = coeffs.get<scalar>("mu");
    const scalar muR = coeffs.getOrDefault<scalar>("rollingFriction", 0);
    pp_.setSize(n*n);
    materials.forPairs
    (
        coeffs,
        [&](const label a, const label b, const dictionary* entry, bool)
        {
            pp_[materials.pairIndex(a, b)] = pairContact_.properties
            (
                particleE_[a], particleNu_[a], particleE_[b], particleNu_[b],
                entry ? *entry : coeffs, e, mu, muR
            );
        }
    );

    batchLaws_.clear();
    if (pairContact_.defaultParts())
    {
        batchLaws_.setSize(pp_.size());
        forAll(pp_, pairi)
        {
            batchLaws_[pairi] = defaultLawConstants::of(pp_[pairi]);
        }
    }

    // The collision time's per-material factors
    selfEstar_.setSize(n);
    rayleighFactorSqr_.setSize(n);
    for (label m = 0; m < n; ++m)
    {
        selfEstar_[m] = pairProperties(m, m).Estar;
        rayleighFactorSqr_[m] =
            particleE_[m]/(2*(1 + particleNu_[m]))
           *sqr(0.8766 + 0.163*particleNu_[m]);
    }

    // The walls: walls/<material> overrides e, mu and rollingFriction
    const dictionary& walls = coeffs.subDict("walls");
    const scalar Ew = chi_*youngsModulus(walls);
    const scalar nuw = poissonsRatio(walls);
    const scalar ew = walls.get<scalar>("e");
    const scalar muw = walls.get<scalar>("mu");
    const scalar muRw = walls.getOrDefault<scalar>("rollingFriction", 0);
    pw_.setSize(n);
    for (label m = 0; m < n; ++m)
    {
        const dictionary* own = walls.findDict(materials.name(m));
        pw_[m] = wallContact_.properties
        (
            particleE_[m], particleNu_[m], Ew, nuw, own ? *own : walls,
            ew, muw, muRw
        );
    }
}


template<class CloudType>
Foam::scalar Foam::EllipsoidCollision<CloudType>::bufferLayer
(
    const parcelType& p
) const
{
    return deltaBl_ >= 0 ? deltaBl_ : deltaBlRatio_*cmptMin(p.semiAxes());
}


template<class CloudType>
Foam::ellipsoid Foam::EllipsoidCollision<CloudType>::shell
(
    const parcelType& p,
    const point& x
) const
{
    // The inflated semi-axes of Eq. (41) directly (ellipsoid::inflated
    // would build the body first)
    return ellipsoid
    (
        p.semiAxes() + vector::uniform(bufferLayer(p)), x, p.orientation()
    );
}


template<class CloudType>
void Foam::EllipsoidCollision<CloudType>::checkBufferLayer
(
    const parcelType& pA,
    const parcelType* pB,
    const scalar overlap,
    const scalar twoDeltaBl,
    const scalar vn,
    const scalar mStar,
    const scalar R
)
{
    // The overlap approaches the buffer layers (half of them used up): the
    // true surfaces come close to touching. Ruan (section 3.3.1) keeps it
    // below 8 %. The first warnings name the pair; then a count per step.
    if (twoDeltaBl <= 0 || overlap <= 0.5*twoDeltaBl)
    {
        return;
    }
    ++nBufferWarnings_;
    if (nBufferWarningsTotal_++ >= 5)
    {
        return;
    }

    // Eq. (52): E > m v0^2/((2 delta_bl)^(5/2) R^(1/2)), in logarithms
    // (a buffer layer of a few nanometres underflows the power)
    const scalar logEmin =
        Foam::log(mStar) + 2*Foam::log(max(mag(vn), VSMALL))
      - 2.5*Foam::log(twoDeltaBl) - 0.5*Foam::log(R);
    const scalar Emin =
        logEmin < Foam::log(GREAT) ? Foam::exp(logEmin) : GREAT;

    WarningInFunction
        << "Contact of parcel (origProc " << pA.origProc() << ", origId "
        << pA.origId() << ") with "
        << (pB
            ? "parcel (origProc " + Foam::name(pB->origProc()) + ", origId "
            + Foam::name(pB->origId()) + ")"
            : word("a wall")).c_str()
        << ": overlap "
        << overlap << " m = " << overlap/twoDeltaBl
        << " of the two buffer layers (2 deltaBl = " << twoDeltaBl
        << " m; Ruan keeps it below 0.08). Eq. (52) asks for E > " << Emin
        << " Pa at the approach velocity " << mag(vn) << " m/s"
        << (nBufferWarningsTotal_ == 5 ? " (further cases are counted)" : "")
        << endl;
}


template<class CloudType>
typename Foam::EllipsoidCollision<CloudType>::contactBody
Foam::EllipsoidCollision<CloudType>::body
(
    parcelType& p,
    const vector& omega
) const
{
    const scalar dBl = bufferLayer(p);
    return contactBody
    {
        &p,
        p.U(),
        omega,
        p.mass(),
        cmptMax(p.semiAxes()) + dBl,
        dBl,
        p.isSphere(),
        labelPair(p.origProc(), p.origId()),
        -1,
        p.material()
    };
}


template<class CloudType>
void Foam::EllipsoidCollision<CloudType>::preInteraction()
{
    nBufferWarnings_ = 0;
    elasticEnergy_ = 0;
    nUnconverged_ = 0;
    nPairSides_ = 0;
    nWallContacts_ = 0;
    contacts_.clear();
    deltaT_ = this->owner().mesh().time().deltaTValue();

    // The contact bodies, once per collide, in cloud order: gathered by
    // the move (EllipsoidCloud::moveCollide; parcels finish their move in
    // cloud order, also in parallel where those received from other
    // processors are appended and finish last) or here
    if (!gathering_ || bodies_.size() != this->owner().size())
    {
        bodies_.clear();
        for (parcelType& p : this->owner())
        {
            gatherBody(p);
        }
    }
    gathering_ = false;
    bodies_.zeroForces();

    // The positions of the parcels of cells with referred neighbours
    // (other processors, cyclics)
    if (referring())
    {
        const List<DynamicList<parcelType*>>& cellOccupancy =
            this->owner().cellOccupancy();
        cellPositions_.setSize(cellOccupancy.size());
        for (const labelList& realCells : il_.ril())
        {
            for (const label celli : realCells)
            {
                const DynamicList<parcelType*>& cell = cellOccupancy[celli];
                pointField& x = cellPositions_[celli];
                x.setSize(cell.size());
                forAll(cell, k)
                {
                    x[k] = cell[k]->centre();
                }
            }
        }
    }

    if
    (
        !list_.valid
        (
            bodies_.positions(),
            [this](const label i) -> const labelPair& { return bodies_[i].id; }
        )
    )
    {
        buildNeighbourList();
    }
}


template<class CloudType>
void Foam::EllipsoidCollision<CloudType>::beginGather()
{
    bodies_.clear();
    gathering_ = true;
}


template<class CloudType>
void Foam::EllipsoidCollision<CloudType>::cacheWallFaceBoxes()
{
    // Each boundary face's bounding box, unit normal and area, and whether
    // the face is its box (the mesh is static)
    const polyMesh& mesh = this->owner().mesh();
    if (wallFaceBb_.size() != mesh.nBoundaryFaces())
    {
        wallFaceBb_.setSize(mesh.nBoundaryFaces());
        wallFaceIsBox_.setSize(mesh.nBoundaryFaces());
        wallFaceNormal_.setSize(mesh.nBoundaryFaces());
        wallFaceArea_.setSize(mesh.nBoundaryFaces());
        forAll(wallFaceBb_, bFacei)
        {
            const label facei = mesh.nInternalFaces() + bFacei;
            const boundBox& bb = wallFaceBb_[bFacei] =
                boundBox(mesh.points(), mesh.faces()[facei], false);

            // A plane face along axis k whose area is that of its box in
            // the other two directions is that box
            const vector& Sf = mesh.faceAreas()[facei];
            const scalar magSf = mag(Sf);
            wallFaceNormal_[bFacei] = magSf > 0 ? Sf/magSf : vector(Zero);
            wallFaceArea_[bFacei] = magSf;
            const vector span = bb.span();
            direction k = 0;
            for (direction d = 1; d < vector::nComponents; ++d)
            {
                if (mag(Sf[d]) > mag(Sf[k]))
                {
                    k = d;
                }
            }
            const direction a = (k + 1) % 3;
            const direction b = (k + 2) % 3;
            wallFaceIsBox_[bFacei] =
                magSf > 0
             && mag(Sf[k]) >= (1 - 1e-12)*magSf
             && span[k] <= 1e-9*Foam::sqrt(magSf)
             && mag(span[a]*span[b] - magSf) <= 1e-9*magSf;
        }
    }
}


template<class CloudType>
void Foam::EllipsoidCollision<CloudType>::findWallFaces
(
    const labelList& oldIndex
)
{
    // Wall faces in reach: those of the interaction list of the parcel's
    // cell whose bounding box comes within r + skin. Complete while the
    // parcel stays within skin/2 of its position (the list is rebuilt
    // otherwise):
    // the list of a cell holds the faces whose boxes come within
    // maxInteractionDistance of the cell's box (InteractionLists), and
    // r + skin/2 <= maxInteractionDistance
    const polyMesh& mesh = this->owner().mesh();
    const label n = bodies_.size();
    const scalar skin = list_.skin();
    const labelListList& directWallFaces = il_.dwfil();

    // The wall histories' run of each body at the last build (-1: none)
    const bool store = !referring();
    labelList oldRun(wallParcels_.size() ? wallParcels_.last() + 1 : 0, -1);
    forAll(wallParcels_, m)
    {
        oldRun[wallParcels_[m]] = m;
    }

    wallStart_.setSize(n + 1);
    wallStart_[0] = 0;
    wallFaces_.clear();
    wallParcels_.clear();
    for (label i = 0; i < n; ++i)
    {
        parcelType& p = bodies_.parcel(i);
        const scalar r = bodies_[i].radius;
        if (r + 0.5*skin > maxDistance_)
        {
            FatalIOErrorInFunction(this->coeffDict())
                << "Entry maxInteractionDistance = "
                << Foam::name(maxDistance_)
                << " is too small for parcel (origProc " << p.origProc()
                << ", origId " << p.origId() << ") with the bounding radius "
                << Foam::name(r) << " m of its collision shell: it must be"
                << " >= the radius + neighbourSkin/2 = "
                << Foam::name(r + 0.5*skin) << exit(FatalIOError);
        }
        const point& x = bodies_.x(i);
        for (const label facei : directWallFaces[p.cell()])
        {
            // A collapsed face (zero area) has no plane: its neighbours
            // hold the wall there
            const label bFacei = facei - mesh.nInternalFaces();
            const boundBox& bb = wallFaceBb_[bFacei];
            if
            (
                wallFaceArea_[bFacei] > 0
             && magSqr(x - bb.nearest(x)) < sqr(r + skin)
            )
            {
                wallFaces_.append(facei);
            }
        }
        wallStart_[i + 1] = wallFaces_.size();

        // In face order, not the order of the interaction list of the
        // cell the parcel was in at the build: of two coplanar faces that
        // both hold a contact point (on their shared edge) the first is
        // kept, and the faces' planes differ at round-off; a restart,
        // which builds the list elsewhere, must keep the same one
        std::sort
        (
            wallFaces_.begin() + wallStart_[i],
            wallFaces_.begin() + wallStart_[i + 1]
        );
        if (wallStart_[i + 1] > wallStart_[i])
        {
            wallParcels_.append(i);

            // Its wall histories: those of its run at the last build, or
            // its records if it was not listed then (read, injected); none
            // if it had no wall in reach
            if (store)
            {
                const label iOld = oldIndex[i];
                if (iOld < 0)
                {
                    wallHistories_.append(p.collisionRecords().wallRecords());
                }
                else if (iOld < oldRun.size() && oldRun[iOld] >= 0)
                {
                    wallHistories_.append(oldRun[iOld]);
                }
                else
                {
                    wallHistories_.append
                    (
                        UList<WallCollisionRecord<vector>>()
                    );
                }
            }
        }
        else if (store)
        {
            // No wall in reach: a wall contact of the last step has
            // ended (in parallel all records are renewed every step)
            mutableWallRecords(p.collisionRecords()).clear();
        }
    }
    if (store)
    {
        wallHistories_.endStep();
    }
}


template<class CloudType>
void Foam::EllipsoidCollision<CloudType>::buildNeighbourList()
{
    auto idOf =
        [this](const label i) -> const labelPair& { return bodies_[i].id; };

    // The previous list and its histories, carried over below
    const labelList oldIndex(list_.indices(bodies_.size(), idOf));
    neighbourList old;
    old.transfer(list_);
    pairHistories oldHistories;
    oldHistories.transfer(histories_);

    list_.build
    (
        bodies_.positions(),
        idOf,
        [this](const label i) { return bodies_[i].radius; }
    );

    // A pair not in the old list: the history of pair (A, B) from the
    // records of A, if A has one (read on restart, injected or
    // transferred: its records are current; in parallel and with cyclics
    // all records are written every step)
    histories_.carry
    (
        list_, old, oldHistories, oldIndex, referring() || keepRecords_,
        [this](const label a, const label b, vector& xi)
        {
            const parcelType& pA = bodies_.parcel(a);
            const parcelType& pB = bodies_.parcel(b);
            for (const auto& record : pA.collisionRecords().pairRecords())
            {
                if
                (
                    record.origProcOfOther() == pB.origProc()
                 && record.origIdOfOther() == pB.origId()
                )
                {
                    xi = record.collisionData();
                    return true;
                }
            }
            return false;
        }
    );

    // The pairs' separations are relative to the travel since this build
    bodies_.restartTravel();

    // The bodies' collision-time factors, for the last kicks until the
    // next build
    timeFactors_.setSize(bodies_.size());
    forAll(timeFactors_, i)
    {
        timeFactors_[i] = timeFactors(bodies_.parcel(i));
    }

    cacheWallFaceBoxes();
    findWallFaces(oldIndex);
}


template<class CloudType>
void Foam::EllipsoidCollision<CloudType>::writePairRecords()
{
    for (label i = 0; i < bodies_.size(); ++i)
    {
        parcelType& pA = bodies_.parcel(i);
        for (label k = list_.begin(i); k < list_.end(i); ++k)
        {
            if (histories_.touching(k))
            {
                parcelType& pB = bodies_.parcel(list_.partner(k));
                pA.collisionRecords().matchPairRecord
                (
                    pB.origProc(),
                    pB.origId()
                ).collisionData() = histories_.xi(k);
                pB.collisionRecords().matchPairRecord
                (
                    pA.origProc(),
                    pA.origId()
                ).collisionData() = -histories_.xi(k);
            }
        }
    }
}


template<class CloudType>
Foam::ellipsoidContact::result
Foam::EllipsoidCollision<CloudType>::pairGeometry
(
    const contactBody& A,
    const point& xA,
    const contactBody& B,
    const point& xB,
    const bool referred,
    vector& nTrack
) const
{
    // A referred pair is evaluated on both processors: in one canonical
    // order (lower origProc, origId first), so both solve the same contact
    // problem (the referred copy's position may still differ at round-off;
    // tribocharging balances by charging such a pair on one side only)
    const bool swapped =
        referred
     && (
            A.p->origProc() > B.p->origProc()
         || (
                A.p->origProc() == B.p->origProc()
             && A.p->origId() > B.p->origId()
            )
        );
    const contactBody& b1 = swapped ? B : A;
    const contactBody& b2 = swapped ? A : B;
    const point& x1 = swapped ? xB : xA;
    const point& x2 = swapped ? xA : xB;

    // Two spheres: the analytic fast path, without ellipsoid objects;
    // the shells of gathered parcels are made once per collide, those of
    // referred parcels here
    ellipsoidContact::result c;
    if (b1.sphere && b2.sphere)
    {
        c = ellipsoidContact::sphereSphere(x1, b1.radius, x2, b2.radius);
    }
    else if (b1.shell >= 0 && b2.shell >= 0)
    {
        const ellipsoid& e1 = bodies_.shell(b1);
        const ellipsoid& e2 = bodies_.shell(b2);
        c =
            method_ == ellipsoidContact::method::automatic
          ? ellipsoidContact::contact(e1, e2, nTrack)
          : ellipsoidContact::contact(e1, e2, method_);
    }
    else
    {
        c = ellipsoidContact::contact
        (
            shell(*b1.p, x1), shell(*b2.p, x2), method_
        );
    }
    if (swapped)
    {
        std::swap(c.x1, c.x2);
        std::swap(c.gradR.centre1, c.gradR.centre2);
        std::swap(c.gradR.rotation1, c.gradR.rotation2);
        c.n = -c.n;
    }
    return c;
}


template<class CloudType>
Foam::ellipsoidContact::result
Foam::EllipsoidCollision<CloudType>::listPairGeometry
(
    const label i,
    const label k
)
{
    // A lasting contact's normal turns smoothly: started from its linear
    // extrapolation, Newton is within the square of the step's turn of the
    // normal, and converges in one step instead of two (the start changes
    // the converged normal only at round-off, ellipsoidContact.H)
    const label j = list_.partner(k);
    vector& n = histories_.direction(k);
    const vector before = n;
    n += histories_.directionChange(k);
    const ellipsoidContact::result c = pairGeometry
    (
        bodies_[i], bodies_.x(i), bodies_[j], bodies_.x(j), false, n
    );
    keepTrack
    (
        k, before,
        histories_.touching(k) && c.contact && c.overlap > 0 && c.converged
     && magSqr(before) > 0 && magSqr(n) > 0,
        c.separation, i, j
    );
    return c;
}


template<class CloudType>
inline void Foam::EllipsoidCollision<CloudType>::keepTrack
(
    const label k,
    const vector& before,
    const bool lasting,
    const scalar separation,
    const label i,
    const label j
)
{
    const vector& n = histories_.direction(k);
    histories_.directionChange(k) = lasting ? n - before : vector(Zero);

    // Separated along n: so while the bodies travel less than the gap
    // (ContactBodies sums the travel of the bodies with a shell: a pair
    // with a sphere keeps no gap)
    histories_.apartUntil(k) =
        separation > 0 && bodies_[i].shell >= 0 && bodies_[j].shell >= 0
      ? bodies_.travel(i) + bodies_.travel(j) + separation
      : 0;
}


template<class CloudType>
Foam::vector Foam::EllipsoidCollision<CloudType>::pairForce
(
    const ellipsoidContact::result& c,
    const contactBody& A,
    const point& xA,
    const contactBody& B,
    const point& xB,
    vector& xi,
    const label referredFrom,
    vector& torqueA,
    vector& torqueB
)
{
    const bool referred = referredFrom >= 0;

    // A contact with a referred parcel is also evaluated on the referred
    // parcel's processor: half of its energy is booked here
    const scalar energyWeight = referred ? 0.5 : 1;

    if (!c.converged)
    {
        ++nUnconverged_;
    }

    if (recordContacts_)
    {
        contacts_.append
        (
            {A.p, B.p, xA, xB, c, A.radius, -1, referred, referredFrom}
        );
    }

    // Contact point: the midpoint (exact angular momentum balance).
    // sphereContactBatch.C and ellipsoidContactBatch.C repeat what follows
    // for two real spheres and for a lasting contact of two real
    // ellipsoids (a change here goes there too; their unit tests compare
    // them bit for bit)
    const point xc = 0.5*(c.x1 + c.x2);
    const vector vRel =
        pointVelocity(A.U, A.omega, xA, xc)
      - pointVelocity(B.U, B.omega, xB, xc);
    const scalar mStar = A.mass*B.mass/(A.mass + B.mass);

    const contactProperties& law = pp_[A.material*nMaterials_ + B.material];
    scalar dUdR;
    contactWork work{0, 0};
    const vector F = pairContact_.force
    (
        law, c, vRel, mStar,
        bodies_.normalMobility(A, xA, xc, c.n)
      + bodies_.normalMobility(B, xB, xc, c.n),
        deltaT_, xi, dUdR, work
    );
    dissipatedEnergy_ += energyWeight*work.dissipated;
    elasticEnergy_ += energyWeight*work.elastic;

    const scalar twoDeltaBl = A.deltaBl + B.deltaBl;
    if (twoDeltaBl > 0 && c.overlap > 0.5*twoDeltaBl)
    {
        checkBufferLayer
        (
            *A.p, B.p, c.overlap, twoDeltaBl, vRel & c.n, mStar,
            c.reducedRadius
        );
    }

    // Rolling friction, limited by the smaller rotational inertia
    scalar rolled = 0;
    const vector Mr =
        law.muR > 0
      ? pairContact_.rollingTorque
        (
            law, c, F, A.omega - B.omega,
            min
            (
                cmptMin(A.p->principalMoments()),
                cmptMin(B.p->principalMoments())
            ),
            deltaT_, rolled
        )
      : Zero;
    dissipatedEnergy_ += energyWeight*rolled;

    // Torques about the centroids (Ruan Eq. 40), and the elastic force and
    // torques of the change of R (-dUdR gradR, see Description; zero for
    // two spheres)
    const vector MA = ((xc - xA) ^ F) + Mr;
    const vector MB = ((xc - xB) ^ F) + Mr;
    if (A.sphere && B.sphere)
    {
        torqueA += MA;
        torqueB -= MB;
        return F;
    }
    torqueA += MA - dUdR*c.gradR.rotation1;
    torqueB -= MB + dUdR*c.gradR.rotation2;
    return F - dUdR*c.gradR.centre1;
}


template<class CloudType>
inline bool Foam::EllipsoidCollision<CloudType>::stillSeparated
(
    const label k,
    const scalar travelled
)
{
    // Still separated along the tracked direction (the bodies travelled
    // less than its gap since): what the narrow phase's first evaluation
    // there would decide, with the same normalisation of the direction, so
    // the run is bit-identical
    const scalar apartUntil = histories_.apartUntil(k);
    if (apartUntil > 0 && travelled < apartUntil)
    {
        vector& n = histories_.direction(k);
        n = n*(1/mag(n));
        return true;
    }
    return false;
}


template<class CloudType>
inline bool Foam::EllipsoidCollision<CloudType>::pairApart
(
    const label i,
    const label k
)
{
    // The travel of both bodies since the list's build, with a factor for
    // the round-off of its sums (relative eps per step since the build)
    const label j = list_.partner(k);
    auto travelled = [&]()
    {
        return (bodies_.travel(i) + bodies_.travel(j))*(1 + 1e-8);
    };

    // Bounding spheres still apart, or still overlapping, as at the
    // pair's last check (the bodies travelled less than the margin found
    // then): decided without the partner's record. Apart, its history is
    // already what the check below leaves
    const scalar reachUntil =
        bodies_.nShells() > 0 ? histories_.reachUntil(k) : 0;
    if (reachUntil != 0)
    {
        const scalar t = travelled();
        if (t < mag(reachUntil))
        {
            return reachUntil > 0 || stillSeparated(k, t);
        }
    }

    // Bounding spheres of the collision shells. Apart, the pair's tracked
    // direction is forgotten: it then depends only on the pair's own
    // history since it came within reach, not on when the list was built
    const contactBody& A = bodies_[i];
    const contactBody& B = bodies_[j];
    const bool spheres = A.sphere && B.sphere;
    const scalar reach = A.radius + B.radius;
    const scalar distanceSqr = magSqr(bodies_.x(i) - bodies_.x(j));
    const bool outOfReach = distanceSqr > sqr(reach);
    if (A.shell >= 0 && B.shell >= 0)
    {
        keepReach(k, i, j, outOfReach, distanceSqr, reach);
    }
    if (outOfReach)
    {
        histories_.setTouching(k, false);
        if (!spheres)
        {
            histories_.direction(k) = Zero;
            histories_.directionChange(k) = Zero;
            histories_.apartUntil(k) = 0;
        }
        return true;
    }
    return !spheres && stillSeparated(k, travelled());
}


template<class CloudType>
inline void Foam::EllipsoidCollision<CloudType>::keepReach
(
    const label k,
    const label i,
    const label j,
    const bool outOfReach,
    const scalar distanceSqr,
    const scalar reach
)
{
    // The centres' distance changes by at most the travel of the bodies
    // (ContactBodies sums |dc| of each gather): the spheres stay as they
    // are while the travel grows by less than the distance's margin to
    // the reach. The margin leaves 1e-10 of the reach for the round-off
    // of the distance and of the check's squares
    const scalar distance = Foam::sqrt(distanceSqr);
    const scalar margin =
        (outOfReach ? distance - reach : reach - distance) - 1e-10*reach;
    const scalar until = bodies_.travel(i) + bodies_.travel(j) + margin;
    histories_.reachUntil(k) =
        margin > 0 ? (outOfReach ? until : -until) : 0;
}


template<class CloudType>
inline void Foam::EllipsoidCollision<CloudType>::realRealPair
(
    const label i,
    const label k
)
{
    if (!pairApart(i, k))
    {
        narrowPhasePair(i, k);
    }
}


template<class CloudType>
void Foam::EllipsoidCollision<CloudType>::narrowPhasePair
(
    const label i,
    const label k
)
{
    const contactBody& A = bodies_[i];
    const point& xA = bodies_.x(i);
    const label j = list_.partner(k);
    const contactBody& B = bodies_[j];
    const point& xB = bodies_.x(j);

    // Two spheres: the analytic contact (pairGeometry's for them, which
    // spheres do not track a direction for)
    realRealContact
    (
        i, k,
        A.sphere && B.sphere
      ? ellipsoidContact::sphereSphere(xA, A.radius, xB, B.radius)
      : listPairGeometry(i, k)
    );
}


template<class CloudType>
inline void Foam::EllipsoidCollision<CloudType>::realRealContact
(
    const label i,
    const label k,
    const ellipsoidContact::result& c
)
{
    if (!c.contact || c.overlap <= 0)
    {
        histories_.setTouching(k, false);
        return;
    }

    // A new contact starts its tangential history
    vector& xi = histories_.xi(k);
    if (!histories_.touching(k))
    {
        xi = Zero;
        histories_.setTouching(k, true);
    }
    nPairSides_ += 2;

    const label j = list_.partner(k);
    const vector F = pairForce
    (
        c, bodies_[i], bodies_.x(i), bodies_[j], bodies_.x(j), xi, -1,
        bodies_.torque(i), bodies_.torque(j)
    );
    bodies_.force(i) += F;
    bodies_.force(j) -= F;
}


template<class CloudType>
inline bool Foam::EllipsoidCollision<CloudType>::laneToScalarPath
(
    const label i,
    const label k,
    const contactBatchKicks& batch,
    const label l,
    const scalar overlap
) const
{
    // A contact's first or last step (the onset correction), or an overlap
    // beyond half the buffer layers (the warning)
    const scalar twoDeltaBl =
        bodies_[i].deltaBl + bodies_[list_.partner(k)].deltaBl;
    return
        batch.needsScalar(l)
     || (twoDeltaBl > 0 && overlap > 0.5*twoDeltaBl);
}


template<class CloudType>
inline void Foam::EllipsoidCollision<CloudType>::laneKickEffect
(
    const label i,
    const label k,
    const contactBatchKicks& batch,
    const label l
)
{
    // pairForce's effects (real pairs book all of their energy)
    const label j = list_.partner(k);
    histories_.setTouching(k, true);
    histories_.xi(k) = batch.xi(l);
    nPairSides_ += 2;
    dissipatedEnergy_ += batch.dissipated(l);
    elasticEnergy_ += batch.elastic(l);
    bodies_.torque(i) += batch.torqueA(l);
    bodies_.torque(j) -= batch.minusTorqueB(l);
    const vector F = batch.F(l);
    bodies_.force(i) += F;
    bodies_.force(j) -= F;
}


template<class CloudType>
inline void Foam::EllipsoidCollision<CloudType>::sphereLaneEffect
(
    const label i,
    const label k,
    const sphereContactBatch& batch,
    const label l
)
{
    if (!batch.contact(l))
    {
        histories_.setTouching(k, false);
    }
    else if (laneToScalarPath(i, k, batch, l, batch.overlap(l)))
    {
        narrowPhasePair(i, k);
    }
    else
    {
        laneKickEffect(i, k, batch, l);
    }
}


template<class CloudType>
inline void Foam::EllipsoidCollision<CloudType>::ellipsoidLaneEffect
(
    const label i,
    const label k,
    const ellipsoidContactBatch& batch,
    const label l,
    const bool kicked
)
{
    if
    (
        !batch.decided(l)
     || (kicked && laneToScalarPath(i, k, batch, l, batch.overlap(l)))
    )
    {
        narrowPhasePair(i, k);
    }
    else
    {
        // listPairGeometry's effects (a lasting contact: no gap), then the
        // kick's or the contact pair by pair
        vector& n = histories_.direction(k);
        const vector before = n;
        n = batch.normal(l);
        const label j = list_.partner(k);
        keepTrack(k, before, true, 0, i, j);
        if (kicked)
        {
            laneKickEffect(i, k, batch, l);
        }
        else
        {
            realRealContact(i, k, batch.contact(l));
        }
    }
}


template<class CloudType>
inline bool Foam::EllipsoidCollision<CloudType>::setEllipsoidLane
(
    const label k,
    const contactBody& A,
    const point& xA,
    const contactBody& B,
    const point& xB,
    const label pairi,
    ellipsoidContactBatch& batch,
    const label l,
    const bool kicked
)
{
    // A lasting contact with a tracked direction and its extrapolation:
    // what listPairGeometry starts from
    if
    (
        !histories_.touching(k) || A.shell < 0 || B.shell < 0
     || histories_.apartUntil(k) > 0 || (kicked && pp_[pairi].muR > 0)
    )
    {
        return false;
    }
    const vector& n = histories_.direction(k);
    const vector start = n + histories_.directionChange(k);
    const ellipsoid& eA = bodies_.shell(A);
    const ellipsoid& eB = bodies_.shell(B);
    if
    (
        !(magSqr(n) > 0) || !(magSqr(start) > 0)
     || (eA.isSphere() && eB.isSphere())
    )
    {
        return false;
    }
    batch.setLane(l, eA, eB, start);
    if (kicked)
    {
        batch.setBodies
        (
            l,
            xA, A.U, A.omega, A.mass, bodies_.inverseInertiaOf(A),
            xB, B.U, B.omega, B.mass, bodies_.inverseInertiaOf(B),
            batchLaws_[pairi], histories_.xi(k)
        );
    }
    return true;
}


template<class CloudType>
void Foam::EllipsoidCollision<CloudType>::batchInteraction
(
    const bool sphereLanes,
    const bool ellipsoidLanes
)
{
    // Pairs wait in the list's order: sphere pairs in reach in the sphere
    // batch's lanes, lasting contacts of ellipsoids in the ellipsoid
    // batch's (its narrow phase, and the kick where the sphere lanes take
    // it too), the others (new contacts of ellipsoids, rolling resistance)
    // to go one by one; at a full batch or queue the batches are evaluated
    // and the queue takes effect in order. A pair out of reach or certified
    // apart changes only its own history: at once. The others are queued
    // after that test (pairApart), and nothing of their pairs changes
    // before they take effect: a lane that a batch leaves to the scalar
    // path, and a pair queued for it, take the contact pair by pair
    // (narrowPhasePair) without the test again
    const label queueSize = 4*contactBatchKicks::width;
    enum class path { scalar, sphere, ellipsoid };
    struct waiting
    {
        label i, k, lane;
        path by;
    };
    FixedList<waiting, queueSize> queue;
    label nQueued = 0, nSphereLanes = 0, nEllipsoidLanes = 0;
    sphereContactBatch spheres;
    ellipsoidContactBatch ellipsoids;

    // The ellipsoid lanes also take the kick where the sphere lanes may
    const bool kicked = lanesKick();

    auto takeEffect = [&]()
    {
        if (nSphereLanes > 0)
        {
            spheres.evaluate(nSphereLanes, deltaT_);
        }
        if (nEllipsoidLanes > 0)
        {
            ellipsoids.evaluate(nEllipsoidLanes);
            if (kicked)
            {
                ellipsoids.kick(nEllipsoidLanes, deltaT_);
            }
        }
        for (label q = 0; q < nQueued; ++q)
        {
            const waiting& w = queue[q];
            switch (w.by)
            {
                case path::scalar:
                    narrowPhasePair(w.i, w.k);
                    break;
                case path::sphere:
                    sphereLaneEffect(w.i, w.k, spheres, w.lane);
                    break;
                case path::ellipsoid:
                    ellipsoidLaneEffect(w.i, w.k, ellipsoids, w.lane, kicked);
                    break;
            }
        }
        nQueued = 0;
        nSphereLanes = 0;
        nEllipsoidLanes = 0;
    };

    for (label i = 0; i < bodies_.size(); ++i)
    {
        const contactBody& A = bodies_[i];
        const point& xA = bodies_.x(i);
        for (label k = list_.begin(i); k < list_.end(i); ++k)
        {
            if (pairApart(i, k))
            {
                // Only the pair's own history changed: nothing to queue
                continue;
            }
            const label j = list_.partner(k);
            const contactBody& B = bodies_[j];
            const point& xB = bodies_.x(j);
            waiting w{i, k, -1, path::scalar};
            const label pairi = A.material*nMaterials_ + B.material;
            if (A.sphere && B.sphere)
            {
                if (sphereLanes && !(pp_[pairi].muR > 0))
                {
                    spheres.setLane
                    (
                        nSphereLanes,
                        xA, A.radius, A.U, A.omega, A.mass,
                        xB, B.radius, B.U, B.omega, B.mass,
                        batchLaws_[pairi],
                        histories_.touching(k)
                      ? histories_.xi(k) : vector(Zero)
                    );
                    w = {i, k, nSphereLanes++, path::sphere};
                }
            }
            else if
            (
                ellipsoidLanes
             && setEllipsoidLane
                (
                    k, A, xA, B, xB, pairi, ellipsoids, nEllipsoidLanes, kicked
                )
            )
            {
                w = {i, k, nEllipsoidLanes++, path::ellipsoid};
            }
            queue[nQueued++] = w;
            if
            (
                nSphereLanes == sphereContactBatch::width
             || nEllipsoidLanes == ellipsoidContactBatch::width
             || nQueued == queueSize
            )
            {
                takeEffect();
            }
        }
    }
    takeEffect();
}


template<class CloudType>
void Foam::EllipsoidCollision<CloudType>::realRealInteraction()
{
    // The sphere batch takes what pairForce does with the default law's
    // parts (not the listing of the contacts), for beds with spheres; the
    // ellipsoid batch the narrow phase of the default method, for beds
    // with ellipsoids
    const bool sphereLanes =
        lanesKick() && bodies_.nShells() < bodies_.size();
    const bool ellipsoidLanes =
        method_ == ellipsoidContact::method::automatic
     && bodies_.nShells() > 0;
    if (sphereLanes || ellipsoidLanes)
    {
        batchInteraction(sphereLanes, ellipsoidLanes);
        return;
    }
    for (label i = 0; i < bodies_.size(); ++i)
    {
        for (label k = list_.begin(i); k < list_.end(i); ++k)
        {
            realRealPair(i, k);
        }
    }
}


template<class CloudType>
void Foam::EllipsoidCollision<CloudType>::realReferredInteraction()
{
    const labelListList& ril = il_.ril();
    List<IDLList<parcelType>>& referredParticles = il_.referredParticles();
    List<DynamicList<parcelType*>>& cellOccupancy =
        this->owner().cellOccupancy();

    // The processor each referred cell came from
    labelList from(ril.size(), Pstream::myProcNo());
    const labelListList& constructMap = il_.cellMap().constructMap();
    forAll(constructMap, proci)
    {
        for (const label refCelli : constructMap[proci])
        {
            from[refCelli] = proci;
        }
    }

    forAll(ril, refCelli)
    {
        for (parcelType& referred : referredParticles[refCelli])
        {
            const point xR = referred.centre();
            const contactBody R = body(referred);
            for (const label realCelli : ril[refCelli])
            {
                const DynamicList<parcelType*>& cell = cellOccupancy[realCelli];
                forAll(cell, k)
                {
                    parcelType& pA = *cell[k];
                    const point& xA = cellPositions_[realCelli][k];
                    const scalar rA = cmptMax(pA.semiAxes()) + bufferLayer(pA);
                    if (magSqr(xA - xR) > sqr(rA + R.radius))
                    {
                        continue;
                    }
                    const contactBody A = body(pA);
                    vector nTrack(Zero);
                    const ellipsoidContact::result c =
                        pairGeometry(A, xA, R, xR, true, nTrack);
                    if (!c.contact || c.overlap <= 0)
                    {
                        continue;
                    }
                    ++nPairSides_;

                    // The history on the real parcel's side (the referred
                    // parcel's processor keeps the other)
                    vector& xi =
                        pA.collisionRecords().matchPairRecord
                        (
                            referred.origProc(),
                            referred.origId()
                        ).collisionData();
                    vector torqueR(Zero);
                    pA.f() +=
                        pairForce
                        (
                            c, A, xA, R, xR, xi, from[refCelli], pA.torque(),
                            torqueR
                        );
                }
            }
        }
    }
}


template<class CloudType>
void Foam::EllipsoidCollision<CloudType>::wallFaceContact
(
    const bool parcelRecords,
    const label i,
    const face& f,
    const pointField& pts,
    const point& fc,
    const vector& nOutOfDomain,
    const scalar faceArea,
    const boundBox& bb,
    const bool box,
    const label patchi,
    DynamicList<point>& contactPoints
)
{
    const contactBody& b = bodies_[i];
    const point& xp = bodies_.x(i);
    const scalar r = b.radius;

    // The face's plane or its bounding box out of reach of the shell's
    // bounding sphere: no contact (cheap tests before any geometry;
    // the box test drops the coplanar neighbours of the face in
    // contact)
    const scalar h = (xp - fc) & nOutOfDomain;
    if (h <= -r || h >= r)
    {
        return;
    }
    if (magSqr(xp - bb.nearest(xp)) >= sqr(r))
    {
        return;
    }

    // An ellipsoid's curvature only once the contact belongs to this face
    // (most evaluations are of coplanar neighbours of the face in contact)
    ellipsoidContact::result c =
        b.sphere
      ? ellipsoidContact::spherePlane(xp, r, fc, -nOutOfDomain)
      : ellipsoidContact::ellipsoidPlanePoint
        (
            bodies_.shell(b), fc, -nOutOfDomain
        );
    if (!c.contact || c.overlap <= 0)
    {
        return;
    }

    // The contact belongs to this face if its plane point lies on the
    // face (within round-off of the face size) (bounding box first:
    // most coplanar neighbours fail it)
    const scalar tol = 1e-9*Foam::sqrt(faceArea) + SMALL*r;
    if
    (
        cmptMin(c.x2 - bb.min()) < -tol
     || cmptMax(c.x2 - bb.max()) > tol
    )
    {
        return;
    }
    if (!box && f.nearestPoint(c.x2, pts).distance() > tol)
    {
        return;
    }
    for (const point& x : contactPoints)
    {
        if (magSqr(x - c.x2) < sqr(1e-6*r))
        {
            return;
        }
    }
    if (!b.sphere)
    {
        ellipsoidContact::addPlaneCurvature(bodies_.shell(b), c);
    }
    contactPoints.append(c.x2);
    ++nWallContacts_;

    parcelType& p = *b.p;
    if (recordContacts_)
    {
        contacts_.append({&p, nullptr, xp, xp, c, r, patchi, false, -1});
    }

    const point xc = 0.5*(c.x1 + c.x2);
    const vector vRel = pointVelocity(b.U, b.omega, xp, xc);
    vector& xi =
        (
            parcelRecords
          ? p.collisionRecords().matchWallRecord(xc - xp, r)
          : wallHistories_.match(xc - xp, r)
        ).collisionData();

    const contactProperties& law = pw_[b.material];
    scalar dUdR;
    contactWork work{0, 0};
    const vector F = wallContact_.force
    (
        law, c, vRel, b.mass, bodies_.normalMobility(b, xp, xc, c.n),
        deltaT_, xi, dUdR, work
    );
    dissipatedEnergy_ += work.dissipated;
    elasticEnergy_ += work.elastic;
    scalar rolled = 0;
    const vector Mr =
        law.muR > 0
      ? wallContact_.rollingTorque
        (
            law, c, F, b.omega, cmptMin(p.principalMoments()), deltaT_, rolled
        )
      : Zero;
    dissipatedEnergy_ += rolled;
    if (b.deltaBl > 0 && c.overlap > 0.5*b.deltaBl)
    {
        checkBufferLayer
        (
            p, nullptr, c.overlap, b.deltaBl, vRel & c.n, b.mass,
            c.reducedRadius
        );
    }
    // The elastic torque of the change of R (see Description)
    bodies_.force(i) += F;
    bodies_.torque(i) += ((xc - xp) ^ F) + Mr - dUdR*c.gradR.rotation1;
}


template<class CloudType>
void Foam::EllipsoidCollision<CloudType>::wallInteraction()
{
    const polyMesh& mesh = this->owner().mesh();
    const faceList& faces = mesh.faces();
    const pointField& points = mesh.points();
    const vectorField& faceCentres = mesh.faceCentres();
    const labelListList& referredWallFaces = il_.rwfilInverse();

    // Contacts of one parcel (contact points on the walls) to keep
    // coplanar neighbour faces from counting one contact twice
    DynamicList<point> contactPoints;

    // Parcels with wall faces in reach (all parcels when some have
    // referred wall faces: the faces across processors and cyclics are
    // found per step from the interaction lists; their wall histories
    // then live in the parcels' records)
    const bool allParcels = referring();
    const label nLoop = allParcels ? bodies_.size() : wallParcels_.size();
    for (label m = 0; m < nLoop; ++m)
    {
        const label i = allParcels ? m : wallParcels_[m];
        contactPoints.clear();
        if (!allParcels)
        {
            wallHistories_.open(m);
        }

        for (label k = wallStart_[i]; k < wallStart_[i + 1]; ++k)
        {
            const label facei = wallFaces_[k];
            const label bFacei = facei - mesh.nInternalFaces();
            wallFaceContact
            (
                allParcels,
                i,
                faces[facei],
                points,
                faceCentres[facei],
                wallFaceNormal_[bFacei],
                wallFaceArea_[bFacei],
                wallFaceBb_[bFacei],
                wallFaceIsBox_[bFacei],
                // The patch only for the listed contacts (a search)
                recordContacts_ ? mesh.boundaryMesh().whichPatch(facei) : -1,
                contactPoints
            );
        }

        if (allParcels)
        {
            for (const label rwfi : referredWallFaces[bodies_.parcel(i).cell()])
            {
                const referredWallFace& rwf = il_.referredWallFaces()[rwfi];
                const pointField& pts = rwf.points();
                wallFaceContact
                (
                    allParcels,
                    i,
                    rwf,
                    pts,
                    rwf.centre(pts),
                    rwf.unitNormal(pts),
                    rwf.mag(pts),
                    boundBox(pts, rwf, false),
                    false,
                    rwf.patchIndex(),
                    contactPoints
                );
            }
        }
        else
        {
            wallHistories_.close();
        }
    }
    if (!allParcels)
    {
        wallHistories_.endStep();
    }
}


template<class CloudType>
void Foam::EllipsoidCollision<CloudType>::postInteraction()
{
    // The pair histories live in the neighbour list, the wall histories
    // (serial without cyclics) in wallHistories_. The parcels' records
    // are written when they are read: every step in parallel and with
    // cyclics (parcels change processor, referred pairs use the records),
    // the pairs' also when a submodel asks for them, otherwise at write
    // time (restart)
    const bool writeTime = this->owner().mesh().time().writeTime();
    if (writeTime)
    {
        // The narrow phase's tracked directions are not written: the run
        // forgets them as a restart from this time does, so both continue
        // identically (the next narrow phase starts from the centre line)
        histories_.forgetDirections();
        bodies_.restartTravel();
    }

    // Records written: those of contacts that ended forgotten, as
    // CollisionRecordList::update() does, in place (update() copies both
    // record lists into new ones for every parcel and step: two
    // allocations each, 6 % of a settled bed of spheres)
    const bool referred = referring();
    if (referred || keepRecords_ || writeTime)
    {
        writePairRecords();
        for (parcelType* p : bodies_.parcels())
        {
            keepAccessedRecords(mutablePairRecords(p->collisionRecords()));
            if (referred)
            {
                keepAccessedRecords(mutableWallRecords(p->collisionRecords()));
            }
        }
    }
    if (!referred && writeTime)
    {
        forAll(wallParcels_, m)
        {
            parcelType& p = bodies_.parcel(wallParcels_[m]);
            mutableWallRecords(p.collisionRecords()) = wallHistories_.run(m);
        }
    }

    // The dissipated energy so far, for a restart (the cloud writes its
    // output properties after the step)
    if (writeTime)
    {
        this->owner().outputProperties().set
        (
            "contactDissipatedEnergy",
            dissipatedEnergy()
        );
        this->owner().outputProperties().set("collisionSubCycles", subCycles_);
        this->owner().outputProperties().set
        (
            "collisionSubCyclesBelowNeed",
            stepsBelowNeed_
        );
    }

    if (nBufferWarnings_ > 0 && nBufferWarningsTotal_ > 5)
    {
        Info<< "    " << nBufferWarnings_ << " contacts with an overlap beyond"
            << " half the buffer layers (deltaBl)" << endl;
    }

    if (nUnconverged_ > 0)
    {
        WarningInFunction
            << nUnconverged_ << " ellipsoid contacts did not converge "
            << "in the narrow phase (robust and polynomial methods)" << endl;
    }
}


template<class CloudType>
void Foam::EllipsoidCollision<CloudType>::checkCoeffs() const
{
    const dictionary& coeffs = this->coeffDict();

    if
    (
        coeffs.found("deltaBl")
     && !(deltaBl_ >= 0 && deltaBl_ <= maxDistance_)
    )
    {
        FatalIOErrorInFunction(coeffs)
            << "Entry deltaBl = " << deltaBl_ << " is out of range: >= 0,"
            << " at most maxInteractionDistance = " << maxDistance_
            << exit(FatalIOError);
    }

    // The neighbour search bins the mesh's bounding box by this distance:
    // a longer one finds the same pairs
    const scalar diagonal = mag(this->owner().mesh().bounds().span());
    if (!(maxDistance_ <= diagonal))
    {
        FatalIOErrorInFunction(coeffs)
            << "Entry maxInteractionDistance = " << maxDistance_
            << " is out of range (0, " << diagonal << "] (the diagonal of the"
            << " mesh's bounding box)" << exit(FatalIOError);
    }

    // The wall faces in reach are taken from the interaction list of the
    // parcel's cell at the list build: complete while the parcel stays
    // within skin/2 of its position then (see buildNeighbourList)
    if (!(list_.skin() > 0) || !(list_.skin() <= maxDistance_))
    {
        FatalIOErrorInFunction(coeffs)
            << "Entry neighbourSkin = " << Foam::name(list_.skin())
            << " is out of range (0, maxInteractionDistance = "
            << Foam::name(maxDistance_) << "]" << exit(FatalIOError);
    }
}


template<class CloudType>
void Foam::EllipsoidCollision<CloudType>::printLaws() const
{
    Info<< "    Ellipsoid Hertz contact: stiffness ratio chi = " << chi_
        << ", buffer layer "
        << (deltaBl_ >= 0
            ? Foam::name(deltaBl_) + " m"
            : Foam::name(deltaBlRatio_) + " x smallest semi-axis").c_str()
        << ", " << pairContact_.description().c_str() << endl;
    if (wallContact_.description() != pairContact_.description())
    {
        Info<< "    walls: " << wallContact_.description().c_str() << endl;
    }
    const particleMaterials& materials = this->owner().constProps().materials();
    for (label a = 0; a < nMaterials_; ++a)
    {
        const std::string what
        (
            nMaterials_ > 1 ? "    " + materials.name(a) + ": " : "    "
        );
        for (label b = a; b < nMaterials_; ++b)
        {
            const contactProperties& l = pairProperties(a, b);
            const std::string with
            (
                nMaterials_ > 1 ? "with " + materials.name(b) + " " : ""
            );
            Info<< what.c_str() << with.c_str() << "E* = " << l.Estar
                << ", G* = " << l.Gstar << ", e = " << l.e
                << " (dashpot beta = " << l.beta << "), mu = " << l.mu
                << endl;
        }
        const contactProperties& l = wallProperties(a);
        Info<< what.c_str() << "walls: E* = " << l.Estar << ", e = " << l.e
            << " (beta = " << l.beta << "), mu = " << l.mu << endl;
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

template<class CloudType>
Foam::EllipsoidCollision<CloudType>::EllipsoidCollision
(
    const dictionary& dict,
    CloudType& owner
)
:
    ContactModel<CloudType>(dict, owner, typeName),
    nMaterials_(owner.constProps().materials().size()),
    pairContact_(this->coeffDict()),
    wallContact_(this->coeffDict().subDict("walls"), &pairContact_),
    pp_(),
    pw_(),
    deltaBl_(this->coeffDict().template lookupOrDefault<scalar>("deltaBl", -1)),
    deltaBlRatio_
    (
        getCheckedOrDefault<scalar>
        (
            this->coeffDict(), "deltaBlRatio", 0.05,
            [](const scalar r) { return r >= 0 && r < 1; }, " [0, 1)"
        )
    ),
    chi_(owner.constProps().stiffnessRatio()),
    nBufferWarnings_(0),
    nBufferWarningsTotal_(0),
    resolutionSteps_
    (
        getCheckedOrDefault<label>
        (
            this->coeffDict(), "collisionResolutionSteps", 50,
            [](const label n) { return n >= 1; }, ": >= 1"
        )
    ),
    method_(ellipsoidContact::method::automatic),
    il_
    (
        owner.mesh(),
        maxInteractionDistance(this->coeffDict()),
        false,
        this->coeffDict().template lookupOrDefault<word>
        (
            "U",
            owner.U().name()
        )
    ),
    nUnconverged_(0),
    dissipatedEnergy_(0),
    dissipatedEnergy0_
    (
        owner.outputProperties().template lookupOrDefault<scalar>
        (
            "contactDissipatedEnergy",
            0
        )
    ),
    elasticEnergy_(0),
    bodies_(),
    gathering_(false),
    deltaT_(owner.mesh().time().deltaTValue()),
    list_
    (
        this->coeffDict().template lookupOrDefault<scalar>
        (
            "neighbourSkin",
            0.25*maxInteractionDistance(this->coeffDict())
        )
    ),
    maxDistance_(maxInteractionDistance(this->coeffDict())),
    subCycles_
    (
        owner.outputProperties().template lookupOrDefault<label>
        (
            "collisionSubCycles",
            0
        )
    ),
    stepsBelowNeed_
    (
        owner.outputProperties().template lookupOrDefault<label>
        (
            "collisionSubCyclesBelowNeed",
            0
        )
    ),
    subCyclesTimeIndex_(-1),
    histories_(),
    keepRecords_(false),
    wallStart_(),
    wallFaces_(),
    wallParcels_(),
    wallHistories_(),
    nPairSides_(0),
    nWallContacts_(0),
    cellPositions_(),
    wallFaceBb_(),
    wallFaceIsBox_(),
    wallFaceNormal_(),
    wallFaceArea_(),
    recordContacts_(false),
    contacts_(),
    particleE_(),
    particleNu_(),
    selfEstar_(),
    rayleighFactorSqr_(),
    kicked_(),
    nKicked_(0),
    kickedValid_(false)
{
    checkCoeffs();
    makeLaws(this->coeffDict());

    // The narrow-phase methods a case may select
    static const Enum<ellipsoidContact::method> methods
    ({
        {ellipsoidContact::method::automatic, "automatic"},
        {ellipsoidContact::method::robust, "robust"},
        {ellipsoidContact::method::polynomial, "polynomial"},
    });
    method_ =
        methods.getOrDefault
        (
            "method", this->coeffDict(), ellipsoidContact::method::automatic
        );

    printLaws();
}


template<class CloudType>
Foam::EllipsoidCollision<CloudType>::EllipsoidCollision
(
    const EllipsoidCollision<CloudType>& cm
)
:
    ContactModel<CloudType>(cm),
    pairContact_(cm.coeffDict()),
    wallContact_(cm.coeffDict().subDict("walls"), &pairContact_),
    il_(cm.owner().mesh())
{
    NotImplemented;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class CloudType>
Foam::labelList
Foam::EllipsoidCollision<CloudType>::referralNeighbours() const
{
    DynamicList<label> procs;
    if (Pstream::parRun())
    {
        const mapDistribute& map = il_.cellMap();
        forAll(map.subMap(), proci)
        {
            if
            (
                proci != Pstream::myProcNo()
             && (map.subMap()[proci].size() || map.constructMap()[proci].size())
            )
            {
                procs.append(proci);
            }
        }
    }
    return labelList(std::move(procs));
}


template<class CloudType>
inline void Foam::EllipsoidCollision<CloudType>::selfContact
(
    const parcelType& p,
    scalar& mStar,
    scalar& RStar
) const
{
    // Worst case in the cloud: the fastest parcel hitting a copy of
    // itself head-on (m* = m/2, relative speed 2|U|) at its sharpest tip
    // (radius of curvature c^2/a for semi-axes a >= b >= c, R* = R/2);
    // a wall contact (m* = m, R* = R, speed |U|) lasts longer
    const vector& s = p.semiAxes();
    mStar = 0.5*p.mass();
    RStar = 0.5*(sqr(cmptMin(s))/cmptMax(s));
}


template<class CloudType>
inline typename Foam::EllipsoidCollision<CloudType>::collisionTimeFactors
Foam::EllipsoidCollision<CloudType>::timeFactors(const parcelType& p) const
{
    const label material = p.material();
    scalar mStar, RStar;
    selfContact(p, mStar, RStar);
    const scalar mByE2 = sqr(mStar/selfEstar_[material]);

    // Rayleigh time step, Rasera Eq. (13), for the report
    return
    {
        mByE2,
        mByE2/RStar,
        sqr(cmptMin(p.semiAxes()))*p.rho()/rayleighFactorSqr_[material]
    };
}


template<class CloudType>
inline void Foam::EllipsoidCollision<CloudType>::addCollisionTime
(
    const parcelType& p,
    const collisionTimeFactors& k,
    collisionTimeMinima& m
) const
{
    // Hertz collision duration (Johnson 1985)
    //     t_c = 2.868 (m*^2/(R* E*^2 v))^(1/5),
    // minimised through its monotonic argument: a parcel's in double as
    // (m*/E*)^2/R*/v where the steps stay in the normal range (no log per
    // parcel), else through its logarithm (the heavy, soft or resting
    // parcels of the accepted ranges, inputLimits.H, overflow it)
    auto normal = [](const scalar x) { return x > 1e-290 && x < 1e290; };
    const scalar v = max(2*mag(p.U()), VSMALL);
    const scalar arg = k.tcFactor/v;
    if (normal(k.mByE2) && normal(arg))
    {
        m.tcArg = min(m.tcArg, arg);
    }
    else
    {
        scalar mStar, RStar;
        selfContact(p, mStar, RStar);
        m.logTcArg = min
        (
            m.logTcArg,
            2*(Foam::log(mStar) - Foam::log(selfEstar_[p.material()]))
          - Foam::log(RStar) - Foam::log(v)
        );
    }
    m.rayleighSqr = min(m.rayleighSqr, k.rayleighSqr);
}


template<class CloudType>
Foam::scalar Foam::EllipsoidCollision<CloudType>::reducedCollisionTime
(
    collisionTimeMinima m,
    scalar* rayleighStep
) const
{
    reduce(m.tcArg, minOp<scalar>());
    reduce(m.logTcArg, minOp<scalar>());
    reduce(m.rayleighSqr, minOp<scalar>());
    if (rayleighStep)
    {
        *rayleighStep = Foam::sqrt(m.rayleighSqr)*constant::mathematical::pi;
    }
    if (m.tcArg < VGREAT)
    {
        m.logTcArg = min(m.logTcArg, Foam::log(m.tcArg));
    }
    return
        0.2*m.logTcArg < Foam::log(GREAT/2.868)
      ? 2.868*Foam::exp(0.2*m.logTcArg)
      : GREAT;
}


template<class CloudType>
Foam::scalar Foam::EllipsoidCollision<CloudType>::collisionTime
(
    scalar* rayleighStep
) const
{
    collisionTimeMinima m;
    for (const parcelType& p : this->owner())
    {
        addCollisionTime(p, m);
    }
    return reducedCollisionTime(m, rayleighStep);
}


template<class CloudType>
Foam::label Foam::EllipsoidCollision<CloudType>::nSubCycles() const
{
    // The minima of the parcels' last kicks if the step starts from
    // their velocities, with those of the parcels injected since
    // (appended to the cloud)
    scalar minRayleigh = GREAT;
    scalar minTc = GREAT;
    const label nInjected = this->owner().size() - nKicked_;
    if (kickedValid_ && nInjected >= 0)
    {
        collisionTimeMinima m = kicked_;
        const parcelType* p = nInjected ? this->owner().last() : nullptr;
        for (label i = 0; i < nInjected; ++i)
        {
            addCollisionTime(*p, m);
            p = static_cast<const parcelType*>(p->prev_);
        }
        minTc = reducedCollisionTime(m, &minRayleigh);
    }
    else
    {
        minTc = collisionTime(&minRayleigh);
    }
    kickedValid_ = false;

    const scalar deltaT = this->owner().mesh().time().deltaTValue();
    if (minTc >= GREAT)
    {
        return 1;
    }
    if (!(minTc*inputLimits::subCyclesMax >= deltaT*resolutionSteps_))
    {
        scalar Estar = 0;
        for (label m = 0; m < nMaterials_; ++m)
        {
            Estar = max(Estar, pairProperties(m, m).Estar);
        }
        FatalIOErrorInFunction(this->coeffDict())
            << "The shortest collision time, " << minTc << " s (Hertz, of"
            << " the fastest parcel of the cloud with E* = " << Estar
            << " Pa from the entries youngsModulus), resolved by"
            << " collisionResolutionSteps = " << resolutionSteps_
            << " steps, needs more than " << inputLimits::subCyclesMax
            << " collision sub-cycles of the time step deltaT = " << deltaT
            << " s: lower deltaT, or check youngsModulus and the parcels'"
            << " rho, size and U" << exit(FatalIOError);
    }
    const scalar dtC = minTc/resolutionSteps_;
    const label nNeeded = max(label(1), label(std::ceil(deltaT/dtC - 1e-9)));

    // The count rises at once to the need and falls to it only after the
    // need has stayed below it for twice as long as the fastest contact
    // lasts (resolutionSteps/count steps; twice for the slower, longer
    // contacts of ellipsoids). A sub-step that changes while
    // contacts last breaks the leapfrog's symmetry, and the need falls
    // within every contact as its parcels slow down: a head-on elastic
    // impact at 50 steps, its count lowered from 13 to 6 and back within
    // the contact, lost 2.6e-3 of its energy (1e-7 at a fixed step). A
    // settled bed comes down to its need within a few steps
    // Once per time step (the scene check asks too)
    const label timeIndex = this->owner().mesh().time().timeIndex();
    if (timeIndex == subCyclesTimeIndex_ && subCycles_ > 0)
    {
        return subCycles_;
    }
    subCyclesTimeIndex_ = timeIndex;

    label n = nNeeded;
    if (subCycles_ > nNeeded)
    {
        const label hold = 2*resolutionSteps_/subCycles_ + 1;
        if (++stepsBelowNeed_ < hold)
        {
            n = subCycles_;
        }
    }
    if (n != subCycles_ || n == nNeeded)
    {
        stepsBelowNeed_ = 0;
    }
    subCycles_ = n;

    if (debug || this->owner().mesh().time().timeIndex() % 100 == 1)
    {
        Info<< "    Collision time " << minTc << " s / "
            << resolutionSteps_ << " steps = " << dtC
            << " s (Rayleigh time step, Rasera Eq. 13: " << minRayleigh
            << " s): " << n << " sub-cycles of " << deltaT/n << " s" << nl
            << "    Neighbour list (skin " << list_.skin() << " m): "
            << list_.nPairs() << " candidate pairs, "
            << list_.nBuilds() << " builds so far" << endl;
    }

    return n;
}


template<class CloudType>
void Foam::EllipsoidCollision<CloudType>::collide()
{
    preInteraction();

    // Real pairs and walls on the contact bodies, then the parcels
    // referred from other processors or across cyclics on the parcels
    if (referring())
    {
        PstreamBuffers pBufs(Pstream::commsTypes::nonBlocking);
        const label startOfRequests = Pstream::nRequests();
        il_.sendReferredData(this->owner().cellOccupancy(), pBufs);
        realRealInteraction();
        wallInteraction();
        bodies_.scatter();
        il_.receiveReferredData(pBufs, startOfRequests);
        realReferredInteraction();
    }
    else
    {
        realRealInteraction();
        wallInteraction();
        bodies_.scatter();
    }

    postInteraction();
}


// ************************************************************************* //
