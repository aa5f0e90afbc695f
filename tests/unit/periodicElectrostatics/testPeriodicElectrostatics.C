/*---------------------------------------------------------------------------*\
    chargedFoam: unit tests of the tri-periodic electrostatics kernels
    (GoogleTest)

    Independent references: Madelung constants of NaCl and CsCl, the
    Wigner-type constant of a charge in a cubic box with a neutralising
    background, the Coulomb force of a small dipole in a large box with its
    analytic tinfoil correction, finite-difference energy gradients, exact
    conservation properties (Boutsikakis 2023, Sec. 2.3), and Ewald as the
    reference of the approximate kernels.
\*---------------------------------------------------------------------------*/

#include "ewaldSum.H"
#include "quasiPeriodicDirect.H"
#include "pseudoParticle.H"
#include "p3m.H"
#include "coulombCollision.H"
#include "pairwiseCoulomb.H"
#include "mathematicalConstants.H"
#include "Random.H"
#include "IStringStream.H"

#include <gtest/gtest.h>

using namespace Foam;
using constant::mathematical::pi;

namespace
{

// Uniform random cloud in the box [0, L); charges q0 (mono) or +-q0 random
void randomCloud
(
    const label n,
    const vector& L,
    pointField& x,
    scalarField& q,
    const bool mono,
    const label seed = 1,
    const scalar q0 = 1e-9
)
{
    Random rnd(seed);
    x.setSize(n);
    q.setSize(n);
    for (label i = 0; i < n; ++i)
    {
        x[i] = cmptMultiply
        (
            L,
            vector
            (
                rnd.sample01<scalar>(), rnd.sample01<scalar>(),
                rnd.sample01<scalar>()
            )
        );
        q[i] = mono ? q0 : (rnd.sample01<scalar>() < 0.5 ? -q0 : q0);
    }
}

scalar rmsDiff(const vectorField& a, const vectorField& b)
{
    scalar s = 0;
    forAll(a, i) s += magSqr(a[i] - b[i]);
    return Foam::sqrt(s/a.size());
}

scalar rms(const vectorField& a)
{
    scalar s = 0;
    forAll(a, i) s += magSqr(a[i]);
    return Foam::sqrt(s/a.size());
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Ewald  * * * * * * * * * * * * * * * * * //

TEST(periodicEwald, MadelungNaCl)
{
    // Conventional cubic NaCl cell (a = 1), 8 ions; nearest distance 1/2.
    // E = -N_pairs M k q^2/r0, M = 1.747564594633 (e.g. Kittel)
    const scalar q = 1e-9;
    pointField x;
    scalarField c;
    for (label i = 0; i < 2; ++i)
    for (label j = 0; j < 2; ++j)
    for (label k = 0; k < 2; ++k)
    {
        x.append(point(0.5*i + 0.1, 0.5*j + 0.1, 0.5*k + 0.1));
        c.append(((i + j + k) % 2 == 0) ? q : -q);
    }
    const ewaldSum ewald(vector::uniform(1));
    const scalar E = ewald.energy(x, c);
    const scalar Eref = -4*1.747564594633*ewald.k()*q*q/0.5;
    EXPECT_NEAR(E/Eref, 1.0, 1e-10);

    // Forces vanish by symmetry
    vectorField f;
    ewald.compute(x, c, f);
    EXPECT_LT(rms(f), 1e-10*ewald.k()*q*q/0.25);
}


TEST(periodicEwald, MadelungCsClOrthorhombicCheck)
{
    // CsCl: 2 ions, r0 = sqrt(3)/2, M = 1.762674773070. Run it also as an
    // orthorhombic box of two cells along z (4 ions, energy doubles)
    const scalar q = 1e-9;
    const pointField x({point(0.2, 0.3, 0.1), point(0.7, 0.8, 0.6)});
    const scalarField c(List<scalar>({q, -q}));
    const ewaldSum ewald(vector::uniform(1));
    const scalar Eref = -1.762674773070*ewald.k()*q*q/(0.5*Foam::sqrt(3.0));
    EXPECT_NEAR(ewald.energy(x, c)/Eref, 1.0, 1e-10);

    const pointField x2
    ({
        point(0.2, 0.3, 0.1), point(0.7, 0.8, 0.6),
        point(0.2, 0.3, 1.1), point(0.7, 0.8, 1.6)
    });
    const scalarField c2(List<scalar>({q, -q, q, -q}));
    const ewaldSum ewald2(vector(1, 1, 2));
    EXPECT_NEAR(ewald2.energy(x2, c2)/(2*Eref), 1.0, 1e-10);
}


TEST(periodicEwald, SingleChargeNeutralisingBackground)
{
    // One charge in a cube of edge L with a uniform neutralising
    // background: E = xi q^2/(2 L), xi = -2.837297479481 (simple cubic
    // Wigner lattice constant, Nijboer & de Wette 1957)
    const scalar q = 2e-9, L = 0.3;
    const ewaldSum ewald(vector::uniform(L));
    const scalar E =
        ewald.energy(pointField(1, point(0.1, 0.2, 0.05)), scalarField(1, q));
    EXPECT_NEAR(E/(ewald.k()*q*q*(-2.837297479481)/(2*L)), 1.0, 1e-10);
}


TEST(periodicEwald, SmallDipoleInLargeBox)
{
    // +q at (d/2, 0, 0), -q at (-d/2, 0, 0) in a cube L >> d. Tinfoil:
    // the image dipoles cancel in spherical order and the surface term adds
    // (4 pi/3V) q M: F_+ = -k q^2/d^2 (1 - (4 pi/3)(d/L)^3) + O((d/L)^5)
    const scalar q = 1e-9, d = 0.01;
    for (const scalar L : {0.1, 0.2})
    {
        const pointField x
        ({
            point(0.5*L + 0.5*d, 0.5*L, 0.5*L),
            point(0.5*L - 0.5*d, 0.5*L, 0.5*L)
        });
        const scalarField c(List<scalar>({q, -q}));
        const ewaldSum ewald(vector::uniform(L));
        vectorField f;
        ewald.compute(x, c, f);
        const scalar Fc = ewald.k()*q*q/(d*d);
        const scalar dev = (-f[0].x() - Fc)/Fc;
        const scalar expected = -(4*pi/3)*Foam::pow(d/L, 3);
        EXPECT_NEAR(dev/expected, 1.0, 10*sqr(d/L)) << "L = " << L;
        EXPECT_NEAR(f[0].x(), -f[1].x(), 1e-12*Fc);
    }
}


TEST(periodicEwald, ForceIsMinusEnergyGradient)
{
    // Non-neutral mixed cloud in an orthorhombic box: central differences
    const vector L(1.0, 0.8, 1.3);
    pointField x;
    scalarField q;
    randomCloud(20, L, x, q, false, 7);
    q[0] *= 2;  // non-neutral whatever the draw
    const ewaldSum ewald(L);
    vectorField f;
    ewald.compute(x, q, f);
    const scalar h = 1e-5;
    for (const label i : {0, 5, 13})
    {
        for (direction d = 0; d < 3; ++d)
        {
            pointField xp(x), xm(x);
            xp[i][d] += h;
            xm[i][d] -= h;
            const scalar g =
                -(ewald.energy(xp, q) - ewald.energy(xm, q))/(2*h);
            EXPECT_NEAR(g, f[i][d], 1e-6*mag(f[i]) + 1e-8*rms(f));
        }
    }
}


TEST(periodicEwald, SubsetAndToleranceConvergence)
{
    // Forces on a subset equal the full evaluation; a tighter tolerance
    // (different splitting and cutoffs) changes nothing beyond 1e-10
    const vector L(1, 1, 1);
    pointField x;
    scalarField q;
    randomCloud(300, L, x, q, true, 3);
    const ewaldSum ewald(L);
    vectorField f, fs, ft;
    ewald.compute(x, q, f);
    const labelList targets({0, 17, 150, 299});
    ewald.forces(x, q, targets, fs);
    forAll(targets, k)
    {
        EXPECT_LT(mag(fs[k] - f[targets[k]]), 1e-10*mag(f[targets[k]]));
    }
    const ewaldSum tight(L, 1, 1e-13);
    tight.compute(x, q, ft);
    EXPECT_LT(rmsDiff(f, ft), 1e-10*rms(ft));
}


// * * * * * * * * * * * * * * Quasi-periodic direct * * * * * * * * * * * * //

TEST(periodicDirect, MeanForceIsZero)
{
    // Boutsikakis 2023, Sec. 2.3 / Fig. 15: Newton's third law pair by pair
    const vector L(2*pi, 2*pi, 2*pi);
    pointField x;
    scalarField q;
    randomCloud(500, L, x, q, true, 11, 5e-9);
    for (const label Nper : {1, 2})
    {
        const quasiPeriodicDirect direct(L, 1, Nper);
        vectorField f;
        direct.compute(x, q, f);
        const vector mean = sum(f)/f.size();
        EXPECT_LT(mag(mean), 1e-13*rms(f)) << "Nper = " << Nper;
    }
}


TEST(periodicDirect, ConvergenceInNperAndEwaldLimit)
{
    // Fig. 7 style: error vs the largest Nper falls with Nper; and the
    // derived limit: direct(Nper) - dipole term -> Ewald (tinfoil)
    const vector L(1, 1, 1);
    pointField x;
    scalarField q;
    randomCloud(60, L, x, q, true, 5);
    vectorField fEwald;
    ewaldSum(L).compute(x, q, fEwald);

    const label NperMax = 8;
    vectorField fMax;
    quasiPeriodicDirect(L, 1, NperMax).compute(x, q, fMax);

    scalar prevErr = GREAT, prevEw = GREAT;
    for (label Nper = 1; Nper < NperMax; ++Nper)
    {
        vectorField f, fc;
        quasiPeriodicDirect(L, 1, Nper).compute(x, q, f);
        quasiPeriodicDirect(L, 1, Nper, true).compute(x, q, fc);
        const scalar err = rmsDiff(f, fMax)/rms(fMax);
        const scalar errEw = rmsDiff(fc, fEwald)/rms(fEwald);
        Info<< "    Nper " << Nper << ": rms rel. diff. to Nper = "
            << NperMax << ": " << err << ", (minus dipole) to Ewald: "
            << errEw << nl;
        EXPECT_LT(err, prevErr);
        EXPECT_LT(errEw, prevEw);
        prevErr = err;
        prevEw = errEw;
    }
    // Without the dipole term the limit differs from Ewald at O(1)
    const scalar errNoDipole = rmsDiff(fMax, fEwald)/rms(fEwald);
    Info<< "    Nper " << NperMax << " without dipole term vs Ewald: "
        << errNoDipole << nl;
    EXPECT_LT(prevEw, 1e-3);
    EXPECT_GT(errNoDipole, 100*prevEw);
}


TEST(periodicDirect, PotentialsMinimumImageAndNperDivergence)
{
    // Nper = 1 against the minimum-image sum written out here; a
    // mono-charged cloud's mean potential grows as Nper^2 (Boutsikakis
    // 2023, Eq. 12 and Fig. 6): as the square of the cube's edge
    // (2 Nper - 1) L (a uniformly charged cube), so <phi>/(2 Nper - 1)^2
    // levels off
    const vector L(1, 1, 1);
    pointField x;
    scalarField q;
    randomCloud(50, L, x, q, true, 43);
    scalarField phi1;
    quasiPeriodicDirect(L, 1, 1).potentials(x, q, phi1);
    const scalar kc = quasiPeriodicDirect(L).k();
    forAll(x, i)
    {
        scalar s = 0;
        forAll(x, j)
        {
            if (j == i) continue;
            vector d = x[i] - x[j];
            for (direction c = 0; c < 3; ++c)
            {
                d[c] -= L[c]*std::round(d[c]/L[c]);
            }
            s += q[j]/mag(d);
        }
        EXPECT_NEAR(phi1[i], kc*s, 1e-12*mag(kc*s));
    }
    scalarList ratio;
    for (const label Nper : {4, 6, 8})
    {
        scalarField phi;
        quasiPeriodicDirect(L, 1, Nper).potentials(x, q, phi);
        ratio.append(average(phi)/sqr(scalar(2*Nper - 1)));
        Info<< "    Nper " << Nper << ": <phi>/(2 Nper - 1)^2 = " << ratio.last()
            << nl;
    }
    // The limit: the potential at the centre of a uniformly charged cube,
    // k rho a^2 (3 ln(2 + sqrt 3) - pi/2), rho of the N - 1 other charges
    const scalar cubeCentre = 3*Foam::log(2 + Foam::sqrt(3.0)) - pi/2;
    const scalar limit = kc*(x.size() - 1)*1e-9*cubeCentre;
    Info<< "    limit " << limit << nl;
    EXPECT_LT(mag(ratio[2]/limit - 1), mag(ratio[0]/limit - 1));
    EXPECT_LT(mag(ratio[2]/limit - 1), 1e-3);
}


// * * * * * * * * * * * * * * Pseudo-particle  * * * * * * * * * * * * * * //

TEST(periodicPseudoParticle, InteractingChargeSum)
{
    // Boutsikakis 2023, Sec. 2.3: every particle sees (2 Nper - 1)^3 sum q
    // (minus itself), rectangle sections included
    const vector L(1, 1.2, 0.9);
    pointField x;
    scalarField q;
    for (const bool mono : {true, false})
    {
        randomCloud(2000, L, x, q, mono, 13);
        const scalar Q = sum(q), Qabs = sum(mag(q));
        for (const label Nper : {1, 2})
        {
            for (const label Ne : {4, 7})
            {
                const pseudoParticle pp(L, 1, Nper, 1, Ne);
                const scalarField qs(pp.interactingCharge(x, q));
                scalar maxErr = 0;
                forAll(qs, i)
                {
                    const scalar expect = scalar(pow3(scalar(2*Nper - 1)))*Q - q[i];
                    maxErr = max(maxErr, mag(qs[i] - expect));
                }
                EXPECT_LT(maxErr, 1e-12*scalar(pow3(scalar(2*Nper - 1)))*Qabs)
                    << "mono " << mono << " Nper " << Nper << " Ne " << Ne;
            }
        }
    }
}


TEST(periodicPseudoParticle, OptimalNeAndErrorFallsWithNv)
{
    // App. A.2: Ne_opt = Np^(1/6) ((2Nv+1)/(2Nper-1))^(1/2)
    EXPECT_EQ(pseudoParticle::optimalNe(10000, 1, 1), 8);     // 8.04
    EXPECT_EQ(pseudoParticle::optimalNe(100000, 1, 1), 12);   // 11.8
    EXPECT_EQ(pseudoParticle::optimalNe(100, 1, 1), 4);       // clipped

    // Table 3 trend (Np = 1e4, Ne = 8: Nv = 1, 2, 3): the error vs the
    // direct method falls with Nv; Np = 2000 here to stay fast
    const vector L(1, 1, 1);
    pointField x;
    scalarField q;
    randomCloud(2000, L, x, q, true, 17);
    vectorField fd;
    quasiPeriodicDirect(L).compute(x, q, fd);
    scalar prev = GREAT;
    for (const label Nv : {1, 2, 3})
    {
        vectorField f;
        pseudoParticle(L, 1, 1, Nv, 8).compute(x, q, f);
        const periodicForceError e(f, fd);
        Info<< "    Ne 8 Nv " << Nv << ": ";
        e.write(Info);
        Info<< nl;
        EXPECT_LT(e.median, prev);
        prev = e.median;
    }
}


// * * * * * * * * * * * * * * * * * P3M  * * * * * * * * * * * * * * * * * //

TEST(periodicP3M, ErrorWithinEstimateAndFallsWithAccuracy)
{
    const vector L(1, 1, 1);
    for (const bool mono : {false, true})
    {
        pointField x;
        scalarField q;
        randomCloud(2000, L, x, q, mono, 19);
        vectorField fRef;
        ewaldSum(L).compute(x, q, fRef);

        scalar prev = GREAT;
        for (const scalar acc : {1e-2, 1e-3, 1e-4, 1e-5})
        {
            const p3m pm(L, 1, acc);
            vectorField f;
            pm.compute(x, q, f);
            const scalar err = rmsDiff(f, fRef);
            const p3m::parameters& p = pm.params();
            Info<< "    mono " << mono << " accuracy " << acc
                << ": rms error " << err << " estimate " << p.error
                << " target " << p.target << " (rc " << p.rCut
                << " alpha " << p.alpha << " mesh " << p.mesh[0] << ')'
                << nl;
            // The estimates are rms over random systems: the measured error
            // must not exceed the estimate by more than a factor 2, nor the
            // requested target by more than that
            EXPECT_LT(err, 2*p.error);
            EXPECT_LT(err, 2*p.target);
            EXPECT_LT(err, prev);
            prev = err;
        }
    }
}


TEST(periodicP3M, OrthorhombicAndOrders)
{
    const vector L(1.0, 0.7, 1.4);
    pointField x;
    scalarField q;
    randomCloud(1000, L, x, q, false, 23);
    vectorField fRef;
    ewaldSum(L).compute(x, q, fRef);
    for (const label P : {3, 4, 6, 7})
    {
        const p3m pm(L, 1, 1e-4, P);
        vectorField f;
        pm.compute(x, q, f);
        const scalar err = rmsDiff(f, fRef);
        Info<< "    order " << P << ": rms error " << err << " estimate "
            << pm.params().error << nl;
        EXPECT_LT(err, 2*pm.params().error) << "order " << P;
    }
}


TEST(periodicP3M, SmallSystemsAndWrapping)
{
    // All-pairs fallback (few particles) against Ewald, and positions
    // outside the box give the forces of their wrapped images
    const vector L(1, 1, 1);
    for (const label n : {1, 2, 7})
    {
        pointField x;
        scalarField q;
        randomCloud(n, L, x, q, false, 31);
        vectorField fRef, f;
        ewaldSum(L).compute(x, q, fRef);
        const p3m pm(L, 1, 1e-5);
        pm.compute(x, q, f);
        const scalar scale = pm.forceScale(q);
        EXPECT_LT(rmsDiff(f, fRef), 2*pm.params().error + 1e-12*scale)
            << "n = " << n;
    }

    pointField x;
    scalarField q;
    randomCloud(500, L, x, q, true, 37);
    pointField xs(x);
    forAll(xs, i)
    {
        xs[i] += vector(i % 3 - 1, 2*(i % 2) - 1, -3*(i % 5 == 0));
    }
    for (const word method : {"ewald", "direct", "pseudoParticle", "p3m"})
    {
        dictionary dict(IStringStream("L 1;")());
        dict.add("method", method);
        autoPtr<periodicElectrostatics> k = periodicElectrostatics::New(dict);
        vectorField f, fs;
        k->compute(x, q, f);
        k->compute(xs, q, fs);
        EXPECT_LT(rmsDiff(f, fs), 1e-9*rms(f)) << method;
    }
}


TEST(periodicP3M, PotentialsAreEwaldEnergyDerivatives)
{
    // The potential at charge i is dU/dq_i of Ewald's energy (self term
    // and neutralising background included); U is quadratic in q, so the
    // central difference with step q0 is exact to round-off. Mixed,
    // non-neutral cloud in an orthorhombic box; serial P3M against it
    const vector L(1.0, 0.8, 1.3);
    pointField x;
    scalarField q;
    randomCloud(200, L, x, q, false, 41);
    q[0] *= 3;
    const ewaldSum ewald(L);
    const labelList probe({0, 1, 57, 123, 199});
    scalarField phiRef(probe.size());
    forAll(probe, k)
    {
        scalarField qp(q), qm(q);
        qp[probe[k]] += 1e-9;
        qm[probe[k]] -= 1e-9;
        phiRef[k] = (ewald.energy(x, qp) - ewald.energy(x, qm))/2e-9;
    }
    // Potential scale: k q0 n^(1/3), a charge at the mean spacing
    const scalar scale =
        ewald.k()*1e-9*std::cbrt(x.size()/(L.x()*L.y()*L.z()));
    scalar prev = GREAT;
    for (const scalar acc : {1e-3, 1e-5})
    {
        const p3m pm(L, 1, acc);
        scalarField phi;
        pm.potentials(x, q, phi);
        scalar err = 0;
        forAll(probe, k)
        {
            err = max(err, mag(phi[probe[k]] - phiRef[k]));
        }
        // Sum of q phi / 2 is the energy
        const scalar U = 0.5*sum(q*phi), Uref = ewald.energy(x, q);
        Info<< "    accuracy " << acc << ": largest |phi - dU/dq| / k q0 "
            << "n^(1/3) = " << err/scale << ", energy " << U << " vs Ewald "
            << Uref << nl;
        EXPECT_LT(err, 10*acc*scale);
        EXPECT_NEAR(U, Uref, 10*acc*scale*sum(mag(q)));
        EXPECT_LT(err, prev);
        prev = err;
    }
}


// * * * * * * * * * * * * * * Isotropy, Eq. (10) * * * * * * * * * * * * * //

TEST(periodicIsotropy, ForceCovariance)
{
    // Jittered lattice of like charges (no close pairs: finite force
    // variance). Off-diagonal/diagonal of <F'_i F'_j> (Eq. 10) ~ sampling
    // noise sqrt(2/N) ~ 2 % for N = 4096; allow 4 sigma
    const label n = 16, N = n*n*n;
    const vector L(1, 1, 1);
    Random rnd(29);
    pointField x(N);
    scalarField q(N, 1e-9);
    label m = 0;
    for (label i = 0; i < n; ++i)
    for (label j = 0; j < n; ++j)
    for (label k = 0; k < n; ++k)
    {
        x[m++] = (point(i, j, k) + 0.8*vector
        (
            rnd.sample01<scalar>(), rnd.sample01<scalar>(),
            rnd.sample01<scalar>()
        ))/n;
    }
    const scalar tol = 4*Foam::sqrt(2.0/N);
    for (const word method : {"direct", "p3m"})
    {
        dictionary dict(IStringStream("L 1; Nper 1;")());
        dict.add("method", method);
        autoPtr<periodicElectrostatics> kernel =
            periodicElectrostatics::New(dict);
        vectorField f;
        kernel->compute(x, q, f);
        const tensor C = forceCovariance(f);
        const scalar F2 = tr(C)/3;
        Info<< "    " << method << ": <F'F'>/F^2 = " << C/F2 << nl;
        for (direction a = 0; a < 3; ++a)
        {
            EXPECT_NEAR(C(a, a)/F2, 1, tol) << method;
            for (direction b = a + 1; b < 3; ++b)
            {
                EXPECT_NEAR(C(a, b)/F2, 0, tol) << method;
            }
        }
    }
}


// * * * * * * * * * * * * * * * Selection  * * * * * * * * * * * * * * * * //

TEST(periodicSelection, DictionaryAndErrors)
{
    FatalError.throwExceptions();
    FatalIOError.throwExceptions();

    for (const word method : {"ewald", "direct", "pseudoParticle", "p3m"})
    {
        dictionary dict(IStringStream("L (1 2 3); epsilonR 2;")());
        dict.add("method", method);
        autoPtr<periodicElectrostatics> k = periodicElectrostatics::New(dict);
        EXPECT_EQ(k->method(), method);
        EXPECT_NEAR(k->k()*2/pairwiseCoulomb().k(), 1, 1e-14);
        EXPECT_EQ(k->L(), vector(1, 2, 3));
    }

    EXPECT_THROW
    (
        periodicElectrostatics::New
        (
            dictionary(IStringStream("method fmm; L 1;")())
        ),
        Foam::error
    );
    EXPECT_THROW
    (
        periodicElectrostatics::New
        (
            dictionary(IStringStream("method p3m; L 1; order 9;")())
        ),
        Foam::error
    );
    EXPECT_THROW
    (
        periodicElectrostatics::New
        (
            dictionary(IStringStream("method direct; L (1 0 1);")())
        ),
        Foam::error
    );
    EXPECT_THROW
    (
        periodicElectrostatics::New
        (
            dictionary(IStringStream("method pseudoParticle; L 1; Ne 3;")())
        ),
        Foam::error
    );

    // Size mismatch
    const quasiPeriodicDirect direct(vector::uniform(1));
    vectorField f;
    EXPECT_THROW
    (
        direct.compute(pointField(3, Zero), scalarField(2, 1), f),
        Foam::error
    );

    FatalError.dontThrowExceptions();
    FatalIOError.dontThrowExceptions();
}


// * * * * * * * * * * * * Time-step criterion, Eq. (23) * * * * * * * * * * //

TEST(periodicCoulombCollision, Table5TimeStepCriterion)
{
    // Boutsikakis 2023, Table 5 with Sec. 3.3: Q = 5 nC, m = 1.80e-4 kg,
    // n = 1e4/(2 pi)^3; d_C/dl of every row follows from the converged
    // agitation qp2 = 4.5721e-3 m^2/s^2 (dt = 5e-3 s) by Eqs. (21-22),
    // dl = <|w|> dt. Tolerance: m = 1.80e-4 kg is printed with 3 digits
    // (+-0.28 %, d_C ~ 1/m); the other inputs have 5.
    const scalar k = pairwiseCoulomb().k();
    const scalar Q = 5e-9, m = 1.8e-4, qp2 = 4.5721e-3;
    const scalar n = 1e4/pow3(2*pi);
    const scalar w = coulombCollision::meanRelativeSpeed(qp2);
    const scalar dC = coulombCollision::diameter(k, Q, Q, m, m, w);
    const scalar rows[4][2] =
        {{50e-3, 25.82}, {25e-3, 51.63}, {10e-3, 129.09}, {5e-3, 258.17}};
    for (const auto& r : rows)
    {
        EXPECT_NEAR(dC/(w*r[0])/r[1], 1, 2.8e-3) << "dt = " << r[0];
    }

    // Eq. (23): dt_max = 0.01 d_C/<|w|>; the paper finds convergence for
    // dt <= 1e-2 s (0.28 % error) but not at 2.5e-2 s
    const scalar dtMax = coulombCollision::maxTimeStep(k, Q, Q, m, m, qp2);
    EXPECT_NEAR(dtMax, 0.01*dC/w, 1e-15);
    EXPECT_GT(dtMax, 1e-2);
    EXPECT_LT(dtMax, 2.5e-2);

    // Sec. 3.1: Nv_min for Ne = 8 is the Nv = 1 of Table 4
    EXPECT_EQ(coulombCollision::minNv(8, dC, 2*pi), 1);

    // Eq. (27) is Eqs. (21), (22) and (25) combined: 3 pi/16 = 0.589
    const scalar qp2e = coulombCollision::agitationEstimate(k, Q, m, n);
    const scalar dCe = coulombCollision::diameter
    (
        k, Q, Q, m, m, coulombCollision::meanRelativeSpeed(qp2e)
    );
    EXPECT_NEAR(dCe/coulombCollision::diameterEstimate(n), 1, 1e-12);
    EXPECT_NEAR(coulombCollision::diameterEstimate(1), 0.589, 5e-4);

    // Eq. (25) vs the measured agitation of Table 5: "~" within 10 %
    EXPECT_NEAR(qp2e/qp2, 1, 0.1);

    // Eq. (26): tau_el = sqrt(6) tau_C, tau_C = 1/(2Q) sqrt(m/(k n))
    EXPECT_NEAR
    (
        coulombCollision::tauEl(k, Q, m, n),
        Foam::sqrt(6.0)/(2*Q)*Foam::sqrt(m/(k*n)),
        1e-12*coulombCollision::tauEl(k, Q, m, n)
    );

    // Named error for a non-positive mass
    FatalError.throwExceptions();
    EXPECT_THROW(coulombCollision::diameter(k, Q, Q, 0, m, w), Foam::error);
    FatalError.dontThrowExceptions();
}


int main(int argc, char** argv)
{
    ::testing::InitGoogleTest(&argc, argv);
    return RUN_ALL_TESTS();
}


// ************************************************************************* //
