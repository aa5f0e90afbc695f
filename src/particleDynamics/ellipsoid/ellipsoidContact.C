/*---------------------------------------------------------------------------*\
    chargedFoam: charged dielectric particles for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "ellipsoidContact.H"
#include "error.H"
#include "Ostream.H"
#include "mathematicalConstants.H"

#include <array>
#include <cmath>
#include <limits>

// Eigen (a well-kept library) for the 4x4 non-symmetric eigenproblem of
// the intersection test and the roots of the sixth-order polynomial (the
// 2x2 Newton systems and Ruan's Eq. 30 are solved in closed form). Its
// headers are not written for OpenFOAM's warning set; GCC 12 also reports
// false "may be used uninitialized" inside Eigen's fixed-size
// Schur/Hessenberg code after inlining, which push/pop cannot scope: those
// two are off for this file.
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#pragma GCC diagnostic ignored "-Wuninitialized"
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wold-style-cast"
#pragma GCC diagnostic ignored "-Wshadow"
#pragma GCC diagnostic ignored "-Wdeprecated-copy"
#include <Eigen/Dense>
#include <unsupported/Eigen/Polynomials>
#pragma GCC diagnostic pop

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

using namespace Foam;
using ellipsoidContact::method;
using ellipsoidContact::radiusGradient;
using ellipsoidContact::result;

const scalar eps = std::numeric_limits<scalar>::epsilon();


// Unit vector along d, (1 0 0) for a zero d (coincident centres)
vector unitOrX(const vector& d)
{
    const scalar m = mag(d);
    return m > 0 ? d/m : vector(1, 0, 0);
}


// The no-contact result (see ellipsoidContact.H)
result noContact(const ellipsoid& e1, const ellipsoid& e2)
{
    result r;
    r.contact = false;
    r.x1 = e1.centre();
    r.x2 = e2.centre();
    r.n = unitOrX(e2.centre() - e1.centre());
    r.used = method::none;
    return r;
}


// Reduced radius R = 1/(K1 + K2), Ruan section 2.3.3 with K of Eq. (37)
scalar reducedRadius
(
    const ellipsoid& e1,
    const point& x1,
    const ellipsoid& e2,
    const point& x2
)
{
    return 1/(e1.curvature(x1) + e2.curvature(x2));
}


// Orthonormal tangent basis (t1, t2) of the unit vector m
void tangents(const vector& m, vector& t1, vector& t2)
{
    // The coordinate axis least aligned with m gives a well-conditioned t1
    const vector am(mag(m.x()), mag(m.y()), mag(m.z()));
    vector e(Zero);
    if (am.x() <= am.y() && am.x() <= am.z()) e.x() = 1;
    else if (am.y() <= am.z()) e.y() = 1;
    else e.z() = 1;

    t1 = e - (e & m)*m;
    t1 *= 1/mag(t1);
    t2 = m ^ t1;
}


// The tangent basis of a direction, kept where it was formed (the Newton
// iteration that converged) for the contact's curvatures at that direction
struct tangentFrame
{
    vector t1, t2;
    bool valid = false;
};


/*---------------------------------------------------------------------------*\
          Gradient of the reduced radius (see ellipsoidContact.H)
\*---------------------------------------------------------------------------*/

// S^-1 n, the support distance h = sqrt(n.S^-1 n) of e along the unit n
// and 1/h: what the curvature and its gradient need of the support point.
// The penetration depth's Newton state holds them for the common normal
// (depthFunction::state w, h, hInv: the same operations), so the
// contact's curvatures do not compute them again
struct supportAlong
{
    vector Mn;
    scalar h;
    scalar hInv;

    supportAlong(const vector& Mn, const scalar h, const scalar hInv)
    :
        Mn(Mn),
        h(h),
        hInv(hInv)
    {}

    supportAlong(const ellipsoid& e, const vector& n)
    :
        Mn(e.Sinv() & n),
        h(Foam::sqrt(n & Mn)),
        hInv(1/h)
    {}
};


// Mean curvature (Ruan Eq. 37) of e at its support point along the unit n,
// as a function of n: K(n) = h(n) (tr S - n.S n)/2, h = sqrt(n.S^-1 n).
// gradK: the tangential part of its gradient (of the extension
// h(n) (tr S |n|^2 - n.S n)/2; only tangential changes of n occur).
// K is even in n, so the same K and gradK serve the body whose support
// point is along -n.
void curvatureAlong
(
    const ellipsoid& e,
    const vector& n,
    const supportAlong& sup,
    scalar& K,
    vector& gradK
)
{
    const vector& Mn = sup.Mn;
    const vector Sn = e.S() & n;
    const scalar h = sup.h;
    const scalar trS = tr(e.S());
    const scalar tau = trS - (n & Sn);
    K = 0.5*h*tau;
    const vector g = (0.5*tau*sup.hInv)*Mn + h*(trS*n - Sn);
    gradK = g - (g & n)*n;
}


// Radii-of-curvature tensor D = grad grad h of e along the unit n,
// applied to t: (S^-1 t)/h - (S^-1 n)(S^-1 n . t)/h^3 (even in n);
// S^-1 n and 1/h from the body's supportAlong along n (products with the
// reciprocals: a division costs several multiplications, and D is
// applied four times per contact)
class radiiOfCurvature
{
    const symmTensor& Minv_;
    const vector& Mn_;
    const scalar hInv_;
    const scalar hInv3_;

public:

    radiiOfCurvature(const ellipsoid& e, const supportAlong& sup)
    :
        Minv_(e.Sinv()),
        Mn_(sup.Mn),
        hInv_(sup.hInv),
        hInv3_(sup.hInv*sup.hInv*sup.hInv)
    {}

    vector operator()(const vector& t) const
    {
        return (Minv_ & t)*hInv_ - Mn_*((Mn_ & t)*hInv3_);
    }
};


// gradR of a common-normal contact r (ellipsoidContact::
// reducedRadiusGradient, see ellipsoidContact.H) and the curvature sum
// K1 + K2 along its normal, with both bodies' support data along it (and
// the tangent basis of the normal where the caller has it)
radiusGradient radiusGradientAndCurvature
(
    const ellipsoid& e1,
    const ellipsoid& e2,
    const result& r,
    const supportAlong& sup1,
    const supportAlong& sup2,
    scalar& Ksum,
    const tangentFrame* frame = nullptr
)
{
    const vector& n = r.n;
    scalar K1, K2;
    vector gradK1, gradK2;
    curvatureAlong(e1, n, sup1, K1, gradK1);
    curvatureAlong(e2, n, sup2, K2, gradK2);
    Ksum = K1 + K2;
    const vector G = gradK1 + gradK2;

    // w = H^-1 G on the tangent plane, H = D1 + D2 - overlap P, in the
    // basis of n (the Newton iteration's where it formed it at n)
    vector t1, t2;
    if (frame && frame->valid)
    {
        t1 = frame->t1;
        t2 = frame->t2;
    }
    else
    {
        tangents(n, t1, t2);
    }
    // D is linear: D(w) below from D(t1), D(t2), as w lies in the
    // tangent plane (two mat-vecs fewer)
    const radiiOfCurvature D1(e1, sup1), D2(e2, sup2);
    const vector D1t1 = D1(t1), D1t2 = D1(t2), D2t1 = D2(t1), D2t2 = D2(t2);
    const vector Dt1 = D1t1 + D2t1;
    const vector Dt2 = D1t2 + D2t2;
    const scalar H11 = (t1 & Dt1) - r.overlap;
    const scalar H22 = (t2 & Dt2) - r.overlap;
    const scalar H12 = 0.5*((t1 & Dt2) + (t2 & Dt1));
    const scalar det = H11*H22 - H12*H12;

    radiusGradient d;
    if (!(det > 0) || !(H11 > 0))
    {
        // Not a strict minimum of the depth: the normal is not a smooth
        // function of the configuration here
        return d;
    }
    const scalar G1 = t1 & G, G2 = t2 & G;
    const scalar w1 = (H22*G1 - H12*G2)/det, w2 = (H11*G2 - H12*G1)/det;
    const vector w = w1*t1 + w2*t2;

    // R = 1/(K1 + K2) at the common-normal points (the contact's
    // reducedRadius, here from the same K(n) as its gradient)
    const scalar R2 = 1/sqr(K1 + K2);
    const vector r1 = r.x1 - e1.centre();
    const vector r2 = r.x2 - e2.centre();
    d.centre1 = R2*w;
    d.centre2 = -R2*w;
    d.rotation1 = -R2*((n ^ (w1*D1t1 + w2*D1t2)) - (r1 ^ w) - (n ^ gradK1));
    d.rotation2 = -R2*((n ^ (w1*D2t1 + w2*D2t2)) + (r2 ^ w) - (n ^ gradK2));
    return d;
}


/*---------------------------------------------------------------------------*\
                 Robust method: penetration depth along n
\*---------------------------------------------------------------------------*/

// g(n) = h1(n) + h2(n) - n.(c2 - c1), h the support functions; grad g =
// x1(n) - x2(n) (x1 support point of 1 along n, x2 of 2 along -n)
class depthFunction
{
    const symmTensor& M1_;
    const symmTensor& M2_;
    const vector d_;

public:

    // State at one direction
    struct state
    {
        vector m;           // unit direction
        vector w1, w2;      // M1 m, M2 m
        scalar h1, h2;      // support distances
        scalar hInv1, hInv2;    // their reciprocals, for the gradient and
                                // the Hessian: set by reciprocals(), not
                                // by eval() (most tracked pairs are
                                // decided by g alone); NaN until then, so
                                // a use before it fails loudly (sigFpe)
        scalar g;           // depth
    };

    depthFunction(const ellipsoid& e1, const ellipsoid& e2)
    :
        M1_(e1.Sinv()),
        M2_(e2.Sinv()),
        d_(e2.centre() - e1.centre())
    {}

    const vector& d() const
    {
        return d_;
    }

    state eval(const vector& m) const
    {
        state s;
        s.m = m;
        s.w1 = M1_ & m;
        s.w2 = M2_ & m;
        s.h1 = Foam::sqrt(m & s.w1);
        s.h2 = Foam::sqrt(m & s.w2);
        s.g = s.h1 + s.h2 - (m & d_);
        s.hInv1 = s.hInv2 = std::numeric_limits<scalar>::quiet_NaN();
        return s;
    }

    // 1/h1, 1/h2 of s: the gradient and the Hessian multiply by them (a
    // division costs several multiplications; a Newton iteration's
    // gradient and two Hessian products would divide 22 times)
    static void reciprocals(state& s)
    {
        s.hInv1 = 1/s.h1;
        s.hInv2 = 1/s.h2;
    }

    // grad g = x1 - x2 (relative to the centres: no large coordinates);
    // s with its reciprocals
    vector grad(const state& s) const
    {
        return s.w1*s.hInv1 + s.w2*s.hInv2 - d_;
    }

    // Euclidean Hessian of h1 + h2 applied to t:
    // (M t)/h - (M m)(M m . t)/h^3 for each body; s with its reciprocals
    vector hessian(const state& s, const vector& t) const
    {
        return
            (M1_ & t)*s.hInv1
          - s.w1*((s.w1 & t)*(s.hInv1*s.hInv1*s.hInv1))
          + (M2_ & t)*s.hInv2
          - s.w2*((s.w2 & t)*(s.hInv2*s.hInv2*s.hInv2));
    }
};


// Directions on the unit sphere for the start search (Fibonacci lattice:
// near-uniform, deterministic; 128 points, ~18 deg apart) with the
// nearest neighbours of each, to find the local minima of the sampled g
const label nSample = 128;
const label nNeighbour = 6;

struct sampleSet
{
    std::array<vector, nSample> dir;
    std::array<std::array<label, nNeighbour>, nSample> nbr;
};

const sampleSet& samples()
{
    // Thread-safe initialisation of a function-local static (C++11)
    static const sampleSet set = []()
    {
        sampleSet S;
        const scalar golden = constant::mathematical::pi*(3 - Foam::sqrt(5.0));
        for (label i = 0; i < nSample; ++i)
        {
            const scalar z = 1 - (2*i + 1)/scalar(nSample);
            const scalar r = Foam::sqrt(max(0.0, 1 - z*z));
            const scalar phi = golden*i;
            S.dir[i] = vector(r*Foam::cos(phi), r*Foam::sin(phi), z);
        }
        for (label i = 0; i < nSample; ++i)
        {
            // Insertion of the nNeighbour largest cosines
            scalar best[nNeighbour];
            for (label k = 0; k < nNeighbour; ++k)
            {
                best[k] = -2;
                S.nbr[i][k] = i;
            }
            for (label j = 0; j < nSample; ++j)
            {
                if (j == i) continue;
                const scalar c = S.dir[i] & S.dir[j];
                label k = nNeighbour;
                while (k > 0 && c > best[k - 1])
                {
                    if (k < nNeighbour)
                    {
                        best[k] = best[k - 1];
                        S.nbr[i][k] = S.nbr[i][k - 1];
                    }
                    --k;
                }
                if (k < nNeighbour)
                {
                    best[k] = c;
                    S.nbr[i][k] = j;
                }
            }
        }
        return S;
    }();
    return set;
}


// The Newton step (s1, s2) on the tangent plane (t1, t2) at s for the
// gradient (G1, G2), |G| = magG: the Riemannian Hessian, shifted
// (Levenberg-Marquardt, mu > 0) where not safely positive definite, the
// step limited to the trust radius maxStep (its length magS)
void newtonStep
(
    const depthFunction& f,
    const depthFunction::state& s,
    const vector& t1,
    const vector& t2,
    const scalar G1,
    const scalar G2,
    const scalar magG,
    const scalar L,
    const scalar maxStep,
    scalar& s1,
    scalar& s2,
    scalar& magS,
    scalar& mu
)
{
    // Riemannian Hessian on the sphere: projected Euclidean Hessian
    // minus (m . grad g) I = g I (g is 1-homogeneous). At the contact
    // it is R1 + R2 - overlap I (radii-of-curvature tensors).
    const vector Ht1 = f.hessian(s, t1);
    const vector Ht2 = f.hessian(s, t2);
    const scalar H11 = (t1 & Ht1) - s.g;
    const scalar H22 = (t2 & Ht2) - s.g;
    const scalar H12 = 0.5*((t1 & Ht2) + (t2 & Ht1));

    // Levenberg-Marquardt shift if not safely positive definite
    const scalar tr = 0.5*(H11 + H22);
    const scalar rad = Foam::sqrt(sqr(0.5*(H11 - H22)) + H12*H12);
    const scalar lMin = tr - rad, lMax = tr + rad;
    mu = 0;
    if (!(lMin > 1e-10*max(mag(lMax), L)))
    {
        mu = -lMin + 1e-3*max(mag(lMax), L);
    }

    const scalar A11 = H11 + mu, A22 = H22 + mu, detA = A11*A22 - H12*H12;
    s1 = -(A22*G1 - H12*G2)/detA;
    s2 = -(A11*G2 - H12*G1)/detA;
    magS = Foam::sqrt(s1*s1 + s2*s2);
    if (!std::isfinite(magS))
    {
        // Degenerate Hessian: steepest descent on the trust radius
        s1 = -G1/magG*maxStep;
        s2 = -G2/magG*maxStep;
        magS = maxStep;
        mu = 1;
    }
    if (magS > maxStep)
    {
        s1 *= maxStep/magS;
        s2 *= maxStep/magS;
        magS = maxStep;
    }
}


// Damped Newton minimisation of g on the unit sphere from the state s0
depthFunction::state newtonOnSphere
(
    const depthFunction& f,
    const depthFunction::state& s0,
    const scalar L,
    label& iterations,
    bool& converged,
    const bool stopWhenSeparated = false,
    tangentFrame* frame = nullptr
)
{
    // Tolerances: the tangential residual x1 - x2 is a difference of
    // lengths of size L, known to a few eps*L; a step of 1e-14 rad moves
    // the contact points by 1e-14 of their radius of curvature
    const scalar tolG = 64*eps*L;
    const scalar tolStep = 1e-14;
    const scalar maxStep = 0.5;     // trust radius [rad]
    const label maxIter = 60;

    depthFunction::state s = s0;
    converged = false;
    iterations = 0;
    if (frame)
    {
        frame->valid = false;
    }

    for (label iter = 0; iter < maxIter; ++iter)
    {
        // g < 0: n is a separating direction, the minimum is not needed
        if (stopWhenSeparated && s.g < 0)
        {
            break;
        }
        iterations = iter + 1;

        depthFunction::reciprocals(s);
        const vector grad = f.grad(s);
        vector t1, t2;
        tangents(s.m, t1, t2);
        const scalar G1 = t1 & grad, G2 = t2 & grad;
        const scalar magG = Foam::sqrt(G1*G1 + G2*G2);

        if (magG <= tolG)
        {
            converged = true;
            if (frame)
            {
                frame->t1 = t1;
                frame->t2 = t2;
                frame->valid = true;
            }
            break;
        }

        scalar s1, s2, magS, mu;
        newtonStep(f, s, t1, t2, G1, G2, magG, L, maxStep, s1, s2, magS, mu);

        // Pure Newton steps in the quadratic-convergence region are taken
        // whole: their decrease of g is below the round-off of g
        const vector step = s1*t1 + s2*t2;
        depthFunction::state trial;
        scalar alpha = 1;
        bool accepted = false;

        if (mu == 0 && magS < 1e-4)
        {
            const vector m = s.m + step;
            trial = f.eval(m*(1/mag(m)));
            accepted = true;
        }
        else
        {
            const scalar slope = G1*s1 + G2*s2;
            for (label k = 0; k < 50; ++k)
            {
                const vector m = s.m + alpha*step;
                trial = f.eval(m*(1/mag(m)));
                if (trial.g <= s.g + 1e-4*alpha*slope)
                {
                    accepted = true;
                    break;
                }
                alpha *= 0.5;
            }
        }

        if (!accepted)
        {
            // No representable decrease: g is flat to round-off here
            converged = (magG <= 1e-8*L);
            break;
        }

        s = trial;

        if (alpha*magS <= tolStep)
        {
            converged = true;
            break;
        }
    }

    return s;
}


// The contact result of the common normal s.m of (e1, e2)
result commonNormalResult
(
    const ellipsoid& e1,
    const ellipsoid& e2,
    const depthFunction::state& s,
    const label iterations,
    const bool converged,
    const tangentFrame& frame
)
{
    result r;
    r.contact = true;
    r.used = method::robust;
    r.iterations = iterations;
    r.converged = converged;
    r.n = s.m;
    // The converging iteration formed the reciprocals where it formed the
    // frame (depthFunction::reciprocals)
    const scalar hInv1 = frame.valid ? s.hInv1 : 1/s.h1;
    const scalar hInv2 = frame.valid ? s.hInv2 : 1/s.h2;
    r.x1 = e1.centre() + s.w1*hInv1;
    r.x2 = e2.centre() - s.w2*hInv2;

    // g = n.(x1 - x2) by 1-homogeneity, without the cancellation of
    // differencing two possibly large coordinates
    r.overlap = max(s.g, scalar(0));
    if (r.converged)
    {
        // R = 1/(K1 + K2) from the same K(n) as its gradient; the Newton
        // state holds S^-1 n and h of both bodies along n = s.m
        scalar Ksum;
        r.gradR = radiusGradientAndCurvature
        (
            e1, e2, r, supportAlong(s.w1, s.h1, hInv1),
            supportAlong(s.w2, s.h2, hInv2),
            Ksum, &frame
        );
        r.reducedRadius = 1/Ksum;
    }
    else
    {
        r.reducedRadius = reducedRadius(e1, r.x1, e2, r.x2);
    }
    return r;
}


// What one Newton run on g from nTrack (zero: the centre line) proves
// (see "Certified single start" in ellipsoidContact.H)
enum class certificate { separated, contact, undecided };

// A lower bound of the gap -g > 0 of a separating direction, less the
// round-off of g (a few eps of the lengths in it; see "Separation
// certificate" in ellipsoidContact.H)
scalar certifiedGap(const ellipsoid& e1, const ellipsoid& e2, const scalar g)
{
    const vector d = e2.centre() - e1.centre();
    const scalar L =
        e1.boundingRadius() + e2.boundingRadius()
      + mag(d.x()) + mag(d.y()) + mag(d.z());
    return max(-g - 64*eps*L, scalar(0));
}


// ellipsoidContactBatch.C repeats, in SIMD lanes, what this run does for a
// lasting contact started near its normal (the depth, pure Newton steps,
// the certificate, commonNormalResult with radiusGradientAndCurvature,
// curvatureAlong, tangents, depthFunction): a change here or there goes
// to both (the batch's unit tests compare them bit for bit)
certificate certifiedSingleStart
(
    const ellipsoid& e1,
    const ellipsoid& e2,
    vector& nTrack,
    result& r,
    scalar& g
)
{
    const depthFunction f(e1, e2);

    // Most tracked pairs within reach but apart are still separated along
    // the last step's direction: one evaluation decides them (g > 0 where
    // the centres coincide, so the order of the tests does not matter)
    const bool tracked = magSqr(nTrack) > 0;
    depthFunction::state s0;
    if (tracked)
    {
        s0 = f.eval(nTrack*(1/mag(nTrack)));
        if (s0.g < 0)
        {
            nTrack = s0.m;
            g = s0.g;
            return certificate::separated;
        }
    }

    const scalar dist = mag(f.d());
    if (!(dist > 0))
    {
        return certificate::undecided;
    }
    const scalar L = e1.boundingRadius() + e2.boundingRadius() + dist;
    if (!tracked)
    {
        const vector m0 = f.d()/dist;
        s0 = f.eval(m0/mag(m0));
    }

    label iters = 0;
    bool conv = false;
    tangentFrame frame;
    const depthFunction::state s =
        newtonOnSphere(f, s0, L, iters, conv, true, &frame);

    if (s.g < 0)
    {
        nTrack = s.m;
        g = s.g;
        return certificate::separated;
    }

    // A stationary depth below the radius of a ball that rolls inside the
    // Minkowski difference (Blaschke): no other direction is shallower.
    // The factor 0.9 covers the residual of the stationarity.
    const scalar rollingRadius =
        e1.minRadiusOfCurvature() + e2.minRadiusOfCurvature();
    if (conv && s.g > 0 && s.g < 0.9*rollingRadius)
    {
        r = commonNormalResult(e1, e2, s, iters, true, frame);
        nTrack = s.m;
        return certificate::contact;
    }
    nTrack = Zero;
    return certificate::undecided;
}


// The robust method without the intersection test
result robustCore
(
    const ellipsoid& e1,
    const ellipsoid& e2,
    const vector& nGuess
)
{
    const depthFunction f(e1, e2);
    const scalar L = e1.boundingRadius() + e2.boundingRadius() + mag(f.d());

    // Candidate starts: the caller's guess, the centre line and the local
    // minima of g over the sampled directions (lowest first): g can have
    // several local minima for deep overlaps of elongated bodies, and
    // Newton finds the one of the basin it starts in
    const sampleSet& S = samples();
    scalar gSample[nSample];
    for (label i = 0; i < nSample; ++i)
    {
        gSample[i] = f.eval(S.dir[i]).g;
    }

    const label maxMinima = 6;
    vector starts[maxMinima + 2];
    label nStarts = 0;

    if (magSqr(nGuess) > 0 && std::isfinite(magSqr(nGuess)))
    {
        starts[nStarts++] = nGuess/mag(nGuess);
    }
    if (magSqr(f.d()) > 0)
    {
        starts[nStarts++] = f.d()/mag(f.d());
    }

    label minima[maxMinima];
    label nMinima = 0;
    for (label i = 0; i < nSample; ++i)
    {
        bool isMin = true;
        for (label k = 0; k < nNeighbour; ++k)
        {
            if (gSample[S.nbr[i][k]] < gSample[i])
            {
                isMin = false;
                break;
            }
        }
        if (!isMin)
        {
            continue;
        }

        // Keep the maxMinima lowest, sorted
        label k = nMinima < maxMinima ? nMinima++ : maxMinima;
        while (k > 0 && gSample[i] < gSample[minima[k - 1]])
        {
            if (k < maxMinima)
            {
                minima[k] = minima[k - 1];
            }
            --k;
        }
        if (k < maxMinima)
        {
            minima[k] = i;
        }
    }
    for (label k = 0; k < nMinima; ++k)
    {
        starts[nStarts++] = S.dir[minima[k]];
    }

    // Refine every start, keep the lowest g (converged runs preferred)
    depthFunction::state bestState = f.eval(starts[0]);
    bestState.g = GREAT;
    label bestIters = 0;
    bool bestConverged = false;
    tangentFrame bestFrame;

    for (label k = 0; k < nStarts; ++k)
    {
        label iters = 0;
        bool conv = false;
        tangentFrame frame;
        const depthFunction::state s =
            newtonOnSphere
            (
                f, f.eval(starts[k]/mag(starts[k])), L, iters, conv, false,
                &frame
            );

        const bool better =
            (conv && !bestConverged)
         || (conv == bestConverged && s.g < bestState.g);

        if (better && std::isfinite(s.g))
        {
            bestState = s;
            bestIters = iters;
            bestConverged = conv;
            bestFrame = frame;
        }
    }

    return commonNormalResult
    (
        e1, e2, bestState, bestIters, bestConverged, bestFrame
    );
}


/*---------------------------------------------------------------------------*\
                 Polynomial method, Ruan Eqs. (29)-(31)
\*---------------------------------------------------------------------------*/

// Polynomial in tau up to degree 6, coefficients in increasing order
typedef std::array<scalar, 7> poly;

poly polyConst(const scalar c0, const scalar c1 = 0)
{
    poly p;
    p.fill(0);
    p[0] = c0;
    p[1] = c1;
    return p;
}

poly operator*(const poly& a, const poly& b)
{
    poly p;
    p.fill(0);
    for (label i = 0; i < 7; ++i)
    {
        for (label j = 0; i + j < 7; ++j)
        {
            p[i + j] += a[i]*b[j];
        }
    }
    return p;
}

poly operator+(const poly& a, const poly& b)
{
    poly p;
    for (label i = 0; i < 7; ++i) p[i] = a[i] + b[i];
    return p;
}

poly operator-(const poly& a, const poly& b)
{
    poly p;
    for (label i = 0; i < 7; ++i) p[i] = a[i] - b[i];
    return p;
}

poly operator*(const scalar s, const poly& a)
{
    poly p;
    for (label i = 0; i < 7; ++i) p[i] = s*a[i];
    return p;
}

// Value and derivative (Horner)
void polyEval(const poly& p, const scalar t, scalar& v, scalar& dv)
{
    v = p[6];
    dv = 0;
    for (label i = 5; i >= 0; --i)
    {
        dv = dv*t + v;
        v = v*t + p[i];
    }
}

scalar polyValue(const poly& p, const scalar t)
{
    scalar v, dv;
    polyEval(p, t, v, dv);
    return v;
}


// Ruan Eqs. (30)-(31) in a's scaled body frame (P_a = xi^T Da xi - 1,
// P_b = (xi - e)^T Sb (xi - e) - 1, w = Sb e): Phi(tau) = det(Sb + tau Da),
// y(tau) = adj(Sb + tau Da) w (so xi = y/Phi), and the sextic in tau whose
// roots put xi on surface a
poly levelSurfacePolynomial
(
    const vector& Da,
    const tensor& SbT,
    const vector& w,
    poly& Phi,
    poly y[3]
)
{
    // Eq. (30): (Sb + tau Da) xi = Sb e, i.e. xi = adj(A) w/det(A) with
    // A(tau) = Sb + tau Da, y(tau) = adj(A(tau)) w, Phi(tau) = det A(tau)
    poly A[3][3];
    for (direction i = 0; i < 3; ++i)
    {
        for (direction j = 0; j < 3; ++j)
        {
            A[i][j] = polyConst(SbT(i, j), i == j ? Da[i] : 0);
        }
    }

    poly adj[3][3];
    for (label i = 0; i < 3; ++i)
    {
        for (label j = 0; j < 3; ++j)
        {
            const label j1 = (j + 1) % 3, j2 = (j + 2) % 3;
            const label i1 = (i + 1) % 3, i2 = (i + 2) % 3;
            adj[i][j] = A[j1][i1]*A[j2][i2] - A[j1][i2]*A[j2][i1];
        }
    }

    Phi = A[0][0]*adj[0][0] + A[0][1]*adj[1][0] + A[0][2]*adj[2][0];

    for (label i = 0; i < 3; ++i)
    {
        y[i] = w[0]*adj[i][0] + w[1]*adj[i][1] + w[2]*adj[i][2];
    }

    // Eq. (31) with S1 = Da, b1 = 0, c1 = -1: y^T Da y - Phi^2 = 0
    return
        Da[0]*(y[0]*y[0]) + Da[1]*(y[1]*y[1]) + Da[2]*(y[2]*y[2])
      - Phi*Phi;
}


// Point of surface a on the innermost level surface of b: the minimum of
// P_b subject to P_a = 0, Ruan Eqs. (29)-(31). Returns false if no valid
// real root was found.
bool levelSurfacePoint
(
    const ellipsoid& ea,
    const ellipsoid& eb,
    const scalar L,
    point& x,
    label& iterations
)
{
    // Body frame of a, centred on c_a, lengths scaled by L:
    //   P_a(xi) = xi^T Da xi - 1        (S_a = Da, b_a = 0, c_a = -1)
    //   P_b(xi) = (xi - e)^T Sb (xi - e) - 1
    const tensor& Ra = ea.R();
    const vector& ax = ea.semiAxes();
    const vector Da(sqr(L/ax.x()), sqr(L/ax.y()), sqr(L/ax.z()));
    const vector e = (Ra.T() & (eb.centre() - ea.centre()))/L;
    const tensor SbT = (Ra.T() & tensor(eb.S()) & Ra)*sqr(L);
    const vector w = SbT & e;

    poly Phi, y[3];
    const poly p = levelSurfacePolynomial(Da, SbT, w, Phi, y);

    Eigen::Matrix<scalar, 7, 1> coeffs;
    for (label i = 0; i < 7; ++i)
    {
        coeffs(i) = p[i];
    }

    Eigen::PolynomialSolver<scalar, 6> solver;
    solver.compute(coeffs);
    const Eigen::PolynomialSolver<scalar, 6>::RootsType& roots =
        solver.roots();

    bool found = false;
    scalar bestPb = GREAT;
    vector bestXi(Zero);
    iterations = 0;

    for (label k = 0; k < roots.size(); ++k)
    {
        // Real roots, allowing for the imaginary round-off of a near-double
        // root; polished by Newton on Eq. (31)
        scalar tau = roots(k).real();
        if (!(mag(roots(k).imag()) <= 1e-3*(1 + mag(tau))))
        {
            continue;
        }
        for (label it = 0; it < 8; ++it)
        {
            scalar v, dv;
            polyEval(p, tau, v, dv);
            if (dv == 0)
            {
                break;
            }
            const scalar dTau = v/dv;
            ++iterations;
            if (!std::isfinite(dTau))
            {
                break;
            }
            tau -= dTau;
            if (mag(dTau) <= 4*eps*(1 + mag(tau)))
            {
                break;
            }
        }

        // Eq. (30)
        const scalar phi = polyValue(Phi, tau);
        const vector yv
        (
            polyValue(y[0], tau),
            polyValue(y[1], tau),
            polyValue(y[2], tau)
        );
        const vector xi = yv/phi;
        if (!std::isfinite(magSqr(xi)))
        {
            continue;
        }

        // A root of Eq. (31) puts xi on surface a; spurious roots (e.g. of
        // the repeated factors of a spheroid, where Phi = 0) do not
        const scalar Pa =
            Da[0]*sqr(xi[0]) + Da[1]*sqr(xi[1]) + Da[2]*sqr(xi[2]) - 1;
        if (!(mag(Pa) < 1e-6))
        {
            continue;
        }

        const vector dxi = xi - e;
        const scalar Pb = (dxi & (SbT & dxi)) - 1;
        if (Pb < bestPb)
        {
            bestPb = Pb;
            bestXi = xi;
            found = true;
        }
    }

    x = ea.centre() + L*(Ra & bestXi);
    return found;
}


// The polynomial method without the intersection test
result polynomialCore(const ellipsoid& e1, const ellipsoid& e2)
{
    const scalar L = max(e1.boundingRadius(), e2.boundingRadius());

    result r;
    r.contact = true;
    r.used = method::polynomial;

    label it1 = 0, it2 = 0;
    const bool ok1 = levelSurfacePoint(e1, e2, L, r.x1, it1);
    const bool ok2 = levelSurfacePoint(e2, e1, L, r.x2, it2);
    r.iterations = it1 + it2;
    r.converged = ok1 && ok2;

    if (!r.converged)
    {
        // Keep the result usable: centres, centre line, no overlap
        r.x1 = e1.centre();
        r.x2 = e2.centre();
        r.n = unitOrX(e2.centre() - e1.centre());
        r.overlap = 0;
        r.reducedRadius = 0;
        return r;
    }

    // Eq. (33) at x1; overlap |x1 - x2| (section 2.3.3)
    r.n = e1.normal(r.x1);
    r.overlap = mag(r.x1 - r.x2);
    r.reducedRadius = reducedRadius(e1, r.x1, e2, r.x2);

    return r;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * * //

const char* Foam::ellipsoidContact::methodName(const method m)
{
    switch (m)
    {
        case method::automatic: return "automatic";
        case method::sphere: return "sphere";
        case method::polynomial: return "polynomial";
        case method::robust: return "robust";
        case method::plane: return "plane";
        case method::none: return "none";
    }
    return "unknown";
}


bool Foam::ellipsoidContact::intersect
(
    const ellipsoid& e1,
    const ellipsoid& e2
)
{
    const vector d = e2.centre() - e1.centre();
    const scalar r1 = e1.boundingRadius(), r2 = e2.boundingRadius();

    // Bounding spheres apart: separated, no eigenproblem
    if (magSqr(d) > sqr(r1 + r2))
    {
        return false;
    }

    // Frame x = c1 + L xi: Q1 = diag(S1 L^2, -1) (inverse analytic),
    // Q2 from S2 L^2 and the centre e = d/L, Ruan Eqs. (22)-(23)
    const scalar L = max(r1, r2);
    const scalar L2 = sqr(L);
    const tensor S1inv(e1.Sinv());
    const tensor S2(e2.S());
    const vector e = d/L;
    const vector S2e = (S2 & e)*L2;

    Eigen::Matrix4d Q1inv = Eigen::Matrix4d::Zero();
    Eigen::Matrix4d Q2 = Eigen::Matrix4d::Zero();
    for (direction i = 0; i < 3; ++i)
    {
        for (direction j = 0; j < 3; ++j)
        {
            Q1inv(i, j) = S1inv(i, j)/L2;
            Q2(i, j) = S2(i, j)*L2;
        }
        Q2(i, 3) = -S2e[i];
        Q2(3, i) = -S2e[i];
    }
    Q1inv(3, 3) = -1;
    Q2(3, 3) = (e & S2e) - 1;

    const Eigen::EigenSolver<Eigen::Matrix4d> es(Q1inv*Q2, false);
    if (es.info() != Eigen::Success)
    {
        // Not seen in practice; err on the side of a contact check
        return true;
    }

    // Wang, Wang & Kim 2001: separated iff two distinct negative real
    // eigenvalues (a complex pair, Ruan/Alfano-Greer, is one way to fail)
    scalar neg[4];
    label nNeg = 0;
    for (label k = 0; k < 4; ++k)
    {
        const std::complex<scalar> ev = es.eigenvalues()(k);
        if (ev.imag() == 0 && ev.real() < 0)
        {
            neg[nNeg++] = ev.real();
        }
    }

    return !(nNeg == 2 && neg[0] != neg[1]);
}


Foam::ellipsoidContact::result Foam::ellipsoidContact::sphereSphere
(
    const ellipsoid& e1,
    const ellipsoid& e2
)
{
    if (!e1.isSphere() || !e2.isSphere())
    {
        FatalErrorInFunction
            << "Sphere-sphere contact of non-spheres: " << e1 << " and "
            << e2 << nl << "    use method automatic, robust or polynomial"
            << exit(FatalError);
    }

    return sphereSphere
    (
        e1.centre(), e1.semiAxes().x(),
        e2.centre(), e2.semiAxes().x()
    );
}


Foam::ellipsoidContact::result Foam::ellipsoidContact::polynomialMethod
(
    const ellipsoid& e1,
    const ellipsoid& e2
)
{
    if (!intersect(e1, e2))
    {
        return noContact(e1, e2);
    }
    return polynomialCore(e1, e2);
}


Foam::ellipsoidContact::result Foam::ellipsoidContact::robustMethod
(
    const ellipsoid& e1,
    const ellipsoid& e2,
    const vector& nGuess
)
{
    if (!intersect(e1, e2))
    {
        return noContact(e1, e2);
    }
    return robustCore(e1, e2, nGuess);
}


Foam::ellipsoidContact::result Foam::ellipsoidContact::contact
(
    const ellipsoid& e1,
    const ellipsoid& e2,
    const method m
)
{
    switch (m)
    {
        case method::sphere:
        {
            return sphereSphere(e1, e2);
        }
        case method::polynomial:
        {
            return polynomialMethod(e1, e2);
        }
        case method::robust:
        {
            return robustMethod(e1, e2);
        }
        case method::automatic:
        {
            vector nTrack(Zero);
            return contact(e1, e2, nTrack);
        }
        default:
        {
            FatalErrorInFunction
                << "Method " << methodName(m)
                << " is not a method for a pair of ellipsoids; use"
                << " automatic, sphere, polynomial or robust"
                << exit(FatalError);
        }
    }
    return result();
}


Foam::ellipsoidContact::result Foam::ellipsoidContact::contact
(
    const ellipsoid& e1,
    const ellipsoid& e2,
    vector& nTrack
)
{
    if (e1.isSphere() && e2.isSphere())
    {
        return sphereSphere(e1, e2);
    }
    if
    (
        magSqr(e2.centre() - e1.centre())
      > sqr(e1.boundingRadius() + e2.boundingRadius())
    )
    {
        return noContact(e1, e2);
    }
    result c;
    scalar g = 0;
    switch (certifiedSingleStart(e1, e2, nTrack, c, g))
    {
        case certificate::separated:
        {
            result r = noContact(e1, e2);
            r.separation = certifiedGap(e1, e2, g);
            return r;
        }
        case certificate::contact: return c;
        case certificate::undecided: break;
    }
    if (!intersect(e1, e2))
    {
        return noContact(e1, e2);
    }
    const result r = robustCore(e1, e2, Zero);
    if (r.converged)
    {
        nTrack = r.n;
        return r;
    }
    const result p = polynomialCore(e1, e2);
    return p.converged ? p : r;
}


Foam::ellipsoidContact::radiusGradient
Foam::ellipsoidContact::reducedRadiusGradient
(
    const ellipsoid& e1,
    const ellipsoid& e2,
    const result& r
)
{
    scalar Ksum;
    return radiusGradientAndCurvature
    (
        e1, e2, r, supportAlong(e1, r.n), supportAlong(e2, r.n), Ksum
    );
}


Foam::ellipsoidContact::result Foam::ellipsoidContact::ellipsoidPlanePoint
(
    const ellipsoid& e,
    const point& p0,
    const vector& nOut
)
{
    const scalar magN = mag(nOut);
    if (!std::isfinite(magN) || !(mag(magN - 1) <= 1e-8))
    {
        FatalErrorInFunction
            << "Plane normal " << nOut << " (magnitude " << magN
            << ") is not a finite unit vector" << exit(FatalError);
    }
    if (!std::isfinite(magSqr(p0)))
    {
        FatalErrorInFunction
            << "Plane point " << p0 << " is not finite" << exit(FatalError);
    }

    // Deepest point below the plane: the support point along n = -nOut,
    // with its support distance h (that along nOut is the same h, exactly)
    result r;
    r.used = method::plane;
    r.n = -nOut;
    scalar h;
    r.x1 = e.support(r.n, h);

    // Depth from the centre (support distance minus the centre's height)
    // rather than from x1: no cancellation of large coordinates
    const scalar depth = h - ((e.centre() - p0) & nOut);

    r.contact = depth > 0;
    r.overlap = max(depth, scalar(0));
    r.x2 = r.x1 + depth*nOut;
    return r;
}


void Foam::ellipsoidContact::addPlaneCurvature
(
    const ellipsoid& e,
    result& r
)
{
    if (r.contact)
    {
        // Eq. (37) at x1 as a function of the normal, which is fixed: only
        // the orientation moves K (Description)
        scalar K;
        vector gradK;
        curvatureAlong(e, r.n, supportAlong(e, r.n), K, gradK);
        r.reducedRadius = 1/K;
        r.gradR.rotation1 = sqr(r.reducedRadius)*(r.n ^ gradK);
    }
}


Foam::ellipsoidContact::result Foam::ellipsoidContact::ellipsoidPlane
(
    const ellipsoid& e,
    const point& p0,
    const vector& nOut
)
{
    result r = ellipsoidPlanePoint(e, p0, nOut);
    addPlaneCurvature(e, r);
    return r;
}


Foam::ellipsoidContact::result Foam::ellipsoidContact::spherePlane
(
    const point& c,
    const scalar radius,
    const point& p0,
    const vector& nOut
)
{
    // ellipsoidPlane for a sphere: support point c - r nOut, curvature 1/r
    result r;
    r.used = method::plane;
    r.n = -nOut;
    r.x1 = c - radius*nOut;
    const scalar depth = radius - ((c - p0) & nOut);
    r.contact = depth > 0;
    r.overlap = max(depth, scalar(0));
    r.x2 = r.x1 + depth*nOut;
    r.reducedRadius = r.contact ? radius : 0;
    return r;
}


// * * * * * * * * * * * * * * * IOstream Operators  * * * * * * * * * * * * //

Foam::Ostream& Foam::operator<<
(
    Ostream& os,
    const ellipsoidContact::result& r
)
{
    os  << "contact " << r.contact
        << " x1 " << r.x1 << " x2 " << r.x2 << " n " << r.n
        << " overlap " << r.overlap
        << " reducedRadius " << r.reducedRadius
        << " method " << ellipsoidContact::methodName(r.used)
        << " iterations " << r.iterations
        << " converged " << r.converged;
    return os;
}


// ************************************************************************* //
