/*---------------------------------------------------------------------------*\
    chargedFoam: charged dielectric particles for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "SceneCheck.H"
#include "sceneMeasures.H"
#include "meshPoisson.H"
#include "coulombCollision.H"
#include "pairwiseCoulomb.H"
#include "ellipsoid.H"
#include "wallPolyPatch.H"
#include "cyclicPolyPatch.H"
#include "ListListOps.H"
#include "mathematicalConstants.H"
#include "checkedEntry.H"

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

namespace Foam
{
namespace sceneCheckDetail
{

//- The lists of all processors joined on the master (in processor order)
template<class T>
List<T> gatherOnMaster(const List<T>& mine)
{
    List<List<T>> all(Pstream::nProcs());
    all[Pstream::myProcNo()] = mine;
    Pstream::gatherList(all);
    if (Pstream::master())
    {
        return ListListOps::combine<List<T>>(all, accessOp<List<T>>());
    }
    return List<T>();
}

} // End namespace sceneCheckDetail
} // End namespace Foam


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

template<class CloudType>
Foam::SceneCheck<CloudType>::SceneCheck
(
    const dictionary& cloudDict,
    const CloudType& cloud
)
:
    cloud_(cloud),
    active_(true),
    recheckInterval_(0),
    breakdownField_(3e6),
    lastCheck_(-1)
{
    const dictionary& dict = cloudDict.subOrEmptyDict("sceneCheck");
    active_ = dict.getOrDefault<bool>("active", true);
    recheckInterval_ = getCheckedOrDefault<label>
    (
        dict, "recheckInterval", 0,
        [](const label n) { return n >= 0; },
        ": steps between scene checks, >= 0 (0: at the first step only)"
    );
    breakdownField_ = getCheckedOrDefault<scalar>
    (
        dict, "breakdownField", 3e6,
        [](const scalar E) { return E > 0 && std::isfinite(E); },
        ": the breakdown field of the medium [V/m], finite and > 0 (air: 3e6)"
    );
}


// * * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * //

template<class CloudType>
void Foam::SceneCheck<CloudType>::checkIfDue()
{
    if (!active_)
    {
        return;
    }
    const label index = cloud_.mesh().time().timeIndex();
    const bool due =
        lastCheck_ < 0
      ? returnReduce(cloud_.size(), sumOp<label>()) > 0
      : (recheckInterval_ > 0 && index - lastCheck_ >= recheckInterval_);
    if (due)
    {
        check();
        lastCheck_ = index;
    }
}


template<class CloudType>
void Foam::SceneCheck<CloudType>::gatherParcels(scene& s) const
{
    typedef typename CloudType::parcelType parcelType;
    using namespace sceneCheckDetail;

    // The parcels, on the master
    DynamicList<point> myX;
    DynamicList<scalar> myQ, myEps, myM, myAMin, myAMax, myArea, myTau;
    DynamicList<symmTensor> mySinv;
    DynamicList<vector> myU;
    DynamicList<label> myOrigProc, myOrigId;
    s.volParticles = 0;
    const scalarField& muc = cloud_.mu().primitiveField();
    for (const parcelType& p : cloud_)
    {
        const vector& a = p.semiAxes();
        const tensor R = p.orientation().R();
        myX.append(p.centre());
        myQ.append(p.q());
        myEps.append(p.epsilonR());
        myM.append(p.mass());
        myU.append(p.U());
        myOrigProc.append(p.origProc());
        myOrigId.append(p.origId());
        myAMin.append(cmptMin(a));
        myAMax.append(cmptMax(a));
        myArea.append(ellipsoid::surfaceArea(a));
        s.volParticles += p.nParticle()*p.mass()/p.rho();
        // Stokes response time of the volume-equivalent sphere
        const scalar mu = muc[p.cell()];
        if (mu > 0)
        {
            const scalar dv = 2*Foam::cbrt(a.x()*a.y()*a.z());
            myTau.append(p.rho()*sqr(dv)/(18*mu));
        }
        // R diag(a^2, b^2, c^2) R^T: the support function's matrix
        const tensor S2
        (
            sqr(a.x()), 0, 0,
            0, sqr(a.y()), 0,
            0, 0, sqr(a.z())
        );
        mySinv.append(symm(R & S2 & R.T()));
    }
    s.x = gatherOnMaster<point>(myX);
    s.q = gatherOnMaster<scalar>(myQ);
    s.eps = gatherOnMaster<scalar>(myEps);
    s.m = gatherOnMaster<scalar>(myM);
    s.U = gatherOnMaster<vector>(myU);
    s.aMin = gatherOnMaster<scalar>(myAMin);
    s.aMax = gatherOnMaster<scalar>(myAMax);
    s.area = gatherOnMaster<scalar>(myArea);
    s.Sinv = gatherOnMaster<symmTensor>(mySinv);
    s.tauDrag = gatherOnMaster<scalar>(myTau);
    s.origProc = gatherOnMaster<label>(myOrigProc);
    s.origId = gatherOnMaster<label>(myOrigId);
    s.n = s.x.size();
}


template<class CloudType>
void Foam::SceneCheck<CloudType>::findWalls(scene& s) const
{
    // Wall and cyclic patches, wall faces of this processor
    for (const polyPatch& pp : cloud_.mesh().boundaryMesh())
    {
        if (isA<wallPolyPatch>(pp))
        {
            s.wallNames.append(pp.name());
            forAll(pp, i)
            {
                s.wallFaces.append(pp.start() + i);
            }
        }
        else if (isA<cyclicPolyPatch>(pp))
        {
            s.cyclicNames.append(pp.name());
        }
    }
    s.nWallFaces = returnReduce(s.wallFaces.size(), sumOp<label>());
}


template<class CloudType>
void Foam::SceneCheck<CloudType>::chargeStatistics(scene& s) const
{
    // Charges, shapes, surface field, polarisability
    const scalar eps0 = pairwiseCoulomb::vacuumPermittivity;
    const label n = s.n;
    s.polarisable.setSize(n);
    s.polarisable = false;
    for (label i = 0; i < n; ++i)
    {
        const scalar qi = s.q[i];
        s.qMin = min(s.qMin, qi);
        s.qMax = max(s.qMax, qi);
        s.qNet += qi;
        s.qAbsMean += mag(qi);
        s.mMean += s.m[i];
        s.aspectMin = min(s.aspectMin, s.aMax[i]/s.aMin[i]);
        s.aspectMax = max(s.aspectMax, s.aMax[i]/s.aMin[i]);
        s.epsMin = min(s.epsMin, s.eps[i]);
        s.epsMax = max(s.epsMax, s.eps[i]);
        const scalar Esi = mag(qi)/(eps0*s.area[i]);
        if (Esi > s.Es)
        {
            s.Es = Esi;
            s.iEs = i;
        }
        s.nAboveBreakdown += (Esi > breakdownField_);
        if (qi != 0)
        {
            ++s.nCharged;
            (qi > 0 ? s.nPositive : s.nNegative)++;
            s.chargedBox.add(s.x[i]);
        }
        if (mag(s.eps[i] - s.epsMedium) > 1e-9*s.epsMedium)
        {
            s.polarisable[i] = true;
            ++s.nPolarisable;
        }
    }
    if (n > 0)
    {
        s.qAbsMean /= n;
        s.mMean /= n;
    }
}


template<class CloudType>
void Foam::SceneCheck<CloudType>::surfaceGaps(scene& s) const
{
    // Surface gaps of the polarisable parcels (gapRange smaller
    // semi-axes)
    if (Pstream::master() && s.nPolarisable > 0)
    {
        s.gaps = sceneMeasures::nearestGaps
        (
            s.x, s.Sinv, s.aMin, s.aMax, s.polarisable, s.gapRange
        );
        forAll(s.gaps, i)
        {
            if (s.polarisable[i] && s.gaps[i] < s.gapRange)
            {
                ++s.nClose2;
                if (s.gaps[i] < 1 && s.q[i] != 0)
                {
                    ++s.nClose1Charged;
                }
            }
        }
    }
}


template<class CloudType>
void Foam::SceneCheck<CloudType>::wallDistances(scene& s) const
{
    // Wall distances of a sample of the charged parcels (all parcels if
    // none is charged yet): the master picks it, every processor searches
    // its own wall faces, the minimum wins
    List<point> sample;
    if (Pstream::master())
    {
        DynamicList<point> picked;
        const bool anyCharged = s.nCharged > 0;
        const label nPool = anyCharged ? s.nCharged : s.n;
        const label stride =
            max(label(1), nPool/2000 + (nPool % 2000 ? 1 : 0));
        label j = 0;
        for (label i = 0; i < s.n; ++i)
        {
            if (!anyCharged || s.q[i] != 0)
            {
                if (j++ % stride == 0)
                {
                    picked.append(s.x[i]);
                }
            }
        }
        sample.transfer(picked);
    }
    Pstream::scatter(sample);
    s.dWall =
        sceneMeasures::distanceToFaces(cloud_.mesh(), s.wallFaces, sample);
    Pstream::listCombineGather(s.dWall, minEqOp<scalar>());
}


template<class CloudType>
void Foam::SceneCheck<CloudType>::cloudSize(scene& s) const
{
    // The cloud's size: the charged parcels' box (all parcels' if none is
    // charged yet); a single parcel has no partner (l infinite)
    boundBox box(s.chargedBox);
    if (s.nCharged == 0)
    {
        for (const point& p : s.x)
        {
            box.add(p);
        }
    }
    const label nSized = s.nCharged > 0 ? s.nCharged : s.n;
    s.extent = nSized > 1 ? box.mag() : GREAT;
    s.dWallMedian = sceneMeasures::percentile(s.dWall, 0.5);
    s.imageEffect =
        s.nWallFaces > 0 && s.dWallMedian < GREAT
      ? sceneMeasures::imageEstimate(s.extent, s.dWallMedian)
      : 0;
}


template<class CloudType>
void Foam::SceneCheck<CloudType>::coulombCollisionStep(scene& s) const
{
    // Time step of the force evaluations and the Coulomb-collision step
    // of a mono-charged cloud (Eqs. 21-23 with the agitation of Eq. 25 or
    // the measured one, the larger)
    s.deltaT = cloud_.mesh().time().deltaTValue();
    s.dtStep = s.deltaT/s.nSub;
    const bool monoCharged =
        s.nCharged > 1 && (s.nPositive == 0 || s.nNegative == 0);
    if (monoCharged && s.farType != "periodic")
    {
        const label n = s.n;
        scalar sumU2 = 0;
        vector sumU(Zero);
        for (const vector& u : s.U)
        {
            sumU += u;
            sumU2 += magSqr(u);
        }
        const scalar qp2Measured =
            0.5*max(sumU2/n - magSqr(sumU/n), scalar(0));
        const scalar qp2 = max
        (
            qp2Measured,
            coulombCollision::agitationEstimate
            (
                s.k, s.qAbsMean, s.mMean, n/s.vol
            )
        );
        // Charges below ~1e-160 C square to 0: no deflection to resolve
        if (qp2 > 0 && s.k*sqr(s.qAbsMean) > 0)
        {
            s.dtCoulomb = coulombCollision::maxTimeStep
            (
                s.k, s.qAbsMean, s.qAbsMean, s.mMean, s.mMean, qp2
            );
        }
    }
}


template<class CloudType>
void Foam::SceneCheck<CloudType>::printParcels(const scene& s) const
{
    const polyMesh& mesh = cloud_.mesh();
    const label n = s.n;
    Info<< nl << "Scene check of " << cloud_.name() << " at t = "
        << mesh.time().timeName() << " s:" << nl
        << "    parcels            " << n << ", aspect ratio "
        << s.aspectMin << " to " << s.aspectMax << ", volume fraction "
        << s.volParticles/s.vol << ", spacing (V/N)^(1/3) "
        << Foam::cbrt(s.vol/max(n, label(1))) << " m" << nl
        << "    charges            " << s.nCharged << " charged ("
        << s.nPositive << " positive), q from " << s.qMin << " to "
        << s.qMax << " C, net " << s.qNet << " C" << nl
        << "    surface field      largest q/(eps0 S) = " << s.Es << " V/m ";
    if (s.gas)
    {
        Info<< "(breakdownField " << breakdownField_ << " V/m)" << nl;
    }
    else
    {
        Info<< "(vacuum carrier: no breakdown)" << nl;
    }
    Info
        << "    polarisable        " << s.nPolarisable << " (epsilonR "
        << s.epsMin << " to " << s.epsMax << ", medium " << s.epsMedium
        << ")";
    if (s.nPolarisable > 0)
    {
        Info<< "; surface gap to the nearest parcel: ";
        if (s.nClose2 > 0)
        {
            DynamicList<scalar> close(s.nClose2);
            for (const scalar g : s.gaps)
            {
                if (g < s.gapRange) close.append(g);
            }
            Info<< "min " << min(s.gaps) << ", 5 % "
                << sceneMeasures::percentile(close, 0.05) << ", median "
                << sceneMeasures::percentile(close, 0.5)
                << " smaller semi-axes over the " << s.nClose2
                << " parcels within " << s.gapRange;
        }
        else
        {
            Info<< "none within " << s.gapRange << " smaller semi-axes";
        }
    }
    Info<< nl;
}


template<class CloudType>
void Foam::SceneCheck<CloudType>::printWalls(const scene& s) const
{
    const polyMesh& mesh = cloud_.mesh();
    string walls, cyclics;
    for (const word& w : s.wallNames)
    {
        const word& kind = s.patchKinds[mesh.boundaryMesh().findPatchID(w)];
        walls += (walls.empty() ? "" : ", ") + w + ": " + kind;
    }
    for (const word& w : s.cyclicNames)
    {
        cyclics += (cyclics.empty() ? "" : " ") + w;
    }
    Info<< "    walls              ";
    if (s.wallNames.empty())
    {
        Info<< "none";
    }
    else
    {
        Info<< walls.c_str() << " (" << s.nWallFaces << " faces)";
    }
    Info<< "; cyclic: ";
    if (s.cyclicNames.empty())
    {
        Info<< "none";
    }
    else
    {
        Info<< cyclics.c_str();
    }
    Info<< nl;
    if (s.nWallFaces > 0 && s.n > 0)
    {
        Info<< "    wall distance      median " << s.dWallMedian
            << " m over " << s.dWall.size() << " parcels; ";
        if (s.extent < GREAT)
        {
            Info<< "cloud size " << s.extent << " m: conducting walls would"
                << " change free-space forces by ~"
                << label(100*s.imageEffect + 0.5) << " % ((size/(2 d))^2)";
        }
        else
        {
            Info<< "one parcel: only walls act on it";
        }
        Info<< nl;
    }
}


template<class CloudType>
void Foam::SceneCheck<CloudType>::printTimes(const scene& s) const
{
    const word tribo = cloud_.triboCharging().modelType();
    Info<< "    models             electrostaticsModel " << s.farType
        << ", nearField " << s.nearType << ", triboChargingModel "
        << (tribo.empty() ? word("none") : tribo) << ", collisionModel "
        << cloud_.collision().type() << nl
        << "    time step          " << s.dtStep << " s (deltaT "
        << s.deltaT << " s / " << s.nSub << ")";
    if (s.dtCoulomb < GREAT)
    {
        Info<< "; Coulomb-collision step (Boutsikakis Eq. 23) "
            << s.dtCoulomb << " s";
    }
    Info<< nl << "    time scales        ";
    if (s.tHertz < GREAT)
    {
        Info<< "Hertz collision " << s.tHertz << " s (fastest parcel); ";
    }
    if (s.nCharged > 0)
    {
        // Plasma period 2 pi/omega_p, omega_p^2 = n <q^2>/(eps0 epsR <m>)
        scalar q2 = 0;
        for (const scalar qi : s.q)
        {
            q2 += sqr(qi);
        }
        q2 /= s.n;
        // Charges below ~1e-160 C square to 0: no period to give
        const scalar omegaP2 =
            (s.n/s.vol)*q2
           /(pairwiseCoulomb::vacuumPermittivity*s.epsMedium*s.mMean);
        if (omegaP2 > 0)
        {
            Info<< "plasma period "
                << 2*constant::mathematical::pi/Foam::sqrt(omegaP2)
                << " s; ";
        }
    }
    if (s.tauDrag.size())
    {
        Info<< "drag response (Stokes) median "
            << sceneMeasures::percentile(s.tauDrag, 0.5) << " s";
    }
    else
    {
        Info<< "no drag (carrier without viscosity)";
    }
    Info<< nl;
}


template<class CloudType>
Foam::DynamicList<Foam::string>
Foam::SceneCheck<CloudType>::warningsFor(const scene& s) const
{
    // The entry to change and why
    const auto& es = cloud_.electrostatics();
    const word& farType = s.farType;
    const word& nearType = s.nearType;
    const bool charging = cloud_.triboCharging().active();
    const bool applied = es.appliedField().valid();
    DynamicList<string> warnings;
    if
    (
        (farType == "directCoulomb" || farType == "cutoffCoulomb")
     && (s.nCharged > 0 || charging) && s.imageEffect > 0.05
    )
    {
        warnings.append
        (
            "electrostaticsModel " + farType + " sums charges in free space,"
            " but the walls are close to the charges (median distance "
            + Foam::name(s.dWallMedian) + " m, cloud size "
            + (s.extent < GREAT ? Foam::name(s.extent) : word("one parcel"))
            + " m): if the walls conduct (or are dielectric), their images"
            " change the forces by ~"
            + Foam::name(label(100*s.imageEffect + 0.5)) + " %. Use"
            " electrostaticsModel imageCoulomb (grounded planar walls) or"
            " meshPoisson (any walls, electrodes); boundaries that are open"
            " (no material) are patches of type patch, not wall."
        );
    }
    if (nearType == "none" && s.nPolarisable > 0 && (s.nClose2 > 0 || applied))
    {
        warnings.append
        (
            "nearField none: " + Foam::name(s.nPolarisable) + " polarisable"
            " parcels (epsilonR != " + Foam::name(s.epsMedium) + ")"
          + (
                s.nClose2 > 0
              ? ", " + Foam::name(s.nClose2) + " of them within two smaller"
                " semi-axes of a neighbour, where point charges miss the"
                " induced forces (up to 4x, doc/polarisation.md)"
              : string("")
            )
          + (applied ? ", in an applied field (no dielectric force or"
                " torque without a near field)" : "")
          + ". Set <model>Coeffs { nearField { type inducedDipole; } }"
            " (or type bem for close pairs)."
        );
    }
    if (nearType == "inducedDipole" && s.nClose1Charged > 0)
    {
        warnings.append
        (
            "nearField inducedDipole: " + Foam::name(s.nClose1Charged)
          + " charged polarisable parcels within one smaller semi-axis of a"
            " neighbour, where the dipole rung's force is 13-80 % off the"
            " surface-resolved one (doc/polarisation.md). Set nearField"
            " { type bem; } to resolve them."
        );
    }
    if (s.dtCoulomb < GREAT && s.dtStep > s.dtCoulomb)
    {
        warnings.append
        (
            "the force step " + Foam::name(s.dtStep) + " s exceeds the"
            " Coulomb-collision step " + Foam::name(s.dtCoulomb) + " s of this"
            " mono-charged cloud (Boutsikakis 2023 Eq. 23): close encounters"
            " are under-resolved. Reduce deltaT in system/controlDict."
        );
    }
    if (s.gas && s.Es > breakdownField_)
    {
        warnings.append
        (
            "the largest surface field q/(eps0 S) = " + Foam::name(s.Es)
          + " V/m, of parcel (origProc " + Foam::name(s.origProc[s.iEs])
          + ", origId " + Foam::name(s.origId[s.iEs]) + ") at "
          + Foam::name(s.x[s.iEs]) + " with q = " + Foam::name(s.q[s.iEs])
          + " C, exceeds sceneCheck/breakdownField = "
          + Foam::name(breakdownField_) + " V/m ("
          + Foam::name(s.nAboveBreakdown) + " parcel(s) above): the medium"
            " would discharge. Check the parcels' q (or"
            " constantProperties/q0)."
        );
    }
    if
    (
        es.active() && s.nCharged == 0 && !charging
     && (s.nPolarisable == 0 || !applied)
    )
    {
        warnings.append
        (
            "electrostaticsModel " + farType + " has nothing to compute: no"
            " parcel is charged, no contact charging"
          + string(s.nPolarisable > 0 ? " and no applied field" : "")
          + ". Set electrostaticsModel none (no cost)."
        );
    }
    else if (nearType != "none" && s.nPolarisable == 0)
    {
        warnings.append
        (
            "nearField " + nearType + " has no polarisable parcel (every"
            " epsilonR equals the medium's " + Foam::name(s.epsMedium) + ")."
            " Remove the nearField entry (no cost)."
        );
    }

    return warnings;
}


template<class CloudType>
Foam::DynamicList<Foam::string> Foam::SceneCheck<CloudType>::check() const
{
    const auto& es = cloud_.electrostatics();
    scene s;
    s.farType = es.type();
    s.nearType = es.nearField().type();
    s.epsMedium = es.mediumEpsilonR();
    s.k =
        1/(4*constant::mathematical::pi*pairwiseCoulomb::vacuumPermittivity
          *s.epsMedium);
    // A carrier gas can break down; vacuum (density 0) cannot
    s.gas = gMax(cloud_.rho().primitiveField()) > 0;

    gatherParcels(s);
    findWalls(s);
    chargeStatistics(s);
    surfaceGaps(s);
    wallDistances(s);

    // Collective to the end: the collision model's sub-cycles (a
    // reduction) and the domain volume, on every processor
    s.nSub = max(label(1), cloud_.collision().nSubCycles());
    s.vol = gSum(cloud_.mesh().cellVolumes());
    reduce(s.volParticles, sumOp<scalar>());
    const auto* ec = cloud_.contactModel();
    s.tHertz = ec ? ec->collisionTime() : GREAT;
    // Electrical kinds of the patches (Phi's conditions or meshPoisson's
    // defaults: what a mesh solve would take them for)
    s.patchKinds = meshPoisson::patchKinds(cloud_.mesh());

    if (!Pstream::master())
    {
        return DynamicList<string>();
    }
    cloudSize(s);
    coulombCollisionStep(s);

    // Summary, with 4 significant digits (the run's precision is for
    // fields)
    const std::streamsize precision0 = Info().precision(4);
    printParcels(s);
    printWalls(s);
    printTimes(s);
    Info().precision(precision0);

    DynamicList<string> warns(warningsFor(s));
    for (const string& w : warns)
    {
        // Warning without the source location: the message names the entry
        Warning() << "Scene check: " << w.c_str() << nl << endl;
    }
    if (warns.empty())
    {
        Info<< "    no warnings" << nl;
    }
    Info<< endl;

    return warns;
}


// ************************************************************************* //
