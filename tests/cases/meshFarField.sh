# electrostaticsModel meshPoisson (FV Poisson far field + shaped near-field
# correction) against exact references: a charge near a grounded wall and a
# random cloud in a grounded box vs the image solution (tests/tools/
# groundedBox.py, Ewald sum of the images); the error falls with mesh
# refinement and with the shape radius; the shaped correction beats Rasera's
# Eq. 31 (cellCentroid); 2 processors equal serial; a tri-periodic box
# (cyclic patches, neutralising background) vs the periodic Ewald kernel; an
# applied field from electrode potentials; bad input.
. "$(dirname "$0")/common.sh.inc"

$PY - "$work" "$top" <<'PYEOF'
import os, sys
import numpy as np
work, top = sys.argv[1], sys.argv[2]
sys.path.insert(0, top + "/applications/benchmarks/meshFarField")
sys.path.insert(0, top + "/tests/tools")
from farFieldCase import FarFieldCase, ELECTRODES, electrodesPhi
import groundedBox as gb

def report(name, ok, detail):
    print(f"{'PASS' if ok else 'FAIL'}: meshFarField.{name} ({detail})", flush=True)

def rms_err(E, Eref):
    return np.sqrt(np.mean(np.sum((E - Eref)**2, axis=1))/np.mean(np.sum(Eref**2, axis=1)))

def run(name, x, q, n, model="meshPoisson", coeffs="radius 0.15;", nProcs=1, **kw):
    c = FarFieldCase(f"{work}/{name}", x, q, 1.0, n, model, coeffs, **kw)
    try:
        c.run(nProcs)
        return c.fields()[0]
    except RuntimeError as e:
        print(f"    {e}")
        return None

# 1. One charge 0.1 m from a grounded wall (its shape, radius 0.15 m, is cut
#    by the wall: the images carry it) vs the image solution of the box
x1 = np.array([[0.1, 0.5, 0.5]]); q1 = np.array([1e-9])
ref1 = gb.field(x1, q1, 1.0)
e = {}
for n in (16, 32):
    E = run(f"plane{n}", x1, q1, n)
    e[n] = np.linalg.norm(E - ref1)/np.linalg.norm(ref1) if E is not None else np.inf
report("imagePlane", e[32] < 0.05 and e[32] < e[16]/1.8,
       f"|E - E_image|/|E_image| at d = 0.1 m: h = 1/16: {e[16]:.2e}, 1/32: {e[32]:.2e} (< 0.05, ratio >= 1.8)")

# 2-4. 100 random charges of both signs
rng = np.random.default_rng(1)
x = 0.05 + 0.9*rng.random((100, 3)); q = 1e-9*(2*rng.random(100) - 1)
ref = gb.field(x, q, 1.0)
err = {}
for name, n, coeffs in [("n16", 16, "radius 0.15;"), ("n32", 32, "radius 0.15;"),
                        ("R01", 32, "radius 0.1;"), ("R03", 32, "radius 0.3;"),
                        ("centroid", 32, "correction cellCentroid; rCut 0.15;")]:
    E = run(name, x, q, n, coeffs=coeffs)
    err[name] = rms_err(E, ref) if E is not None else np.inf
e16, e32 = err["n16"], err["n32"]
report("refinement", e32 < e16/2.5 and e32 < 0.02,
       f"rms rel. force error, radius 0.15 m: h = 1/16: {e16:.2e}, 1/32: {e32:.2e} (ratio {e16/e32:.1f} >= 2.5, and < 0.02)")
report("radius", err["R03"] < e32 < err["R01"],
       f"h = 1/32, radius 0.1/0.15/0.3 m: {err['R01']:.2e} > {e32:.2e} > {err['R03']:.2e}")
report("shapedVsEq31", 3*e32 < err["centroid"],
       f"h = 1/32, radius = rCut = 0.15 m: shaped {e32:.2e} vs cellCentroid (Rasera Eq. 31) {err['centroid']:.2e}, >= 3x better")

# 4b. solveInterval 3, step 2 (the copies and images follow the
#     charges between solves) equals a fresh solve (resting charges)
E = run("interval", x, q, 32, coeffs="radius 0.15; solveInterval 3;", steps=2)
Es = run("serial", x, q, 32)
if E is None or Es is None:
    report("solveInterval", False, "run failed")
else:
    d = np.abs(E - Es).max()/np.abs(Es).max()
    report("solveInterval", d < 1e-9, f"solveInterval 3, step 2 (no solve) vs solveInterval 1: max |dE|/max|E| = {d:.1e}, tol 1e-9")

# 5. 2 processors vs serial
Ep = run("parallel", x, q, 32, nProcs=2)
if Es is None or Ep is None:
    report("parallel", False, "run failed")
else:
    d = np.abs(Ep - Es).max()/np.abs(Es).max()
    report("parallel", d < 1e-7, f"2 processors vs serial: max |dE|/max|E| = {d:.1e}, tol 1e-7 (Poisson tolerance 1e-12)")

# 6. Tri-periodic box (cyclic patches, neutralising background: net charge
#    != 0) vs the periodic Ewald kernel (electrostaticsModel periodic)
qp = 1e-9*(2*rng.random(100) - 0.8)
xp = rng.random((100, 3))
Eew = run("ewald", xp, qp, 4, model="periodic", coeffs="method ewald; accuracy 1e-10;", periodic=True)
res = {}
for n in (16, 32):
    E = run(f"cyclic{n}", xp, qp, n, periodic=True)
    res[n] = rms_err(E, Eew) if (E is not None and Eew is not None) else np.inf
report("periodic", res[32] < 0.02 and res[32] < res[16]/2.5,
       f"cyclic box, net charge {qp.sum():.1e} C, vs Ewald: rms rel. error h = 1/16: {res[16]:.2e}, 1/32: {res[32]:.2e} (< 0.02, ratio >= 2.5)")

# 7. Applied field: electrodes at 0 V and 100 V 1 m apart, insulating
#    sides; two neutral probes see E = (-100, 0, 0) V/m
xe = np.array([[0.3, 0.4, 0.5], [0.7, 0.6, 0.2]]); qe = np.zeros(2)
E = run("electrodes", xe, qe, 8, boundary=ELECTRODES, Phi=electrodesPhi(100))
if E is None:
    report("appliedField", False, "run failed")
else:
    d = np.abs(E - [-100, 0, 0]).max()/100
    report("appliedField", d < 1e-8, f"E at neutral probes vs -V/L: max rel. deviation {d:.1e}, tol 1e-8")

# 8. Bad input: missing radius, no solver for Phi
c = FarFieldCase(f"{work}/bad", x1, q1, 1.0, 4, "meshPoisson", "epsilonR 1;")
try:
    c.run(); ok = False
except RuntimeError:
    ok = "Entry radius" in c.log() and "must be given, finite and > 0" in c.log()
report("badRadius", ok, "missing radius: FatalIOError naming the entry")
c = FarFieldCase(f"{work}/bad2", x1, q1, 1.0, 4, "meshPoisson", "radius 0.3;")
c.write()
with open(f"{work}/bad2/system/fvSolution", "w") as f:
    f.write("FoamFile { version 2.0; format ascii; class dictionary; object fvSolution; }\nsolvers {}\n")
c.write = lambda: None
try:
    c.run(); ok = False
except RuntimeError:
    ok = "no solver entry for Phi" in c.log()
report("badSolver", ok, "no Phi solver in fvSolution: clear error")
PYEOF
