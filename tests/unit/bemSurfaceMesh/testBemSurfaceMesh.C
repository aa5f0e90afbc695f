/*---------------------------------------------------------------------------*\
    chargedFoam: unit tests of the BEM ellipsoid surface mesh (GoogleTest)

    References are independent of the mesh generator: Euler's formula and
    edge pairing of a closed orientable surface, the ellipsoid volume
    4 pi abc/3 by the divergence theorem over the flat triangles, the
    surface area by 2D quadrature, textbook curvatures of a spheroid, and
    brute-force quadrature of int dA/r.
\*---------------------------------------------------------------------------*/

#include "ellipsoidSurfaceMesh.H"
#include "mathematicalConstants.H"
#include "IOstreams.H"

#include <gtest/gtest.h>

#include <map>
#include <utility>

using namespace Foam;
using constant::mathematical::pi;

namespace
{

void checkClosed(const ellipsoidSurfaceMesh& m)
{
    // Every directed edge appears once and its reverse once
    std::map<std::pair<label, label>, label> cnt;
    for (const auto& f : m.faces())
    {
        for (label e = 0; e < 3; ++e)
        {
            ++cnt[{f[e], f[(e + 1) % 3]}];
        }
    }
    for (const auto& kv : cnt)
    {
        ASSERT_EQ(kv.second, 1);
        ASSERT_EQ(cnt.count({kv.first.second, kv.first.first}), 1u);
    }
    EXPECT_EQ(m.size(), 2*m.points().size() - 4);
}

scalar flatVolume(const ellipsoidSurfaceMesh& m)
{
    scalar V = 0;
    for (const auto& f : m.faces())
    {
        const point& a = m.points()[f[0]];
        const point& b = m.points()[f[1]];
        const point& c = m.points()[f[2]];
        V += (a & (b ^ c))/6;
    }
    return V;
}

} // namespace


TEST(bemSurfaceMesh, ExactPatchCountClosedOutward)
{
    const vector axes[3] = {vector(1, 1, 1), vector(2, 1, 1), vector(3, 1.5, 1)};
    const label counts[4] = {100, 392, 956, 2000};
    for (const vector& s : axes)
    {
        for (const label n : counts)
        {
            ellipsoidSurfaceMesh m(s, n);
            EXPECT_EQ(m.size(), n);
            checkClosed(m);

            // Divergence theorem over the flat triangles: slightly below
            // the ellipsoid volume (inscribed polyhedron), positive
            // because the faces point outwards
            const scalar V = flatVolume(m);
            const scalar Vex = 4*pi*s.x()*s.y()*s.z()/3;
            EXPECT_GT(V, 0);
            EXPECT_LT(V, Vex);
            EXPECT_GT(V, (1 - 20.0/n)*Vex);

            // Curved areas sum to the quadrature area
            const auto q = m.quality();
            // (O(h^2) = O(1/n) error of the 4x4 subdivided areas)
            EXPECT_NEAR(q.totalArea/q.exactArea, 1, 1.0/n)
                << s.x() << " n=" << n;

            // Normals point away from the centre
            for (label i = 0; i < m.size(); ++i)
            {
                ASSERT_GT(m.normals()[i] & m.centres()[i], 0);
            }
        }
    }
}


TEST(bemSurfaceMesh, QualityNearEqualAreas)
{
    const vector axes[5] =
        {vector(1, 1, 1), vector(2, 1, 1), vector(5, 1, 1), vector(10, 1, 1),
         vector(3, 1.5, 1)};
    for (const vector& s : axes)
    {
        for (const label n : {400, 2000})
        {
            ellipsoidSurfaceMesh m(s, n);
            m.writeQuality(Info);
            const auto q = m.quality();
            EXPECT_LT(q.areaStd/q.areaMean, 0.15) << s.x() << " n=" << n;
            EXPECT_GT(q.angleMin, 20) << s.x() << " n=" << n;
            EXPECT_LT(q.angleMax, 120) << s.x() << " n=" << n;
        }
    }
}


TEST(bemSurfaceMesh, CurvatureGrading)
{
    // Patch size ~ H^-beta: on a prolate a = 5 the tips (H = a/b^2 = 5)
    // get smaller patches than the equator (H = 0.52); still a closed,
    // well-shaped triangulation of the whole surface
    const vector s(5, 1, 1);
    ellipsoidSurfaceMesh m(s, 2000, 40, 0.5);
    m.writeQuality(Info);
    EXPECT_EQ(m.size(), 2000);
    checkClosed(m);
    const auto q = m.quality();
    EXPECT_NEAR(q.totalArea/q.exactArea, 1, 1.0/2000);
    EXPECT_GT(q.angleMin, 20);
    EXPECT_LT(q.angleMax, 120);
    scalar at = 0, ae = 0;
    label nt = 0, ne = 0;
    forAll(m.centres(), i)
    {
        const scalar x = m.centres()[i].x();
        if (x > 0.95*s.x()) { at += m.areas()[i]; ++nt; }
        if (mag(x) < 0.1*s.x()) { ae += m.areas()[i]; ++ne; }
    }
    // Expected ratio (5/0.52)^(2 beta) ~ 9.6; ask for more than 3
    EXPECT_LT(3*at/nt, ae/ne);
}


TEST(bemSurfaceMesh, CurvatureOfSpheroid)
{
    // Prolate spheroid (a, b, b): H = a/b^2 at the tip and
    // (b/a^2 + 1/b)/2 on the equator; sphere H = 1/R
    const scalar a = 3, b = 1.2;
    const vector s(a, b, b);
    EXPECT_NEAR
    (
        ellipsoidSurfaceMesh::meanCurvature(s, point(a, 0, 0)), a/sqr(b),
        1e-12
    );
    EXPECT_NEAR
    (
        ellipsoidSurfaceMesh::meanCurvature(s, point(0, 0, b)),
        0.5*(b/sqr(a) + 1/b), 1e-12
    );
    EXPECT_NEAR
    (
        ellipsoidSurfaceMesh::meanCurvature(vector(2, 2, 2), point(0, 2, 0)),
        0.5, 1e-12
    );

    // Projection: the closest point is on the surface and the offset is
    // along its normal
    const point p(1.7, 0.9, -0.4);
    const point x = ellipsoidSurfaceMesh::project(s, p);
    EXPECT_NEAR(sqr(x.x()/a) + sqr(x.y()/b) + sqr(x.z()/b), 1, 1e-12);
    const vector d = p - x;
    EXPECT_LT(mag(d - (d & ellipsoidSurfaceMesh::normal(s, x))
        *ellipsoidSurfaceMesh::normal(s, x)), 1e-10);
}


TEST(bemSurfaceMesh, InverseDistanceIntegral)
{
    const point A(0, 0, 0), B(1.3, 0.1, 0), C(0.4, 0.9, 0);
    const point P = (A + B + C)/3;
    const scalar J = ellipsoidSurfaceMesh::inverseDistanceIntegral(A, B, C, P);

    // Brute force: midpoint rule on a fine subdivision, singular cell
    // handled by the polar form around P (small relative contribution)
    const label m = 600;
    scalar Jb = 0;
    for (label i = 0; i < m; ++i)
    {
        for (label j = 0; j < m - i; ++j)
        {
            auto add = [&](point p0, point p1, point p2)
            {
                const point c = (p0 + p1 + p2)/3;
                const scalar w = 0.5*mag((p1 - p0) ^ (p2 - p0));
                Jb += w/mag(c - P);
            };
            auto nd = [&](label u, label v)
            {
                return point(A + (scalar(u)/m)*(B - A) + (scalar(v)/m)*(C - A));
            };
            add(nd(i, j), nd(i + 1, j), nd(i, j + 1));
            if (i + j < m - 1)
            {
                add(nd(i + 1, j), nd(i + 1, j + 1), nd(i, j + 1));
            }
        }
    }
    EXPECT_NEAR(J/Jb, 1, 2e-3);
}


// ************************************************************************* //

int main(int argc, char** argv)
{
    ::testing::InitGoogleTest(&argc, argv);
    return RUN_ALL_TESTS();
}


// ************************************************************************* //
