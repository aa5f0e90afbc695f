/*---------------------------------------------------------------------------*\
    chargedFoam: unit tests of the ellipsoid contact geometry (GoogleTest)

    References are independent of the code under test:
      - overlap/separation: the Perram-Wertheim contact function (Perram &
        Wertheim 1985, J. Comput. Phys. 58:409), F = max over lambda of
        min over x of [lambda P1~(x) + (1 - lambda) P2~(x)]: F < 1 overlap,
        F = 1 touching (the minimiser is then the touching point), F > 1
        separated; lambda found by bisection on dF/dlambda, written here
        with Eigen from the semi-axes and rotation, not with the library;
      - contact configurations with a known answer: two ellipsoids are put
        in touch along a random approach direction (bisection on F), then
        one is pushed by depth delta along the common normal n of the
        touching point: for convex bodies the penetration depth is then
        exactly delta with the same normal and contact points x1 = touching
        point, x2 = x1 - delta n (the depth along any direction m is
        g0(m) + delta m.n >= delta near n while the curvature radii exceed
        delta); this premise is itself checked by a brute-force minimum of
        the depth over 20000 sampled directions + local compass search;
      - deep overlaps (random placements): the same brute-force minimum of
        the depth (the penetration depth is its global minimum);
      - Ruan's level-surface points (polynomial method): brute-force
        minimum of P2 over 20000 sampled points of surface 1 + compass
        search (and 1 <-> 2);
      - curvature: principal curvatures from the shape operator of the
        implicit surface (tangential Hessian / |grad|), analytic radii at
        the tips of spheroids;
      - spheres and planes: the textbook formulas.
\*---------------------------------------------------------------------------*/

#include "ellipsoidContact.H"
#include "ellipsoidContactBatch.H"
#include "hertzOnset.H"
#include "error.H"
#include "mathematicalConstants.H"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wold-style-cast"
#pragma GCC diagnostic ignored "-Wshadow"
#pragma GCC diagnostic ignored "-Wdeprecated-copy"
#include <Eigen/Dense>
#pragma GCC diagnostic pop

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <iomanip>
#include <iostream>
#include <random>
#include <vector>

using namespace Foam;
using Eigen::Matrix3d;
using Eigen::Vector3d;

namespace
{

typedef std::mt19937_64 rng_t;
const double pi = constant::mathematical::pi;


// * * * * * * * * * * * * * * * * Helpers * * * * * * * * * * * * * * * * //

double uniform(rng_t& g, const double a = 0, const double b = 1)
{
    return std::uniform_real_distribution<double>(a, b)(g);
}

double logUniform(rng_t& g, const double a, const double b)
{
    return std::exp(uniform(g, std::log(a), std::log(b)));
}

Vector3d toE(const vector& v)
{
    return Vector3d(v.x(), v.y(), v.z());
}

vector toF(const Vector3d& v)
{
    return vector(v(0), v(1), v(2));
}

vector randomUnit(rng_t& g)
{
    std::normal_distribution<double> N(0, 1);
    vector v;
    do
    {
        v = vector(N(g), N(g), N(g));
    } while (mag(v) < 1e-3);
    return v/mag(v);
}

// Uniform random rotation (Shoemake 1992)
tensor randomRotation(rng_t& g)
{
    const double u1 = uniform(g), u2 = 2*pi*uniform(g), u3 = 2*pi*uniform(g);
    const quaternion q
    (
        std::sqrt(u1)*std::cos(u3),
        vector
        (
            std::sqrt(1 - u1)*std::sin(u2),
            std::sqrt(1 - u1)*std::cos(u2),
            std::sqrt(u1)*std::sin(u3)
        )
    );
    return q.normalized().R();
}

// Semi-axes with minor semi-axis cMin and aspect ratios 1..arMax:
// triaxial, prolate, oblate, or (with allowSphere) a sphere
vector randomAxes(rng_t& g, const double cMin, const double arMax, bool allowSphere)
{
    const int kind = int(8*uniform(g));
    const double r1 = logUniform(g, 1, arMax), r2 = logUniform(g, 1, arMax);
    vector ax;
    if (kind == 0 && allowSphere) ax = vector(cMin, cMin, cMin);
    else if (kind <= 2) ax = vector(cMin*r1, cMin, cMin);           // prolate
    else if (kind <= 4) ax = vector(cMin*r1, cMin*r1, cMin);        // oblate
    else ax = vector(cMin, cMin*r1, cMin*r2);                       // triaxial
    // Random assignment of the axes to body x, y, z
    const int p = int(6*uniform(g));
    const int perm[6][3] = {{0,1,2},{0,2,1},{1,0,2},{1,2,0},{2,0,1},{2,1,0}};
    return vector(ax[perm[p][0]], ax[perm[p][1]], ax[perm[p][2]]);
}


// An ellipsoid described independently of the library
struct body
{
    vector ax;
    point c;
    tensor R;
    Matrix3d A;         // x^T A x = 1 on the surface (centred)
    Matrix3d Ainv;

    body(const vector& axes, const point& centre, const tensor& rot)
    :
        ax(axes),
        c(centre),
        R(rot)
    {
        Matrix3d Rm;
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j)
                Rm(i, j) = R(i, j);
        const Vector3d a2(sqr(ax.x()), sqr(ax.y()), sqr(ax.z()));
        A = Rm*a2.cwiseInverse().asDiagonal()*Rm.transpose();
        Ainv = Rm*a2.asDiagonal()*Rm.transpose();
    }

    double minAxis() const { return cmptMin(ax); }
    double maxAxis() const { return cmptMax(ax); }
    ellipsoid shape() const { return ellipsoid(ax, c, R); }
};


// Perram-Wertheim: F and the minimiser x (inertial frame)
struct pwResult
{
    double F;
    Vector3d x;
};

pwResult perramWertheim(const body& b1, const body& b2)
{
    // Frame centred on c1; x(lambda) minimises
    // lambda x^T A1 x + (1 - lambda)(x - r)^T A2 (x - r)
    const Vector3d r = toE(b2.c - b1.c);
    auto xOf = [&](const double l) -> Vector3d
    {
        const Matrix3d M = l*b1.A + (1 - l)*b2.A;
        return M.llt().solve((1 - l)*(b2.A*r));
    };

    // dF/dlambda = P1~(x) - P2~(x) (envelope theorem), decreasing in lambda
    double lo = 0, hi = 1;
    for (int it = 0; it < 80; ++it)
    {
        const double mid = 0.5*(lo + hi);
        if (mid <= lo || mid >= hi) break;
        const Vector3d x = xOf(mid);
        const Vector3d y = x - r;
        if (x.dot(b1.A*x) - y.dot(b2.A*y) > 0) lo = mid;
        else hi = mid;
    }
    const double l = 0.5*(lo + hi);
    const Vector3d x = xOf(l);
    const Vector3d y = x - r;
    pwResult res;
    res.F = l*x.dot(b1.A*x) + (1 - l)*y.dot(b2.A*y);
    res.x = x + toE(b1.c);
    return res;
}


// Penetration depth along the unit direction m (support functions)
double depthAlong(const body& b1, const body& b2, const Vector3d& m)
{
    return
        std::sqrt(m.dot(b1.Ainv*m)) + std::sqrt(m.dot(b2.Ainv*m))
      - m.dot(toE(b2.c - b1.c));
}


// Brute force: minimum depth over 20000 Fibonacci directions, then compass
// search on the sphere down to 1e-11 rad
struct bfResult
{
    double g;
    Vector3d m;
};

bfResult bruteForceDepth(const body& b1, const body& b2)
{
    const int n = 20000;
    const double golden = pi*(3 - std::sqrt(5.0));
    bfResult best;
    best.g = GREAT;
    for (int i = 0; i < n; ++i)
    {
        const double z = 1 - (2*i + 1)/double(n);
        const double rr = std::sqrt(std::max(0.0, 1 - z*z));
        const Vector3d m(rr*std::cos(golden*i), rr*std::sin(golden*i), z);
        const double g = depthAlong(b1, b2, m);
        if (g < best.g)
        {
            best.g = g;
            best.m = m;
        }
    }
    for (double h = 0.05; h > 1e-11; )
    {
        Vector3d t1 = best.m.unitOrthogonal();
        Vector3d t2 = best.m.cross(t1);
        bool moved = false;
        const Vector3d steps[4] = {t1, -t1, t2, -t2};
        for (const Vector3d& s : steps)
        {
            const Vector3d m = (best.m + h*s).normalized();
            const double g = depthAlong(b1, b2, m);
            if (g < best.g)
            {
                best.g = g;
                best.m = m;
                moved = true;
            }
        }
        if (!moved) h *= 0.5;
    }
    return best;
}


// A pair with a known contact: touching along u, then pushed by delta
struct knownContact
{
    body b1, b2;
    double sTouch;      // centre distance along u at touching
    double sClosed;     // the same from F(s u) = s^2 F(u)
    Vector3d xTouch;    // touching point
    Vector3d n;         // unit normal from 1 to 2 at touching
    double delta;       // signed: > 0 overlap, < 0 gap

    Vector3d x1() const { return xTouch; }
    Vector3d x2() const { return xTouch - delta*n; }
};

knownContact makeContact
(
    const body& b1,
    const vector& ax2,
    const tensor& R2,
    const vector& u,
    const double delta,
    const bool bisect
)
{
    knownContact k{b1, body(ax2, b1.c, R2), 0, 0, Vector3d::Zero(), Vector3d::Zero(), delta};

    // Closed form: PW's F scales as the square of the centre distance
    // Bounding spheres in touch: the ellipsoids are not overlapping, F >= 1
    const double s0 = b1.maxAxis() + cmptMax(ax2);
    body probe(ax2, b1.c + s0*u, R2);
    k.sClosed = s0/std::sqrt(perramWertheim(b1, probe).F);

    double s = k.sClosed;
    if (bisect)
    {
        // Bisection on the PW criterion F(s) < 1 (overlap)
        double lo = 0, hi = s0;
        for (int it = 0; it < 200; ++it)
        {
            const double mid = 0.5*(lo + hi);
            if (mid <= lo || mid >= hi) break;
            const body b(ax2, b1.c + mid*u, R2);
            if (perramWertheim(b1, b).F < 1) lo = mid;
            else hi = mid;
        }
        s = 0.5*(lo + hi);
    }
    k.sTouch = s;

    const body touching(ax2, b1.c + s*u, R2);
    const pwResult pw = perramWertheim(b1, touching);
    k.xTouch = pw.x;
    k.n = (b1.A*(pw.x - toE(b1.c))).normalized();
    k.b2 = body(ax2, toF(toE(b1.c + s*u) - delta*k.n), R2);
    return k;
}


double median(std::vector<double> v)
{
    if (v.empty()) return 0;
    std::sort(v.begin(), v.end());
    return v[v.size()/2];
}

double maxOf(const std::vector<double>& v)
{
    return v.empty() ? 0 : *std::max_element(v.begin(), v.end());
}

double angleBetween(const Vector3d& a, const Vector3d& b)
{
    return std::atan2(a.cross(b).norm(), a.dot(b));
}

bool finite(const vector& v)
{
    return std::isfinite(v.x()) && std::isfinite(v.y()) && std::isfinite(v.z());
}


// Error statistics of one method against the known contacts
struct errorStats
{
    std::vector<double> point, overlap, angle;

    // Scaled by the overlap: point error/delta, angle/(delta/cMin), and
    // the overlap taken as n.(x1 - x2) instead of |x1 - x2|
    std::vector<double> pointPerDelta, anglePerDelta, overlapProjected;

    void add
    (
        const ellipsoidContact::result& r,
        const knownContact& k,
        const double cMin
    )
    {
        const double ep = std::max
        (
            (toE(r.x1) - k.x1()).norm(),
            (toE(r.x2) - k.x2()).norm()
        );
        const double ang = angleBetween(toE(r.n), k.n);
        point.push_back(ep/cMin);
        overlap.push_back(std::abs(r.overlap - k.delta)/k.delta);
        angle.push_back(ang);
        pointPerDelta.push_back(ep/k.delta);
        anglePerDelta.push_back(ang/(k.delta/cMin));
        overlapProjected.push_back
        (
            std::abs((r.n & (r.x1 - r.x2)) - k.delta)/k.delta
        );
    }

    void printScaled(const std::string& name) const
    {
        std::cout
            << "    " << std::left << std::setw(11) << name << std::right
            << std::scientific << std::setprecision(2)
            << " point error/delta max " << maxOf(pointPerDelta)
            << " med " << median(pointPerDelta)
            << " | angle/(delta/cmin) max " << maxOf(anglePerDelta)
            << " med " << median(anglePerDelta)
            << " | overlap as n.(x1-x2): rel max " << maxOf(overlapProjected)
            << " med " << median(overlapProjected) << std::endl;
    }

    void print(const std::string& name, const std::string& range) const
    {
        std::cout
            << "    " << std::left << std::setw(11) << name
            << std::setw(16) << range << std::right << std::scientific
            << std::setprecision(2)
            << " point/cmin max " << std::setw(9) << maxOf(point)
            << " med " << std::setw(9) << median(point)
            << " | overlap rel max " << std::setw(9) << maxOf(overlap)
            << " med " << std::setw(9) << median(overlap)
            << " | angle [rad] max " << std::setw(9) << maxOf(angle)
            << " med " << std::setw(9) << median(angle)
            << " (n = " << point.size() << ")" << std::endl;
    }
};

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Tests  * * * * * * * * * * * * * * * * //

TEST(ellipsoidContact, ReferenceConstructionIsSelfConsistent)
{
    // The touching point lies on both surfaces, the closed-form and
    // bisected touching distances agree, and the pushed pair has no
    // direction of smaller penetration depth than delta (brute force)
    rng_t g(101);
    for (int i = 0; i < 200; ++i)
    {
        const body b1(randomAxes(g, 1, 10, true), toF(Vector3d::Random()), randomRotation(g));
        const vector ax2 = randomAxes(g, uniform(g, 0.5, 2), 10, true);
        const double cMin = std::min(b1.minAxis(), cmptMin(ax2));
        const double delta = cMin*logUniform(g, 1e-6, 1e-2);
        const knownContact k =
            makeContact(b1, ax2, randomRotation(g), randomUnit(g), delta, true);

        EXPECT_NEAR(k.sClosed/k.sTouch, 1, 1e-14);

        const Vector3d y1 = k.x1() - toE(k.b1.c), y2 = k.x2() - toE(k.b2.c);
        EXPECT_NEAR(y1.dot(k.b1.A*y1), 1, 1e-13);
        EXPECT_NEAR(y2.dot(k.b2.A*y2), 1, 1e-13);

        const double L = k.b1.maxAxis() + k.b2.maxAxis();
        EXPECT_NEAR(depthAlong(k.b1, k.b2, k.n), delta, 1e-14*L);
        const bfResult bf = bruteForceDepth(k.b1, k.b2);
        EXPECT_GT(bf.g, delta - 1e-13*L) << "a direction of smaller depth";
        EXPECT_LT(bf.g, delta + 1e-13*L);
        EXPECT_LT(angleBetween(bf.m, k.n), 1e-5);
    }
}


TEST(ellipsoidContact, BruteForceAccuracyBothMethods)
{
    // Random poses, aspect ratios 1..10, overlaps 1e-6..1e-2 of the minor
    // semi-axis; errors against the known contact of each configuration
    rng_t g(7);
    const int nConfig = 4000;
    const double decades[5] = {1e-6, 1e-5, 1e-4, 1e-3, 1e-2};

    errorStats robustAll, polyAll, robustDec[4], polyDec[4];
    int polyUnconverged = 0;

    for (int i = 0; i < nConfig; ++i)
    {
        const int dec = i % 4;
        const body b1(randomAxes(g, 1, 10, false), toF(Vector3d::Random()), randomRotation(g));
        const vector ax2 = randomAxes(g, uniform(g, 0.5, 2), 10, false);
        const double cMin = std::min(b1.minAxis(), cmptMin(ax2));
        const double delta = cMin*logUniform(g, decades[dec], decades[dec + 1]);
        const knownContact k =
            makeContact(b1, ax2, randomRotation(g), randomUnit(g), delta, true);

        const ellipsoid e1 = k.b1.shape(), e2 = k.b2.shape();

        ASSERT_TRUE(ellipsoidContact::intersect(e1, e2));

        const ellipsoidContact::result rr =
            ellipsoidContact::contact(e1, e2, ellipsoidContact::method::robust);
        ASSERT_TRUE(rr.contact);
        ASSERT_TRUE(rr.converged);
        robustAll.add(rr, k, cMin);
        robustDec[dec].add(rr, k, cMin);

        const ellipsoidContact::result rp =
            ellipsoidContact::contact(e1, e2, ellipsoidContact::method::polynomial);
        ASSERT_TRUE(rp.contact);
        if (!rp.converged)
        {
            ++polyUnconverged;
            continue;
        }
        polyAll.add(rp, k, cMin);
        polyDec[dec].add(rp, k, cMin);
    }

    std::cout
        << "  Contact accuracy vs known contacts (" << nConfig
        << " random pairs, aspect ratios 1..10):" << std::endl;
    const char* names[4] =
        {"[1e-6,1e-5)", "[1e-5,1e-4)", "[1e-4,1e-3)", "[1e-3,1e-2)"};
    for (int d = 0; d < 4; ++d)
    {
        robustDec[d].print("robust", std::string("delta/c ") + names[d]);
    }
    robustAll.print("robust", "all");
    for (int d = 0; d < 4; ++d)
    {
        polyDec[d].print("polynomial", std::string("delta/c ") + names[d]);
    }
    polyAll.print("polynomial", "all");
    robustAll.printScaled("robust");
    polyAll.printScaled("polynomial");
    std::cout
        << "    polynomial: " << polyUnconverged
        << " configurations without a valid root" << std::endl;

    // The robust method is accurate to round-off amplified by the geometry
    EXPECT_LT(maxOf(robustAll.point), 1e-9);
    EXPECT_LT(maxOf(robustAll.overlap), 1e-6);
    EXPECT_LT(maxOf(robustAll.angle), 1e-9);

    // The polynomial (level-surface) points are not the common-normal
    // points: they are O(delta) away from them, so |x1 - x2| is an O(1)
    // relative error of the overlap (see the printed table). Bounds: a
    // wrong root would put the points O(cMin) away.
    EXPECT_LT(maxOf(polyAll.pointPerDelta), 10);
    EXPECT_LT(maxOf(polyAll.anglePerDelta), 5);
    EXPECT_LT(maxOf(polyAll.overlap), 5);
}


TEST(ellipsoidContact, PolynomialMethodFindsTheLevelSurfacePoints)
{
    // Ruan's definition checked by brute force: x1 minimises P2 over the
    // surface of 1 (20000 sampled surface points + compass search), x2
    // minimises P1 over the surface of 2
    rng_t g(31);

    // Minimum of the level function of b over the surface of a
    auto levelMin = [](const body& a, const body& b) -> Vector3d
    {
        auto P = [&](const Vector3d& s) -> double
        {
            const Vector3d x =
                toE(a.c) + toE(a.R & vector(cmptMultiply(a.ax, toF(s)))) - toE(b.c);
            return x.dot(b.A*x) - 1;
        };
        const int n = 20000;
        const double golden = pi*(3 - std::sqrt(5.0));
        Vector3d best(0, 0, 1);
        double pBest = GREAT;
        for (int i = 0; i < n; ++i)
        {
            const double z = 1 - (2*i + 1)/double(n);
            const double rr = std::sqrt(std::max(0.0, 1 - z*z));
            const Vector3d s(rr*std::cos(golden*i), rr*std::sin(golden*i), z);
            const double p = P(s);
            if (p < pBest) { pBest = p; best = s; }
        }
        for (double h = 0.05; h > 1e-12; )
        {
            const Vector3d t1 = best.unitOrthogonal(), t2 = best.cross(t1);
            bool moved = false;
            for (const Vector3d& st : {t1, Vector3d(-t1), t2, Vector3d(-t2)})
            {
                const Vector3d s = (best + h*st).normalized();
                const double p = P(s);
                if (p < pBest) { pBest = p; best = s; moved = true; }
            }
            if (!moved) h *= 0.5;
        }
        return toE(a.c) + toE(a.R & vector(cmptMultiply(a.ax, toF(best))));
    };

    std::vector<double> err;
    for (int i = 0; i < 60; ++i)
    {
        const body b1(randomAxes(g, 1, 10, false), point::zero, randomRotation(g));
        const vector ax2 = randomAxes(g, uniform(g, 0.5, 2), 10, false);
        const knownContact k = makeContact
        (
            b1, ax2, randomRotation(g), randomUnit(g), logUniform(g, 1e-4, 1e-1), false
        );
        const ellipsoidContact::result r = ellipsoidContact::contact
        (
            k.b1.shape(), k.b2.shape(), ellipsoidContact::method::polynomial
        );
        ASSERT_TRUE(r.converged);
        const double L = std::max(k.b1.maxAxis(), k.b2.maxAxis());
        err.push_back((toE(r.x1) - levelMin(k.b1, k.b2)).norm()/L);
        err.push_back((toE(r.x2) - levelMin(k.b2, k.b1)).norm()/L);
    }
    std::cout
        << "  Polynomial points vs brute-force level-surface minima: max "
        << std::scientific << std::setprecision(2) << maxOf(err)
        << " med " << median(err) << " (of the larger semi-axis)" << std::endl;
    EXPECT_LT(maxOf(err), 1e-6);
}


TEST(ellipsoidContact, RobustnessRandomPairs)
{
    // 1e5 random pairs: overlapping (1e-6..1e-1 of the minor semi-axis),
    // separated (gaps 1e-6..1), touching within +-1e-6, and random
    // placements (deep overlaps, containment, separation). A failure is:
    // non-finite output, disagreement with the Perram-Wertheim overlap
    // check (intersect() or result.contact), overlap < 0, |n| != 1, or no
    // convergence.
    rng_t g(2024);
    const int nPair = 100000;

    struct counter
    {
        int nonFinite = 0, missed = 0, false_ = 0, negative = 0, normal = 0,
            unconverged = 0, contacts = 0;
        double seconds = 0, secondsOverlapping = 0;
        long iterations = 0;
        int failures() const
        {
            return nonFinite + missed + false_ + negative + normal + unconverged;
        }
    };
    counter cAuto, cRobust, cPoly;
    int intersectMissed = 0, intersectFalse = 0, ambiguous = 0;
    int depthChecked = 0, depthBad = 0, nOverlapping = 0;
    double secIntersect = 0;

    auto check = [&](const ellipsoidContact::result& r, bool truth, counter& c)
    {
        if
        (
            !finite(r.x1) || !finite(r.x2) || !finite(r.n)
         || !std::isfinite(r.overlap) || !std::isfinite(r.reducedRadius)
        )
        {
            ++c.nonFinite;
        }
        if (truth && !r.contact) ++c.missed;
        if (!truth && r.contact) ++c.false_;
        if (r.overlap < 0) ++c.negative;
        if (std::abs(mag(r.n) - 1) > 1e-12) ++c.normal;
        if (r.contact)
        {
            ++c.contacts;
            if (!r.converged || !(r.reducedRadius > 0)) ++c.unconverged;
        }
    };

    typedef std::chrono::steady_clock clock;
    auto secondsSince = [](const clock::time_point& t0)
    {
        return std::chrono::duration<double>(clock::now() - t0).count();
    };

    const clock::time_point tStart = clock::now();

    for (int i = 0; i < nPair; ++i)
    {
        const int kind = i % 4;
        const body b1(randomAxes(g, 1, 10, true), toF(3*Vector3d::Random()), randomRotation(g));
        const vector ax2 = randomAxes(g, uniform(g, 0.3, 3), 10, true);
        const tensor R2 = randomRotation(g);
        const double cMin = std::min(b1.minAxis(), cmptMin(ax2));

        body b2(ax2, b1.c, R2);
        double delta = 0;
        if (kind < 3)
        {
            if (kind == 0) delta = cMin*logUniform(g, 1e-6, 1e-1);
            else if (kind == 1) delta = -cMin*logUniform(g, 1e-6, 1);
            else delta = cMin*uniform(g, -1e-6, 1e-6);
            b2 = makeContact(b1, ax2, R2, randomUnit(g), delta, false).b2;
        }
        else
        {
            b2 = body
            (
                ax2,
                b1.c + uniform(g)*(b1.maxAxis() + cmptMax(ax2))*randomUnit(g),
                R2
            );
        }

        const double F = perramWertheim(b1, b2).F;
        if (std::abs(F - 1) < 1e-13)
        {
            ++ambiguous;        // touching to round-off: either answer
            continue;
        }
        const bool truth = F < 1;
        nOverlapping += truth;

        const ellipsoid e1 = b1.shape(), e2 = b2.shape();

        clock::time_point t0 = clock::now();
        const bool hit = ellipsoidContact::intersect(e1, e2);
        secIntersect += secondsSince(t0);
        if (truth && !hit) ++intersectMissed;
        if (!truth && hit) ++intersectFalse;

        auto timed = [&](const ellipsoidContact::method m, counter& c)
        {
            const clock::time_point t = clock::now();
            const ellipsoidContact::result r = ellipsoidContact::contact(e1, e2, m);
            const double dt = secondsSince(t);
            c.seconds += dt;
            if (truth) c.secondsOverlapping += dt;
            c.iterations += r.iterations;
            check(r, truth, c);
            return r;
        };
        const ellipsoidContact::result ra =
            timed(ellipsoidContact::method::automatic, cAuto);
        const ellipsoidContact::result rr =
            timed(ellipsoidContact::method::robust, cRobust);
        timed(ellipsoidContact::method::polynomial, cPoly);

        // Known depth: the penetration depth cannot exceed delta (g(n) =
        // delta) and equals it for small delta; automatic (mostly the
        // certified single start) and robust (the full search)
        for (const ellipsoidContact::result* r : {&ra, &rr})
        {
            if (kind == 0 && r->contact)
            {
                ++depthChecked;
                const double tol = 1e-6*delta + 1e-13*(b1.maxAxis() + cmptMax(ax2));
                if (r->overlap > delta + tol) ++depthBad;
                if (delta <= 1e-2*cMin && std::abs(r->overlap - delta) > tol) ++depthBad;
            }
        }
    }

    const double total = secondsSince(tStart);
    const double nEval = nPair - ambiguous;

    std::cout
        << "  Robustness: " << nPair << " random pairs (" << nOverlapping
        << " overlapping, " << ambiguous << " ambiguous within |F - 1| < 1e-13)"
        << ", total " << std::fixed << std::setprecision(2) << total
        << " s incl. reference" << std::endl
        << "    intersect():  missed overlaps " << intersectMissed
        << ", false overlaps " << intersectFalse << ", "
        << std::setprecision(2) << 1e6*secIntersect/nEval << " us/pair" << std::endl;

    auto report = [&](const char* name, const counter& c)
    {
        std::cout
            << "    " << std::left << std::setw(12) << name << std::right
            << " failures " << c.failures()
            << " (non-finite " << c.nonFinite << ", missed " << c.missed
            << ", false " << c.false_ << ", overlap<0 " << c.negative
            << ", |n|!=1 " << c.normal << ", unconverged " << c.unconverged
            << "), contacts " << c.contacts << std::endl
            << "                 " << std::fixed << std::setprecision(2)
            << 1e6*c.seconds/nEval << " us/pair, "
            << 1e6*c.secondsOverlapping/nOverlapping
            << " us/overlapping pair, " << double(c.iterations)/c.contacts
            << " iterations/contact, " << c.seconds << " s" << std::endl;
    };
    report("automatic", cAuto);
    report("robust", cRobust);
    report("polynomial", cPoly);
    std::cout
        << "    automatic and robust depth == delta checks failed: " << depthBad
        << " of " << depthChecked << std::endl;

    EXPECT_EQ(intersectMissed, 0);
    EXPECT_EQ(intersectFalse, 0);
    EXPECT_EQ(cAuto.failures(), 0);
    EXPECT_EQ(cRobust.failures(), 0);
    EXPECT_EQ(depthBad, 0);
    EXPECT_LT(ambiguous, 10);
    EXPECT_EQ(cPoly.nonFinite, 0);
    EXPECT_EQ(cPoly.negative + cPoly.normal + cPoly.missed + cPoly.false_, 0);
    EXPECT_LT(total, 45);
}


TEST(ellipsoidContact, RobustMethodFindsTheGlobalPenetrationDepth)
{
    // Deep overlaps from random placements, where the depth g(n) can have
    // several local minima over the directions n: the robust overlap must
    // be the global minimum (brute force over 20000 directions + compass
    // search). A single Newton start from the centre line or the best
    // sample misses it in ~2-3 % of these pairs.
    rng_t g(4242);
    int nCompared = 0, nWorse = 0, nBelow = 0;
    double worst = 0;
    while (nCompared < 1500)
    {
        const body b1(randomAxes(g, 1, 10, true), point::zero, randomRotation(g));
        const vector ax2 = randomAxes(g, uniform(g, 0.3, 3), 10, true);
        const body b2
        (
            ax2,
            uniform(g)*(b1.maxAxis() + cmptMax(ax2))*randomUnit(g),
            randomRotation(g)
        );
        if (!(perramWertheim(b1, b2).F < 1 - 1e-6)) continue;
        ++nCompared;

        const ellipsoidContact::result r =
            ellipsoidContact::contact(b1.shape(), b2.shape());
        const bfResult bf = bruteForceDepth(b1, b2);
        const double L = b1.maxAxis() + b2.maxAxis();
        if (r.overlap > bf.g + 1e-9*L)
        {
            ++nWorse;
            worst = std::max(worst, (r.overlap - bf.g)/L);
        }
        if (r.overlap < bf.g - 1e-9*L) ++nBelow;
    }
    std::cout
        << "  Deep overlaps: " << nCompared << " pairs, robust depth above the"
        << " brute-force minimum in " << nWorse << " (worst " << worst
        << " of the size), below in " << nBelow << std::endl;
    EXPECT_EQ(nWorse, 0);
    EXPECT_EQ(nBelow, 0);
}


TEST(ellipsoidContact, TrackedStartAgreesWithTheFullSearch)
{
    // A pair moved through contact in small steps (approach, rotation,
    // separation), the narrow phase started each step from the tracked
    // direction of the step before: the same contact as the full search
    // (robust: intersection test and 128 sampled starts) to round-off,
    // and when separated the tracked direction is a separating plane's
    // normal (the support functions do not reach each other along it)
    rng_t g(77);
    int nContact = 0, nSeparated = 0, nBad = 0;
    for (int pair = 0; pair < 200; ++pair)
    {
        const vector ax1 = randomAxes(g, 1, 5, false);
        const vector ax2 = randomAxes(g, uniform(g, 0.5, 2), 5, false);
        const tensor R1 = randomRotation(g);
        const vector u = randomUnit(g);
        const vector w = 0.02*randomUnit(g);
        const double cMin = std::min(cmptMin(ax1), cmptMin(ax2));
        const body b0(ax1, point::zero, R1);
        const body touching = makeContact(b0, ax2, randomRotation(g), u, 0, false).b2;
        vector nTrack(Zero);
        for (int step = -20; step <= 20; ++step)
        {
            // Depth profile: 1e-3 cMin at the middle, apart at the ends
            const double depth = cMin*(1e-3 - 1e-4*std::abs(step));
            const vector rot = step*w;
            const tensor Rw =
                step == 0 ? tensor::I : quaternion(rot/mag(rot), mag(rot)).R();
            const ellipsoid e1(ax1, point::zero, R1);
            const ellipsoid e2(ax2, touching.c - depth*u, Rw & touching.R);
            const ellipsoidContact::result rt = ellipsoidContact::contact(e1, e2, nTrack);
            const ellipsoidContact::result rr =
                ellipsoidContact::contact(e1, e2, ellipsoidContact::method::robust);
            const double L = cmptMax(ax1) + cmptMax(ax2);
            if (rt.contact != rr.contact) { ++nBad; continue; }
            if (rt.contact)
            {
                ++nContact;
                if
                (
                    std::abs(rt.overlap - rr.overlap) > 1e-12*L
                 || mag(rt.n - rr.n) > 1e-9 || mag(nTrack - rt.n) > 0
                 || mag(rt.x1 - rr.x1) > 1e-9*L
                )
                {
                    ++nBad;
                }
            }
            else if (magSqr(nTrack) > 0)
            {
                ++nSeparated;
                const vector d = e2.centre() - e1.centre();
                if (!(e1.supportDistance(nTrack) + e2.supportDistance(nTrack) < (nTrack & d)))
                {
                    ++nBad;
                }
            }
        }
    }
    std::cout
        << "  Tracked start: " << nContact << " contacts, " << nSeparated
        << " separations with a tracked direction, disagreements " << nBad << std::endl;
    EXPECT_EQ(nBad, 0);
    EXPECT_GT(nContact, 1000);
    EXPECT_GT(nSeparated, 1000);
}


// Bit for bit: the same double, sign of zero included
bool sameBits(const double a, const double b)
{
    return std::memcmp(&a, &b, sizeof(double)) == 0;
}

bool sameBits(const vector& a, const vector& b)
{
    return sameBits(a.x(), b.x()) && sameBits(a.y(), b.y()) && sameBits(a.z(), b.z());
}

bool sameResult(const ellipsoidContact::result& a, const ellipsoidContact::result& b)
{
    return
        a.contact == b.contact && a.used == b.used && a.iterations == b.iterations
     && a.converged == b.converged && sameBits(a.x1, b.x1) && sameBits(a.x2, b.x2)
     && sameBits(a.n, b.n) && sameBits(a.overlap, b.overlap)
     && sameBits(a.reducedRadius, b.reducedRadius) && sameBits(a.separation, b.separation)
     && sameBits(a.gradR.centre1, b.gradR.centre1)
     && sameBits(a.gradR.rotation1, b.gradR.rotation1)
     && sameBits(a.gradR.centre2, b.gradR.centre2)
     && sameBits(a.gradR.rotation2, b.gradR.rotation2);
}


TEST(ellipsoidContactBatch, isTheScalarPathBitForBit)
{
    // Pairs moved through contact in small steps (approach, rotation of
    // both, separation), four at a time in the batch's lanes, each started
    // as EllipsoidCollision starts a lasting contact: from its last normal
    // extrapolated by the normal's change over the step before. Every
    // decided lane gives ellipsoidContact::contact(e1, e2, nTrack) from the
    // same start bit for bit; the undecided ones are left to it
    rng_t g(2024);
    const int width = ellipsoidContactBatch::width;
    label nLasting = 0, nDecided = 0, nDiffer = 0, nWrongDecided = 0;
    label nIterations[6] = {0, 0, 0, 0, 0, 0};
    ellipsoidContactBatch batch;

    for (int group = 0; group < 300; ++group)
    {
        // Lane l's pair; the group has 1..4 lanes (partial batches)
        const int nLanes = 1 + group % width;
        struct pairMotion
        {
            vector ax1, ax2, u, w1, w2, v;
            tensor R1, R2;
            point touching;
            double cMin;
            vector n = Zero, dn = Zero;
            bool inContact = false;
        };
        std::vector<pairMotion> P(nLanes);
        for (pairMotion& p : P)
        {
            p.ax1 = randomAxes(g, uniform(g, 0.5, 2), 5, false);
            p.ax2 = randomAxes(g, uniform(g, 0.5, 2), 5, true);
            p.R1 = randomRotation(g);
            p.u = randomUnit(g);
            // Turns per step from a settling bed's (1e-5 rad) to 0.02 rad
            p.w1 = logUniform(g, 1e-5, 0.02)*randomUnit(g);
            p.w2 = logUniform(g, 1e-5, 0.02)*randomUnit(g);
            p.v = uniform(g, 0, 2e-5)*randomUnit(g);
            p.cMin = std::min(cmptMin(p.ax1), cmptMin(p.ax2));
            const body b0(p.ax1, point::zero, p.R1);
            const knownContact k =
                makeContact(b0, p.ax2, randomRotation(g), p.u, 0, false);
            p.touching = k.b2.c;
            p.R2 = k.b2.R;
        }

        for (int step = -20; step <= 20; ++step)
        {
            std::vector<ellipsoid> e1, e2;
            std::vector<vector> start(nLanes);
            label nSet = 0;
            std::vector<int> lane(nLanes, -1);
            for (int l = 0; l < nLanes; ++l)
            {
                pairMotion& p = P[l];
                // Depth 2e-3 cMin at the middle, apart at the ends
                const double depth = p.cMin*(2e-3 - 2e-4*std::abs(step));
                const vector r1 = step*p.w1, r2 = step*p.w2;
                const tensor Q1 =
                    step == 0 ? tensor::I : quaternion(r1/mag(r1), mag(r1)).R();
                const tensor Q2 =
                    step == 0 ? tensor::I : quaternion(r2/mag(r2), mag(r2)).R();
                e1.push_back(ellipsoid(p.ax1, step*p.v, Q1 & p.R1));
                e2.push_back
                (
                    ellipsoid(p.ax2, p.touching - depth*p.u, Q2 & p.R2)
                );
                start[l] = p.n + p.dn;
                // A lasting contact with a tracked direction goes in a lane
                if (p.inContact && magSqr(p.n) > 0 && magSqr(start[l]) > 0)
                {
                    batch.setLane(nSet, e1[l], e2[l], start[l]);
                    lane[l] = nSet++;
                }
            }
            if (nSet > 0)
            {
                batch.evaluate(nSet);
            }
            for (int l = 0; l < nLanes; ++l)
            {
                pairMotion& p = P[l];
                vector nTrack = start[l];
                const ellipsoidContact::result c =
                    ellipsoidContact::contact(e1[l], e2[l], nTrack);
                if (lane[l] >= 0)
                {
                    ++nLasting;
                    ++nIterations[std::min<label>(c.iterations, 5)];
                    if (batch.decided(lane[l]))
                    {
                        ++nDecided;
                        const ellipsoidContact::result b = batch.contact(lane[l]);
                        nDiffer += !sameResult(b, c) || !sameBits(b.n, nTrack);
                        // A decided lane is a converged contact
                        nWrongDecided += !(c.contact && c.converged);
                    }
                }
                // EllipsoidCollision::listPairGeometry's tracking
                const bool lasting =
                    p.inContact && c.contact && c.overlap > 0 && c.converged
                 && magSqr(p.n) > 0 && magSqr(nTrack) > 0;
                p.dn = lasting ? nTrack - p.n : vector(Zero);
                p.n = nTrack;
                p.inContact = c.contact && c.overlap > 0;
            }
        }
    }
    std::cout
        << "  Batch: " << nLasting << " lasting contacts, " << nDecided
        << " decided in the lanes, " << nDiffer << " differ from the scalar path"
        << std::endl;
    std::cout << "  Newton iterations of the scalar path 0..5+:";
    for (const label n : nIterations) std::cout << " " << n;
    std::cout << std::endl;
    EXPECT_EQ(nDiffer, 0);
    EXPECT_EQ(nWrongDecided, 0);
    EXPECT_GT(nLasting, 5000);
    EXPECT_GT(nDecided, nLasting/2);
}


TEST(ellipsoidContact, SeparationCertificateHoldsWhileTheBodiesTravelLess)
{
    // Pairs put apart by a known gap (1e-6..1e-1 of the minor semi-axis),
    // the narrow phase started from a perturbed normal or the centre line.
    // A returned separation s must be a lower bound of the gap along the
    // returned direction (the depth along it, evaluated here with Eigen)
    // and close to it; then both bodies move and turn with |dc| + a theta
    // summed over both just below s (the translations closing the gap
    // along that direction, the turns about random axes; in half of the
    // pairs translations alone, which close the gap by exactly their
    // length): the pair must still be separated along it
    rng_t g(91);
    int nCertified = 0, nBound = 0, nLoose = 0, nClosed = 0;
    for (int pair = 0; pair < 4000; ++pair)
    {
        const vector ax1 = randomAxes(g, 1, 5, false);
        const vector ax2 = randomAxes(g, uniform(g, 0.5, 2), 5, false);
        const double cMin = std::min(cmptMin(ax1), cmptMin(ax2));
        const body b1(ax1, toF(Vector3d::Random()), randomRotation(g));
        const double gap = cMin*logUniform(g, 1e-6, 1e-1);
        const knownContact k =
            makeContact(b1, ax2, randomRotation(g), randomUnit(g), -gap, true);
        const ellipsoid e1 = k.b1.shape(), e2 = k.b2.shape();
        vector nTrack =
            pair % 2
          ? vector(Zero)
          : toF(k.n) + uniform(g, 0, 0.3)*randomUnit(g);
        const ellipsoidContact::result r =
            ellipsoidContact::contact(e1, e2, nTrack);
        ASSERT_FALSE(r.contact);
        if (!(r.separation > 0))
        {
            continue;
        }
        ++nCertified;
        const Vector3d m = toE(nTrack);
        const double L = k.b1.maxAxis() + k.b2.maxAxis() + 2;
        const double gapAlong = -depthAlong(k.b1, k.b2, m);
        if (r.separation > gapAlong) ++nBound;
        if (r.separation < gapAlong - 1e-13*L) ++nLoose;

        // Travel just below s, split at random over the four motions
        const bool translationsOnly = (pair/2) % 2;
        double w[4], sum = 0;
        for (int i = 0; i < 4; ++i)
        {
            w[i] = translationsOnly && i >= 2 ? 0 : uniform(g);
            sum += w[i];
        }
        const double T = (1 - 1e-6)*r.separation;
        auto turned = [&](const body& b, const double share)
        {
            const double theta = share*T/b.maxAxis();
            return quaternion(randomUnit(g), theta).R() & b.R;
        };
        const body moved1
        (
            k.b1.ax, k.b1.c + (w[0]/sum*T)*nTrack, turned(k.b1, w[2]/sum)
        );
        const body moved2
        (
            k.b2.ax, k.b2.c - (w[1]/sum*T)*nTrack, turned(k.b2, w[3]/sum)
        );
        if (!(depthAlong(moved1, moved2, m) < 0)) ++nClosed;
    }
    std::cout
        << "  Separation certificate: " << nCertified << " certified of 4000,"
        << " above the gap " << nBound << ", loose " << nLoose
        << ", closed by a smaller travel " << nClosed << std::endl;
    EXPECT_GT(nCertified, 3000);
    EXPECT_EQ(nBound, 0);
    EXPECT_EQ(nLoose, 0);
    EXPECT_EQ(nClosed, 0);
}


TEST(ellipsoidContact, SpheresFastPathIsAnalytic)
{
    rng_t g(3);
    for (int i = 0; i < 1000; ++i)
    {
        const double r1 = uniform(g, 0.1, 2), r2 = uniform(g, 0.1, 2);
        const point c1 = toF(10*Vector3d::Random());
        const vector u = randomUnit(g);
        const double ov = (r1 + r2)*logUniform(g, 1e-9, 0.5);
        const point c2 = c1 + (r1 + r2 - ov)*u;

        const ellipsoid e1(r1, c1), e2(vector(r2, r2, r2), c2, randomRotation(g));
        const ellipsoidContact::result r = ellipsoidContact::contact(e1, e2);

        // Analytic contact, from the computed centres
        const vector d = c2 - c1;
        const vector n = d/mag(d);
        const double scale = mag(c1) + mag(c2) + r1 + r2;
        ASSERT_TRUE(r.contact);
        EXPECT_EQ(r.used, ellipsoidContact::method::sphere);
        EXPECT_LT(mag(r.n - n), 4e-16);
        EXPECT_LT(mag(r.x1 - (c1 + r1*n)), 4e-16*scale);
        EXPECT_LT(mag(r.x2 - (c2 - r2*n)), 4e-16*scale);
        EXPECT_NEAR(r.overlap, r1 + r2 - mag(d), 4e-16*scale);
        EXPECT_NEAR(r.reducedRadius, r1*r2/(r1 + r2), 1e-15*r1);

        // The general methods agree on spheres
        const ellipsoidContact::result rr =
            ellipsoidContact::contact(e1, e2, ellipsoidContact::method::robust);
        EXPECT_LT(mag(rr.n - n), 1e-12);
        EXPECT_NEAR(rr.overlap, r.overlap, 1e-12*scale);
        EXPECT_NEAR(rr.reducedRadius, r.reducedRadius, 1e-12*r1);
        const ellipsoidContact::result rp =
            ellipsoidContact::contact(e1, e2, ellipsoidContact::method::polynomial);
        EXPECT_TRUE(rp.converged);
        EXPECT_LT(mag(rp.n - n), 1e-8);
        EXPECT_NEAR(rp.overlap, r.overlap, 1e-8*scale);

        // Separated: no contact
        const ellipsoid e3(r2, c1 + (r1 + r2 + ov)*u);
        EXPECT_FALSE(ellipsoidContact::contact(e1, e3).contact);
        EXPECT_FALSE(ellipsoidContact::intersect(e1, e3));
    }
}


TEST(ellipsoidContact, EllipsoidPlaneIsTheSupportPoint)
{
    rng_t g(5);
    for (int i = 0; i < 200; ++i)
    {
        const vector ax = randomAxes(g, uniform(g, 0.2, 1), 10, true);
        const tensor R = randomRotation(g);
        const point c = toF(Vector3d::Random());
        const vector nOut = randomUnit(g);
        const double h = uniform(g, -1, 1)*cmptMax(ax);
        const point p0 = c - h*nOut + 0.3*(randomUnit(g) ^ nOut);
        const ellipsoid e(ax, c, R);

        // Analytic support point in the body frame: the point of the
        // surface x^2/a^2 + ... = 1 with normal along m = -R^T nOut is
        // x_i = a_i^2 m_i/sqrt(sum a_j^2 m_j^2)
        const vector m = -(R.T() & nOut);
        const vector am(sqr(ax.x())*m.x(), sqr(ax.y())*m.y(), sqr(ax.z())*m.z());
        const point xs = c + (R & (am/std::sqrt(am & m)));
        const double depth = (p0 - xs) & nOut;

        const ellipsoidContact::result r = ellipsoidContact::ellipsoidPlane(e, p0, nOut);
        const double L = mag(c) + cmptMax(ax);
        EXPECT_LT(mag(r.x1 - xs), 1e-14*L);
        EXPECT_EQ(r.contact, depth > 0);
        EXPECT_NEAR(r.overlap, std::max(depth, 0.0), 1e-14*L);
        EXPECT_LT(mag(r.n + nOut), 1e-15);
        if (r.contact)
        {
            EXPECT_NEAR((r.x2 - p0) & nOut, 0, 1e-14*L);
            EXPECT_NEAR(r.reducedRadius*e.curvature(xs), 1, 1e-12);
        }

        // No sampled surface point lies deeper
        double lowest = GREAT;
        for (int k = 0; k < 4000; ++k)
        {
            const vector s = randomUnit(g);
            const point x = c + (R & vector(cmptMultiply(ax, s)));
            lowest = std::min(lowest, (x - p0) & nOut);
        }
        EXPECT_GE(lowest, ((xs - p0) & nOut) - 1e-14*L);
    }

    // Sphere on a plane: overlap r - height, contact point c - r n, R = r
    const ellipsoid s(0.5, point(1, 2, 0.45));
    const ellipsoidContact::result r =
        ellipsoidContact::ellipsoidPlane(s, point(7, -3, 0), vector(0, 0, 1));
    EXPECT_TRUE(r.contact);
    EXPECT_NEAR(r.overlap, 0.05, 1e-15);
    EXPECT_LT(mag(r.x1 - point(1, 2, -0.05)), 1e-15);
    EXPECT_LT(mag(r.x2 - point(1, 2, 0)), 1e-15);
    EXPECT_NEAR(r.reducedRadius, 0.5, 1e-15);
    const ellipsoidContact::result r2 =
        ellipsoidContact::ellipsoidPlane(s, point(7, -3, -0.06), vector(0, 0, 1));
    EXPECT_FALSE(r2.contact);
    EXPECT_EQ(r2.overlap, 0);

    // Prolate spheroid standing on its a-tip: R = b^2/a
    const double a = 3, b = 0.5;
    const ellipsoid p(vector(a, b, b), point(0, 0, a - 1e-3), quaternion(vector(0, 1, 0), pi/2));
    const ellipsoidContact::result rp =
        ellipsoidContact::ellipsoidPlane(p, point::zero, vector(0, 0, 1));
    EXPECT_NEAR(rp.overlap, 1e-3, 1e-14);
    EXPECT_NEAR(rp.reducedRadius, b*b/a, 1e-13);
}


TEST(ellipsoidContact, CurvatureEq37IsTheMeanCurvature)
{
    // Principal curvatures from the shape operator of the implicit surface
    // F = x^T A x - 1: W = P Hess(F) P/|grad F| on the tangent plane
    rng_t g(11);
    double maxVsGaussRoot = 0;
    for (int i = 0; i < 500; ++i)
    {
        const vector ax = randomAxes(g, uniform(g, 0.2, 2), 10, true);
        const body b(ax, toF(Vector3d::Random()), randomRotation(g));
        const ellipsoid e = b.shape();

        // Random surface point
        const vector s = randomUnit(g);
        const Vector3d y = toE(b.R & vector(cmptMultiply(ax, s)));
        const Vector3d gradF = 2*b.A*y;
        const Vector3d nn = gradF.normalized();
        const Matrix3d P = Matrix3d::Identity() - nn*nn.transpose();
        const Matrix3d W = P*(2*b.A)*P/gradF.norm();
        Eigen::SelfAdjointEigenSolver<Matrix3d> es(W);
        // Eigenvalues: 0 (normal) and k1, k2 (> 0 for the outward normal)
        Vector3d ev = es.eigenvalues();
        std::sort(ev.data(), ev.data() + 3);
        const double k1 = ev(1), k2 = ev(2);
        ASSERT_NEAR(ev(0), 0, 1e-10*k2);

        const point x = b.c + toF(y);
        const double K = e.curvature(x);
        EXPECT_NEAR(K, 0.5*(k1 + k2), 1e-10*k2) << "Eq. (37) is not the mean curvature";
        EXPECT_NEAR(e.gaussianCurvature(x), k1*k2, 1e-10*k2*k2);
        // No radius of curvature below c^2/a (the certified single start
        // of the contact relies on it)
        EXPECT_LE(k2*e.minRadiusOfCurvature(), 1 + 1e-10);
        maxVsGaussRoot = std::max(maxVsGaussRoot, std::abs(K/std::sqrt(k1*k2) - 1));
    }
    // ... and not the (root of the) Gaussian curvature
    EXPECT_GT(maxVsGaussRoot, 0.5);

    // Dimension 1/length: scaling the ellipsoid by 2 halves K
    const ellipsoid e1(vector(3, 2, 1), point::zero), e2(vector(6, 4, 2), point::zero);
    EXPECT_NEAR(e2.curvature(point(2*1.2, 2*1.1, 2*0.3))*2,
                e1.curvature(point(1.2, 1.1, 0.3)), 1e-14);

    // Tips of spheroids: analytic principal radii
    const double a = 3, c = 0.7;
    const ellipsoid prolate(vector(a, c, c), point(1, 2, 3));
    EXPECT_NEAR(1/prolate.curvature(point(1 + a, 2, 3)), c*c/a, 1e-14);      // a-tip: R = b^2/a twice
    EXPECT_NEAR(prolate.minRadiusOfCurvature(), c*c/a, 1e-15);
    EXPECT_NEAR(ellipsoid(vector(0.5, 2, 1), point::zero).minRadiusOfCurvature(), 0.125, 1e-15);
    EXPECT_NEAR(prolate.curvature(point(1, 2 + c, 3)), 0.5*(c/(a*a) + 1/c), 1e-14); // equator
    const ellipsoid oblate(vector(a, a, c), point::zero);
    EXPECT_NEAR(1/oblate.curvature(point(0, 0, c)), a*a/c, 1e-12);          // pole
    EXPECT_NEAR(oblate.curvature(point(a, 0, 0)), 0.5*(a/(c*c) + 1/a), 1e-14); // rim

    // Reduced radius of two identical prolate spheroids tip to tip:
    // 1/(2 a/c^2)
    const ellipsoid t1(vector(a, c, c), point::zero);
    const ellipsoid t2(vector(a, c, c), point(2*a - 1e-4, 0, 0));
    const ellipsoidContact::result r = ellipsoidContact::contact(t1, t2);
    EXPECT_NEAR(r.overlap, 1e-4, 1e-13);
    EXPECT_NEAR(r.reducedRadius, c*c/(2*a), 1e-12);
}


TEST(ellipsoidContact, ShellInflationShiftsTouchingDistance)
{
    // Ruan Eq. (41): spheres of radii r1, r2 with the collision shells
    // inflated by deltaBl touch at r1 + r2 + 2 deltaBl
    const double r1 = 1, r2 = 0.4, dBl = 0.05;
    const ellipsoid s1(r1, point(0.2, -0.1, 0.3)), s2Far(r2, point::zero);
    const vector u = vector(1, 2, -2)/3;
    const double touch = r1 + r2 + 2*dBl;

    for (const double eps : {1e-3, 1e-7, 1e-10})
    {
        const ellipsoid inside(r2, s1.centre() + (touch - eps)*u);
        const ellipsoid outside(r2, s1.centre() + (touch + eps)*u);

        EXPECT_TRUE(ellipsoidContact::intersect(s1.inflated(dBl), inside.inflated(dBl)));
        EXPECT_FALSE(ellipsoidContact::intersect(s1.inflated(dBl), outside.inflated(dBl)));
        EXPECT_FALSE(ellipsoidContact::intersect(s1, inside));  // true surfaces apart

        const ellipsoidContact::result r =
            ellipsoidContact::contact(s1.inflated(dBl), inside.inflated(dBl));
        EXPECT_TRUE(r.contact);
        EXPECT_NEAR(r.overlap, eps, 1e-14);
        EXPECT_LT(mag(r.x1 - (s1.centre() + (r1 + dBl)*u)), 1e-14);
        EXPECT_NEAR(r.reducedRadius, (r1 + dBl)*(r2 + dBl)/(r1 + r2 + 2*dBl), 1e-14);

        // The general path on the same shells
        const ellipsoidContact::result rr = ellipsoidContact::contact
        (
            s1.inflated(dBl), inside.inflated(dBl), ellipsoidContact::method::robust
        );
        EXPECT_NEAR(rr.overlap, eps, 1e-13);
        EXPECT_FALSE
        (
            ellipsoidContact::contact
            (
                s1.inflated(dBl), outside.inflated(dBl),
                ellipsoidContact::method::robust
            ).contact
        );
    }

    // The characteristic matrix of Eq. (41): diag(1/(a+d)^2, .., -1) at the
    // origin in the body frame, and X^T Q X = P(x) of the shell anywhere
    const ellipsoid e(vector(2, 1, 0.5), point::zero);
    const SquareMatrix<scalar> Q = e.characteristicMatrix(dBl);
    EXPECT_NEAR(Q(0, 0), 1/sqr(2 + dBl), 1e-15);
    EXPECT_NEAR(Q(1, 1), 1/sqr(1 + dBl), 1e-15);
    EXPECT_NEAR(Q(2, 2), 1/sqr(0.5 + dBl), 1e-15);
    EXPECT_EQ(Q(3, 3), -1);
    EXPECT_EQ(Q(0, 1), 0);
    EXPECT_EQ(Q(2, 3), 0);

    rng_t g(17);
    const ellipsoid f(vector(2, 1, 0.5), point(1, -2, 3), randomRotation(g));
    const SquareMatrix<scalar> Qf = f.characteristicMatrix(dBl);
    const ellipsoid shell = f.inflated(dBl);
    for (int i = 0; i < 20; ++i)
    {
        const point x = f.centre() + toF(3*Vector3d::Random());
        const double X[4] = {x.x(), x.y(), x.z(), 1};
        double q = 0;
        for (int k = 0; k < 4; ++k)
            for (int l = 0; l < 4; ++l)
                q += X[k]*Qf(k, l)*X[l];
        EXPECT_NEAR(q, shell.level(x), 1e-12*(1 + mag(shell.level(x))));
    }
}


TEST(ellipsoidContact, ContainmentIsAnOverlap)
{
    // One ellipsoid inside the other: all eigenvalues of Q1^-1 Q2 are real
    // (no complex pair), the Wang-Wang-Kim criterion still reports overlap
    const ellipsoid big(vector(3, 2, 2), point::zero);
    const ellipsoid small(vector(0.5, 0.3, 0.2), point(0.5, 0.2, 0), quaternion(vector(1, 1, 0)/std::sqrt(2.0), 0.3));
    EXPECT_TRUE(ellipsoidContact::intersect(big, small));
    EXPECT_TRUE(ellipsoidContact::intersect(small, big));
    const ellipsoidContact::result r = ellipsoidContact::contact(big, small);
    EXPECT_TRUE(r.contact);
    EXPECT_TRUE(r.converged);
    EXPECT_GT(r.overlap, 0.5);
}


// Rotation by the angle |a| about the axis a (Rodrigues)
tensor rotationBy(const vector& a)
{
    const double t = mag(a);
    if (t == 0) return tensor::I;
    const vector k = a/t;
    const tensor K(0, -k.z(), k.y(), k.z(), 0, -k.x(), -k.y(), k.x(), 0);
    return tensor::I + std::sin(t)*K + (1 - std::cos(t))*(K & K);
}


TEST(ellipsoidContact, ReducedRadiusGradientMatchesFiniteDifferences)
{
    // gradR against central differences of the reduced radius that the
    // contact reports (Eq. 37 at the common-normal points): moving each
    // centre along x, y, z and turning each body about x, y, z through its
    // centre. Also: the gradient carries no net force or torque (R is
    // invariant under rigid motions of the pair)
    rng_t g(31);
    double worst = 0, worstInvariance = 0, worstPlane = 0;
    int nPairs = 0;
    for (int i = 0; i < 200; ++i)
    {
        const body b1(randomAxes(g, 1, 10, false), toF(Vector3d::Random()), randomRotation(g));
        const vector ax2 = randomAxes(g, 1, 10, false);
        const knownContact k = makeContact
        (
            b1, ax2, randomRotation(g), randomUnit(g), logUniform(g, 1e-4, 1e-1), false
        );
        const ellipsoid e1 = k.b1.shape(), e2 = k.b2.shape();
        const ellipsoidContact::result r = ellipsoidContact::contact(e1, e2);
        ASSERT_TRUE(r.contact && r.converged);
        ASSERT_EQ(r.used, ellipsoidContact::method::robust);
        ++nPairs;

        // R of a moved configuration (Newton from the current normal)
        auto R = [&](const int body, const bool rotate, const vector& step)
        {
            const ellipsoid& e = body == 1 ? e1 : e2;
            const ellipsoid moved =
                rotate
              ? e.moved(e.centre(), rotationBy(step) & e.R())
              : e.moved(e.centre() + step, e.R());
            const ellipsoidContact::result rm =
                body == 1
              ? ellipsoidContact::robustMethod(moved, e2, r.n)
              : ellipsoidContact::robustMethod(e1, moved, r.n);
            return rm.reducedRadius;
        };

        const double L = std::min(e1.minSemiAxis(), e2.minSemiAxis());
        vector numeric[4] = {Zero, Zero, Zero, Zero};
        for (int b = 1; b <= 2; ++b)
        {
            for (int rot = 0; rot <= 1; ++rot)
            {
                const double h = rot ? 1e-5 : 1e-5*L;
                for (direction d = 0; d < 3; ++d)
                {
                    vector e(Zero);
                    e[d] = h;
                    numeric[2*(b - 1) + rot][d] =
                        (R(b, rot, e) - R(b, rot, -e))/(2*h);
                }
            }
        }
        const vector analytic[4] =
        {
            r.gradR.centre1, r.gradR.rotation1, r.gradR.centre2, r.gradR.rotation2
        };
        const double Rr = r.reducedRadius;
        for (int m = 0; m < 4; ++m)
        {
            // Scale: R/L per unit length, R per radian
            const double scale = (m % 2 == 0) ? Rr/L : Rr;
            worst = std::max(worst, mag(analytic[m] - numeric[m])/scale);
        }
        const vector netForce = r.gradR.centre1 + r.gradR.centre2;
        const vector netTorque =
            r.gradR.rotation1 + r.gradR.rotation2
          + (e1.centre() ^ r.gradR.centre1) + (e2.centre() ^ r.gradR.centre2);
        worstInvariance = std::max
        (
            worstInvariance, (mag(netForce)/(Rr/L) + mag(netTorque)/Rr)
        );
    }

    // Ellipsoid on a plane: only turning the ellipsoid moves R
    for (int i = 0; i < 200; ++i)
    {
        const vector ax = randomAxes(g, 1, 10, false);
        const point c = toF(Vector3d::Random());
        const vector nOut = randomUnit(g);
        const ellipsoid e(ax, c, randomRotation(g));
        const point p0 = c - (e.supportDistance(nOut) - 1e-2)*nOut;
        const ellipsoidContact::result r = ellipsoidContact::ellipsoidPlane(e, p0, nOut);
        ASSERT_TRUE(r.contact);
        vector numeric(Zero);
        const double h = 1e-5;
        for (direction d = 0; d < 3; ++d)
        {
            vector a(Zero);
            a[d] = h;
            const ellipsoid ep = e.moved(c, rotationBy(a) & e.R());
            const ellipsoid em = e.moved(c, rotationBy(-a) & e.R());
            numeric[d] =
            (
                ellipsoidContact::ellipsoidPlane(ep, p0, nOut).reducedRadius
              - ellipsoidContact::ellipsoidPlane(em, p0, nOut).reducedRadius
            )/(2*h);
        }
        worstPlane = std::max
        (
            worstPlane, mag(r.gradR.rotation1 - numeric)/r.reducedRadius
        );
        EXPECT_EQ(r.gradR.centre1, vector::zero);
    }

    std::cout
        << "    gradR vs central differences (" << nPairs << " pairs, 200 on"
        << " a plane): max error " << std::scientific << std::setprecision(2)
        << worst << " (pairs), " << worstPlane << " (plane) of R/L, R;"
        << " net force + torque " << worstInvariance << std::endl;
    EXPECT_LT(worst, 1e-6);
    EXPECT_LT(worstPlane, 1e-6);
    EXPECT_LT(worstInvariance, 1e-9);
}


TEST(ellipsoidContact, SymmetryOfThePair)
{
    // Swapping the bodies swaps the points and flips the normal
    rng_t g(23);
    for (int i = 0; i < 200; ++i)
    {
        const body b1(randomAxes(g, 1, 10, false), point::zero, randomRotation(g));
        const vector ax2 = randomAxes(g, 1, 10, false);
        const knownContact k = makeContact
        (
            b1, ax2, randomRotation(g), randomUnit(g), logUniform(g, 1e-6, 1e-2), false
        );
        const ellipsoid e1 = k.b1.shape(), e2 = k.b2.shape();
        const ellipsoidContact::result r12 = ellipsoidContact::contact(e1, e2);
        const ellipsoidContact::result r21 = ellipsoidContact::contact(e2, e1);
        EXPECT_LT(mag(r12.x1 - r21.x2), 1e-9);
        EXPECT_LT(mag(r12.n + r21.n), 1e-9);
        EXPECT_NEAR(r12.overlap, r21.overlap, 1e-12);
    }
}


TEST(ellipsoidContact, BadInputIsAnError)
{
    FatalError.throwExceptions();
    const scalar nan = std::numeric_limits<scalar>::quiet_NaN();
    EXPECT_THROW(ellipsoid(vector(1, 0, 1), point::zero), Foam::error);
    EXPECT_THROW(ellipsoid(vector(1, -1, 1), point::zero), Foam::error);
    EXPECT_THROW(ellipsoid(vector(1, nan, 1), point::zero), Foam::error);
    EXPECT_THROW(ellipsoid(vector(1, 1, 1), point(0, nan, 0)), Foam::error);
    EXPECT_THROW(ellipsoid(0, point::zero), Foam::error);
    EXPECT_THROW(ellipsoid(vector(1, 2, 3), point::zero, tensor(1, 0, 0, 0, 1, 0, 0, 0, 1.1)), Foam::error);
    EXPECT_THROW(ellipsoid(vector(1, 2, 3), point::zero, tensor(-1, 0, 0, 0, 1, 0, 0, 0, 1)), Foam::error);
    EXPECT_THROW(ellipsoid(vector(1, 2, 3), point::zero, quaternion(0, vector::zero)), Foam::error);

    const ellipsoid e(vector(1, 2, 3), point::zero);
    const ellipsoid s(1, point(1, 0, 0));
    EXPECT_THROW(e.inflated(-0.1), Foam::error);
    EXPECT_THROW(e.inflated(nan), Foam::error);
    EXPECT_THROW(e.curvature(point::zero), Foam::error);
    EXPECT_THROW(e.normal(point::zero), Foam::error);
    EXPECT_THROW(ellipsoidContact::ellipsoidPlane(e, point::zero, vector(0, 0, 2)), Foam::error);
    EXPECT_THROW(ellipsoidContact::ellipsoidPlane(e, point::zero, vector(0, nan, 1)), Foam::error);
    EXPECT_THROW(ellipsoidContact::ellipsoidPlane(e, point(nan, 0, 0), vector(0, 0, 1)), Foam::error);
    EXPECT_THROW(ellipsoidContact::sphereSphere(e, s), Foam::error);
    EXPECT_THROW(ellipsoidContact::contact(e, s, ellipsoidContact::method::plane), Foam::error);
    FatalError.dontThrowExceptions();

    // A slightly drifted quaternion is normalised, not an error
    const ellipsoid d(vector(1, 2, 3), point::zero, quaternion(1.01, vector(0, 0, 0)));
    EXPECT_LT(mag(d.R() - tensor::I), 1e-15);
}


int main(int argc, char** argv)
{
    ::testing::InitGoogleTest(&argc, argv);
    return RUN_ALL_TESTS();
}


// ************************************************************************* //


TEST(ellipsoid, RotationOfUnitAndDriftedQuaternions)
{
    // ellipsoid::rotation normalises its quaternion: by a Newton step
    // within 1e-8 of unit length (a parcel's), else by |q|. Both against
    // the rotation of the quaternion normalised in long double: a few
    // ulps, on both sides of the threshold and far from it
    rng_t g(11);
    std::uniform_real_distribution<double> U(-1, 1);
    scalar worst = 0;
    for (const scalar drift : {0.0, 1e-16, 1e-12, 4.9e-9, 5.1e-9, 1e-6, 0.3, 7.0})
    {
        for (label i = 0; i < 1000; ++i)
        {
            const quaternion q(U(g), vector(U(g), U(g), U(g)));
            const long double m = std::sqrt
            (
                (long double)q.w()*q.w() + (long double)q.v().x()*q.v().x()
              + (long double)q.v().y()*q.v().y()
              + (long double)q.v().z()*q.v().z()
            );
            if (m < 0.1)
            {
                continue;
            }
            // |q|^2 = 1 + drift to round-off
            const long double s = std::sqrt(1 + (long double)drift)/m;
            const quaternion qd
            (
                double(s*q.w()),
                vector(double(s*q.v().x()), double(s*q.v().y()), double(s*q.v().z()))
            );
            const quaternion unit
            (
                double(q.w()/m),
                vector(double(q.v().x()/m), double(q.v().y()/m), double(q.v().z()/m))
            );
            const tensor R = ellipsoid::rotation(qd);
            worst = max(worst, cmptMax(cmptMag(R - unit.R())));
            EXPECT_LT(cmptMax(cmptMag((R & R.T()) - tensor::I)), 2e-15);
        }
    }
    std::cout << "[ measured ] ellipsoid::rotation of unit and drifted"
        << " quaternions: largest difference " << worst << std::endl;
    EXPECT_LT(worst, 2e-15);
}


TEST(ellipsoid, SurfaceAreaAgainstClosedFormsAndQuadrature)
{
    const scalar pi = constant::mathematical::pi;

    // Sphere
    EXPECT_NEAR(ellipsoid::surfaceArea(vector(2, 2, 2))/(16*pi), 1, 1e-14);

    // Prolate spheroid a > b = c: 2 pi b^2 (1 + a/(b e) asin e)
    {
        const scalar a = 3, b = 1, e = Foam::sqrt(1 - sqr(b/a));
        const scalar S = 2*pi*sqr(b)*(1 + a/(b*e)*std::asin(e));
        EXPECT_NEAR(ellipsoid::surfaceArea(vector(b, a, b))/S, 1, 1e-12);
    }

    // Oblate spheroid a = b > c: 2 pi a^2 (1 + (1 - e^2)/e atanh e)
    {
        const scalar a = 2, c = 0.5, e = Foam::sqrt(1 - sqr(c/a));
        const scalar S = 2*pi*sqr(a)*(1 + (1 - sqr(e))/e*std::atanh(e));
        EXPECT_NEAR(ellipsoid::surfaceArea(vector(a, c, a))/S, 1, 1e-12);
    }

    // Triaxial: midpoint quadrature of |x_u ^ x_v| over the parametric
    // surface x = (a sin u cos v, b sin u sin v, c cos u)
    {
        const scalar a = 3, b = 2, c = 1;
        const label n = 2000;
        scalar S = 0;
        for (label i = 0; i < n; ++i)
        {
            const scalar u = pi*(i + 0.5)/n;
            for (label j = 0; j < 2*n; ++j)
            {
                const scalar v = pi*(j + 0.5)/n;
                const vector xu
                (
                    a*std::cos(u)*std::cos(v), b*std::cos(u)*std::sin(v), -c*std::sin(u)
                );
                const vector xv
                (
                    -a*std::sin(u)*std::sin(v), b*std::sin(u)*std::cos(v), 0
                );
                S += mag(xu ^ xv);
            }
        }
        S *= sqr(pi/n);
        EXPECT_NEAR(ellipsoid::surfaceArea(vector(c, a, b))/S, 1, 1e-6);
    }
}


// * * * * * * * * * * * * * * * Hertz onset * * * * * * * * * * * * * * * //

TEST(hertzOnset, HurwitzZetaAgainstMpmath)
{
    // zeta(-3/2, q), zeta(-5/2, q) from mpmath 1.3 (mpmath.zeta(s, q), 17
    // digits); q = 1: the Riemann values zeta(-3/2), zeta(-5/2)
    const scalar ref[7][3] =
    {
        {1e-6, -0.025485512719718134, 0.0085168650644568186},
        {0.1, -0.030681943042529056, 0.000943625820149835},
        {0.25, -0.015109295630837674, -0.0080380960820038427},
        {0.5, 0.016474822351728459, -0.0070113342544251243},
        {0.75, 0.020934024932713121, 0.0067986555828864603},
        {0.9, 0.00038795975130299785, 0.011436355745128029},
        {1.0, -0.025485201889833036, 0.008516928777850331}
    };
    for (const auto& r : ref)
    {
        const hertzOnset::zetaPair z = hertzOnset::hertzZeta(r[0]);
        EXPECT_NEAR(z.s32, r[1], 1e-12) << "q = " << r[0];
        EXPECT_NEAR(z.s52, r[2], 1e-12) << "q = " << r[0];
    }
    // zeta(s, 1/2) = (2^-s - 1) zeta(s)
    const hertzOnset::zetaPair h = hertzOnset::hertzZeta(0.5);
    const hertzOnset::zetaPair one = hertzOnset::hertzZeta(1);
    EXPECT_NEAR(h.s32, (std::pow(2, -1.5) - 1)*one.s32, 1e-12);
    EXPECT_NEAR(h.s52, (std::pow(2, -2.5) - 1)*one.s52, 1e-12);

    FatalError.throwExceptions();
    EXPECT_THROW(hertzOnset::hertzZeta(0), Foam::error);
    EXPECT_THROW(hertzOnset::hertzZeta(1.5), Foam::error);
}


TEST(hertzOnset, LeapfrogImpactConservesEnergy)
{
    // x'' = -x^3/2 for x > 0 (units of every head-on Hertz impact), kick-
    // drift-kick at t_c/N, over the phase of the first touch within a
    // step: the energy after the impact, plain and with the corrections
    // of the first and last step in contact
    auto impact = [](const label N, const scalar phase, const bool correct)
    {
        const scalar dt = 3.2187/N;
        scalar x = -phase*dt, v = 1, f = 0;
        bool touching = false;
        for (label i = 0; i < 3*N; ++i)
        {
            v += 0.5*dt*f;
            x += dt*v;
            f = 0;
            if (x > 0)
            {
                scalar d32 = x*std::sqrt(x);
                if (correct && !touching)
                {
                    d32 -= hertzOnset::onsetCorrection(x, v*dt).delta32;
                }
                const scalar vNext = v - dt*d32;
                if (correct && x + vNext*dt <= 0)
                {
                    d32 -= hertzOnset::onsetCorrection(x, -vNext*dt).delta32;
                }
                f = -d32;
            }
            touching = x > 0;
            v += 0.5*dt*f;
        }
        return mag(v*v - 1);
    };

    for (const label N : {label(50), label(100)})
    {
        scalar plain = 0, corrected = 0;
        for (label k = 0; k < 40; ++k)
        {
            plain = max(plain, impact(N, (k + 0.5)/40, false));
            corrected = max(corrected, impact(N, (k + 0.5)/40, true));
        }
        std::printf
        (
            "[ measured ] 1D Hertz impact, %d steps per collision: max"
            " |E/E0 - 1| plain %.2e, corrected %.2e\n",
            int(N), plain, corrected
        );
        EXPECT_LT(corrected, 1e-3*plain);
    }
}
