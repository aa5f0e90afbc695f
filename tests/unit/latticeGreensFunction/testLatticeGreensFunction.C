/*---------------------------------------------------------------------------*\
    chargedFoam: unit tests of the 7-point lattice's Green's function
    (GoogleTest)

    References independent of the table's DST solve: Watson's integral for
    G(0) (Watson 1939; W = 1.5163860591519780, G(0) = W/6), the field of
    the continuum 1/(4 pi r) with its lattice correction
    (5 (x^4 + y^4 + z^4)/r^4 - 3)/(32 pi r^3) differenced by hand far from
    the charge, the lattice's symmetries, and Coulomb's law for two S2
    shapes 14 cells apart.
\*---------------------------------------------------------------------------*/

#include "latticeGreensFunction.H"
#include "mathematicalConstants.H"

#include <gtest/gtest.h>

using namespace Foam;
using constant::mathematical::pi;

namespace Foam
{
// For gtest's failure messages
template<class Cmpt>
inline std::ostream& operator<<(std::ostream& os, const Vector<Cmpt>& v)
{
    return os << '(' << v.x() << ' ' << v.y() << ' ' << v.z() << ')';
}
}

namespace
{

const latticeGreensFunction& table()
{
    static const latticeGreensFunction G(24);
    return G;
}

scalar asymptotic(const scalar x, const scalar y, const scalar z)
{
    const scalar r2 = x*x + y*y + z*z;
    const scalar r = std::sqrt(r2);
    const scalar q4 = (x*x*x*x + y*y*y*y + z*z*z*z)/(r2*r2);
    return 1/(4*pi*r) + (5*q4 - 3)/(32*pi*r*r2);
}

} // End anonymous namespace


TEST(latticeGreensFunction, watsonIntegral)
{
    EXPECT_NEAR(table().G0(), 1.5163860591519780/6, 1e-8);
}


TEST(latticeGreensFunction, farFieldIsTheExpansion)
{
    for (const labelVector n : {labelVector(20, 0, 0), labelVector(12, 12, 0),
                                labelVector(10, 10, 10), labelVector(-7, 15, 4)})
    {
        const scalar a = n.x(), b = n.y(), c = n.z();
        const vector ref
        (
            -0.5*(asymptotic(a + 1, b, c) - asymptotic(a - 1, b, c)),
            -0.5*(asymptotic(a, b + 1, c) - asymptotic(a, b - 1, c)),
            -0.5*(asymptotic(a, b, c + 1) - asymptotic(a, b, c - 1))
        );
        const vector D(table().field(n.x(), n.y(), n.z()));
        EXPECT_LT(mag(D - ref), 2e-4*mag(ref)) << n;
        // and it is not the continuum's field alone (the lattice's
        // anisotropy is resolved)
        const vector r(a, b, c);
        const vector coulomb(r/(4*pi*pow3(mag(r))));
        EXPECT_GT(mag(D - coulomb), 10*mag(D - ref)) << n;
    }
}


TEST(latticeGreensFunction, symmetries)
{
    const latticeGreensFunction& G = table();
    for (const labelVector n : {labelVector(1, 2, 3), labelVector(5, 0, 2)})
    {
        const label a = n.x(), b = n.y(), c = n.z();
        const vector D(G.field(a, b, c));
        // odd in its own direction, even in the others
        EXPECT_EQ(G.field(-a, b, c), vector(-D.x(), D.y(), D.z()));
        EXPECT_EQ(G.field(a, -b, -c), vector(D.x(), -D.y(), -D.z()));
        // the cube's permutations
        const vector P(G.field(b, a, c));
        EXPECT_NEAR(P.x(), D.y(), 1e-15);
        EXPECT_NEAR(P.y(), D.x(), 1e-15);
        EXPECT_NEAR(P.z(), D.z(), 1e-15);
    }
    EXPECT_EQ(G.field(0, 0, 0), vector::zero);
}


TEST(latticeGreensFunction, shapesAndPairs)
{
    const latticeGreensFunction& G = table();
    DynamicList<labelVector> cT, cS;
    DynamicList<scalar> wT, wS;
    // One cell each: the pair field is D
    latticeGreensFunction::shape(vector(0.1, 0, 0), 0.5, cT, wT);
    latticeGreensFunction::shape(vector(3, -2, 1), 0.5, cS, wS);
    ASSERT_EQ(cT.size(), 1);
    ASSERT_EQ(cS.size(), 1);
    EXPECT_EQ(G.pairField(cT, wT, cS, wS), G.field(-3, 2, -1));

    // S2 shapes of 2 cells: normalised, within the radius; 14 cells apart
    // their lattice force is Coulomb's within the (h/r)^2 error
    const vector uT(0.3, 0.2, -0.4);
    const vector uS(uT + vector(14, 0, 0));
    latticeGreensFunction::shape(uT, 2, cT, wT);
    latticeGreensFunction::shape(uS, 2, cS, wS);
    scalar total = 0;
    for (const scalar w : wT)
    {
        total += w;
    }
    EXPECT_NEAR(total, 1, 1e-14);
    forAll(cT, i)
    {
        EXPECT_LT(mag(vector(cT[i]) - uT), 2);
        EXPECT_GT(wT[i], 0);
    }
    const vector E(G.pairField(cT, wT, cS, wS));
    const scalar coulomb = 1/(4*pi*sqr(14.0));
    EXPECT_NEAR(E.x(), -coulomb, 0.01*coulomb);
    EXPECT_LT(mag(vector(0, E.y(), E.z())), 0.01*coulomb);
}


int main(int argc, char** argv)
{
    ::testing::InitGoogleTest(&argc, argv);
    return RUN_ALL_TESTS();
}


// ************************************************************************* //
