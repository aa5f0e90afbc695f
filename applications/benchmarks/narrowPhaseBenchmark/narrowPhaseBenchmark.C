/*---------------------------------------------------------------------------*\
    chargedFoam: charged dielectric particles for OpenFOAM
-------------------------------------------------------------------------------
Application
    narrowPhaseBenchmark

Description
    Benchmark (not a test) of the narrow-phase contact cost per pair of the
    kernels of src/particleDynamics (ellipsoidContact.H): CPU time per pair
    in ns (see Timing) of

        intersect       ellipsoidContact::intersect alone
        automatic       ellipsoidContact::contact(e1, e2) (default selector)
        sphere          contact(e1, e2, method::sphere) (spheres only)
        robust          contact(e1, e2, method::robust)
        polynomial      contact(e1, e2, method::polynomial)
        plane           ellipsoidContact::ellipsoidPlane(e1, p0, nOut)
        gradR           ellipsoidContact::reducedRadiusGradient(e1, e2, r)
                        on the robust result r (part of robust, timed alone
                        on overlapping pairs for its share of the cost)
        plane, no gradR the ellipsoid-plane contact without the gradient of
                        R: support point, depth and R = 1/K(x1) by
                        ellipsoid::curvature (Eq. 37), written out here as
                        the reference for the gradient's cost in plane

    and each time divided by the sphere fast path (automatic on the sphere
    population). All contact() methods include the intersection test.

    Pair populations, built once before any timing from a std::mt19937_64
    of the given seed (identical populations for identical -pairs and
    -seed):
      - spheres: radii r = 1 mm x U(0.8, 1.25), overlap delta =
        LogU(1e-4, 1e-2) x the smaller radius along a random normal;
      - ellipsoids of aspect ratio AR = 2, 5, 10 (largest/smallest semi-
        axis), each body independently prolate (AR, 1, 1), oblate
        (AR, AR, 1) or triaxial (AR, sqrt(AR), 1) times a minor semi-axis
        of 1 mm x U(0.8, 1.25), in uniformly random orientations (Shoemake),
        overlapping by delta = LogU(1e-4, 1e-2) x the smaller minor semi-
        axis. Construction, exact and independent of the kernels: for a
        random unit normal n the bodies touch at the support points
        x1(n), x2(-n) (common normal, separated by their common tangent
        plane); body 2 is then pushed by delta along -n, which makes the
        penetration depth exactly delta (the robust overlap is compared
        with it as a check);
      - separated: the same ellipsoids touching, then pulled apart along
        n by a gap U(0.001, 1) x the largest gap keeping the centre
        distance below the sum of the bounding radii: the pairs a bounding-
        sphere broad phase passes and the intersection test must reject.
    Each pair carries a plane for the ellipsoid-plane kernel: random unit
    normal nOut, overlapping body 1 by delta (contact populations) or apart
    by the gap (separated populations). Centres lie in a 0.1 m box.

    Timing: per population one untimed warm-up sweep over all pairs per
    kernel, then 5 rounds in which every kernel makes one timed pass
    (interleaved, so a change of the machine's load hits all kernels alike);
    a pass is as many sweeps over all pairs as make it last >= 20 ms (1 for
    the expensive kernels, more for the cheap ones, so that clock resolution
    and interruptions do not count); reported is the median of the 5 passes
    divided by the pairs swept. The clock is the CPU time of the thread
    (CLOCK_THREAD_CPUTIME_ID), not advanced while the thread waits for a
    core, so other processes on a shared machine disturb it far less than
    the wall clock (both totals are printed). Every result is folded into a
    checksum that passes through an optimisation barrier (the kernels are in
    a shared library anyway, so calls cannot be elided). Single thread.

    Floating-point exception trapping (trapFpe in etc/controlDict,
    FOAM_SIGFPE, switched on by argList) is switched off: the kernels check
    their own results with std::isfinite, and the polynomial method divides
    by zero for some pairs of spheres. The exceptions (division by zero,
    invalid, overflow) raised per kernel are counted instead.

    Statistics (from one untimed pass): mean Newton iterations of robust
    (iterations of the best start, over pairs with contact), fraction of
    robust and polynomial results with converged = false, fraction of
    automatic results that fell back to the polynomial method, agreement
    of intersect() with the construction, median relative difference of
    the robust overlap from the constructed delta.

    Output: machine (nproc, CPU model, load average), build options, the
    table of times, the table of ratios and the statistics, as Markdown
    tables.

Usage
    narrowPhaseBenchmark [-pairs N] [-seed S]

    -pairs N    pairs per population (default 10000: the whole run takes
                about 15 s of CPU on a 2-core Xeon VM)
    -seed S     seed of the populations (default 1)

SourceFiles
    narrowPhaseBenchmark.C

\*---------------------------------------------------------------------------*/

#include "argList.H"
#include "ellipsoidContact.H"
#include "hertzOnset.H"
#include "mathematicalConstants.H"
#include "sigFpe.H"

// Only for the version macros; Eigen's headers are not written for
// OpenFOAM's warning set
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wold-style-cast"
#pragma GCC diagnostic ignored "-Wshadow"
#pragma GCC diagnostic ignored "-Wdeprecated-copy"
#include <Eigen/Core>
#pragma GCC diagnostic pop

#include <algorithm>
#include <cfenv>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <random>
#include <string>
#include <vector>

#include <dlfcn.h>
#include <sched.h>
#include <time.h>
#include <unistd.h>

#ifndef NPB_BUILD_OPTIONS
    #define NPB_BUILD_OPTIONS "unknown (not set by Make/options)"
#endif

using namespace Foam;

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

typedef std::mt19937_64 rng_t;

const label nRepeat = 5;

//- Shortest timed pass [ns]: cheap kernels sweep the pairs several times
const scalar minPass = 2e7;


//- Optimisation barrier: the compiler must assume the value is used
template<class T>
inline void doNotOptimize(const T& value)
{
    asm volatile("" : : "r,m"(value) : "memory");
}


scalar uniform(rng_t& g, const scalar a = 0, const scalar b = 1)
{
    return std::uniform_real_distribution<scalar>(a, b)(g);
}


scalar logUniform(rng_t& g, const scalar a, const scalar b)
{
    return std::exp(uniform(g, std::log(a), std::log(b)));
}


vector randomUnit(rng_t& g)
{
    std::normal_distribution<scalar> N(0, 1);
    vector v(Zero);
    do
    {
        v = vector(N(g), N(g), N(g));
    } while (mag(v) < 1e-3);
    return v/mag(v);
}


//- Uniformly distributed rotation (Shoemake 1992)
tensor randomRotation(rng_t& g)
{
    const scalar twoPi = constant::mathematical::twoPi;
    const scalar u1 = uniform(g), u2 = twoPi*uniform(g), u3 = twoPi*uniform(g);
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


//- Semi-axes of aspect ratio ar, minor semi-axis cMin: prolate, oblate or
//  triaxial with equal probability
vector randomAxes(rng_t& g, const scalar ar, const scalar cMin)
{
    const label kind = std::min(label(3*uniform(g)), label(2));
    if (kind == 0)
    {
        return cMin*vector(ar, 1, 1);
    }
    else if (kind == 1)
    {
        return cMin*vector(ar, ar, 1);
    }
    return cMin*vector(ar, std::sqrt(ar), 1);
}


//- One pair and a plane for body 1
struct pairCase
{
    ellipsoid e1;
    ellipsoid e2;
    point p0;           // plane point
    vector nOut;        // plane outward unit normal
    scalar delta;       // constructed overlap (0: separated)
    ellipsoidContact::result robust;    // method::robust, for gradR
};


//- A population of pairs
struct population
{
    std::string name;
    bool spheres;
    bool separated;
    std::vector<pairCase> pairs;
};


//- Build a population; ar = 1: spheres
population makePopulation
(
    const std::string& name,
    const scalar ar,
    const bool separated,
    const label nPairs,
    rng_t& g
)
{
    const scalar lengthScale = 1e-3;    // 1 mm minor semi-axis
    const scalar boxSize = 0.1;         // centres in a 0.1 m box

    population pop;
    pop.name = name;
    pop.spheres = (ar == 1);
    pop.separated = separated;
    pop.pairs.reserve(nPairs);

    for (label i = 0; i < nPairs; ++i)
    {
        const scalar c1Min = lengthScale*uniform(g, 0.8, 1.25);
        const scalar c2Min = lengthScale*uniform(g, 0.8, 1.25);
        const vector ax1 =
            pop.spheres ? vector::one*c1Min : randomAxes(g, ar, c1Min);
        const vector ax2 =
            pop.spheres ? vector::one*c2Min : randomAxes(g, ar, c2Min);
        const tensor R1 = pop.spheres ? tensor::I : randomRotation(g);
        const tensor R2 = pop.spheres ? tensor::I : randomRotation(g);
        const point c1
        (
            uniform(g, 0, boxSize),
            uniform(g, 0, boxSize),
            uniform(g, 0, boxSize)
        );
        const vector n = randomUnit(g);

        const ellipsoid e1(ax1, c1, R1);
        const ellipsoid e2AtOrigin(ax2, Zero, R2);

        // Touching centre offset: support point of 1 along n meets the
        // support point of 2 along -n, anti-parallel normals
        const vector d0 = (e1.support(n) - c1) - e2AtOrigin.support(-n);

        const scalar delta =
            separated ? 0 : logUniform(g, 1e-4, 1e-2)*min(c1Min, c2Min);

        // Separated: gap along n, centre distance below the bounding sum
        scalar gap = 0;
        if (separated)
        {
            const scalar Rb = e1.boundingRadius() + e2AtOrigin.boundingRadius();
            const scalar dn = d0 & n;
            const scalar gMax =
                -dn + std::sqrt(max(dn*dn - magSqr(d0) + sqr(Rb), scalar(0)));
            gap = uniform(g, 0.001, 1)*gMax;
        }

        const point c2 = c1 + d0 + (gap - delta)*n;

        // Plane for body 1: overlap delta, or apart by the gap
        const vector nOut = randomUnit(g);
        const scalar h1 = e1.supportDistance(nOut);
        const point p0 = c1 - (h1 - delta + gap)*nOut;

        pairCase pc
        {
            e1,
            e2AtOrigin.moved(c2, R2),
            p0,
            nOut,
            delta,
            ellipsoidContact::result()
        };
        pc.robust = ellipsoidContact::contact
        (
            pc.e1, pc.e2, ellipsoidContact::method::robust
        );
        pop.pairs.push_back(pc);
    }

    return pop;
}


//- Checksum of a contact result
inline scalar fold(const ellipsoidContact::result& r)
{
    return r.overlap + r.x1.x() + r.n.y() + r.iterations + r.contact;
}


//- CPU time of this thread [ns]: not advanced while the thread waits
//  for a core, so other processes on the machine disturb it far less than
//  the wall clock
inline scalar threadCpuTime()
{
    timespec ts;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return 1e9*scalar(ts.tv_sec) + scalar(ts.tv_nsec);
}


//- Total CPU and wall time of the timed passes [ns]
scalar totalCpu = 0;
scalar totalWall = 0;


//- One pass of nSweep sweeps over all pairs: CPU time per pair [ns]
template<class Kernel>
scalar timePass
(
    const std::vector<pairCase>& pairs,
    const Kernel& kernel,
    const label nSweep,
    scalar& checksum
)
{
    typedef std::chrono::steady_clock clock;

    scalar acc = 0;
    const clock::time_point wall0 = clock::now();
    const scalar cpu0 = threadCpuTime();
    for (label sweep = 0; sweep < nSweep; ++sweep)
    {
        for (const pairCase& pc : pairs)
        {
            acc += kernel(pc);
            doNotOptimize(acc);
        }
    }
    const scalar cpu1 = threadCpuTime();
    const clock::time_point wall1 = clock::now();
    checksum += acc;

    totalCpu += cpu1 - cpu0;
    totalWall +=
        std::chrono::duration<scalar, std::nano>(wall1 - wall0).count();

    return (cpu1 - cpu0)/(nSweep*max(label(pairs.size()), label(1)));
}


//- Warm-up (rep < 0: one sweep, sets nSweep for a pass of >= minPass) or
//  timed pass (rep >= 0: appends the time per pair to times)
template<class Kernel>
void timeKernel
(
    const std::vector<pairCase>& pairs,
    const Kernel& kernel,
    const label rep,
    label& nSweep,
    std::vector<scalar>& times,
    scalar& checksum
)
{
    if (rep < 0)
    {
        const scalar t = timePass(pairs, kernel, 1, checksum)*pairs.size();
        nSweep = max(label(1), label(std::ceil(minPass/max(t, scalar(1)))));
    }
    else
    {
        times.push_back(timePass(pairs, kernel, nSweep, checksum));
    }
}


//- Median of the timed passes
scalar median(std::vector<scalar> t)
{
    if (t.empty())
    {
        return -1;
    }
    std::sort(t.begin(), t.end());
    return t[t.size()/2];
}


//- Row of timings and statistics of one population
struct row
{
    std::string name;
    label nPairs = 0;
    scalar tIntersect = 0;
    scalar tAutomatic = 0;
    scalar tSphere = -1;            // < 0: not applicable
    scalar tRobust = 0;
    scalar tPolynomial = 0;
    scalar tPlane = 0;
    scalar tGradR = -1;             // < 0: not applicable
    scalar tOnset = -1;             // < 0: not timed (spheres only)
    scalar tPlaneNoGradR = 0;

    label nContact = 0;             // pairs the robust method treated
    scalar robustIterations = 0;    // mean over nContact
    scalar robustNotConverged = 0;  // fraction of nContact
    scalar polyNotConverged = 0;    // fraction of its contacts
    scalar autoFallback = 0;        // fraction of automatic -> polynomial
    scalar intersectAgrees = 0;     // fraction agreeing with construction
    scalar overlapError = 0;        // median |robust overlap - delta|/delta

    // Fraction of pairs whose call raised a floating-point exception
    // (division by zero, invalid, overflow): a SIGFPE abort with trapFpe
    scalar fpeIntersect = 0;
    scalar fpeAutomatic = 0;
    scalar fpeRobust = 0;
    scalar fpePolynomial = 0;
    scalar fpePlane = 0;
};


//- Did the last operations raise a trapped floating-point exception?
inline bool fpeRaised()
{
    return std::fetestexcept(FE_DIVBYZERO | FE_INVALID | FE_OVERFLOW);
}


//- The untimed statistics of the population into r
void statistics(const population& pop, row& r)
{
    using namespace ellipsoidContact;

    // Statistics, untimed
    label nRobust = 0, nRobustBad = 0, nPoly = 0, nPolyBad = 0;
    label nAuto = 0, nFallback = 0, nAgree = 0;
    label fpeI = 0, fpeA = 0, fpeR = 0, fpeP = 0, fpePl = 0;
    scalar iterSum = 0;
    std::vector<scalar> errors;

    for (const pairCase& pc : pop.pairs)
    {
        std::feclearexcept(FE_ALL_EXCEPT);
        const bool hit = intersect(pc.e1, pc.e2);
        if (fpeRaised()) ++fpeI;
        if (hit == !pop.separated)
        {
            ++nAgree;
        }

        std::feclearexcept(FE_ALL_EXCEPT);
        const result rr = contact(pc.e1, pc.e2, method::robust);
        if (fpeRaised()) ++fpeR;
        if (rr.contact)
        {
            ++nRobust;
            iterSum += rr.iterations;
            if (!rr.converged) ++nRobustBad;
            if (pc.delta > 0)
            {
                errors.push_back(mag(rr.overlap - pc.delta)/pc.delta);
            }
        }

        std::feclearexcept(FE_ALL_EXCEPT);
        const result rp = contact(pc.e1, pc.e2, method::polynomial);
        if (fpeRaised()) ++fpeP;
        if (rp.contact)
        {
            ++nPoly;
            if (!rp.converged) ++nPolyBad;
        }

        std::feclearexcept(FE_ALL_EXCEPT);
        const result ra = contact(pc.e1, pc.e2, method::automatic);
        if (fpeRaised()) ++fpeA;
        if (ra.contact)
        {
            ++nAuto;
            if (ra.used == method::polynomial) ++nFallback;
        }

        std::feclearexcept(FE_ALL_EXCEPT);
        const result rl = ellipsoidPlane(pc.e1, pc.p0, pc.nOut);
        if (fpeRaised()) ++fpePl;
        doNotOptimize(rl.overlap);
    }
    std::feclearexcept(FE_ALL_EXCEPT);

    const scalar perPair = 1.0/max(r.nPairs, label(1));
    r.fpeIntersect = fpeI*perPair;
    r.fpeAutomatic = fpeA*perPair;
    r.fpeRobust = fpeR*perPair;
    r.fpePolynomial = fpeP*perPair;
    r.fpePlane = fpePl*perPair;

    r.nContact = nRobust;
    r.robustIterations = nRobust ? iterSum/nRobust : 0;
    r.robustNotConverged = nRobust ? scalar(nRobustBad)/nRobust : 0;
    r.polyNotConverged = nPoly ? scalar(nPolyBad)/nPoly : 0;
    r.autoFallback = nAuto ? scalar(nFallback)/nAuto : 0;
    r.intersectAgrees = r.nPairs ? scalar(nAgree)/r.nPairs : 0;
    if (!errors.empty())
    {
        std::sort(errors.begin(), errors.end());
        r.overlapError = errors[errors.size()/2];
    }
}


//- The kernels' median times per pair into r (the checksum keeps the
//  compiler from dropping the calls)
void timings(const population& pop, row& r, scalar& checksum)
{
    using namespace ellipsoidContact;

    // Timings: one warm-up pass per kernel (rep = -1), then nRepeat
    // rounds, each kernel once per round (interleaved, so a change of the
    // machine's load affects all kernels alike)
    auto kIntersect = [](const pairCase& pc) -> scalar
    {
        return intersect(pc.e1, pc.e2);
    };
    auto kAutomatic = [](const pairCase& pc) -> scalar
    {
        return fold(contact(pc.e1, pc.e2, method::automatic));
    };
    auto kSphere = [](const pairCase& pc) -> scalar
    {
        return fold(contact(pc.e1, pc.e2, method::sphere));
    };
    auto kRobust = [](const pairCase& pc) -> scalar
    {
        return fold(contact(pc.e1, pc.e2, method::robust));
    };
    auto kPolynomial = [](const pairCase& pc) -> scalar
    {
        return fold(contact(pc.e1, pc.e2, method::polynomial));
    };
    auto kPlane = [](const pairCase& pc) -> scalar
    {
        return fold(ellipsoidPlane(pc.e1, pc.p0, pc.nOut));
    };
    auto kGradR = [](const pairCase& pc) -> scalar
    {
        const radiusGradient d = reducedRadiusGradient(pc.e1, pc.e2, pc.robust);
        return d.centre1.x() + d.rotation1.y() + d.rotation2.z();
    };
    auto kPlaneNoGradR = [](const pairCase& pc) -> scalar
    {
        const point x1 = pc.e1.support(-pc.nOut);
        const scalar depth =
            pc.e1.supportDistance(pc.nOut) - ((pc.e1.centre() - pc.p0) & pc.nOut);
        return depth > 0 ? depth + 1/pc.e1.curvature(x1) : x1.x();
    };
    // The correction of the first and last step of a contact (both powers
    // of the Hertz law), at an overlap per step of 1.5 delta
    auto kOnset = [](const pairCase& pc) -> scalar
    {
        const hertzOnset::correction c =
            hertzOnset::onsetCorrection(pc.delta, 1.5*pc.delta);
        return c.delta32 + c.delta52;
    };
    const bool overlapping = !pop.pairs.empty() && pop.pairs[0].delta > 0;

    std::vector<scalar> tI, tA, tS, tR, tP, tL, tG, tL0, tO;
    label nI = 1, nA = 1, nS = 1, nR = 1, nP = 1, nL = 1, nG = 1, nL0 = 1;
    label nO = 1;
    for (label rep = -1; rep < nRepeat; ++rep)
    {
        timeKernel(pop.pairs, kIntersect, rep, nI, tI, checksum);
        timeKernel(pop.pairs, kAutomatic, rep, nA, tA, checksum);
        if (pop.spheres)
        {
            timeKernel(pop.pairs, kSphere, rep, nS, tS, checksum);
            timeKernel(pop.pairs, kOnset, rep, nO, tO, checksum);
        }
        timeKernel(pop.pairs, kRobust, rep, nR, tR, checksum);
        timeKernel(pop.pairs, kPolynomial, rep, nP, tP, checksum);
        timeKernel(pop.pairs, kPlane, rep, nL, tL, checksum);
        timeKernel(pop.pairs, kPlaneNoGradR, rep, nL0, tL0, checksum);
        if (overlapping && !pop.spheres)
        {
            timeKernel(pop.pairs, kGradR, rep, nG, tG, checksum);
        }
    }

    r.tIntersect = median(tI);
    r.tAutomatic = median(tA);
    r.tSphere = median(tS);
    r.tRobust = median(tR);
    r.tPolynomial = median(tP);
    r.tPlane = median(tL);
    r.tPlaneNoGradR = median(tL0);
    if (!tG.empty())
    {
        r.tGradR = median(tG);
    }
    if (!tO.empty())
    {
        r.tOnset = median(tO);
    }
}


row benchmark(const population& pop, scalar& checksum)
{
    row r;
    r.name = pop.name;
    r.nPairs = pop.pairs.size();
    statistics(pop, r);
    timings(pop, r, checksum);
    return r;
}


//- First line of /proc/cpuinfo with the key, value only
std::string cpuInfo(const std::string& key)
{
    std::ifstream is("/proc/cpuinfo");
    std::string line;
    while (std::getline(is, line))
    {
        if (line.compare(0, key.size(), key) == 0)
        {
            const std::string::size_type colon = line.find(':');
            if (colon != std::string::npos)
            {
                return line.substr(line.find_first_not_of(" \t", colon + 1));
            }
        }
    }
    return "unknown";
}


//- Processors available to this process (as nproc)
label nProcessors()
{
    cpu_set_t set;
    CPU_ZERO(&set);
    if (sched_getaffinity(0, sizeof(set), &set) == 0)
    {
        return CPU_COUNT(&set);
    }
    return sysconf(_SC_NPROCESSORS_ONLN);
}


std::string loadAverage()
{
    std::ifstream is("/proc/loadavg");
    std::string a, b, c;
    is >> a >> b >> c;
    return a + " " + b + " " + c;
}


//- The file the kernels were loaded from
std::string kernelLibrary()
{
    Dl_info info;
    bool (*fn)(const ellipsoid&, const ellipsoid&) =
        &ellipsoidContact::intersect;
    void* addr = nullptr;
    std::memcpy(&addr, &fn, sizeof(addr));
    if (dladdr(addr, &info) && info.dli_fname)
    {
        return info.dli_fname;
    }
    return "unknown";
}


std::string fmtTime(const scalar t)
{
    if (t < 0) return "-";
    char buf[32];
    std::snprintf(buf, sizeof(buf), t < 100 ? "%.1f" : "%.0f", t);
    return buf;
}


std::string fmtRatio(const scalar t, const scalar ref)
{
    if (t < 0 || !(ref > 0)) return "-";
    char buf[32];
    std::snprintf(buf, sizeof(buf), t/ref < 10 ? "%.2f" : "%.0f", t/ref);
    return buf;
}


std::string fmtFraction(const scalar f, const label n)
{
    if (n == 0) return "-";
    char buf[32];
    std::snprintf(buf, sizeof(buf), "%.3f", f);
    return buf;
}

//- The report's header: command, machine, build, timing method
void printHeader(const label nPairs, const label seed, const bool trapRequested)
{
    std::printf("## narrowPhaseBenchmark\n\n");
    std::printf("- command: narrowPhaseBenchmark -pairs %d -seed %d\n",
        int(nPairs), int(seed));
    std::printf("- machine: nproc %d, CPU \"%s\", load average %s (at start)\n",
        int(nProcessors()), cpuInfo("model name").c_str(),
        loadAverage().c_str());
    std::printf("- build: %s; compiler %s; Eigen %d.%d.%d\n",
        NPB_BUILD_OPTIONS, __VERSION__,
        EIGEN_WORLD_VERSION, EIGEN_MAJOR_VERSION, EIGEN_MINOR_VERSION);
    std::printf("- kernels: %s\n", kernelLibrary().c_str());
    std::printf("- floating-point exception trapping: %s by trapFpe/"
        "FOAM_SIGFPE, switched off here (exceptions are counted)\n",
        trapRequested ? "requested" : "not requested");
    std::printf("- timing: thread CPU time (CLOCK_THREAD_CPUTIME_ID), median"
        " of %d passes (each >= %g ms, whole sweeps over all pairs) after"
        " one warm-up sweep, kernels interleaved, single thread\n\n",
        int(nRepeat), 1e-6*minPass);
    std::fflush(stdout);
}


//- The time tables: per pair, ratios to the sphere path, gradR, onset
void printTimes(const std::vector<row>& rows)
{
    const scalar ref = rows[0].tAutomatic;

    std::printf("CPU time per pair [ns]:\n\n");
    std::printf("| population | pairs | intersect | automatic | sphere"
        " | robust | polynomial | ellipsoid-plane"
        " | robust mean Newton iterations | robust not converged"
        " | polynomial not converged |\n");
    std::printf("|---|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|\n");
    for (const row& r : rows)
    {
        char iters[32];
        std::snprintf(iters, sizeof(iters), "%.1f", r.robustIterations);
        std::printf
        (
            "| %s | %d | %s | %s | %s | %s | %s | %s | %s | %s | %s |\n",
            r.name.c_str(), int(r.nPairs),
            fmtTime(r.tIntersect).c_str(), fmtTime(r.tAutomatic).c_str(),
            fmtTime(r.tSphere).c_str(), fmtTime(r.tRobust).c_str(),
            fmtTime(r.tPolynomial).c_str(), fmtTime(r.tPlane).c_str(),
            r.nContact ? iters : "-",
            fmtFraction(r.robustNotConverged, r.nContact).c_str(),
            fmtFraction(r.polyNotConverged, r.nContact).c_str()
        );
    }

    std::printf("\nRatio to the sphere fast path (automatic, spheres:"
        " %s ns/pair):\n\n", fmtTime(ref).c_str());
    std::printf("| population | intersect | automatic | sphere | robust"
        " | polynomial | ellipsoid-plane |\n");
    std::printf("|---|--:|--:|--:|--:|--:|--:|\n");
    for (const row& r : rows)
    {
        std::printf("| %s | %s | %s | %s | %s | %s | %s |\n",
            r.name.c_str(),
            fmtRatio(r.tIntersect, ref).c_str(),
            fmtRatio(r.tAutomatic, ref).c_str(),
            fmtRatio(r.tSphere, ref).c_str(),
            fmtRatio(r.tRobust, ref).c_str(),
            fmtRatio(r.tPolynomial, ref).c_str(),
            fmtRatio(r.tPlane, ref).c_str());
    }

    std::printf("\nThe reduced-radius gradient (the elastic force's"
        " -dU/dR grad R) inside the robust contact, timed alone on the"
        " robust results:\n\n");
    std::printf("| population | gradR [ns] | robust [ns] | gradR/robust"
        " | ellipsoid-plane [ns] | plane without gradR [ns]"
        " | plane/without |\n");
    std::printf("|---|--:|--:|--:|--:|--:|--:|\n");
    for (const row& r : rows)
    {
        if (r.tGradR >= 0)
        {
            std::printf("| %s | %s | %s | %.3f | %s | %s | %.2f |\n",
                r.name.c_str(),
                fmtTime(r.tGradR).c_str(), fmtTime(r.tRobust).c_str(),
                r.tGradR/r.tRobust, fmtTime(r.tPlane).c_str(),
                fmtTime(r.tPlaneNoGradR).c_str(),
                r.tPlane/r.tPlaneNoGradR);
        }
    }

    for (const row& r : rows)
    {
        if (r.tOnset >= 0)
        {
            std::printf("\nThe correction of a contact's first and last"
                " step (hertzOnset::onsetCorrection for delta^3/2 and"
                " delta^5/2: two Hurwitz zeta values): %s ns per step that"
                " needs it, %.2f times the sphere contact (%s); at 50 steps"
                " per collision %.3f of it per contact step\n",
                fmtTime(r.tOnset).c_str(), r.tOnset/ref, r.name.c_str(),
                2*r.tOnset/ref/50);
        }
    }
}


//- The untimed checks of the populations
void printChecks(const std::vector<row>& rows)
{
    std::printf("\nChecks of the populations (untimed; fractions of"
        " pairs):\n\n");
    std::printf("| population | intersect() agrees with construction"
        " | median abs(robust overlap - delta)/delta"
        " | automatic fell back to polynomial"
        " | FP exception: intersect | automatic | robust | polynomial"
        " | ellipsoid-plane |\n");
    std::printf("|---|--:|--:|--:|--:|--:|--:|--:|--:|\n");
    for (const row& r : rows)
    {
        char err[32];
        std::snprintf(err, sizeof(err), "%.1e", r.overlapError);
        std::printf("| %s | %.3f | %s | %s | %.3f | %.3f | %.3f | %.3f"
            " | %.3f |\n",
            r.name.c_str(), r.intersectAgrees,
            r.nContact ? err : "-",
            fmtFraction(r.autoFallback, r.nContact).c_str(),
            r.fpeIntersect, r.fpeAutomatic, r.fpeRobust, r.fpePolynomial,
            r.fpePlane);
    }
}


} // End anonymous namespace


// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Benchmark of the narrow-phase contact kernels (ellipsoidContact):"
        " time per pair of intersect, contact (automatic, sphere, robust,"
        " polynomial) and ellipsoidPlane for spheres, ellipsoids of aspect"
        " ratio 2, 5, 10 and separated pairs."
    );
    argList::noBanner();
    argList::noParallel();
    argList::noFunctionObjects();
    argList::removeOption("case");
    argList::addOption
    (
        "pairs",
        "N",
        "pairs per population (default 10000)"
    );
    argList::addOption
    (
        "seed",
        "S",
        "seed of the pair populations (default 1)"
    );

    argList args(argc, argv);

    // Floating-point exception trapping (trapFpe in etc/controlDict,
    // FOAM_SIGFPE) is switched off: the kernels test their results with
    // std::isfinite, and the polynomial method divides by zero for some
    // pairs (e.g. spheres). The exceptions raised are counted instead.
    const bool trapRequested = sigFpe::requested();
    sigFpe::unset(false);

    const label nPairs = args.getOrDefault<label>("pairs", 10000);
    const label seed = args.getOrDefault<label>("seed", 1);

    if (nPairs < 1)
    {
        FatalErrorInFunction
            << "-pairs " << nPairs << ": needs at least 1 pair"
            << exit(FatalError);
    }

    printHeader(nPairs, seed, trapRequested);

    // Populations, built once before any timing
    const std::chrono::steady_clock::time_point t0 =
        std::chrono::steady_clock::now();

    rng_t g(seed);
    std::vector<population> pops;
    pops.push_back(makePopulation("spheres", 1, false, nPairs, g));
    pops.push_back(makePopulation("AR 2, overlapping", 2, false, nPairs, g));
    pops.push_back(makePopulation("AR 5, overlapping", 5, false, nPairs, g));
    pops.push_back(makePopulation("AR 10, overlapping", 10, false, nPairs, g));
    pops.push_back(makePopulation("AR 2, separated", 2, true, nPairs, g));
    pops.push_back(makePopulation("AR 5, separated", 5, true, nPairs, g));
    pops.push_back(makePopulation("AR 10, separated", 10, true, nPairs, g));

    scalar checksum = 0;
    std::vector<row> rows;
    for (const population& pop : pops)
    {
        rows.push_back(benchmark(pop, checksum));
    }

    printTimes(rows);
    printChecks(rows);

    const scalar seconds = std::chrono::duration<scalar>
    (
        std::chrono::steady_clock::now() - t0
    ).count();

    std::printf("\nTimed passes: CPU %.1f s, wall %.1f s (CPU/wall %.2f);"
        " whole run %.1f s wall; sink %.3e (optimisation barrier)\n",
        1e-9*totalCpu, 1e-9*totalWall, totalCpu/max(totalWall, scalar(1)),
        seconds, checksum);

    return 0;
}


// ************************************************************************* //
