/*---------------------------------------------------------------------------*\
    chargedFoam: unit tests of the rigid-body rotation kernel (GoogleTest)

    References are independent of the kernel: Ruan 2022 Eqs. (16)-(18) and
    (20) transcribed here from the paper (the Euler equations are
    integrated by a fine classical Runge-Kutta scheme), hand-written
    elementary rotation matrices and Rodrigues' formula, hand-computed
    moments of inertia, and the closed-form torque-free motion of a
    symmetric top (e.g. Landau & Lifshitz, Mechanics, sections 33 and 36).

    Measured numbers are printed as "[ measured ] ..." lines.
\*---------------------------------------------------------------------------*/

#include "rigidBodyRotation.H"
#include "mathematicalConstants.H"
#include "Random.H"
#include "error.H"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <limits>

using namespace Foam;

namespace
{

typedef rigidBodyRotation RBR;

const scalar pi = constant::mathematical::pi;

void report(const char* what, const double value)
{
    std::printf("[ measured ] %-58s %.3e\n", what, value);
}


// Rotation angle [rad] of the relative rotation between a and b
// (q and -q are the same orientation)
scalar angleBetween(const quaternion& a, const quaternion& b)
{
    const quaternion d = conjugate(b)*a;
    return 2*std::atan2(mag(d.v()), mag(d.w()));
}

scalar maxCmptDiff(const tensor& A, const tensor& B)
{
    scalar m = 0;
    for (direction i = 0; i < tensor::nComponents; ++i)
    {
        m = max(m, mag(A[i] - B[i]));
    }
    return m;
}

scalar angleBetweenVectors(const vector& a, const vector& b)
{
    return std::atan2(mag(a ^ b), a & b);
}

// Elementary active rotations by angle a about x and z, written out
tensor Rx(const scalar a)
{
    const scalar c = std::cos(a), s = std::sin(a);
    return tensor(1, 0, 0,  0, c, -s,  0, s, c);
}

tensor Rz(const scalar a)
{
    const scalar c = std::cos(a), s = std::sin(a);
    return tensor(c, -s, 0,  s, c, 0,  0, 0, 1);
}

// Rodrigues: rotation by angle a about the unit axis n
tensor rodrigues(const vector& n, const scalar a)
{
    const tensor K(0, -n.z(), n.y(),  n.z(), 0, -n.x(),  -n.y(), n.x(), 0);
    return tensor::I + std::sin(a)*K + (1 - std::cos(a))*(K & K);
}

// Ruan Eq. (16), upper 3x3 block, transcribed from the paper
tensor ruanEq16
(
    const scalar e1,
    const scalar e2,
    const scalar e3,
    const scalar eta
)
{
    return tensor
    (
        1 - 2*(e2*e2 + e3*e3), 2*(e1*e2 + e3*eta),    2*(e1*e3 - e2*eta),
        2*(e2*e1 - e3*eta),    1 - 2*(e3*e3 + e1*e1), 2*(e2*e3 + e1*eta),
        2*(e3*e1 + e2*eta),    2*(e3*e2 - e1*eta),    1 - 2*(e1*e1 + e2*e2)
    );
}

// Ruan Eq. (17), transcribed from the paper: (eps1, eps2, eps3, eta)
std::array<scalar, 4> ruanEq17
(
    const scalar phi,
    const scalar theta,
    const scalar psi
)
{
    return
    {{
        std::cos((phi - psi)/2)*std::sin(theta/2),
        std::sin((phi - psi)/2)*std::sin(theta/2),
        std::sin((phi + psi)/2)*std::cos(theta/2),
        std::cos((phi + psi)/2)*std::cos(theta/2)
    }};
}


// Reference solution: Ruan Eq. (18) (quaternion kinematics) and Eq. (20)
// (Euler equations, no torque), state (eps1, eps2, eps3, eta, Omega_p),
// classical 4th-order Runge-Kutta with a fine step
typedef std::array<scalar, 7> rotorState;

rotorState ruanRhs(const rotorState& y, const vector& I)
{
    const scalar e1 = y[0], e2 = y[1], e3 = y[2], eta = y[3];
    const scalar Ox = y[4], Oy = y[5], Oz = y[6];

    return
    {{
        0.5*(eta*Ox - e3*Oy + e2*Oz),
        0.5*(e3*Ox + eta*Oy - e1*Oz),
        0.5*(-e2*Ox + e1*Oy + eta*Oz),
        0.5*(-e1*Ox - e2*Oy - e3*Oz),
        Oy*Oz*(I.y() - I.z())/I.x(),
        Oz*Ox*(I.z() - I.x())/I.y(),
        Ox*Oy*(I.x() - I.y())/I.z()
    }};
}

void referenceRK4
(
    quaternion& q,
    vector& omega,
    const vector& I,
    const scalar T,
    const label nSteps
)
{
    rotorState y
    {{
        q.v().x(), q.v().y(), q.v().z(), q.w(),
        omega.x(), omega.y(), omega.z()
    }};
    const scalar h = T/nSteps;

    auto axpy = [](const rotorState& a, const scalar s, const rotorState& b)
    {
        rotorState r;
        for (size_t i = 0; i < r.size(); ++i) r[i] = a[i] + s*b[i];
        return r;
    };

    for (label n = 0; n < nSteps; ++n)
    {
        const rotorState k1 = ruanRhs(y, I);
        const rotorState k2 = ruanRhs(axpy(y, h/2, k1), I);
        const rotorState k3 = ruanRhs(axpy(y, h/2, k2), I);
        const rotorState k4 = ruanRhs(axpy(y, h, k3), I);
        for (size_t i = 0; i < y.size(); ++i)
        {
            y[i] += h/6*(k1[i] + 2*k2[i] + 2*k3[i] + k4[i]);
        }
    }

    q = quaternion(y[3], vector(y[0], y[1], y[2]));
    omega = vector(y[4], y[5], y[6]);
}


// A 2500 kg/m^3 ellipsoid of semi-axes s*(1, 2, 3), s = 50 um:
// I_x > I_y > I_z, so y is the intermediate (unstable) axis
const scalar rho = 2500;
const vector triaxialSemiAxes = 50e-6*vector(1, 2, 3);

scalar ellipsoidMass(const vector& abc)
{
    return rho*4.0/3.0*pi*abc.x()*abc.y()*abc.z();
}


// Statistics of a long torque-free run
struct freeRotorStats
{
    scalar maxEnergyError = 0;     // max |E/E0 - 1|
    scalar energyDrift = 0;        // change of the envelope of E/E0 - 1
    scalar maxMagLError = 0;       // max | |R^T L| / |L| - 1 |
    scalar maxNormError = 0;       // max | |q| - 1 |
    scalar dirErrFirst = 0;        // max direction error of the angular
    scalar dirErrLast = 0;         // momentum of the motion, first/last 10%
    label flips = 0;               // sign changes of Lp_y
};

freeRotorStats runFreeRotor
(
    const quaternion& q0,
    const vector& omega0,
    const vector& I,
    const scalar dt,
    const label nSteps
)
{
    // Independent of the kernel: L = R (I Omega), E = Omega.I.Omega/2
    const vector Lin = q0.R() & vector(cmptMultiply(I, omega0));
    const scalar E0 = 0.5*(omega0 & vector(cmptMultiply(I, omega0)));
    const scalar magL = mag(Lin);
    const label window = nSteps/10;

    freeRotorStats s;
    scalar eMaxFirst = -GREAT, eMinFirst = GREAT;
    scalar eMaxLast = -GREAT, eMinLast = GREAT;

    quaternion qPrev = q0;
    quaternion q = q0;
    RBR::freeRotation(q, Lin, I, dt);
    scalar LyPrev = (Lin & q0.R()).y();

    for (label n = 1; n < nSteps; ++n)
    {
        quaternion qNext = q;
        RBR::freeRotation(qNext, Lin, I, dt);

        const tensor R = q.R();
        const vector Lp = Lin & R;
        const scalar e =
            0.5*(sqr(Lp.x())/I.x() + sqr(Lp.y())/I.y() + sqr(Lp.z())/I.z())
           /E0 - 1;

        s.maxEnergyError = max(s.maxEnergyError, mag(e));
        s.maxMagLError = max(s.maxMagLError, mag(mag(Lp)/magL - 1));
        s.maxNormError = max(s.maxNormError, mag(mag(q) - 1));
        if (Lp.y()*LyPrev < 0) ++s.flips;
        LyPrev = Lp.y();

        // Angular velocity of the computed motion by a central difference
        // of the orientation, and its angular momentum R I R^T omega: it
        // must point along the fixed inertial L, up to O(dt^2)
        quaternion dq = qNext*conjugate(qPrev);
        if (dq.w() < 0) dq = -dq;
        const scalar magV = mag(dq.v());
        const vector omegaIn =
            (2*std::atan2(magV, dq.w())/(2*dt)/magV)*dq.v();
        const vector Lfd = R & vector(cmptMultiply(I, omegaIn & R));
        const scalar dirErr = angleBetweenVectors(Lfd, Lin);

        if (n < window)
        {
            eMaxFirst = max(eMaxFirst, e);
            eMinFirst = min(eMinFirst, e);
            s.dirErrFirst = max(s.dirErrFirst, dirErr);
        }
        else if (n >= nSteps - window)
        {
            eMaxLast = max(eMaxLast, e);
            eMinLast = min(eMinLast, e);
            s.dirErrLast = max(s.dirErrLast, dirErr);
        }

        qPrev = q;
        q = qNext;
    }

    // The energy error of a symplectic splitting oscillates with bounded
    // amplitude; a secular drift would move the top and bottom of the
    // oscillation. Compare the envelope of the first and last tenth.
    s.energyDrift = max(mag(eMaxLast - eMaxFirst), mag(eMinLast - eMinFirst));

    return s;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Inertia * * * * * * * * * * * * * * * * * //

TEST(rigidBodyRotation, PrincipalMomentsOfEllipsoid)
{
    // m = 5, (a, b, c) = (1, 2, 3): I = m/5 (b^2+c^2, c^2+a^2, a^2+b^2)
    const vector I = RBR::principalMoments(5, vector(1, 2, 3));
    EXPECT_DOUBLE_EQ(I.x(), 13);
    EXPECT_DOUBLE_EQ(I.y(), 10);
    EXPECT_DOUBLE_EQ(I.z(), 5);

    // Solid sphere: 2/5 m r^2
    const vector Is = RBR::principalMoments(3, vector(0.5, 0.5, 0.5));
    for (direction i = 0; i < 3; ++i)
    {
        EXPECT_DOUBLE_EQ(Is[i], 2.0/5.0*3*0.25);
    }
}


// * * * * * * * * * * * * * * * * Orientation * * * * * * * * * * * * * * * //

TEST(rigidBodyRotation, EulerAnglesMatchRuanEq16And17)
{
    const scalar angles[][3] =
    {
        {0, 0, 0},
        {0.3, 0.7, -0.2},
        {pi/2, 0, 0},
        {-2.5, 2.9, 1.3},
        {4.0, -1.2, 6.1},
        {1e-9, pi, -1e-9}
    };

    scalar maxErrQ = 0, maxErrR = 0;
    for (const auto& a : angles)
    {
        const quaternion q = RBR::fromEulerAngles(a[0], a[1], a[2]);
        EXPECT_NEAR(mag(q), 1, 1e-15);

        // Ruan's (eps1, eps2, eps3, eta) are q = (eta, eps)
        const std::array<scalar, 4> r = ruanEq17(a[0], a[1], a[2]);
        maxErrQ = max(maxErrQ, mag(q.v().x() - r[0]));
        maxErrQ = max(maxErrQ, mag(q.v().y() - r[1]));
        maxErrQ = max(maxErrQ, mag(q.v().z() - r[2]));
        maxErrQ = max(maxErrQ, mag(q.w() - r[3]));

        // Ruan's R (Eq. 16, inertial -> particle) is the transpose of q.R()
        const tensor R16 = ruanEq16(r[0], r[1], r[2], r[3]);
        maxErrR = max(maxErrR, maxCmptDiff(R16, q.R().T()));
        maxErrR = max(maxErrR, maxCmptDiff(R16, RBR::inertialToParticle(q)));

        // ... and maps inertial to particle coordinates
        const vector xin(0.3, -1.1, 2.0);
        const vector xp = R16 & xin;
        EXPECT_LT(mag(RBR::toInertial(q, xp) - xin), 1e-14);
        EXPECT_LT(mag(RBR::toBody(q, xin) - xp), 1e-14);
    }
    report("Eq.(17) quaternion components, max error", maxErrQ);
    report("Eq.(16) R vs q.R().T(), max component error", maxErrR);
    EXPECT_LT(maxErrQ, 1e-15);
    EXPECT_LT(maxErrR, 1e-15);
}


TEST(rigidBodyRotation, EulerAnglesAreZXZComposition)
{
    Random rnd(7);
    scalar maxErr = 0;
    for (label n = 0; n < 100; ++n)
    {
        const scalar phi = 2*pi*(2*rnd.sample01<scalar>() - 1);
        const scalar theta = pi*rnd.sample01<scalar>();
        const scalar psi = 2*pi*(2*rnd.sample01<scalar>() - 1);

        const quaternion q = RBR::fromEulerAngles(phi, theta, psi);
        EXPECT_NEAR(mag(q), 1, 1e-15);

        // Body -> inertial: Rz(phi) Rx(theta) Rz(psi), by hand and by
        // OpenFOAM's own z-x-z Euler quaternion
        const tensor Rzxz = Rz(phi) & Rx(theta) & Rz(psi);
        maxErr = max(maxErr, maxCmptDiff(q.R(), Rzxz));
        const quaternion qFoam(quaternion::ZXZ, vector(phi, theta, psi));
        maxErr = max(maxErr, maxCmptDiff(q.R(), qFoam.R()));
    }
    report("fromEulerAngles vs Rz Rx Rz, max component error", maxErr);
    EXPECT_LT(maxErr, 1e-14);

    // Hand-checked: phi = pi/2 turns the body x axis onto inertial y,
    // theta = pi/2 turns the body y axis onto inertial z
    const quaternion qPhi = RBR::fromEulerAngles(pi/2, 0, 0);
    EXPECT_LT(mag(RBR::toInertial(qPhi, vector(1, 0, 0)) - vector(0, 1, 0)), 1e-15);
    const quaternion qTheta = RBR::fromEulerAngles(0, pi/2, 0);
    EXPECT_LT(mag(RBR::toInertial(qTheta, vector(0, 1, 0)) - vector(0, 0, 1)), 1e-15);
}


TEST(rigidBodyRotation, AngularMomentumVelocityEnergy)
{
    const vector I = RBR::principalMoments(2, vector(1, 2, 3));
    const quaternion q = RBR::fromEulerAngles(0.4, 1.1, -0.7);
    const vector omegaP(0.3, -1.2, 2.5);

    // L = R (I Omega_p) with the hand-built Rz Rx Rz
    const tensor R = Rz(0.4) & Rx(1.1) & Rz(-0.7);
    const vector Lref = R & vector(I.x()*0.3, -I.y()*1.2, I.z()*2.5);

    const vector Lin = RBR::angularMomentum(q, omegaP, I);
    EXPECT_LT(mag(Lin - Lref), 1e-14*mag(Lref));
    EXPECT_LT(mag(RBR::omegaBody(q, Lin, I) - omegaP), 1e-14*mag(omegaP));

    const scalar Eref =
        0.5*(I.x()*sqr(0.3) + I.y()*sqr(1.2) + I.z()*sqr(2.5));
    EXPECT_NEAR(RBR::kineticEnergy(q, Lin, I), Eref, 1e-14*Eref);

    // The inertial angular velocity R Omega_p, against the hand-built R,
    // and identical to toInertial(omegaBody) (the same operations)
    const vector omegaIn = RBR::omegaInertial(q, Lin, I);
    EXPECT_LT(mag(omegaIn - (R & omegaP)), 1e-14*mag(omegaP));
    const vector viaBody = RBR::toInertial(q, RBR::omegaBody(q, Lin, I));
    EXPECT_EQ(omegaIn.x(), viaBody.x());
    EXPECT_EQ(omegaIn.y(), viaBody.y());
    EXPECT_EQ(omegaIn.z(), viaBody.z());
}


// * * * * * * * * * * * * * * Free rotation * * * * * * * * * * * * * * * * //

TEST(rigidBodyRotation, AsymmetricTopConservesEnergyAndMomentum)
{
    const vector I =
        RBR::principalMoments(ellipsoidMass(triaxialSemiAxes), triaxialSemiAxes);
    const quaternion q0 = RBR::fromEulerAngles(0.4, 1.1, -0.7);
    const label nSteps = 100000;

    struct testCase { const char* name; vector omega; label minFlips; };
    const testCase cases[] =
    {
        // Generic tumbling about the stable (largest moment) axis
        {"generic", 1e3*vector(0.6, 0.5, 0.8), 0},
        // Near the intermediate axis: Dzhanibekov flips of L_y
        {"intermediate axis", 1e3*vector(1e-3, 1, 1e-3), 20}
    };

    for (const testCase& c : cases)
    {
        // 50 steps per rotation period 2 pi/|Omega|
        const scalar dt = 2*pi/mag(c.omega)/50;
        const freeRotorStats s = runFreeRotor(q0, c.omega, I, dt, nSteps);

        std::printf("[ measured ] %s, 1e5 steps of T/50:\n", c.name);
        report("  max |E/E0 - 1| (bounded O(dt^2) oscillation)", s.maxEnergyError);
        report("  secular energy drift (envelope, first vs last 10%)", s.energyDrift);
        report("  max | |L_p|/|L| - 1 |", s.maxMagLError);
        report("  max | |q| - 1 |", s.maxNormError);
        report("  L direction error of the motion, first 10% [rad]", s.dirErrFirst);
        report("  L direction error of the motion, last 10% [rad]", s.dirErrLast);
        std::printf("[ measured ]   sign flips of L_y                 %d\n", int(s.flips));

        EXPECT_LT(s.energyDrift, 1e-6) << c.name;
        EXPECT_LT(s.maxEnergyError, 5e-3) << c.name;
        EXPECT_LT(s.maxMagLError, 1e-12) << c.name;
        EXPECT_LT(s.maxNormError, 1e-14) << c.name;
        EXPECT_LT(s.dirErrFirst, 1e-2) << c.name;
        EXPECT_LT(mag(s.dirErrLast - s.dirErrFirst), 1e-6) << c.name;
        EXPECT_GE(s.flips, c.minFlips) << c.name;
    }
}


TEST(rigidBodyRotation, AsymmetricTopAtParticleStepConservesEnergyTo1e6)
{
    // The stricter reading of "drift < 1e-6": the largest deviation of the
    // energy itself, at a rotation per step typical of DEM collision
    // sub-steps (T/2000, i.e. 3e-3 rad per step), over 1e5 steps
    const vector I =
        RBR::principalMoments(ellipsoidMass(triaxialSemiAxes), triaxialSemiAxes);
    const quaternion q0 = RBR::fromEulerAngles(0.4, 1.1, -0.7);

    for (const vector& omega :
        {vector(1e3*vector(0.6, 0.5, 0.8)), vector(1e3*vector(1e-3, 1, 1e-3))})
    {
        const scalar dt = 2*pi/mag(omega)/2000;
        const freeRotorStats s = runFreeRotor(q0, omega, I, dt, 100000);
        report("T/2000, 1e5 steps: max |E/E0 - 1|", s.maxEnergyError);
        report("T/2000, 1e5 steps: max | |L_p|/|L| - 1 |", s.maxMagLError);
        EXPECT_LT(s.maxEnergyError, 1e-6);
        EXPECT_LT(s.maxMagLError, 1e-12);
    }
}


TEST(rigidBodyRotation, EnergyErrorIsSecondOrder)
{
    const vector I =
        RBR::principalMoments(ellipsoidMass(triaxialSemiAxes), triaxialSemiAxes);
    const quaternion q0 = RBR::fromEulerAngles(0.4, 1.1, -0.7);
    const vector omega0 = 1e3*vector(0.6, 0.5, 0.8);
    const scalar T = 2*pi/mag(omega0);

    // Same physical time (100 periods), halving dt
    scalar prev = 0;
    for (label nPerT = 50; nPerT <= 200; nPerT *= 2)
    {
        const freeRotorStats s =
            runFreeRotor(q0, omega0, I, T/nPerT, 100*nPerT);
        std::printf
        (
            "[ measured ] dt = T/%-4d max |E/E0 - 1| = %.3e",
            int(nPerT), s.maxEnergyError
        );
        if (prev > 0)
        {
            std::printf("  ratio %.3f", prev/s.maxEnergyError);
            EXPECT_NEAR(prev/s.maxEnergyError, 4, 0.4);
        }
        std::printf("\n");
        prev = s.maxEnergyError;
    }
}


TEST(rigidBodyRotation, AsymmetricTopMatchesEulerEquations)
{
    const vector I =
        RBR::principalMoments(ellipsoidMass(triaxialSemiAxes), triaxialSemiAxes);
    const quaternion q0 = RBR::fromEulerAngles(0.4, 1.1, -0.7);
    const vector omega0 = 1e3*vector(0.6, 0.5, 0.8);
    const scalar T = 2*pi/mag(omega0);
    const scalar tEnd = 3*T;

    // Ruan Eqs. (18), (20) by RK4 with 4000 steps per period
    quaternion qRef = q0;
    vector omegaRef = omega0;
    referenceRK4(qRef, omegaRef, I, tEnd, 12000);

    const vector Lin = q0.R() & vector(cmptMultiply(I, omega0));

    scalar prev = 0;
    for (label nPerT = 25; nPerT <= 200; nPerT *= 2)
    {
        quaternion q = q0;
        const label nSteps = 3*nPerT;
        for (label n = 0; n < nSteps; ++n)
        {
            RBR::freeRotation(q, Lin, I, tEnd/nSteps);
        }
        const scalar err = angleBetween(q, qRef);
        const scalar errOmega =
            mag(RBR::omegaBody(q, Lin, I) - omegaRef)/mag(omega0);

        std::printf
        (
            "[ measured ] asymmetric top, 3 periods, dt = T/%-4d"
            " orientation error %.3e rad, omega error %.3e",
            int(nPerT), err, errOmega
        );
        if (prev > 0)
        {
            std::printf("  ratio %.3f", prev/err);
            EXPECT_NEAR(prev/err, 4, 0.5);
        }
        std::printf("\n");
        prev = err;

        // Accuracy scale: a few 1e-2 rad at T/25, as expected for O(dt^2)
        EXPECT_LT(err, 0.2);
    }
}


TEST(rigidBodyRotation, SymmetricTopMatchesAnalyticPrecession)
{
    // Prolate spheroid a = b < c: I_x = I_y = I1, I_z = I3 < I1
    const vector abc = 50e-6*vector(1, 1, 3);
    const vector I = RBR::principalMoments(ellipsoidMass(abc), abc);
    ASSERT_DOUBLE_EQ(I.x(), I.y());
    const scalar I1 = I.x(), I3 = I.z();

    const quaternion q0 = RBR::fromEulerAngles(0.3, 0.7, -0.2);
    const vector omega0 = 1e3*vector(0.5, -0.2, 1);
    const scalar T = 2*pi/mag(omega0);
    const scalar tEnd = 4*T;

    const vector Lin = q0.R() & vector(cmptMultiply(I, omega0));
    const scalar magL = mag(Lin);

    // Analytic torque-free motion of a symmetric top:
    //  - body frame: Omega_3 is constant, (Omega_1, Omega_2) turns about the
    //    symmetry axis at the rate Omega_b = (I3 - I1)/I1 Omega_3
    //  - inertial frame: the body turns about the fixed L at |L|/I1 while
    //    spinning about its symmetry axis at -Omega_b:
    //      q(t) = (L/|L|, |L| t/I1) * q0 * (e_z, -Omega_b t)
    const scalar OmegaB = (I3 - I1)/I1*omega0.z();
    const scalar cb = std::cos(OmegaB*tEnd), sb = std::sin(OmegaB*tEnd);
    const vector omegaExact
    (
        cb*omega0.x() - sb*omega0.y(),
        sb*omega0.x() + cb*omega0.y(),
        omega0.z()
    );
    const quaternion qExact =
        quaternion(Lin/magL, magL*tEnd/I1)*q0
       *quaternion(vector(0, 0, 1), -OmegaB*tEnd);

    // The spheroid's flow is exact (two commuting exact rotations): the
    // error is round-off for any step, down to one step over 4 periods;
    // 10^5 steps turn the body by 2e-4 rad each, below the threshold of
    // the half angles' series (1e-3)
    for
    (
        const label nSteps
      : {label(1), label(7), label(200), label(1600), label(100000)}
    )
    {
        quaternion q = q0;
        for (label n = 0; n < nSteps; ++n)
        {
            RBR::freeRotation(q, Lin, I, tEnd/nSteps);
        }
        const scalar err = angleBetween(q, qExact);
        const scalar errOmega =
            mag(RBR::omegaBody(q, Lin, I) - omegaExact)/mag(omega0);
        const scalar errEnergy =
            mag
            (
                RBR::kineticEnergy(q, Lin, I)
               /RBR::kineticEnergy(q0, Lin, I) - 1
            );

        std::printf
        (
            "[ measured ] symmetric top, 4 periods in %-5d steps:"
            " orientation error %.3e rad, omega error %.3e, energy %.3e\n",
            int(nSteps), err, errOmega, errEnergy
        );
        EXPECT_LT(err, 1e-10);
        EXPECT_LT(errOmega, 1e-10);

        // Round-off of the energy, growing with the steps (an eps each)
        EXPECT_LT
        (
            errEnergy,
            max(1e-13, nSteps*std::numeric_limits<scalar>::epsilon())
        );
    }
}


TEST(rigidBodyRotation, SphereRotatesExactlyAboutFixedAxis)
{
    const vector abc = 100e-6*vector(1, 1, 1);
    const vector I = RBR::principalMoments(ellipsoidMass(abc), abc);
    const quaternion q0 = RBR::fromEulerAngles(-1.0, 2.0, 0.5);
    const tensor R0 = Rz(-1.0) & Rx(2.0) & Rz(0.5);

    const vector omega(300, -700, 200);   // inertial frame
    const vector Lin = I.x()*omega;
    const scalar dt = 0.3/mag(omega);     // 0.3 rad per step
    const label nSteps = 1000;

    quaternion q = q0;
    for (label n = 0; n < nSteps; ++n)
    {
        RBR::freeRotation(q, Lin, I, dt);
    }

    // Rodrigues rotation by |omega| t about omega/|omega|, then R0
    const tensor Rref =
        rodrigues(omega/mag(omega), mag(omega)*dt*nSteps) & R0;
    const scalar err = maxCmptDiff(q.R(), Rref);
    report("sphere, 1000 steps of 0.3 rad: max component error", err);
    EXPECT_LT(err, 1e-12);

    const scalar E0 = 0.5*I.x()*magSqr(omega);
    EXPECT_NEAR(RBR::kineticEnergy(q, Lin, I)/E0, 1, 1e-14);
}


TEST(rigidBodyRotation, SphereSmallAnglesAgreeWithTheExactRotation)
{
    // Angles per step on both sides of the series' threshold (half angle
    // 1e-3) and far below it, 10^4 steps each: the rotation composed
    // step by step against one Rodrigues rotation by the whole angle, and
    // |q| = 1 kept by the normalisation
    const scalar I = 2.5e-12;
    const quaternion q0 = RBR::fromEulerAngles(0.4, -1.1, 2.3);
    const tensor R0 = Rz(0.4) & Rx(-1.1) & Rz(2.3);
    const vector axis(normalised(vector(0.3, -0.8, 0.5)));
    for (const scalar angle : {1e-7, 1e-4, 1.99e-3, 2.01e-3, 0.05})
    {
        const scalar dt = 1e-5;
        const vector Lin = I*(angle/dt)*axis;
        const label nSteps = 10000;
        quaternion q = q0;
        for (label n = 0; n < nSteps; ++n)
        {
            RBR::sphereRotation(q, Lin, I, dt);
        }
        const tensor Rref = rodrigues(axis, angle*nSteps) & R0;
        const scalar err = maxCmptDiff(q.R(), Rref);
        const scalar normErr = mag(mag(q) - 1);
        std::printf("    sphere, 10^4 steps of %g rad: max component error %.2e, | |q| - 1 | %.1e\n",
            angle, err, normErr);
        EXPECT_LT(err, 2e-12);
        EXPECT_LT(normErr, 1e-14);
    }
}


TEST(rigidBodyRotation, TurnAngleBoundIsFourTanOfAQuarterAngle)
{
    // q1 = (turn by theta about a random axis) q0, and -q1 (the same
    // rotation): the bound is 4 tan(theta/4) >= theta, to round-off of the
    // quaternions' components also for tiny angles
    Random rnd(7);
    scalar worst = 0;
    for (const scalar theta : {1e-13, 1e-9, 1e-6, 1e-3, 0.1, 1.0, 3.0, 3.14})
    {
        for (label i = 0; i < 100; ++i)
        {
            const quaternion q0 = RBR::fromEulerAngles
            (
                6*rnd.sample01<scalar>(), 3*rnd.sample01<scalar>(),
                6*rnd.sample01<scalar>()
            );
            vector axis(Zero);
            while (mag(axis) < 0.1)
            {
                axis = vector(rnd.GaussNormal<vector>());
            }
            const quaternion q1 = quaternion(axis/mag(axis), theta)*q0;
            for (const scalar sign : {1.0, -1.0})
            {
                const scalar b = RBR::turnAngleBound(q0, sign*q1);
                const scalar exact = 4*std::tan(theta/4);
                worst = max(worst, mag(b - exact)/(1e-15 + exact));
                EXPECT_GE(b, theta - 1e-15);
                EXPECT_NEAR(b, exact, 1e-15 + 1e-14*exact);
            }
        }
    }
    report("turnAngleBound: max |bound - 4 tan(theta/4)|/(1e-15 + 4 tan)", worst);
}


TEST(rigidBodyRotation, TimeReversible)
{
    const vector I =
        RBR::principalMoments(ellipsoidMass(triaxialSemiAxes), triaxialSemiAxes);
    const vector abc = 100e-6*vector(1, 1, 1);
    const vector Isphere = RBR::principalMoments(ellipsoidMass(abc), abc);
    const quaternion q0 = RBR::fromEulerAngles(0.4, 1.1, -0.7);

    // Global tolerance: round-off of ~1e-16 per step, amplified by the
    // sensitivity of the motion to its initial orientation: a few hundred
    // over this run for the generic top but ~2000 near the unstable
    // intermediate axis (printed below), hence the larger tolerance there.
    // The step-by-step check is at round-off (a few ulp) for all three.
    struct testCase
    {
        const char* name; vector I; vector omega; scalar tol;
    };
    const testCase cases[] =
    {
        {"asymmetric, generic", I, 1e3*vector(0.6, 0.5, 0.8), 5e-12},
        {"asymmetric, intermediate axis", I, 1e3*vector(1e-3, 1, 1e-3), 1e-9},
        {"sphere", Isphere, 1e3*vector(0.6, 0.5, 0.8), 1e-13}
    };

    for (const testCase& c : cases)
    {
        const vector Lin = q0.R() & vector(cmptMultiply(c.I, c.omega));
        const scalar dt = 2*pi/mag(c.omega)/50;
        const label nSteps = 1013;      // not a whole number of periods

        // Forward, checking that every single step is undone by -dt
        quaternion q = q0;
        scalar stepErr = 0;
        for (label n = 0; n < nSteps; ++n)
        {
            const quaternion qOld = q;
            RBR::freeRotation(q, Lin, c.I, dt);
            quaternion qBack = q;
            RBR::freeRotation(qBack, Lin, c.I, -dt);
            stepErr = max(stepErr, angleBetween(qBack, qOld));
        }
        const scalar away = angleBetween(q, q0);

        // Backward to the start
        for (label n = 0; n < nSteps; ++n)
        {
            RBR::freeRotation(q, Lin, c.I, -dt);
        }
        const scalar err = angleBetween(q, q0);

        // Sensitivity: growth of a 1e-12 rad initial orientation offset
        quaternion qa = q0;
        quaternion qb = quaternion(vector(1, 1, 1), 1e-12)*q0;
        const scalar offset0 = angleBetween(qa, qb);
        for (label n = 0; n < nSteps; ++n)
        {
            RBR::freeRotation(qa, Lin, c.I, dt);
            RBR::freeRotation(qb, Lin, c.I, dt);
        }
        const scalar amplification = angleBetween(qa, qb)/offset0;

        std::printf
        (
            "[ measured ] reversibility, %-30s %d steps +dt, then -dt:"
            " %.3e rad (one step: %.3e rad; amplification %.0f)\n",
            c.name, int(nSteps), err, stepErr, amplification
        );
        EXPECT_GT(away, 0.1) << c.name;     // the run went somewhere
        EXPECT_LT(stepErr, 4e-15) << c.name;
        EXPECT_LT(err, c.tol) << c.name;
    }
}


// * * * * * * * * * * * * * * * * Bad input * * * * * * * * * * * * * * * * //

TEST(rigidBodyRotation, BadInputIsAnError)
{
    FatalError.throwExceptions();

    const scalar nan = std::numeric_limits<scalar>::quiet_NaN();
    const scalar inf = std::numeric_limits<scalar>::infinity();
    const vector I(1, 2, 3);
    const vector L(0.1, 0.2, 0.3);
    const quaternion q = RBR::fromEulerAngles(0.1, 0.2, 0.3);

    // Mass and semi-axes
    EXPECT_THROW(RBR::principalMoments(0, vector(1, 2, 3)), Foam::error);
    EXPECT_THROW(RBR::principalMoments(-1, vector(1, 2, 3)), Foam::error);
    EXPECT_THROW(RBR::principalMoments(nan, vector(1, 2, 3)), Foam::error);
    EXPECT_THROW(RBR::principalMoments(1, vector(1, 0, 3)), Foam::error);
    EXPECT_THROW(RBR::principalMoments(1, vector(1, -2, 3)), Foam::error);
    EXPECT_THROW(RBR::principalMoments(1, vector(inf, 2, 3)), Foam::error);

    // Angles
    EXPECT_THROW(RBR::fromEulerAngles(nan, 0, 0), Foam::error);
    EXPECT_THROW(RBR::fromEulerAngles(0, inf, 0), Foam::error);

    // Moments of inertia
    EXPECT_THROW(RBR::omegaBody(q, L, vector(1, 0, 3)), Foam::error);
    EXPECT_THROW(RBR::omegaBody(q, L, vector(1, -2, 3)), Foam::error);
    EXPECT_THROW(RBR::kineticEnergy(q, L, vector(nan, 2, 3)), Foam::error);
    EXPECT_THROW(RBR::angularMomentum(q, L, vector(1, 2, inf)), Foam::error);

    // Non-finite vectors, non-unit or non-finite quaternions
    EXPECT_THROW(RBR::omegaBody(q, vector(nan, 0, 0), I), Foam::error);
    EXPECT_THROW(RBR::omegaInertial(q, vector(nan, 0, 0), I), Foam::error);
    EXPECT_THROW(RBR::omegaInertial(q, L, vector(1, 0, 3)), Foam::error);
    EXPECT_THROW
    (
        RBR::omegaInertial(quaternion(2, vector::zero), L, I),
        Foam::error
    );
    EXPECT_THROW(RBR::angularMomentum(q, vector(0, inf, 0), I), Foam::error);
    EXPECT_THROW(RBR::omegaBody(quaternion(Zero), L, I), Foam::error);
    EXPECT_THROW(RBR::toBody(quaternion(2, vector::zero), L), Foam::error);
    EXPECT_THROW
    (
        RBR::toInertial(quaternion(nan, vector::zero), L),
        Foam::error
    );

    // freeRotation: nothing is changed when the input is rejected
    const quaternion qBad(1.1, vector::zero);
    const scalar dt = 0.01;
    quaternion q1 = q;
    EXPECT_THROW(RBR::freeRotation(q1, L, I, nan), Foam::error);
    EXPECT_THROW(RBR::freeRotation(q1, L, I, inf), Foam::error);
    EXPECT_THROW(RBR::freeRotation(q1, vector(0, 0, inf), I, dt), Foam::error);
    EXPECT_THROW(RBR::freeRotation(q1, L, vector(1, nan, 3), dt), Foam::error);
    EXPECT_THROW(RBR::freeRotation(q1, L, vector(0, 0, 0), dt), Foam::error);
    EXPECT_TRUE(q1 == q);
    quaternion q2 = qBad;
    EXPECT_THROW(RBR::freeRotation(q2, L, I, dt), Foam::error);

    FatalError.dontThrowExceptions();
}


int main(int argc, char** argv)
{
    ::testing::InitGoogleTest(&argc, argv);
    return RUN_ALL_TESTS();
}


// ************************************************************************* //
