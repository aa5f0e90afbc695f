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
    recheckInterval_ = dict.getOrDefault<label>("recheckInterval", 0);
    breakdownField_ = dict.getOrDefault<scalar>("breakdownField", 3e6);

    if (recheckInterval_ < 0)
    {
        FatalIOErrorInFunction(dict)
            << "Entry recheckInterval = " << recheckInterval_ << " in "
            << dict.name().c_str() << " is out of range: steps between scene"
            << " checks, >= 0 (0: at the first step only)"
            << exit(FatalIOError);
    }
    if (!(breakdownField_ > 0) || !std::isfinite(breakdownField_))
    {
        FatalIOErrorInFunction(dict)
            << "Entry breakdownField = " << breakdownField_ << " in "
            << dict.name().c_str() << " is out of range: the breakdown"
            << " field of the medium [V/m], finite and > 0 (air: 3e6)"
            << exit(FatalIOError);
    }
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
Foam::DynamicList<Foam::string> Foam::SceneCheck<CloudType>::check() const
{
    typedef typename CloudType::parcelType parcelType;
    using namespace sceneCheckDetail;

    const polyMesh& mesh = cloud_.mesh();
    const auto& es = cloud_.electrostatics();
    const word farType = es.type();
    const word nearType = es.nearField().type();
    const scalar epsMedium = es.mediumEpsilonR();
    const scalar eps0 = pairwiseCoulomb::vacuumPermittivity;
    const scalar k = 1/(4*constant::mathematical::pi*eps0*epsMedium);

    // A carrier gas can break down; vacuum (density 0) cannot
    const bool gas = gMax(cloud_.rho().primitiveField()) > 0;

    // The parcels, on the master
    DynamicList<point> myX;
    DynamicList<scalar> myQ, myEps, myM, myAMin, myAMax, myArea, myTau;
    DynamicList<symmTensor> mySinv;
    DynamicList<vector> myU;
    DynamicList<label> myOrigProc, myOrigId;
    scalar volParticles = 0;
    const scalarField& muc = cloud_.mu().primitiveField();
    for (const parcelType& p : cloud_)
    {
        const vector& s = p.semiAxes();
        const tensor R = p.orientation().R();
        myX.append(p.centre());
        myQ.append(p.q());
        myEps.append(p.epsilonR());
        myM.append(p.mass());
        myU.append(p.U());
        myOrigProc.append(p.origProc());
        myOrigId.append(p.origId());
        myAMin.append(cmptMin(s));
        myAMax.append(cmptMax(s));
        myArea.append(ellipsoid::surfaceArea(s));
        volParticles += p.nParticle()*p.mass()/p.rho();
        // Stokes response time of the volume-equivalent sphere
        const scalar mu = muc[p.cell()];
        if (mu > 0)
        {
            const scalar dv = 2*Foam::cbrt(s.x()*s.y()*s.z());
            myTau.append(p.rho()*sqr(dv)/(18*mu));
        }
        // R diag(a^2, b^2, c^2) R^T: the support function's matrix
        const tensor S2
        (
            sqr(s.x()), 0, 0,
            0, sqr(s.y()), 0,
            0, 0, sqr(s.z())
        );
        mySinv.append(symm(R & S2 & R.T()));
    }
    const List<point> x(gatherOnMaster<point>(myX));
    const List<scalar> q(gatherOnMaster<scalar>(myQ));
    const List<scalar> eps(gatherOnMaster<scalar>(myEps));
    const List<scalar> m(gatherOnMaster<scalar>(myM));
    const List<vector> U(gatherOnMaster<vector>(myU));
    const List<scalar> aMin(gatherOnMaster<scalar>(myAMin));
    const List<scalar> aMax(gatherOnMaster<scalar>(myAMax));
    const List<scalar> area(gatherOnMaster<scalar>(myArea));
    const List<symmTensor> Sinv(gatherOnMaster<symmTensor>(mySinv));
    const List<scalar> tauDrag(gatherOnMaster<scalar>(myTau));
    const List<label> origProc(gatherOnMaster<label>(myOrigProc));
    const List<label> origId(gatherOnMaster<label>(myOrigId));
    const label n = x.size();

    // Wall and cyclic patches, wall faces of this processor
    wordList wallNames, cyclicNames;
    DynamicList<label> wallFaces;
    for (const polyPatch& pp : mesh.boundaryMesh())
    {
        if (isA<wallPolyPatch>(pp))
        {
            wallNames.append(pp.name());
            forAll(pp, i)
            {
                wallFaces.append(pp.start() + i);
            }
        }
        else if (isA<cyclicPolyPatch>(pp))
        {
            cyclicNames.append(pp.name());
        }
    }
    const label nWallFaces = returnReduce(wallFaces.size(), sumOp<label>());

    // Charges, shapes, surface field, polarisability
    label nCharged = 0, nPositive = 0, nNegative = 0, nPolarisable = 0;
    scalar qMin = GREAT, qMax = -GREAT, qNet = 0, qAbsMean = 0, mMean = 0;
    scalar Es = 0, aspectMin = GREAT, aspectMax = 0;
    label iEs = -1, nAboveBreakdown = 0;
    scalar epsMin = GREAT, epsMax = 0;
    boundBox chargedBox;
    boolList polarisable(n, false);
    for (label i = 0; i < n; ++i)
    {
        qMin = min(qMin, q[i]);
        qMax = max(qMax, q[i]);
        qNet += q[i];
        qAbsMean += mag(q[i]);
        mMean += m[i];
        aspectMin = min(aspectMin, aMax[i]/aMin[i]);
        aspectMax = max(aspectMax, aMax[i]/aMin[i]);
        epsMin = min(epsMin, eps[i]);
        epsMax = max(epsMax, eps[i]);
        const scalar Esi = mag(q[i])/(eps0*area[i]);
        if (Esi > Es)
        {
            Es = Esi;
            iEs = i;
        }
        nAboveBreakdown += (Esi > breakdownField_);
        if (q[i] != 0)
        {
            ++nCharged;
            (q[i] > 0 ? nPositive : nNegative)++;
            chargedBox.add(x[i]);
        }
        if (mag(eps[i] - epsMedium) > 1e-9*epsMedium)
        {
            polarisable[i] = true;
            ++nPolarisable;
        }
    }
    if (n > 0)
    {
        qAbsMean /= n;
        mMean /= n;
    }

    // Surface gaps of the polarisable parcels (two smaller semi-axes)
    const scalar gapRange = 2;
    scalarField gaps;
    label nClose2 = 0, nClose1Charged = 0;
    if (Pstream::master() && nPolarisable > 0)
    {
        gaps = sceneMeasures::nearestGaps
        (
            x, Sinv, aMin, aMax, polarisable, gapRange
        );
        forAll(gaps, i)
        {
            if (polarisable[i] && gaps[i] < gapRange)
            {
                ++nClose2;
                if (gaps[i] < 1 && q[i] != 0)
                {
                    ++nClose1Charged;
                }
            }
        }
    }

    // Wall distances of a sample of the charged parcels (all parcels if
    // none is charged yet): the master picks it, every processor searches
    // its own wall faces, the minimum wins
    List<point> sample;
    if (Pstream::master())
    {
        DynamicList<point> s;
        const bool anyCharged = nCharged > 0;
        const label nPool = anyCharged ? nCharged : n;
        const label stride =
            max(label(1), nPool/2000 + (nPool % 2000 ? 1 : 0));
        label j = 0;
        for (label i = 0; i < n; ++i)
        {
            if (!anyCharged || q[i] != 0)
            {
                if (j++ % stride == 0)
                {
                    s.append(x[i]);
                }
            }
        }
        sample.transfer(s);
    }
    Pstream::scatter(sample);
    scalarField dWall(sceneMeasures::distanceToFaces(mesh, wallFaces, sample));
    Pstream::listCombineGather(dWall, minEqOp<scalar>());

    // Collective to the end: the collision model's sub-cycles (a
    // reduction) and the domain volume, on every processor
    const label nSub = max(label(1), cloud_.collision().nSubCycles());
    const scalar vol = gSum(mesh.cellVolumes());
    reduce(volParticles, sumOp<scalar>());
    const auto* ec =
        dynamic_cast<const typename CloudType::contactModelType*>
        (
            &cloud_.collision()
        );
    const scalar tHertz = ec ? ec->collisionTime() : GREAT;
    // Electrical kinds of the patches (Phi's conditions or meshPoisson's
    // defaults: what a mesh solve would take them for)
    const wordList patchKinds(meshPoisson::patchKinds(cloud_.mesh()));

    DynamicList<string> warnings;
    if (!Pstream::master())
    {
        return warnings;
    }

    // The cloud's size: the charged parcels' box (all parcels' if none is
    // charged yet); a single parcel has no partner (l infinite)
    boundBox box(chargedBox);
    if (nCharged == 0)
    {
        for (const point& p : x)
        {
            box.add(p);
        }
    }
    const label nSized = nCharged > 0 ? nCharged : n;
    const scalar extent = nSized > 1 ? box.mag() : GREAT;
    const scalar dWallMedian = sceneMeasures::percentile(dWall, 0.5);
    const scalar imageEffect =
        nWallFaces > 0 && dWallMedian < GREAT
      ? sceneMeasures::imageEstimate(extent, dWallMedian)
      : 0;

    // Time step of the force evaluations and the Coulomb-collision step
    // of a mono-charged cloud (Eqs. 21-23 with the agitation of Eq. 25 or
    // the measured one, the larger)
    const scalar deltaT = mesh.time().deltaTValue();
    const scalar dtStep = deltaT/nSub;
    scalar dtCoulomb = GREAT;
    const bool monoCharged =
        nCharged > 1 && (nPositive == 0 || nNegative == 0);
    if (monoCharged && farType != "periodic")
    {
        scalar sumU2 = 0;
        vector sumU(Zero);
        for (const vector& u : U)
        {
            sumU += u;
            sumU2 += magSqr(u);
        }
        const scalar qp2Measured =
            0.5*max(sumU2/n - magSqr(sumU/n), scalar(0));
        const scalar qp2 = max
        (
            qp2Measured,
            coulombCollision::agitationEstimate(k, qAbsMean, mMean, n/vol)
        );
        // Charges below ~1e-160 C square to 0: no deflection to resolve
        if (qp2 > 0 && k*sqr(qAbsMean) > 0)
        {
            dtCoulomb = coulombCollision::maxTimeStep
            (
                k, qAbsMean, qAbsMean, mMean, mMean, qp2
            );
        }
    }

    // Summary, with 4 significant digits (the run's precision is for
    // fields)
    const word tribo = cloud_.triboCharging().modelType();
    const std::streamsize precision0 = Info().precision(4);
    string walls, cyclics;
    for (const word& w : wallNames)
    {
        const word& kind =
            patchKinds[mesh.boundaryMesh().findPatchID(w)];
        walls += (walls.empty() ? "" : ", ") + w + ": " + kind;
    }
    for (const word& w : cyclicNames)
    {
        cyclics += (cyclics.empty() ? "" : " ") + w;
    }
    const word cloudName = cloud_.name();
    Info<< nl << "Scene check of " << cloudName << " at t = "
        << mesh.time().timeName() << " s:" << nl
        << "    parcels            " << n << ", aspect ratio "
        << aspectMin << " to " << aspectMax << ", volume fraction "
        << volParticles/vol << ", spacing (V/N)^(1/3) "
        << Foam::cbrt(vol/max(n, label(1))) << " m" << nl
        << "    charges            " << nCharged << " charged (" << nPositive
        << " positive), q from " << qMin << " to " << qMax << " C, net "
        << qNet << " C" << nl
        << "    surface field      largest q/(eps0 S) = " << Es << " V/m ";
    if (gas)
    {
        Info<< "(breakdownField " << breakdownField_ << " V/m)" << nl;
    }
    else
    {
        Info<< "(vacuum carrier: no breakdown)" << nl;
    }
    Info
        << "    polarisable        " << nPolarisable << " (epsilonR "
        << epsMin << " to " << epsMax << ", medium " << epsMedium << ")";
    if (nPolarisable > 0)
    {
        Info<< "; surface gap to the nearest parcel: ";
        if (nClose2 > 0)
        {
            DynamicList<scalar> close(nClose2);
            for (const scalar g : gaps)
            {
                if (g < gapRange) close.append(g);
            }
            Info<< "min " << min(gaps) << ", 5 % "
                << sceneMeasures::percentile(close, 0.05) << ", median "
                << sceneMeasures::percentile(close, 0.5)
                << " smaller semi-axes over the " << nClose2
                << " parcels within " << gapRange;
        }
        else
        {
            Info<< "none within " << gapRange << " smaller semi-axes";
        }
    }
    Info<< nl << "    walls              ";
    if (wallNames.empty())
    {
        Info<< "none";
    }
    else
    {
        Info<< walls.c_str() << " (" << nWallFaces << " faces)";
    }
    Info<< "; cyclic: ";
    if (cyclicNames.empty())
    {
        Info<< "none";
    }
    else
    {
        Info<< cyclics.c_str();
    }
    Info<< nl;
    if (nWallFaces > 0 && n > 0)
    {
        Info<< "    wall distance      median " << dWallMedian
            << " m over " << dWall.size() << " parcels; ";
        if (extent < GREAT)
        {
            Info<< "cloud size " << extent << " m: conducting walls would"
                << " change free-space forces by ~"
                << label(100*imageEffect + 0.5) << " % ((size/(2 d))^2)";
        }
        else
        {
            Info<< "one parcel: only walls act on it";
        }
        Info<< nl;
    }
    Info<< "    models             electrostaticsModel " << farType
        << ", nearField " << nearType << ", triboChargingModel "
        << (tribo.empty() ? word("none") : tribo) << ", collisionModel "
        << cloud_.collision().type() << nl
        << "    time step          " << dtStep << " s (deltaT " << deltaT
        << " s / " << nSub << ")";
    if (dtCoulomb < GREAT)
    {
        Info<< "; Coulomb-collision step (Boutsikakis Eq. 23) " << dtCoulomb
            << " s";
    }
    Info<< nl << "    time scales        ";
    if (tHertz < GREAT)
    {
        Info<< "Hertz collision " << tHertz << " s (fastest parcel); ";
    }
    if (nCharged > 0)
    {
        // Plasma period 2 pi/omega_p, omega_p^2 = n <q^2>/(eps0 epsR <m>)
        scalar q2 = 0;
        for (const scalar qi : q)
        {
            q2 += sqr(qi);
        }
        q2 /= n;
        // Charges below ~1e-160 C square to 0: no period to give
        const scalar omegaP2 = (n/vol)*q2/(eps0*epsMedium*mMean);
        if (omegaP2 > 0)
        {
            Info<< "plasma period "
                << 2*constant::mathematical::pi/Foam::sqrt(omegaP2)
                << " s; ";
        }
    }
    if (tauDrag.size())
    {
        Info<< "drag response (Stokes) median "
            << sceneMeasures::percentile(tauDrag, 0.5) << " s";
    }
    else
    {
        Info<< "no drag (carrier without viscosity)";
    }
    Info<< nl;
    Info().precision(precision0);

    // Warnings: the entry to change and why
    const bool charging = cloud_.triboCharging().active();
    const bool applied = es.appliedField().valid();
    if
    (
        (farType == "directCoulomb" || farType == "cutoffCoulomb")
     && (nCharged > 0 || charging) && imageEffect > 0.05
    )
    {
        warnings.append
        (
            "electrostaticsModel " + farType + " sums charges in free space,"
            " but the walls are close to the charges (median distance "
            + Foam::name(dWallMedian) + " m, cloud size "
            + (extent < GREAT ? Foam::name(extent) : word("one parcel"))
            + " m): if the walls conduct (or are dielectric), their images"
            " change the forces by ~"
            + Foam::name(label(100*imageEffect + 0.5)) + " %. Use"
            " electrostaticsModel imageCoulomb (grounded planar walls) or"
            " meshPoisson (any walls, electrodes); boundaries that are open"
            " (no material) are patches of type patch, not wall."
        );
    }
    if (nearType == "none" && nPolarisable > 0 && (nClose2 > 0 || applied))
    {
        warnings.append
        (
            "nearField none: " + Foam::name(nPolarisable) + " polarisable"
            " parcels (epsilonR != " + Foam::name(epsMedium) + ")"
          + (
                nClose2 > 0
              ? ", " + Foam::name(nClose2) + " of them within two smaller"
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
    if (nearType == "inducedDipole" && nClose1Charged > 0)
    {
        warnings.append
        (
            "nearField inducedDipole: " + Foam::name(nClose1Charged)
          + " charged polarisable parcels within one smaller semi-axis of a"
            " neighbour, where the dipole rung's force is 13-80 % off the"
            " surface-resolved one (doc/polarisation.md). Set nearField"
            " { type bem; } to resolve them."
        );
    }
    if (dtCoulomb < GREAT && dtStep > dtCoulomb)
    {
        warnings.append
        (
            "the force step " + Foam::name(dtStep) + " s exceeds the"
            " Coulomb-collision step " + Foam::name(dtCoulomb) + " s of this"
            " mono-charged cloud (Boutsikakis 2023 Eq. 23): close encounters"
            " are under-resolved. Reduce deltaT in system/controlDict."
        );
    }
    if (gas && Es > breakdownField_)
    {
        warnings.append
        (
            "the largest surface field q/(eps0 S) = " + Foam::name(Es)
          + " V/m, of parcel (origProc " + Foam::name(origProc[iEs])
          + ", origId " + Foam::name(origId[iEs]) + ") at "
          + Foam::name(x[iEs]) + " with q = " + Foam::name(q[iEs])
          + " C, exceeds sceneCheck/breakdownField = "
          + Foam::name(breakdownField_) + " V/m ("
          + Foam::name(nAboveBreakdown) + " parcel(s) above): the medium"
            " would discharge. Check the parcels' q (or"
            " constantProperties/q0)."
        );
    }
    if
    (
        es.active() && nCharged == 0 && !charging
     && (nPolarisable == 0 || !applied)
    )
    {
        warnings.append
        (
            "electrostaticsModel " + farType + " has nothing to compute: no"
            " parcel is charged, no contact charging"
          + string(nPolarisable > 0 ? " and no applied field" : "")
          + ". Set electrostaticsModel none (no cost)."
        );
    }
    else if (nearType != "none" && nPolarisable == 0)
    {
        warnings.append
        (
            "nearField " + nearType + " has no polarisable parcel (every"
            " epsilonR equals the medium's " + Foam::name(epsMedium) + ")."
            " Remove the nearField entry (no cost)."
        );
    }

    for (const string& w : warnings)
    {
        // Warning without the source location: the message names the entry
        Warning() << "Scene check: " << w.c_str() << nl << endl;
    }
    if (warnings.empty())
    {
        Info<< "    no warnings" << nl;
    }
    Info<< endl;

    return warnings;
}


// ************************************************************************* //
