/*---------------------------------------------------------------------------*\
    chargedFoam: benchmark of the tri-periodic electrostatics kernels
-------------------------------------------------------------------------------
Application
    periodicElectrostaticsBenchmark

Description
    Time per force evaluation and force error vs Ewald for a mono-charged
    uniform random cloud (Boutsikakis 2023, Sec. 2.1.2: L = 2 pi m,
    Q = 5 nC) of Np = 1e3 .. 1e6 charges:
      - direct:     quasi-periodic direct sum, Nper = 1 (Eq. 9);
      - direct-dip: the same minus the minimum-image dipole term (its limit
                    for Nper -> inf is Ewald; see quasiPeriodicDirect.H);
      - pseudo:     pseudo-particle method, Nv = 1, Nper = 1, optimal Ne
                    (App. A.2);
      - p3m:        P3M at the requested relative accuracy (default 1e-4
                    of k <q^2> n^(2/3)), parameters chosen automatically;
      - lammps:     Debian's LAMMPS PPPM (kspace_style pppm, pair coul/long,
                    order 5) on the same charges, same real-space cutoff as
                    p3m, absolute accuracy accuracy*F0/sqrt(2) (LAMMPS
                    meets the accuracy by the real and the k-space part
                    each, p3m by their rms sum).
    Reference: Ewald (tolerance 1e-10) on all particles up to 5000, else on
    a random subset of 1000 targets (300 above 2e5). Errors per particle |F - F_Ewald|/|F_Ewald|
    in the bins of Boutsikakis 2023, Fig. 14 / Table 3.

    Timings: median over repeats (single thread); p3m and LAMMPS without
    their set-up (parameter choice, influence function, FFT plans);
    LAMMPS = (Pair + Kspace)/steps from its timing breakdown of 10 steps of
    frozen atoms (its neighbour list is built once, outside), ours
    includes the cell-list build.

Usage
    periodicElectrostaticsBenchmark [-quick] [-N '(1000 10000)']
        [-accuracy 1e-4] [-noLammps] [-runs DIR] [-seed S]
        [-maxDirect 100000] [-maxPseudo 1000000]
    periodicElectrostaticsBenchmark -N '(100)' -layers 8
        (Boutsikakis Figs. 6-7: the quasi-periodic sum's energy and forces
        against the number of periodic layers)

\*---------------------------------------------------------------------------*/

#include "argList.H"
#include "ewaldSum.H"
#include "quasiPeriodicDirect.H"
#include "pseudoParticle.H"
#include "p3m.H"
#include "mathematicalConstants.H"
#include "Random.H"
#include "OFstream.H"
#include "IFstream.H"
#include "OSspecific.H"
#include "clock.H"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>
#include <algorithm>
#include <thread>

using namespace Foam;

namespace
{

double now()
{
    return std::chrono::duration<double>
    (
        std::chrono::steady_clock::now().time_since_epoch()
    ).count();
}

// Median time of f() over repeats: at least 1 run, more while the total
// stays below ~1.5 s (at most 7)
template<class F>
double timeIt(F f)
{
    std::vector<double> t;
    double total = 0;
    while (t.size() < 7)
    {
        const double t0 = now();
        f();
        t.push_back(now() - t0);
        total += t.back();
        if (total > 1.5 && t.size() >= 1) break;
    }
    std::sort(t.begin(), t.end());
    return t[t.size()/2];
}

struct Row
{
    std::string method;
    double time;
    bool haveErr;
    periodicForceError err;
    std::string note;
};

// Result of one LAMMPS run
struct lammpsResult
{
    bool ok = false;
    double pair = 0, kspace = 0, loop = 0;
    int steps = 0;
    std::string grid, gEwald, estAbs;
    List<vector> f;
};

std::string lammpsExe()
{
    for (const char* exe : {"lmp", "lmp_serial"})
    {
        const std::string cmd =
            std::string("command -v ") + exe + " >/dev/null 2>&1";
        if (std::system(cmd.c_str()) == 0) return exe;
    }
    return "";
}

// Run LAMMPS PPPM in lj units: lengths as ours, charges q/q0, so that
// F = k q0^2 F_lammps
lammpsResult runLammps
(
    const std::string& exe,
    const fileName& dir,
    const vector& L,
    const pointField& x,
    const scalarField& qt,
    const scalar rCut,
    const scalar absAccuracy,
    const label order,
    const label steps
)
{
    lammpsResult r;
    mkDir(dir);
    {
        std::ofstream os((dir/"data.lmp").c_str());
        char b[256];
        os << "chargedFoam periodicElectrostatics benchmark\n\n"
           << x.size() << " atoms\n1 atom types\n\n";
        std::snprintf(b, sizeof(b), "0 %.17g xlo xhi\n0 %.17g ylo yhi\n"
            "0 %.17g zlo zhi\n\nMasses\n\n1 1\n\nAtoms # charge\n\n",
            L.x(), L.y(), L.z());
        os << b;
        forAll(x, i)
        {
            std::snprintf(b, sizeof(b), "%d 1 %.17g %.17g %.17g %.17g\n",
                int(i + 1), qt[i], x[i].x(), x[i].y(), x[i].z());
            os << b;
        }
    }
    {
        std::ofstream os((dir/"in.lmp").c_str());
        char b[512];
        std::snprintf(b, sizeof(b),
            "units lj\natom_style charge\nboundary p p p\n"
            "read_data data.lmp\n"
            "pair_style coul/long %.17g\npair_coeff * *\n"
            "kspace_style pppm 1e-4\n"
            "kspace_modify force %.17g order %d\n"
            "neighbor 0.0 bin\nneigh_modify one 20000 page 2000000\n"
            "thermo_style custom step pe\n"
            "dump d all custom 1 forces.dump id fx fy fz\n"
            "dump_modify d sort id format float %%.17g\n"
            "run 0\nundump d\nrun %d\n",
            rCut, absAccuracy, int(order), int(steps));
        os << b;
    }
    const std::string cmd =
        "cd '" + dir + "' && OMP_NUM_THREADS=1 " + exe
      + " -in in.lmp -log log.lammps -screen none > lammps.stdout 2>&1";
    if (std::system(cmd.c_str()) != 0)
    {
        std::printf("    LAMMPS failed: see %s/lammps.stdout\n", dir.c_str());
        return r;
    }

    // Log: PPPM parameters, the timing breakdown of the last run
    std::ifstream log((dir/"log.lammps").c_str());
    std::string line;
    while (std::getline(log, line))
    {
        auto after = [&](const std::string& key, std::string& v)
        {
            const auto p = line.find(key);
            if (p != std::string::npos) v = line.substr(p + key.size());
        };
        after("grid = ", r.grid);
        after("G vector (1/distance) = ", r.gEwald);
        after("estimated absolute RMS force accuracy = ", r.estAbs);
        if (line.rfind("Loop time of ", 0) == 0)
        {
            std::sscanf(line.c_str(), "Loop time of %lf on %*d procs for %d",
                &r.loop, &r.steps);
        }
        double mn, av;
        if (std::sscanf(line.c_str(), "Pair | %lf | %lf", &mn, &av) == 2)
        {
            r.pair = av;
        }
        if (std::sscanf(line.c_str(), "Kspace | %lf | %lf", &mn, &av) == 2)
        {
            r.kspace = av;
        }
    }

    std::ifstream dump((dir/"forces.dump").c_str());
    r.f.setSize(x.size(), Zero);
    label nRead = 0;
    bool atoms = false;
    while (std::getline(dump, line))
    {
        if (!atoms)
        {
            atoms = (line.rfind("ITEM: ATOMS", 0) == 0);
            continue;
        }
        std::istringstream is(line);
        long id;
        double fx, fy, fz;
        if (is >> id >> fx >> fy >> fz && id >= 1 && id <= x.size())
        {
            r.f[id - 1] = vector(fx, fy, fz);
            ++nRead;
        }
    }
    r.ok = (nRead == x.size() && r.steps > 0);
    return r;
}

//- The benchmark's settings
struct settings
{
    scalar accuracy;
    label seed;
    label maxDirect;
    label maxPseudo;
    fileName runs;
    std::string lmp;
    vector L;
    scalar Q;
};


//- N charges Q at random in the box [0, L) (the sequence of rnd)
void makeCloud
(
    const label N,
    Random& rnd,
    const vector& L,
    const scalar Q,
    pointField& x,
    scalarField& q
)
{
    x.setSize(N);
    q.setSize(N);
    q = Q;
    for (label i = 0; i < N; ++i)
    {
        x[i] = cmptMultiply
        (
            L,
            vector
            (
                rnd.sample01<scalar>(), rnd.sample01<scalar>(),
                rnd.sample01<scalar>()
            )
        );
    }
}


//- p3m only: time and estimated error for the cutoffs rcs at N charges
void sweepCutoffs(const settings& s, const label N, const scalarList& rcs)
{
    const scalar Q = s.Q;
    const vector& L = s.L;
    const scalar accuracy = s.accuracy;
    Random rnd(s.seed);
    pointField x;
    scalarField q;
    makeCloud(N, rnd, L, Q, x, q);
    std::printf("| rc | alpha | mesh | est. error/target | real [s] |"
        " kspace [s] | total [s] |\n|---|---|---|---|---|---|---|\n");
    for (const scalar rc : rcs)
    {
        dictionary dict;
        dict.add("L", L);
        dict.add("accuracy", accuracy);
        dict.add("rCut", rc);
        const p3m pm(dict);
        pm.tune(N, N*Q*Q);
        List<vector> f;
        double tr = GREAT, tk = GREAT, tt = GREAT;
        for (int r = 0; r < 3; ++r)
        {
            const double t0 = now();
            pm.compute(x, q, f);
            tt = std::min(tt, now() - t0);
            tr = std::min(tr, double(pm.timeReal_));
            tk = std::min(tk, double(pm.timeKspace_));
        }
        const p3m::parameters& p = pm.params();
        std::printf("| %.4g | %.4g | %d | %.3g | %.4g | %.4g | %.4g |\n",
            p.rCut, p.alpha, int(p.mesh[0]), p.error/p.target, tr, tk,
            tt);
    }
}


//- Boutsikakis 2023 Figs. 6-7 at N charges: the quasi-periodic direct sum
//  for Nper = 1 .. NperMax: the mean particle energy <u_e> = <q phi> (Eq.
//  12) over the uniformly charged cube's limit k rho a^2 C Q, a = (2 Nper -
//  1) L, C = 3 ln(2 + sqrt 3) - pi/2 (the potential at a unit cube's
//  centre, rho of the N - 1 others); <|F|>; the per-particle error against
//  Nper = NperMax (Fig. 7's bins), against Ewald, and with the
//  minimum-image dipole term removed against Ewald (its limit)
void layers(const settings& s, const label N, const label NperMax)
{
    const vector& L = s.L;
    Random rnd(s.seed);
    pointField x;
    scalarField q;
    makeCloud(N, rnd, L, s.Q, x, q);
    List<vector> fEwald, fMax;
    ewaldSum(L).compute(x, q, fEwald);
    quasiPeriodicDirect(L, 1, NperMax).compute(x, q, fMax);
    const scalar V = L.x()*L.y()*L.z();
    const scalar cubeCentre =
        3*Foam::log(2 + Foam::sqrt(3.0)) - constant::mathematical::pi/2;
    const scalar kc = ewaldSum(L).k();

    std::printf("### Periodic layers (Boutsikakis Figs. 6-7), Np = %d\n\n",
        int(N));
    std::printf("| Nper | <u_e> [J] | <u_e>/cube limit | <abs F> [N] |"
        " vs Nper = %d: rms rel. | median | bins 0-1/1-5/5-10/10-20/20-50/>50 %%"
        " | vs Ewald: rms rel. | median | minus dipole vs Ewald: rms rel."
        " | median | time [s] |\n", int(NperMax));
    std::printf("|---|---|---|---|---|---|---|---|---|---|---|---|\n");
    for (label Nper = 1; Nper <= NperMax; ++Nper)
    {
        const quasiPeriodicDirect direct(L, 1, Nper);
        List<vector> f;
        scalarField phi;
        const double t = timeIt([&](){ direct.compute(x, q, f); });
        direct.potentials(x, q, phi);
        const scalar ue = average(q*phi);
        const scalar a = (2*Nper - 1)*cmptAv(L);
        const scalar limit = kc*(N - 1)*s.Q/V*a*a*cubeCentre*s.Q;
        scalar meanF = 0;
        for (const vector& v : f) meanF += mag(v);
        meanF /= N;
        const periodicForceError eMax(f, fMax), eEw(f, fEwald);
        List<vector> fc(f);
        direct.addMinImageDipole(x, q, fc, -1);
        const periodicForceError eDip(fc, fEwald);
        std::printf("| %d | %.5g | %.5f | %.5g | %.3g | %.3g |", int(Nper),
            ue, ue/limit, meanF, eMax.rmsAbs/eMax.rmsRef, eMax.median);
        for (label b = 0; b < 6; ++b)
        {
            std::printf("%s%.0f", b ? "/" : " ", 100*eMax.bins[b]);
        }
        std::printf(" | %.3g | %.3g | %.3g | %.3g | %.3g |\n",
            eEw.rmsAbs/eEw.rmsRef, eEw.median, eDip.rmsAbs/eDip.rmsRef,
            eDip.median, t);
        std::fflush(stdout);
    }
    std::printf("\n");
}


//- The Ewald reference: on all charges, or on a random subset of targets
//  (N > 5000) drawn from rnd; its row first in rows
void ewaldReference
(
    const vector& L,
    Random& rnd,
    const pointField& x,
    const scalarField& q,
    labelList& targets,
    List<vector>& fE,
    std::vector<Row>& rows
)
{
    const label N = x.size();
    // Ewald reference on all or on a subset of targets
    targets.clear();
    if (N > 5000)
    {
        const label M = (N > 200000) ? 300 : 1000;
        labelList perm(identity(N));
        for (label k = 0; k < M; ++k)
        {
            const label j = k + rnd.position<label>(0, N - 1 - k);
            std::swap(perm[k], perm[j]);
        }
        targets = SubList<label>(perm, M);
    }
    const ewaldSum ewald(L);
    fE.setSize(N);
    fE = Zero;
    double tE;
    {
        const double t0 = now();
        if (targets.empty())
        {
            ewald.compute(x, q, fE);
        }
        else
        {
            List<vector> fs;
            ewald.forces(x, q, targets, fs);
            forAll(targets, k) fE[targets[k]] = fs[k];
        }
        tE = now() - t0;
    }
    rows.push_back
    ({
        "ewald (reference)", tE, false, periodicForceError(fE, fE, targets),
        targets.empty() ? "all particles"
      : ("on " + std::to_string(targets.size()) + " targets")
    });
}


//- The quasi-periodic rows: direct Nper = 1 (with and without the
//  minimum-image dipole) and the pseudo-particle method
void quasiPeriodicRows
(
    const settings& s,
    const pointField& x,
    const scalarField& q,
    const List<vector>& fE,
    const labelList& idx,
    std::vector<Row>& rows
)
{
    const label N = x.size();
    const vector& L = s.L;
    // Direct, Nper = 1, and minus the dipole term
    List<vector> fDirect;
    if (N <= s.maxDirect)
    {
        const quasiPeriodicDirect direct(L);
        List<vector> f;
        const double t = timeIt([&](){ direct.compute(x, q, f); });
        fDirect = f;
        rows.push_back({"direct Nper=1", t, true,
            periodicForceError(f, fE, idx), ""});
        const double t1 = now();
        direct.addMinImageDipole(x, q, f, -1);
        rows.push_back({"direct-dip Nper=1", t + now() - t1, true,
            periodicForceError(f, fE, idx), "minus min-image dipole"});
    }

    // Pseudo-particle, optimal Ne; also against the direct sum (the
    // measure of Boutsikakis 2023, Fig. 14 / Table 3)
    if (N <= s.maxPseudo)
    {
        const pseudoParticle pp(L);
        List<vector> f;
        const double t = timeIt([&](){ pp.compute(x, q, f); });
        rows.push_back({"pseudo Nv=1 Nper=1", t, true,
            periodicForceError(f, fE, idx),
            "Ne = " + std::to_string(pp.Ne(N))});
        if (fDirect.size() == N)
        {
            rows.push_back({"pseudo vs direct", t, true,
                periodicForceError(f, fDirect, idx),
                "error measured against direct Nper=1, not Ewald"});
        }
    }
}


//- The P3M rows at the accuracy and 10x and 100x looser; returns the
//  forces at the accuracy and its cutoff and Coulomb constant
List<vector> p3mRows
(
    const settings& s,
    const pointField& x,
    const scalarField& q,
    const List<vector>& fE,
    const labelList& idx,
    std::vector<Row>& rows,
    scalar& rCut,
    scalar& k
)
{
    const label N = x.size();
    const vector& L = s.L;
    const scalar Q = s.Q;
    const scalar accuracy = s.accuracy;
    // P3M
    const p3m pm(L, 1, accuracy);
    double tSetup;
    {
        const double t0 = now();
        pm.tune(N, N*Q*Q);
        tSetup = now() - t0;
    }
    List<vector> fP;
    const double tP = timeIt([&](){ pm.compute(x, q, fP); });
    const p3m::parameters& pp = pm.params();
    char note[512];
    std::snprintf(note, sizeof(note), "rc %.4g a %.4g mesh %d P %d,"
        " est. %.3g (target %.3g) N; real %.3g s, kspace %.3g s;"
        " setup %.2f s", pp.rCut, pp.alpha, int(pp.mesh[0]),
        int(pp.order), pp.error, pp.target, pm.timeReal_,
        pm.timeKspace_, tSetup);
    rows.push_back({"p3m", tP, true, periodicForceError(fP, fE, idx),
        note});

    // P3M at 10x and 100x looser accuracy: still far below the error
    // of the quasi-periodic methods (the pseudo-particle comparison)
    for (const scalar loosen : {10.0, 100.0})
    {
        const p3m pl(L, 1, min(0.1, loosen*accuracy));
        pl.tune(N, N*Q*Q);
        List<vector> fl;
        const double tl = timeIt([&](){ pl.compute(x, q, fl); });
        const p3m::parameters& pq = pl.params();
        std::snprintf(note, sizeof(note), "rc %.4g a %.4g mesh %d P %d,"
            " est. %.3g (target %.3g) N", pq.rCut, pq.alpha,
            int(pq.mesh[0]), int(pq.order), pq.error, pq.target);
        rows.push_back
        ({
            "p3m accuracy " + std::to_string(loosen*accuracy)
                .substr(0, 6), tl, true,
            periodicForceError(fl, fE, idx), note
        });
    }
    rCut = pp.rCut;
    k = pm.k();
    return fP;
}


//- LAMMPS PPPM at the accuracy and 10x tighter, at P3M's cutoff rCut
//  (forces scaled by the Coulomb constant k); their rows, and their
//  results in lrs
void lammpsRows
(
    const settings& s,
    const pointField& x,
    const scalarField& q,
    const scalar rCut,
    const scalar k,
    const List<vector>& fE,
    const labelList& idx,
    std::vector<Row>& rows,
    std::vector<lammpsResult>& lrs
)
{
    const label N = x.size();
    const vector& L = s.L;
    const scalar Q = s.Q;
    char note[512];
    // LAMMPS PPPM at the nominal accuracy and 10x tighter (its measured
    // error can exceed ours at the nominal one: equal accuracy is then
    // bracketed)
    if (!s.lmp.empty())
    {
        scalarField qt(q/Q);
        pointField xw(N);
        forAll(x, i)
        {
            for (direction d = 0; d < 3; ++d)
            {
                xw[i][d] = x[i][d] - L[d]*std::floor(x[i][d]/L[d]);
            }
        }
        const scalar n = N/(L.x()*L.y()*L.z());
        const scalar F0t = Foam::pow(n, 2.0/3.0);  // <qt^2> = 1
        for (const scalar tighten : {1.0, 10.0})
        {
            // acc/10 needs ~N^(4/3) mesh memory: 1.1 GB at 1e5
            if (tighten > 1 && N > 200000) continue;
            lammpsResult lr = runLammps
            (
                s.lmp,
                s.runs/("N" + std::to_string(N) + "_acc"
              + std::to_string(int(tighten))),
                L, xw, qt, rCut,
                s.accuracy*F0t/Foam::sqrt(2.0)/tighten, 5, 10
            );
            if (!lr.ok) continue;
            const scalar c = k*Q*Q;
            forAll(lr.f, i) lr.f[i] *= c;
            const double t = (lr.pair + lr.kspace)/lr.steps;
            std::snprintf(note, sizeof(note), "grid %s, g_ewald %s,"
                " est. abs. %s (lj units), pair %.3g s, kspace %.3g s"
                " per step", lr.grid.c_str(), lr.gEwald.c_str(),
                lr.estAbs.c_str(), lr.pair/lr.steps,
                lr.kspace/lr.steps);
            rows.push_back
            ({
                tighten == 1 ? "lammps pppm" : "lammps pppm acc/10", t,
                true, periodicForceError(lr.f, fE, idx), note
            });
            lrs.push_back(lr);
        }
    }
}


//- The table of the rows of N charges
void printTable(const label N, const std::vector<Row>& rows)
{
    // Table
    std::printf("### Np = %d\n\n", int(N));
    std::printf("| method | time/eval [s] | rms err/rms F | median"
        " rel. err | p90 | 0-1 %% | 1-5 %% | 5-10 %% | 10-20 %% |"
        " 20-50 %% | >50 %% | notes |\n");
    std::printf("|---|---|---|---|---|---|---|---|---|---|---|---|\n");
    for (const Row& r : rows)
    {
        std::printf("| %s | %.4g |", r.method.c_str(), r.time);
        if (r.haveErr)
        {
            const periodicForceError& e = r.err;
            std::printf(" %.3g | %.3g | %.3g |",
                e.rmsAbs/max(e.rmsRef, VSMALL), e.median, e.p90);
            for (const scalar b : e.bins)
            {
                std::printf(" %.1f |", 100*b);
            }
        }
        else
        {
            std::printf(" - | - | - | - | - | - | - | - | - |");
        }
        std::printf(" %s |\n", r.note.c_str());
    }
    std::printf("\n");
}


//- Ratios within this run: P3M against LAMMPS and the pseudo-particle
//  method
void printRatios
(
    const label N,
    const std::vector<Row>& rows,
    const List<vector>& fP,
    const std::vector<lammpsResult>& lrs
)
{
    // Ratios within this run
    auto find = [&](const std::string& m) -> const Row*
    {
        for (const Row& r : rows)
        {
            if (r.method.rfind(m, 0) == 0) return &r;
        }
        return nullptr;
    };
    const Row* rp = find("p3m");
    const Row* rl = find("lammps");
    const Row* rs = find("pseudo");
    if (rl)
    {
        scalar d = 0;
        forAll(fP, i) d += magSqr(fP[i] - lrs[0].f[i]);
        std::printf("- p3m time / LAMMPS time = %.3g (goal <= 1.5);"
            " rms |F_p3m - F_lammps| / rms F = %.3g; rms error p3m %.3g,"
            " LAMMPS %.3g", rp->time/rl->time,
            Foam::sqrt(d/N)/max(rp->err.rmsRef, VSMALL),
            rp->err.rmsAbs/rp->err.rmsRef, rl->err.rmsAbs/rl->err.rmsRef);
        const Row* rt = find("lammps pppm acc/10");
        if (rt)
        {
            std::printf("; p3m time / LAMMPS acc/10 time = %.3g"
                " (its rms error %.3g)", rp->time/rt->time,
                rt->err.rmsAbs/rt->err.rmsRef);
        }
        std::printf("\n");
    }
    if (rs)
    {
        std::printf("- pseudo time / p3m time = %.3g; p3m median error"
            " %.3g vs pseudo %.3g\n", rs->time/rp->time, rp->err.median,
            rs->err.median);
        for (const Row& r : rows)
        {
            if (r.method.rfind("p3m accuracy", 0) != 0) continue;
            std::printf("- pseudo time / %s time = %.3g; its median"
                " error %.3g, p90 %.3g (pseudo: %.3g, %.3g)\n",
                r.method.c_str(), rs->time/r.time, r.err.median,
                r.err.p90, rs->err.median, rs->err.p90);
        }
    }
    std::printf("\n");
    std::fflush(stdout);
}


//- Every method on N charges: the rows, the table and the ratios
void benchmarkN(const settings& s, const label N)
{
    Random rnd(s.seed);
    pointField x;
    scalarField q;
    makeCloud(N, rnd, s.L, s.Q, x, q);
    labelList targets;
    List<vector> fE;
    std::vector<Row> rows;
    ewaldReference(s.L, rnd, x, q, targets, fE, rows);
    const labelList& idx = targets;
    quasiPeriodicRows(s, x, q, fE, idx, rows);
    scalar rCut = 0, k = 0;
    const List<vector> fP(p3mRows(s, x, q, fE, idx, rows, rCut, k));
    std::vector<lammpsResult> lrs;
    lammpsRows(s, x, q, rCut, k, fE, idx, rows, lrs);
    printTable(N, rows);
    printRatios(N, rows, fP, lrs);
}


} // End anonymous namespace


int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Benchmark of the tri-periodic electrostatics kernels (direct,"
        " pseudo-particle, P3M) against Ewald and LAMMPS PPPM"
    );
    argList::noBanner();
    argList::noParallel();
    argList::noFunctionObjects();
    argList::removeOption("case");
    argList::addBoolOption("quick", "Np = 1000, 4000, 10000 (CI size)");
    argList::addOption("N", "list", "particle numbers, e.g. '(1000 10000)'");
    argList::addOption("accuracy", "a", "relative accuracy of p3m (1e-4)");
    argList::addBoolOption("noLammps", "skip LAMMPS");
    argList::addOption("runs", "dir", "work folder for LAMMPS runs");
    argList::addOption("seed", "S", "seed of the clouds (default 1)");
    argList::addOption("maxDirect", "N", "largest Np for direct (1e5)");
    argList::addOption("maxPseudo", "N", "largest Np for pseudo (1e6)");
    argList::addOption
    (
        "sweep", "list",
        "p3m only: time and estimated error for these rCut [m] at the first"
        " Np (check of the cost model of the automatic choice)"
    );
    argList::addOption
    (
        "layers", "NperMax",
        "only Boutsikakis Figs. 6-7: the direct sum for Nper = 1 .. NperMax"
        " at the first Np (energy, <|F|>, errors vs NperMax and Ewald)"
    );
    argList args(argc, argv);

    const bool quick = args.found("quick");
    labelList Ns
    (
        quick ? labelList({1000, 4000, 10000})
              : labelList({1000, 10000, 100000, 1000000})
    );
    args.readIfPresent("N", Ns);
    const scalar accuracy = args.getOrDefault<scalar>("accuracy", 1e-4);
    const label seed = args.getOrDefault<label>("seed", 1);
    const label maxDirect = args.getOrDefault<label>("maxDirect", 100000);
    const label maxPseudo = args.getOrDefault<label>("maxPseudo", 1000000);
    const fileName runs = args.getOrDefault<fileName>
    (
        "runs", fileName(cwd()/(quick ? "runs/quick" : "runs/full"))
    );
    const std::string lmp = args.found("noLammps") ? "" : lammpsExe();

    const scalar twoPi = constant::mathematical::twoPi;
    const vector L(twoPi, twoPi, twoPi);
    const scalar Q = 5e-9;

    std::printf("## periodicElectrostaticsBenchmark\n\n");
    std::printf("- mono-charged uniform random cloud, L = 2 pi m, Q = 5 nC"
        " (Boutsikakis 2023, Sec. 2.1.2), seed %d\n", int(seed));
    std::printf("- p3m accuracy %g (rms force error / k<q^2>n^(2/3)),"
        " order 5; LAMMPS: %s\n", accuracy,
        lmp.empty() ? "not run" : (lmp + ", pppm order 5, coul/long,"
        " same rc, kspace_modify force = accuracy*F0/sqrt(2)").c_str());
    std::printf("- build: %s\n- machine: %s, nproc %d, load %s\n\n",
        PEB_BUILD_OPTIONS, clock::dateTime().c_str(), int(std::thread::hardware_concurrency()),
        [](){ std::ifstream f("/proc/loadavg"); std::string s;
            std::getline(f, s); return s; }().c_str());

    const settings s{accuracy, seed, maxDirect, maxPseudo, runs, lmp, L, Q};
    if (args.found("layers"))
    {
        layers(s, Ns[0], args.get<label>("layers"));
        return 0;
    }
    if (args.found("sweep"))
    {
        sweepCutoffs(s, Ns[0], args.get<scalarList>("sweep"));
        return 0;
    }
    for (const label N : Ns)
    {
        benchmarkN(s, N);
    }

    return 0;
}


// ************************************************************************* //
