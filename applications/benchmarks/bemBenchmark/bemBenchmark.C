/*---------------------------------------------------------------------------*\
    chargedFoam: charged dielectric particles for OpenFOAM
-------------------------------------------------------------------------------
Application
    bemBenchmark

Description
    Cost of the BEM solver (bemSolver), the set-ups of Ruan 2022, Fig. 3:
      1. two spheres R = 1, surface gap 0.5 R, n patches each, n = 100..5000;
      2. Np spheres in a row, n = 392, gap 0.2 R, Np = 2..100;
    direct O(N^2) matvec against the treecode (O(N log N)) and the fast
    multipole method (O(N)): time per GMRES iteration (matvec only, and
    whole GMRES time / iterations), time per solve, iterations, and fitted
    exponents t ~ n^a, Np^b (Ruan with FMM: n^1.564, Np^1.333);
      1b. treecode and FMM only, n up to 20000;
      3. GMRES iterations with and without the block preconditioner;
      4. accuracy against cost on Ruan App. A (point charge + dielectric
         sphere, kappa ratio 10): uniform and graded meshes;
      5. accuracy and cost of the fast sums alone against the direct sum
         (treecode at its default, FMM over orders p and opening
         parameters theta): relative L2 error of E, phi and n.E.
    All runs single-threaded, times are thread CPU times; kappa_p = 10,
    sigma_f = 1, tolerance 1e-4, default solver controls (treecode theta
    0.3, quadrupole, leaf 32; FMM p 5, theta 0.5, leaf 16; curvature self
    term; near quadrature).

    Usage: bemBenchmark [-quick] [-section 1|1b|2|3|4|5]

\*---------------------------------------------------------------------------*/

#include "argList.H"
#include "bemSolver.H"
#include "bemFmm.H"
#include "bemTreecode.H"
#include "ellipsoidSurfaceMesh.H"
#include "pairwiseCoulomb.H"
#include "mathematicalConstants.H"
#include "cpuTime.H"

#include <algorithm>
#include <cstdio>
#include <ctime>
#include <functional>
#include <memory>
#include <random>
#include <vector>

using namespace Foam;
using constant::mathematical::pi;

namespace
{

struct run
{
    scalar perMatvec, perIterMatvec, perIter, perSolve, setup;
    label iterations;
};


//- A solved case, kept alive for the timing rounds
struct solvedCase
{
    std::unique_ptr<bemSolver> solver;
    run r;
    label nTimes;                   // products to time
    std::vector<scalar> times;
};


solvedCase solveSpheres
(
    const label np,
    const label n,
    const scalar gap,
    const bemMatvecMethod mv,
    const bool precondition,
    const scalar kp = 10
)
{
    bemSolverControls c;
    c.matvec = mv;
    c.precondition = precondition;
    solvedCase sc;
    sc.solver.reset(new bemSolver(1, c));
    bemSolver& s = *sc.solver;
    const label sh = s.shape(vector(1, 1, 1), n);
    const scalar A = sum(s.mesh(sh).areas());
    for (label p = 0; p < np; ++p)
    {
        s.addParticle(sh, point(p*(2 + gap), 0, 0), tensor::I, kp, A);
    }
    const auto& info = s.solve();
    run& r = sc.r;
    r.iterations = info.iterations;
    r.perIterMatvec = info.matvecTime/max(info.iterations, label(1));
    r.perIter = info.solveTime/max(info.iterations, label(1));
    r.perSolve = info.setupTime + info.solveTime;
    r.setup = info.setupTime;
    r.perMatvec = 0;
    // Median of repeated products: less sensitive to a loaded machine than
    // the few products inside one solve
    sc.nTimes = mv == bemMatvecMethod::direct && np*n > 20000 ? 3 : 7;
    return sc;
}


run spheres
(
    const label np,
    const label n,
    const scalar gap,
    const bemMatvecMethod mv,
    const bool precondition,
    const scalar kp = 10
)
{
    solvedCase sc = solveSpheres(np, n, gap, mv, precondition, kp);
    sc.r.perMatvec = sc.solver->matvecCpuTime(sc.nTimes);
    return sc.r;
}


// Median time per product of every case, timed in rounds: each round times
// one product of each case (the median of three in a row, i.e. with warm
// caches, for products under 0.05 s), so that a slow phase of the shared
// machine (another job on the sibling core) hits all sizes alike instead of
// one
void timeInRounds(std::vector<solvedCase>& cases)
{
    label nRounds = 0;
    for (const solvedCase& c : cases)
    {
        nRounds = max(nRounds, c.nTimes);
    }
    for (label round = 0; round < nRounds; ++round)
    {
        for (solvedCase& c : cases)
        {
            if (round < c.nTimes)
            {
                c.times.push_back
                (
                    c.solver->matvecCpuTime(c.r.perIterMatvec < 0.05 ? 3 : 1)
                );
            }
        }
    }
    for (solvedCase& c : cases)
    {
        std::sort(c.times.begin(), c.times.end());
        c.r.perMatvec = c.times[c.times.size()/2];
        c.solver.reset();
    }
}


const char* header3 =
    " direct: s/matvec (median) | s/iter (GMRES) | s/solve | iters |"
    " treecode: s/matvec (median) | s/iter (GMRES) | s/solve | iters |"
    " FMM: s/matvec (median) | s/iter (GMRES) | s/solve | iters |\n"
    "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";


void printRuns(const run& d, const run& t, const run& f)
{
    for (const run* r : {&d, &t, &f})
    {
        std::printf
        (
            " %.3e | %.3e | %.3e | %d |", r->perMatvec, r->perIter,
            r->perSolve, r->iterations
        );
    }
    std::printf("\n");
    std::fflush(stdout);
}


// Thread CPU time [s]
double cpuNow()
{
    timespec ts;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return ts.tv_sec + 1e-9*ts.tv_nsec;
}


scalar relL2(const vectorField& a, const vectorField& b)
{
    return Foam::sqrt(sum(magSqr(a - b))/sum(magSqr(b)));
}


scalar relL2(const scalarField& a, const scalarField& b)
{
    return Foam::sqrt(sum(sqr(a - b))/sum(sqr(b)));
}


// Least-squares slope of log t against log x
scalar slope(const std::vector<scalar>& x, const std::vector<scalar>& t)
{
    const label n = x.size();
    scalar sx = 0, sy = 0, sxx = 0, sxy = 0;
    for (label i = 0; i < n; ++i)
    {
        const scalar lx = Foam::log(x[i]), ly = Foam::log(t[i]);
        sx += lx; sy += ly; sxx += lx*lx; sxy += lx*ly;
    }
    return (n*sxy - sx*sy)/(n*sxx - sx*sx);
}


scalar imageSeries(const scalar kt, const scalar dR)
{
    scalar s = 0;
    for (label n = 1; n < 1000000; ++n)
    {
        const scalar t =
            (1 - kt)*n/((1 + kt)*n + 1)*std::pow(1/(1 + dR), 2*(n + 1));
        s += t;
        if (mag(t) < 1e-15*mag(s)) break;
    }
    return s/(8*pi);
}


// Section 5: one table of fast-sum errors and costs on the patch centres x
// (normals nrm, areas a) of a set of spheres: the smooth density qs (q =
// a sigma) and random charges qr
void fastSumTable
(
    const pointField& x,
    const vectorField& nrm,
    const scalarField& qs,
    const scalarField& qr,
    const std::vector<label>& orders,
    const std::vector<scalar>& thetas
)
{
    vectorField Es, Er;
    scalarField ps, pr;
    bemTreecode::direct(x, qs, x, true, Es, &ps);
    bemTreecode::direct(x, qr, x, true, Er, &pr);
    const scalarField nEs(nrm & Es);
    const label N = x.size();

    std::printf
    (
        "| method | p | theta | leaf | smooth: E | phi | n.E | random: E |"
        " phi | s/evaluation (median of 5) | P2P pairs/target |"
        " M2L/target |\n|---|---|---|---|---|---|---|---|---|---|---|---|\n"
    );
    auto row = [&]
    (
        const char* name, const label p, const scalar theta,
        const label leaf,
        const std::function<void(const scalarField&, vectorField&,
            scalarField*)>& eval,
        const std::function<scalar()>& nDirect,
        const std::function<scalar()>& nM2L
    )
    {
        vectorField E;
        scalarField ph;
        eval(qs, E, &ph);
        const scalar eEs = relL2(E, Es), ePs = relL2(ph, ps);
        const scalar enE = relL2(scalarField(nrm & E), nEs);
        eval(qr, E, &ph);
        const scalar eEr = relL2(E, Er), ePr = relL2(ph, pr);
        std::vector<double> t;
        for (label r = 0; r < 5; ++r)
        {
            const double t0 = cpuNow();
            eval(qs, E, nullptr);
            t.push_back(cpuNow() - t0);
        }
        std::sort(t.begin(), t.end());
        std::printf
        (
            "| %s | %d | %.2f | %d | %.1e | %.1e | %.1e | %.1e | %.1e |"
            " %.3e | %.0f | %.1f |\n", name, p, theta, leaf, eEs, ePs, enE,
            eEr, ePr, t[2], nDirect()/N, nM2L()/N
        );
        std::fflush(stdout);
    };

    const bemSolverControls c;
    {
        const bemTreecode tc(x, c.theta, c.order, c.leafSize);
        row
        (
            "treecode", c.order, c.theta, c.leafSize,
            [&](const scalarField& q, vectorField& E, scalarField* ph)
            { tc.evaluate(q, x, true, E, ph); },
            [&]() { return tc.nDirect(); },
            [&]() { return tc.nMultipole(); }
        );
    }
    for (const label p : orders)
    {
        for (const scalar th : thetas)
        {
            const bemFmm f(x, p, th, c.fmmLeafSize);
            const bool dflt = p == c.fmmOrder && th == c.fmmTheta;
            row
            (
                dflt ? "**FMM (default)**" : "FMM", p, th, c.fmmLeafSize,
                [&](const scalarField& q, vectorField& E, scalarField* ph)
                { f.evaluate(q, x, true, E, ph); },
                [&]() { return f.nDirect(); },
                [&]() { return f.nMultipole(); }
            );
        }
    }
}


// Patch centres, normals and charges of np unit spheres n patches each
// along x (centre distance 2 + gap): smooth density sigma = +-cos t (about
// z, alternating sign) and random charges a U(-1, 1)
void sphereSet
(
    const label np,
    const label n,
    const scalar gap,
    pointField& x,
    vectorField& nrm,
    scalarField& qs,
    scalarField& qr
)
{
    const ellipsoidSurfaceMesh m(vector(1, 1, 1), n);
    const label ns = m.size();
    x.setSize(np*ns);
    nrm.setSize(np*ns);
    qs.setSize(np*ns);
    qr.setSize(np*ns);
    std::mt19937 rng(11);
    std::uniform_real_distribution<scalar> U(-1, 1);
    for (label p = 0; p < np; ++p)
    {
        for (label k = 0; k < ns; ++k)
        {
            const label i = p*ns + k;
            x[i] = m.centres()[k] + vector(p*(2 + gap), 0, 0);
            nrm[i] = m.normals()[k];
            qs[i] = (p % 2 ? -1 : 1)*m.areas()[k]*m.centres()[k].z();
            qr[i] = m.areas()[k]*U(rng);
        }
    }
}

//- Section 1: 1. patches per particle
void patchesPerParticle(const bool quick)
{
    std::vector<label> ns =
        quick ? std::vector<label>{100, 392, 1000}
      : std::vector<label>{100, 200, 392, 800, 1600, 3200, 5000};
    std::printf
    (
        "\n## 1. Two spheres, gap 0.5R, kappa_p 10: time vs patches per"
        " particle n\n\n| n | N |%s", header3
    );
    const bemMatvecMethod mvs[3] =
    {
        bemMatvecMethod::direct, bemMatvecMethod::treecode,
        bemMatvecMethod::fmm
    };
    std::vector<solvedCase> cases;
    for (const label n : ns)
    {
        for (const bemMatvecMethod mv : mvs)
        {
            cases.push_back(solveSpheres(2, n, 0.5, mv, true));
        }
    }
    timeInRounds(cases);
    std::vector<scalar> x, td, tt, tf;
    for (size_t i = 0; i < ns.size(); ++i)
    {
        const label n = ns[i];
        const run& d = cases[3*i].r;
        const run& t = cases[3*i + 1].r;
        const run& f = cases[3*i + 2].r;
        std::printf("| %d | %d |", n, 2*n);
        printRuns(d, t, f);
        // Fit over n >= 392 (smaller n: fixed costs dominate)
        if (n >= 392)
        {
            x.push_back(n);
            td.push_back(d.perMatvec);
            tt.push_back(t.perMatvec);
            tf.push_back(f.perMatvec);
        }
    }
    std::printf
    (
        "\nFitted exponent of the median matvec time vs n (n >= 392):"
        " direct %.3f, treecode %.3f, FMM %.3f (Ruan: GMRES alone 2,"
        " FMM 1.564)\n", slope(x, td), slope(x, tt), slope(x, tf)
    );
}


//- Section 1b: 1b. larger n, fast sums only (the direct sum would take minutes)
void largerPatchCounts()
{
    std::printf
    (
        "\n## 1b. Two spheres, gap 0.5R: treecode and FMM, larger n\n\n"
        "| n | N | treecode: s/matvec (median) | s/iter (GMRES) | s/solve |"
        " iters | FMM: s/matvec (median) | s/iter (GMRES) | s/solve |"
        " iters |\n|---|---|---|---|---|---|---|---|---|---|\n"
    );
    const std::vector<label> ns{1600, 5000, 10000, 20000};
    std::vector<solvedCase> cases;
    for (const label n : ns)
    {
        cases.push_back
        (
            solveSpheres(2, n, 0.5, bemMatvecMethod::treecode, true)
        );
        cases.push_back(solveSpheres(2, n, 0.5, bemMatvecMethod::fmm, true));
    }
    timeInRounds(cases);
    std::vector<scalar> x, tt, tf;
    for (size_t i = 0; i < ns.size(); ++i)
    {
        const run& t = cases[2*i].r;
        const run& f = cases[2*i + 1].r;
        std::printf("| %d | %d |", ns[i], 2*ns[i]);
        for (const run* r : {&t, &f})
        {
            std::printf
            (
                " %.3e | %.3e | %.3e | %d |", r->perMatvec, r->perIter,
                r->perSolve, r->iterations
            );
        }
        std::printf("\n");
        std::fflush(stdout);
        x.push_back(ns[i]);
        tt.push_back(t.perMatvec);
        tf.push_back(f.perMatvec);
    }
    std::printf
    (
        "\nFitted exponent of the matvec time vs n (n = 1600..20000):"
        " treecode %.3f, FMM %.3f\n", slope(x, tt), slope(x, tf)
    );
}


//- Section 2: 2. particle number
void particleNumber(const bool quick)
{
    std::vector<label> nps =
        quick ? std::vector<label>{2, 5, 10}
      : std::vector<label>{2, 5, 10, 20, 50, 100};
    std::printf
    (
        "\n## 2. Np spheres in a row, n = 392, gap 0.2R, kappa_p 10:"
        " time vs Np\n\n| Np | N |%s", header3
    );
    const bemMatvecMethod mvs[3] =
    {
        bemMatvecMethod::direct, bemMatvecMethod::treecode,
        bemMatvecMethod::fmm
    };
    std::vector<solvedCase> cases;
    for (const label np : nps)
    {
        for (const bemMatvecMethod mv : mvs)
        {
            cases.push_back(solveSpheres(np, 392, 0.2, mv, true));
        }
    }
    timeInRounds(cases);
    std::vector<scalar> x, td, tt, tf;
    for (size_t i = 0; i < nps.size(); ++i)
    {
        const label np = nps[i];
        const run& d = cases[3*i].r;
        const run& t = cases[3*i + 1].r;
        const run& f = cases[3*i + 2].r;
        std::printf("| %d | %d |", np, 392*np);
        printRuns(d, t, f);
        x.push_back(np);
        td.push_back(d.perMatvec);
        tt.push_back(t.perMatvec);
        tf.push_back(f.perMatvec);
    }
    std::printf
    (
        "\nFitted exponent of the median matvec time vs Np: direct"
        " %.3f, treecode %.3f, FMM %.3f (Ruan: GMRES alone 2, FMM"
        " 1.333)\n", slope(x, td), slope(x, tt), slope(x, tf)
    );
}


//- Section 3: 3. preconditioner
void preconditioner()
{
    std::printf
    (
        "\n## 3. GMRES iterations (tolerance 1e-4): block-diagonal (self"
        " block LU) against diagonal (Jacobi) preconditioning, n = 392\n\n"
        "| case | kappa_p | block LU | diagonal |\n|---|---|---|---|\n"
    );
    for (const scalar kp : {10.0, 100.0})
    {
        for (const label np : {2, 20})
        {
            const scalar gap = np == 2 ? 0.1 : 0.2;
            const bemMatvecMethod mv = bemSolverControls().matvec;
            const run a = spheres(np, 392, gap, mv, true, kp);
            const run b = spheres(np, 392, gap, mv, false, kp);
            std::printf
            (
                "| %d spheres, gap %.1fR | %g | %d | %d |\n",
                np, gap, kp, a.iterations, b.iterations
            );
            std::fflush(stdout);
        }
    }
}


//- Section 4: 4. accuracy vs cost, App. A
void accuracyVsCost(const bool quick)
{
    const scalar eps0 = pairwiseCoulomb::vacuumPermittivity;
    std::printf
    (
        "\n## 4. Accuracy vs cost, Ruan App. A (point charge + sphere,"
        " kappa ratio 10)\n\n"
        "| d/R | mesh | n | rel. error of U | s/solve (incl. meshing and set-up) |\n"
        "|---|---|---|---|---|\n"
    );
    std::vector<label> ns =
        quick ? std::vector<label>{250, 1000}
      : std::vector<label>{100, 250, 500, 1000, 2000};
    for (const scalar dR : {0.05, 0.5})
    {
        for (const label graded : {0, 1})
        {
            for (const label n : ns)
            {
                cpuTime ct;
                bemSolver s(1);
                const scalar lam =
                    graded ? min(1.0, 0.6*Foam::sqrt(dR)) : 1.0;
                const label sh =
                    s.shape(vector(1, 1, 1), n, vector(1, 0, 0), lam);
                s.addParticle(sh, point::zero, tensor::I, 10, 0.0);
                s.addPointCharge(point(1 + dR, 0, 0), 1.0);
                s.solve();
                const scalar err =
                    s.energy()*eps0/imageSeries(10, dR) - 1;
                std::printf
                (
                    "| %.2f | %s | %d | %+.2e | %.3f |\n", dR,
                    graded ? "graded" : "uniform", n, err,
                    ct.elapsedCpuTime()
                );
                std::fflush(stdout);
            }
        }
    }
}


//- Section 5: 5. accuracy and cost of the fast sums alone
void fastSums(const bool quick)
{
    const std::vector<label> orders =
        quick ? std::vector<label>{3, 5} : std::vector<label>{2, 3, 4, 5, 6, 8};
    const std::vector<scalar> thetas =
        quick ? std::vector<scalar>{0.5} : std::vector<scalar>{0.4, 0.5, 0.6};
    pointField x;
    vectorField nrm;
    scalarField qs, qr;
    std::printf
    (
        "\n## 5. Fast sums against the direct sum: relative L2 error"
        " and CPU time per evaluation (field only)\n\n"
        "### 5a. One sphere, n = 1600, smooth sigma = cos t\n\n"
    );
    sphereSet(1, 1600, 0, x, nrm, qs, qr);
    fastSumTable(x, nrm, qs, qr, orders, thetas);
    const label n = quick ? 1600 : 5000;
    std::printf
    (
        "\n### 5b. Two spheres, gap 0.5R, n = %d each, smooth sigma ="
        " +-cos t\n\n", n
    );
    sphereSet(2, n, 0.5, x, nrm, qs, qr);
    fastSumTable(x, nrm, qs, qr, orders, thetas);
}


} // namespace


int main(int argc, char *argv[])
{
    argList::addNote("Cost of the BEM solver (Ruan 2022, Fig. 3 set-ups)");
    argList::noParallel();
    argList::noFunctionObjects();
    argList::addBoolOption("quick", "smaller sizes (a smoke test)");
    argList::addOption
    (
        "section", "name", "run only this section: 1, 1b, 2, 3, 4 or 5"
    );
    argList args(argc, argv);
    const bool quick = args.found("quick");
    const word only = args.getOrDefault<word>("section", "");
    auto section = [&](const char* sec) { return only.empty() || only == sec; };

    // 1. patches per particle
    if (section("1"))
    {
        patchesPerParticle(quick);
    }

    // 1b. larger n, fast sums only (the direct sum would take minutes)
    if (!quick && section("1b"))
    {
        largerPatchCounts();
    }

    // 2. particle number
    if (section("2"))
    {
        particleNumber(quick);
    }

    // 3. preconditioner
    if (section("3"))
    {
        preconditioner();
    }

    // 4. accuracy vs cost, App. A
    if (section("4"))
    {
        accuracyVsCost(quick);
    }

    // 5. accuracy and cost of the fast sums alone
    if (section("5"))
    {
        fastSums(quick);
    }

    return 0;
}


// ************************************************************************* //
