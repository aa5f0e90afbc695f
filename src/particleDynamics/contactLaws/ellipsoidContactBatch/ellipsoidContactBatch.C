/*---------------------------------------------------------------------------*\
    chargedFoam: charged dielectric particles for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "ellipsoidContactBatch.H"
#include "contactLawLanes.H"

#include <limits>

using namespace Foam::simd;

static_assert
(
    Foam::ellipsoidContactBatch::width == Foam::simd::width,
    "one lane per contact of a batch"
);

// * * * * * * * * * * * * * * * Local Functions  * * * * * * * * * * * * * //

namespace
{

using Foam::scalar;
using Foam::label;

// Each function repeats the operations of its namesake in
// ellipsoidContact.C (a change there goes here too; the unit test compares
// the two bit for bit)

// depthFunction::state at the unit direction m
struct depthState
{
    lanes3 m, w1, w2;
    lanes h1, h2, g;
};

// depthFunction::eval
inline depthState eval
(
    const lanesSymm& M1,
    const lanesSymm& M2,
    const lanes3& d,
    const lanes3& m
)
{
    depthState s;
    s.m = m;
    s.w1 = dot(M1, m);
    s.w2 = dot(M2, m);
    s.h1 = sqrtOf(dot(m, s.w1));
    s.h2 = sqrtOf(dot(m, s.w2));
    s.g = s.h1 + s.h2 - dot(m, d);
    return s;
}

// tangents: the coordinate axis least aligned with m gives t1
inline void tangents(const lanes3& m, lanes3& t1, lanes3& t2)
{
    const lanes zero = broadcast(0), one = broadcast(1);
    const lanes ax = absOf(m.x), ay = absOf(m.y), az = absOf(m.z);
    const laneMask ex = (ax <= ay) & (ax <= az);
    const laneMask ey = ~ex & (ay <= az);
    const laneMask ez = ~ex & ~ey;
    const lanes3 e{ex ? one : zero, ey ? one : zero, ez ? one : zero};
    t1 = e - dot(e, m)*m;
    t1 = t1*(one/sqrtOf(dot(t1, t1)));
    t2 = cross(m, t1);
}

// depthFunction::hessian (and radiiOfCurvature, its terms of one body):
// (M t)/h - (M m)(M m . t)/h^3 with the reciprocals
inline lanes3 curvatureTerm
(
    const lanesSymm& M,
    const lanes3& w,
    const lanes hInv,
    const lanes hInv3,
    const lanes3& t
)
{
    return dot(M, t)*hInv - w*(dot(w, t)*hInv3);
}

// curvatureAlong: the mean curvature K (Ruan Eq. 37) as a function of n,
// K(n) = h(n) (tr S - n.S n)/2, and the tangential part of its gradient
inline void curvatureAlong
(
    const lanesSymm& S,
    const lanes3& n,
    const lanes3& Mn,
    const lanes h,
    const lanes hInv,
    lanes& K,
    lanes3& gradK
)
{
    const lanes half = broadcast(0.5);
    const lanes3 Sn = dot(S, n);
    const lanes trS = tr(S);
    const lanes tau = trS - dot(n, Sn);
    K = half*h*tau;
    const lanes3 g = (half*tau*hInv)*Mn + h*(trS*n - Sn);
    gradK = g - dot(g, n)*n;
}

// newtonOnSphere with stopWhenSeparated from s, pure Newton steps only
// (newtonStep with mu = 0, a step below 1e-4 rad taken whole): lanes still
// iterating (active), converged with the frame (converged), or left to the
// scalar path (off); L the length scale of the tolerances
inline depthState pureNewton
(
    const lanesSymm& M1,
    const lanesSymm& M2,
    const lanes3& d,
    depthState s,
    const lanes L,
    laneMask& off,
    lanes& iterations
)
{
    const lanes zero = broadcast(0), one = broadcast(1);
    const lanes half = broadcast(0.5);
    const lanes tolG =
        broadcast(64*std::numeric_limits<scalar>::epsilon())*L;
    laneMask active = ~off;
    laneMask converged = active & ~active;
    for
    (
        label iter = 0;
        iter < Foam::ellipsoidContactBatch::maxIterations;
        ++iter
    )
    {
        off |= active & (s.g < zero);
        active &= ~off;
        iterations = active ? broadcast(iter + 1) : iterations;

        // The tangential gradient, at round-off: converged
        const lanes hInv1 = one/s.h1, hInv2 = one/s.h2;
        const lanes3 grad = s.w1*hInv1 + s.w2*hInv2 - d;
        lanes3 t1, t2;
        tangents(s.m, t1, t2);
        const lanes G1 = dot(t1, grad), G2 = dot(t2, grad);
        const laneMask done = active & (sqrtOf(G1*G1 + G2*G2) <= tolG);
        converged |= done;
        active &= ~done;
        if (!any(active))
        {
            break;
        }

        // newtonStep: the Riemannian Hessian (depthFunction::hessian sums
        // its four terms left to right); its Levenberg-Marquardt shift
        // (off)
        const lanes hInv31 = hInv1*hInv1*hInv1, hInv32 = hInv2*hInv2*hInv2;
        auto hessian = [&](const lanes3& t)
        {
            return
                dot(M1, t)*hInv1
              - s.w1*(dot(s.w1, t)*hInv31)
              + dot(M2, t)*hInv2
              - s.w2*(dot(s.w2, t)*hInv32);
        };
        const lanes3 Ht1 = hessian(t1), Ht2 = hessian(t2);
        const lanes H11 = dot(t1, Ht1) - s.g;
        const lanes H22 = dot(t2, Ht2) - s.g;
        const lanes H12 = half*(dot(t1, Ht2) + dot(t2, Ht1));
        const lanes trH = half*(H11 + H22);
        const lanes halfDiff = half*(H11 - H22);
        const lanes rad = sqrtOf(halfDiff*halfDiff + H12*H12);
        const lanes lMin = trH - rad, lMax = trH + rad;
        off |= active & ~(lMin > broadcast(1e-10)*maxOf(absOf(lMax), L));

        // The step (mu = 0), taken whole below 1e-4 rad, else a line
        // search (off)
        const lanes A11 = H11 + zero, A22 = H22 + zero;
        const lanes detA = A11*A22 - H12*H12;
        off |= active & (detA == zero);
        active &= ~off;
        const lanes safeDetA = active ? detA : one;
        const lanes s1 = (-(A22*G1 - H12*G2))/safeDetA;
        const lanes s2 = (-(A11*G2 - H12*G1))/safeDetA;
        const lanes magS = sqrtOf(s1*s1 + s2*s2);
        off |= active & ~(magS < broadcast(1e-4));
        active &= ~off;
        const lanes3 m = s.m + (s1*t1 + s2*t2);
        const depthState trial =
            eval(M1, M2, d, m*(one/sqrtOf(dot(m, m))));
        s.m = choose(active, trial.m, s.m);
        s.w1 = choose(active, trial.w1, s.w1);
        s.w2 = choose(active, trial.w2, s.w2);
        s.h1 = active ? trial.h1 : s.h1;
        s.h2 = active ? trial.h2 : s.h2;
        s.g = active ? trial.g : s.g;

        // A step at 1e-14 rad ends the run without the frame (off)
        off |= active & (one*magS <= broadcast(1e-14));
        active &= ~off;
    }
    off |= active | ~converged;
    return s;
}


// radiusGradientAndCurvature's results; KsumSafe: K1 + K2, 1 in the lanes
// that are off
struct radiusLanes
{
    lanes KsumSafe;
    lanes3 centre1, rotation1, centre2, rotation2;
};

// radiusGradientAndCurvature at the common normal s.m of the state s, with
// its frame (t1, t2) and reciprocals, the overlap and the contact points
// relative to the centres (r1, r2)
inline radiusLanes radiusGradientAndCurvature
(
    const lanesSymm& S1,
    const lanesSymm& S2,
    const lanesSymm& M1,
    const lanesSymm& M2,
    const depthState& s,
    const lanes hInv1,
    const lanes hInv2,
    const lanes3& t1,
    const lanes3& t2,
    const lanes overlap,
    const lanes3& r1,
    const lanes3& r2,
    const laneMask off
)
{
    const lanes zero = broadcast(0), one = broadcast(1);
    const lanes half = broadcast(0.5);
    const lanes3& n = s.m;
    lanes K1, K2;
    lanes3 gradK1, gradK2;
    curvatureAlong(S1, n, s.w1, s.h1, hInv1, K1, gradK1);
    curvatureAlong(S2, n, s.w2, s.h2, hInv2, K2, gradK2);
    const lanes Ksum = K1 + K2;
    const lanes3 G = gradK1 + gradK2;
    const lanes hInv31 = hInv1*hInv1*hInv1, hInv32 = hInv2*hInv2*hInv2;
    const lanes3 D1t1 = curvatureTerm(M1, s.w1, hInv1, hInv31, t1);
    const lanes3 D1t2 = curvatureTerm(M1, s.w1, hInv1, hInv31, t2);
    const lanes3 D2t1 = curvatureTerm(M2, s.w2, hInv2, hInv32, t1);
    const lanes3 D2t2 = curvatureTerm(M2, s.w2, hInv2, hInv32, t2);
    const lanes3 Dt1 = D1t1 + D2t1;
    const lanes3 Dt2 = D1t2 + D2t2;
    const lanes H11 = dot(t1, Dt1) - overlap;
    const lanes H22 = dot(t2, Dt2) - overlap;
    const lanes H12 = half*(dot(t1, Dt2) + dot(t2, Dt1));
    const lanes det = H11*H22 - H12*H12;

    // Not a strict minimum of the depth: gradR zero
    const laneMask smooth = (det > zero) & (H11 > zero);
    const lanes safeDet = smooth ? det : one;
    const lanes Gt1 = dot(t1, G), Gt2 = dot(t2, G);
    const lanes w1 = (H22*Gt1 - H12*Gt2)/safeDet;
    const lanes w2 = (H11*Gt2 - H12*Gt1)/safeDet;
    const lanes3 w = w1*t1 + w2*t2;

    radiusLanes r;
    r.KsumSafe = off ? one : Ksum;
    const lanes R2 = one/(r.KsumSafe*r.KsumSafe);
    const lanes3 none{zero, zero, zero};
    r.centre1 = choose(smooth, R2*w, none);
    r.centre2 = choose(smooth, (-R2)*w, none);
    r.rotation1 = choose
    (
        smooth,
        (-R2)
       *(cross(n, w1*D1t1 + w2*D1t2) - cross(r1, w) - cross(n, gradK1)),
        none
    );
    r.rotation2 = choose
    (
        smooth,
        (-R2)
       *(cross(n, w1*D2t1 + w2*D2t2) + cross(r2, w) - cross(n, gradK2)),
        none
    );
    return r;
}

} // End anonymous namespace


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::ellipsoidContactBatch::pad(const label n)
{
    for (label l = n; l < width; ++l)
    {
        for (label c = 0; c < 6; ++c)
        {
            Sinv1_[c][l] = Sinv1_[c][0];
            Sinv2_[c][l] = Sinv2_[c][0];
            S1_[c][l] = S1_[c][0];
            S2_[c][l] = S2_[c][0];
        }
        for (label c = 0; c < 3; ++c)
        {
            c1_[c][l] = c1_[c][0];
            c2_[c][l] = c2_[c][0];
            nTrack_[c][l] = nTrack_[c][0];
        }
        reach_[l] = reach_[0];
        rolling_[l] = rolling_[0];
    }
}


void Foam::ellipsoidContactBatch::padKick(const label n)
{
    for (label l = n; l < width; ++l)
    {
        for (label c = 0; c < 3; ++c)
        {
            xA_[c][l] = xA_[c][0];
            xB_[c][l] = xB_[c][0];
            UA_[c][l] = UA_[c][0];
            UB_[c][l] = UB_[c][0];
            omegaA_[c][l] = omegaA_[c][0];
            omegaB_[c][l] = omegaB_[c][0];
            xi_[c][l] = xi_[c][0];
        }
        for (label c = 0; c < 6; ++c)
        {
            invIA_[c][l] = invIA_[c][0];
            invIB_[c][l] = invIB_[c][0];
        }
        mA_[l] = mA_[0];
        mB_[l] = mB_[0];
    }
    law_.pad(n);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::ellipsoidContactBatch::evaluate(const label nLanes)
{
    pad(nLanes);

    const lanes zero = broadcast(0), one = broadcast(1);
    const lanesSymm M1 = loadSymm(Sinv1_), M2 = loadSymm(Sinv2_);
    const lanes3 c1 = load3(c1_), c2 = load3(c2_);

    // contact(e1, e2, nTrack): bounding spheres apart
    const lanes3 d = c2 - c1;
    const lanes reach = load(reach_);
    laneMask off = dot(d, d) > reach*reach;

    // certifiedSingleStart: the depth at the tracked direction, separated
    // there, or coincident centres
    const lanes3 nTrack = load3(nTrack_);
    depthState s =
        eval(M1, M2, d, nTrack*(one/sqrtOf(dot(nTrack, nTrack))));
    const lanes dist = sqrtOf(dot(d, d));
    off |= (s.g < zero) | ~(dist > zero);
    lanes iterations = zero;
    s = pureNewton(M1, M2, d, s, reach + dist, off, iterations);

    // The converging iteration's reciprocals and frame (the same
    // operations on the same state)
    const lanes hInv1 = one/s.h1, hInv2 = one/s.h2;
    lanes3 t1, t2;
    tangents(s.m, t1, t2);

    // The rolling-radius certificate
    off |= ~((s.g > zero) & (s.g < broadcast(0.9)*load(rolling_)));

    // commonNormalResult
    const lanes3 x1 = c1 + s.w1*hInv1;
    const lanes3 x2 = c2 - s.w2*hInv2;
    const lanes overlap = maxOf(s.g, zero);
    const radiusLanes r = radiusGradientAndCurvature
    (
        loadSymm(S1_), loadSymm(S2_), M1, M2, s, hInv1, hInv2, t1, t2,
        overlap, x1 - c1, x2 - c2, off
    );

    store3(n_, s.m);
    store3(x1_, x1);
    store3(x2_, x2);
    store(overlap_, overlap);
    store(R_, one/r.KsumSafe);
    store3(gradRc1_, r.centre1);
    store3(gradRc2_, r.centre2);
    store3(gradRr1_, r.rotation1);
    store3(gradRr2_, r.rotation2);
    for (label l = 0; l < nLanes; ++l)
    {
        decided_[l] = !off[l];
        iterations_[l] = label(iterations[l]);
    }
}


void Foam::ellipsoidContactBatch::kick(const label nLanes, const scalar dt)
{
    padKick(nLanes);

    const lanes one = broadcast(1);
    const lanes3 xA = load3(xA_), xB = load3(xB_);
    const lanes3 n = load3(n_);

    // Undecided lanes go on with a positive overlap and radius
    // (discarded)
    laneMask decided;
    for (label l = 0; l < width; ++l)
    {
        decided[l] = l < nLanes && decided_[l] ? -1 : 0;
    }
    const lanes overlap = decided ? load(overlap_) : one;
    const lanes R = decided ? load(R_) : one;

    // EllipsoidCollision::pairForce: the contact point, the relative
    // velocity there, the reduced mass and the normal mobilities
    // (ContactBodies::normalMobility: 1/m + (r x n).I^-1 (r x n))
    const lanes mA = load(mA_), mB = load(mB_);
    const pairMotion p = pairMotionOf
    (
        load3(x1_), load3(x2_), xA, load3(UA_), load3(omegaA_), mA,
        xB, load3(UB_), load3(omegaB_), mB
    );
    const lanes3 rnA = cross(p.xc - xA, n);
    const lanes3 rnB = cross(p.xc - xB, n);
    const lanes invMassNormal =
        (one/mA + dot(rnA, dot(loadSymm(invIA_), rnA)))
      + (one/mB + dot(rnB, dot(loadSymm(invIB_), rnB)));

    // contactLaw::force with the default parts
    lanes3 xi = load3(xi_);
    const kickLanes k =
        defaultLawKick
        (
            law_, n, overlap, R, p.vRel, p.mStar, invMassNormal,
            broadcast(dt), xi
        );

    // Torques about the centres, and the elastic force and torques of the
    // change of R: -dUdR gradR (ellipsoidContact.H)
    store3
    (
        torqueA_, torqueAbout(p.xc, xA, k.F) - k.dUdR*load3(gradRr1_)
    );
    store3
    (
        torqueB_, torqueAbout(p.xc, xB, k.F) + k.dUdR*load3(gradRr2_)
    );
    store3(F_, k.F - k.dUdR*load3(gradRc1_));
    store3(xi_, xi);
    store(dissipated_, k.dissipated);
    store(elastic_, k.elastic);
    for (label l = 0; l < nLanes; ++l)
    {
        needsScalar_[l] = k.corrected[l];
    }
}


Foam::ellipsoidContact::result
Foam::ellipsoidContactBatch::contact(const label l) const
{
    ellipsoidContact::result r;
    r.contact = true;
    r.used = ellipsoidContact::method::robust;
    r.iterations = iterations_[l];
    r.converged = true;
    r.n = get(n_, l);
    r.x1 = get(x1_, l);
    r.x2 = get(x2_, l);
    r.overlap = overlap_[l];
    r.reducedRadius = R_[l];
    r.gradR.centre1 = get(gradRc1_, l);
    r.gradR.rotation1 = get(gradRr1_, l);
    r.gradR.centre2 = get(gradRc2_, l);
    r.gradR.rotation2 = get(gradRr2_, l);
    return r;
}


// ************************************************************************* //
