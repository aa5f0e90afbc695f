/*---------------------------------------------------------------------------*\
    chargedFoam: charged dielectric particles for OpenFOAM
-------------------------------------------------------------------------------
Description
    Unit tests of the induced-dipole kernel (Ruan 2022 Eqs. 45-50) in the
    forms the cloud's near field uses: the CG solve against a dense direct
    solve, forces and torques against finite differences of the energy,
    the cutoff, periodic images, the charges' fields given as an external
    field, and the pair weights of pairs in contact (Eq. 44).

\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>

#include "inducedDipole.H"
#include "pairwiseCoulomb.H"
#include "mathematicalConstants.H"
#include "Random.H"
#include "quaternion.H"

#include <Eigen/Dense>

using namespace Foam;
using Foam::constant::mathematical::pi;

namespace
{

const scalar eps0 = pairwiseCoulomb::vacuumPermittivity;
const scalar kC = 1/(4*pi*eps0);

//- A cloud of n ellipsoids in a cube of edge L, radii ~ a, random shapes,
//  orientations, permittivities (some 1: not polarisable) and charges
struct cloud
{
    List<point> x;
    scalarField q;
    List<tensor> alpha;
    List<vector> semiAxes;
    List<tensor> R;
    scalarField kappa;

    cloud(const label n, const scalar L, const scalar a, const label seed)
    {
        Random rnd(seed);
        while (x.size() < n)
        {
            const point c = L*rnd.sample01<vector>();
            bool clear = true;
            for (const point& y : x)
            {
                clear = clear && mag(c - y) > 6*a;
            }
            if (!clear) continue;
            x.append(c);
            q.append((rnd.sample01<scalar>() - 0.4)*1e-12);
            semiAxes.append(a*vector(1 + 2*rnd.sample01<scalar>(), 1, 0.6 + 0.4*rnd.sample01<scalar>()));
            quaternion o(rnd.sample01<vector>() - vector::uniform(0.5), 2*pi*rnd.sample01<scalar>());
            R.append(o.R());
            kappa.append(x.size() % 4 == 0 ? 1 : 1 + 20*rnd.sample01<scalar>());
            alpha.append(inducedDipole::polarisability(semiAxes.last(), R.last(), kappa.last(), 1));
        }
    }
};


//- The dipoles by a dense direct solve of Eqs. 46-47 (Eigen LU)
List<vector> directDipoles(const cloud& c, const vector& E0)
{
    const label n = c.x.size();
    Eigen::MatrixXd A = Eigen::MatrixXd::Identity(3*n, 3*n);
    Eigen::VectorXd b(3*n);
    for (label i = 0; i < n; ++i)
    {
        vector Ei = E0;
        for (label j = 0; j < n; ++j)
        {
            if (j == i) continue;
            const vector r = c.x[i] - c.x[j];
            const scalar d = mag(r);
            Ei += kC*c.q[j]*r/pow3(d);
            // p_i - alpha_i T_ij p_j = alpha_i Ec_i
            const tensor T = kC*(3*(r*r)/sqr(d) - tensor::I)/pow3(d);
            const tensor aT = c.alpha[i] & T;
            for (label a = 0; a < 3; ++a)
                for (label b2 = 0; b2 < 3; ++b2)
                    A(3*i + a, 3*j + b2) = -aT(a, b2);
        }
        const vector aE = c.alpha[i] & Ei;
        for (label a = 0; a < 3; ++a) b(3*i + a) = aE[a];
    }
    const Eigen::VectorXd p = A.fullPivLu().solve(b);
    List<vector> P(n);
    for (label i = 0; i < n; ++i) P[i] = vector(p(3*i), p(3*i + 1), p(3*i + 2));
    return P;
}


inducedDipole solved(const cloud& c, const vector& E0, const scalar rNear = -1)
{
    inducedDipole dm(1, 1e-13, 1000);
    dm.setParticles(c.x, c.q, c.alpha, List<vector>(c.x.size(), Zero));
    dm.setExternalField(E0);
    dm.setCutoff(rNear);
    dm.solve();
    return dm;
}

} // End anonymous namespace


TEST(inducedDipole, CGMatchesDirectSolve)
{
    const cloud c(30, 2e-3, 5e-5, 1);
    const vector E0(1e5, -2e4, 3e4);
    const inducedDipole dm = solved(c, E0);
    const List<vector> P = directDipoles(c, E0);
    scalar pMax = 0, err = 0;
    forAll(P, i)
    {
        pMax = max(pMax, mag(P[i]));
        err = max(err, mag(P[i] - dm.dipoles()[i]));
    }
    std::printf("30 ellipsoids: %d CG iterations, max |p_CG - p_LU| / max|p| = %.2e\n",
                int(dm.iterations()), err/pMax);
    EXPECT_LT(err, 1e-11*pMax);
    EXPECT_GT(dm.iterations(), 1);
}


TEST(inducedDipole, ForcesAndTorquesAreEnergyGradients)
{
    // W = energy() + externalEnergy() - sum q_i E0 . x_i is the energy of
    // the linear system in the uniform field E0: F_i = -dW/dx_i and the
    // torque about an axis n = -dW/dtheta (rotating alpha_i)
    const cloud c(6, 6e-4, 5e-5, 7);
    const vector E0(5e4, 1e5, -3e4);
    auto W = [&](const cloud& cc)
    {
        const inducedDipole dm = solved(cc, E0);
        scalar w = dm.energy() + dm.externalEnergy();
        forAll(cc.x, i) w -= cc.q[i]*(E0 & cc.x[i]);
        return w;
    };
    const inducedDipole dm = solved(c, E0);
    scalar fMax = 0, mMax = 0;
    forAll(c.x, i)
    {
        fMax = max(fMax, mag(dm.forces()[i]));
        mMax = max(mMax, mag(dm.torques()[i]));
    }
    const scalar h = 1e-9;
    scalar eF = 0, eM = 0;
    forAll(c.x, i)
    {
        for (direction d = 0; d < 3; ++d)
        {
            cloud cp(c), cm(c);
            cp.x[i][d] += h;
            cm.x[i][d] -= h;
            const scalar F = -(W(cp) - W(cm))/(2*h);
            eF = max(eF, mag(F - dm.forces()[i][d]));

            // Rotation by +-th about axis d of particle i
            const scalar th = 1e-6;
            vector n(Zero);
            n[d] = 1;
            const tensor Rp = quaternion(n, th).R(), Rm = quaternion(n, -th).R();
            cp = c;
            cm = c;
            cp.alpha[i] = Rp & c.alpha[i] & Rp.T();
            cm.alpha[i] = Rm & c.alpha[i] & Rm.T();
            const scalar M = -(W(cp) - W(cm))/(2*th);
            eM = max(eM, mag(M - dm.torques()[i][d]));
        }
    }
    std::printf("finite differences of the energy: force error %.2e of max |F|,"
                " torque error %.2e of max |M|\n", eF/fMax, eM/mMax);
    EXPECT_LT(eF, 1e-6*fMax);
    EXPECT_LT(eM, 1e-6*mMax);
}


TEST(inducedDipole, CutoffBeyondTheCloudIsAllPairs)
{
    const cloud c(40, 2e-3, 4e-5, 3);
    const vector E0(0, 0, 1e5);
    const inducedDipole all = solved(c, E0);
    const inducedDipole cut = solved(c, E0, 1.0);
    scalar err = 0, fMax = 0;
    forAll(c.x, i)
    {
        fMax = max(fMax, mag(all.forces()[i]));
        err = max(err, mag(all.forces()[i] - cut.forces()[i]));
    }
    EXPECT_EQ(cut.pairs().size(), 40*39/2);
    EXPECT_LT(err, 1e-12*fMax);

    // A short cutoff keeps only the close pairs
    const inducedDipole shortCut = solved(c, E0, 5e-4);
    label nClose = 0;
    forAll(c.x, i)
        for (label j = i + 1; j < c.x.size(); ++j)
            nClose += mag(c.x[i] - c.x[j]) < 5e-4;
    EXPECT_EQ(shortCut.pairs().size(), nClose);
}


TEST(inducedDipole, ChargeFieldsGivenAsExternalField)
{
    // The far field gives the charges' fields: same result as counting
    // them here (the cloud's decomposition)
    const cloud c(12, 1e-3, 5e-5, 11);
    const vector Ea(2e4, 0, 1e4);
    const inducedDipole ref = solved(c, Ea);

    List<vector> Efar(c.x.size(), Ea);
    forAll(c.x, i)
        forAll(c.x, j)
            if (i != j)
            {
                const vector r = c.x[i] - c.x[j];
                Efar[i] += kC*c.q[j]*r/pow3(mag(r));
            }
    inducedDipole dm(1, 1e-13, 1000);
    dm.setParticles(c.x, c.q, c.alpha, Efar);
    dm.countChargeFields(false);
    dm.solve();
    scalar eF = 0, eM = 0, fMax = 0, mMax = 0;
    forAll(c.x, i)
    {
        fMax = max(fMax, mag(ref.forces()[i]));
        mMax = max(mMax, mag(ref.torques()[i]));
        eF = max(eF, mag(ref.forces()[i] - dm.forces()[i]));
        eM = max(eM, mag(ref.torques()[i] - dm.torques()[i]));
    }
    EXPECT_LT(eF, 1e-11*fMax);
    EXPECT_LT(eM, 1e-11*mMax);
    // The energy of the dipoles in the far field is all of the
    // polarisation energy
    EXPECT_NEAR
    (
        dm.externalEnergy(),
        ref.externalEnergy() + ref.energy()
      - [&](){ scalar u = 0; forAll(c.x, i) for (label j = i + 1; j < c.x.size(); ++j) u += kC*c.q[i]*c.q[j]/mag(c.x[i] - c.x[j]); return u; }(),
        1e-10*mag(dm.externalEnergy())
    );
}


TEST(inducedDipole, PeriodicMinimumImage)
{
    // Two particles near opposite faces of a periodic box interact as the
    // same two particles side by side
    const scalar L = 1e-3;
    const vector s(6e-5, 3e-5, 3e-5);
    const tensor A = inducedDipole::polarisability
    (
        s, quaternion(vector(0, 0, 1), 0.5).R(), 5, 1
    );
    List<point> x({point(0.05e-3, 0.5e-3, 0.5e-3), point(0.9e-3, 0.52e-3, 0.5e-3)});
    List<point> xNear({point(1.05e-3, 0.5e-3, 0.5e-3), point(0.9e-3, 0.52e-3, 0.5e-3)});
    const scalarField q(List<scalar>({1e-13, -2e-13}));
    const List<tensor> alpha({A, A});
    const List<vector> E0(2, vector(1e4, 0, 0));

    inducedDipole per(1, 1e-13, 100), ref(1, 1e-13, 100);
    per.setParticles(x, q, alpha, E0);
    per.setPeriod(vector(L, L, L));
    per.setCutoff(3e-4);
    per.solve();
    ref.setParticles(xNear, q, alpha, E0);
    ref.setCutoff(3e-4);
    ref.solve();
    ASSERT_EQ(per.pairs().size(), 1);
    for (label i = 0; i < 2; ++i)
    {
        EXPECT_LT(mag(per.forces()[i] - ref.forces()[i]), 1e-12*mag(ref.forces()[i]));
        EXPECT_LT(mag(per.torques()[i] - ref.torques()[i]), 1e-12*mag(ref.torques()[i]));
        EXPECT_GT(mag(ref.torques()[i]), 0);
    }
}


TEST(inducedDipole, PairWeightsScaleThePairTerms)
{
    // Ruan Eq. 44: the pair terms of pairs in contact enter forces and
    // torques times w = chi^(2/5); the induction is not weighted. With the
    // charges counted here (c = 1): F_i = q_i E0 + w dF_i, M_i = p_i x E0
    // + w (M_i - p_i x E0). With the charges in E0 (c = 0) the charges'
    // torque is re-weighted too: M_i(w) = M_i(1) + (w - 1) p_i x E_pair,i
    // where E_pair is the whole pair field (charges and dipoles)
    const scalar w = Foam::pow(0.01, 0.4);
    const cloud c(2, 4e-4, 5e-5, 5);
    const vector E0(1e4, 2e4, -1e4);
    const List<labelPair> contact({labelPair(1, 0)});

    inducedDipole one(1, 1e-13, 100), wt(1, 1e-13, 100);
    for (inducedDipole* d : {&one, &wt})
    {
        d->setParticles(c.x, c.q, c.alpha, List<vector>(2, Zero));
        d->setExternalField(E0);
    }
    wt.setPairWeights(contact, w);
    one.solve();
    wt.solve();
    for (label i = 0; i < 2; ++i)
    {
        EXPECT_LT(mag(wt.dipoles()[i] - one.dipoles()[i]), 1e-14*mag(one.dipoles()[i]));
        const vector F = c.q[i]*E0 + w*one.forceIncrements()[i];
        EXPECT_LT(mag(wt.forces()[i] - F), 1e-12*mag(F));
        const vector M0 = one.dipoles()[i] ^ E0;
        const vector M = M0 + w*(one.torques()[i] - M0);
        EXPECT_LT(mag(wt.torques()[i] - M), 1e-12*mag(one.torques()[i]));
    }

    // Charges in E0 (far field), contact pair weighted
    List<vector> Efar(2, E0);
    Efar[0] += kC*c.q[1]*(c.x[0] - c.x[1])/pow3(mag(c.x[0] - c.x[1]));
    Efar[1] += kC*c.q[0]*(c.x[1] - c.x[0])/pow3(mag(c.x[0] - c.x[1]));
    inducedDipole far(1, 1e-13, 100);
    far.setParticles(c.x, c.q, c.alpha, Efar);
    far.countChargeFields(false);
    far.setPairWeights(contact, w);
    far.solve();
    for (label i = 0; i < 2; ++i)
    {
        const vector Epair = one.fields()[i] - E0;
        const vector M = one.torques()[i] + (w - 1)*(one.dipoles()[i] ^ Epair);
        EXPECT_LT(mag(far.torques()[i] - M), 1e-11*mag(one.torques()[i]));
    }
}


int main(int argc, char** argv)
{
    ::testing::InitGoogleTest(&argc, argv);
    return RUN_ALL_TESTS();
}


// ************************************************************************* //
