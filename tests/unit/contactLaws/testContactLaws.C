/*---------------------------------------------------------------------------*\
    chargedFoam: unit tests of the contact laws (GoogleTest)

    The laws' parts (normalModel, tangentialModel, rollingModel) checked
    against what defines them, not against their own formulas:
      - hertzDashpot restitutes the e it was calibrated for: a body
        bouncing off a wall, integrated by the leapfrog the clouds use,
        for several masses, radii, moduli and speeds;
      - an elastic frictionless impact conserves energy (the onset
        correction), and the elastic energy in the books is the Hertz
        potential 8/15 E* sqrt(R) delta^5/2;
      - Coulomb friction is mu F_n against the slip; the Mindlin spring
        never exceeds mu F_n and never creates energy (dissipated >= 0 in
        every kick of random sequences);
      - the rolling torque never reverses the relative spin;
      - selection: the dictionary entries pick the parts, a wall law
        takes the pairs' parts unless it names its own, unknown names and
        out-of-range constants are errors;
      - sphereContactBatch, the SIMD lanes of sphere-sphere contacts with
        the default parts, gives the scalar path's results bit for bit
        and leaves the contacts' first and last steps to it;
      - the wall-contact histories of the flat store (wallHistories) are
        those of OpenFOAM's own per-parcel record lists
        (CollisionRecordList: matchWallRecord, update) in random sequences
        of contacts, across rebuilds that reorder, drop and add bodies.

    Measured numbers are printed as "[ measured ] ..." lines.
\*---------------------------------------------------------------------------*/

#include "contactLaw.H"
#include "sphereContactBatch.H"
#include "ellipsoidContactBatch.H"
#include "rigidBodyRotation.H"
#include "wallHistories.H"
#include "labelField.H"
#include "vectorField.H"
#include "CollisionRecordList.H"
#include "Random.H"
#include "error.H"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

using namespace Foam;

namespace
{

void report(const char* what, const double value)
{
    std::printf("[ measured ] %-58s %.3e\n", what, value);
}


dictionary lawDict
(
    const word& tangential = "mindlin",
    const scalar e = 0.5,
    const scalar mu = 0.3
)
{
    dictionary d;
    d.add("tangentialModel", tangential);
    d.add("e", e);
    d.add("mu", mu);
    return d;
}


// The first step of a contact, or the last (the next drift ends without
// overlap at the speed the uncorrected kick leaves): hertzDashpot's onset
// correction applies, and the batches of contacts leave the kick to the
// scalar path
bool onsetCorrected
(
    const contactProperties& p,
    const ellipsoidContact::result& c,
    const vector& vRel,
    const scalar mStar,
    const scalar invMassNormal,
    const scalar dt
)
{
    const scalar vn = vRel & c.n;
    const scalar sqrtR = Foam::sqrt(c.reducedRadius);
    const scalar sqrtRdelta = sqrtR*Foam::sqrt(c.overlap);
    const scalar etaN =
        2*Foam::sqrt(5.0/6.0)*mag(p.beta)
       *Foam::sqrt(2*p.Estar*sqrtRdelta*mStar);
    const scalar kHertz = (4.0/3.0)*p.Estar*sqrtR;
    const scalar Fe = kHertz*(c.overlap*Foam::sqrt(c.overlap));
    const scalar vnNext =
        vn - dt*max(Fe + etaN*vn, scalar(0))*invMassNormal;
    return c.overlap <= vn*dt || c.overlap + vnNext*dt <= 0;
}


// EllipsoidCollision::pairForce of two real bodies A and B in contact c,
// the batches' reference: the law's kick with the normal mobilities
// 1/m + (r x n).I^-1 (r x n) (invI zero for a sphere), the torques on A and
// (minus) on B about their centres with the forces and torques of
// -dU/dR gradR, whether the onset correction applies (the batches leave
// that kick to the scalar path) and whether the contact slips
struct pairKick
{
    bool corrected;
    bool slipping;
    vector F, torqueA, minusTorqueB, xi;
    contactWork work;
};

pairKick pairForceReference
(
    const contactLaw& law,
    const contactProperties& p,
    const ellipsoidContact::result& c,
    const point& xA, const vector& UA, const vector& omegaA,
    const scalar mA, const symmTensor& invIA,
    const point& xB, const vector& UB, const vector& omegaB,
    const scalar mB, const symmTensor& invIB,
    const vector& xi,
    const scalar dt
)
{
    const point xc = 0.5*(c.x1 + c.x2);
    const vector vRel =
        (UA + (omegaA ^ (xc - xA))) - (UB + (omegaB ^ (xc - xB)));
    const scalar mStar = mA*mB/(mA + mB);
    const vector rnA = (xc - xA) ^ c.n;
    const vector rnB = (xc - xB) ^ c.n;
    const scalar invMassNormal =
        (1/mA + (rnA & (invIA & rnA))) + (1/mB + (rnB & (invIB & rnB)));

    pairKick k;
    k.corrected = onsetCorrected(p, c, vRel, mStar, invMassNormal, dt);
    k.xi = xi;
    k.work = {0, 0};
    scalar dUdR;
    const vector F = law.force
    (
        p, c, vRel, mStar, invMassNormal, dt, k.xi, dUdR, k.work
    );
    const scalar Fn = -(F & c.n);
    k.slipping = mag(F + Fn*c.n) >= (1 - 1e-9)*p.mu*Fn;
    k.F = F - dUdR*c.gradR.centre1;
    k.torqueA = (((xc - xA) ^ F) + vector(Zero)) - dUdR*c.gradR.rotation1;
    k.minusTorqueB =
        (((xc - xB) ^ F) + vector(Zero)) + dUdR*c.gradR.rotation2;
    return k;
}


// Does lane l's kick differ from the reference k?
bool kickDiffers
(
    const contactBatchKicks& batch,
    const label l,
    const pairKick& k
)
{
    return
        batch.F(l) != k.F || batch.torqueA(l) != k.torqueA
     || batch.minusTorqueB(l) != k.minusTorqueB || batch.xi(l) != k.xi
     || batch.dissipated(l) != k.work.dissipated
     || batch.elastic(l) != k.work.elastic;
}


// A normal contact of overlap delta against a wall along +x
ellipsoidContact::result normalContact(const scalar delta, const scalar R)
{
    ellipsoidContact::result c;
    c.contact = delta > 0;
    c.n = vector(1, 0, 0);
    c.overlap = delta;
    c.reducedRadius = R;
    return c;
}


// A body of mass m approaching a wall at v0 along +x, integrated by the
// kick-drift-kick leapfrog with nSteps steps per Hertz collision time;
// returns the rebound speed over v0 and the elastic energy of the books at
// the deepest overlap against the Hertz potential there
scalar bounce
(
    const contactLaw& law,
    const contactProperties& p,
    const scalar m,
    const scalar R,
    const scalar v0,
    const scalar nSteps,
    scalar* potentialError = nullptr
)
{
    // Hertz collision time (Johnson 1985)
    const scalar tc =
        2.87*std::pow(sqr(m)/(R*sqr(p.Estar)*v0), 0.2);
    const scalar dt = tc/nSteps;

    // Start half a step's drift from the wall, so that the contact begins
    // within a step
    scalar x = -0.37*v0*dt, v = v0, a = 0;
    scalar worst = 0;
    vector xi(Zero);
    for (label step = 0; step < 100*nSteps; ++step)
    {
        v += 0.5*dt*a;
        x += v*dt;
        a = 0;
        if (x > 0)
        {
            scalar dUdR;
            contactWork work{0, 0};
            const vector F =
                law.force
                (
                    p, normalContact(x, R), vector(v, 0, 0), m, 1/m, dt, xi,
                    dUdR, work
                );
            a = F.x()/m;
            const scalar U = 8.0/15.0*p.Estar*std::sqrt(R)*std::pow(x, 2.5);
            worst = max(worst, mag(work.elastic - U)/U);
        }
        v += 0.5*dt*a;
        if (x < 0 && v < 0)
        {
            break;
        }
    }
    if (potentialError)
    {
        *potentialError = worst;
    }
    return -v/v0;
}

} // End anonymous namespace


TEST(hertzDashpot, restitutesTheCalibratedCoefficient)
{
    Random rnd(7);
    scalar worst = 0;
    for (const scalar e : {0.1, 0.3, 0.5, 0.7, 0.9, 0.99})
    {
        const contactLaw law(lawDict("mindlin", e, 0));
        for (label k = 0; k < 4; ++k)
        {
            // masses of 1e-9 to 1e-3 kg, radii of 1e-5 to 1e-2 m, moduli
            // of 1e6 to 1e11 Pa, speeds of 1e-3 to 10 m/s
            const scalar m = std::pow(10.0, -9 + 6*rnd.sample01<scalar>());
            const scalar R = std::pow(10.0, -5 + 3*rnd.sample01<scalar>());
            const scalar E = std::pow(10.0, 6 + 5*rnd.sample01<scalar>());
            const scalar v0 = std::pow(10.0, -3 + 4*rnd.sample01<scalar>());
            const contactProperties p =
                law.properties(E, 0.3, E, 0.3, dictionary(), e, 0, 0);
            const scalar eMeasured = bounce(law, p, m, R, v0, 400);
            worst = max(worst, mag(eMeasured - e));
            EXPECT_NEAR(eMeasured, e, 2e-3) << "e " << e << ", m " << m;
        }
    }
    report("hertzDashpot: largest |e - e_given| at 400 steps", worst);
}


TEST(hertzDashpot, elasticImpactConservesEnergy)
{
    const contactLaw law(lawDict("mindlin", 1, 0));
    const contactProperties p =
        law.properties(1e8, 0.3, 2e11, 0.3, dictionary(), 1, 0, 0);
    scalar potentialError = 0;
    const scalar e = bounce(law, p, 1e-6, 1e-3, 0.5, 50, &potentialError);
    report("elastic impact at 50 steps: |1 - e^2| (energy)", mag(1 - sqr(e)));
    report("books' elastic energy against the Hertz potential", potentialError);
    EXPECT_LT(mag(1 - sqr(e)), 1e-6);
    EXPECT_LT(potentialError, 1e-12);
}


TEST(coulombFriction, isMuFnAgainstTheSlip)
{
    const contactLaw law(lawDict("coulomb", 0.5, 0.4));
    const contactProperties p =
        law.properties(1e8, 0.3, 1e8, 0.3, dictionary(), 0.5, 0.4, 0);
    const vector vRel(-0.01, 0.3, -0.4);       // approaching, slipping
    vector xi(Zero);
    scalar dUdR;
    contactWork work{0, 0};
    const scalar dt = 1e-6;
    const vector F =
        law.force
        (
            p, normalContact(1e-6, 1e-3), vRel, 1e-6, 2e6, dt, xi, dUdR,
            work
        );
    const scalar Fn = -F.x();
    const vector Ft(0, F.y(), F.z());
    const vector vt(0, vRel.y(), vRel.z());
    EXPECT_GT(Fn, 0);
    EXPECT_NEAR(mag(Ft), 0.4*Fn, 1e-12*Fn);
    EXPECT_NEAR((Ft & vt)/(mag(Ft)*mag(vt)), -1, 1e-14);
    EXPECT_GE(work.dissipated, 0.4*Fn*mag(vt)*dt*(1 - 1e-12));
}


TEST(mindlinSpring, boundedByFrictionAndNeverCreatesEnergy)
{
    const contactLaw law(lawDict("mindlin", 0.5, 0.3));
    const contactProperties p =
        law.properties(5e6, 0.3, 5e6, 0.3, dictionary(), 0.5, 0.3, 0);
    Random rnd(11);
    label nSlip = 0, nKicks = 0;
    scalar worstExcess = 0;
    for (label seq = 0; seq < 200; ++seq)
    {
        vector xi(Zero);
        scalar delta = 1e-7*(1 + rnd.sample01<scalar>());
        for (label k = 0; k < 50; ++k)
        {
            // random normals near x, overlaps and relative velocities
            ellipsoidContact::result c = normalContact(delta, 5e-4);
            c.n = vector
            (
                1, 0.1*rnd.GaussNormal<scalar>(), 0.1*rnd.GaussNormal<scalar>()
            );
            c.n /= mag(c.n);
            const vector vRel = 1e-3*rnd.GaussNormal<vector>();
            scalar dUdR;
            contactWork work{0, 0};
            const vector F =
                law.force(p, c, vRel, 1e-6, 2e6, 1e-6, xi, dUdR, work);
            const scalar Fn = -(F & c.n);
            const vector Ft = F + Fn*c.n;
            ++nKicks;
            if (mag(Ft) >= (1 - 1e-12)*0.3*Fn)
            {
                ++nSlip;
            }
            if (Fn > 0)
            {
                worstExcess = max(worstExcess, (mag(Ft) - 0.3*Fn)/Fn);
            }
            // what the contact takes from the motion is stored (elastic)
            // or dissipated: never created (to round-off of the terms)
            EXPECT_GE
            (
                work.dissipated,
                -1e-12*(mag(F)*mag(vRel)*1e-6 + work.elastic)
            );
            delta = max(1e-9, delta*(1 + 0.2*rnd.GaussNormal<scalar>()));
        }
    }
    report("Mindlin: kicks at the friction limit (of 10000)", nSlip);
    report("Mindlin: largest (|F_t| - mu F_n)/F_n", worstExcess);
    EXPECT_GT(nSlip, 100);           // both regimes are exercised
    EXPECT_LT(nSlip, nKicks - 100);
    EXPECT_LE(worstExcess, 1e-12);
}


TEST(constantTorque, neverReversesTheSpin)
{
    const contactLaw law(lawDict());
    const contactProperties p =
        law.properties(1e8, 0.3, 1e8, 0.3, dictionary(), 0.5, 0.3, 0.05);
    const scalar dt = 1e-5, I = 1e-12;
    for (const scalar w : {1e-6, 1e-2, 1.0, 100.0})
    {
        const vector omega(0, 0, w);
        scalar dissipated = 0;
        const vector M =
            law.rollingTorque
            (
                p, normalContact(1e-6, 1e-3), vector(-1e-3, 0, 0), omega, I,
                dt, dissipated
            );
        EXPECT_LE(M.z(), 0);
        EXPECT_NEAR(M.x(), 0, 1e-300);
        // both half kicks of a step leave the spin's sign
        EXPECT_GE(w + dt*M.z()/I, -1e-12*w);
        EXPECT_NEAR(M.z(), -min(0.05*1e-3*1e-3, I*w/dt), 1e-12*mag(M.z()));
        EXPECT_GE(dissipated, 0);
    }
}


TEST(contactLaw, selectionAndErrors)
{
    dictionary pair(lawDict("mindlin"));
    const contactLaw pairLaw(pair);
    EXPECT_EQ(pairLaw.normal().type(), "hertzDashpot");
    EXPECT_EQ(pairLaw.tangential().type(), "mindlin");
    EXPECT_EQ(pairLaw.rolling().type(), "constantTorque");

    // A wall law takes the pairs' parts unless it names its own
    const contactLaw sameWalls(dictionary(), &pairLaw);
    EXPECT_EQ(sameWalls.tangential().type(), "mindlin");
    dictionary walls;
    walls.add("tangentialModel", word("coulomb"));
    const contactLaw ownWalls(walls, &pairLaw);
    EXPECT_EQ(ownWalls.tangential().type(), "coulomb");

    FatalIOError.throwExceptions();
    dictionary bad;
    bad.add("tangentialModel", word("bogus"));
    EXPECT_THROW(contactLaw law(bad), Foam::IOerror);
    EXPECT_THROW
    (
        pairLaw.properties(1e8, 0.3, 1e8, 0.3, dictionary(), 1.5, 0.3, 0),
        Foam::IOerror
    );
    EXPECT_THROW
    (
        pairLaw.properties(1e8, 0.3, 1e8, 0.3, dictionary(), 0.5, -1, 0),
        Foam::IOerror
    );
    dictionary badRolling;
    badRolling.add("rollingFriction", -0.1);
    EXPECT_THROW
    (
        pairLaw.properties(1e8, 0.3, 1e8, 0.3, badRolling, 0.5, 0.3, 0),
        Foam::IOerror
    );
}

// sphereContactBatch against the scalar path it stands for: the sphere
// contact (ellipsoidContact::sphereSphere), then what the collision
// model's pairForce does for two spheres with the law's parts through
// contactLaw::force (the point velocities at the midpoint of the contact
// points, the reduced mass, the normal mobility 1/mA + 1/mB, the torques
// about the centres). Random lanes of two materials, in full and partial
// batches: spheres apart and in contact, new contacts and lasting ones
// (histories with a normal part to project away), sticking and slipping,
// first and last steps. Every lane in contact that the batch does not
// leave to the scalar path gives the scalar results bit for bit; the lanes
// it leaves are those whose Hertz kick takes the onset correction
TEST(sphereContactBatch, isTheScalarPathBitForBit)
{
    const contactLaw law(lawDict("mindlin", 0.5, 0.3));
    ASSERT_TRUE(law.defaultParts());
    EXPECT_FALSE(contactLaw(lawDict("coulomb")).defaultParts());
    const contactProperties props[2] =
    {
        law.properties(5e6, 0.3, 5e6, 0.3, dictionary(), 0.5, 0.3, 0),
        law.properties(7e7, 0.25, 5e6, 0.3, dictionary(), 0.8, 0.1, 0)
    };
    const defaultLawConstants constants[2] =
    {
        defaultLawConstants::of(props[0]),
        defaultLawConstants::of(props[1])
    };
    const scalar dt = 5e-6;
    Random rnd(17);
    sphereContactBatch batch;
    label nContact = 0, nApart = 0, nScalar = 0, nSlip = 0, nDiffer = 0;
    label nWrongScalar = 0;

    struct laneInput
    {
        point xA, xB;
        scalar rA, rB, mA, mB;
        vector UA, UB, omegaA, omegaB, xi;
        label material;
    };

    for (label b = 0; b < 20000; ++b)
    {
        const label nLanes = 1 + (b % sphereContactBatch::width);
        laneInput in[sphereContactBatch::width];
        for (label l = 0; l < nLanes; ++l)
        {
            laneInput& x = in[l];
            x.rA = 5e-4*(1 + rnd.sample01<scalar>());
            x.rB = 5e-4*(1 + rnd.sample01<scalar>());
            x.mA = 2500*4.19*pow3(x.rA);
            x.mB = 2500*4.19*pow3(x.rB);
            const vector dir = rnd.GaussNormal<vector>();
            // overlaps from -2e-4 (apart) to 8e-4 of the radii' sum
            const scalar gap =
                (x.rA + x.rB)*(1 - 1e-3*rnd.sample01<scalar>() + 2e-4);
            x.xA = vector(0.01, -0.02, 0.03) + 1e-3*rnd.GaussNormal<vector>();
            x.xB = x.xA + gap*dir/mag(dir);
            x.UA = 0.005*rnd.GaussNormal<vector>();
            x.UB = 0.005*rnd.GaussNormal<vector>();
            x.omegaA = 5*rnd.GaussNormal<vector>();
            x.omegaB = 5*rnd.GaussNormal<vector>();
            // histories from 1e-10 to 1e-7 m: sticking and slipping
            const scalar kind = rnd.sample01<scalar>();
            const scalar xiScale = 1e-7*std::pow(1e-3, rnd.sample01<scalar>());
            x.xi =
                kind < 0.2 ? vector(Zero)
              : kind < 0.3 ? xiScale*dir
              : xiScale*rnd.GaussNormal<vector>();
            x.material = rnd.sample01<scalar>() < 0.5 ? 0 : 1;
            batch.setLane
            (
                l,
                x.xA, x.rA, x.UA, x.omegaA, x.mA,
                x.xB, x.rB, x.UB, x.omegaB, x.mB,
                constants[x.material], x.xi
            );
        }
        batch.evaluate(nLanes, dt);

        for (label l = 0; l < nLanes; ++l)
        {
            const laneInput& x = in[l];
            const ellipsoidContact::result c =
                ellipsoidContact::sphereSphere(x.xA, x.rA, x.xB, x.rB);
            if (!c.contact || c.overlap <= 0)
            {
                ++nApart;
                nDiffer += batch.contact(l);
                continue;
            }
            ++nContact;
            nDiffer += !batch.contact(l);
            nDiffer += batch.overlap(l) != c.overlap;

            const pairKick k = pairForceReference
            (
                law, props[x.material], c,
                x.xA, x.UA, x.omegaA, x.mA, symmTensor::zero,
                x.xB, x.UB, x.omegaB, x.mB, symmTensor::zero,
                x.xi, dt
            );
            if (batch.needsScalar(l))
            {
                ++nScalar;
                nWrongScalar += !k.corrected;
                continue;
            }
            nWrongScalar += k.corrected;
            nSlip += k.slipping;
            nDiffer += kickDiffers(batch, l, k);
        }
    }
    report("sphere batch: lanes in contact", nContact);
    report("sphere batch: lanes apart", nApart);
    report("sphere batch: lanes left to the scalar path", nScalar);
    report("sphere batch: slipping lanes", nSlip);
    EXPECT_GT(nApart, 1000);
    EXPECT_GT(nScalar, 100);
    EXPECT_GT(nSlip, 1000);
    EXPECT_GT(nContact - nScalar - nSlip, 1000);
    EXPECT_EQ(nWrongScalar, 0);
    EXPECT_EQ(nDiffer, 0);
}


// Lasting contacts of random ellipsoids (aspect ratios 1 to 3, two
// materials) started near their normal, four at a time: each decided
// lane's narrow phase is ellipsoidContact::contact's from the same start,
// and its kick what EllipsoidCollision::pairForce forms from that contact
// (contact point, relative velocity, the normal mobilities of the inverse
// inertia tensors, the law, the torques and -dU/dR gradR) bit for bit
TEST(ellipsoidContactBatch, kickIsTheScalarPathBitForBit)
{
    const contactLaw law(lawDict("mindlin", 0.5, 0.3));
    const contactProperties props[2] =
    {
        law.properties(5e6, 0.3, 5e6, 0.3, dictionary(), 0.5, 0.3, 0),
        law.properties(7e7, 0.25, 5e6, 0.3, dictionary(), 0.8, 0.1, 0)
    };
    const defaultLawConstants constants[2] =
    {
        defaultLawConstants::of(props[0]),
        defaultLawConstants::of(props[1])
    };
    const scalar dt = 5e-6;
    const scalar rho = 2500;
    Random rnd(29);
    ellipsoidContactBatch batch;
    label nLanes = 0, nDecided = 0, nScalar = 0, nSlip = 0;
    label nWrongScalar = 0, nDiffer = 0, nNonZeroGradR = 0;

    struct laneInput
    {
        ellipsoid e1, e2;
        vector start, UA, UB, omegaA, omegaB, xi;
        scalar mA, mB;
        symmTensor invIA, invIB;
        label material;
    };

    auto randomBody = [&](const point& centre, scalar& m, symmTensor& invI)
    {
        const vector axes
        (
            5e-4*(1 + 2*rnd.sample01<scalar>()),
            5e-4*(1 + 0.5*rnd.sample01<scalar>()),
            5e-4
        );
        const quaternion q
        (
            rnd.GaussNormal<scalar>(), rnd.GaussNormal<vector>()
        );
        const ellipsoid e(axes, centre, q);
        m = rho*4.19*axes.x()*axes.y()*axes.z();
        const vector I = rigidBodyRotation::principalMoments(m, axes);
        const tensor& R = e.R();
        const tensor Iinv(1/I.x(), 0, 0, 0, 1/I.y(), 0, 0, 0, 1/I.z());
        invI = symm(R & Iinv & R.T());
        return e;
    };

    for (label b = 0; b < 5000; ++b)
    {
        const label n = 1 + (b % ellipsoidContactBatch::width);
        std::vector<laneInput> in;
        for (label l = 0; l < n; ++l)
        {
            scalar mA, mB;
            symmTensor invIA, invIB;
            const ellipsoid e1 =
                randomBody(vector(0.01, -0.02, 0.03), mA, invIA);
            const vector u = rnd.GaussNormal<vector>();
            const vector du = u/mag(u);
            // Touching at the centre distance sOut along u (bisection),
            // then pushed in by 1e-9 to 1e-5 m (a tenth apart by 1e-6 m)
            const ellipsoid probe = randomBody(point::zero, mB, invIB);
            scalar sIn = 0;
            scalar sOut =
                e1.boundingRadius() + probe.boundingRadius() + 1e-6;
            for (label it = 0; it < 60; ++it)
            {
                const scalar sMid = 0.5*(sIn + sOut);
                const ellipsoid e2 =
                    probe.moved(e1.centre() + sMid*du, probe.R());
                (ellipsoidContact::contact(e1, e2).contact ? sIn : sOut) = sMid;
            }
            const scalar depth =
                rnd.sample01<scalar>() < 0.1
              ? -1e-6
              : 1e-9*std::pow(1e4, rnd.sample01<scalar>());
            const ellipsoid e2 =
                probe.moved(e1.centre() + (sOut - depth)*du, probe.R());

            // The start: the contact's normal turned by 1e-8 to 1e-5 rad
            vector nTrack(Zero);
            const ellipsoidContact::result c0 =
                ellipsoidContact::contact(e1, e2, nTrack);
            const vector n0 = c0.contact ? c0.n : du;
            const vector start =
                n0 + 1e-8*std::pow(1e3, rnd.sample01<scalar>())
                   *rnd.GaussNormal<vector>();

            laneInput x
            {
                e1, e2, start,
                0.005*rnd.GaussNormal<vector>(),
                0.005*rnd.GaussNormal<vector>(),
                5*rnd.GaussNormal<vector>(), 5*rnd.GaussNormal<vector>(),
                vector(Zero), mA, mB, invIA, invIB,
                rnd.sample01<scalar>() < 0.5 ? 0 : 1
            };
            const scalar kind = rnd.sample01<scalar>();
            const scalar xiScale = 1e-7*std::pow(1e-3, rnd.sample01<scalar>());
            x.xi =
                kind < 0.2 ? vector(Zero)
              : kind < 0.3 ? xiScale*du
              : xiScale*rnd.GaussNormal<vector>();
            in.push_back(x);
            batch.setLane(l, x.e1, x.e2, x.start);
            batch.setBodies
            (
                l,
                x.e1.centre(), x.UA, x.omegaA, x.mA, x.invIA,
                x.e2.centre(), x.UB, x.omegaB, x.mB, x.invIB,
                constants[x.material], x.xi
            );
        }
        batch.evaluate(n);
        batch.kick(n, dt);

        for (label l = 0; l < n; ++l)
        {
            const laneInput& x = in[l];
            ++nLanes;
            vector nTrack = x.start;
            const ellipsoidContact::result c =
                ellipsoidContact::contact(x.e1, x.e2, nTrack);
            if (!batch.decided(l))
            {
                continue;
            }
            ++nDecided;
            const ellipsoidContact::result g = batch.contact(l);
            nDiffer +=
                g.n != c.n || g.x1 != c.x1 || g.x2 != c.x2
             || g.overlap != c.overlap || g.reducedRadius != c.reducedRadius
             || g.gradR.rotation1 != c.gradR.rotation1
             || g.gradR.centre1 != c.gradR.centre1 || nTrack != c.n
             || batch.normal(l) != c.n || batch.overlap(l) != c.overlap;
            nNonZeroGradR += mag(c.gradR.rotation1) > 0;

            const pairKick k = pairForceReference
            (
                law, props[x.material], c,
                x.e1.centre(), x.UA, x.omegaA, x.mA, x.invIA,
                x.e2.centre(), x.UB, x.omegaB, x.mB, x.invIB,
                x.xi, dt
            );
            if (batch.needsScalar(l))
            {
                ++nScalar;
                nWrongScalar += !k.corrected;
                continue;
            }
            nWrongScalar += k.corrected;
            nSlip += k.slipping;
            nDiffer += kickDiffers(batch, l, k);
        }
    }
    report("ellipsoid batch: lanes", nLanes);
    report("ellipsoid batch: decided lanes", nDecided);
    report("ellipsoid batch: kicks left to the scalar path", nScalar);
    report("ellipsoid batch: slipping lanes", nSlip);
    EXPECT_GT(nDecided, nLanes/2);
    EXPECT_GT(nLanes - nDecided, 1000);
    EXPECT_GT(nScalar, 100);
    EXPECT_GT(nSlip, 1000);
    EXPECT_GT(nDecided - nScalar - nSlip, 1000);
    EXPECT_GT(nNonZeroGradR, nDecided/2);
    EXPECT_EQ(nWrongScalar, 0);
    EXPECT_EQ(nDiffer, 0);
}


// The flat store against OpenFOAM's per-parcel record lists: each body
// touches walls along a random subset of six directions (jittered, so
// that a contact matches its record of the step before), its tangential
// history accumulated in the record; every 7 steps the bodies near walls
// are rebuilt (reordered, some dropped, some new with records of their
// own, as read on a restart)
TEST(wallHistories, matchOpenFOAMsRecordLists)
{
    typedef CollisionRecordList<vector, vector> recordList;
    typedef WallCollisionRecord<vector> record;
    Random rnd(1234);
    const label nBodies = 40;
    const scalar r = 1e-3;
    const vector axes[6] =
    {
        vector(1, 0, 0), vector(-1, 0, 0), vector(0, 1, 0),
        vector(0, -1, 0), vector(0, 0, 1), vector(0, 0, -1)
    };

    List<recordList> lists(nBodies);
    wallHistories<record> store;
    labelList near;             // bodies in the store's runs, in run order
    label nMatched = 0, nCompared = 0;
    for (label step = 0; step < 200; ++step)
    {
        if (step % 7 == 0)
        {
            // Rebuild: a random order of a random subset; bodies not in the
            // store before bring their own records (none for most)
            labelList runOf(nBodies, -1);
            forAll(near, m)
            {
                runOf[near[m]] = m;
            }
            DynamicList<label> next;
            for (label b = 0; b < nBodies; ++b)
            {
                if (rnd.sample01<scalar>() < 0.7)
                {
                    next.append(b);
                }
            }
            for (label k = next.size() - 1; k > 0; --k)
            {
                std::swap(next[k], next[rnd.position<label>(0, k)]);
            }
            for (const label b : next)
            {
                if (runOf[b] >= 0)
                {
                    store.append(runOf[b]);
                    continue;
                }
                if (rnd.sample01<scalar>() < 0.3)
                {
                    // Records of its own (unaccessed, as read)
                    const vector& axis = axes[rnd.position<label>(0, 5)];
                    lists[b].matchWallRecord(0.9*r*axis, r).collisionData() =
                        rnd.sample01<vector>();
                    lists[b].update();
                }
                store.append(lists[b].wallRecords());
            }
            store.endStep();
            near = next;
        }

        forAll(near, m)
        {
            const label b = near[m];
            store.open(m);
            for (const vector& axis : axes)
            {
                if (rnd.sample01<scalar>() < 0.5)
                {
                    continue;
                }
                const vector jitter =
                    0.05*(rnd.sample01<vector>() - 0.5*vector::one);
                const vector pRel = 0.9*r*(axis + jitter)/mag(axis + jitter);
                const vector dXi = rnd.sample01<vector>();
                record& a = store.match(pRel, r);
                record& o = lists[b].matchWallRecord(pRel, r);
                nMatched += mag(o.collisionData()) > 0;
                a.collisionData() += dXi;
                o.collisionData() += dXi;
            }
            store.close();
            lists[b].update();
        }
        store.endStep();

        forAll(near, m)
        {
            const UList<record>& ours = store.run(m);
            const auto& theirs = lists[near[m]].wallRecords();
            ASSERT_EQ(ours.size(), theirs.size()) << "step " << step;
            forAll(ours, k)
            {
                EXPECT_EQ(ours[k].pRel(), theirs[k].pRel());
                EXPECT_EQ(ours[k].collisionData(), theirs[k].collisionData());
                EXPECT_FALSE(ours[k].accessed());
                ++nCompared;
            }
        }

        // Bodies without walls in reach: their contacts ended (their
        // records cleared, as findWallFaces does)
        for (label b = 0; b < nBodies; ++b)
        {
            if (!near.found(b))
            {
                lists[b] = recordList();
            }
        }
    }
    report("wallHistories: records compared with OpenFOAM's", nCompared);
    report("wallHistories: contacts that continued a history", nMatched);
    EXPECT_GT(nMatched, 1000);
}


int main(int argc, char** argv)
{
    ::testing::InitGoogleTest(&argc, argv);
    return RUN_ALL_TESTS();
}


// ************************************************************************* //
