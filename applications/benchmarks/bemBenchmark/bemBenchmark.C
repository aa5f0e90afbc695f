/*---------------------------------------------------------------------------*\
    chargedFoam: charged dielectric particles for OpenFOAM
-------------------------------------------------------------------------------
Application
    bemBenchmark

Description
    Cost of the BEM solver (bemSolver), the set-ups of Ruan 2022, Fig. 3:
      1. two spheres R = 1, surface gap 0.5 R, n patches each, n = 100..5000;
      2. Np spheres in a row, n = 392, gap 0.2 R, Np = 2..100;
    direct O(N^2) matvec against the treecode: time per GMRES iteration
    (matvec only, and whole GMRES time / iterations), time per solve,
    iterations, and fitted exponents t ~ n^a, Np^b (Ruan with FMM: n^1.564,
    Np^1.333);
      3. GMRES iterations with and without the block preconditioner;
      4. accuracy against cost on Ruan App. A (point charge + dielectric
         sphere, kappa ratio 10): uniform and graded meshes.
    All runs single-threaded, times are thread CPU times; kappa_p = 10,
    sigma_f = 1, tolerance 1e-4, default solver controls (treecode theta
    0.3, quadrupole, leaf 32; curvature self term; near quadrature).

    Usage: bemBenchmark [-quick] [-section 1|1b|2|3|4]

\*---------------------------------------------------------------------------*/

#include "argList.H"
#include "bemSolver.H"
#include "pairwiseCoulomb.H"
#include "mathematicalConstants.H"
#include "cpuTime.H"

#include <cstdio>
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
    bemSolverControls c;
    c.matvec = mv;
    c.precondition = precondition;
    bemSolver s(1, c);
    const label sh = s.shape(vector(1, 1, 1), n);
    const scalar A = sum(s.mesh(sh).areas());
    for (label p = 0; p < np; ++p)
    {
        s.addParticle(sh, point(p*(2 + gap), 0, 0), tensor::I, kp, A);
    }
    const auto& info = s.solve();
    run r;
    r.iterations = info.iterations;
    r.perIterMatvec = info.matvecTime/max(info.iterations, label(1));
    r.perIter = info.solveTime/max(info.iterations, label(1));
    r.perSolve = info.setupTime + info.solveTime;
    r.setup = info.setupTime;
    // Median of repeated products: less sensitive to a loaded machine than
    // the few products inside one solve
    r.perMatvec = s.matvecCpuTime(mv == bemMatvecMethod::direct && np*n > 20000 ? 3 : 7);
    return r;
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

} // namespace


int main(int argc, char *argv[])
{
    argList::addNote("Cost of the BEM solver (Ruan 2022, Fig. 3 set-ups)");
    argList::noParallel();
    argList::noFunctionObjects();
    argList::addBoolOption("quick", "smaller sizes (a smoke test)");
    argList::addOption
    (
        "section", "name", "run only this section: 1, 1b, 2, 3 or 4"
    );
    argList args(argc, argv);
    const bool quick = args.found("quick");
    const word only = args.getOrDefault<word>("section", "");
    auto section = [&](const char* sec) { return only.empty() || only == sec; };

    // 1. patches per particle
    if (section("1"))
    {
        std::vector<label> ns =
            quick ? std::vector<label>{100, 392, 1000}
          : std::vector<label>{100, 200, 392, 800, 1600, 3200, 5000};
        std::printf
        (
            "\n## 1. Two spheres, gap 0.5R, kappa_p 10: time vs patches per"
            " particle n\n\n"
            "| n | N | direct: s/matvec (median) | s/iter (GMRES) | s/solve |"
            " iters | treecode: s/matvec (median) | s/iter (GMRES) | s/solve |"
            " iters |\n|---|---|---|---|---|---|---|---|---|---|\n"
        );
        std::vector<scalar> x, td, tt, sd, st;
        for (const label n : ns)
        {
            const run d = spheres(2, n, 0.5, bemMatvecMethod::direct, true);
            const run t = spheres(2, n, 0.5, bemMatvecMethod::treecode, true);
            std::printf
            (
                "| %d | %d | %.3e | %.3e | %.3e | %d | %.3e | %.3e | %.3e |"
                " %d |\n", n, 2*n, d.perMatvec, d.perIter, d.perSolve,
                d.iterations, t.perMatvec, t.perIter, t.perSolve,
                t.iterations
            );
            std::fflush(stdout);
            x.push_back(n);
            td.push_back(d.perMatvec);
            tt.push_back(t.perMatvec);
        }
        // Fit over n >= 392 (smaller n: fixed costs dominate)
        std::vector<scalar> x2, td2, tt2;
        for (size_t i = 0; i < x.size(); ++i)
        {
            if (x[i] >= 392)
            {
                x2.push_back(x[i]); td2.push_back(td[i]); tt2.push_back(tt[i]);
            }
        }
        std::printf
        (
            "\nFitted exponent of the median matvec time vs n (n >= 392):"
            " direct %.3f, treecode %.3f (Ruan: GMRES alone 2, FMM 1.564)\n",
            slope(x2, td2), slope(x2, tt2)
        );
    }

    // 1b. larger n, treecode only (the direct sum would take minutes)
    if (!quick && section("1b"))
    {
        std::printf
        (
            "\n## 1b. Two spheres, gap 0.5R: treecode only, larger n\n\n"
            "| n | N | s/matvec (median) | s/iter (GMRES) | s/solve | iters |"
            "\n|---|---|---|---|---|---|\n"
        );
        std::vector<scalar> x, tt;
        for (const label n : {1600, 5000, 10000, 20000})
        {
            const run t = spheres(2, n, 0.5, bemMatvecMethod::treecode, true);
            std::printf
            (
                "| %d | %d | %.3e | %.3e | %.3e | %d |\n", n, 2*n,
                t.perMatvec, t.perIter, t.perSolve, t.iterations
            );
            std::fflush(stdout);
            x.push_back(n);
            tt.push_back(t.perMatvec);
        }
        std::printf
        (
            "\nFitted exponent of the treecode matvec time vs n"
            " (n = 1600..20000): %.3f\n", slope(x, tt)
        );
    }

    // 2. particle number
    if (section("2"))
    {
        std::vector<label> nps =
            quick ? std::vector<label>{2, 5, 10}
          : std::vector<label>{2, 5, 10, 20, 50, 100};
        std::printf
        (
            "\n## 2. Np spheres in a row, n = 392, gap 0.2R, kappa_p 10:"
            " time vs Np\n\n"
            "| Np | N | direct: s/matvec (median) | s/iter (GMRES) | s/solve |"
            " iters | treecode: s/matvec (median) | s/iter (GMRES) | s/solve |"
            " iters |\n|---|---|---|---|---|---|---|---|---|---|\n"
        );
        std::vector<scalar> x, td, tt;
        for (const label np : nps)
        {
            const run d = spheres(np, 392, 0.2, bemMatvecMethod::direct, true);
            const run t = spheres(np, 392, 0.2, bemMatvecMethod::treecode, true);
            std::printf
            (
                "| %d | %d | %.3e | %.3e | %.3e | %d | %.3e | %.3e | %.3e |"
                " %d |\n", np, 392*np, d.perMatvec, d.perIter,
                d.perSolve, d.iterations, t.perMatvec, t.perIter,
                t.perSolve, t.iterations
            );
            std::fflush(stdout);
            x.push_back(np);
            td.push_back(d.perMatvec);
            tt.push_back(t.perMatvec);
        }
        std::printf
        (
            "\nFitted exponent of the median matvec time vs Np: direct"
            " %.3f, treecode %.3f (Ruan: GMRES alone 2, FMM 1.333)\n",
            slope(x, td), slope(x, tt)
        );
    }

    // 3. preconditioner
    if (section("3"))
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
                const run a = spheres(np, 392, gap, bemMatvecMethod::treecode, true, kp);
                const run b = spheres(np, 392, gap, bemMatvecMethod::treecode, false, kp);
                std::printf
                (
                    "| %d spheres, gap %.1fR | %g | %d | %d |\n",
                    np, gap, kp, a.iterations, b.iterations
                );
                std::fflush(stdout);
            }
        }
    }

    // 4. accuracy vs cost, App. A
    if (section("4"))
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

    return 0;
}


// ************************************************************************* //
