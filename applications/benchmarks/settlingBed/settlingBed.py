#!/usr/bin/env python3
"""Settling-bed benchmark: particle-steps per second of chargedFoam, OpenFOAM's
own colliding cloud and LIGGGHTS on the same bed (see README.md).

    settlingBed.py [-quick] [-runs DIR] [-doc FILE | -no-doc] [-only CODE,...]
                   [-report]

Spheres (cfSpheres, cfPairCollision, ofIco, liggghts):
  1. settling phase, not timed: LIGGGHTS pours N spheres from the lattice for
     SETTLE steps (its loop time is reported too, as a whole-pour rate);
  2. every code starts from that state (positions, velocities, angular
     velocities; no contact history) and runs WINDOW steps of the same
     time step: the timed window.
Ellipsoids (cfEllipsoids): chargedFoam is the only code; it pours its own
bed (not timed: larger time step with its adaptive sub-cycling, as in
tutorials/ellipsoidPour), then restarts from it for the timed window at
the benchmark's time step.

Timing: the time loop only. OpenFOAM solvers: difference of the
ExecutionTime (CPU time of the process) printed after the first and after
the last-but-one step of the window (the last step also writes the final
state); LIGGGHTS: its "Loop time" (wall time) of the window run. The
process CPU and wall times are recorded as a cross-check.
"""
import argparse
import datetime
import json
import math
import statistics
import os
import platform
import re
import shutil
import subprocess
import sys
import time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)

import cases  # noqa: E402
import physics as ph  # noqa: E402

ROOT = os.path.abspath(os.path.join(HERE, "..", "..", ".."))
DOC = os.path.join(ROOT, "doc", "benchmarks", "settlingBed.md")

SPHERE_CODES = ["cfSpheres", "cfPairCollision", "ofIco", "liggghts"]
ALL_CODES = SPHERE_CODES + ["cfEllipsoids"]

# Configurations: full (default) and -quick
CONFIGS = {
    "full": dict(
        n=10000,            # spheres
        base=30e-3,         # side of the square box floor [m]
        settle=14700,       # LIGGGHTS steps before the window (0.1 s)
        window=1000,        # timed steps of every sphere code
        repeats=5,          # cfSpheres and LIGGGHTS window runs, taken in
                            # turns (noisy machines); medians reported
        nEllipsoids=10000,  # ellipsoids (own pour, see README)
        ellipsoidBase=40e-3,
        ellipsoidSettleTime=0.2,
        ellipsoidWindow=200,
    ),
    "quick": dict(
        n=2000,
        base=15e-3,
        settle=14700,
        window=200,
        repeats=3,
        nEllipsoids=500,
        ellipsoidBase=12e-3,
        ellipsoidSettleTime=0.12,
        ellipsoidWindow=50,
    ),
}


# ----------------------------------------------------------------------------
# Running

def log(msg):
    print(msg, flush=True)


def loadavg():
    try:
        return open("/proc/loadavg").read().split()[0]
    except OSError:
        return "?"


def run(cmd, cwd, logfile, env=None):
    """Run cmd in cwd, output to logfile; returns wall and CPU seconds of
    the process and its peak resident size [bytes] (its own rusage)."""
    t0 = time.perf_counter()
    with open(os.path.join(cwd, logfile), "w") as out:
        p = subprocess.Popen(cmd, cwd=cwd, stdout=out, stderr=subprocess.STDOUT, env=env)
        _, status, ru = os.wait4(p.pid, 0)
        p.returncode = os.waitstatus_to_exitcode(status)
    wall = time.perf_counter() - t0
    cpu = ru.ru_utime + ru.ru_stime
    if p.returncode != 0:
        raise RuntimeError(f"{' '.join(cmd)} failed in {cwd} (exit {p.returncode}); see {logfile}")
    return wall, cpu, 1024*ru.ru_maxrss     # Linux: ru_maxrss in KiB


def snapshot_chargedfoam(runs):
    """Copy chargedParticleFoam and the project's libraries, so that a
    rebuild of the repository during the benchmark does not change them."""
    opts = os.environ["WM_OPTIONS"]
    src = os.path.join(ROOT, "platforms", opts)
    dst = os.path.join(runs, "snapshot")
    if os.path.isdir(dst):
        shutil.rmtree(dst)
    os.makedirs(os.path.join(dst, "bin"))
    os.makedirs(os.path.join(dst, "lib"))
    shutil.copy2(os.path.join(src, "bin", "chargedParticleFoam"), os.path.join(dst, "bin"))
    for f in os.listdir(os.path.join(src, "lib")):
        if f.endswith(".so"):
            shutil.copy2(os.path.join(src, "lib", f), os.path.join(dst, "lib"))
    env = dict(os.environ)
    env["LD_LIBRARY_PATH"] = os.path.join(dst, "lib") + ":" + env.get("LD_LIBRARY_PATH", "")
    env["PATH"] = os.path.join(dst, "bin") + ":" + env["PATH"]
    return env


def run_openfoam(case, env):
    app = re.search(r"^application\s+(\S+);", open(os.path.join(case, "system", "controlDict")).read(),
                    re.M).group(1)
    run(["blockMesh"], case, "log.blockMesh", env)
    wall, cpu, rss = run([app], case, f"log.{app}", env)
    return dict(app=app, processWall=wall, processCpu=cpu, peakRss=rss)


def run_liggghts(case, env, cpu_loop=False):
    """Run in.settlingBed. With cpu_loop, also run the same input with 0
    steps (setup and final output only): the difference of the two process
    CPU times is the CPU time of the loop."""
    wall, cpu, rss = run(["liggghts", "-in", "in.settlingBed", "-log", "log.liggghts", "-screen", "none"],
                         case, "stdout.liggghts", env)
    rec = dict(app="liggghts", processWall=wall, processCpu=cpu, peakRss=rss)
    if cpu_loop:
        with open(os.path.join(case, "in.settlingBed")) as f:
            text = f.read()
        text = re.sub(r"^run\s+\d+\s*$", "run             0", text, count=1, flags=re.M)
        text = text.replace("final.dump", "setupOnly.dump")
        with open(os.path.join(case, "in.setupOnly"), "w") as f:
            f.write(text)
        w0, c0, _ = run(["liggghts", "-in", "in.setupOnly", "-log", "log.setupOnly", "-screen", "none"],
                     case, "stdout.setupOnly", env)
        rec.update(setupOnlyWall=w0, setupOnlyCpu=c0, loopCpu=cpu - c0)
    return rec


# ----------------------------------------------------------------------------
# Parsing

def parse_openfoam_log(path):
    text = open(path).read()
    steps = re.split(r"^Time = ", text, flags=re.M)[1:]
    times, execs, clocks, subcycles, ke, coord, contacts = [], [], [], [], [], [], []
    for s in steps:
        m = re.search(r"^ExecutionTime = (\S+) s\s+ClockTime = (\S+) s", s, re.M)
        if not m:
            continue
        times.append(float(s.split()[0]))
        execs.append(float(m.group(1)))
        clocks.append(float(m.group(2)))
        sc = re.search(r"^\s+(\d+) move-collide subCycles", s, re.M)
        subcycles.append(int(sc.group(1)) if sc else 1)
        k = re.search(r"Linear kinetic energy\s+=\s+(\S+)", s)
        ke.append(float(k.group(1)) if k else float("nan"))
        c = re.search(r"Coordination number\s+=\s+(\S+)", s)
        coord.append(float(c.group(1)) if c else float("nan"))
        pc = re.search(r"Contacts: particle-particle\s+=\s+(\d+), particle-wall\s+=\s+(\d+)", s)
        contacts.append((int(pc.group(1)), int(pc.group(2))) if pc else None)
    return dict(times=times, exec=execs, clock=clocks, subcycles=subcycles, ke=ke, coord=coord,
                contacts=[c for c in contacts if c],
                warnings=len(re.findall(r"FOAM Warning", text)),
                bufferWarnings=len(re.findall(r"beyond half the buffer layers|of the two buffer layers", text)))


def openfoam_timing(logpath):
    """Timed steps and seconds: ExecutionTime after step 1 to after step
    M - 1 (M - 2 steps)."""
    p = parse_openfoam_log(logpath)
    m = len(p["exec"])
    if m < 3:
        raise RuntimeError(f"{logpath}: only {m} steps")
    steps = m - 2
    seconds = p["exec"][m - 2] - p["exec"][0]
    clock = p["clock"][m - 2] - p["clock"][0]
    return dict(steps=steps, seconds=seconds, clockSeconds=clock, stepsRun=m,
                maxSubCycles=max(p["subcycles"]), stepsSubCycled=sum(1 for s in p["subcycles"] if s > 1),
                keFinal=p["ke"][-1], coordFinal=p["coord"][-1], warnings=p["warnings"],
                bufferWarnings=p["bufferWarnings"],
                pairContacts=p["contacts"][-1][0] if p["contacts"] else None,
                wallContactsLog=p["contacts"][-1][1] if p["contacts"] else None)


def parse_liggghts_log(path):
    text = open(path).read()
    loops = re.findall(r"Loop time of (\S+) on (\d+) procs for (\d+) steps with (\d+) atoms", text)
    loop = next(l for l in loops if int(l[2]) > 0)
    pair = re.search(r"Pair\s+time \(%\) = (\S+)", text)
    neigh = re.search(r"Neigh time \(%\) = (\S+)", text)
    builds = re.search(r"Neighbor list builds = (\d+)", text)
    # last thermo line of the timed run: step atoms ke zmean
    thermo = re.findall(r"^\s+(\d+)\s+(\d+)\s+(\S+)\s+(\S+)\s*$", text.split("Loop time")[0], re.M)
    return dict(steps=int(loop[2]), seconds=float(loop[0]), procs=int(loop[1]), atoms=int(loop[3]),
                pairSeconds=float(pair.group(1)) if pair else float("nan"),
                neighSeconds=float(neigh.group(1)) if neigh else float("nan"),
                neighBuilds=int(builds.group(1)) if builds else -1,
                keFinal=float(thermo[-1][2]) if thermo else float("nan"))


def latest_time_dir(case):
    ts = [d for d in os.listdir(case) if re.fullmatch(r"[0-9.eE+-]+", d)]
    ts = [d for d in ts if float(d) > 0]
    return os.path.join(case, max(ts, key=float)) if ts else None


def final_positions_openfoam(case, cloud):
    sys.path.insert(0, os.path.join(ROOT, "etc", "python"))
    from foamLagrangian import read_positions
    d = latest_time_dir(case)
    return read_positions(os.path.join(d, "lagrangian", cloud, "positions"))


def final_state_liggghts(case):
    return cases.State.from_liggghts_dump(os.path.join(case, "final.dump"))


def sphere_contacts(x, base, lz):
    """Sphere-sphere contacts (overlapping pairs) per particle, and the
    number of sphere-wall contacts."""
    from scipy.spatial import cKDTree
    pairs = cKDTree(x).query_pairs(ph.D, output_type="ndarray")
    r = ph.D/2
    walls = ((x[:, 0] < r).sum() + (x[:, 0] > base - r).sum() + (x[:, 1] < r).sum()
             + (x[:, 1] > base - r).sum() + (x[:, 2] < r).sum() + (x[:, 2] > lz - r).sum())
    return 2*len(pairs)/len(x), walls


# ----------------------------------------------------------------------------
# Machine

def machine_info():
    cpu = "?"
    for line in open("/proc/cpuinfo"):
        if line.startswith("model name"):
            cpu = line.split(":", 1)[1].strip()
            break
    lscpu = subprocess.run(["lscpu"], capture_output=True, text=True).stdout
    m = re.search(r"Hypervisor vendor:\s+(\S+)", lscpu)
    virt = f"{m.group(1)} guest" if m else "bare metal"
    fam = re.search(r"CPU family:\s+(\S+)", lscpu)
    mod = re.search(r"^Model:\s+(\S+)", lscpu, re.M)
    if fam and mod:
        cpu += f", family {fam.group(1)} model {mod.group(1)}"
    try:
        c = subprocess.run(["systemd-detect-virt", "--container"], capture_output=True, text=True).stdout.strip()
        if c and c != "none":
            virt += f", {c} container"
    except OSError:
        pass
    def version(pkg):
        r = subprocess.run(["dpkg-query", "-W", "-f=${Version}", pkg], capture_output=True, text=True)
        return r.stdout.strip() or "?"

    head = "?"
    try:
        h = open(os.path.join(ROOT, ".git", "HEAD")).read().strip()
        if h.startswith("ref:"):
            ref = os.path.join(ROOT, ".git", h.split()[1])
            head = open(ref).read().strip()[:12] if os.path.exists(ref) else h.split()[1]
        else:
            head = h[:12]
    except OSError:
        pass
    return dict(nproc=os.cpu_count(), cpu=cpu, virtualisation=virt,
                kernel=platform.release(), openfoam=version("openfoam"),
                liggghts=version("liggghts"), gcc=version("g++"),
                chargedFoamCommit=head,
                # etc/bashrc's choice of instruction set for the project's builds
                buildFlags=os.environ.get("FOAM_EXTRA_CXXFLAGS", ""),
                date=datetime.datetime.now().strftime("%Y-%m-%d %H:%M"))


# ----------------------------------------------------------------------------
# Benchmark

def sphere_benchmark(cfg, runs, env, only, results):
    n = cfg["n"]
    base = cfg["base"]
    cell = ph.CELL_SPHERE
    dt, tc, vmax = ph.time_step(n, ph.SPACING_SPHERE, base)
    lz = ph.box_height(n, ph.SPACING_SPHERE, base, cell)
    results["spheres"] = dict(n=n, dt=dt, tc=tc, vmax=vmax, base=base, lz=lz, cell=cell,
                              settleSteps=cfg["settle"],
                              window=cfg["window"], codes={})

    # 1. Settling phase (LIGGGHTS), not timed
    settle = os.path.join(runs, "spheres", "settle")
    log(f"[settle] LIGGGHTS pours {n} spheres for {cfg['settle']} steps of {dt:g} s "
        f"(t = {cfg['settle']*dt:.4f} s), load {loadavg()}")
    cases.write_case("liggghts", settle, cases.Setup(cases.State.lattice(n, base), cfg["settle"], dt, base, lz, vmax, cell))
    proc = run_liggghts(settle, env)
    lg = parse_liggghts_log(os.path.join(settle, "log.liggghts"))
    x = final_state_liggghts(settle).x
    cn, _ = sphere_contacts(x, base, lz)
    results["spheres"]["settle"] = dict(lg, **proc, zmean=float(x[:, 2].mean()), contactsPerParticle=cn)
    log(f"         {lg['seconds']:.1f} s loop ({n*lg['steps']/lg['seconds']:.3g} particle-steps/s), "
        f"mean height {x[:, 2].mean()*1e3:.3f} mm, {cn:.2f} contacts per particle")
    state = final_state_liggghts(settle)

    # 2. Timed window, every code from the same state. chargedFoam's spheres
    # and LIGGGHTS, whose ratio is the benchmark's goal, run several times
    # in turns, so that a slow phase of a shared machine hits both
    repeated = [c for c in ("cfSpheres", "liggghts") if not only or c in only]
    schedule = [(c, r) for r in range(cfg["repeats"]) for c in repeated]
    schedule += [(c, 0) for c in SPHERE_CODES
                 if c not in repeated and (not only or c in only)]
    runsOf = {}
    for code, r in schedule:
        repeats = cfg["repeats"] if code in repeated else 1
        res = runsOf.setdefault(code, [])
        case = os.path.join(runs, "spheres", code + (f".{r + 1}" if repeats > 1 else ""))
        setup = cases.Setup(state, cfg["window"], dt, base, lz, vmax, cell)
        cases.write_case(code, case, setup)
        log(f"[{code}] {cfg['window']} steps{f' (run {r + 1}/{repeats})' if repeats > 1 else ''}, "
            f"load {loadavg()}")
        la0 = loadavg()
        if code == "liggghts":
            proc = run_liggghts(case, env, cpu_loop=True)
            t = parse_liggghts_log(os.path.join(case, "log.liggghts"))
            # timed: CPU of the loop; LIGGGHTS' own (wall) loop time kept
            t["loopWall"] = t["seconds"]
            t["seconds"] = proc["loopCpu"]
            xf = final_state_liggghts(case).x
        else:
            proc = run_openfoam(case, env)
            t = openfoam_timing(os.path.join(case, f"log.{proc['app']}"))
            xf = final_positions_openfoam(case, "kinematicCloud" if code == "ofIco" else "cloud")
        cn, nw = sphere_contacts(xf, base, lz)
        rec = dict(t, **proc, n=len(xf), zmean=float(xf[:, 2].mean()), contactsPerParticle=cn,
                   wallContacts=int(nw), loadStart=la0, loadEnd=loadavg(), case=os.path.relpath(case, runs))
        rec["rate"] = n*rec["steps"]/rec["seconds"]
        res.append(rec)
        log(f"         {rec['steps']} steps in {rec['seconds']:.2f} s: {rec['rate']:.4g} particle-steps/s "
            f"({1e6/rec['rate']:.3g} us per particle-step); N = {len(xf)}, "
            f"mean height {rec['zmean']*1e3:.4f} mm")
    for code in SPHERE_CODES:
        if code not in runsOf:
            continue
        # median run (by rate)
        res = sorted(runsOf[code], key=lambda r: r["rate"])
        best = dict(res[len(res)//2])
        best["repeats"] = [r["rate"] for r in res]
        best["runRates"] = [r["rate"] for r in runsOf[code]]    # in run order
        results["spheres"]["codes"][code] = best


def read_ellipsoid_state(case):
    """Positions and count of the latest time of a chargedFoam case."""
    x = final_positions_openfoam(case, "cloud")
    return x


def ellipsoid_benchmark(cfg, runs, env, results):
    n = cfg["nEllipsoids"]
    base = cfg["ellipsoidBase"]
    cell = ph.CELL_ELLIPSOID
    dt, _, vmax = ph.time_step(cfg["n"], ph.SPACING_SPHERE, cfg["base"])   # the spheres' step
    lz = ph.box_height(n, ph.SPACING_ELLIPSOID, base, cell)
    case = os.path.join(runs, "ellipsoids", "cfEllipsoids")
    tSettle = cfg["ellipsoidSettleTime"]
    dtSettle = 1e-4
    results["ellipsoids"] = dict(n=n, dt=dt, base=base, lz=lz, cell=cell, settleTime=tSettle, settleDeltaT=dtSettle,
                                 window=cfg["ellipsoidWindow"])

    # 1. Pour, not timed: deltaT 1e-4 with the code's adaptive sub-cycles
    #    (collisionResolutionSteps 10), as tutorials/ellipsoidPour
    nSettle = round(tSettle/dtSettle)
    st = cases.State.lattice(n, base, "ellipsoid")
    setup = cases.Setup(st, nSettle, dtSettle, base, lz, vmax, cell)
    cases.write_case("cfEllipsoids", case, setup)
    cases.set_resolution(case, 10)
    log(f"[cfEllipsoids pour] {n} ellipsoids, {tSettle} s with deltaT {dtSettle:g} and adaptive "
        f"sub-cycles (not timed), load {loadavg()}")
    proc = run_openfoam(case, env)
    os.rename(os.path.join(case, "log.chargedParticleFoam"), os.path.join(case, "log.pour"))
    p = parse_openfoam_log(os.path.join(case, "log.pour"))
    results["ellipsoids"]["pour"] = dict(processWall=proc["processWall"], steps=len(p["exec"]),
                                         subSteps=sum(p["subcycles"]), coordFinal=p["coord"][-1],
                                         keFinal=p["ke"][-1])
    log(f"         {proc['processWall']:.0f} s, {sum(p['subcycles'])} sub-steps, coordination "
        f"{p['coord'][-1]:.2f}")

    # 2. Timed window: restart at the benchmark's time step, one sub-cycle.
    #    Run in turns with a cfSpheres window (the first sphere case, from
    #    its start again), so that each ellipsoid run has a sphere run of the
    #    same phase of a shared machine: the per-pair ratios are the measure
    t0 = nSettle*dtSettle
    cases.set_window(case, t0, cfg["ellipsoidWindow"], dt, setup.resolution_steps()[1])
    peer = os.path.join(runs, "spheres", "cfSpheres.1")
    paired = "spheres" in results and "cfSpheres" in results["spheres"]["codes"] and os.path.isdir(peer)
    repeats = cfg["repeats"] if paired else 1
    windows, peers = [], []
    for r in range(repeats):
        log(f"[cfEllipsoids] {cfg['ellipsoidWindow']} steps of {dt:g} s from t = {t0:g} s"
            f"{f' (run {r + 1}/{repeats})' if repeats > 1 else ''}, load {loadavg()}")
        remove_times_after(case, t0)
        la0 = loadavg()
        wall, cpu, _ = run(["chargedParticleFoam"], case, "log.chargedParticleFoam", env)
        t = openfoam_timing(os.path.join(case, "log.chargedParticleFoam"))
        x = read_ellipsoid_state(case)
        rec = dict(t, processWall=wall, processCpu=cpu, n=len(x), zmean=float(x[:, 2].mean()),
                   loadStart=la0, loadEnd=loadavg(), case=os.path.relpath(case, runs))
        rec["rate"] = n*rec["steps"]/rec["seconds"]
        windows.append(rec)
        log(f"         {rec['steps']} steps in {rec['seconds']:.2f} s: {rec['rate']:.4g} particle-steps/s "
            f"({1e6/rec['rate']:.3g} us per particle-step); N = {len(x)}, coordination {rec['coordFinal']:.2f}")
        if paired:
            log(f"[cfSpheres peer] {os.path.relpath(peer, runs)} again (run {r + 1}/{repeats}), load {loadavg()}")
            remove_times_after(peer, 0)
            run(["chargedParticleFoam"], peer, "log.chargedParticleFoam", env)
            tp = openfoam_timing(os.path.join(peer, "log.chargedParticleFoam"))
            peers.append(results["spheres"]["n"]*tp["steps"]/tp["seconds"])
            log(f"         {tp['steps']} steps in {tp['seconds']:.2f} s: "
                f"{1e6/peers[-1]:.3g} us per particle-step; ellipsoids / spheres per particle-step "
                f"{peers[-1]/rec['rate']:.2f}")
    # median run (by rate), with the per-pair ratios in run order
    best = dict(sorted(windows, key=lambda w: w["rate"])[len(windows)//2])
    best["repeats"] = [w["rate"] for w in windows]
    if paired:
        best["peerRates"] = peers
        best["pairRatios"] = [p/w["rate"] for p, w in zip(peers, windows)]
    results["ellipsoids"]["window"] = best


def remove_times_after(case, t):
    """Remove the case's time directories later than t (a window's end),
    so that a repeat starts from the same state."""
    for d in os.listdir(case):
        try:
            later = float(d) > t*(1 + 1e-9) + 1e-15
        except ValueError:
            continue
        if later and os.path.isdir(os.path.join(case, d)):
            shutil.rmtree(os.path.join(case, d))


def cell_study(cfg, runs, env, cells, steps):
    """Sensitivity of the OpenFOAM-based codes to the mesh cell size (their
    broad phase works on the mesh cells): cfSpheres and ofIco windows of
    `steps` steps from the pour of a finished run, for each cell size."""
    n, base = cfg["n"], cfg["base"]
    dt, _, vmax = ph.time_step(n, ph.SPACING_SPHERE, base)
    lz = ph.box_height(n, ph.SPACING_SPHERE, base, ph.CELL_SPHERE)    # the benchmark's box
    dump = os.path.join(runs, "spheres", "settle", "final.dump")
    if not os.path.exists(dump):
        sys.exit(f"settlingBed: {dump} missing: run the benchmark first")
    state = cases.State.from_liggghts_dump(dump)
    out = dict(n=n, steps=steps, rows=[])
    for cell in cells:
        for code in ("cfSpheres", "ofIco"):
            case = os.path.join(runs, "cells", f"{code}-{cell*1e3:g}mm")
            cases.write_case(code, case, cases.Setup(state, steps, dt, base, lz, vmax, cell))
            log(f"[cells] {code}, cells of {cell*1e3:g} mm, {steps} steps, load {loadavg()}")
            la0 = loadavg()
            proc = run_openfoam(case, env)
            t = openfoam_timing(os.path.join(case, f"log.{proc['app']}"))
            rate = n*t["steps"]/t["seconds"]
            log(f"         {1e6/rate:.3g} us per particle-step")
            out["rows"].append(dict(code=code, cell=cell, rate=rate, seconds=t["seconds"],
                                    steps=t["steps"], maxSubCycles=t["maxSubCycles"],
                                    loadStart=la0, loadEnd=loadavg()))
    json.dump(out, open(os.path.join(runs, "results-cells.json"), "w"), indent=1)
    return out


def scale_study(runs, env, sizes, repeats):
    """Cost and memory against N: for each N a bed of the benchmark's height
    (the floor's side grows as sqrt(N), so the time step, the contacts per
    particle and the cells per particle stay), poured by LIGGGHTS, then the
    timed windows of cfSpheres and LIGGGHTS in turns, as the benchmark's.
    Memory: the peak resident size of each window's process."""
    full = CONFIGS["full"]
    out = dict(sizes=sizes, machine=machine_info(), rows=[])
    for n in sizes:
        # at least the benchmark's particle-steps per window: a window of 10^3
        # spheres and 1000 steps lasts half a second, shorter than the
        # machine's load changes
        window = max(full["window"], int(round(full["window"]*full["n"]/n)))
        cfg = dict(full, n=n, base=full["base"]*math.sqrt(n/full["n"]), repeats=repeats,
                   window=window)
        res = {}
        log(f"[scale] N = {n}, floor {cfg['base']*1e3:.1f} mm")
        sphere_benchmark(cfg, os.path.join(runs, "scale", f"n{n}"), env, ["cfSpheres", "liggghts"], res)
        sp = res["spheres"]
        row = dict(n=n, base=cfg["base"], window=cfg["window"])
        for code, c in sp["codes"].items():
            row[code] = dict(rate=c["rate"], rates=c["repeats"], peakRss=c["peakRss"],
                             contactsPerParticle=c["contactsPerParticle"])
        # chargedFoam / LIGGGHTS per pair of runs taken in turn
        row["pairRatios"] = [l/c for c, l in zip(sp["codes"]["cfSpheres"]["runRates"],
                                                  sp["codes"]["liggghts"]["runRates"])]
        out["rows"].append(row)
        json.dump(out, open(os.path.join(runs, "results-scale.json"), "w"), indent=1)
    return out


def scale_table(sc):
    """Cost per particle-step and memory against N (relative to the N of
    the benchmark, 10^4, where run)."""
    rows = sc["rows"]
    ref = next((r for r in rows if r["n"] == CONFIGS["full"]["n"]), rows[0])
    us = lambda r, c: 1e6/r[c]["rate"]
    out = ["| N | floor [mm] | timed steps | contacts per particle | chargedFoam [us per particle-step] | "
           f"/ N = {ref['n']} | LIGGGHTS [us per particle-step] | / N = {ref['n']} | "
           "chargedFoam / LIGGGHTS (median of the pairs) | chargedFoam peak resident [MB] | "
           "LIGGGHTS peak resident [MB] |",
           "|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|"]
    for r in rows:
        out.append(f"| {r['n']} | {r['base']*1e3:.1f} | {r['window']} | "
                   f"{r['cfSpheres']['contactsPerParticle']:.2f} | "
                   f"{us(r, 'cfSpheres'):.3g} | {us(r, 'cfSpheres')/us(ref, 'cfSpheres'):.2f} | "
                   f"{us(r, 'liggghts'):.3g} | {us(r, 'liggghts')/us(ref, 'liggghts'):.2f} | "
                   f"{np.median(r['pairRatios']):.2f} | {r['cfSpheres']['peakRss']/1e6:.0f} | "
                   f"{r['liggghts']['peakRss']/1e6:.0f} |")
    if len(rows) > 1:
        a, b = rows[0], rows[-1]
        per = lambda c: (b[c]["peakRss"] - a[c]["peakRss"])/(b["n"] - a["n"])
        out.append("")
        out.append(f"Memory per particle, the growth of the peak resident size from N = {a['n']} to "
                   f"{b['n']} over the particles added (the mesh grows with the floor, as it would in "
                   f"a user's case): chargedFoam {per('cfSpheres'):.0f} bytes, LIGGGHTS "
                   f"{per('liggghts'):.0f} bytes ({per('cfSpheres')/per('liggghts'):.1f}x).")
    return "\n".join(out)


def cell_table(cs):
    cells = sorted({r["cell"] for r in cs["rows"]})
    out = ["| mesh cell [mm] | " + " | ".join(f"{c} [us per particle-step]" for c in ("cfSpheres", "ofIco")) + " |",
           "|--:|--:|--:|"]
    for cell in cells:
        row = [f"{cell*1e3:g}"]
        for code in ("cfSpheres", "ofIco"):
            r = [x for x in cs["rows"] if x["cell"] == cell and x["code"] == code]
            row.append(f"{1e6/r[0]['rate']:.3g}" if r else "-")
        out.append("| " + " | ".join(row) + " |")
    return "\n".join(out)


# ----------------------------------------------------------------------------
# Report

def _sub(c):
    if c.get("app") == "liggghts":
        return "1"
    if c["maxSubCycles"] == 1:
        return "1 (all steps)"
    return f"up to {c['maxSubCycles']} ({c['stepsSubCycled']} steps)"


def tables(res):
    sp = res.get("spheres", {})
    codes = sp.get("codes", {})
    lig = codes.get("liggghts")
    out = []
    rows = []
    for code in SPHERE_CODES:
        if code in codes:
            rows.append((code, cases.CODES[code], sp["n"], codes[code]))
    ell = res.get("ellipsoids", {}).get("window")
    if ell:
        rows.append(("cfEllipsoids", cases.CODES["cfEllipsoids"] + " (own bed, see notes)",
                     res["ellipsoids"]["n"], ell))
    out.append("| code | N | timed steps | loop CPU time [s] | loop wall time [s] | particle-steps/s "
               "| us per particle-step | cost / LIGGGHTS | sub-cycles per step |")
    out.append("|---|--:|--:|--:|--:|--:|--:|--:|--:|")
    for code, desc, n, c in rows:
        ratio = f"**{lig['rate']/c['rate']:.1f}**" if lig else "-"
        wall = c.get("loopWall", c.get("clockSeconds"))
        reps = c.get("repeats", [])
        med = f" (median of {len(reps)})" if len(reps) > 1 else ""
        out.append(f"| {code}: {desc} | {n} | {c['steps']} | {c['seconds']:.2f}{med} | {wall:.4g} | "
                   f"{c['rate']:.3g} | {1e6/c['rate']:.3g} | {ratio} | {_sub(c)} |")
    out.append("")
    out.append("Sanity check of the beds at the end of the timed window (the sphere codes start from the "
               "same state):")
    out.append("")
    out.append("| bed | particles | mean height of centres [mm] | translational kinetic energy [J] "
               "| contacts per particle | particle-wall contacts |")
    out.append("|---|--:|--:|--:|--:|--:|")
    st = sp.get("settle")
    if st:
        out.append(f"| start (LIGGGHTS pour, t = {sp['settleSteps']*sp['dt']:.4f} s) | {sp['n']} | "
                   f"{st['zmean']*1e3:.4f} | {st['keFinal']:.3e} | {st['contactsPerParticle']:.2f} | - |")
    for code in SPHERE_CODES:
        if code in codes:
            c = codes[code]
            out.append(f"| {code} | {c['n']} | {c['zmean']*1e3:.4f} | {c['keFinal']:.3e} | "
                       f"{c['contactsPerParticle']:.2f} | {c['wallContacts']} |")
    if ell:
        out.append(f"| cfEllipsoids (own bed, {res['ellipsoids']['n']} ellipsoids) | {ell['n']} | "
                   f"{ell['zmean']*1e3:.4f} | {ell['keFinal']:.3e} | {ell['coordFinal']:.2f} | "
                   f"{ell.get('wallContactsLog', '-')} |")
    cf = codes.get("cfSpheres")
    if ell and cf and ell.get("pairContacts") is not None:
        out.append("")
        out.append("Ellipsoids against spheres (chargedFoam; contacts = particle pairs in contact + wall "
                   "contacts at the end of the window):")
        out.append("")
        out.append("| bed | N | contacts | us per particle-step | us per contact-step | ellipsoids / spheres "
                   "per particle-step | per contact-step |")
        out.append("|---|--:|--:|--:|--:|--:|--:|")
        nc_s = cf["contactsPerParticle"]*cf["n"]/2 + cf["wallContacts"]
        nc_e = ell["pairContacts"] + ell["wallContactsLog"]
        us_s, us_e = 1e6/cf["rate"], 1e6/ell["rate"]
        uc_s = us_s*sp["n"]/nc_s
        uc_e = us_e*res["ellipsoids"]["n"]/nc_e
        # The ratio: the median of the per-pair ratios where the ellipsoid
        # windows ran in turns with sphere windows, else of the medians
        pairs = ell.get("pairRatios")
        r = statistics.median(pairs) if pairs else us_e/us_s
        perContact = (res["ellipsoids"]["n"]/nc_e)/(sp["n"]/nc_s)
        out.append(f"| cfSpheres | {sp['n']} | {nc_s:.0f} | {us_s:.3g} | {uc_s:.3g} | 1 | 1 |")
        out.append(f"| cfEllipsoids | {res['ellipsoids']['n']} | {nc_e} | {us_e:.3g} | {uc_e:.3g} | "
                   f"**{r:.1f}** | **{r*perContact:.1f}** |")
        if pairs:
            out.append("")
            out.append(f"The ratios are the median of {len(pairs)} ellipsoid windows, each run in turn with a "
                       f"cfSpheres window (ellipsoids / spheres per particle-step, in run order: "
                       f"{', '.join(f'{x:.2f}' for x in pairs)}); the us columns are the medians of each "
                       f"code's runs.")
    return "\n".join(out)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("-quick", action="store_true", help="small N (see CONFIGS)")
    ap.add_argument("-runs", default=os.path.join(HERE, "runs"), help="case directory root")
    ap.add_argument("-doc", default=None,
                    help=f"markdown file for the results (default: {os.path.relpath(DOC, ROOT)}; "
                         "with -quick only when given)")
    ap.add_argument("-no-doc", action="store_true", help="do not write the markdown file")
    ap.add_argument("-only", default="", help="comma-separated codes (default: all)")
    ap.add_argument("-cells", default="",
                    help="comma-separated mesh cell sizes [m]: after a run, time cfSpheres and ofIco "
                         "for each (windows of -cell-steps steps from the same pour)")
    ap.add_argument("-cell-steps", type=int, default=300)
    ap.add_argument("-scale", default="",
                    help="comma-separated numbers of spheres (e.g. 1e3,1e4,1e5): cost per particle-step "
                         "and peak memory of cfSpheres and LIGGGHTS against N (beds of the benchmark's "
                         "height; table added to the doc by the next -report)")
    ap.add_argument("-scale-repeats", type=int, default=3)
    ap.add_argument("-report", action="store_true",
                    help="no runs: print the tables of the last run (RUNS/<mode>/results.json) and "
                         "rewrite the doc from it")
    args = ap.parse_args()

    mode = "quick" if args.quick else "full"
    if args.doc is None and not args.quick:
        args.doc = DOC
    if args.doc is None:
        args.no_doc = True
    cfg = CONFIGS[mode]
    runs = os.path.join(os.path.abspath(args.runs), mode)
    resfile = os.path.join(runs, "results.json")

    if args.cells:
        env = dict(os.environ)
        snap = os.path.join(runs, "snapshot")
        env["LD_LIBRARY_PATH"] = os.path.join(snap, "lib") + ":" + env.get("LD_LIBRARY_PATH", "")
        env["PATH"] = os.path.join(snap, "bin") + ":" + env["PATH"]
        cs = cell_study(cfg, runs, env, [float(c) for c in args.cells.split(",")], args.cell_steps)
        print(cell_table(cs))
        return 0

    if args.scale:
        os.makedirs(runs, exist_ok=True)
        env = snapshot_chargedfoam(runs)
        env["OMP_NUM_THREADS"] = "1"
        sc = scale_study(runs, env, [int(float(v)) for v in args.scale.split(",")], args.scale_repeats)
        print(scale_table(sc))
        return 0

    if args.report:
        res = json.load(open(resfile))
        print(tables(res))
        if not args.no_doc and res.get("complete"):
            import report
            report.write_doc(args.doc, res, tables(res), quick=args.quick, regenerated=True)
            print(f"wrote {args.doc}")
        return 0

    only = [c for c in args.only.split(",") if c]
    for c in only:
        if c not in ALL_CODES:
            ap.error(f"unknown code {c}; valid: {', '.join(ALL_CODES)}")

    for exe in ("liggghts", "chargedParticleFoam", "icoUncoupledKinematicParcelFoam", "blockMesh"):
        if not shutil.which(exe):
            sys.exit(f"settlingBed: {exe} not found (source etc/bashrc; apt-get install liggghts)")

    os.makedirs(runs, exist_ok=True)
    env = snapshot_chargedfoam(runs)
    env["OMP_NUM_THREADS"] = "1"
    t0 = time.time()
    res = dict(mode=mode, config=cfg, machine=machine_info(), loadStart=loadavg(),
               material=dict(d=ph.D, rho=ph.RHO, E=ph.E, nu=ph.NU, e=ph.REST, mu=ph.MU, g=ph.G,
                             beta=ph.damping_ratio_cached(ph.REST),
                             alpha=math.sqrt(5)*abs(ph.damping_ratio_cached(ph.REST)),
                             eLiggghts=ph.liggghts_restitution(ph.damping_ratio_cached(ph.REST))))
    log(f"settlingBed ({mode}): {res['machine']['cpu']}, nproc {res['machine']['nproc']}, "
        f"load {loadavg()}; cases in {runs}")

    if not only or any(c in SPHERE_CODES for c in only):
        sphere_benchmark(cfg, runs, env, only, res)
    if not only or "cfEllipsoids" in only:
        ellipsoid_benchmark(cfg, runs, env, res)
    res["totalSeconds"] = time.time() - t0
    res["loadEnd"] = loadavg()
    res["complete"] = not only
    json.dump(res, open(resfile, "w"), indent=1)

    print()
    print(tables(res))
    print(f"\ntotal {res['totalSeconds']/60:.1f} min; results in {resfile}")
    if not args.no_doc and not only:
        import report
        report.write_doc(args.doc, res, tables(res), quick=args.quick)
        print(f"wrote {args.doc}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
