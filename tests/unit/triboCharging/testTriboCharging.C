/*---------------------------------------------------------------------------*\
    chargedFoam: unit tests of the tribocharging kernel (GoogleTest)

    References:
      - Rasera 2022 (Powder Technol. 117607), Tables 1-6, reproduced to the
        precision they are printed with. Tolerance of a tabulated result
        f(x_1..x_n) computed from tabulated inputs x_k: half a unit in the
        last printed digit of f, plus the first-order effect of half a unit
        in the last printed digit of every input,
            tol = hu(f) + sum_k |f(.., x_k + hu(x_k), ..) - f(x)|,
        (the digits are read from the numbers as printed, see "printed").
        Rows the paper's own numbers do not reproduce are asserted to be
        outside that tolerance by the documented amount, so that a change
        of the kernel cannot hide or fake them;
      - values computed independently by hand (Python, CODATA 2018 eps0,
        quoted to 16 digits) for every table row;
      - a Hertz impact of a sphere on a plane integrated step by step, whose
        loading-only charge sum must converge to A_max kappa_c eps0 (Gamma -
        E.n), and exact identities between the paper's equations.
\*---------------------------------------------------------------------------*/

#include "triboCharging.H"
#include "mathematicalConstants.H"
#include "error.H"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <iostream>
#include <string>
#include <vector>

using namespace Foam;
using constant::mathematical::pi;

namespace
{

// CODATA 2018
const scalar eps0CODATA = 8.8541878128e-12;

//- A number as printed in the paper: value and half a unit in its last
//  printed digit, both times scale (unit conversion, diameter -> radius)
struct printed
{
    scalar value;
    scalar halfUnit;

    printed(const std::string& s, const scalar scale = 1)
    {
        const std::string::size_type e = s.find_first_of("eE");
        const std::string mant = s.substr(0, e);
        const int ex = (e == std::string::npos) ? 0 : std::stoi(s.substr(e + 1));
        const std::string::size_type dot = mant.find('.');
        const int decimals =
            (dot == std::string::npos) ? 0 : int(mant.size() - dot - 1);

        value = std::stod(s)*scale;
        halfUnit = 0.5*std::pow(10.0, ex - decimals)*std::abs(scale);
    }
};


//- Tolerance of f(inputs) against the printed output (see the header)
scalar printedTolerance
(
    const std::function<scalar(const std::vector<scalar>&)>& f,
    const std::vector<printed>& in,
    const printed& out
)
{
    std::vector<scalar> x;
    for (const printed& p : in)
    {
        x.push_back(p.value);
    }
    const scalar f0 = f(x);

    scalar tol = out.halfUnit;
    for (size_t k = 0; k < in.size(); ++k)
    {
        std::vector<scalar> xk(x);
        xk[k] += in[k].halfUnit;
        tol += std::abs(f(xk) - f0);
    }
    return tol;
}


//- Rasera Table 1 (particle on a wall) with the mechanical data of Table 2
struct wallRow
{
    const char* name;
    const char* rad;        // Table 1 "Rad. [mm]"
    bool diameter;          // column holds the diameter (PTFE, HDPE)
    const char* qI;         // [C]
    const char* dq;         // [C]
    const char* qSat;       // [C]
    const char* Gamma;      // [V/m]
    const char* kappa;      // [-]
    const char* Y;          // Table 2 [GPa]
    const char* nu;
    const char* rho;        // [kg/m^3]
    const char* vn;         // [m/s]

    // Independent hand computation (Python, eps0 CODATA 2018)
    scalar GammaHand;
    scalar A25Hand;
    scalar kappaHand;

    // Paper value reproduced? If not: documented relative difference
    bool GammaOk;
    scalar GammaRelDiff;
    bool kappaOk;
    scalar kappaRelDiff;
};


const std::vector<wallRow> table1 =
{
    {
        "PTFE/Al", "3.18", true, "-1.71e-10", "-2.70e-11", "-6.57e-10",
        "-2.34e6", "9.64", "0.564", "0.42", "2150", "2.56",
        -2.335675617070365e+06, 1.831936118993036e-07, 9.634324769779024,
        true, 0, true, 0
    },
    {
        "HDPE/Al", "3.18", true, "-3.2e-11", "-4.70e-12", "-3.97e-10",
        "-1.39e6", "3.65", "0.800", "0.46", "968", "2.56",
        -1.411359543343889e+06, 1.137556148726656e-07, 3.596137293618346,
        false, 1.5367e-2, false, -1.4757e-2
    },
    {
        "aLM/SS", "0.275", false, "2.29e-12", "-1.65e-12", "-1.81e-11",
        "-2.15e6", "36.62", "18.0", "0.3", "1540", "4.9",
        -2.151070247139533e+06, 2.099480870397470e-09, 36.62942052747226,
        true, 0, true, 0
    },
    {
        "ASP/SS", "0.275", false, "-1.37e-12", "-2.41e-12", "-4.01e-11",
        "-4.77e6", "16.45", "7.2", "0.3", "1400", "5.5",
        -4.765630768524601e+06, 3.197894549960126e-09, 18.49186262433277,
        true, 0, false, 0.12413
    },
    {
        "SG/SS", "0.275", false, "-1.01e-12", "-8.16e-13", "-1.58e-11",
        "-1.88e6", "28.55", "23.0", "0.21", "1581", "4.5",
        -1.877729828994730e+06, 1.832549961735300e-09, 28.61155175870481,
        true, 0, true, 0
    }
};


// Gamma of a Table 1 row from (qSat, r): Eq. (17)
scalar GammaOf(const std::vector<scalar>& x)
{
    return triboCharging::GammaFromSaturationCharge(x[0], x[1]);
}

// kappa_c of a Table 1 row from (dq, r, qSat, qI, rho, Y, nu, vn):
// Eq. (20) with dA from Eq. (25)
scalar kappaOf(const std::vector<scalar>& x)
{
    const scalar dA =
        triboCharging::maxContactAreaWall(x[1], x[4], x[5], x[6], x[7]);
    return triboCharging::kappaWall(x[0], dA, x[1], x[2], x[3]);
}


struct wallInputs
{
    printed r, qI, dq, qSat, Y, nu, rho, vn;

    explicit wallInputs(const wallRow& row)
    :
        r(row.rad, row.diameter ? 0.5e-3 : 1e-3),
        qI(row.qI),
        dq(row.dq),
        qSat(row.qSat),
        Y(row.Y, 1e9),
        nu(row.nu),
        rho(row.rho),
        vn(row.vn)
    {}
};


void report
(
    const std::string& what,
    const scalar computed,
    const printed& paper,
    const scalar tol
)
{
    std::cout
        << "    " << what << ": computed " << computed
        << ", paper " << paper.value
        << ", rel. diff " << (computed - paper.value)/paper.value
        << ", printed-precision tol " << tol/std::abs(paper.value)
        << (std::abs(computed - paper.value) <= paper.halfUnit
            ? ", rounds to the printed value" : "")
        << std::endl;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * Constants and identities  * * * * * * * * * * //

TEST(triboCharging, PermittivityIsCODATA)
{
    // (by value: pairwiseCoulomb's constant has no out-of-line definition)
    const scalar pc = pairwiseCoulomb::vacuumPermittivity;
    EXPECT_EQ(triboCharging::eps0, eps0CODATA);
    EXPECT_EQ(triboCharging::eps0, pc);
}


TEST(triboCharging, HandComputedChargeTransfer)
{
    // Eq. (16): dA = 1e-8 m^2, kappa_c = 10, Gamma = -2e6 V/m,
    // E.n = 5e5 V/m: dq = 1e-8*10*eps0*(-2.5e6) = -2.2135469532e-12 C
    const scalar dq = triboCharging::chargeTransfer(1e-8, 10, -2e6, 5e5);
    EXPECT_NEAR(dq/(-2.2135469532e-12), 1.0, 1e-10);

    const triboCharging tc(10, -2e6);
    EXPECT_EQ(tc.chargeTransfer(1e-8, 5e5), dq);
    EXPECT_NEAR
    (
        triboCharging::chargeDensity(10, -2e6, 5e5)*1e-8/dq, 1.0, 1e-14
    );
}


TEST(triboCharging, ShrinkingAreaTransfersNothing)
{
    // Convention: charge is transferred on loading only (dA > 0)
    const triboCharging tc(9.64, -2.34e6);
    EXPECT_EQ(tc.chargeTransfer(-1e-9, 0), 0);
    EXPECT_EQ(tc.chargeTransfer(0, 0), 0);
    EXPECT_EQ(tc.chargeTransfer(-1e-9, -1e7), 0);
    EXPECT_EQ(triboCharging::chargeTransfer(-1e-9, 9.64, -2.34e6, 0), 0);
    EXPECT_EQ(triboCharging::chargeTransfer(0, 9.64, -2.34e6, 3e6), 0);
    EXPECT_LT(tc.chargeTransfer(1e-9, 0), 0);

    // Loading to A, unloading to A/2 and reloading to A: the reload
    // transfers again for the area regained (dA from the previous step)
    const scalar A = 1e-8;
    scalar q = tc.chargeTransfer(A, 0);
    q += tc.chargeTransfer(-A/2, 0);
    EXPECT_EQ(q, tc.chargeTransfer(A, 0));
    q += tc.chargeTransfer(A/2, 0);
    EXPECT_NEAR(q/tc.chargeTransfer(1.5*A, 0), 1.0, 1e-14);
}


TEST(triboCharging, WorkFunctionGamma)
{
    // Eqs. (14)-(15): 1 eV difference over delta_e = 500 nm (Laurentie's
    // value): 1 V/500 nm = 2e6 V/m, negative on the body of the higher
    // work function (it takes the electrons: PTFE on steel, Rasera
    // Table 5)
    const scalar e = triboCharging::elementaryCharge;
    EXPECT_NEAR
    (
        triboCharging::GammaFromWorkFunctions(5.0*e, 4.0*e, 500e-9)/(-2e6),
        1.0,
        1e-14
    );
    EXPECT_NEAR
    (
        triboCharging::GammaFromWorkFunctions(4.0*e, 4.5*e, 1e-9)/5e8,
        1.0,
        1e-14
    );
}


TEST(triboCharging, SaturationGammaForms)
{
    // Eq. (17): q_sat/(4 pi eps0 r^2) = sigma_sat/eps0
    const scalar r = 1.59e-3, qSat = -6.57e-10;
    const scalar sigma = qSat/(4*pi*r*r);
    EXPECT_NEAR
    (
        triboCharging::GammaFromSaturationCharge(qSat, r)
       /triboCharging::GammaFromSaturationChargeDensity(sigma),
        1.0,
        1e-14
    );

    // Eq. (18): like particles give zero, the order gives the sign
    EXPECT_EQ(triboCharging::GammaFromSaturationChargeDensity(sigma, sigma), 0);
    EXPECT_NEAR
    (
        triboCharging::GammaFromSaturationChargeDensity(sigma, 0)
       /triboCharging::GammaFromSaturationChargeDensity(sigma),
        1.0,
        1e-14
    );
    EXPECT_EQ
    (
        triboCharging::GammaFromSaturationChargeDensity(1e-5, 3e-5),
       -triboCharging::GammaFromSaturationChargeDensity(3e-5, 1e-5)
    );

    // Eq. (19): sigma_f/eps0 + Phi_sat/r
    EXPECT_NEAR
    (
        triboCharging::GammaSaturationModel(-4.5e-6, -1600, 2e-3)
       /(-4.5e-6/eps0CODATA - 8e5),
        1.0,
        1e-14
    );
}


TEST(triboCharging, Eq20IsEq16WithSphereFields)
{
    // Eq. (20) = Eq. (16) solved for kappa_c with Gamma from Eq. (17) and
    // the field of the particle's own charge at its surface
    const scalar r = 1.59e-3, dA = 1.8e-7;
    const scalar qSat = -6.57e-10, qI = -1.71e-10, dq = -2.7e-11;
    const scalar k20 = triboCharging::kappaWall(dq, dA, r, qSat, qI);
    const scalar k16 = triboCharging::kappaFromTransfer
    (
        dq,
        dA,
        triboCharging::GammaFromSaturationCharge(qSat, r),
        triboCharging::surfaceField(qI, r)
    );
    EXPECT_NEAR(k20/k16, 1.0, 1e-13);

    // and charging with that kappa_c gives back the measured dq
    const triboCharging tc(k20, triboCharging::GammaFromSaturationCharge(qSat, r));
    EXPECT_NEAR(tc.chargeTransfer(dA, triboCharging::surfaceField(qI, r))/dq, 1.0, 1e-13);
}


TEST(triboCharging, Eq21ReducesToEq22ForLikeParticles)
{
    // Equal radii and saturation charges: the bracket of Eq. (21) becomes
    // r^2 (q_j - q_i) and Eq. (21) becomes Eq. (22)
    const scalar r = 1.59e-3, dA = 6e-8, dq = 8.57e-13;
    const scalar qI = -4e-13, qJ = 4.02e-13, qSat = -1e-10;
    EXPECT_NEAR
    (
        triboCharging::kappaPair(dq, dA, r, qSat, qI, r, qSat, qJ)
       /triboCharging::kappaLikePair(dq, dA, r, qJ - qI),
        1.0,
        1e-12
    );

    // Eq. (23) is Eq. (22) with dq = q_j - q_i
    EXPECT_NEAR
    (
        triboCharging::kappaLikePair(dq, dA, r, dq)
       /triboCharging::kappaLikePair(dA, r),
        1.0,
        1e-14
    );

    // Eq. (24): Gamma kappa_c = dq/(dA eps0); a neutral sphere on a wall
    // (q_i = 0) has Gamma kappa_c = that product
    const scalar Gk = triboCharging::GammaKappa(dq, dA);
    const scalar qS = 1e-10;
    EXPECT_NEAR
    (
        triboCharging::kappaWall(dq, dA, r, qS, 0)
       *triboCharging::GammaFromSaturationCharge(qS, r)/Gk,
        1.0,
        1e-13
    );
}


TEST(triboCharging, Eq25IsHertzMaxAreaOnRigidWall)
{
    // Eq. (25) = pi r delta_max, delta_max from the energy balance of the
    // Hertz force Eq. (4) with Y* of Eq. (6) against a rigid wall
    for (const wallRow& row : table1)
    {
        const wallInputs in(row);
        const scalar m = triboCharging::sphereMass(in.r.value, in.rho.value);
        const scalar YStar =
            triboCharging::effectiveModulus(in.Y.value, in.nu.value);
        const scalar AH = triboCharging::hertzMaxContactArea
        (
            m, in.r.value, YStar, in.vn.value
        );
        const scalar A25 = triboCharging::maxContactAreaWall
        (
            in.r.value, in.rho.value, in.Y.value, in.nu.value, in.vn.value
        );
        EXPECT_NEAR(A25/AH, 1.0, 1e-13) << row.name;
        EXPECT_NEAR(A25/row.A25Hand, 1.0, 1e-13) << row.name;

        // a very stiff wall tends to the rigid one
        EXPECT_NEAR
        (
            triboCharging::effectiveModulus(in.Y.value, in.nu.value, 1e30, 0.3)
           /YStar,
            1.0,
            1e-14
        );
    }
}


TEST(triboCharging, Eq26IsTwoToThePoint6TimesHertz)
{
    // Eq. (26) as printed is 2^0.6 x pi r* delta_max of the Hertz impact
    // of the same two spheres (PA66 of Table 4, 3.18 and 4.0 mm, and an
    // unlike pair)
    const scalar Y = 1.27e9, nu = 0.49, rho = 1140, v = 1.71;
    for (const scalar d : {3.18e-3, 4.0e-3})
    {
        const scalar r = d/2;
        const scalar m = triboCharging::sphereMass(r, rho);
        const scalar A26 =
            triboCharging::maxContactAreaPair(m, r, Y, nu, m, r, Y, nu, v);
        const scalar AH = triboCharging::hertzMaxContactArea
        (
            triboCharging::effectiveMass(m, m),
            triboCharging::effectiveRadius(r, r),
            triboCharging::effectiveModulus(Y, nu, Y, nu),
            v
        );
        EXPECT_NEAR(A26/AH, std::pow(2.0, 0.6), 1e-13);
    }

    const scalar mI = 1e-5, mJ = 3e-5, rI = 1e-3, rJ = 2e-3;
    const scalar A26 = triboCharging::maxContactAreaPair
    (
        mI, rI, 1e9, 0.4, mJ, rJ, 7e10, 0.3, 2
    );
    const scalar AH = triboCharging::hertzMaxContactArea
    (
        triboCharging::effectiveMass(mI, mJ),
        triboCharging::effectiveRadius(rI, rJ),
        triboCharging::effectiveModulus(1e9, 0.4, 7e10, 0.3),
        2
    );
    EXPECT_NEAR(A26/AH, std::pow(2.0, 0.6), 1e-13);
}


// * * * * * * * * * * * * Hertz impact, integrated by hand * * * * * * * * * //

namespace
{

//- Charge gained by a sphere in a normal Hertz impact on a rigid wall,
//  integrated by velocity Verlet with nSteps per contact duration; the
//  contact area A = pi r delta is fed to Eq. (16) as increments. signedSum
//  adds dA < 0 too (the convention NOT used), for comparison.
scalar impactCharge
(
    const triboCharging& tc,
    const scalar En,
    const label nSteps,
    const bool signedSum = false
)
{
    const scalar r = 1.59e-3, rho = 2150, Y = 0.564e9, nu = 0.42, v = 2.56;
    const scalar m = triboCharging::sphereMass(r, rho);
    const scalar YStar = triboCharging::effectiveModulus(Y, nu);
    const scalar k = 4.0/3.0*YStar*std::sqrt(r);

    // Hertz contact duration 2.9432 delta_max/v (Johnson 1985)
    const scalar deltaMax = triboCharging::hertzMaxOverlap(m, r, YStar, v);
    const scalar dt = 2.9432*deltaMax/v/nSteps;

    scalar delta = 0, u = v, a = 0, A = 0, q = 0;
    for (label n = 0; n < 10*nSteps; ++n)
    {
        delta += u*dt + 0.5*a*dt*dt;
        const scalar aNew = delta > 0 ? -k*std::pow(delta, 1.5)/m : 0;
        u += 0.5*(a + aNew)*dt;
        a = aNew;

        const scalar ANew = triboCharging::contactArea(r, delta);
        const scalar dA = ANew - A;
        q += signedSum ? dA*tc.kappaC()*eps0CODATA*(tc.Gamma() - En)
                       : tc.chargeTransfer(dA, En);
        A = ANew;

        if (delta <= 0)
        {
            break;
        }
    }
    EXPECT_LE(delta, 0) << "impact did not end";
    return q;
}

} // End anonymous namespace


TEST(triboCharging, HertzImpactConvergesToMaxArea)
{
    // Loading to A_max (Eq. 25) in a constant field: the charge of the
    // impact is A_max kappa_c eps0 (Gamma - E.n); the incremental sum over a
    // discretised impact converges to it at second order (Verlet and the
    // sampling of the maximum)
    const triboCharging tc(9.64, -2.34e6);
    const scalar Amax = triboCharging::maxContactAreaWall
    (
        1.59e-3, 2150, 0.564e9, 0.42, 2.56
    );

    for (const scalar En : {0.0, 1e6, -3e6})
    {
        const scalar exact = Amax*9.64*eps0CODATA*(-2.34e6 - En);

        scalar errPrev = GREAT;
        std::cout << "    E.n = " << En << " V/m, A_max = " << Amax
                  << " m^2, exact dq = " << exact << " C" << std::endl;
        for (const label n : {10, 40, 160, 640, 2560})
        {
            const scalar err = std::abs(impactCharge(tc, En, n)/exact - 1);
            std::cout << "      " << n << " steps per contact: rel. error "
                      << err << std::endl;
            EXPECT_LT(err, 3.0/(n*n)) << n << " steps";
            EXPECT_LT(err, errPrev/8) << n << " steps";
            errPrev = err;
        }
        EXPECT_LT(errPrev, 1e-6);

        // The rejected convention (dA < 0 transfers back) nets nothing
        EXPECT_LT(std::abs(impactCharge(tc, En, 640, true)/exact), 1e-12);
    }
}


// * * * * * * * * * * * * * * * Rasera Table 1  * * * * * * * * * * * * * * //

TEST(triboCharging, Table1MatchesHandComputation)
{
    for (const wallRow& row : table1)
    {
        const wallInputs in(row);
        const scalar G = GammaOf({in.qSat.value, in.r.value});
        const scalar k = kappaOf
        ({
            in.dq.value, in.r.value, in.qSat.value, in.qI.value,
            in.rho.value, in.Y.value, in.nu.value, in.vn.value
        });
        EXPECT_NEAR(G/row.GammaHand, 1.0, 1e-13) << row.name;
        EXPECT_NEAR(k/row.kappaHand, 1.0, 1e-13) << row.name;
    }
}


TEST(triboCharging, Table1ReproducesPaper)
{
    for (const wallRow& row : table1)
    {
        const wallInputs in(row);
        std::cout << "  " << row.name << std::endl;

        // Gamma, Eq. (17)
        {
            const printed paper(row.Gamma);
            const std::vector<printed> x({in.qSat, in.r});
            const scalar G = GammaOf({x[0].value, x[1].value});
            const scalar tol = printedTolerance(GammaOf, x, paper);
            report("Gamma [V/m]", G, paper, tol);

            const scalar rel = (G - paper.value)/paper.value;
            if (row.GammaOk)
            {
                EXPECT_LE(std::abs(G - paper.value), tol) << row.name;

                // stricter: Gamma rounds to the printed value
                EXPECT_LE(std::abs(G - paper.value), paper.halfUnit) << row.name;
            }
            else
            {
                EXPECT_GT(std::abs(G - paper.value), tol) << row.name;
                EXPECT_NEAR(rel, row.GammaRelDiff, 1e-4) << row.name;
            }
        }

        // kappa_c, Eq. (20) with dA of Eq. (25)
        {
            const printed paper(row.kappa);
            const std::vector<printed> x
            ({in.dq, in.r, in.qSat, in.qI, in.rho, in.Y, in.nu, in.vn});
            std::vector<scalar> xv;
            for (const printed& p : x) xv.push_back(p.value);
            const scalar k = kappaOf(xv);
            const scalar tol = printedTolerance(kappaOf, x, paper);
            report("kappa_c", k, paper, tol);

            const scalar rel = (k - paper.value)/paper.value;
            if (row.kappaOk)
            {
                EXPECT_LE(std::abs(k - paper.value), tol) << row.name;
            }
            else
            {
                EXPECT_GT(std::abs(k - paper.value), tol) << row.name;
                EXPECT_NEAR(rel, row.kappaRelDiff, 1e-4) << row.name;
            }
        }
    }
}


TEST(triboCharging, Table1KappaIndependentOfRadius)
{
    // 4 pi r^2 cancels between Eq. (20) and Eq. (25): the diameter/radius
    // ambiguity of the "Rad." column matters for Gamma only
    for (const wallRow& row : table1)
    {
        const wallInputs in(row);
        std::vector<scalar> x
        ({
            in.dq.value, in.r.value, in.qSat.value, in.qI.value,
            in.rho.value, in.Y.value, in.nu.value, in.vn.value
        });
        const scalar k = kappaOf(x);
        x[1] *= 2;
        EXPECT_NEAR(kappaOf(x)/k, 1.0, 1e-13) << row.name;
    }
}


TEST(triboCharging, Table1HDPEReproducedWithQsat392)
{
    // HDPE: Gamma is 1.5 % too large and kappa_c 1.5 % too small with the
    // printed q_sat = -3.97e-10 C. q_sat = -3.92e-10 C reproduces both
    // printed values (-1.39e6 V/m, 3.65): likely a typo in Table 1.
    const wallRow& row = table1[1];
    wallInputs in(row);
    in.qSat = printed("-3.92e-10");

    const printed G(row.Gamma), K(row.kappa);
    const std::vector<printed> xG({in.qSat, in.r});
    const scalar g = GammaOf({xG[0].value, xG[1].value});
    EXPECT_LE(std::abs(g - G.value), printedTolerance(GammaOf, xG, G));

    const std::vector<printed> xK
    ({in.dq, in.r, in.qSat, in.qI, in.rho, in.Y, in.nu, in.vn});
    std::vector<scalar> xv;
    for (const printed& p : xK) xv.push_back(p.value);
    const scalar k = kappaOf(xv);
    EXPECT_LE(std::abs(k - K.value), printedTolerance(kappaOf, xK, K));
    std::cout << "    HDPE with q_sat = -3.92e-10 C: Gamma = " << g
              << " V/m, kappa_c = " << k << std::endl;
}


TEST(triboCharging, Table1ASPReproducedWithDq214)
{
    // ASP: kappa_c = 18.49 with the printed dq = -2.41e-12 C against the
    // printed 16.45 (+12.4 %); the transposed digits dq = -2.14e-12 C give
    // 16.42, within the printed precision. A hypothesis only.
    const wallRow& row = table1[3];
    wallInputs in(row);
    in.dq = printed("-2.14e-12");

    const printed K(row.kappa);
    const std::vector<printed> xK
    ({in.dq, in.r, in.qSat, in.qI, in.rho, in.Y, in.nu, in.vn});
    std::vector<scalar> xv;
    for (const printed& p : xK) xv.push_back(p.value);
    const scalar k = kappaOf(xv);
    EXPECT_LE(std::abs(k - K.value), printedTolerance(kappaOf, xK, K));
    std::cout << "    ASP with dq = -2.14e-12 C: kappa_c = " << k << std::endl;
}


// * * * * * * * * * * * * * * * Rasera Table 3  * * * * * * * * * * * * * * //

TEST(triboCharging, Table3PA66)
{
    // Like PA66 particles (Table 4: Y = 1.27 GPa, nu = 0.49, rho = 1140,
    // v = 1.71 m/s): Gamma = 0 by Eq. (18). kappa_c by Eq. (22) with dA of
    // Eq. (26) and q_j - q_i = Delta sigma_0 (the column printed in [C]).
    // The "Rad." column is a diameter (Chowdhury's 3.2/4.0/4.8 mm spheres);
    // kappa_c does not depend on it (dA ~ r^2).
    //
    // NOT reproduced: 541.4 and 1232.7 against the printed 27.79 and 40.66
    // (x19.5 and x30.3, a size-dependent factor: no constant - unit, 2^0.6
    // of Eq. 26, radius/diameter - explains both rows). Pinned here.
    struct row
    {
        const char* d; const char* dsigma0; const char* dq; const char* kappa;
        scalar A26Hand, kappaHand, AHertzHand;
    };
    const std::vector<row> table3 =
    {
        {"3.18", "8.02e-13", "8.57e-13", "27.79",
         6.270497438194057e-08, 5.413879329996824e+02, 4.136985487089114e-08},
        {"4.0", "4.48e-13", "1.09e-12", "40.66",
         9.921280705975328e-08, 1.232680715717365e+03, 6.545604188266468e-08}
    };

    const scalar Y = 1.27e9, nu = 0.49, rho = 1140, v = 1.71;
    for (const row& t : table3)
    {
        const printed d(t.d, 1e-3), ds(t.dsigma0), dq(t.dq), paper(t.kappa);
        const scalar r = d.value/2;
        const scalar m = triboCharging::sphereMass(r, rho);

        const scalar sigma = 1e-5;
        EXPECT_EQ(triboCharging::GammaFromSaturationChargeDensity(sigma, sigma), 0);

        const scalar A26 =
            triboCharging::maxContactAreaPair(m, r, Y, nu, m, r, Y, nu, v);
        EXPECT_NEAR(A26/t.A26Hand, 1.0, 1e-13) << t.d;

        const scalar AH = triboCharging::hertzMaxContactArea
        (
            triboCharging::effectiveMass(m, m),
            triboCharging::effectiveRadius(r, r),
            triboCharging::effectiveModulus(Y, nu, Y, nu),
            v
        );
        EXPECT_NEAR(AH/t.AHertzHand, 1.0, 1e-13) << t.d;

        const scalar k = triboCharging::kappaLikePair(dq.value, A26, r, ds.value);
        EXPECT_NEAR(k/t.kappaHand, 1.0, 1e-13) << t.d;

        std::cout << "    PA66 " << t.d << " mm: kappa_c (Eqs. 22, 26) = " << k
                  << ", with the Hertz area "
                  << triboCharging::kappaLikePair(dq.value, AH, r, ds.value)
                  << ", Eq. (23) " << triboCharging::kappaLikePair(A26, r)
                  << "; paper " << paper.value << std::endl;
        EXPECT_GT(k/paper.value, 15) << t.d;
    }
}


// * * * * * * * * * * * * * Rasera Tables 5 and 6 * * * * * * * * * * * * * //

TEST(triboCharging, Table6GammaFromTable5ByEq19)
{
    // Gamma(r) = sigma_f/eps0 + Phi_sat/r fitted (least squares) to the
    // 3.18, 7.14 and 11.11 mm PTFE data of Table 5 predicts the 12.7 mm
    // Gamma of Table 6, for the min, avg and max columns
    const std::vector<printed> d
    ({printed("3.18", 0.5e-3), printed("7.14", 0.5e-3), printed("11.11", 0.5e-3)});
    const printed d127("12.7", 0.5e-3);

    const std::vector<std::vector<const char*>> table5 =
    {
        {"-1.44e6", "-9.16e5", "-7.66e5"},
        {"-1.52e6", "-9.62e5", "-8.03e5"},
        {"-1.60e6", "-1.01e6", "-8.41e5"}
    };
    const std::vector<const char*> table6 = {"-7.32e5", "-7.67e5", "-8.03e5"};

    auto predict = [](const std::vector<scalar>& x)
    {
        // x = (r1, r2, r3, G1, G2, G3, r)
        const scalarList r({x[0], x[1], x[2]});
        const scalarList G({x[3], x[4], x[5]});
        scalar sigmaF, PhiSat;
        triboCharging::fitSaturationModel(r, G, sigmaF, PhiSat);
        return triboCharging::GammaSaturationModel(sigmaF, PhiSat, x[6]);
    };

    for (size_t c = 0; c < table6.size(); ++c)
    {
        std::vector<printed> x(d);
        for (const char* g : table5[c])
        {
            x.push_back(printed(g));
        }
        x.push_back(d127);
        std::vector<scalar> xv;
        for (const printed& p : x) xv.push_back(p.value);

        const printed paper(table6[c]);
        const scalar G = predict(xv);
        const scalar tol = printedTolerance(predict, x, paper);
        report("Table 6 Gamma (12.7 mm)", G, paper, tol);
        EXPECT_LE(std::abs(G - paper.value), tol);
        EXPECT_LE(std::abs(G - paper.value), paper.halfUnit);
    }

    // Two exact points are reproduced exactly
    scalar sigmaF, PhiSat;
    triboCharging::fitSaturationModel
    (
        scalarList({1e-3, 2e-3}), scalarList({-3e6, -2e6}), sigmaF, PhiSat
    );
    EXPECT_NEAR(PhiSat/(-2000), 1.0, 1e-12);
    EXPECT_NEAR(sigmaF/(-1e6*eps0CODATA), 1.0, 1e-12);
}


// * * * * * * * * * * * * * * * * Bad input * * * * * * * * * * * * * * * * //

TEST(triboCharging, BadInputIsAnError)
{
    FatalError.throwExceptions();
    const scalar nan = std::nan("");

    // kappa_c < 0, non-finite Gamma
    EXPECT_THROW(triboCharging(-1, -2e6), Foam::error);
    EXPECT_THROW(triboCharging(1, nan), Foam::error);
    EXPECT_THROW(triboCharging::chargeTransfer(1e-8, -0.1, -2e6, 0), Foam::error);
    EXPECT_THROW(triboCharging::chargeTransfer(nan, 1, -2e6, 0), Foam::error);
    EXPECT_THROW(triboCharging::chargeDensity(-1, -2e6, 0), Foam::error);

    // radius <= 0
    for (const scalar r : {0.0, -1e-3})
    {
        EXPECT_THROW(triboCharging::GammaFromSaturationCharge(-1e-10, r), Foam::error);
        EXPECT_THROW(triboCharging::surfaceField(1e-10, r), Foam::error);
        EXPECT_THROW(triboCharging::kappaWall(-1e-11, 1e-7, r, -6e-10, 0), Foam::error);
        EXPECT_THROW(triboCharging::kappaLikePair(1e-12, 1e-7, r, 1e-12), Foam::error);
        EXPECT_THROW(triboCharging::kappaLikePair(1e-7, r), Foam::error);
        EXPECT_THROW(triboCharging::maxContactAreaWall(r, 2150, 5e8, 0.4, 2), Foam::error);
        EXPECT_THROW(triboCharging::sphereMass(r, 2150), Foam::error);
        EXPECT_THROW(triboCharging::effectiveRadius(r, 1e-3), Foam::error);
        EXPECT_THROW(triboCharging::contactArea(r, 1e-6), Foam::error);
        EXPECT_THROW(triboCharging::GammaSaturationModel(0, -1000, r), Foam::error);
        EXPECT_THROW
        (
            triboCharging::maxContactAreaPair(1e-5, r, 1e9, 0.4, 1e-5, 1e-3, 1e9, 0.4, 2),
            Foam::error
        );
    }

    // material and kinematics
    EXPECT_THROW(triboCharging::maxContactAreaWall(1e-3, 0, 5e8, 0.4, 2), Foam::error);
    EXPECT_THROW(triboCharging::maxContactAreaWall(1e-3, 2150, 0, 0.4, 2), Foam::error);
    EXPECT_THROW(triboCharging::maxContactAreaWall(1e-3, 2150, 5e8, 0.6, 2), Foam::error);
    EXPECT_THROW(triboCharging::maxContactAreaWall(1e-3, 2150, 5e8, -1, 2), Foam::error);
    EXPECT_THROW(triboCharging::maxContactAreaWall(1e-3, 2150, 5e8, 0.4, -2), Foam::error);
    EXPECT_THROW(triboCharging::effectiveModulus(5e8, 0.4, 1e9, 0.7), Foam::error);
    EXPECT_THROW(triboCharging::hertzMaxOverlap(0, 1e-3, 1e9, 1), Foam::error);
    EXPECT_THROW(triboCharging::effectiveMass(1e-5, -1e-5), Foam::error);

    // contact area of a measurement <= 0, undetermined or negative kappa_c
    EXPECT_THROW(triboCharging::kappaWall(-1e-11, 0, 1e-3, -6e-10, 0), Foam::error);
    EXPECT_THROW(triboCharging::kappaWall(-1e-11, 1e-7, 1e-3, -6e-10, -6e-10), Foam::error);
    EXPECT_THROW(triboCharging::kappaWall(+1e-11, 1e-7, 1e-3, -6e-10, 0), Foam::error);
    EXPECT_THROW(triboCharging::kappaLikePair(1e-12, 1e-7, 1e-3, 0), Foam::error);
    EXPECT_THROW(triboCharging::kappaLikePair(-1e-12, 1e-7, 1e-3, 1e-12), Foam::error);
    EXPECT_THROW
    (
        triboCharging::kappaPair(1e-12, 1e-7, 1e-3, 1e-10, 0, 1e-3, 1e-10, 0),
        Foam::error
    );
    EXPECT_THROW(triboCharging::kappaFromTransfer(1e-12, 1e-7, 1e5, 1e5), Foam::error);
    EXPECT_THROW(triboCharging::kappaFromTransfer(-1e-12, 1e-7, 1e5, 0), Foam::error);
    EXPECT_THROW(triboCharging::GammaKappa(1e-12, -1e-7), Foam::error);

    // work functions: delta_e <= 0
    EXPECT_THROW(triboCharging::GammaFromWorkFunctions(1e-19, 0, 0), Foam::error);
    EXPECT_THROW(triboCharging::GammaFromWorkFunctions(1e-19, 0, -1e-9), Foam::error);

    // Eq. (19) fit: fewer than two distinct radii, size mismatch
    scalar sF, Ph;
    EXPECT_THROW
    (
        triboCharging::fitSaturationModel(scalarList({1e-3}), scalarList({-1e6}), sF, Ph),
        Foam::error
    );
    EXPECT_THROW
    (
        triboCharging::fitSaturationModel
        (
            scalarList({1e-3, 1e-3}), scalarList({-1e6, -2e6}), sF, Ph
        ),
        Foam::error
    );
    EXPECT_THROW
    (
        triboCharging::fitSaturationModel
        (
            scalarList({1e-3, 2e-3}), scalarList({-1e6}), sF, Ph
        ),
        Foam::error
    );

    FatalError.dontThrowExceptions();
}


int main(int argc, char** argv)
{
    ::testing::InitGoogleTest(&argc, argv);
    return RUN_ALL_TESTS();
}


// ************************************************************************* //
