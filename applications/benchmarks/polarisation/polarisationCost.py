#!/usr/bin/env python3
"""Cost of the induced-dipole near field against the same far field alone.

A charged pour of dielectric ellipsoids (tutorials/ellipsoidPour: prolates
2 x 1 x 1 mm, with charges +-q and epsilonR 4, far field cutoffCoulomb) is
settled once; from the settled bed the same steps are then run as

    farField    cutoffCoulomb alone (point charges)
    dipoles     + nearField inducedDipole, defaults (rNear 2 bounding diameters)
    dipoles3    + nearField inducedDipole, rNear = 3 bounding diameters
    dipolesMin  + nearField inducedDipole, rNear = 1 bounding diameter

in turns, --rounds times. The cost of a run is its ExecutionTime between
the first and the last step (start-up excluded). Prints the ratio of each
variant to the far-field run of the same round, and their medians, and the
dipole solve's statistics (pairs, CG iterations).

Accuracy of the cutoff: one step from the settled bed with rNear = 1, 1.5,
2, 3 and 4 bounding diameters against all pairs (rNear beyond the box): the
error of the near field's part of the force (fE minus the far field's) and
of the torque, relative to their rms over the parcels.

    polarisationCost.py [--n 300] [--steps 300] [--rounds 3] [--settle 0.2]
"""
import argparse
import os
import re
import shutil
import statistics
import subprocess
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..", "etc", "python"))
from foamCase import run_logged, set_entry   # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.abspath(os.path.join(HERE, "..", "..", ".."))
DT = 1e-4


def prepare(base, n, q, settle):
    if os.path.isdir(base):
        shutil.rmtree(base)
    shutil.copytree(os.path.join(ROOT, "tutorials", "ellipsoidPour"), base)
    subprocess.run(["./Allclean"], cwd=base, stdout=subprocess.DEVNULL)
    subprocess.run([sys.executable, "makeParcels.py", str(n)], cwd=base,
                   stdout=subprocess.DEVNULL, check=True)
    rng = np.random.default_rng(3)
    parcels = open(os.path.join(base, "constant/parcels")).read()
    parcels = re.sub(r"q 0;", lambda m: "q %.6e;" % (q*rng.choice([-1, 1])), parcels)
    open(os.path.join(base, "constant/parcels"), "w").write(parcels)
    cp = os.path.join(base, "constant/cloudProperties")
    s = open(cp).read()
    s = s.replace("rho0            2500;", "rho0            2500;\n    epsilonR        4;")
    s = s.replace("electrostaticsModel none;",
                  "electrostaticsModel cutoffCoulomb;\n"
                  "    cutoffCoulombCoeffs\n    {\n        rCut 6e-3;\n        // nearField\n    }")
    open(cp, "w").write(s)
    cd = os.path.join(base, "system/controlDict")
    set_entry(cd, "endTime", settle)
    set_entry(cd, "writeInterval", int(round(settle/DT)))
    run_logged(["blockMesh"], base, "log.blockMesh")
    run_logged(["chargedParticleFoam"], base, "log.settle")


def variant(base, run, settle, steps, near):
    if os.path.isdir(run):
        shutil.rmtree(run)
    shutil.copytree(base, run, ignore=shutil.ignore_patterns("log.*", "postProcessing"))
    set_entry(os.path.join(run, "system/controlDict"), "endTime", "%.10g" % (settle + steps*DT))
    if near is not None:
        cp = os.path.join(run, "constant/cloudProperties")
        s = open(cp).read()
        open(cp, "w").write(s.replace("// nearField", "nearField { type inducedDipole; %s}" % near))


def cost(run, steps):
    log = open(os.path.join(run, "log.solver")).read()
    t = [float(x) for x in re.findall(r"^ExecutionTime = (\S+) s", log, re.M)]
    assert len(t) == steps, (run, len(t))
    dipoles = re.findall(r"Induced dipoles\s*= (\d+) polarisable, (\d+) pairs within rNear (\S+) m, (\d+) CG", log)
    return (t[-1] - t[0])/(len(t) - 1), dipoles


def read_lagrangian(run, time, field):
    sys.path.insert(0, os.path.join(ROOT, "etc", "python"))
    from foamLagrangian import read_field
    return read_field(os.path.join(run, time, "lagrangian", "cloud", field)).reshape(-1, 3)


def accuracy(runs, base, settle, dMax):
    """Near-field force and torque errors of truncated rNear (one step)."""
    t1 = "%.10g" % (settle + DT)
    def one(name, near):
        run = os.path.join(runs, "acc-" + name)
        variant(base, run, settle, 1, near)
        set_entry(os.path.join(run, "system/controlDict"), "writeInterval", 1)
        run_logged(["chargedParticleFoam"], run, "log.solver")
        return read_lagrangian(run, t1, "fE"), read_lagrangian(run, t1, "tE")
    f0, _ = one("farField", None)
    fRef, tRef = one("all", "rNear 1; tolerance 1e-12; ")
    dRef = fRef - f0
    rms = lambda v: np.sqrt((v*v).sum(axis=1).mean())
    rows = []
    for k in (1, 1.5, 2, 3, 4):
        f, t = one("r%g" % k, "rNear %g; tolerance 1e-12; " % (k*dMax))
        eF = np.linalg.norm(f - fRef, axis=1)/rms(dRef)
        eT = np.linalg.norm(t - tRef, axis=1)/rms(tRef)
        rows.append((k, k*dMax*1e3, np.sqrt((eF**2).mean()), eF.max(), np.sqrt((eT**2).mean()), eT.max()))
    print("\nAccuracy of the cutoff (one step from the settled bed, against all pairs;"
          " errors relative to the rms over the parcels of the near field's force fE - fE_far"
          " (%.3g N) and of the torque tE (%.3g N m))\n" % (rms(dRef), rms(tRef)))
    print("| rNear [bounding diameters] | rNear [mm] | force error rms | max | torque error rms | max |")
    print("| --- | --- | --- | --- | --- | --- |")
    for r in rows:
        print("| %g | %g | %.2e | %.2e | %.2e | %.2e |" % r)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--n", type=int, default=300)
    ap.add_argument("--steps", type=int, default=300)
    ap.add_argument("--rounds", type=int, default=3)
    ap.add_argument("--settle", type=float, default=0.2)
    ap.add_argument("--q", type=float, default=2e-11)
    ap.add_argument("--accuracy-only", action="store_true")
    ap.add_argument("--no-accuracy", action="store_true")
    args = ap.parse_args()

    runs = os.path.join(HERE, "runs")
    os.makedirs(runs, exist_ok=True)
    base = os.path.join(runs, "base")
    print(f"settling {args.n} charged dielectric ellipsoids to t = {args.settle} s ...", flush=True)
    prepare(base, args.n, args.q, args.settle)

    if not args.no_accuracy:
        accuracy(runs, base, args.settle, 2e-3)
    if args.accuracy_only:
        return

    variants = [("farField", ""), ("dipoles", ""), ("dipoles3", "rNear 6e-3; "), ("dipolesMin", "rNear 2e-3; ")]
    costs = {v: [] for v, _ in variants}
    stats = {}
    for r in range(args.rounds):
        for v, opt in variants:
            run = os.path.join(runs, v)
            variant(base, run, args.settle, args.steps,
                    None if v == "farField" else opt)
            run_logged(["chargedParticleFoam"], run, "log.solver")
            c, d = cost(run, args.steps)
            costs[v].append(c)
            if d:
                stats[v] = d
        print("round %d: %s" % (r + 1, ", ".join(
            "%s %.3f ms/step" % (v, costs[v][-1]*1e3) for v, _ in variants)), flush=True)

    print("\n%d ellipsoids (2 x 1 x 1 mm, epsilonR 4, charges +-%g C), cutoffCoulomb rCut 6 mm,"
          " %d steps from the settled bed, %d rounds in turns\n" % (args.n, args.q, args.steps, args.rounds))
    print("| run | rNear [mm] | pairs | CG iterations per step | cost / far field, per round | median |")
    print("| --- | --- | --- | --- | --- | --- |")
    for v, _ in variants:
        ratios = [c/f for c, f in zip(costs[v], costs["farField"])]
        if v in stats:
            d = stats[v]
            pairs = statistics.median(int(x[1]) for x in d)
            its = statistics.mean(int(x[3]) for x in d)
            rn = float(d[0][2])*1e3
            extra = "%.0f | %.0f | %.1f" % (rn, pairs, its)
        else:
            extra = "- | - | -"
        print("| %s | %s | %s | %.2f |" % (v, extra, " ".join("%.2f" % x for x in ratios),
                                           statistics.median(ratios)))


if __name__ == "__main__":
    main()
