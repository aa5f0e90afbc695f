#!/usr/bin/env python3
"""BEM clusters against all-particle BEM on a cluster-forming scene.

Scene: --n (300) prolates (semi-axes 1 x 0.5 x 0.5 mm, or a/b = --aspect;
epsilonR 10, charges +-q of random sign, random orientations, small random
velocities) placed without overlap in a closed cube at solid fraction --phi
(0.04), no gravity, ellipsoidCollision (e 0.7). A formation run (far field
cutoffCoulomb over the whole box + nearField inducedDipole) lets
oppositely charged parcels attract and stick into aggregates, to t =
--form. From the formed state the rungs

    far       cutoffCoulomb alone (point charges)
    dipoles   + nearField inducedDipole (defaults)
    bem       + nearField bem (defaults: clusterGap 1, 1200 patches per
              parcel, isolated parcels: inducedDipole, parcels near a
              cluster: multipoles)
    bem-pc    + nearField bem with neighbours pointCharges
    bem-gap2  + nearField bem with clusterGap 2
    bem-gap4  + nearField bem with clusterGap 4
    bem-rnear2d + nearField bem with rNear 2 bounding diameters (4 a;
              the default is 4, 8 a)
    allBem    + nearField bem with clusterGap 1e6: every parcel in one
              cluster (all-particle BEM, the paper's approach)

run in turns, --rounds times (far and dipoles 10 x --steps steps, the
cluster rungs --steps, allBem --all-steps). The cost of a run is taken
between its first and last logged step (start-up excluded) and split by
the log's cumulative CPU times (contact, far field, dipoles, BEM clusters,
rest); ratios are per round to the point-charge run, medians over rounds.

Accuracy: two steps of each rung from the formed state (fE, tE written;
the first gives the clusters' members the multipoles their neighbours see);
forces and torques against allBem's as relative RMS errors, for the
parcels in the rung's clusters (the members written in the cloud's output
properties) and for the others.

    bemClusters.py [--n 300] [--phi 0.04] [--q 5e-11] [--form 0.2]
                   [--aspect 2] [--steps 20] [--all-steps 3] [--rounds 3]
                   [--rcut 0] [--runs dir] [--reuse] [--no-accuracy]
                   [--no-cost] [--bem-rungs bem,bem-pc,bem-gap2,bem-gap4,bem-rnear2d]
                   [--acc-steps 2]
"""
import argparse
import os
import re
import shutil
import statistics
import subprocess
import sys
import time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.abspath(os.path.join(HERE, "..", "..", ".."))
sys.path.insert(0, os.path.join(ROOT, "etc", "python"))
from foamLagrangian import read_field   # noqa: E402
from foamCase import run_logged, set_entry   # noqa: E402

DT = 1e-4
# Accuracy: forces of the second step from the formed state (the first
# gives the clusters' members the multipoles their neighbours see)
ACC_STEPS = 2
A, B = 1e-3, 5e-4          # semi-axes [m]: a x b x b
EPSR = 10

HEADER = """/*--------------------------------*- C++ -*----------------------------------*\\
  chargedFoam benchmark: bemClusters (OpenFOAM v1912)
\\*---------------------------------------------------------------------------*/
FoamFile
{
    version     2.0;
    format      ascii;
    class       %s;
    location    "%s";
    object      %s;
}
// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //
"""

CLOUD = """
solution
{
    active          true;
    coupled         false;
    transient       yes;
    cellValueSourceCorrection off;
    maxCo           0.3;
    interpolationSchemes
    {
        rho.carrier     cell;
        U.carrier       cell;
        mu.carrier      cell;
    }
    integrationSchemes { U Euler; }
    sourceTerms { schemes {} }
}

constantProperties
{
    rho0            2500;       // [kg/m3]
    youngsModulus   5e6;
    poissonsRatio   0.3;
    epsilonR        %(epsR)g;
}

subModels
{
    particleForces {}           // no gravity

    electrostaticsModel cutoffCoulomb;
    cutoffCoulombCoeffs
    {
        rCut        %(rCut).6g;
        %(near)s
    }

    injectionModels
    {
        scene
        {
            type            explicitParcels;
            SOI             0;
            #include        "parcels"
        }
    }

    collisionModel          ellipsoidCollision;
    ellipsoidCollisionCoeffs
    {
        maxInteractionDistance  2.1e-3;
        e                       0.7;
        mu                      0.3;
        tangentialModel         mindlin;
        collisionResolutionSteps 20;
        walls
        {
            youngsModulus   5e6;
            poissonsRatio   0.3;
            e               0.7;
            mu              0.3;
        }
    }

    dispersionModel         none;
    patchInteractionModel   standardWallInteraction;
    standardWallInteractionCoeffs
    {
        type        rebound;
        e           1;
        mu          0;
    }
    stochasticCollisionModel none;
    surfaceFilmModel        none;
}

cloudFunctions
{}
"""

NEAR = {
    "far": "// no near field",
    "dipoles": "nearField { type inducedDipole; }",
    "bem": "nearField { type bem; }",
    "bem-pc": "nearField { type bem; neighbours pointCharges; }",
    "bem-gap2": "nearField { type bem; clusterGap 2; }",
    "bem-gap4": "nearField { type bem; clusterGap 4; }",
    # rNear (neighbours seen as multipoles, isolated parcels' dipole
    # pairs) 2 bounding diameters instead of the default 4
    "bem-rnear2d": "nearField { type bem; rNear %r; }" % (4*A),
    "allBem": "nearField { type bem; clusterGap 1e6; }",
}
BEM_RUNGS = ("bem", "bem-pc", "bem-gap2", "bem-gap4", "bem-rnear2d")


def box_side(n, phi):
    return (n*4/3*np.pi*A*B*B/phi)**(1/3)


def write_cloud(case, near, rcut):
    open(os.path.join(case, "constant/cloudProperties"), "w").write(
        HEADER % ("dictionary", "constant", "cloudProperties")
        + CLOUD % dict(epsR=EPSR, rCut=rcut, near=NEAR[near]))


def random_parcels(n, L, q, seed):
    """n prolates without overlap (centres >= 2.2 mm apart: bounding spheres
    of radius a = 1 mm, 0.2 mm apart), at least 1.1 mm from the walls; charges
    +-q of random sign (as many of each as possible), uniformly random
    orientations (Shoemake), velocities uniform in +-2.5 cm/s."""
    rng = np.random.default_rng(seed)
    lo, hi = 1.1e-3, L - 1.1e-3
    x = np.empty((0, 3))
    tries = 0
    while len(x) < n:
        p = lo + (hi - lo)*rng.random(3)
        if len(x) == 0 or np.min(np.sum((x - p)**2, axis=1)) >= (2.2e-3)**2:
            x = np.vstack([x, p])
        tries += 1
        if tries > 200000:
            sys.exit(f"cannot place {n} parcels in a {L*1e3:.1f} mm box; lower --phi")
    sign = np.array([1.0, -1.0]*(n//2) + [1.0]*(n % 2))
    rng.shuffle(sign)
    lines = []
    for i in range(n):
        u1, u2, u3 = rng.random(3)
        qt = (np.sqrt(u1)*np.cos(2*np.pi*u3), np.sqrt(1 - u1)*np.sin(2*np.pi*u2),
              np.sqrt(1 - u1)*np.cos(2*np.pi*u2), np.sqrt(u1)*np.sin(2*np.pi*u3))
        U = 0.05*(rng.random(3) - 0.5)
        lines.append(
            f"    {{ position ({x[i,0]:.9e} {x[i,1]:.9e} {x[i,2]:.9e}); "
            f"U ({U[0]:.5f} {U[1]:.5f} {U[2]:.5f}); semiAxes ({A:g} {B:g} {B:g}); "
            f"quaternion ({qt[0]:.12f} {qt[1]:.12f} {qt[2]:.12f} {qt[3]:.12f}); "
            f"q {sign[i]*q:.6e}; epsilonR {EPSR:g}; }}")
    return "// Written by bemClusters.py\nparcels\n(\n" + "\n".join(lines) + "\n);\n"


def prepare(base, args, L, rcut):
    """The case from tutorials/ellipsoidPour: a cube of side L, no gravity,
    the scene's parcels, formation run with cutoffCoulomb + inducedDipole
    to t = --form."""
    if os.path.isdir(base):
        shutil.rmtree(base)
    shutil.copytree(os.path.join(ROOT, "tutorials", "ellipsoidPour"), base)
    subprocess.run(["./Allclean"], cwd=base, stdout=subprocess.DEVNULL)
    for f in ("Allrun", "Allclean", "makeParcels.py", "packing.py"):
        os.remove(os.path.join(base, f))
    nc = max(1, int(round(L/2e-3)))
    bm = os.path.join(base, "system/blockMeshDict")
    s = open(bm).read()
    s = re.sub(r"^vertices.*?^\);", "vertices\n(\n" + "\n".join(
        "    (%s %s %s)" % v for v in (
            ("0", "0", "0"), ("L", "0", "0"), ("L", "L", "0"), ("0", "L", "0"),
            ("0", "0", "L"), ("L", "0", "L"), ("L", "L", "L"), ("0", "L", "L"))
        ).replace("L", "%.6g" % (L*1e3)) + "\n);", s, count=1, flags=re.M | re.S)
    s = re.sub(r"\(6 6 20\)", "(%d %d %d)" % (nc, nc, nc), s)
    s = s.replace("12 mm x 12 mm x 40 mm box", "cube of side %.3g mm" % (L*1e3))
    open(bm, "w").write(s)
    g = os.path.join(base, "constant/g")
    s = open(g).read().replace("(0 0 -9.81)", "(0 0 0)")
    open(g, "w").write(s)
    open(os.path.join(base, "constant/parcels"), "w").write(
        random_parcels(args.n, L, args.q, args.seed))
    write_cloud(base, "dipoles", rcut)
    cd = os.path.join(base, "system/controlDict")
    set_entry(cd, "endTime", "%.10g" % args.form)
    set_entry(cd, "writeInterval", int(round(args.form/DT)))
    run_logged(["blockMesh"], base, "log.blockMesh")
    t0 = time.time()
    run_logged(["chargedParticleFoam"], base, "log.form")
    return time.time() - t0


def variant(base, run, t0, steps, near, rcut, write=False):
    if os.path.isdir(run):
        shutil.rmtree(run)
    shutil.copytree(base, run, ignore=shutil.ignore_patterns("log.*", "postProcessing"))
    cd = os.path.join(run, "system/controlDict")
    set_entry(cd, "endTime", "%.10g" % (t0 + steps*DT))
    if write:
        set_entry(cd, "writeInterval", 1)
    write_cloud(run, near, rcut)


FLOAT = r"[-+0-9.eE]+|nan|inf"


def parse_log(path):
    """Per logged step: execution time and the cumulative CPU split, and the
    BEM cluster statistics."""
    log = open(path).read()
    steps = re.split(r"^Time = ", log, flags=re.M)[1:]
    rows = []
    for s in steps:
        r = {}
        m = re.search(r"^ExecutionTime = (\S+) s", s, re.M)
        if not m:
            continue
        r["exec"] = float(m.group(1))
        m = re.search(r"CPU time \[s\] since start\s*= contact (\S+), far field (\S+), near field (\S+)", s)
        if m:
            r["contact"], r["far"], r["near"] = (float(m.group(k).rstrip(",")) for k in (1, 2, 3))
        m = re.search(r"CPU time \[s\] since start\s*= dipoles (\S+), BEM clusters (\S+)", s)
        if m:
            r["dip"], r["clu"] = float(m.group(1).rstrip(",")), float(m.group(2))
        m = re.search(r"set-up of meshes and blocks (\S+)\)", s)
        if m:
            r["setup"] = float(m.group(1))
        m = re.search(r"BEM clusters\s*= (\d+) \((\d+) parcels, largest (\d+); (\d+) solved\), "
                      r"(\d+) GMRES iterations", s)
        if m:
            r["nClu"], r["nIn"], r["largest"], r["nSolved"], r["gmres"] = (int(m.group(k)) for k in range(1, 6))
        m = re.search(r"Induced dipoles\s*= (\d+) polarisable, (\d+) pairs within rNear (\S+) m, (\d+) CG", s)
        if m:
            r["cg"] = int(m.group(4))
        m = re.search(r"Current number of parcels\s*= (\d+)", s)
        if m:
            r["nParcels"] = int(m.group(1))
        rows.append(r)
    return rows


def main():
    global B, BEM_RUNGS, ACC_STEPS
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--n", type=int, default=300)
    ap.add_argument("--phi", type=float, default=0.04)
    ap.add_argument("--q", type=float, default=5e-11)
    ap.add_argument("--form", type=float, default=0.2)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--rcut", type=float, default=0)
    ap.add_argument("--steps", type=int, default=20)
    ap.add_argument("--all-steps", type=int, default=3)
    ap.add_argument("--rounds", type=int, default=3)
    ap.add_argument("--reuse", action="store_true")
    ap.add_argument("--no-accuracy", action="store_true")
    ap.add_argument("--no-cost", action="store_true")
    ap.add_argument("--aspect", type=float, default=2,
                    help="a/b of the prolates (1: spheres, no free-charge quadrupole)")
    ap.add_argument("--runs", default=os.path.join(HERE, "runs"))
    ap.add_argument("--acc-steps", type=int, default=ACC_STEPS,
                    help="accuracy: the forces of this step from the formed state")
    ap.add_argument("--bem-rungs", default=",".join(BEM_RUNGS),
                    help="the cluster rungs to run, of " + " ".join(BEM_RUNGS))
    args = ap.parse_args()
    B = A/args.aspect
    ACC_STEPS = args.acc_steps
    BEM_RUNGS = tuple(r for r in args.bem_rungs.split(",") if r)
    for r in BEM_RUNGS:
        if r not in NEAR or r in ("far", "dipoles", "allBem"):
            sys.exit(f"--bem-rungs: {r} is not one of " + " ".join(BEM_RUNGS))

    runs = os.path.abspath(args.runs)
    os.makedirs(runs, exist_ok=True)
    base = os.path.join(runs, "base")
    L = box_side(args.n, args.phi)
    rcut = args.rcut if args.rcut > 0 else 1.01*np.sqrt(3)*L
    if not args.reuse:
        print(f"formation: {args.n} ellipsoids in a {L*1e3:.2f} mm cube, q +-{args.q:g} C,"
              f" to t = {args.form} s ...", flush=True)
        w = prepare(base, args, L, rcut)
        print(f"  {w:.0f} s", flush=True)
    t0 = latest_time(base)

    if not args.no_accuracy:
        accuracy(base, runs, t0, rcut)
    if not args.no_cost:
        cost(base, runs, t0, rcut, args)


def latest_time(case):
    times = [d for d in os.listdir(case) if re.fullmatch(r"[0-9.eE+-]+", d) and d != "0"]
    if not times:
        sys.exit(f"no formed state in {case}; run without --reuse")
    return max(float(t) for t in times)


def time_dir(case, t):
    for d in os.listdir(case):
        try:
            if abs(float(d) - t) < 1e-9*max(1, abs(t)) + 1e-12:
                return os.path.join(case, d)
        except ValueError:
            pass
    sys.exit(f"no time {t} in {case}")


def one_step_fields(case, t):
    c = os.path.join(time_dir(case, t), "lagrangian", "cloud")
    ids = read_field(os.path.join(c, "origId")).astype(int)
    order = np.argsort(ids)
    return (ids[order], read_field(os.path.join(c, "fE")).reshape(-1, 3)[order],
            read_field(os.path.join(c, "tE")).reshape(-1, 3)[order])


def accuracy(base, runs, t0, rcut):
    """Two steps of each rung from the formed state; forces and torques
    against all-particle BEM, for the parcels in the clusters of each bem
    rung and for the isolated ones. Errors are relative RMS (sqrt of the
    summed squared differences over the summed squares of the reference):
    a parcel's net force can nearly cancel, so per-parcel ratios mislead."""
    res, rows = {}, {}
    for near in ("far", "dipoles") + BEM_RUNGS + ("allBem",):
        run = os.path.join(runs, "acc-" + near)
        variant(base, run, t0, ACC_STEPS, near, rcut, write=True)
        run_logged(["chargedParticleFoam"], run, "log.chargedParticleFoam")
        res[near] = one_step_fields(run, t0 + ACC_STEPS*DT)
        rows[near] = parse_log(os.path.join(run, "log.chargedParticleFoam"))[-1]
    ids = res["allBem"][0]
    for near in res:
        assert np.array_equal(res[near][0], ids), f"{near}: parcels differ"
    F0, T0 = res["allBem"][1], res["allBem"][2]
    rms = lambda d, r: np.sqrt((d**2).sum()/(r**2).sum())
    print(f"\nAccuracy against all-particle BEM, step {ACC_STEPS} from the formed state "
          f"({len(ids)} parcels; relative RMS errors):")
    print("| rung | parcels in its clusters | force error, in clusters | torque error, in clusters "
          "| force error, isolated | torque error, isolated |")
    print("| --- | --- | --- | --- | --- | --- |")
    for near in ("far", "dipoles") + BEM_RUNGS:
        F, T = res[near][1], res[near][2]
        # parcels in clusters: those of this rung, or of the default bem
        # for the rungs without clusters
        member = cluster_members(os.path.join(runs, "acc-" + (near if near in BEM_RUNGS else "bem")),
                                 t0 + ACC_STEPS*DT, ids)
        r = rows.get(near, {})
        desc = (f"{member.sum()} in {r['nClu']} (largest {r['largest']})"
                if near in BEM_RUNGS else f"({member.sum()}, as bem's)")
        cells = []
        for sel in (member, ~member):
            if sel.any():
                cells += [f"{100*rms(F[sel] - F0[sel], F0[sel]):.3g} %",
                          f"{100*rms(T[sel] - T0[sel], T0[sel]):.3g} %"]
            else:
                cells += ["-", "-"]
        print(f"| {near} | {desc} | " + " | ".join(cells) + " |")


def cluster_members(case, t, ids):
    """Parcels in bem's clusters at time t: the (origProc, origId) pairs of
    the bound charges the bem near field keeps for its warm start (written
    in the cloud's output properties, exactly the members of that step)."""
    props = open(os.path.join(time_dir(case, t), "uniform", "lagrangian", "cloud",
                              "cloudOutputProperties")).read()
    m = re.search(r"bemNearField\s*\{.*?\bids\s+(?:List<label>\s*)?(\d+)\s*\(([^)]*)\)",
                  props, re.S)
    if not m:
        sys.exit(f"{case}: no bemNearField ids in cloudOutputProperties at {t}")
    pairs = np.array(m.group(2).split(), dtype=int).reshape(-1, 2)
    assert (pairs[:, 0] == 0).all(), "serial runs only"
    return np.isin(ids, pairs[:, 1])


def run_cost(base, runs, t0, near, steps, rcut):
    """Cost per step [s] of one run, between its first and last logged step,
    and the split of that cost by the log's cumulative CPU times."""
    run = os.path.join(runs, "cost-" + near)
    variant(base, run, t0, steps, near, rcut)
    run_logged(["chargedParticleFoam"], run, "log.chargedParticleFoam")
    rows = [r for r in parse_log(os.path.join(run, "log.chargedParticleFoam")) if "far" in r]
    a, b = rows[0], rows[-1]
    n = len(rows) - 1
    d = lambda k: (b.get(k, 0) - a.get(k, 0))/n
    split = dict(step=(b["exec"] - a["exec"])/n, contact=d("contact"), far=d("far"),
                 dipoles=d("dip") if near in BEM_RUNGS + ("allBem",) else d("near"),
                 clusters=d("clu"), setup=d("setup"))
    split["rest"] = split["step"] - split["contact"] - split["far"] - split["dipoles"] - split["clusters"]
    split["gmres"] = statistics.mean(r.get("gmres", 0) for r in rows[1:])
    split["inClusters"] = statistics.mean(r.get("nIn", 0) for r in rows[1:])
    split["nParcels"] = b.get("nParcels", 0)
    return split


def cost(base, runs, t0, rcut, args):
    """The rungs in turns, --rounds times; medians of the per-round ratios
    to the point-charge run."""
    rungs = (("far", 10*args.steps), ("dipoles", 10*args.steps)) \
        + tuple((near, args.steps) for near in BEM_RUNGS) + (("allBem", args.all_steps),)
    per = {near: [] for near, _ in rungs}
    for k in range(args.rounds):
        for near, steps in rungs:
            per[near].append(run_cost(base, runs, t0, near, steps, rcut))
        ratios = "  ".join(f"{near} {per[near][-1]['step']/max(per['far'][-1]['step'], 1e-9):.3g}"
                           for near, _ in rungs)
        print(f"round {k + 1}: cost per step / point charges: {ratios}", flush=True)
    med = lambda near, key: statistics.median(r[key] for r in per[near])
    ratio = lambda near, ref: statistics.median(
        a["step"]/b["step"] for a, b in zip(per[near], per[ref]))
    print(f"\nCost per step, medians of {args.rounds} rounds in turns ({10*args.steps} steps without"
          f" BEM, {args.steps} with clusters, all-particle BEM {args.all_steps}; first logged"
          f" step excluded):")
    print("| rung | step / point charges | contact | far field | dipoles | BEM clusters "
          "| of which set-up | rest | parcels in clusters | GMRES iterations per step |")
    print("| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |")
    for near, _ in rungs:
        st = med(near, "step")
        frac = lambda key: f"{100*med(near, key)/st:.0f} %"
        print(f"| {near} | {ratio(near, 'far'):.3g} | {frac('contact')} | {frac('far')} | "
              f"{frac('dipoles')} | {frac('clusters')} | {frac('setup')} | {frac('rest')} | "
              f"{med(near, 'inClusters'):.0f} / {per[near][0]['nParcels']} | "
              f"{med(near, 'gmres'):.3g} |")
    for near in BEM_RUNGS:
        print(f"\nall-particle BEM / {near}, per step: {ratio('allBem', near):.3g} "
              f"(per round: " + ", ".join(f"{a['step']/b['step']:.3g}"
                                         for a, b in zip(per["allBem"], per[near])) + ")")


if __name__ == "__main__":
    main()
