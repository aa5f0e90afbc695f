# Contact charging in a many-body scene: fifty charged ellipsoids (aspect
# ratio 2) fall into a box and charge each other and the walls (Rasera
# Eq. 16, directCoulomb fields). Particles + walls keep the initial charge
# to round-off at every step (serial and 2 processors, where contacts across
# the processor boundary are charged on both sides); contacts did charge;
# a restart (charges, contact areas and fields read back) continues the run
# exactly; the 2-, 4- and 8-processor runs reproduce the serial one.
. "$(dirname "$0")/common.sh.inc"

copyCase ellipsoidPour "$work/serial"
cd "$work/serial" || exit 1
$PY makeParcels.py 50 > /dev/null
$PY - <<'PYEOF'
import re
import numpy as np
rng = np.random.default_rng(7)
s = open("constant/parcels").read()
s = re.sub(r"q 0;", lambda m: "q %.6e;" % (2e-12*(2*rng.random() - 1)), s)
open("constant/parcels", "w").write(s)
p = "constant/cloudProperties"
s = open(p).read()
s = s.replace("electrostaticsModel none;", """electrostaticsModel directCoulomb;

    triboChargingModel  GammaKappa;
    GammaKappaCoeffs
    {
        particles { kappaC 20; }
        walls { ".*" { kappaC 10; Gamma -1e6; } }
    }""")
open(p, "w").write(s)
PYEOF
setEndTime 0.08
setWriteInterval 200
cp -r "$work/serial" "$work/restarted"
cp -r "$work/serial" "$work/parallel"
cp -r "$work/serial" "$work/parallel4"
cp -r "$work/serial" "$work/parallel8"

run blockMesh blockMesh && run solver chargedParticleFoam \
    || fail "triboCharging.serialRun (solver failed)"

# balance <case> <name>: particles + walls constant, charging happened
balance()
{
    $PY - "$1" "$2" <<'PYEOF'
import sys
import numpy as np
case, name = sys.argv[1:3]
d = np.loadtxt(case + "/postProcessing/lagrangian/cloud/triboCharging/0/chargeBalance.dat")
q, wall, bal, npair, nwall = d[:, 1], d[:, 2], d[:, 3], d[:, 4], d[:, 5]
scale = np.abs(q).max() + np.abs(wall).max()
drift = np.abs(bal - bal[0]).max()/scale
ok = drift < 1e-12
print(f"{'PASS' if ok else 'FAIL'}: triboCharging.{name}.balance (particles + walls "
      f"drift {drift:.1e} of the charges over {len(d)} steps, tol 1e-12)")
ok = npair.sum() > 0 and nwall.sum() > 0 and abs(wall[-1]) > 0
print(f"{'PASS' if ok else 'FAIL'}: triboCharging.{name}.charged ({int(npair.sum())} "
      f"particle-particle and {int(nwall.sum())} wall contact steps charged; "
      f"walls received {wall[-1]:.3e} C)")
PYEOF
}
balance "$work/serial" serial

cd "$work/restarted" || exit 1
setEndTime 0.04
run blockMesh blockMesh && run solver1 chargedParticleFoam \
    || fail "triboCharging.firstHalf (solver failed)"
setEndTime 0.08
run solver2 chargedParticleFoam || fail "triboCharging.secondHalf (solver failed)"
$PY "$tools/compareClouds.py" "$work/serial/0.08" "$work/restarted/0.08" \
    --tol 1e-12 --name triboCharging.restart
wS=$(tail -1 "$work/serial/postProcessing/lagrangian/cloud/triboCharging/0/chargeBalance.dat" | awk '{print $3}')
wR=$(tail -1 "$work/restarted/postProcessing/lagrangian/cloud/triboCharging/0.04/chargeBalance.dat" | awk '{print $3}')
check triboCharging.restartWalls "(wall charge kept over the restart: $wS vs $wR C)" \
    $PY -c "import sys; sys.exit(0 if abs($wS - $wR) <= 1e-12*abs($wS) else 1)"

cd "$work/parallel" || exit 1
run blockMesh blockMesh
run decomposePar decomposePar || fail "triboCharging.parallel (decomposePar)"
setEndTime 0.04
run solver mpirun -np 2 chargedParticleFoam -parallel \
    || fail "triboCharging.parallel (mpirun failed)"
run reconstructPar reconstructPar || fail "triboCharging.parallel (reconstructPar)"
$PY "$tools/compareClouds.py" "$work/serial/0.04" "$work/parallel/0.04" \
    --tol 1e-10 --qtol 1e-10 --name triboCharging.parallel
balance "$work/parallel" parallel

# 4 and 8 processors (2 x 2 across the box, 2 x 2 x 2): contacts across
# each processor boundary charge the partner through its processor only
for split in "4:2 2 1" "8:2 2 2"
do
    np=${split%%:*}
    cd "$work/parallel$np" || exit 1
    setDecomposition "$np" "${split#*:}"
    run blockMesh blockMesh
    run decomposePar decomposePar || fail "triboCharging.parallel$np (decomposePar)"
    setEndTime 0.04
    run solver mpirun -np "$np" chargedParticleFoam -parallel \
        || fail "triboCharging.parallel$np (mpirun failed)"
    run reconstructPar reconstructPar || fail "triboCharging.parallel$np (reconstructPar)"
    $PY "$tools/compareClouds.py" "$work/serial/0.04" "$work/parallel$np/0.04" \
        --tol 1e-10 --qtol 1e-10 --name "triboCharging.parallel$np"
    balance "$work/parallel$np" "parallel$np"
done
