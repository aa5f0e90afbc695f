/*---------------------------------------------------------------------------*\
    chargedFoam: unit tests of the grounded-plane image charges (GoogleTest)

    References are written out independently of the kernel: the analytic
    image force of one wall, the 3 images of a right-angle edge and the 7 of
    a corner summed by hand, and a box's images enumerated axis by axis;
    the exact box (boxImages) against symmetry and the single-wall limit.
\*---------------------------------------------------------------------------*/

#include "groundedPlanes.H"
#include "boxImages.H"
#include "Random.H"
#include "error.H"
#include "mathematicalConstants.H"

#include <gtest/gtest.h>

using namespace Foam;

namespace Foam
{
// For gtest's failure messages
inline std::ostream& operator<<(std::ostream& os, const vector& v)
{
    return os << '(' << v.x() << ' ' << v.y() << ' ' << v.z() << ')';
}
}

namespace
{

const scalar kC = 1/(4*constant::mathematical::pi*8.8541878128e-12); // CODATA 2018
const scalar q0 = 1e-9;

// Planes x = 0, y = 0, z = 0 bounding the octant x, y, z > 0
groundedPlanes octant(const label n)
{
    List<point> p(n, point::zero);
    List<vector> nn({vector(-1, 0, 0), vector(0, -1, 0), vector(0, 0, -1)});
    nn.setSize(n);
    return groundedPlanes(p, nn);
}

vector fieldAt
(
    const groundedPlanes& planes,
    const point& x,
    const scalar q,
    const scalar rCut
)
{
    const pairwiseCoulomb coulomb;
    List<point> xs({x});
    List<scalar> qs({q});
    vectorField E(1, Zero);
    planes.addFieldsWithinCutoff(coulomb, xs, xs, qs, rCut, E, 0);
    return E[0];
}

} // End anonymous namespace


TEST(groundedPlanes, SingleWallAttraction)
{
    // q at distance d above the wall z = 0: F = q^2/(4 pi eps0 (2d)^2)
    // toward the wall
    const groundedPlanes wall(List<point>({point(3, -2, 0)}), List<vector>({vector(0, 0, -2)}));
    const scalar d = 0.013;
    const vector F = q0*fieldAt(wall, point(0.4, 0.7, d), q0, 1);
    const vector Fref(0, 0, -kC*q0*q0/sqr(2*d));
    EXPECT_LT(mag(F - Fref), 1e-12*mag(Fref)) << F << " vs " << Fref;
    EXPECT_TRUE(wall.rightAngled());
}


TEST(groundedPlanes, RightAngleEdgeIsBalancedQuadrupole)
{
    // q at (a, b, c) in the edge x = 0, y = 0: images -q (-a, b), -q
    // (a, -b), +q (-a, -b); their forces summed by hand
    const groundedPlanes edge = octant(2);
    const scalar a = 0.02, b = 0.035, c = 0.5;
    const vector F = q0*fieldAt(edge, point(a, b, c), q0, 1);
    const scalar k2 = kC*q0*q0;
    const vector F1(-k2/sqr(2*a), 0, 0);
    const vector F2(0, -k2/sqr(2*b), 0);
    const scalar r3 = std::pow(sqr(2*a) + sqr(2*b), 1.5);
    const vector F3(k2*2*a/r3, k2*2*b/r3, 0);
    const vector Fref = F1 + F2 + F3;
    EXPECT_LT(mag(F - Fref), 1e-12*mag(Fref)) << F << " vs " << Fref;

    pointField xI;
    scalarField qI;
    edge.images(List<point>({point(a, b, c)}), List<scalar>({q0}), 1, xI, qI);
    ASSERT_EQ(xI.size(), 3);
    EXPECT_NEAR(sum(qI), -q0, 1e-24);     // -q -q +q
}


TEST(groundedPlanes, RightAngleCornerHasSevenImages)
{
    const groundedPlanes corner = octant(3);
    EXPECT_EQ(corner.perpendicularPairs().size(), 3);
    EXPECT_EQ(corner.perpendicularTriples().size(), 1);
    const point x(0.011, 0.023, 0.017);

    pointField xI;
    scalarField qI;
    labelList owner;
    corner.images(List<point>({x}), List<scalar>({q0}), 1, xI, qI, &owner);
    ASSERT_EQ(xI.size(), 7);
    EXPECT_EQ(owner, labelList(7, Zero));

    // The 7 mirror points (sx x, sy y, sz z), charge q sx sy sz
    vector Fref(Zero);
    for (const int sx : {1, -1})
    for (const int sy : {1, -1})
    for (const int sz : {1, -1})
    {
        if (sx == 1 && sy == 1 && sz == 1) continue;
        const point y(sx*x.x(), sy*x.y(), sz*x.z());
        const vector r(x - y);
        Fref += kC*q0*(q0*sx*sy*sz)*r/std::pow(magSqr(r), 1.5);
    }
    const vector F = q0*fieldAt(corner, x, q0, 1);
    EXPECT_LT(mag(F - Fref), 1e-12*mag(Fref)) << F << " vs " << Fref;
    // By symmetry of the corner: pushed into it along every axis
    EXPECT_LT(F.x(), 0);
    EXPECT_LT(F.y(), 0);
    EXPECT_LT(F.z(), 0);
}


TEST(groundedPlanes, PairFeelsTheOthersImages)
{
    // Wall z = 0; q1 at (0,0,d1), q2 at (s,0,d2): E1 = own image + q2 +
    // image of q2, and likewise for 2
    const groundedPlanes wall(List<point>({point::zero}), List<vector>({vector(0, 0, -1)}));
    const scalar d1 = 0.02, d2 = 0.05, s = 0.03;
    List<point> x({point(0, 0, d1), point(s, 0, d2)});
    List<scalar> q({q0, -2*q0});

    auto E = [](const point& at, const point& from, const scalar qq)
    {
        const vector r(at - from);
        return kC*qq*r/std::pow(magSqr(r), 1.5);
    };
    const vectorField Eref
    ({
        E(x[0], point(0, 0, -d1), -q[0]) + E(x[0], x[1], q[1])
      + E(x[0], point(s, 0, -d2), -q[1]),
        E(x[1], point(s, 0, -d2), -q[1]) + E(x[1], x[0], q[0])
      + E(x[1], point(0, 0, -d1), -q[0])
    });

    const pairwiseCoulomb coulomb;
    vectorField Ef(2, Zero);
    wall.addFieldsWithinCutoff(coulomb, x, x, q, 1, Ef, 0);
    forAll(x, i)
    {
        EXPECT_LT(mag(Ef[i] - Eref[i]), 1e-12*mag(Eref[i])) << i;
    }
}


TEST(groundedPlanes, NoSelfForce)
{
    // Far from every plane (beyond range) a lone charge feels nothing:
    // not itself, no image
    const groundedPlanes corner = octant(3);
    EXPECT_EQ(fieldAt(corner, point(0.5, 0.6, 0.7), q0, 0.4), vector::zero);

    // Targets that are not the sources: the field of the charge itself
    // and of its images
    const pairwiseCoulomb coulomb;
    const groundedPlanes wall(List<point>({point::zero}), List<vector>({vector(0, 0, -1)}));
    List<point> xs({point(0, 0, 0.1)});
    List<scalar> qs({q0});
    List<point> xt({point(0, 0, 0.2)});
    vectorField E(1, Zero);
    wall.addFieldsWithinCutoff(coulomb, xt, xs, qs, 1, E, -1);
    const scalar Ez = kC*q0*(1/sqr(0.1) - 1/sqr(0.3));
    EXPECT_LT(mag(E[0] - vector(0, 0, Ez)), 1e-12*Ez);
}


TEST(groundedPlanes, CutoffTruncatesImages)
{
    const groundedPlanes wall(List<point>({point::zero}), List<vector>({vector(0, 0, -1)}));
    const scalar d = 0.1;
    // Own image at 2d: outside rCut = 1.9 d, inside rCut = 2.1 d
    EXPECT_EQ(fieldAt(wall, point(0, 0, d), q0, 1.9*d), vector::zero);
    EXPECT_LT
    (
        mag(fieldAt(wall, point(0, 0, d), q0, 2.1*d)
          - vector(0, 0, -kC*q0/sqr(2*d))),
        1e-12*kC*q0/sqr(2*d)
    );

    // Another charge's image beyond rCut is dropped though the charge
    // itself is within: q1 at (0,0,d), q2 at (0.15,0,d): distance 0.15 to
    // q2, 0.25 to its image; rCut 0.2 > 2d keeps q1's own image
    const pairwiseCoulomb coulomb;
    List<point> x({point(0, 0, d), point(0.15, 0, d)});
    List<scalar> q({q0, q0});
    vectorField E(2, Zero);
    wall.addFieldsWithinCutoff(coulomb, x, x, q, 0.2 + 1e-9, E, 0);
    const vector E0ref
    (
        vector(0, 0, -kC*q0/sqr(2*d)) + vector(-kC*q0/sqr(0.15), 0, 0)
    );
    EXPECT_LT(mag(E[0] - E0ref), 1e-12*mag(E0ref));

    // range below d: no image at all
    vectorField E2(2, Zero);
    wall.addFieldsWithinCutoff(coulomb, x, x, q, 1, E2, 0, 0.5*d);
    EXPECT_LT(mag(E2[0] - vector(-kC*q0/sqr(0.15), 0, 0)), 1e-12*kC*q0/sqr(0.15));
}


TEST(groundedPlanes, BoxImagesEqualAxisByAxisEnumeration)
{
    // Unit box: 6 planes; images of a charge: on each axis no reflection,
    // the low wall or the high wall (if closer than range), all 26
    // combinations but the identity, charge (-1)^(number of reflections).
    // Parallel walls are never composed.
    const List<point> p
    ({
        point(0, 0.3, 0.2), point(1, 0.5, 0.5), point(0.1, 0, 0.9),
        point(0.5, 1, 0.5), point(0.7, 0.4, 0), point(0.5, 0.5, 1)
    });
    const List<vector> n
    ({
        vector(-1, 0, 0), vector(1, 0, 0), vector(0, -1, 0),
        vector(0, 1, 0), vector(0, 0, -1), vector(0, 0, 1)
    });
    const groundedPlanes box(p, n);
    EXPECT_TRUE(box.rightAngled());
    EXPECT_EQ(box.perpendicularPairs().size(), 12);
    EXPECT_EQ(box.perpendicularTriples().size(), 8);

    Random rnd(7);
    const label N = 40;
    List<point> x(N);
    List<scalar> q(N);
    forAll(x, i)
    {
        x[i] = point(0.02, 0.02, 0.02)
          + 0.96*point(rnd.sample01<scalar>(), rnd.sample01<scalar>(), rnd.sample01<scalar>());
        q[i] = q0*(2*rnd.sample01<scalar>() - 1);
    }

    for (const scalar rCut : {0.1, 0.3, 0.6, 1.5})
    {
        vectorField Eref(N, Zero);
        label nImages = 0;
        forAll(x, t)
        {
            forAll(x, s)
            {
                for (label ix = 0; ix < 3; ++ix)
                for (label iy = 0; iy < 3; ++iy)
                for (label iz = 0; iz < 3; ++iz)
                {
                    // 0: none, 1: low wall, 2: high wall
                    const label m[3] = {ix, iy, iz};
                    point y(x[s]);
                    scalar qs = q[s];
                    bool ok = true;
                    for (direction c = 0; c < 3; ++c)
                    {
                        if (m[c] == 0) continue;
                        const scalar dist = m[c] == 1 ? x[s][c] : 1 - x[s][c];
                        ok = ok && dist < rCut;
                        y[c] = m[c] == 1 ? -x[s][c] : 2 - x[s][c];
                        qs = -qs;
                    }
                    if (!ok || (ix == 0 && iy == 0 && iz == 0 && s == t))
                    {
                        continue;
                    }
                    if (t == 0 && (ix || iy || iz)) ++nImages;
                    const vector r(x[t] - y);
                    if (magSqr(r) < sqr(rCut))
                    {
                        Eref[t] += kC*qs*r/std::pow(magSqr(r), 1.5);
                    }
                }
            }
        }

        pointField xI;
        scalarField qI;
        box.images(x, q, rCut, xI, qI);
        EXPECT_EQ(xI.size(), nImages) << "rCut " << rCut;

        const pairwiseCoulomb coulomb;
        vectorField E(N, Zero);
        box.addFieldsWithinCutoff(coulomb, x, x, q, rCut, E, 0);
        scalar maxE = 0, maxErr = 0;
        forAll(x, i)
        {
            maxE = max(maxE, mag(Eref[i]));
            maxErr = max(maxErr, mag(E[i] - Eref[i]));
        }
        EXPECT_LT(maxErr, 1e-12*maxE) << "rCut " << rCut;
    }
}


TEST(groundedPlanes, NonPerpendicularPlanesAreNotComposed)
{
    // Two planes at 60 degrees: one image each, no composition
    const groundedPlanes wedge
    (
        List<point>({point::zero, point::zero}),
        List<vector>({vector(0, -1, 0), vector(-std::sqrt(0.75), 0.5, 0)})
    );
    EXPECT_FALSE(wedge.rightAngled());
    EXPECT_EQ(wedge.perpendicularPairs().size(), 0);
    pointField xI;
    scalarField qI;
    wedge.images(List<point>({point(0.05, 0.01, 0)}), List<scalar>({q0}), 1, xI, qI);
    EXPECT_EQ(xI.size(), 2);

    // A slab (parallel planes): right-angled, one image per wall
    const groundedPlanes slab
    (
        List<point>({point::zero, point(0, 0, 0.1)}),
        List<vector>({vector(0, 0, -1), vector(0, 0, 1)})
    );
    EXPECT_TRUE(slab.rightAngled());
    slab.images(List<point>({point(0, 0, 0.03)}), List<scalar>({q0}), 1, xI, qI);
    ASSERT_EQ(xI.size(), 2);
    EXPECT_LT(mag(xI[0] - point(0, 0, -0.03)), 1e-15);
    EXPECT_LT(mag(xI[1] - point(0, 0, 0.17)), 1e-15);
}


TEST(groundedPlanes, BadPlanesAreAnError)
{
    FatalError.throwExceptions();
    EXPECT_THROW
    (
        groundedPlanes(List<point>({point::zero}), List<vector>({vector::zero})),
        Foam::error
    );
    EXPECT_THROW
    (
        groundedPlanes
        (
            List<point>({point::zero, point(1, 2, 0)}),
            List<vector>({vector(0, 0, -1), vector(0, 0, -3)})
        ),
        Foam::error
    );
    FatalError.dontThrowExceptions();
}


// The exact box: a charge at the centre of a grounded cube feels nothing;
// close to one face it feels its image -q at 2 d, the other faces adding
// O((2 d/L)^2); an insulating face repels with the image +q
TEST(boxImages, CentreAndSingleWallLimit)
{
    const scalar L = 1, d = 0.01;
    const FixedList<boxImages::faceKind, 3> grounded
    (
        boxImages::faceKind::grounded
    );
    List<vector> f;
    boxImages::forces
    (
        List<point>({point(0.5, 0.5, 0.5)}), List<scalar>({q0}),
        point::zero, vector(L, L, L), grounded, 1, labelList({0}), f
    );
    EXPECT_LT(mag(f[0]), 1e-10*kC*q0*q0/(L*L)) << f[0];

    const scalar single = kC*q0*q0/sqr(2*d);
    boxImages::forces
    (
        List<point>({point(d, 0.5, 0.5)}), List<scalar>({q0}),
        point::zero, vector(L, L, L), grounded, 1, labelList({0}), f
    );
    EXPECT_NEAR(f[0].x(), -single, 1e-3*single);
    EXPECT_LT(mag(f[0].y()) + mag(f[0].z()), 1e-9*single);

    // Insulating x faces (images of equal sign), grounded y and z; the
    // origin shifted
    FixedList<boxImages::faceKind, 3> kinds(grounded);
    kinds[0] = boxImages::faceKind::insulating;
    const point o(-3, 2, 7);
    boxImages::forces
    (
        List<point>({o + vector(d, 0.5, 0.5)}), List<scalar>({q0}),
        o, vector(L, L, L), kinds, 1, labelList({0}), f
    );
    EXPECT_NEAR(f[0].x(), single, 2e-3*single);
}


// Two charges in a periodic box with one grounded axis: the forces on the
// pair are equal and opposite along the periodic axes (the images' forces
// on each charge mirror each other by the box's symmetry about its centre)
TEST(boxImages, PeriodicAxesMomentum)
{
    FixedList<boxImages::faceKind, 3> kinds(boxImages::faceKind::periodic);
    kinds[2] = boxImages::faceKind::grounded;
    const List<point> x({point(0.3, 0.4, 0.5), point(0.7, 0.6, 0.5)});
    List<vector> f;
    boxImages::forces
    (
        x, List<scalar>({q0, -q0}), point::zero, vector(1, 1, 1), kinds, 1,
        labelList({0, 1}), f
    );
    const scalar scale = kC*q0*q0;
    EXPECT_LT(mag(f[0].x() + f[1].x()), 1e-9*scale);
    EXPECT_LT(mag(f[0].y() + f[1].y()), 1e-9*scale);
    EXPECT_GT(mag(f[0]), 1e-3*scale);
}


int main(int argc, char** argv)
{
    ::testing::InitGoogleTest(&argc, argv);
    return RUN_ALL_TESTS();
}


// ************************************************************************* //
