#!/usr/bin/env python3
"""Messages, bytes and peak memory per rank and per step of the
electrostatics rungs in parallel, measured in the processes (mpiTally.c, a
PMPI shim), under weak scaling: each rank holds the same number of parcels
and cells.

Scene: a box of P unit cubes along x (P ranks, decomposition simple (P 1 1),
10^3 cells per cube, walls; cyclic in x, y and z for the periodic rung;
with --ring cyclic in x, so that every rank has two neighbours as in the
middle of a long duct), n parcels per cube at random positions with
charges of both signs (1e-9 C scale), chargedParticleFoam without contact.
Each rung runs S0 and S steps; per step = (tally(S) - tally(S0))/(S - S0),
which removes the start-up (reading, decomposition) traffic. The parcels are
injected in one serial step first and the parallel runs continue from the
decomposed cloud (each rank reads its own parcels, as in a large run). Peak
memory is the resident high-water mark (VmHWM) of the S-step run.

    commVolume.py [--ranks 2,4,8] [--n 2000] [--steps 2,12] [--ring]
                  [--cgIterations 3]
                  [--rungs cutoffCoulomb,directCoulomb,meshPoisson,periodic,inducedDipole,bem,bemPairs]
                  [--work /tmp/commVolume]
    commVolume.py --pingpong    (latency and bandwidth between 2 ranks)
    commVolume.py --rungs shortDuct --n 400 --ranks 2,4,8
                  (tutorials/shortDuct with its parcels along the whole
                  duct, P slabs: the flagship's physics, strong scaling)

Prints one table per rung (ranks, mean and max bytes/step per rank,
messages/step per rank, all-reduce and all-to-all calls per step, peak
memory per rank in MB) and the ratio of the
bytes per rank at the largest and at 2 ranks (flat within 20 % is the weak
scaling target). More ranks than cores run oversubscribed: only volumes
and memory are meaningful then, not time.
"""
import argparse
import os
import re
import shutil
import subprocess
import sys

import numpy as np

TOP = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", ".."))
HERE = os.path.dirname(os.path.abspath(__file__))

RUNGS = {
    "cutoffCoulomb": "electrostaticsModel cutoffCoulomb;\n    cutoffCoulombCoeffs { rCut 0.2; }",
    "directCoulomb": "electrostaticsModel directCoulomb;",
    "meshPoisson": "electrostaticsModel meshPoisson;\n    meshPoissonCoeffs { radius 0.25; }",
    # Tri-periodic box (cyclic patches instead of walls), P3M at its default
    # accuracy: a halo of rCut and the mesh in slabs of x-planes
    "periodic": "electrostaticsModel periodic;\n    periodicCoeffs { method p3m; }",
    # Dielectric parcels (epsilonR 4): the cutoff sum and the induced
    # dipoles within rNear (a halo and a distributed CG)
    # The CG's iterations follow the global system (0 to 2 a step at
    # tolerance 1e-8, warm-started, more with more parcels): fixed by
    # --cgIterations (CG below) so that every rank count compares the same
    # work
    "inducedDipole": "electrostaticsModel cutoffCoulomb;\n    cutoffCoulombCoeffs { rCut 0.2; "
                     "nearField { type inducedDipole; rNear 0.05;CG } }",
    # The same with BEM clusters (none form at this density: what the
    # cluster search costs; the isolated parcels' dipoles as above)
    "bem": "electrostaticsModel cutoffCoulomb;\n    cutoffCoulombCoeffs { rCut 0.2; "
           "nearField { type bem; rNear 0.05;CG } }",
    # Every parcel in a BEM cluster: the parcels in close pairs (gap 0.2
    # radii, random directions), 200 patches per parcel
    "bemPairs": "electrostaticsModel cutoffCoulomb;\n    cutoffCoulombCoeffs { rCut 0.2; "
                "nearField { type bem; rNear 0.05; nPatches 200;CG } }",
}


def sh(cmd, cwd, log):
    with open(os.path.join(cwd, log), "w") as f:
        r = subprocess.run(cmd, cwd=cwd, stdout=f, stderr=subprocess.STDOUT, shell=True)
    text = open(os.path.join(cwd, log)).read()
    if r.returncode or "FOAM FATAL" in text:
        sys.exit(f"{cmd} failed in {cwd} (see {log}):\n{text[-2000:]}")


def cells_per_unit(rung, ring):
    """In the ring the mesh far field's halo (4 radii) must stay within
    half a rank's extent, as in a long duct (at 2 ranks the strips on
    either side are then different parcels): 20 cells per unit and radius
    2 cells there, else 10"""
    return 20 if ring and rung == "meshPoisson" else 10


def make_case(case, P, n, rung, steps, seed=1, ring=False, cg=3):
    if os.path.exists(case):
        shutil.rmtree(case)
    shutil.copytree(os.path.join(TOP, "tutorials", "twoChargedSpheres"), case,
                    ignore=shutil.ignore_patterns("[0-9]*", "processor*", "log.*"))
    # Mesh: P unit cubes along x, walls
    p = os.path.join(case, "system", "blockMeshDict")
    s = open(p).read()
    s = re.sub(r"^scale .*?;", "scale 1;", s, flags=re.M)
    s = re.sub(r"vertices\s*\(.*?\);", f"""vertices
(
    (0 0 0) ({P} 0 0) ({P} 1 0) (0 1 0) (0 0 1) ({P} 0 1) ({P} 1 1) (0 1 1)
);""", s, flags=re.S)
    c = cells_per_unit(rung, ring)
    s = re.sub(r"blocks\s*\(.*?\);", f"blocks\n(\n    hex (0 1 2 3 4 5 6 7) ({c*P} {c} {c}) simpleGrading (1 1 1)\n);",
               s, flags=re.S)
    if rung == "periodic":
        pairs = [("x", "(0 4 7 3)", "(1 2 6 5)"), ("y", "(0 1 5 4)", "(3 7 6 2)"), ("z", "(0 3 2 1)", "(4 5 6 7)")]
        patches = "".join(f"    {d}0 {{ type cyclic; neighbourPatch {d}1; faces ({a}); }}\n"
                          f"    {d}1 {{ type cyclic; neighbourPatch {d}0; faces ({b}); }}\n" for d, a, b in pairs)
        s = re.sub(r"boundary\s*\(.*\);", "boundary\n(\n" + patches + ");", s, flags=re.S)
    elif ring:
        s = re.sub(r"boundary\s*\(.*\);", "boundary\n(\n"
                   "    x0 { type cyclic; neighbourPatch x1; faces ((0 4 7 3)); }\n"
                   "    x1 { type cyclic; neighbourPatch x0; faces ((1 2 6 5)); }\n"
                   "    walls { type wall; faces ((0 1 5 4) (3 7 6 2) (0 3 2 1) (4 5 6 7)); }\n);",
                   s, flags=re.S)
    else:
        s = re.sub(r"boundary\s*\(.*\);", "boundary\n(\n    walls { type wall; faces ((0 4 7 3) (1 2 6 5) (0 1 5 4) (3 7 6 2) (0 3 2 1) (4 5 6 7)); }\n);",
                   s, flags=re.S)
    open(p, "w").write(s)
    # Parcels and the rung
    rng = np.random.default_rng(seed)
    x = rng.random((n*P, 3))*[P - 0.1, 0.9, 0.9] + 0.05
    if ring:
        # no ends: the parcels fill the ring along x
        x[:, 0] = rng.random(n*P)*P
    q = 1e-9*(2*rng.random(n*P) - 1)
    if rung == "bemPairs":
        # the second of each pair beside the first: centres 1.1 diameters
        # apart (d = 1e-3)
        u = rng.normal(size=(n*P//2, 3))
        u /= np.linalg.norm(u, axis=1)[:, None]
        x[1::2] = x[0::2] + 1.1e-3*u
        if ring:
            x[:, 0] %= P
    p = os.path.join(case, "constant", "cloudProperties")
    s = open(p).read()
    eps = " epsilonR 4;" if rung in ("inducedDipole", "bem", "bemPairs") else ""
    parcels = "\n".join("                { position (%.9g %.9g %.9g); d 1e-3; rho 1000;%s q %.9g; }"
                        % (r[0], r[1], r[2], eps, c) for r, c in zip(x, q))
    s = re.sub(r"parcels\s*\(.*?\n\s*\);", "parcels\n            (\n" + parcels + "\n            );", s, flags=re.S)
    model = RUNGS[rung].replace("radius 0.25", f"radius {2/c:g}") if c != 10 else RUNGS[rung]
    # cg iterations of the dipole solve every step (tolerance 1e-30,
    # maxIter cg: a warning each step), or 0: to the default tolerance
    model = model.replace(";CG", f"; tolerance 1e-30; maxIter {cg};" if cg else ";")
    s = re.sub(r"electrostaticsModel\s+\w+;", model, s)
    # No per-step parcel history (it gathers every parcel on the master)
    # and no scene check: only the solver's own traffic
    s = re.sub(r"cloudFunctions\s*\{.*?\n\}", "cloudFunctions\n{\n}", s, flags=re.S)
    s = re.sub(r"sceneCheck\s*\{[^}]*\}", "", s)
    s += "\nsceneCheck { active false; }\n"
    open(p, "w").write(s)
    if rung == "meshPoisson":
        p = os.path.join(case, "system", "fvSchemes")
        s = open(p).read()
        s = re.sub(r"gradSchemes\s*\{[^}]*\}", "gradSchemes { default Gauss linear; }", s)
        s = re.sub(r"laplacianSchemes\s*\{[^}]*\}", "laplacianSchemes { default Gauss linear corrected; }", s)
        s = re.sub(r"snGradSchemes\s*\{[^}]*\}", "snGradSchemes { default corrected; }", s)
        open(p, "w").write(s)
        p = os.path.join(case, "system", "fvSolution")
        s = open(p).read()
        if "Phi" not in s:
            s = re.sub(r"solvers\s*\{", "solvers\n{\n    Phi { solver PCG; preconditioner DIC; tolerance 1e-10; relTol 0; }", s, count=1)
            open(p, "w").write(s)
    # Steps
    p = os.path.join(case, "system", "controlDict")
    s = open(p).read()
    s = re.sub(r"^deltaT .*?;", "deltaT 1e-7;", s, flags=re.M)
    s = re.sub(r"^endTime .*?;", f"endTime {steps*1e-7:.10g};", s, flags=re.M)
    s = re.sub(r"^writeInterval .*?;", "writeInterval 100000;", s, flags=re.M)
    open(p, "w").write(s)
    p = os.path.join(case, "system", "decomposeParDict")
    s = open(p).read()
    s = re.sub(r"^numberOfSubdomains .*?;", f"numberOfSubdomains {P};", s, flags=re.M)
    s = re.sub(r"n\s+\([^)]*\);", f"n ({P} 1 1);", s)
    open(p, "w").write(s)
    inject_then_restart(case, steps)


def inject_then_restart(case, steps):
    """Inject the parcels in one serial step and continue from the written
    cloud without the injection list: every rank reads only its own
    parcels (decomposePar), as a large run does; explicitParcels would
    have every rank parse and keep the whole list (O(N) memory per rank)"""
    p = os.path.join(case, "system", "controlDict")
    s0 = open(p).read()
    s = re.sub(r"^endTime .*?;", "endTime 1e-7;", s0, flags=re.M)
    s = re.sub(r"^writeInterval .*?;", "writeInterval 1;", s, flags=re.M)
    open(p, "w").write(s)
    sh("blockMesh", case, "log.blockMesh")
    sh("chargedParticleFoam", case, "log.inject")
    s = re.sub(r"^endTime .*?;", f"endTime {(1 + steps)*1e-7:.10g};", s0, flags=re.M)
    s = re.sub(r"^startFrom .*?;", "startFrom latestTime;", s, flags=re.M)
    open(p, "w").write(s)
    p = os.path.join(case, "constant", "cloudProperties")
    s = open(p).read()
    s = re.sub(r"injectionModels\s*\{.*?\n    \}", "injectionModels\n    {\n    }", s, flags=re.S)
    open(p, "w").write(s)
    # The BEM clusters' state of the injection step (every member's bound
    # charge, written for a restart) is dropped: a restart's state is read
    # whole by every rank (the text of N members x patches), which would
    # measure the start, not the steps
    p = os.path.join(case, "1e-07", "uniform", "lagrangian", "cloud", "cloudOutputProperties")
    if os.path.exists(p):
        s = open(p).read()
        s = re.sub(r"\nbemNearField\s*\{.*?\n\}", "", s, flags=re.S)
        open(p, "w").write(s)


def make_duct(case, P, n, steps):
    """tutorials/shortDuct (chargedDPMFoam: gas, contact, wall and particle
    charging, meshPoisson) with n parcels along the whole duct, split into
    P slabs along it: the flagship's physics under strong scaling"""
    if os.path.exists(case):
        shutil.rmtree(case)
    shutil.copytree(os.path.join(TOP, "tutorials", "shortDuct"), case,
                    ignore=shutil.ignore_patterns("[1-9]*", "processor*", "log.*", "*.png"))
    duct = os.path.join(TOP, "tutorials", "chargedDuct")
    subprocess.run([sys.executable, os.path.join(duct, "makeParcels.py"), str(n), "1", "0.245"],
                   cwd=case, stdout=subprocess.DEVNULL, check=True)
    p = os.path.join(case, "system", "controlDict")
    s = open(p).read()
    s = re.sub(r"^endTime .*?;", f"endTime {steps*1e-4:.10g};", s, flags=re.M)
    s = re.sub(r"^writeInterval .*?;", "writeInterval 100000;", s, flags=re.M)
    open(p, "w").write(s)
    p = os.path.join(case, "constant", "cloudProperties")
    s = open(p).read()
    s = re.sub(r"sceneCheck\s*\{[^}]*\}", "", s)
    s += "\nsceneCheck { active false; }\n"
    open(p, "w").write(s)
    with open(os.path.join(case, "system", "decomposeParDict"), "w") as f:
        f.write("FoamFile { version 2.0; format ascii; class dictionary; object decomposeParDict; }\n"
                f"numberOfSubdomains {P};\nmethod simple;\ncoeffs {{ n ({P} 1 1); }}\n")


def tally(case, P, lib, solver="chargedParticleFoam"):
    out = os.path.join(case, "tally.txt")
    if os.path.exists(out):
        os.remove(out)
    sh("blockMesh", case, "log.blockMesh")
    env = f"-x LD_PRELOAD={lib} -x MPI_TALLY_FILE={out}"
    sh("decomposePar -force -latestTime", case, "log.decomposePar")
    sh(f"mpirun --oversubscribe -np {P} {env} {solver} -parallel", case, "log.solver")
    rows = {}
    for line in open(out):
        f = line.split()
        # messages, bytes, peak RSS [kB], all-reduce and all-to-all calls
        rows[int(f[1])] = (int(f[3]), int(f[5]), int(f[7]), int(f[9]), int(f[11]))
    return rows


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--ranks", default="2,4,8")
    ap.add_argument("--n", type=int, default=2000)
    ap.add_argument("--steps", default="2,12")
    ap.add_argument("--rungs", default="cutoffCoulomb,directCoulomb,meshPoisson")
    ap.add_argument("--work", default="/tmp/commVolume")
    ap.add_argument("--cgIterations", type=int, default=3,
                    help="CG iterations of the dipole solve every step (0: to its default tolerance 1e-8)")
    ap.add_argument("--ring", action="store_true",
                    help="the row of cubes cyclic in x: no end ranks (every rank has two neighbours)")
    ap.add_argument("--pingpong", action="store_true",
                    help="only measure the latency and bandwidth between two ranks (pingPong.c)")
    a = ap.parse_args()
    os.makedirs(a.work, exist_ok=True)
    if os.geteuid() == 0:
        os.environ.update(OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    if a.pingpong:
        exe = os.path.join(a.work, "pingPong")
        subprocess.run(["mpicc", "-O2", "-o", exe, os.path.join(HERE, "pingPong.c")], check=True)
        subprocess.run(["mpirun", "-np", "2", exe], check=True)
        return
    lib = os.path.join(a.work, "libmpiTally.so")
    subprocess.run(["mpicc", "-shared", "-fPIC", "-O2", "-o", lib,
                    os.path.join(HERE, "mpiTally.c")], check=True)
    if os.geteuid() == 0:
        os.environ.update(OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    S0, S = (int(v) for v in a.steps.split(","))
    ranks = [int(v) for v in a.ranks.split(",")]
    print(f"per step from {S - S0} steps ({S} minus {S0}); peak memory of the {S}-step run")
    for rung in a.rungs.split(","):
        duct = rung == "shortDuct"
        print(f"\n{rung}" + (f" (strong scaling: {a.n} parcels in all, per fluid step)" if duct
                              else f" (weak scaling: {a.n} parcels and "
                              f"{cells_per_unit(rung, a.ring)**3} cells per rank"
                              + (", a ring: cyclic in x)" if a.ring else ")")))
        print(f"| ranks | bytes/step per rank (mean) | (max) | messages/step per rank (mean) | all-reduces/step | all-to-alls/step | peak memory per rank [MB] (max) |")
        print("| --- | --- | --- | --- | --- | --- | --- |")
        perRank = {}
        notes = []
        for P in ranks:
            res = []
            for steps in (S0, S):
                case = os.path.join(a.work, f"{rung}-P{P}-S{steps}")
                if duct:
                    make_duct(case, P, a.n, steps)
                    res.append(tally(case, P, lib, "chargedDPMFoam"))
                else:
                    make_case(case, P, a.n, rung, steps, ring=a.ring, cg=a.cgIterations)
                    res.append(tally(case, P, lib))
            b = np.array([(res[1][r][1] - res[0][r][1])/(S - S0) for r in range(P)])
            m = np.array([(res[1][r][0] - res[0][r][0])/(S - S0) for r in range(P)])
            ar = np.mean([(res[1][r][3] - res[0][r][3])/(S - S0) for r in range(P)])
            aa = np.mean([(res[1][r][4] - res[0][r][4])/(S - S0) for r in range(P)])
            mem = max(res[1][r][2] for r in range(P))/1024
            if duct:
                # CPU seconds per parcel and fluid step (the master's
                # ExecutionTime; meaningful while P <= cores)
                cpu = [float(re.findall(r"ExecutionTime = ([0-9.e+-]+) s",
                                        open(os.path.join(a.work, f"{rung}-P{P}-S{k}", "log.solver")).read())[-1])
                       for k in (S0, S)]
                notes.append(f"compute at {P} ranks: {(cpu[1] - cpu[0])*P/((S - S0)*a.n):.3e} "
                             f"CPU s per parcel and fluid step")
            perRank[P] = b.mean()
            print(f"| {P} | {b.mean():.3g} | {b.max():.3g} | {m.mean():.3g} | {ar:.3g} | {aa:.3g} | {mem:.0f} |", flush=True)
        for note in notes:
            print(note)
        big = max(ranks)
        if 2 in perRank and perRank[2] > 0 and big > 2:
            print(f"bytes per rank and step, {big} ranks / 2 ranks: {perRank[big]/perRank[2]:.2f}")


if __name__ == "__main__":
    main()
