# electrostaticsModel cutoffCoulomb (direct truncation, cell list) in the
# cloud: 60 charges of both signs in a 1 m box. The written forces fE equal
# an independent brute-force truncated sum (numpy) for rCut = 0.3 m, in
# serial and on 2 and 4 processors (each receives only its neighbours'
# parcels within rCut: a halo; 4 in a row, so the processors have different
# numbers of processor patches), and directCoulomb's for a cutoff beyond the
# box. In the box made a duct cyclic in x: the sum with the pairs through
# the cyclic patch (copies at x -+ 1 m), serially and on rings of 2 and 4
# processors. The reduced-stiffness head-on collision (Ruan Table 1, chi 0.176)
# with the pair split between 2 processors: the same trajectory as serial
# (the halo reaches the contact partner).
. "$(dirname "$0")/common.sh.inc"

copyCase twoChargedSpheres "$work/cut"
cd "$work/cut" || exit 1
$PY "$tools/unitBoxMesh.py" wall
$PY - <<'PYEOF'
import re
import numpy as np
rng = np.random.default_rng(5)
x = 0.05 + 0.9*rng.random((60, 3))
q = 1e-9*(2*rng.random(60) - 1)
np.savetxt("charges.txt", np.column_stack([x, q]))
p = "constant/cloudProperties"
s = open(p).read()
parcels = "\n".join("                { position (%.12g %.12g %.12g); d 1e-3; rho 1000; q %.12g; }" % (r[0], r[1], r[2], c) for r, c in zip(x, q))
s = re.sub(r"parcels\s*\(.*?\n\s*\);", "parcels\n            (\n" + parcels + "\n            );", s, flags=re.S)
s = re.sub(r"electrostaticsModel\s+\w+;", "electrostaticsModel cutoffCoulomb;\n    cutoffCoulombCoeffs { rCut 0.3; }", s)
open(p, "w").write(s)
p = "system/controlDict"
s = open(p).read()
s = re.sub(r"^endTime .*?;", "endTime 1e-6;", s, flags=re.M)
s = re.sub(r"^deltaT .*?;", "deltaT 1e-6;", s, flags=re.M)
s = re.sub(r"^writeInterval .*?;", "writeInterval 1;", s, flags=re.M)
open(p, "w").write(s)
PYEOF
cp -r "$work/cut" "$work/parallel"
cp -r "$work/cut" "$work/parallel4"
cp -r "$work/cut" "$work/far"
cp -r "$work/cut" "$work/direct"
for c in cyclic cyclicRing2 cyclicRing4
do
    cp -r "$work/cut" "$work/$c"
    $PY "$tools/unitBoxMesh.py" xCyclic "$work/$c"
done
sed -i 's/rCut 0.3;/rCut 2;/' "$work/far/constant/cloudProperties"
sed -i 's/electrostaticsModel cutoffCoulomb;/electrostaticsModel directCoulomb;/' "$work/direct/constant/cloudProperties"
for c in cut far direct
do
    cd "$work/$c" || exit 1
    run blockMesh blockMesh && run solver chargedParticleFoam \
        || fail "cutoffCloud.$c (solver failed, see $work/$c/log.solver)"
done
cd "$work/parallel" || exit 1
run blockMesh blockMesh && run decomposePar decomposePar \
 && run solver mpirun -np 2 chargedParticleFoam -parallel \
 && run reconstructPar reconstructPar -latestTime \
    || fail "cutoffCloud.parallel (run failed, see $work/parallel)"
cd "$work/parallel4" || exit 1
setDecomposition 4 "4 1 1"
run blockMesh blockMesh && run decomposePar decomposePar \
 && run solver mpirun -np 4 chargedParticleFoam -parallel \
 && run reconstructPar reconstructPar -latestTime \
    || fail "cutoffCloud.parallel4 (run failed, see $work/parallel4)"
# The duct cyclic in x: pairs through the cyclic patch (copies of the
# parcels within rCut of it), serially and on rings of 2 and 4 processors
# (each with two neighbours, one through the cyclic patch)
cd "$work/cyclic" || exit 1
run blockMesh blockMesh && run solver chargedParticleFoam \
    || fail "cutoffCloud.cyclic (solver failed, see $work/cyclic/log.solver)"
for np in 2 4
do
    cd "$work/cyclicRing$np" || exit 1
    setDecomposition $np "$np 1 1"
    run blockMesh blockMesh && run decomposePar decomposePar \
     && run solver mpirun -np $np chargedParticleFoam -parallel \
     && run reconstructPar reconstructPar -latestTime \
        || fail "cutoffCloud.cyclicRing$np (run failed, see $work/cyclicRing$np)"
done

$PY - "$work" "$top/etc/python" <<'PYEOF'
import os, sys
import numpy as np
work = sys.argv[1]
sys.path.insert(0, sys.argv[2])
from foamLagrangian import read_field, read_positions
k = 8.9875517923e9
d = np.loadtxt(work + "/cut/charges.txt")
x0, q0 = d[:, :3], d[:, 3]

def truncated(rc, periodX=False):
    # Every source within rc, with its copies shifted by -1 and +1 m in x
    # for the duct cyclic in x
    F = np.zeros_like(x0)
    for i in range(len(x0)):
        for sx in ((-1.0, 0.0, 1.0) if periodX else (0.0,)):
            r = x0[i] - (x0 + [sx, 0, 0])
            rr = np.linalg.norm(r, axis=1)
            m = (rr > 0) & (rr < rc)
            F[i] += k*q0[i]*np.sum((q0[m]/rr[m]**3)[:, None]*r[m], axis=0)
    return F

def load(case):
    t = max((e for e in os.listdir(case) if e.replace(".", "").replace("e-", "").isdigit() and e != "0"), key=float)
    p = f"{case}/{t}/lagrangian/cloud"
    x = read_positions(p + "/positions")
    f = read_field(p + "/fE").reshape(-1, 3)
    idx = [np.argmin(np.linalg.norm(x0 - xi, axis=1)) for xi in x]
    return idx, f

ref = {"cut": truncated(0.3), "parallel": truncated(0.3),
       "parallel4": truncated(0.3), "far": None,
       "cyclic": truncated(0.3, True), "cyclicRing2": truncated(0.3, True),
       "cyclicRing4": truncated(0.3, True)}
idxD, fD = load(work + "/direct")
direct = np.zeros_like(x0); direct[idxD] = fD
for name in ("cut", "parallel", "parallel4", "far", "cyclic", "cyclicRing2", "cyclicRing4"):
    idx, f = load(f"{work}/{name}")
    R = ref[name][idx] if ref[name] is not None else direct[idx]
    err = np.abs(f - R).max()/np.abs(R).max()
    tol = 1e-9 if ref[name] is not None else 1e-12
    what = "a numpy truncated sum (rCut 0.3 m)" if ref[name] is not None else "directCoulomb (rCut 2 m > box)"
    if name.startswith("cyclic"):
        # how much the pairs through the cyclic patch weigh: the same sum
        # without them differs by
        d = np.abs(truncated(0.3)[idx] - R).max()/np.abs(R).max()
        what = f"a numpy truncated sum with the copies at x -+ 1 m (rCut 0.3 m; without them {d:.2f})"
    ok = len(set(idx)) == len(x0) and err < tol
    print(f"{'PASS' if ok else 'FAIL'}: cutoffCloud.{name} (fE vs {what}: max rel. difference {err:.1e}, tol {tol:g})")
PYEOF

# A cutoff beyond the cyclic period: a clear error naming rCut and the range
rm -rf "$work/cyclicLongCut"
cp -r "$work/cyclic" "$work/cyclicLongCut"
rm -rf "$work/cyclicLongCut"/[1-9]* "$work/cyclicLongCut"/0.*
sed -i 's/rCut 0.3;/rCut 1.5;/' "$work/cyclicLongCut/constant/cloudProperties"
(cd "$work/cyclicLongCut" && chargedParticleFoam > log.solver 2>&1)
rc=$?
msg=$(grep -m1 "Entry rCut" "$work/cyclicLongCut/log.solver")
[ $rc -ne 0 ] && echo "$msg" | grep -q "exceeds the cyclic period 1 of the mesh: it must be in (0, 1\]" \
    && pass "cutoffCloud.cyclicLongCut (exit $rc: ${msg## })" \
    || fail "cutoffCloud.cyclicLongCut (exit $rc, message: $msg)"

# The reduced-stiffness collision (chi 0.176, deltaT 2e-7 s, to 1.1 ms)
# with cutoffCoulomb rCut 300 um: the two spheres (centres 0 and 250 um)
# on different processors; the contact correction needs the partner from
# the halo. Serial and 2 processors: the same velocities
copyCase reducedStiffness "$work/chi"
cd "$work/chi" || exit 1
sed -i -E "s/^( +stiffnessRatio +)[0-9.e-]+;/\10.176;/" constant/cloudProperties
sed -i -E "s/^( *electrostaticsModel) directCoulomb;/\1 cutoffCoulomb;\n    cutoffCoulombCoeffs { rCut 3e-4; }/" constant/cloudProperties
sed -i -E "s/^deltaT .*/deltaT          2e-7;/; s/^endTime .*/endTime         1.1e-3;/; s/^writeInterval .*/writeInterval   5500;/" system/controlDict
cp -r "$work/chi" "$work/chiParallel"
run blockMesh blockMesh && run solver chargedParticleFoam || fail "cutoffCloud.chi (solver failed)"
cd "$work/chiParallel" || exit 1
run blockMesh blockMesh && run decomposePar decomposePar \
 && run solver mpirun -np 2 chargedParticleFoam -parallel \
 && run reconstructPar reconstructPar -latestTime \
    || fail "cutoffCloud.chiParallel (run failed)"
$PY - "$work" "$top/etc/python" <<'PYEOF'
import sys
import numpy as np
sys.path.insert(0, sys.argv[2])
from foamLagrangian import read_field, read_positions
w = sys.argv[1]
def state(case):
    p = f"{case}/0.0011/lagrangian/cloud/"
    x, U = read_positions(p + "positions"), read_field(p + "U").reshape(-1, 3)
    o = np.argsort(x[:, 0])
    return x[o], U[o]
xs, Us = state(w + "/chi")
xp, Up = state(w + "/chiParallel")
err = np.abs(Up - Us).max()/np.abs(Us).max()
moved = abs(xs[1, 0] - xs[0, 0] - 250e-6) > 1e-6
print(f"{'PASS' if err < 1e-9 and moved else 'FAIL'}: cutoffCloud.haloContact "
      f"(chi 0.176 pair split over 2 processors: velocities vs serial max rel. difference {err:.1e}, tol 1e-9; gap changed: {moved})")
PYEOF
