/*---------------------------------------------------------------------------*\
    chargedFoam: charged dielectric particles for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "EllipsoidCollision.H"
#include "mathematicalConstants.H"
#include "volFields.H"
#include "PstreamBuffers.H"
#include "cutoffPairs.H"

#include <algorithm>
#include <type_traits>

// * * * * * * * * * * * * * * * Local Functions  * * * * * * * * * * * * * //

namespace
{

//- Keep the accessed records (marked unaccessed again) in their order
template<class Record>
void keepAccessedRecords(Foam::DynamicList<Record>& records)
{
    Foam::label n = 0;
    forAll(records, i)
    {
        if (records[i].accessed())
        {
            records[i].setUnaccessed();
            if (n != i)
            {
                records[n] = records[i];
            }
            ++n;
        }
    }
    records.setSize(n);     // a DynamicList keeps its capacity
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * Static Functions  * * * * * * * * * * * * * //

template<class CloudType>
Foam::scalar Foam::EllipsoidCollision<CloudType>::restitution
(
    const scalar beta
)
{
    // x'' = -max(0, x^3/2 + gamma x^1/4 x'), x(0) = 0, x'(0) = 1; the
    // force never pulls, so once it vanishes while separating the parcel
    // flies off freely and e = -x' (see Description)
    const scalar gamma = Foam::sqrt(5.0)*mag(beta);

    auto accel = [gamma](const scalar x, const scalar v)
    {
        const scalar xp = max(x, scalar(0));
        return -max(xp*Foam::sqrt(xp) + gamma*Foam::sqrt(Foam::sqrt(xp))*v, 0.0);
    };

    // RK4; the contact lasts ~3.2 time units
    const scalar h = 2e-4;
    scalar x = 0, v = 1;
    for (label i = 0; i < 1000000; ++i)
    {
        const scalar k1x = v, k1v = accel(x, v);
        const scalar k2x = v + 0.5*h*k1v, k2v = accel(x + 0.5*h*k1x, v + 0.5*h*k1v);
        const scalar k3x = v + 0.5*h*k2v, k3v = accel(x + 0.5*h*k2x, v + 0.5*h*k2v);
        const scalar k4x = v + h*k3v, k4v = accel(x + h*k3x, v + h*k3v);
        x += h/6*(k1x + 2*k2x + 2*k3x + k4x);
        v += h/6*(k1v + 2*k2v + 2*k3v + k4v);

        if (x <= 0 || (v < 0 && accel(x, v) == 0))
        {
            return max(-v, scalar(0));
        }
    }
    return 0;
}


template<class CloudType>
Foam::scalar Foam::EllipsoidCollision<CloudType>::dampingRatio(const scalar e)
{
    if (e >= 1)
    {
        return 0;
    }

    // restitution(beta) falls monotonically with |beta|: bracket, bisect
    scalar lo = 0, hi = 1;
    while (restitution(-hi) > e && hi < 1e3)
    {
        hi *= 2;
    }
    for (label iter = 0; iter < 60; ++iter)
    {
        const scalar mid = 0.5*(lo + hi);
        if (restitution(-mid) > e)
        {
            lo = mid;
        }
        else
        {
            hi = mid;
        }
    }
    return -0.5*(lo + hi);
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

template<class CloudType>
Foam::scalar Foam::EllipsoidCollision<CloudType>::readPositive
(
    const dictionary& d,
    const word& key
)
{
    const scalar value = d.get<scalar>(key);
    if (!(value > 0) || !std::isfinite(value))
    {
        FatalIOErrorInFunction(d)
            << "Entry " << key << " = " << value << " in "
            << d.name().c_str() << " is out of range: it must be finite and > 0"
            << exit(FatalIOError);
    }
    return value;
}


template<class CloudType>
typename Foam::EllipsoidCollision<CloudType>::contactLaw
Foam::EllipsoidCollision<CloudType>::makeLaw
(
    const scalar E1, const scalar nu1,
    const scalar E2, const scalar nu2,
    const scalar e, const scalar mu,
    const dictionary& dict
)
{
    const scalar muR = dict.template lookupOrDefault<scalar>("rollingFriction", 0);
    if (!(muR >= 0) || !std::isfinite(muR))
    {
        FatalIOErrorInFunction(dict)
            << "Entry rollingFriction = " << muR << " in "
            << dict.name().c_str() << " is out of range: it must be >= 0"
            << exit(FatalIOError);
    }
    if (!(e > 0 && e <= 1))
    {
        FatalIOErrorInFunction(dict)
            << "Entry e (restitution coefficient) = " << e << " in "
            << dict.name().c_str() << " is out of range (0, 1]"
            << exit(FatalIOError);
    }
    if (!(mu >= 0) || !std::isfinite(mu))
    {
        FatalIOErrorInFunction(dict)
            << "Entry mu (friction coefficient) = " << mu << " in "
            << dict.name().c_str() << " is out of range: it must be >= 0"
            << exit(FatalIOError);
    }
    for (const scalar nu : {nu1, nu2})
    {
        if (!(nu > -1 && nu <= 0.5))
        {
            FatalIOErrorInFunction(dict)
                << "Entry poissonsRatio = " << nu
                << " is out of range (-1, 0.5]" << exit(FatalIOError);
        }
    }

    contactLaw law;

    // Ruan Eq. (38)
    law.Estar = 1/((1 - sqr(nu1))/E1 + (1 - sqr(nu2))/E2);

    // Rasera Eq. (12) with G = E/(2(1 + nu))
    const scalar G1 = E1/(2*(1 + nu1));
    const scalar G2 = E2/(2*(1 + nu2));
    law.Gstar = 1/((2 - nu1)/G1 + (2 - nu2)/G2);

    law.beta = dampingRatio(e);
    law.mu = mu;
    law.e = e;
    law.muR = muR;
    return law;
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
    const ellipsoid body(p.semiAxes(), x, p.orientation());
    const scalar dBl = bufferLayer(p);
    return dBl > 0 ? body.inflated(dBl) : body;
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

    // Eq. (52): E > m v0^2/((2 delta_bl)^(5/2) R^(1/2))
    const scalar Emin =
        mStar*sqr(vn)/(Foam::pow(twoDeltaBl, 2.5)*Foam::sqrt(R));

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
Foam::vector Foam::EllipsoidCollision<CloudType>::contactForce
(
    const ellipsoidContact::result& c,
    const vector& vRel,
    const scalar mStar,
    const contactLaw& law,
    vector& xi,
    const scalar energyWeight
)
{
    const scalar dt = this->owner().mesh().time().deltaTValue();

    const vector& n = c.n;
    const scalar delta = c.overlap;
    const scalar R = c.reducedRadius;
    const scalar vn = vRel & n;             // > 0: approaching
    const vector vt = vRel - vn*n;

    // Normal: Hertz (Ruan Eq. 36) + dashpot (Rasera Eq. 9), no tension
    const scalar sqrtRdelta = Foam::sqrt(R*delta);
    const scalar Sn = 2*law.Estar*sqrtRdelta;                // dF/d delta
    const scalar etaN =
        2*Foam::sqrt(5.0/6.0)*mag(law.beta)*Foam::sqrt(Sn*mStar);
    const scalar Fe = (4.0/3.0)*law.Estar*sqrtRdelta*delta;
    const scalar Fn = max(Fe + etaN*vn, scalar(0));

    vector F = -Fn*n;

    // Bookkeeping: the elastic energy changes by Fe vn dt, the contact
    // force does -Fn vn dt of work: the difference (Fn - Fe) vn dt >= 0
    // is dissipated (dashpot, or the released energy under the no-tension
    // cut)
    scalar dissipated = (Fn - Fe)*vn*dt;
    scalar elastic = 0.4*Fe*delta;

    if (tangential_ == tangentialModel::coulomb)
    {
        // Ruan Eq. (39): sliding friction against the slip velocity
        const scalar vtMag = mag(vt);
        if (vtMag > VSMALL)
        {
            F -= law.mu*Fn*vt/vtMag;
        }
        dissipated += law.mu*Fn*vtMag*dt;
    }
    else
    {
        // Mindlin spring with history (Rasera Eqs. 7, 8, 11, 12): keep xi
        // in the current tangent plane with its length, then stretch it
        const scalar xiMag = mag(xi);
        xi -= (xi & n)*n;
        const scalar xiProjMag = mag(xi);
        if (xiProjMag > VSMALL)
        {
            xi *= xiMag/xiProjMag;
        }
        xi += vt*dt;

        const scalar kT = 8*law.Gstar*sqrtRdelta;
        const scalar springBefore = 0.5*kT*magSqr(xi - vt*dt);
        const scalar etaT =
            2*Foam::sqrt(5.0/6.0)*mag(law.beta)*Foam::sqrt(kT*mStar);
        vector Ft = -kT*xi - etaT*vt;
        const scalar FtMag = mag(Ft);
        if (FtMag > law.mu*Fn)
        {
            // Slip: friction limit, spring length consistent with it
            Ft *= law.mu*Fn/FtMag;
            xi = kT > VSMALL ? -Ft/kT : vector(Zero);
        }
        F += Ft;

        // Bookkeeping: the work taken from the relative motion, -Ft.vt dt,
        // goes into the spring or is dissipated (dashpot, slip)
        const scalar springAfter = 0.5*kT*magSqr(xi);
        dissipated += -(Ft & vt)*dt - (springAfter - springBefore);
        elastic += springAfter;
    }

    dissipatedEnergy_ += energyWeight*dissipated;
    elasticEnergy_ += energyWeight*elastic;

    return F;
}


template<class CloudType>
Foam::vector Foam::EllipsoidCollision<CloudType>::rollingTorque
(
    const ellipsoidContact::result& c,
    const vector& F,
    const vector& w,
    const scalar Ieff,
    const contactLaw& law,
    const scalar energyWeight
)
{
    const scalar wMag = mag(w);
    if (law.muR <= 0 || wMag < VSMALL)
    {
        return Zero;
    }

    // Ai et al. (2011) model A, limited so that w is not reversed: a
    // half kick dt/2 M/I must not exceed |w| (both kicks of a step)
    const scalar dt = this->owner().mesh().time().deltaTValue();
    const scalar Fn = mag(F & c.n);
    const scalar Mmag = min(law.muR*c.reducedRadius*Fn, Ieff*wMag/dt);

    dissipatedEnergy_ += energyWeight*Mmag*wMag*dt;

    return -Mmag*w/wMag;
}


template<class CloudType>
void Foam::EllipsoidCollision<CloudType>::preInteraction()
{
    nBufferWarnings_ = 0;
    elasticEnergy_ = 0;
    nUnconverged_ = 0;
    contacts_.clear();

    // Positions and angular velocities of the parcels, once per collide
    parcels_.clear();
    x_.clear();
    omega_.clear();
    for (parcelType& p : this->owner())
    {
        p.f() = Zero;
        p.torque() = Zero;
        parcels_.append(&p);
        x_.append(p.centre());
        omega_.append(p.omega());
    }

    // The same for the parcels of cells with referred neighbours (other
    // processors, cyclics)
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

    if (!neighbourListValid())
    {
        buildNeighbourList();
    }
}


template<class CloudType>
bool Foam::EllipsoidCollision<CloudType>::neighbourListValid() const
{
    if (listParcels_.size() != parcels_.size())
    {
        return false;
    }
    const scalar maxMove2 = sqr(0.5*skin_);
    forAll(parcels_, i)
    {
        const parcelType& p = *parcels_[i];
        if
        (
            listParcels_[i] != parcels_[i]
         || listIds_[i].first() != p.origProc()
         || listIds_[i].second() != p.origId()
         || magSqr(x_[i] - listX_[i]) > maxMove2
        )
        {
            return false;
        }
    }
    return true;
}


template<class CloudType>
void Foam::EllipsoidCollision<CloudType>::buildNeighbourList()
{
    ++nListBuilds_;
    const label n = parcels_.size();
    listParcels_ = parcels_;
    listX_ = x_;
    listIds_.setSize(n);
    scalarField r(n);
    scalar rMax = 0;
    forAll(parcels_, i)
    {
        const parcelType& p = *parcels_[i];
        listIds_[i] = labelPair(p.origProc(), p.origId());
        r[i] = cmptMax(p.semiAxes()) + bufferLayer(p);
        rMax = max(rMax, r[i]);
    }

    // Partners j > i of each i; the cell list visits the targets i in
    // order, so the rows come out compressed (partners sorted per row
    // below: evaluation in cloud order)
    listStart_.setSize(n + 1);
    listPartners_.clear();
    label row = 0;
    listStart_[0] = 0;
    if (n > 1)
    {
        forPairsWithinCutoff
        (
            x_, x_, 2*rMax + skin_, 0,
            [&](const label i, const label j, const vector&, const scalar d2)
            {
                if (j > i && d2 < sqr(r[i] + r[j] + skin_))
                {
                    while (row < i)
                    {
                        listStart_[++row] = listPartners_.size();
                    }
                    listPartners_.append(j);
                }
            }
        );
    }
    while (row < n)
    {
        listStart_[++row] = listPartners_.size();
    }
    for (label i = 0; i < n; ++i)
    {
        std::sort
        (
            listPartners_.begin() + listStart_[i],
            listPartners_.begin() + listStart_[i + 1]
        );
    }
}


template<class CloudType>
void Foam::EllipsoidCollision<CloudType>::evaluatePair
(
    parcelType& pA,
    const point& xA,
    const vector& wA,
    parcelType& pB,
    const point& xB,
    const vector& wB,
    const bool referred
)
{
    // A contact with a referred parcel is also evaluated on the referred
    // parcel's processor: half of its energy is booked here
    const scalar energyWeight = referred ? 0.5 : 1;

    // Bounding spheres of the collision shells
    const scalar rA = cmptMax(pA.semiAxes()) + bufferLayer(pA);
    const scalar rB = cmptMax(pB.semiAxes()) + bufferLayer(pB);
    if (magSqr(xA - xB) > sqr(rA + rB))
    {
        return;
    }

    // A referred pair is evaluated on both processors: in one canonical
    // order (lower origProc, origId first), so both solve the same contact
    // problem (the referred copy's position may still differ at round-off;
    // tribocharging balances by charging such a pair on one side only)
    const bool swapped =
        referred
     && (
            pA.origProc() > pB.origProc()
         || (pA.origProc() == pB.origProc() && pA.origId() > pB.origId())
        );
    parcelType& p1 = swapped ? pB : pA;
    parcelType& p2 = swapped ? pA : pB;
    const point& x1 = swapped ? xB : xA;
    const point& x2 = swapped ? xA : xB;
    const scalar r1 = swapped ? rB : rA;
    const scalar r2 = swapped ? rA : rB;

    // Two spheres: the analytic fast path, without ellipsoid objects
    ellipsoidContact::result c =
        p1.isSphere() && p2.isSphere()
      ? ellipsoidContact::sphereSphere(x1, r1, x2, r2)
      : ellipsoidContact::contact(shell(p1, x1), shell(p2, x2), method_);
    if (swapped)
    {
        std::swap(c.x1, c.x2);
        c.n = -c.n;
    }

    if (!c.contact || c.overlap <= 0)
    {
        return;
    }

    if (!c.converged)
    {
        ++nUnconverged_;
    }

    if (recordContacts_)
    {
        contacts_.append({&pA, &pB, xA, xB, c, rA, -1, referred});
    }

    // Contact point: the midpoint (exact angular momentum balance)
    const point xc = 0.5*(c.x1 + c.x2);
    const vector vRel =
        pointVelocity(pA.U(), wA, xA, xc) - pointVelocity(pB.U(), wB, xB, xc);
    const scalar mStar = pA.mass()*pB.mass()/(pA.mass() + pB.mass());

    vector& xiAB =
        pA.collisionRecords().matchPairRecord
        (
            pB.origProc(),
            pB.origId()
        ).collisionData();
    vector& xiBA =
        pB.collisionRecords().matchPairRecord
        (
            pA.origProc(),
            pA.origId()
        ).collisionData();

    const vector F = contactForce(c, vRel, mStar, pp_, xiAB, energyWeight);
    xiBA = -xiAB;

    checkBufferLayer
    (
        pA,
        &pB,
        c.overlap,
        bufferLayer(pA) + bufferLayer(pB),
        vRel & c.n,
        mStar,
        c.reducedRadius
    );

    // Rolling friction, limited by the smaller rotational inertia
    const vector Mr =
        pp_.muR > 0
      ? rollingTorque
        (
            c, F, wA - wB,
            min
            (
                cmptMin(pA.principalMoments()),
                cmptMin(pB.principalMoments())
            ),
            pp_, energyWeight
        )
      : Zero;

    // Forces and torques about the centroids (Ruan Eq. 40)
    pA.f() += F;
    pB.f() -= F;
    pA.torque() += ((xc - xA) ^ F) + Mr;
    pB.torque() -= ((xc - xB) ^ F) + Mr;
}


template<class CloudType>
void Foam::EllipsoidCollision<CloudType>::realRealInteraction()
{
    forAll(parcels_, i)
    {
        parcelType& pA = *parcels_[i];
        const point& xA = x_[i];
        const vector& wA = omega_[i];
        for (label k = listStart_[i]; k < listStart_[i + 1]; ++k)
        {
            const label j = listPartners_[k];
            evaluatePair(pA, xA, wA, *parcels_[j], x_[j], omega_[j]);
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

    forAll(ril, refCelli)
    {
        for (parcelType& referred : referredParticles[refCelli])
        {
            const point xR = referred.centre();
            const vector wR = referred.omega();
            for (const label realCelli : ril[refCelli])
            {
                const DynamicList<parcelType*>& cell = cellOccupancy[realCelli];
                forAll(cell, k)
                {
                    evaluatePair
                    (
                        *cell[k], cellPositions_[realCelli][k],
                        cell[k]->omega(),
                        referred, xR, wR, true
                    );
                }
            }
        }
    }
}


template<class CloudType>
void Foam::EllipsoidCollision<CloudType>::wallInteraction()
{
    const polyMesh& mesh = this->owner().mesh();
    const labelListList& directWallFaces = il_.dwfil();

    // Bounding boxes of the boundary faces (the mesh is static)
    if (wallFaceBb_.size() != mesh.nBoundaryFaces())
    {
        wallFaceBb_.setSize(mesh.nBoundaryFaces());
        forAll(wallFaceBb_, bFacei)
        {
            wallFaceBb_[bFacei] = boundBox
            (
                mesh.points(),
                mesh.faces()[mesh.nInternalFaces() + bFacei],
                false
            );
        }
    }
    const labelListList& referredWallFaces = il_.rwfilInverse();

    // Contacts of one parcel (contact points on the walls) to keep
    // coplanar neighbour faces from counting one contact twice
    DynamicList<point> contactPoints;

    forAll(parcels_, i)
    {
        parcelType& p = *parcels_[i];
        const label celli = p.cell();
        if
        (
            directWallFaces[celli].empty()
         && referredWallFaces[celli].empty()
        )
        {
            continue;
        }
        {
            const point& xp = x_[i];
            const vector& wp = omega_[i];
            const bool sphere = p.isSphere();
            const scalar r = cmptMax(p.semiAxes()) + bufferLayer(p);
            // The collision shell, made for the first face in reach
            std::unique_ptr<const ellipsoid> ePtr;
            contactPoints.clear();

            // face, its points, centre, unit normal out of the domain, patch
            auto wallFace =
            [&]
            (
                const face& f,
                const pointField& pts,
                const point& fc,
                const vector& nOutOfDomain,
                const scalar faceArea,
                const boundBox& bb,
                const label patchi
            )
            {
                // The face's plane or its bounding box out of reach of the
                // shell's bounding sphere: no contact (cheap tests before
                // any geometry; the box test drops the coplanar neighbours
                // of the face in contact)
                const scalar h = (xp - fc) & nOutOfDomain;
                if (h <= -r || h >= r)
                {
                    return;
                }
                if (magSqr(xp - bb.nearest(xp)) >= sqr(r))
                {
                    return;
                }

                if (!sphere && !ePtr)
                {
                    ePtr.reset(new ellipsoid(shell(p, xp)));
                }
                const ellipsoidContact::result c =
                    sphere
                  ? ellipsoidContact::spherePlane(xp, r, fc, -nOutOfDomain)
                  : ellipsoidContact::ellipsoidPlane(*ePtr, fc, -nOutOfDomain);
                if (!c.contact || c.overlap <= 0)
                {
                    return;
                }

                // The contact belongs to this face if its plane point lies
                // on the face (within round-off of the face size)
                // (bounding box first: most coplanar neighbours fail it)
                const scalar tol = 1e-9*Foam::sqrt(faceArea) + SMALL*r;
                if
                (
                    cmptMin(c.x2 - bb.min()) < -tol
                 || cmptMax(c.x2 - bb.max()) > tol
                )
                {
                    return;
                }
                if (f.nearestPoint(c.x2, pts).distance() > tol)
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
                contactPoints.append(c.x2);

                if (recordContacts_)
                {
                    contacts_.append({&p, nullptr, xp, xp, c, r, patchi, false});
                }

                const point xc = 0.5*(c.x1 + c.x2);
                const vector vRel = pointVelocity(p.U(), wp, xp, xc);
                vector& xi =
                    p.collisionRecords().matchWallRecord
                    (
                        xc - xp,
                        r
                    ).collisionData();

                const vector F = contactForce(c, vRel, p.mass(), pw_, xi);
                const vector Mr =
                    pw_.muR > 0
                  ? rollingTorque
                    (
                        c, F, wp, cmptMin(p.principalMoments()), pw_
                    )
                  : Zero;
                checkBufferLayer
                (
                    p, nullptr, c.overlap, bufferLayer(p),
                    vRel & c.n, p.mass(), c.reducedRadius
                );
                p.f() += F;
                p.torque() += ((xc - xp) ^ F) + Mr;
            };

            // Mesh face centres and areas are cached by the mesh
            for (const label facei : directWallFaces[celli])
            {
                const vector& Sf = mesh.faceAreas()[facei];
                const scalar magSf = mag(Sf);
                wallFace
                (
                    mesh.faces()[facei],
                    mesh.points(),
                    mesh.faceCentres()[facei],
                    Sf/magSf,
                    magSf,
                    wallFaceBb_[facei - mesh.nInternalFaces()],
                    // The patch only for the listed contacts (a search)
                    recordContacts_ ? mesh.boundaryMesh().whichPatch(facei) : -1
                );
            }

            for (const label rwfi : referredWallFaces[celli])
            {
                const referredWallFace& rwf = il_.referredWallFaces()[rwfi];
                const pointField& pts = rwf.points();
                wallFace
                (
                    rwf,
                    pts,
                    rwf.centre(pts),
                    rwf.unitNormal(pts),
                    rwf.mag(pts),
                    boundBox(pts, rwf, false),
                    rwf.patchIndex()
                );
            }
        }
    }
}


template<class CloudType>
void Foam::EllipsoidCollision<CloudType>::postInteraction()
{
    // Forget the history of contacts that ended: what
    // CollisionRecordList::update() does, in place (update() copies both
    // record lists into new ones for every parcel and step: two
    // allocations each, 6 % of a settled bed of spheres). The lists
    // belong to the (non-const) parcels; CollisionRecordList only has
    // const accessors.
    for (parcelType* p : parcels_)
    {
        auto& records = p->collisionRecords();
        typedef typename std::decay<decltype(records.pairRecords())>::type
            pairList;
        typedef typename std::decay<decltype(records.wallRecords())>::type
            wallList;
        keepAccessedRecords(const_cast<pairList&>(records.pairRecords()));
        keepAccessedRecords(const_cast<wallList&>(records.wallRecords()));
    }

    // The dissipated energy so far, for a restart (the cloud writes its
    // output properties after the step)
    if (this->owner().mesh().time().writeTime())
    {
        this->owner().outputProperties().set
        (
            "contactDissipatedEnergy",
            dissipatedEnergy()
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


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

template<class CloudType>
Foam::EllipsoidCollision<CloudType>::EllipsoidCollision
(
    const dictionary& dict,
    CloudType& owner
)
:
    CollisionModel<CloudType>(dict, owner, typeName),
    pp_(),
    pw_(),
    tangential_(tangentialModel::mindlin),
    deltaBl_(this->coeffDict().template lookupOrDefault<scalar>("deltaBl", -1)),
    deltaBlRatio_
    (
        this->coeffDict().template lookupOrDefault<scalar>("deltaBlRatio", 0.05)
    ),
    chi_
    (
        owner.constProps().dict().template lookupOrDefault<scalar>
        (
            "stiffnessRatio",
            1
        )
    ),
    nBufferWarnings_(0),
    nBufferWarningsTotal_(0),
    resolutionSteps_
    (
        this->coeffDict().template lookupOrDefault<label>
        (
            "collisionResolutionSteps",
            50
        )
    ),
    method_(ellipsoidContact::method::automatic),
    il_
    (
        owner.mesh(),
        readPositive(this->coeffDict(), "maxInteractionDistance"),
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
    parcels_(),
    x_(),
    omega_(),
    skin_
    (
        this->coeffDict().template lookupOrDefault<scalar>
        (
            "neighbourSkin",
            0.25*readPositive(this->coeffDict(), "maxInteractionDistance")
        )
    ),
    listParcels_(),
    listIds_(),
    listX_(),
    listStart_(),
    listPartners_(),
    nListBuilds_(0),
    cellPositions_(),
    wallFaceBb_(),
    recordContacts_(false),
    contacts_(),
    particleE_(0),
    particleNu_(0)
{
    const dictionary& coeffs = this->coeffDict();
    const dictionary& props = owner.constProps().dict();

    if (!(chi_ > 0 && chi_ <= 1))
    {
        FatalIOErrorInFunction(props)
            << "Entry stiffnessRatio (chi = E_R/E_O, Ruan Eq. 44) = " << chi_
            << " is out of range (0, 1]" << exit(FatalIOError);
    }
    if (this->coeffDict().found("deltaBl") && !(deltaBl_ >= 0))
    {
        FatalIOErrorInFunction(this->coeffDict())
            << "Entry deltaBl = " << deltaBl_ << " is out of range: >= 0"
            << exit(FatalIOError);
    }
    if (!(deltaBlRatio_ >= 0 && deltaBlRatio_ < 1))
    {
        FatalIOErrorInFunction(this->coeffDict())
            << "Entry deltaBlRatio = " << deltaBlRatio_
            << " is out of range [0, 1)" << exit(FatalIOError);
    }

    // Reduced stiffness: all contact moduli scaled by chi
    const scalar E = chi_*readPositive(props, "youngsModulus");
    const scalar nu = props.get<scalar>("poissonsRatio");
    particleE_ = E;
    particleNu_ = nu;

    pp_ = makeLaw
    (
        E, nu, E, nu,
        coeffs.get<scalar>("e"), coeffs.get<scalar>("mu"),
        coeffs
    );

    const dictionary& walls = coeffs.subDict("walls");
    pw_ = makeLaw
    (
        E, nu,
        chi_*readPositive(walls, "youngsModulus"),
        walls.get<scalar>("poissonsRatio"),
        walls.get<scalar>("e"), walls.get<scalar>("mu"),
        walls
    );

    const word tModel
    (
        coeffs.template lookupOrDefault<word>("tangentialModel", "mindlin")
    );
    if (tModel == "coulomb")
    {
        tangential_ = tangentialModel::coulomb;
    }
    else if (tModel != "mindlin")
    {
        FatalIOErrorInFunction(coeffs)
            << "Entry tangentialModel " << tModel
            << " is unknown: valid are coulomb, mindlin" << exit(FatalIOError);
    }

    const word m(coeffs.template lookupOrDefault<word>("method", "automatic"));
    if (m == "robust")
    {
        method_ = ellipsoidContact::method::robust;
    }
    else if (m == "polynomial")
    {
        method_ = ellipsoidContact::method::polynomial;
    }
    else if (m != "automatic")
    {
        FatalIOErrorInFunction(coeffs)
            << "Entry method " << m
            << " is unknown: valid are automatic, robust, polynomial"
            << exit(FatalIOError);
    }

    if (!(skin_ > 0) || !std::isfinite(skin_))
    {
        FatalIOErrorInFunction(coeffs)
            << "Entry neighbourSkin = " << skin_
            << " is out of range: it must be finite and > 0"
            << exit(FatalIOError);
    }

    if (resolutionSteps_ < 1)
    {
        FatalIOErrorInFunction(coeffs)
            << "Entry collisionResolutionSteps = " << resolutionSteps_
            << " is out of range: >= 1" << exit(FatalIOError);
    }

    Info<< "    Ellipsoid Hertz contact: stiffness ratio chi = " << chi_
        << ", buffer layer "
        << (deltaBl_ >= 0
            ? Foam::name(deltaBl_) + " m"
            : Foam::name(deltaBlRatio_) + " x smallest semi-axis").c_str()
        << nl << "    E* = " << pp_.Estar
        << ", G* = " << pp_.Gstar << ", e = " << pp_.e
        << " (dashpot beta = " << pp_.beta << "), mu = " << pp_.mu
        << ", tangential " << tModel << nl
        << "    walls: E* = " << pw_.Estar << ", e = " << pw_.e
        << " (beta = " << pw_.beta << "), mu = " << pw_.mu << endl;
}


template<class CloudType>
Foam::EllipsoidCollision<CloudType>::EllipsoidCollision
(
    const EllipsoidCollision<CloudType>& cm
)
:
    CollisionModel<CloudType>(cm),
    il_(cm.owner().mesh())
{
    NotImplemented;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class CloudType>
Foam::label Foam::EllipsoidCollision<CloudType>::nSubCycles() const
{
    // Worst case in the cloud: the fastest parcel hitting a copy of
    // itself head-on (m* = m/2, relative speed 2|U|) at its sharpest tip
    // (radius of curvature c^2/a for semi-axes a >= b >= c, R* = R/2);
    // a wall contact (m* = m, R* = R, speed |U|) lasts longer
    // Hertz collision duration (Johnson 1985)
    //     t_c = 2.868 (m*^2/(R* E*^2 v))^(1/5),
    // minimised through its monotonic argument (one pow per step)
    scalar minTcArg = GREAT;
    scalar minRayleigh = GREAT;

    const scalar E = pp_.Estar;
    const scalar G = particleE_/(2*(1 + particleNu_));
    for (const parcelType& p : this->owner())
    {
        const vector& s = p.semiAxes();
        const scalar Rtip = sqr(cmptMin(s))/cmptMax(s);
        const scalar m = p.mass();
        const scalar v = max(2*mag(p.U()), VSMALL);

        minTcArg = min(minTcArg, sqr(0.5*m)/(0.5*Rtip*sqr(E)*v));

        // Rayleigh time step, Rasera Eq. (13), for the report
        minRayleigh = min
        (
            minRayleigh,
            cmptMin(s)*Foam::sqrt(p.rho())
        );
    }
    reduce(minTcArg, minOp<scalar>());
    reduce(minRayleigh, minOp<scalar>());
    const scalar minTc =
        minTcArg < GREAT ? 2.868*Foam::pow(minTcArg, 0.2) : GREAT;
    minRayleigh *=
        constant::mathematical::pi/Foam::sqrt(G)/(0.8766 + 0.163*particleNu_);

    const scalar deltaT = this->owner().mesh().time().deltaTValue();
    if (minTc >= GREAT)
    {
        return 1;
    }
    const scalar dtC = minTc/resolutionSteps_;
    const label n = max(label(1), label(std::ceil(deltaT/dtC - 1e-9)));

    if (debug || this->owner().mesh().time().timeIndex() % 100 == 1)
    {
        Info<< "    Collision time " << minTc << " s / "
            << resolutionSteps_ << " steps = " << dtC
            << " s (Rayleigh time step, Rasera Eq. 13: " << minRayleigh
            << " s): " << n << " sub-cycles of " << deltaT/n << " s" << nl
            << "    Neighbour list (skin " << skin_ << " m): "
            << listPartners_.size() << " candidate pairs, "
            << nListBuilds_ << " builds so far" << endl;
    }

    return n;
}


template<class CloudType>
void Foam::EllipsoidCollision<CloudType>::collide()
{
    preInteraction();

    if (referring())
    {
        PstreamBuffers pBufs(Pstream::commsTypes::nonBlocking);
        const label startOfRequests = Pstream::nRequests();
        il_.sendReferredData(this->owner().cellOccupancy(), pBufs);
        realRealInteraction();
        il_.receiveReferredData(pBufs, startOfRequests);
        realReferredInteraction();
    }
    else
    {
        realRealInteraction();
    }

    wallInteraction();
    postInteraction();
}


// ************************************************************************* //
