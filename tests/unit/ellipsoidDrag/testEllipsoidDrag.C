/*---------------------------------------------------------------------------*\
    chargedFoam: unit tests of the ellipsoid drag kernel (GoogleTest)

    References independent of the kernel: the projected area by counting
    the lines along u that hit the ellipsoid on a fine grid of the plane
    normal to u (quadratic discriminant), the closed-form surface area of
    a prolate spheroid, Hölzer & Sommerfeld 2008 Eq. (9) at Phi = Phi_perp
    = 1 (24 + 3 sqrt(Re) + 0.42 Re, transcribed here), and OpenFOAM's
    SphereDragForce::CdRe (v1912, transcribed here).

    Measured numbers are printed as "[ measured ] ..." lines.
\*---------------------------------------------------------------------------*/

#include "ellipsoidDrag.H"
#include "mathematicalConstants.H"
#include "tensor.H"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

using namespace Foam;

namespace
{

const scalar pi = constant::mathematical::pi;

void report(const char* what, const double value)
{
    std::printf("[ measured ] %-58s %.3e\n", what, value);
}

// Area of the shadow of x^T diag(1/a^2, 1/b^2, 1/c^2) x <= 1 along the unit
// u: count the points p of a grid on the plane normal to u whose line
// p + s u meets the ellipsoid (discriminant of the quadratic in s >= 0)
scalar shadowArea(const vector& abc, const vector& u, const label n)
{
    vector e1 = (mag(u.x()) < 0.9 ? vector(1, 0, 0) : vector(0, 1, 0));
    e1 -= (e1 & u)*u;
    e1 /= mag(e1);
    const vector e2 = u ^ e1;
    const scalar L = cmptMax(abc);
    const scalar h = 2*L/n;
    const vector w(1/sqr(abc.x()), 1/sqr(abc.y()), 1/sqr(abc.z()));
    auto q = [&](const vector& x, const vector& y)
    {
        return w.x()*x.x()*y.x() + w.y()*x.y()*y.y() + w.z()*x.z()*y.z();
    };
    label hits = 0;
    for (label i = 0; i < n; ++i)
    {
        for (label j = 0; j < n; ++j)
        {
            const vector p = (-L + (i + 0.5)*h)*e1 + (-L + (j + 0.5)*h)*e2;
            // (p + s u)^T W (p + s u) = 1
            const scalar A = q(u, u), B = 2*q(p, u), C = q(p, p) - 1;
            if (B*B - 4*A*C >= 0) ++hits;
        }
    }
    return hits*h*h;
}

} // End anonymous namespace


TEST(ellipsoidDrag, sphereLimits)
{
    const vector r(2e-4, 2e-4, 2e-4);
    EXPECT_NEAR(ellipsoidDrag::volumeEquivalentDiameter(r), 4e-4, 1e-18);
    EXPECT_DOUBLE_EQ(ellipsoidDrag::sphericity(r), 1);
    for (const vector& u : {vector(1, 0, 0), vector(0, 0.6, 0.8)})
    {
        EXPECT_NEAR(ellipsoidDrag::projectedArea(r, u), pi*4e-8, 1e-20);
        EXPECT_NEAR(ellipsoidDrag::crosswiseSphericity(r, u), 1, 1e-14);
    }
    // H-S Eq. (9) at Phi = Phi_perp = 1, and sphereDrag's Schiller-Naumann
    for (const scalar Re : {0.0, 0.01, 1.0, 50.0, 999.0, 2000.0})
    {
        EXPECT_NEAR
        (
            ellipsoidDrag::CdReHolzerSommerfeld(Re, 1, 1),
            24 + 3*std::sqrt(Re) + 0.42*Re, 1e-12*(24 + Re)
        );
        const scalar sn =
            Re > 1000 ? 0.424*Re : 24*(1 + std::pow(Re, 2.0/3.0)/6);
        EXPECT_EQ(ellipsoidDrag::CdReSphere(Re), sn);
    }
}


TEST(ellipsoidDrag, projectedAreaAgainstShadowCount)
{
    const vector abc(3e-4, 2e-4, 1e-4);
    scalar worst = 0;
    for (const vector& v :
        {vector(1, 0, 0), vector(0, 1, 0), vector(0, 0, 1),
         vector(1, 1, 0), vector(1, -2, 3), vector(0.3, 0.1, -0.9)})
    {
        const vector u = v/mag(v);
        const scalar A = ellipsoidDrag::projectedArea(abc, u);
        const scalar ref = shadowArea(abc, u, 2000);
        worst = max(worst, mag(A - ref)/ref);
        EXPECT_NEAR(A, ref, 2e-3*ref) << "u = " << u.x() << " " << u.y()
            << " " << u.z();
    }
    report("projected area vs shadow count (2000^2 grid), max rel.", worst);
}


TEST(ellipsoidDrag, sphericities)
{
    // Prolate spheroid a > b = c: S = 2 pi b^2 (1 + a/(b e) asin e)
    const scalar a = 2, b = 1;
    const scalar e = std::sqrt(1 - sqr(b/a));
    const scalar S = 2*pi*b*b*(1 + a/(b*e)*std::asin(e));
    const scalar dv = 2*std::cbrt(a*b*b);
    const vector abc(a, b, b);
    EXPECT_NEAR(ellipsoidDrag::sphericity(abc), pi*dv*dv/S, 1e-12);
    report("sphericity of a 2:1:1 spheroid", ellipsoidDrag::sphericity(abc));

    // Crosswise sphericity: end-on (flow along the long axis) > 1 >
    // broadside; both from the cross-sections pi b^2 and pi a b
    EXPECT_NEAR
    (
        ellipsoidDrag::crosswiseSphericity(abc, vector(1, 0, 0)),
        dv*dv/4/(b*b), 1e-12
    );
    EXPECT_NEAR
    (
        ellipsoidDrag::crosswiseSphericity(abc, vector(0, 0, 1)),
        dv*dv/4/(a*b), 1e-12
    );

    // Orientation matters: more drag broadside than end-on, at any Re
    const scalar Phi = ellipsoidDrag::sphericity(abc);
    for (const scalar Re : {0.1, 10.0, 1000.0})
    {
        EXPECT_GT
        (
            ellipsoidDrag::CdReHolzerSommerfeld
            (
                Re, Phi, ellipsoidDrag::crosswiseSphericity(abc, vector(0, 1, 0))
            ),
            ellipsoidDrag::CdReHolzerSommerfeld
            (
                Re, Phi, ellipsoidDrag::crosswiseSphericity(abc, vector(1, 0, 0))
            )
        );
    }
}


int main(int argc, char** argv)
{
    ::testing::InitGoogleTest(&argc, argv);
    return RUN_ALL_TESTS();
}


// ************************************************************************* //
