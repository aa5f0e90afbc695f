# The electrostatics rungs measured on a case's parcels (chargedFoamAdvisor
# -rungs, ElectrostaticsSurvey) and electrostaticsModel auto, on three kinds
# of scene: the grounded duct of the flagship (2000 charged ellipsoids,
# insulating ends), the tri-periodic mono-charged cloud and an open box.
# The survey's errors are recomputed here from independent references (the
# exact duct field of tests/tools/groundedBox.py, numpy sums in free space);
# the recommendation is the cheapest rung within the accuracy; auto takes
# a rung within the accuracy with the advisor's error, keeps it on restart,
# and 2 processors measure the same errors as 1.
. "$(dirname "$0")/common.sh.inc"

# rungValue <rungs.dat> <rung> <column>: 2 rms, 3 p95, 4 cost, 5 ratio
rungValue() { awk -v r="$2" -v c="$3" '$1 == r { print $c }' "$1"; }
rel() { $PY -c "import sys; a, b, t = map(float, sys.argv[1:]); sys.exit(0 if abs(a/b - 1) <= t else 1)" "$1" "$2" "$3"; }

# The recommended rung is the cheapest with rms <= accuracy, and no rung is
# both cheaper and within it
recommendationRight()
{
    $PY - "$1" <<'PYEOF'
import sys
rows, acc = [], None
for line in open(sys.argv[1]):
    if line.startswith("# accuracy"):
        acc = float(line.split()[2])
    elif line.startswith("nearField:"):
        continue
    elif not line.startswith("#") and line.strip():
        f = line.split()
        rows.append((f[0], float(f[1]), float(f[3]), f[6] == "1"))
ok = [r for r in rows if r[1] <= acc]
rec = [r for r in rows if r[3]]
best = min(ok, key=lambda r: r[2]) if ok else None
print("recommended", rec, "cheapest within", acc, ":", best)
sys.exit(0 if (best is None and not rec) or (rec and rec[0] == best) else 1)
PYEOF
}

# Python: rms force error of a free-space sum (cutoff rc, inf = all pairs)
# against the exact field of the box (groundedBox.py, parity per axis) or
# against the full free-space sum (parity none), over all parcels
freeSpaceError()    # <time dir> <rc> <parity|none> <origin> <L>
{
    $PY - "$@" <<PYEOF
import sys
sys.path.insert(0, "$top/etc/python"); sys.path.insert(0, "$tools")
import numpy as np
from foamLagrangian import read_field, read_positions
import groundedBox
t, rc, parity = sys.argv[1], float(sys.argv[2]), sys.argv[3]
x = read_positions(t + "/lagrangian/cloud/positions")
q = read_field(t + "/lagrangian/cloud/q")
k = 1/(4*np.pi*8.8541878128e-12)
d = x[:, None, :] - x[None, :, :]
r = np.sqrt((d**2).sum(-1))
np.fill_diagonal(r, np.inf)
w = np.where(r < rc, 1/r**3, 0.0)
f = k*q[:, None]*((q[None, :, None]*w[:, :, None]*d).sum(1))
if parity == "none":
    wAll = 1/r**3
    ref = k*q[:, None]*((q[None, :, None]*wAll[:, :, None]*d).sum(1))
else:
    par = tuple(int(p) for p in parity.split(","))
    origin = np.array([float(v) for v in sys.argv[4].split(",")])
    L = np.array([float(v) for v in sys.argv[5].split(",")])
    ref = q[:, None]*groundedBox.field(x, q, L, origin=origin, parity=par)
print(np.sqrt(((f - ref)**2).sum()/(ref**2).sum()))
PYEOF
}

# 1. The flagship duct (grounded side walls, insulating ends): 2000
#    ellipsoids after two steps, charged here at random (both signs)
copyCase chargedDuct "$work/duct"
cd "$work/duct" || exit 1
$PY makeParcels.py 2000 > log.makeParcels || fail "advisorRungs.duct (makeParcels failed)"
setEndTime 0.0002
setWriteInterval 2
run blockMesh blockMesh && run solver chargedDPMFoam || fail "advisorRungs.duct (solver failed)"
$PY - <<PYEOF
import sys; sys.path.insert(0, "$top/etc/python")
import numpy as np
from foamLagrangian import read_field, write_field
p = "0.0002/lagrangian/cloud/q"
n = len(read_field(p))
write_field(p, np.random.default_rng(1).normal(-2e-13, 1.5e-13, n))
PYEOF
cp -r "$work/duct" "$work/ductParallel"
cp -r "$work/duct" "$work/ductAuto"
start=$(date +%s.%N)
run advisor chargedFoamAdvisor -latestTime -rungs -sampleSize 2000 \
    || fail "advisorRungs.duct (advisor failed)"
seconds=$($PY -c "import time; print(round(time.time() - $start, 1))")
check advisorRungs.ductSpeed "(the advisor with every rung on the 2000-parcel duct: $seconds s < 120 s)" \
    $PY -c "import sys; sys.exit(0 if $seconds < 120 else 1)"
dat=postProcessing/advisor/0.0002/rungs.dat
# The scene report's time scales: Hertz collision time of the fastest
# parcel head-on against its copy at its sharpest tip (Johnson 1985:
# 2.868 (m*^2/(R* E*^2 v))^(1/5), m* = m/2, R* = c^2/(2 a), E* = E/(2 (1 -
# nu^2)), v = 2 |U|) and the Stokes response time rho d_v^2/(18 mu) of the
# volume-equivalent sphere, from the parcels written here
tc=$(sed -nE 's/.*Hertz collision ([-0-9.e+]+) s.*/\1/p' log.advisor | head -1)
tau=$(sed -nE 's/.*drag response \(Stokes\) median ([-0-9.e+]+) s.*/\1/p' log.advisor | head -1)
read -r tcExpect tauExpect <<< "$($PY - <<PYEOF
import sys; sys.path.insert(0, "$top/etc/python")
import numpy as np
from foamLagrangian import read_field
t = "0.0002/lagrangian/cloud/"
U, ax, rho = read_field(t + "U"), read_field(t + "semiAxes"), read_field(t + "rho")
a, c = ax.max(1), ax.min(1)
m = rho*4/3*np.pi*ax.prod(1)
E, nu = 0.564e9, 0.42
Es = E/(2*(1 - nu**2))
v = 2*np.linalg.norm(U, axis=1)
tc = (2.868*((m/2)**2/(c**2/a/2*Es**2*v))**0.2).min()
dv = 2*np.cbrt(ax.prod(1))
tau = np.median(rho*dv**2/(18*1.2*1.5e-5))
print(tc, tau)
PYEOF
)"
check advisorRungs.hertzTime "($tc s vs Johnson $tcExpect s)" rel "$tc" "$tcExpect" 1e-3
check advisorRungs.dragTime "($tau s vs Stokes $tauExpect s)" rel "$tau" "$tauExpect" 1e-3
check advisorRungs.ductScene "(box, x insulating, y and z grounded, boxImages)" \
    grep -q "scene box ((0.6 0.02 0.02) m; faces x insulating y grounded z grounded), reference boxImages" log.advisor
# The reference and the error measure, recomputed: free-space sums against
# the exact duct field (image Ewald sums in Python, parity (+1, -1, -1))
for rung in directCoulomb "cutoffCoulomb(rCut=4l)"
do
    got=$(rungValue $dat "$rung" 2)
    if [ "$rung" = directCoulomb ]; then rc=inf
    else rc=$(awk '/^# spacing/ { print 4*$3 }' $dat); fi
    expect=$(freeSpaceError 0.0002 "$rc" 1,-1,-1 0,0,0 0.6,0.02,0.02)
    check "advisorRungs.ductReference.$rung" "(rms $got vs $expect from groundedBox.py)" \
        rel "$got" "$expect" 1e-3
done
m2=$(rungValue $dat "meshPoisson(radius=2h)" 2)
m4=$(rungValue $dat "meshPoisson(radius=4h)" 2)
check advisorRungs.ductMesh "(meshPoisson rms $m4 at 4 cells < $m2 at 2 cells < 5 %)" \
    $PY -c "import sys; sys.exit(0 if $m4 < $m2 < 0.05 else 1)"
check advisorRungs.ductFreeSpaceFails "(free-space sums > 20 % in the grounded duct)" \
    $PY -c "import sys; sys.exit(0 if $(rungValue $dat directCoulomb 2) > 0.2 else 1)"
check advisorRungs.ductRecommendation "(cheapest within 5 %)" recommendationRight $dat
check advisorRungs.plot "(rungs.png written)" test -s postProcessing/advisor/0.0002/rungs.png

# 2 processors: the same errors for every rung
cd "$work/ductParallel" || exit 1
run decomposePar decomposePar -latestTime \
    && run parallel mpirun -np 2 chargedFoamAdvisor -parallel -latestTime -rungs -sampleSize 2000 \
    || fail "advisorRungs.parallel (run failed)"
sameErrors()    # <serial rungs.dat> <parallel rungs.dat>: rms, p95 to 1e-6
{
    $PY - "$1" "$2" <<'PYEOF'
import sys
def rows(p):
    return {l.split()[0]: [float(v) for v in l.split()[1:3]]
            for l in open(p) if l.strip() and not l.startswith("#")}
a, b = rows(sys.argv[1]), rows(sys.argv[2])
bad = [k for k in a if k not in b or any(abs(x - y) > 1e-6*max(abs(x), 1e-12)
                                          for x, y in zip(a[k], b[k]))]
print("differ:", bad)
sys.exit(0 if a and set(a) == set(b) and not bad else 1)
PYEOF
}
check advisorRungs.parallel "(rms and p95 of every rung: 2 processors = serial to 1e-6)" \
    sameErrors "$work/duct/$dat" $dat

# electrostaticsModel auto from the charged state, then a restart
cd "$work/ductAuto" || exit 1
sed -i -E 's/^( *electrostaticsModel) meshPoisson;/\1 auto;/' constant/cloudProperties
sed -i -E 's/^startFrom .*/startFrom latestTime;/' system/controlDict
setEndTime 0.0004
run auto chargedDPMFoam || fail "advisorRungs.auto (solver failed)"
chosen=$(sed -nE 's/^Electrostatics auto: ([^ ]+) \(rms force error ([-0-9.e+]+) %.*/\1 \2/p' log.auto)
name=${chosen% *}; err=${chosen#* }
expect=$(rungValue "$work/duct/$dat" "$name" 2)
# (auto measures at the restart's first force evaluation, after the first
# sub-step's move: the same rung's error to a few per cent)
check advisorRungs.auto "(auto chose $name at $err %, the advisor measured ${expect:-nothing} for it; accuracy 5 %)" \
    $PY -c "import sys; e = float('$err')/100; sys.exit(0 if '$expect' and abs(e/float('$expect') - 1) < 0.05 and e <= 0.05 else 1)"
setEndTime 0.0006
run autoRestart chargedDPMFoam || fail "advisorRungs.autoRestart (solver failed)"
check advisorRungs.autoRestart "(the restart keeps $name without measuring)" \
    bash -c "grep -q '^Electrostatics auto: keeps $name' log.autoRestart && ! grep -q 'Electrostatics rungs measured' log.autoRestart"

# 2. The tri-periodic mono-charged cloud (2000 like charges): against Ewald
copyCase monoChargedCloud "$work/periodic"
cd "$work/periodic" || exit 1
$PY makeParcels.py 2000 > log.makeParcels || fail "advisorRungs.periodic (makeParcels failed)"
setEndTime 0.01
setWriteInterval 1
run blockMesh blockMesh && run solver chargedParticleFoam || fail "advisorRungs.periodic (solver failed)"
run advisor chargedFoamAdvisor -latestTime -rungs -sampleSize 2000 || fail "advisorRungs.periodic (advisor failed)"
dat=postProcessing/advisor/0.01/rungs.dat
check advisorRungs.periodicScene "(periodic, reference ewald)" grep -q "^# scene periodic" $dat
p3m=$(rungValue $dat "periodic(p3m,accuracy=1e-05)" 2)
check advisorRungs.periodicP3m "(P3M at accuracy 1e-5: rms $p3m < 1e-4 of Ewald)" \
    $PY -c "import sys; sys.exit(0 if $p3m < 1e-4 else 1)"
check advisorRungs.periodicRecommendation "(cheapest within 5 %)" recommendationRight $dat

# 3. An open box (the same cloud, boundaries of type patch): free space
copyCase monoChargedCloud "$work/open"
cd "$work/open" || exit 1
$PY makeParcels.py 1500 > log.makeParcels || fail "advisorRungs.open (makeParcels failed)"
sed -i -E 's/type cyclic; neighbourPatch [xyz][01];/type patch;/' system/blockMeshDict
sed -i -E 's/^( *electrostaticsModel) periodic;/\1 directCoulomb;/' constant/cloudProperties
setEndTime 0.01
setWriteInterval 1
run blockMesh blockMesh && run solver chargedParticleFoam || fail "advisorRungs.open (solver failed)"
run advisor chargedFoamAdvisor -latestTime -rungs -sampleSize 2000 || fail "advisorRungs.open (advisor failed)"
dat=postProcessing/advisor/0.01/rungs.dat
check advisorRungs.openScene "(open, free-space reference)" grep -q "^# reference freeSpaceSum" $dat
rc=$(awk '/^# spacing/ { print 2*$3 }' $dat)
got=$(rungValue $dat "cutoffCoulomb(rCut=2l)" 2)
expect=$(freeSpaceError 0.01 "$rc" none)
check advisorRungs.openCutoff "(cutoff 2 l: rms $got vs $expect from numpy)" rel "$got" "$expect" 1e-6
check advisorRungs.openRecommendation "(cheapest within 5 %)" recommendationRight $dat

# 4. Polarisable parcels (tutorial dielectricSpheres: radii 50 and 100 um,
#    epsilonR 10, 15 um apart): the near-field table. Point charges against
#    the exact two-sphere force (etc/python/twoDielectricSpheres.py): the
#    advisor's error of nearField none against BEM at 2400 patches must be
#    the exact one to 1 %
copyCase dielectricSpheres "$work/dielectric"
cd "$work/dielectric" || exit 1
setEndTime 1e-6
setWriteInterval 1
run blockMesh blockMesh && run solver chargedParticleFoam || fail "advisorRungs.dielectric (solver failed)"
run advisor chargedFoamAdvisor -latestTime -rungs || fail "advisorRungs.dielectric (advisor failed)"
dat=postProcessing/advisor/1e-06/rungs.dat
got=$(rungValue $dat nearField:none 2)
expect=$($PY - <<PYEOF
import sys; sys.path.insert(0, "$top/etc/python")
import numpy as np
from foamLagrangian import read_positions
from twoDielectricSpheres import force, eps0
x = read_positions("1e-06/lagrangian/cloud/positions")
d = np.linalg.norm(x[1] - x[0])
Q1, Q2 = 1e-14, 3e-13
exact = force(Q1, Q2, 50e-6, 100e-6, d, 10, 10)
point = Q1*Q2/(4*np.pi*eps0*d**2)
print(abs(point - exact)/abs(exact))
PYEOF
)
check advisorRungs.nearFieldPointCharges "(nearField none: rms $got vs exact two-sphere $expect)" rel "$got" "$expect" 0.01
bem=$(rungValue $dat nearField:bem 2)
dip=$(rungValue $dat nearField:inducedDipole 2)
check advisorRungs.nearFieldLadder "(bem $bem < 1 % < dipoles $dip < point charges $got)" \
    $PY -c "import sys; sys.exit(0 if $bem < 0.01 < $dip < $got else 1)"
check advisorRungs.nearFieldRecommendation "(nearField bem, the only one within 5 %)" \
    grep -q "^# nearFieldRecommended nearField:bem" $dat

# Bad options name the entry
cd "$work/open" || exit 1
run badAccuracy chargedFoamAdvisor -latestTime -rungs -accuracy 1.5
check advisorRungs.badAccuracy "(accuracy 1.5 refused, range named)" \
    grep -q "Entry accuracy = 1.5 .*out of range.*(0, 1)" log.badAccuracy
