/*---------------------------------------------------------------------------*\
    chargedFoam: charged dielectric particles for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "RaseraTriboCharging.H"
#include "ellipsoid.H"
#include "wallPolyPatch.H"
#include "mathematicalConstants.H"
#include "processorHalo.H"
#include "checkedEntry.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

template<class CloudType>
Foam::scalar Foam::RaseraTriboCharging<CloudType>::get
(
    const dictionary& d,
    const word& key,
    const bool positive
)
{
    if (!d.found(key))
    {
        FatalIOErrorInFunction(d)
            << "Entry " << key << " is missing in " << d.name().c_str()
            << exit(FatalIOError);
    }
    return getChecked<scalar>
    (
        d, key,
        [positive](const scalar v)
        {
            return
                std::isfinite(v)
             && (!positive || (v >= 0 && v <= inputLimits::large));
        },
        positive
      ? ": it must be finite and >= 0, at most "
      + Foam::name(inputLimits::large)
      : ": it must be finite"
    );
}


template<class CloudType>
Foam::scalar Foam::RaseraTriboCharging<CloudType>::getOwn
(
    const dictionary* own,
    const dictionary& parent,
    const word& key,
    const bool positive
)
{
    return own && own->found(key) ? get(*own, key, positive)
                                  : get(parent, key, positive);
}


template<class CloudType>
void Foam::RaseraTriboCharging<CloudType>::checkGamma
(
    const scalar Gamma,
    const dictionary& d,
    const std::string& where,
    const bool fromWorkFunctions
)
{
    if (!(mag(Gamma) <= inputLimits::fieldMax))
    {
        FatalIOErrorInFunction(d)
            << "Entry "
            << (
                   fromWorkFunctions
                 ? "workFunction (with cutoffDistance and the other"
                   " material's workFunction)"
                 : "Gamma"
               )
            << where.c_str() << " in " << d.name().c_str()
            << " gives Gamma = " << Gamma
            << " V/m: out of range, |Gamma| must be at most "
            << inputLimits::fieldMax << " V/m" << exit(FatalIOError);
    }
}


template<class CloudType>
void Foam::RaseraTriboCharging<CloudType>::read(const bool fromWorkFunctions)
{
    const dictionary& coeffs = this->coeffDict();

    scalar deltaE = 0;
    if (fromWorkFunctions)
    {
        deltaE = get(coeffs, "cutoffDistance", true);
        if (!(deltaE > 0))
        {
            FatalIOErrorInFunction(coeffs)
                << "Entry cutoffDistance (delta_e, Rasera Eq. 14) = "
                << deltaE << " is out of range: it must be > 0 [m]"
                << exit(FatalIOError);
        }
    }

    if (!coeffs.isDict("particles"))
    {
        FatalIOErrorInFunction(coeffs)
            << "Entry particles { kappaC ...; } (particle-particle charging"
            << " efficiency, Rasera Eq. 16) is missing in "
            << coeffs.name().c_str() << exit(FatalIOError);
    }

    // Each material's work function [J] (workFunction form)
    scalarList phi;
    readPairLaws(fromWorkFunctions, deltaE, phi);
    readWallLaws(fromWorkFunctions, deltaE, phi);
}


template<class CloudType>
void Foam::RaseraTriboCharging<CloudType>::readPairLaws
(
    const bool fromWorkFunctions,
    const scalar deltaE,
    scalarList& phi
)
{
    const dictionary& coeffs = this->coeffDict();
    const dictionary& particles = coeffs.subDict("particles");
    const particleMaterials& materials =
        this->owner().constProps().materials();
    const label n = materials.size();

    // Each material: the like contacts' kappa_c and (workFunction) its
    // work function [J], from particles/<material>, else particles
    scalarList kappaLike(n);
    phi.setSize(n, Zero);
    for (label m = 0; m < n; ++m)
    {
        const dictionary* own = particles.findDict(materials.name(m));
        kappaLike[m] = getOwn(own, particles, "kappaC", true);
        if (fromWorkFunctions)
        {
            phi[m] =
                getOwn(own, particles, "workFunction", false)
               *triboCharging::elementaryCharge;
        }
    }

    // Particle pairs: like materials Gamma = 0 (Rasera Eq. 18), unlike
    // from the work functions (Eqs. 14-15) or given per pair
    pp_.setSize(n*n);
    materials.forPairs
    (
        coeffs,
        [&]
        (
            const label a,
            const label b,
            const dictionary* d,
            const bool swapped
        )
        {
            const scalar kappaC =
                d && d->found("kappaC") ? get(*d, "kappaC", true)
              : a == b ? kappaLike[a]
              : get(particles, "kappaC", true);
            if (d && d->found("Gamma") && (a == b || fromWorkFunctions))
            {
                FatalIOErrorInFunction(*d)
                    << "Entry Gamma in " << d->name().c_str() << " is not"
                    << " used: "
                    << (
                           a == b
                         ? "like materials have Gamma = 0 (Rasera Eq. 18)"
                         : "workFunction gives Gamma from the materials'"
                           " work functions (Rasera Eqs. 14-15)"
                       )
                    << exit(FatalIOError);
            }
            scalar Gamma = 0;
            if (fromWorkFunctions)
            {
                Gamma = triboCharging::GammaFromWorkFunctions
                (
                    phi[a], phi[b], deltaE
                );
                checkGamma(Gamma, particles, "", fromWorkFunctions);
            }
            else if (a != b)
            {
                if (!d || !d->found("Gamma"))
                {
                    FatalIOErrorInFunction(coeffs)
                        << "Materials " << materials.name(a) << " and "
                        << materials.name(b) << " have no charging field"
                        << " Gamma in " << coeffs.name().c_str() << ": give"
                        << " materialPairs { <name> { materials ("
                        << materials.name(a) << " " << materials.name(b)
                        << "); Gamma ...; } } (the Gamma of the first from"
                        << " the second [V/m], Rasera Eqs. 16, 18)"
                        << exit(FatalIOError);
                }
                Gamma = get(*d, "Gamma", false);
                checkGamma(Gamma, *d, "", fromWorkFunctions);
                if (swapped)
                {
                    Gamma = -Gamma;
                }
            }
            pp_.set
            (
                materials.pairIndex(a, b),
                new triboCharging(kappaC, Gamma)
            );
        }
    );

    for (label a = 0; a < n; ++a)
    {
        for (label b = a; b < n; ++b)
        {
            const triboCharging& law = pairLaw(a, b);
            Info<< "    tribocharging particle-particle"
                << (
                       n > 1
                     ? " " + materials.name(a) + "-" + materials.name(b)
                     : std::string()
                   ).c_str()
                << ": kappa_c = " << law.kappaC() << ", Gamma = "
                << law.Gamma() << " V/m"
                << (a == b ? " (like particles)" : "") << endl;
        }
    }
}


template<class CloudType>
void Foam::RaseraTriboCharging<CloudType>::readWallLaws
(
    const bool fromWorkFunctions,
    const scalar deltaE,
    const scalarList& phi
)
{
    const dictionary& coeffs = this->coeffDict();
    const particleMaterials& materials =
        this->owner().constProps().materials();
    const label n = materials.size();

    if (!coeffs.isDict("walls"))
    {
        FatalIOErrorInFunction(coeffs)
            << "Entry walls { <patch> { kappaC ...; "
            << (fromWorkFunctions ? "workFunction" : "Gamma")
            << " ...; } } is missing in " << coeffs.name().c_str()
            << exit(FatalIOError);
    }
    const dictionary& walls = coeffs.subDict("walls");

    // Each wall patch and material: walls/<patch>/<material> over
    // walls/<patch> (kappaC; Gamma or, with work functions, the wall's)
    const polyBoundaryMesh& patches = this->owner().mesh().boundaryMesh();
    walls_.setSize(n*patches.size());
    forAll(patches, patchi)
    {
        if (!isA<wallPolyPatch>(patches[patchi]))
        {
            continue;
        }
        const word& name = patches[patchi].name();
        const dictionary* dPtr = walls.findDict(name, keyType::REGEX);
        if (!dPtr)
        {
            FatalIOErrorInFunction(walls)
                << "Wall patch " << name << " has no entry in "
                << walls.name().c_str() << ": every wall patch needs"
                << " { kappaC ...; "
                << (fromWorkFunctions ? "workFunction" : "Gamma")
                << " ...; } (a patch name or a regular expression)"
                << exit(FatalIOError);
        }
        const dictionary& d = *dPtr;
        const scalar phiWall =
            fromWorkFunctions
          ? get(d, "workFunction", false)*triboCharging::elementaryCharge
          : 0;
        for (label m = 0; m < n; ++m)
        {
            const dictionary* own = d.findDict(materials.name(m));
            const scalar kappaC = getOwn(own, d, "kappaC", true);
            const scalar Gamma =
                fromWorkFunctions
              ? triboCharging::GammaFromWorkFunctions(phi[m], phiWall, deltaE)
              : getOwn(own, d, "Gamma", false);
            checkGamma
            (
                Gamma, own ? *own : d, " of wall patch " + name,
                fromWorkFunctions
            );
            walls_.set(n*patchi + m, new triboCharging(kappaC, Gamma));

            Info<< "    tribocharging on wall patch " << name
                << (n > 1 ? ", " + materials.name(m) : std::string()).c_str()
                << ": kappa_c = " << kappaC << ", Gamma = " << Gamma
                << " V/m" << endl;
        }
    }
}


template<class CloudType>
const Foam::triboCharging& Foam::RaseraTriboCharging<CloudType>::lawOf
(
    const ParcelContact<parcelType>& c
) const
{
    const label a = c.pA->material();
    return
        c.pB
      ? pairLaw(a, c.pB->material())
      : walls_[nMaterials_*c.patchi + a];
}


template<class CloudType>
Foam::scalar Foam::RaseraTriboCharging<CloudType>::surfaceField
(
    const parcelType& p
)
{
    // Spheres without the elliptic integrals (a contact hot path)
    const scalar S =
        p.isSphere()
      ? 4*constant::mathematical::pi*sqr(p.semiAxes().x())
      : ellipsoid::surfaceArea(p.semiAxes());
    return p.q()/(triboCharging::eps0*S);
}


template<class CloudType>
Foam::scalar Foam::RaseraTriboCharging<CloudType>::transferOf
(
    const ParcelContact<parcelType>& pc,
    const triboCharging& law,
    scalar& dA,
    bool& impact
)
{
    const ellipsoidContact::result& c = pc.contact;
    parcelType& pA = *pc.pA;

    // Contact area and its growth beyond the largest so far
    const scalar A = constant::mathematical::pi*c.reducedRadius*c.overlap;
    const point xc = 0.5*(c.x1 + c.x2);
    scalar& Amax =
        pc.pB
      ? pA.chargingRecords().matchPairRecord
        (
            pc.pB->origProc(),
            pc.pB->origId()
        ).collisionData()
      : pA.chargingRecords().matchWallRecord
        (
            xc - pc.xA,
            pc.radiusA
        ).collisionData();

    impact = Amax == 0;
    dA = A - Amax;
    if (dA <= 0)
    {
        return 0;
    }
    Amax = A;

    // Field at the contact along n (A to B), Rasera Eqs. (27)-(28)
    scalar En = surfaceField(pA);
    if (pc.pB)
    {
        const parcelType& pB = *pc.pB;
        En -= surfaceField(pB);

        // The others' field: the partner taken out, interpolated between
        // the centroids (symmetric in A and B)
        const auto& es = this->owner().electrostatics();
        const vector EA = pA.E() - es.pointChargeField(pc.xA, pc.xB, pB.q());
        const vector EB = pB.E() - es.pointChargeField(pc.xB, pc.xA, pA.q());
        const vector AB = pc.xB - pc.xA;
        const scalar s = min(max(((xc - pc.xA) & AB)/magSqr(AB), 0), 1);
        En += (((1 - s)*EA + s*EB) & c.n);
    }
    else
    {
        En += (pA.E() & c.n);

        if (wallImages_)
        {
            // Image -q_A of the centroid mirrored in the wall plane
            // (through the wall point x2, normal n): the grounded plane's
            // method of images (Jackson, Classical Electrodynamics 2.1)
            const point xImage = pc.xA + 2*((c.x2 - pc.xA) & c.n)*c.n;
            const vector r = xc - xImage;
            En -=
                pA.q()/(4*constant::mathematical::pi*triboCharging::eps0)
               *(r & c.n)/pow3(mag(r));
        }
    }

    return law.chargeTransfer(dA, En);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

template<class CloudType>
Foam::RaseraTriboCharging<CloudType>::RaseraTriboCharging
(
    const dictionary& dict,
    CloudType& owner,
    const word& type,
    const bool fromWorkFunctions
)
:
    TriboChargingModel<CloudType>(dict, owner, type),
    nMaterials_(owner.constProps().materials().size()),
    pp_(),
    walls_(),
    // Per patch that is not a processor patch: the same list everywhere
    wallCharge0_(owner.mesh().boundaryMesh().nNonProcessor(), Zero),
    wallChargeLocal_(owner.mesh().boundaryMesh().nNonProcessor(), Zero),
    fromWalls0_(nMaterials_ > 1 ? nMaterials_ : 0, Zero),
    fromWallsLocal_(fromWalls0_.size(), Zero),
    fromParticles0_(fromWalls0_.size(), Zero),
    fromParticlesLocal_(fromWalls0_.size(), Zero),
    nPairCharging_(0),
    nWallCharging_(0),
    nPairImpacts_(0),
    nWallImpacts_(0),
    pairArea_(0),
    wallArea_(0),
    wallImages_
    (
        this->coeffDict().template lookupOrDefault<bool>("wallImages", false)
    ),
    balanceInterval_
    (
        getCheckedOrDefault<label>
        (
            this->coeffDict(), "balanceInterval", 1,
            [](const label n) { return n >= 1; },
            ": it must be >= 1 (time steps)"
        )
    ),
    filePtr_(),
    dq_()
{
    read(fromWorkFunctions);

    // Wall charges of the run this one continues
    scalarField q0;
    this->getModelProperty("wallCharge", q0);
    forAll(wallCharge0_, patchi)
    {
        wallCharge0_[patchi] = patchi < q0.size() ? q0[patchi] : 0;
    }
    scalarField fromWalls, fromParticles;
    this->getModelProperty("materialChargeFromWalls", fromWalls);
    this->getModelProperty("materialChargeFromParticles", fromParticles);
    if (fromWalls.size() == fromWalls0_.size())
    {
        fromWalls0_ = fromWalls;
    }
    if (fromParticles.size() == fromParticles0_.size())
    {
        fromParticles0_ = fromParticles;
    }
}


template<class CloudType>
Foam::RaseraTriboCharging<CloudType>::RaseraTriboCharging
(
    const dictionary& dict,
    CloudType& owner
)
:
    RaseraTriboCharging<CloudType>(dict, owner, typeName, false)
{}


template<class CloudType>
Foam::RaseraTriboCharging<CloudType>::RaseraTriboCharging
(
    const RaseraTriboCharging<CloudType>& tm
)
:
    TriboChargingModel<CloudType>(tm),
    nMaterials_(tm.nMaterials_),
    pp_(tm.pp_),
    walls_(tm.walls_),
    wallCharge0_(tm.wallCharge0_),
    wallChargeLocal_(tm.wallChargeLocal_),
    fromWalls0_(tm.fromWalls0_),
    fromWallsLocal_(tm.fromWallsLocal_),
    fromParticles0_(tm.fromParticles0_),
    fromParticlesLocal_(tm.fromParticlesLocal_),
    nPairCharging_(tm.nPairCharging_),
    nWallCharging_(tm.nWallCharging_),
    nPairImpacts_(tm.nPairImpacts_),
    nWallImpacts_(tm.nWallImpacts_),
    pairArea_(tm.pairArea_),
    wallArea_(tm.wallArea_),
    wallImages_(tm.wallImages_),
    balanceInterval_(tm.balanceInterval_),
    filePtr_(),
    dq_()
{}


// * * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * //

template<class CloudType>
void Foam::RaseraTriboCharging<CloudType>::findTransfers
(
    const UList<ParcelContact<parcelType>>& contacts,
    List<DynamicList<labelPair>>& sentIds,
    List<DynamicList<scalar>>& sentDq
)
{
    forAll(contacts, k)
    {
        const ParcelContact<parcelType>& c = contacts[k];
        scalar dA = 0;
        bool impact = false;
        dq_[k] = transferOf(c, lawOf(c), dA, impact);

        // A pair across processors is booked by the lower side only
        const bool lower =
            !c.referred
         || c.pA->origProc() < c.pB->origProc()
         || (
                c.pA->origProc() == c.pB->origProc()
             && c.pA->origId() < c.pB->origId()
            );
        if (dA > 0 && lower)
        {
            (c.pB ? pairArea_ : wallArea_) += dA;
            if (impact)
            {
                ++(c.pB ? nPairImpacts_ : nWallImpacts_);
            }
        }

        if (c.referred && dq_[k] != 0)
        {
            const parcelType& pB = *c.pB;
            if (lower)
            {
                const label proci = c.referredFrom;
                sentIds[proci].append(labelPair(pB.origProc(), pB.origId()));
                sentDq[proci].append(dq_[k]);
            }
            else
            {
                dq_[k] = 0;
            }
        }
    }
}


template<class CloudType>
void Foam::RaseraTriboCharging<CloudType>::applyPartnerShares
(
    List<DynamicList<labelPair>>& sentIds,
    List<DynamicList<scalar>>& sentDq,
    const labelUList& neighbours
)
{
    // The partners' shares, exchanged with the neighbours only (those
    // that refer parcels here and receive this processor's; counts and
    // data between them, no all-to-all)
    const label me = Pstream::myProcNo();
    HashTable<scalar, labelPair, Hash<labelPair>> received;
    const auto receive =
        [&](const UList<labelPair>& ids, const UList<scalar>& dq)
    {
        forAll(dq, j)
        {
            received(ids[j]) += dq[j];
        }
    };
    receive(sentIds[me], sentDq[me]);
    forAll(sentDq, proci)
    {
        if (sentDq[proci].size() && proci != me && !neighbours.found(proci))
        {
            FatalErrorInFunction
                << "A contact with a parcel referred from processor "
                << proci << ", not a referral neighbour" << abort(FatalError);
        }
    }
    if (Pstream::parRun())
    {
        List<List<labelPair>> idsOut(Pstream::nProcs()), idsIn;
        List<List<scalar>> dqOut(Pstream::nProcs()), dqIn;
        for (const label proci : neighbours)
        {
            idsOut[proci].transfer(sentIds[proci]);
            dqOut[proci].transfer(sentDq[proci]);
        }
        processorHalo::exchangeWithNeighbours(neighbours, idsOut, idsIn);
        processorHalo::exchangeWithNeighbours(neighbours, dqOut, dqIn);
        for (const label proci : neighbours)
        {
            receive(idsIn[proci], dqIn[proci]);
        }
    }
    if (received.size())
    {
        for (parcelType& p : this->owner())
        {
            const auto iter =
                received.cfind(labelPair(p.origProc(), p.origId()));
            if (iter.found())
            {
                p.q() -= iter.val();
                if (nMaterials_ > 1)
                {
                    fromParticlesLocal_[p.material()] -= iter.val();
                }
            }
        }
    }
}


template<class CloudType>
void Foam::RaseraTriboCharging<CloudType>::transfer
(
    const UList<ParcelContact<parcelType>>& contacts,
    const labelUList& neighbours
)
{
    // All transfers from the charges before this collide, then applied.
    // A pair across processors is seen on both: only the side of the
    // lower (origProc, origId) transfers, and sends the partner's share to
    // the processor that referred the partner (a copy across a cyclic on
    // this processor: to itself), so the processors balance to the last
    // bit (the two sides' contact geometries differ at round-off). Both
    // sides still update their area records
    dq_.setSize(contacts.size());
    List<DynamicList<labelPair>> sentIds(Pstream::nProcs());
    List<DynamicList<scalar>> sentDq(Pstream::nProcs());
    findTransfers(contacts, sentIds, sentDq);

    forAll(contacts, k)
    {
        const ParcelContact<parcelType>& c = contacts[k];
        if (dq_[k] == 0)
        {
            continue;
        }
        c.pA->q() += dq_[k];
        const bool books = nMaterials_ > 1;
        if (c.pB)
        {
            ++nPairCharging_;
            if (books)
            {
                fromParticlesLocal_[c.pA->material()] += dq_[k];
            }
            if (!c.referred)
            {
                c.pB->q() -= dq_[k];
                if (books)
                {
                    fromParticlesLocal_[c.pB->material()] -= dq_[k];
                }
            }
        }
        else
        {
            ++nWallCharging_;
            wallChargeLocal_[c.patchi] -= dq_[k];
            if (books)
            {
                fromWallsLocal_[c.pA->material()] += dq_[k];
            }
        }
    }

    applyPartnerShares(sentIds, sentDq, neighbours);

    // A transfer that charges a parcel beyond the largest mean surface
    // field (inputLimits.H) comes from a charging efficiency no material
    // has: stop before its forces overflow
    forAll(contacts, k)
    {
        const ParcelContact<parcelType>& c = contacts[k];
        if (dq_[k] != 0)
        {
            checkCharge(*c.pA, c);
            if (c.pB && !c.referred)
            {
                checkCharge(*c.pB, c);
            }
        }
    }

    // Forget the areas of contacts that ended
    for (parcelType& p : this->owner())
    {
        p.chargingRecords().update();
    }
}


template<class CloudType>
void Foam::RaseraTriboCharging<CloudType>::checkCharge
(
    const parcelType& p,
    const ParcelContact<parcelType>& c
) const
{
    const scalar E = mag(surfaceField(p));
    if (E <= inputLimits::fieldMax)
    {
        return;
    }
    const triboCharging& law = lawOf(c);
    const dictionary& coeffs = this->coeffDict();
    FatalIOErrorInFunction(coeffs)
        << "Contact charging gave parcel (origProc " << p.origProc()
        << ", origId " << p.origId() << ") the charge q = " << p.q()
        << " C, a mean surface field |q|/(eps0 S) = " << E << " V/m above "
        << inputLimits::fieldMax << " V/m, beyond any material: the"
        << " charging entries kappaC = " << law.kappaC() << " and Gamma = "
        << law.Gamma() << " V/m of "
        << (
               c.pB
             ? word("particles")
             : word
               (
                   "walls/"
                 + this->owner().mesh().boundaryMesh()[c.patchi].name()
               )
           )
        << " in " << coeffs.name().c_str() << ", or the contact (impact"
        << " speed |U| = " << mag(p.U()) << " m/s, overlap "
        << c.contact.overlap << " m), are out of range"
        << exit(FatalIOError);
}


template<class CloudType>
Foam::scalarField Foam::RaseraTriboCharging<CloudType>::wallCharge() const
{
    scalarField q(wallChargeLocal_);
    Pstream::listCombineGather(q, plusEqOp<scalar>());
    Pstream::listCombineScatter(q);
    return wallCharge0_ + q;
}


template<class CloudType>
void Foam::RaseraTriboCharging<CloudType>::openBalanceFile()
{
    // Per-material columns with several materials
    const label nMaterialColumns = nMaterials_ > 1 ? nMaterials_ : 0;
    const Time& time = this->owner().mesh().time();
    const polyBoundaryMesh& patches = this->owner().mesh().boundaryMesh();
    const fileName dir =
        time.globalPath()/functionObject::outputPrefix/"lagrangian"
       /this->owner().name()/"triboCharging"
       /time.timeName(time.startTime().value());
    mkDir(dir);
    filePtr_.reset(new OFstream(dir/"chargeBalance.dat"));
    OFstream& os = filePtr_();
    os.precision(17);
    os  << "# Contact charging of cloud " << this->owner().name()
        << " [C]: charge received by each wall patch since the start;"
        << " balance = parcels + walls + outflow (charge carried out by"
        << " escaping parcels)" << nl << "# time parcels";
    forAll(patches, patchi)
    {
        if (walls_.set(nMaterials_*patchi))
        {
            os  << ' ' << patches[patchi].name();
        }
    }
    os  << " balance nPairContactsCharging nWallContactsCharging outflow"
        << " nPairImpacts nWallImpacts pairImpactArea wallImpactArea";
    const particleMaterials& materials =
        this->owner().constProps().materials();
    for (label m = 0; m < nMaterialColumns; ++m)
    {
        os  << " parcels:" << materials.name(m);
    }
    for (label m = 0; m < nMaterialColumns; ++m)
    {
        os  << " fromWalls:" << materials.name(m);
    }
    for (label m = 0; m < nMaterialColumns; ++m)
    {
        os  << " fromParticles:" << materials.name(m);
    }
    os  << nl;
}


template<class CloudType>
void Foam::RaseraTriboCharging<CloudType>::writeBalance()
{
    const Time& time = this->owner().mesh().time();
    if (time.timeIndex() % balanceInterval_ != 0 && !time.writeTime())
    {
        return;
    }

    const scalarField qWalls(wallCharge());
    const scalar qParcels = this->owner().totalCharge();

    // Each material's parcel charge (several materials)
    scalarField qMaterials(nMaterials_ > 1 ? nMaterials_ : 0, Zero);
    if (nMaterials_ > 1)
    {
        for (const parcelType& p : this->owner())
        {
            qMaterials[p.material()] += p.nParticle()*p.q();
        }
        Pstream::listCombineGather(qMaterials, plusEqOp<scalar>());
    }
    scalarField fromWalls(fromWallsLocal_);
    scalarField fromParticles(fromParticlesLocal_);
    if (nMaterials_ > 1)
    {
        // Collective: one material has no books and no messages
        Pstream::listCombineGather(fromWalls, plusEqOp<scalar>());
        Pstream::listCombineGather(fromParticles, plusEqOp<scalar>());
        Pstream::listCombineScatter(fromWalls);
        Pstream::listCombineScatter(fromParticles);
        fromWalls += fromWalls0_;
        fromParticles += fromParticles0_;
    }
    const scalar qOut = sum(this->owner().escapedCharge());
    const label nPair = returnReduce(nPairCharging_, sumOp<label>());
    const label nWall = returnReduce(nWallCharging_, sumOp<label>());
    nPairCharging_ = 0;
    nWallCharging_ = 0;
    const label nPairImpacts = returnReduce(nPairImpacts_, sumOp<label>());
    const label nWallImpacts = returnReduce(nWallImpacts_, sumOp<label>());
    const scalar pairArea = returnReduce(pairArea_, sumOp<scalar>());
    const scalar wallArea = returnReduce(wallArea_, sumOp<scalar>());
    nPairImpacts_ = 0;
    nWallImpacts_ = 0;
    pairArea_ = 0;
    wallArea_ = 0;

    const polyBoundaryMesh& patches = this->owner().mesh().boundaryMesh();

    if (time.writeTime())
    {
        this->setModelProperty("wallCharge", qWalls);
        if (nMaterials_ > 1)
        {
            this->setModelProperty("materialChargeFromWalls", fromWalls);
            this->setModelProperty
            (
                "materialChargeFromParticles",
                fromParticles
            );
        }
    }

    if (!Pstream::master())
    {
        return;
    }

    if (!filePtr_.valid())
    {
        openBalanceFile();
    }

    OFstream& os = filePtr_();
    scalar balance = qParcels + qOut;
    os  << time.value() << ' ' << qParcels;
    forAll(patches, patchi)
    {
        if (walls_.set(nMaterials_*patchi))
        {
            os  << ' ' << qWalls[patchi];
            balance += qWalls[patchi];
        }
    }
    os  << ' ' << balance << ' ' << nPair << ' ' << nWall << ' ' << qOut
        << ' ' << nPairImpacts << ' ' << nWallImpacts << ' ' << pairArea
        << ' ' << wallArea;
    forAll(qMaterials, m)
    {
        os  << ' ' << qMaterials[m];
    }
    forAll(qMaterials, m)
    {
        os  << ' ' << fromWalls[m];
    }
    forAll(qMaterials, m)
    {
        os  << ' ' << fromParticles[m];
    }
    os  << endl;
}


// ************************************************************************* //
