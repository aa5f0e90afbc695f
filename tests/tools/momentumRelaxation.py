#!/usr/bin/env python3
"""Two-velocity relaxation of gas and particles in a periodic box, against
the exact solution, for chargedDPMFoam's momentum coupling schemes.

    momentumRelaxation.py WORKDIR [--loadings 0.1 1 10 30]
        [--dt-tau 0.01 0.1 1 10] [--schemes conservativeImplicit
        semiImplicit explicit] [--check]

A fully periodic box of 2 x 2 x 2 cells (1 mm), no gravity, one parcel of
spheres (d = 20 um, rho_p 2500 kg/m3, nParticle n) at each cell centre, so
that every field stays uniform. Air (rho 1.2 kg/m3, nu 1.5e-5 m2/s) moving
at 1e-5 m/s and particles at rest ('gas' rows), or the reverse
('particles' rows): Re ~ 1e-5, so the drag is Stokes' to 1e-4 and
tau_p = rho_p d^2/(18 mu). With the mass loading ML = n m_p/(rho alpha V),
the exact solution (Stokes drag, uniform fields) is

    w = u - v = w0 exp(-(1 + ML) t/tau_p),
    u = U* + ML w/(1 + ML),  v = U* - w/(1 + ML),  U* = (u0 + ML v0)/(1 + ML)

Printed per row: the largest relative change of the total momentum
rho sum(alpha V u) + sum(n m v) (written every step or every few), the
largest error of the slip |w - w_exact|/|w0|, and whether the run stayed
bounded (|w| <= |w0|) and ended.

--check: PASS/FAIL lines for conservativeImplicit: momentum constant to
1e-8 relative in every row, bounded in every row, and the slip error
below 0.6 (1 + ML) dt/tau_p (first order in the step) where that is < 1.
"""
import argparse
import glob
import math
import os
import re
import shutil
import subprocess
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                "..", "..", "etc", "python"))
from foamLagrangian import read_field, read_internal_field  # noqa: E402

ap = argparse.ArgumentParser(description=__doc__,
                             formatter_class=argparse.RawDescriptionHelpFormatter)
ap.add_argument("work")
ap.add_argument("--loadings", type=float, nargs="+", default=[0.1, 1, 10, 30])
ap.add_argument("--dt-tau", type=float, nargs="+", default=[0.01, 0.1, 1, 10])
ap.add_argument("--schemes", nargs="+",
                default=["conservativeImplicit", "semiImplicit", "explicit"])
ap.add_argument("--directions", nargs="+", default=["gas", "particles"])
ap.add_argument("--check", action="store_true")
a = ap.parse_args()

top = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
rhoP, d, rhoG, nu = 2500.0, 20e-6, 1.2, 1.5e-5
mu = rhoG*nu
tau = rhoP*d**2/(18*mu)
mP = rhoP*math.pi*d**3/6
vP = math.pi*d**3/6
h, nCells = 1e-3, 8
Vc = h**3
speed = 1e-5

case = os.path.join(a.work, "case")
shutil.rmtree(case, ignore_errors=True)
shutil.copytree(os.path.join(top, "tutorials", "gasSettling"), case,
                ignore=shutil.ignore_patterns("[1-9]*", "processor*", "log.*"))


def sub(path, pattern, repl, count=1):
    s = open(path).read()
    s, k = re.subn(pattern, repl, s, count=count, flags=re.M)
    assert k >= 1, (path, pattern)
    open(path, "w").write(s)


bm = os.path.join(case, "system", "blockMeshDict")
shutil.copy(os.path.join(case, "system", "blockMeshDict.periodic"), bm)
sub(bm, r"^scale .*;", "scale   1e-3;")
sub(bm, r"\(10  0  0\)", "(2 0 0)")
sub(bm, r"\(10 10  0\)", "(2 2 0)")
sub(bm, r"\( 0 10  0\)", "(0 2 0)")
sub(bm, r"\( 0  0 20\)", "(0 0 2)")
sub(bm, r"\(10  0 20\)", "(2 0 2)")
sub(bm, r"\(10 10 20\)", "(2 2 2)")
sub(bm, r"\( 0 10 20\)", "(0 2 2)")
sub(bm, r"\(8 8 16\)", "(2 2 2)")
sub(os.path.join(case, "constant", "g"), r"^value .*;", "value           (0 0 0);")
cp = os.path.join(case, "constant", "cloudProperties")
sub(cp, r"^(\s*)gravity;\s*$\n", "")
sub(cp, r"^(\s*shape\s+).*;", r"\1(1 1 1);")
sub(cp, r"^(\s*value\s+)8e-5;", rf"\g<1>{d};")
sub(cp, r"^(\s*momentumCoupling\s+).*;", r"\1sourceTerms;")
with open(os.path.join(case, "constant", "cloudPositions"), "w") as f:
    f.write("FoamFile\n{\n    version 2.0;\n    format ascii;\n"
            "    class vectorField;\n    object cloudPositions;\n}\n\n8\n(\n")
    for i in range(2):
        for j in range(2):
            for k in range(2):
                f.write(f"({(i + 0.5)*h} {(j + 0.5)*h} {(k + 0.5)*h})\n")
    f.write(")\n")
r = subprocess.run(["blockMesh"], cwd=case, stdout=open(os.path.join(case, "log.blockMesh"), "w"),
                   stderr=subprocess.STDOUT)
if r.returncode:
    sys.exit("blockMesh failed in " + case)


def run(scheme, ML, dtTau, direction):
    n = ML*rhoG*Vc/(mP + ML*rhoG*vP)
    alpha = 1 - n*vP/Vc
    u0, v0 = (speed, 0.0) if direction == "gas" else (0.0, speed)
    dt = dtTau*tau
    # to w/w0 = exp(-4), at least 5 steps, about 20 writes
    steps = max(5, int(math.ceil(4/((1 + ML)*dtTau))))
    every = max(1, steps//20)
    for t in glob.glob(os.path.join(case, "[0-9]*")):
        if os.path.basename(t) != "0":
            shutil.rmtree(t)
    sub(os.path.join(case, "0", "U.air"), r"^internalField .*;",
        f"internalField   uniform ({u0} 0 0);")
    sub(cp, r"^(\s*nParticle\s+).*;", rf"\g<1>{n!r};")
    sub(cp, r"^(\s*U0\s+).*;", rf"\g<1>({v0} 0 0);")
    coupling = "conservativeImplicit" if scheme == "conservativeImplicit" else "sourceTerms"
    sub(cp, r"^(\s*momentumCoupling\s+).*;", rf"\g<1>{coupling};")
    sub(cp, r"^(\s*U\s+)(semiImplicit|explicit) 1;",
        rf"\g<1>{'explicit' if scheme == 'explicit' else 'semiImplicit'} 1;")
    ctl = os.path.join(case, "system", "controlDict")
    sub(ctl, r"^deltaT .*;", f"deltaT          {dt!r};")
    sub(ctl, r"^endTime .*;", f"endTime         {steps*dt!r};")
    sub(ctl, r"^writeInterval .*;", f"writeInterval   {every};")
    sub(ctl, r"^writePrecision .*;", "writePrecision  17;")
    sub(ctl, r"^timePrecision .*;", "timePrecision   12;")
    log = os.path.join(case, "log.chargedDPMFoam")
    r = subprocess.run(["chargedDPMFoam"], cwd=case, stdout=open(log, "w"),
                       stderr=subprocess.STDOUT)
    ended = r.returncode == 0
    P0 = rhoG*alpha*Vc*nCells*u0 + nCells*n*mP*v0
    w0 = u0 - v0
    dP, dW, bounded = 0.0, 0.0, True
    times = sorted((t for t in glob.glob(os.path.join(case, "[0-9]*"))
                    if os.path.basename(t) != "0"
                    and os.path.isfile(os.path.join(t, "U.air"))),
                   key=lambda t: float(os.path.basename(t)))
    for t in times:
        time = float(os.path.basename(t))
        ug = read_internal_field(os.path.join(t, "U.air"), nCells)[:, 0]
        al = read_internal_field(os.path.join(t, "alpha.air"), nCells)
        up = read_field(os.path.join(t, "lagrangian", "cloud", "U"))[:, 0]
        P = rhoG*float(np.sum(al*ug))*Vc + n*mP*float(np.sum(up))
        if not np.isfinite(P):
            bounded = False
            break
        dP = max(dP, abs(P - P0)/abs(P0))
        w = float(np.mean(ug) - np.mean(up))
        wEx = w0*math.exp(-(1 + ML)*time/tau)
        dW = max(dW, abs(w - wEx)/abs(w0))
        if abs(w) > abs(w0)*(1 + 1e-9):
            bounded = False
    return dict(ended=ended and len(times) > 0, dP=dP, dW=dW, bounded=bounded,
                steps=steps)


rows = []
print(f"tau_p = {tau:.6g} s, cells of {h*1e3:g} mm, d = {d*1e6:g} um")
print("| slip from | mass loading | dt/tau_p | scheme | momentum change | slip error | bounded |")
print("| --- | --- | --- | --- | --- | --- | --- |")
for direction in a.directions:
    for ML in a.loadings:
        for dtTau in a.dt_tau:
            for scheme in a.schemes:
                res = run(scheme, ML, dtTau, direction)
                rows.append((direction, ML, dtTau, scheme, res))
                state = ("yes" if res["bounded"] else "no") \
                    + ("" if res["ended"] else " (run failed)")
                print(f"| {direction} | {ML:g} | {dtTau:g} | {scheme} |"
                      f" {res['dP']:.2e} | {res['dW']:.2e} | {state} |", flush=True)

if a.check:
    mine = [r for r in rows if r[3] == "conservativeImplicit"]
    worstP = max(r[4]["dP"] for r in mine)
    ok = all(r[4]["ended"] for r in mine) and worstP <= 1e-8
    print(("PASS" if ok else "FAIL") + ": momentumCoupling.momentum (conservativeImplicit:"
          f" total momentum constant to {worstP:.2e} relative over {len(mine)} rows,"
          " tolerance 1e-8)")
    bad = [r for r in mine if not r[4]["bounded"]]
    print(("PASS" if not bad else "FAIL") + ": momentumCoupling.bounded (conservativeImplicit:"
          f" slip never grows in {len(mine) - len(bad)} of {len(mine)} rows)")
    acc = [r for r in mine if 0.6*(1 + r[1])*r[2] < 1]
    worst = max(acc, key=lambda r: r[4]["dW"]/((1 + r[1])*r[2]))
    ratio = worst[4]["dW"]/((1 + worst[1])*worst[2])
    print(("PASS" if ratio <= 0.6 else "FAIL") + ": momentumCoupling.relaxation"
          f" (conservativeImplicit, {len(acc)} rows with (1 + ML) dt/tau_p < 1/0.6:"
          f" slip error <= {ratio:.3f} (1 + ML) dt/tau_p, worst at ML {worst[1]:g},"
          f" dt/tau_p {worst[2]:g}; tolerance 0.6)")
