/*---------------------------------------------------------------------------*\
    chargedFoam: unit tests of the pairwise Coulomb kernel (GoogleTest)

    References are independent of the kernel: hand-computed Coulomb forces,
    symmetry, the exact momentum balance, and a finite-difference gradient
    of the energy.
\*---------------------------------------------------------------------------*/

#include "pairwiseCoulomb.H"
#include "Random.H"
#include "error.H"

#include <gtest/gtest.h>

using namespace Foam;

namespace
{

// Coulomb constant from CODATA 2018: k = 8.9875517923(14)e9 N m^2/C^2
const scalar kCODATA = 8.9875517923e9;

// Random cloud of n charges in the unit cube, charges of both signs
void randomCloud(const label n, pointField& x, scalarField& q, label seed = 1)
{
    Random rnd(seed);
    x.setSize(n);
    q.setSize(n);
    for (label i = 0; i < n; ++i)
    {
        x[i] = point(rnd.sample01<scalar>(), rnd.sample01<scalar>(), rnd.sample01<scalar>());
        q[i] = 1e-9*(2*rnd.sample01<scalar>() - 1);
    }
}

scalar maxMag(const vectorField& f)
{
    scalar m = 0;
    for (const vector& v : f) m = max(m, mag(v));
    return m;
}

} // End anonymous namespace


TEST(pairwiseCoulomb, CoulombConstantIsCODATA)
{
    const pairwiseCoulomb coulomb;
    EXPECT_NEAR(coulomb.k()/kCODATA, 1.0, 1e-10);
}


TEST(pairwiseCoulomb, HandComputedPair)
{
    // q1 = 1 nC at the origin, q2 = -2 nC at (0.1, 0, 0):
    // |F| = k*2e-18/0.01 = 1.79751035846e-6 N, attraction along +x on q1
    const pairwiseCoulomb coulomb;
    List<point> x({point(0, 0, 0), point(0.1, 0, 0)});
    List<scalar> q({1e-9, -2e-9});
    vectorField f(2, Zero);
    coulomb.addForces(x, q, f);

    EXPECT_NEAR(f[0].x()/1.79751035846e-6, 1.0, 1e-10);
    EXPECT_EQ(f[0].y(), 0);
    EXPECT_EQ(f[0].z(), 0);
    EXPECT_EQ(f[1].x(), -f[0].x());

    const vector fp = coulomb.pairForce(x[0], q[0], x[1], q[1]);
    EXPECT_EQ(fp.x(), f[0].x());
}


TEST(pairwiseCoulomb, HandComputedEquilateralTriangle)
{
    // Three equal charges on a triangle of side a: each is pushed outward
    // from the centroid with |F| = sqrt(3) k q^2/a^2
    const pairwiseCoulomb coulomb;
    const scalar a = 0.02, qv = 3e-9;
    List<point> x({point(0, 0, 0), point(a, 0, 0), point(a/2, a*Foam::sqrt(3.0)/2, 0)});
    scalarField q(3, qv);
    vectorField f(3, Zero);
    coulomb.addForces(x, q, f);

    const point c = (x[0] + x[1] + x[2])/3;
    const scalar expected = Foam::sqrt(3.0)*kCODATA*qv*qv/(a*a);
    for (label i = 0; i < 3; ++i)
    {
        EXPECT_NEAR(mag(f[i])/expected, 1.0, 1e-9);
        EXPECT_NEAR((f[i]/mag(f[i])) & ((x[i] - c)/mag(x[i] - c)), 1.0, 1e-14);
    }
}


TEST(pairwiseCoulomb, MomentumConservedToRoundOff)
{
    const pairwiseCoulomb coulomb;
    pointField x;
    scalarField q;
    randomCloud(200, x, q);
    vectorField f(x.size(), Zero);
    coulomb.addForces(x, q, f);

    // Sum of |f| sets the round-off scale of the sum of f
    scalar scale = 0;
    for (const vector& v : f) scale += mag(v);
    EXPECT_LT(mag(sum(f)), 1e-14*scale);
}


TEST(pairwiseCoulomb, TranslationInvariant)
{
    const pairwiseCoulomb coulomb;
    pointField x;
    scalarField q;
    randomCloud(50, x, q, 7);
    vectorField f(x.size(), Zero), fShifted(x.size(), Zero);
    coulomb.addForces(x, q, f);

    const vector shift(1.3, -2.7, 0.4);
    const pointField xShifted(x + shift);
    coulomb.addForces(xShifted, q, fShifted);

    EXPECT_LT(maxMag(fShifted - f), 1e-10*maxMag(f));
}


TEST(pairwiseCoulomb, PermittivityScalesForces)
{
    const pairwiseCoulomb vacuum, medium(2.5);
    pointField x;
    scalarField q;
    randomCloud(20, x, q, 3);
    vectorField f1(x.size(), Zero), f2(x.size(), Zero);
    vacuum.addForces(x, q, f1);
    medium.addForces(x, q, f2);
    EXPECT_LT(maxMag(f2 - f1/2.5), 1e-14*maxMag(f1));
}


TEST(pairwiseCoulomb, PairListEqualsDirectSum)
{
    const pairwiseCoulomb coulomb;
    pointField x;
    scalarField q;
    randomCloud(40, x, q, 11);

    DynamicList<labelPair> pairs;
    for (label i = 0; i < x.size(); ++i)
        for (label j = i + 1; j < x.size(); ++j)
            pairs.append(labelPair(i, j));

    vectorField fDirect(x.size(), Zero), fPairs(x.size(), Zero);
    coulomb.addForces(x, q, fDirect);
    coulomb.addForces(x, q, pairs, fPairs);
    EXPECT_LT(maxMag(fPairs - fDirect), 1e-14*maxMag(fDirect));
}


TEST(pairwiseCoulomb, SplitTargetsAndSourcesEqualFullSum)
{
    // The parallel pattern: local pairs + forces of the remote charges
    const pairwiseCoulomb coulomb;
    pointField x;
    scalarField q;
    randomCloud(60, x, q, 5);
    vectorField fAll(x.size(), Zero);
    coulomb.addForces(x, q, fAll);

    const label nA = 25;
    const pointField xA(SubList<point>(x, nA)), xB(SubList<point>(x, x.size() - nA, nA));
    const scalarField qA(SubList<scalar>(q, nA)), qB(SubList<scalar>(q, q.size() - nA, nA));
    vectorField fA(nA, Zero);
    coulomb.addForces(xA, qA, fA);
    coulomb.addForces(xA, qA, xB, qB, fA);

    for (label i = 0; i < nA; ++i)
    {
        EXPECT_LT(mag(fA[i] - fAll[i]), 1e-13*maxMag(fAll));
    }

    // Energy splits the same way
    const scalar eAll = coulomb.energy(x, q);
    const scalar eSplit =
        coulomb.energy(xA, qA) + coulomb.energy(xB, qB)
      + coulomb.energy(xA, qA, xB, qB);
    EXPECT_NEAR(eSplit/eAll, 1.0, 1e-12);
}


TEST(pairwiseCoulomb, FieldTimesChargeIsForceAlsoSplit)
{
    // E_i = F_i/q_i for charged particles; a neutral particle still
    // feels the field of the others (hand sum for particle 0)
    const pairwiseCoulomb coulomb;
    pointField x;
    scalarField q;
    randomCloud(40, x, q, 7);
    q[0] = 0;
    vectorField f(x.size(), Zero), E(x.size(), Zero);
    coulomb.addForces(x, q, f);
    coulomb.addFields(x, q, E);
    for (label i = 1; i < x.size(); ++i)
    {
        EXPECT_LT(mag(q[i]*E[i] - f[i]), 1e-12*maxMag(f));
    }
    vector E0(Zero);
    for (label j = 1; j < x.size(); ++j)
    {
        const vector r = x[0] - x[j];
        E0 += kCODATA*q[j]*r/pow3(mag(r));
        EXPECT_LT(mag(coulomb.pairField(x[0], x[j], q[j]) - kCODATA*q[j]*r/pow3(mag(r))), 1e-9*mag(kCODATA*q[j]*r/pow3(mag(r))));
    }
    EXPECT_LT(mag(E[0] - E0), 1e-9*mag(E0));

    // Targets/sources split = full sum
    const label nA = 15;
    const pointField xA(SubList<point>(x, nA)), xB(SubList<point>(x, x.size() - nA, nA));
    const scalarField qA(SubList<scalar>(q, nA)), qB(SubList<scalar>(q, q.size() - nA, nA));
    vectorField EA(nA, Zero);
    coulomb.addFields(xA, qA, EA);
    coulomb.addFields(xA, xB, qB, EA);
    for (label i = 0; i < nA; ++i)
    {
        EXPECT_LT(mag(EA[i] - E[i]), 1e-12*mag(E[i]));
    }
}


TEST(pairwiseCoulomb, ForceIsMinusEnergyGradient)
{
    const pairwiseCoulomb coulomb;
    pointField x;
    scalarField q;
    randomCloud(10, x, q, 13);
    vectorField f(x.size(), Zero);
    coulomb.addForces(x, q, f);

    const scalar h = 1e-6;
    for (label i = 0; i < x.size(); ++i)
    {
        for (direction c = 0; c < 3; ++c)
        {
            pointField xp(x), xm(x);
            xp[i][c] += h;
            xm[i][c] -= h;
            const scalar dEdx =
                (coulomb.energy(xp, q) - coulomb.energy(xm, q))/(2*h);
            EXPECT_NEAR(-dEdx, f[i][c], 1e-5*maxMag(f));
        }
    }
}


TEST(pairwiseCoulomb, HandComputedEnergy)
{
    // U = k q1 q2/r = k*(1e-9)(-2e-9)/0.1 = -1.79751035846e-7 J
    const pairwiseCoulomb coulomb;
    List<point> x({point(0, 0, 0), point(0, 0.1, 0)});
    List<scalar> q({1e-9, -2e-9});
    EXPECT_NEAR(coulomb.energy(x, q)/-1.79751035846e-7, 1.0, 1e-10);
}


TEST(pairwiseCoulomb, CoincidentChargesAreAnError)
{
    FatalError.throwExceptions();
    const pairwiseCoulomb coulomb;
    List<point> x({point(0, 0, 0), point(1, 0, 0), point(0, 0, 0)});
    scalarField q(3, 1e-9);
    vectorField f(3, Zero);
    EXPECT_THROW(coulomb.addForces(x, q, f), Foam::error);
    EXPECT_THROW(coulomb.energy(x, q), Foam::error);
    FatalError.dontThrowExceptions();
}


TEST(pairwiseCoulomb, NonPositivePermittivityIsAnError)
{
    FatalError.throwExceptions();
    EXPECT_THROW(pairwiseCoulomb(0), Foam::error);
    EXPECT_THROW(pairwiseCoulomb(-1), Foam::error);
    FatalError.dontThrowExceptions();
}


int main(int argc, char** argv)
{
    ::testing::InitGoogleTest(&argc, argv);
    return RUN_ALL_TESTS();
}


// ************************************************************************* //


TEST(pairwiseCoulomb, CutoffSumEqualsBruteForceTruncation)
{
    // Cell-list truncated sum vs a brute-force loop with the same cutoff;
    // with a cutoff beyond the cloud it is the full sum
    const pairwiseCoulomb coulomb;
    pointField x;
    scalarField q;
    randomCloud(400, x, q, 11);
    for (const scalar rCut : {0.05, 0.13, 0.3, 2.0})
    {
        vectorField E(x.size(), Zero);
        coulomb.addFieldsWithinCutoff(x, x, q, rCut, E, 0);
        vectorField Eref(x.size(), Zero);
        forAll(x, i)
        {
            forAll(x, j)
            {
                const vector r = x[i] - x[j];
                if (i != j && magSqr(r) < sqr(rCut))
                {
                    Eref[i] += kCODATA*q[j]*r/pow3(mag(r));
                }
            }
        }
        scalar maxE = 0, maxErr = 0;
        forAll(x, i)
        {
            maxE = max(maxE, mag(Eref[i]));
            maxErr = max(maxErr, mag(E[i] - Eref[i]));
        }
        EXPECT_LT(maxErr, 1e-9*maxE) << "rCut " << rCut;
    }

    vectorField Efull(x.size(), Zero), Ecut(x.size(), Zero);
    coulomb.addFields(x, q, Efull);
    coulomb.addFieldsWithinCutoff(x, x, q, 10, Ecut, 0);
    forAll(x, i)
    {
        EXPECT_LT(mag(Ecut[i] - Efull[i]), 1e-12*mag(Efull[i]));
    }
}
