# Two particle materials in one cloud (constantProperties/materials,
# materialPairs, explicitParcels' material):
#  1. a PTFE sphere hits a nylon sphere head-on (different sizes, densities,
#     moduli; the pair's own e; work functions 5.75 and 4.3 eV): the
#     restitution is the pair's e, the contact lasts the Hertz time of the
#     two materials' E* and m*, and the PTFE takes the charge that Rasera
#     Eq. (16) gives over the Hertz loading with Gamma from the work
#     functions (electrons from nylon to PTFE: PTFE negative), the nylon
#     the opposite;
#  2. a pour of 25 PTFE and 25 nylon ellipsoids into a grounded steel box
#     charges bipolar (PTFE negative, nylon positive), each material's
#     charge changes by what it got from the walls and from particles, and
#     the particles + walls keep the charge to round-off; a restart continues exactly, 2 processors reproduce the
#     serial run;
#  3. OpenFOAM's manualInjection with a material (and an injectorID): its
#     parcels are of that material and density, with a mass basis they
#     carry the model's massTotal.
. "$(dirname "$0")/common.sh.inc"

# ---- 1. head-on PTFE-nylon --------------------------------------------------
copyCase headOnCollision "$work/pair"
cd "$work/pair" || exit 1
$PY - <<'PYEOF'
p = "constant/cloudProperties"
s = open(p).read()
s = s.replace("""    poissonsRatio   0.3;
}""", """    poissonsRatio   0.3;
    materials
    {
        PTFE    { rho0 2150; youngsModulus 0.564e9; poissonsRatio 0.42; }
        nylon   { rho0 1140; youngsModulus 2.7e9;   poissonsRatio 0.39; }
    }
}""", 1)
s = s.replace("{ position (-0.55e-3 0 0); U ( 0.5 0 0); d 1e-3; q 0; }",
              "{ position (-0.55e-3 0 0); U ( 0.5 0 0); d 1e-3; q 0; material PTFE; }")
s = s.replace("{ position ( 0.55e-3 0 0); U (-0.5 0 0); d 1e-3; q 0; }",
              "{ position ( 0.46e-3 0 0); U (-0.5 0 0); d 0.8e-3; q 0; material nylon; }")
s = s.replace("        tangentialModel         mindlin;", """        tangentialModel         mindlin;
        materialPairs
        {
            PTFEnylon { materials (nylon PTFE); e 0.7; mu 0.1; }
        }""", 1)
s = s.replace("    electrostaticsModel none;", """    electrostaticsModel none;
    triboChargingModel  workFunction;
    workFunctionCoeffs
    {
        cutoffDistance  500e-9;
        particles
        {
            kappaC  20;
            PTFE    { workFunction 5.75; }
            nylon   { workFunction 4.3; }
        }
        materialPairs { PTFEnylon { materials (PTFE nylon); kappaC 5; } }
        walls { ".*" { kappaC 10; workFunction 4.4; } }
    }""", 1)
open(p, "w").write(s)
PYEOF
setEndTime 2e-4
run blockMesh blockMesh && run solver chargedParticleFoam \
    || fail "triboMixture.pairRun (solver failed)"
check triboMixture.pairLog "(the log lists the PTFE-nylon law)" \
    grep -q "PTFE: with nylon E\* = " log.solver
$PY - "$top" <<'PYEOF'
import glob, math, sys
import numpy as np
sys.path.insert(0, sys.argv[1] + "/tutorials/headOnCollision")
from headOnCollision import gamma_for, impact

d = np.vstack([np.loadtxt(f, ndmin=2) for f in
               sorted(glob.glob("postProcessing/lagrangian/cloud/particleHistory/*/particleHistory.dat"))])
a, b = (d[d[:, 2] == i] for i in (0, 1))
eps0, e = 8.8541878128e-12, 1.602176634e-19
E = {"PTFE": (0.564e9, 0.42), "nylon": (2.7e9, 0.39)}
rA, rB = 0.5*a[0, 9], 0.5*b[0, 9]
mA = a[0, 10]*4/3*math.pi*rA**3
mB = b[0, 10]*4/3*math.pi*rB**3
ok = abs(a[0, 10] - 2150) < 1e-9 and abs(b[0, 10] - 1140) < 1e-9
print(f"{'PASS' if ok else 'FAIL'}: triboMixture.density (PTFE {a[0, 10]:g}, nylon {b[0, 10]:g} kg/m3 from the materials)")
Estar = 1/sum((1 - nu**2)/Y for Y, nu in E.values())
Rstar, mstar = rA*rB/(rA + rB), mA*mB/(mA + mB)
v0 = abs(a[0, 6] - b[0, 6])
k = 4/3*Estar*math.sqrt(Rstar)
delta0 = (mstar*v0**2/k)**0.4
t0 = delta0/v0

# The dimensionless impact x'' = -(x^3/2 + sqrt(5)|beta| x^1/4 x')
# (headOnCollision.py's RK4): restitution, duration, largest overlap
_, T, xmax = impact(gamma_for(0.7), 1e-5)

vEnd = abs(a[-1, 6] - b[-1, 6])
eMeas = vEnd/v0
ok = abs(eMeas/0.7 - 1) < 1e-2
print(f"{'PASS' if ok else 'FAIL'}: triboMixture.restitution (measured {eMeas:.5f}, the pair's e 0.7 (cloud's e 0.9), tol 1e-2)")

sep = np.linalg.norm(a[:, 3:6] - b[:, 3:6], axis=1)
dsum = rA + rB
inside = sep < dsum
i0 = np.argmax(inside); i1 = len(inside) - np.argmax(inside[::-1])
tt = a[:, 0]
cross = lambda i: tt[i - 1] + (tt[i] - tt[i - 1])*(dsum - sep[i - 1])/(sep[i] - sep[i - 1])
duration = cross(i1) - cross(i0)
ok = abs(duration/(T*t0) - 1) < 1e-2 and i1 - i0 >= 50
print(f"{'PASS' if ok else 'FAIL'}: triboMixture.duration (measured {duration:.4e} s, Hertz with the two materials' E* and m* {T*t0:.4e} s, {i1 - i0} samples, tol 1e-2)")

# Charge of the impact (Rasera Eq. 16, onto new area only): dq/dA =
# kappa eps0 (Gamma - q c/eps0), c = 1/S_A + 1/S_B (Eq. 28 of both), over
# A = pi R* delta up to its largest value
Gamma = (4.3 - 5.75)/500e-9          # on PTFE from nylon [V/m]
kappa = 5
c = 1/(4*math.pi*rA**2) + 1/(4*math.pi*rB**2)
Amax = math.pi*Rstar*xmax*delta0
qRef = eps0*Gamma/c*(1 - math.exp(-kappa*c*Amax))
qA, qB = a[-1, 11], b[-1, 11]
ok = qA < 0 and abs(qA/qRef - 1) < 1e-2
print(f"{'PASS' if ok else 'FAIL'}: triboMixture.pairCharge (PTFE {qA:.4e} C, Eq. 16 over the Hertz loading {qRef:.4e} C, error {qA/qRef - 1:+.1e}, tol 1e-2)")
ok = abs(qA + qB) <= 1e-15*abs(qA)
print(f"{'PASS' if ok else 'FAIL'}: triboMixture.pairBalance (PTFE {qA:.6e} + nylon {qB:.6e} C = {qA + qB:.1e})")
PYEOF

# ---- 2. a mixture poured into a steel box -----------------------------------
copyCase ellipsoidPour "$work/serial"
cd "$work/serial" || exit 1
$PY makeParcels.py 50 > /dev/null
$PY - <<'PYEOF'
import re
p = "constant/parcels"
s = open(p).read()
n = [0]
def material(m):
    n[0] += 1
    return m.group(0) + (" material PTFE;" if n[0] % 2 else " material nylon;")
s = re.sub(r"q 0;", material, s)
open(p, "w").write(s)
p = "constant/cloudProperties"
s = open(p).read()
s = s.replace("""    poissonsRatio   0.3;
}""", """    poissonsRatio   0.3;
    materials
    {
        PTFE    { rho0 2150; }
        nylon   { rho0 1140; youngsModulus 2.5e7; poissonsRatio 0.39; }
    }
}""", 1)
s = s.replace("electrostaticsModel none;", """electrostaticsModel directCoulomb;

    triboChargingModel  workFunction;
    workFunctionCoeffs
    {
        cutoffDistance  500e-9;
        particles
        {
            kappaC  20;
            PTFE    { workFunction 5.75; }
            nylon   { workFunction 4.3; }
        }
        walls { ".*" { kappaC 10; workFunction 4.4; } }
    }""")
open(p, "w").write(s)
PYEOF
setEndTime 0.08
setWriteInterval 200
cp -r "$work/serial" "$work/restarted"
cp -r "$work/serial" "$work/parallel"

run blockMesh blockMesh && run solver chargedParticleFoam \
    || fail "triboMixture.serialRun (solver failed)"

# mixture <case> <name>: balance, per-material columns, bipolar charging
mixture()
{
    $PY - "$1" "$2" <<'PYEOF'
import sys
import numpy as np
case, name = sys.argv[1:3]
f = case + "/postProcessing/lagrangian/cloud/triboCharging/0/chargeBalance.dat"
head = [l for l in open(f) if l.startswith("# time")][0].split()[1:]
d = np.loadtxt(f)
col = {h: i for i, h in enumerate(head)}
q, wall, bal = d[:, col["parcels"]], d[:, 2], d[:, col["balance"]]
qP, qN = d[:, col["parcels:PTFE"]], d[:, col["parcels:nylon"]]
scale = np.abs(q).max() + np.abs(wall).max()
drift = np.abs(bal - bal[0]).max()/scale
ok = drift < 1e-12
print(f"{'PASS' if ok else 'FAIL'}: triboMixture.{name}.balance (particles + walls drift {drift:.1e} of the charges over {len(d)} lines, tol 1e-12)")
err = np.abs(qP + qN - q).max()/np.abs(q).max()
ok = err < 1e-12
print(f"{'PASS' if ok else 'FAIL'}: triboMixture.{name}.materialSum (PTFE + nylon columns = parcels to {err:.1e})")
# Each material's balance: its charge changes by what it received from the
# walls and from particles; the particles' parts add up to zero
scaleM = np.abs(qP).max() + np.abs(qN).max()
errM = max(np.abs(d[:, col[f"parcels:{m}"]] - d[0, col[f"parcels:{m}"]]
                  - d[:, col[f"fromWalls:{m}"]] - d[:, col[f"fromParticles:{m}"]]).max()
           for m in ("PTFE", "nylon"))/scaleM
pairSum = np.abs(d[:, col["fromParticles:PTFE"]] + d[:, col["fromParticles:nylon"]]).max()/scaleM
fromP = d[-1, col["fromParticles:PTFE"]]
ok = errM < 1e-12 and pairSum < 1e-12 and fromP < 0
print(f"{'PASS' if ok else 'FAIL'}: triboMixture.{name}.materialBalance (each material's charge = "
      f"from walls + from particles to {errM:.1e}; particles' parts add up to {pairSum:.1e}; "
      f"PTFE got {fromP:.3e} C from nylon, {d[-1, col['fromWalls:PTFE']]:.3e} C from the walls)")
ok = qP[-1] < 0 < qN[-1]
print(f"{'PASS' if ok else 'FAIL'}: triboMixture.{name}.bipolar (PTFE {qP[-1]:.3e} C < 0 < nylon {qN[-1]:.3e} C; walls {wall[-1]:.3e} C)")
PYEOF
}
mixture "$work/serial" serial

cd "$work/restarted" || exit 1
setEndTime 0.04
run blockMesh blockMesh && run solver1 chargedParticleFoam \
    || fail "triboMixture.firstHalf (solver failed)"
setEndTime 0.08
run solver2 chargedParticleFoam || fail "triboMixture.secondHalf (solver failed)"
$PY "$tools/compareClouds.py" "$work/serial/0.08" "$work/restarted/0.08" \
    --tol 1e-12 --name triboMixture.restart
$PY - "$work" <<'PYEOF'
import sys
import numpy as np
w = sys.argv[1]
def last(f):
    head = [l for l in open(f) if l.startswith("# time")][0].split()[1:]
    return dict(zip(head, np.loadtxt(f)[-1]))
a = last(w + "/serial/postProcessing/lagrangian/cloud/triboCharging/0/chargeBalance.dat")
b = last(w + "/restarted/postProcessing/lagrangian/cloud/triboCharging/0.04/chargeBalance.dat")
keys = [k for k in a if k.startswith(("fromWalls:", "fromParticles:"))]
err = max(abs(a[k] - b[k]) for k in keys)/max(abs(a[k]) for k in keys)
print(f"{'PASS' if err < 1e-12 else 'FAIL'}: triboMixture.restartMaterialBooks (each material's charge from walls "
      f"and particles at 0.08 s, serial and restarted: {err:.1e} apart)")
PYEOF
check triboMixture.restartMaterials "(material read back: the materials of the restarted cloud)" \
    cmp -s "$work/serial/0.08/lagrangian/cloud/material" "$work/restarted/0.08/lagrangian/cloud/material"

cd "$work/parallel" || exit 1
run blockMesh blockMesh
run decomposePar decomposePar || fail "triboMixture.parallel (decomposePar)"
setEndTime 0.04
run solver mpirun -np 2 chargedParticleFoam -parallel \
    || fail "triboMixture.parallel (mpirun failed)"
run reconstructPar reconstructPar || fail "triboMixture.parallel (reconstructPar)"
$PY "$tools/compareClouds.py" "$work/serial/0.04" "$work/parallel/0.04" \
    --tol 1e-10 --qtol 1e-10 --name triboMixture.parallel
mixture "$work/parallel" parallel

# ---- 3. a material from OpenFOAM's injection model --------------------------
# gasSettling's manualInjection with `material light; injectorID 1;`: every
# parcel is of that material and density; with parcelBasisType mass the
# parcels carry the model's mass (nParticle follows the density)
for basis in fixed mass
do
    copyCase gasSettling "$work/injector-$basis"
    cd "$work/injector-$basis" || exit 1
    $PY - "$basis" <<'PYEOF'
import sys
p = "constant/cloudProperties"
s = open(p).read()
s = s.replace("    shape           (2 1 1);", """    shape           (2 1 1);
    materials { glass {} light { rho0 1000; } }""", 1)
s = s.replace("            type            manualInjection;", """            type            manualInjection;
            material        light;
            injectorID      1;""", 1)
if sys.argv[1] == "mass":
    s = s.replace("            massTotal       0;\n            parcelBasisType fixed;\n            nParticle       20;",
                  "            massTotal       2e-6;\n            parcelBasisType mass;", 1)
open(p, "w").write(s)
PYEOF
    setEndTime 1e-3
    setWriteInterval 2
    { run makePositions $PY makePositions.py --n 20 && run blockMesh blockMesh \
        && run solver chargedDPMFoam; } || fail "triboMixture.injector.$basis (solver failed)"
    $PY - "$basis" <<'PYEOF'
import math, re, sys
basis = sys.argv[1]
def field(name):
    t = open("0.001/lagrangian/cloud/" + name).read().split("// * * *", 1)[-1]
    m = re.search(r"(\d+)\s*(?:\{([^}]*)\}|\(([^)]*)\))", t)
    n = int(m.group(1))
    return [float(m.group(2))]*n if m.group(2) is not None else [float(v) for v in m.group(3).split()]
mat, rho, npart, d = field("material"), field("rho"), field("nParticle"), field("d")
ok = len(mat) == 20 and all(m == 1 for m in mat) and all(r == 1000 for r in rho)
print(f"{'PASS' if ok else 'FAIL'}: triboMixture.injector.{basis}.material ({len(mat)} parcels of material "
      f"{sorted(set(mat))} (light), rho {sorted(set(rho))} kg/m3)")
if basis == "mass":
    mass = sum(n*r*math.pi/6*x**3 for n, r, x in zip(npart, rho, d))
    ok = abs(mass/2e-6 - 1) < 1e-12
    print(f"{'PASS' if ok else 'FAIL'}: triboMixture.injector.mass.massTotal (the parcels carry {mass:.10e} kg, "
          f"massTotal 2e-6 kg; nParticle {npart[0]:.6g} of the light material)")
else:
    ok = all(n == 20 for n in npart)
    print(f"{'PASS' if ok else 'FAIL'}: triboMixture.injector.fixed.nParticle (nParticle {sorted(set(npart))}, given 20)")
PYEOF
done
