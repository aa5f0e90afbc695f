# Contact across a cyclic boundary (InteractionLists refer the partner
# through the cyclic patch): two spheres approach each other through the
# periodic x boundary and bounce with the restitution e = 0.7 (1 %),
# total momentum conserved; serial and on 2 processors; contact charging
# through the cyclic patch keeps the total charge. (Start gap not a
# multiple of the step: an onset at round-off distance can be seen by one
# side of a duplicated real-referred pair only; the dashpot then acts once.)
. "$(dirname "$0")/common.sh.inc"

copyCase headOnCollision "$work/serial"
cd "$work/serial" || exit 1
$PY - <<'PYEOF'
import re
p = "system/blockMeshDict"
s = open(p).read()
s = re.sub(r"boundary\s*\(.*\);", """boundary
(
    left
    {
        type cyclic;
        neighbourPatch right;
        faces ((0 4 7 3));
    }
    right
    {
        type cyclic;
        neighbourPatch left;
        faces ((1 2 6 5));
    }
    walls
    {
        type wall;
        faces ((0 1 5 4) (3 7 6 2) (0 3 2 1) (4 5 6 7));
    }
);""", s, flags=re.S)
open(p, "w").write(s)
p = "constant/cloudProperties"
s = open(p).read()
s = re.sub(r"parcels\s*\(.*?\n\s*\);", """parcels
            (
                { position ( 1.44993e-3 0 0); U ( 0.5 0 0); d 1e-3; q 0; }
                { position (-1.44993e-3 0 0); U (-0.5 0 0); d 1e-3; q 0; }
            );""", s, flags=re.S)
s = re.sub(r"(\n\s+e\s+)[0-9.]+;", r"\g<1>0.7;", s, count=1)
open(p, "w").write(s)
PYEOF
setWriteInterval 2000
cp -r "$work/serial" "$work/parallel"
cp -r "$work/serial" "$work/charging"

restitution()
{
    $PY -c "
import sys; sys.path.insert(0, '$top/etc/python')
from foamLagrangian import read_field
import numpy as np
U = read_field('$1/0.0002/lagrangian/cloud/U').reshape(-1, 3)
print(abs(U[0, 0] - U[1, 0])/1.0, U[:, 0].sum())"
}

run blockMesh blockMesh && run solver chargedParticleFoam \
    || fail "cyclicContact.serialRun (solver failed)"
read -r e mom < <(restitution "$work/serial")
check cyclicContact.serial "(restitution through the cyclic patch $e, input 0.7; momentum $mom)" \
    $PY -c "import sys; sys.exit(0 if abs($e/0.7 - 1) < 0.01 and abs($mom) < 1e-12 else 1)"

cd "$work/parallel" || exit 1
run blockMesh blockMesh
run decomposePar decomposePar
run solver mpirun -np 2 chargedParticleFoam -parallel \
    || fail "cyclicContact.parallelRun (mpirun failed)"
run reconstructPar reconstructPar -latestTime
read -r e mom < <(restitution "$work/parallel")
check cyclicContact.parallel "(restitution through cyclic and processor patches $e; momentum $mom)" \
    $PY -c "import sys; sys.exit(0 if abs($e/0.7 - 1) < 0.01 and abs($mom) < 1e-12 else 1)"

# Contact charging through the cyclic patch (serial: the partner is a
# referred copy on the same processor and gets its share there): charged
# spheres (directCoulomb fields) exchange charge, the total is kept
cd "$work/charging" || exit 1
$PY - <<'PYEOF'
import re
p = "constant/cloudProperties"
s = open(p).read()
s = s.replace("d 1e-3; q 0; }", "d 1e-3; q 1e-12; }", 1).replace("d 1e-3; q 0; }", "d 1e-3; q -3e-12; }", 1)
s = s.replace("electrostaticsModel none;", """electrostaticsModel directCoulomb;
    triboChargingModel  GammaKappa;
    GammaKappaCoeffs { particles { kappaC 1e3; } walls { ".*" { kappaC 10; Gamma 0; } } }""")
open(p, "w").write(s)
PYEOF
run blockMesh blockMesh && run solver chargedParticleFoam \
    || fail "cyclicContact.chargingRun (solver failed)"
read -r q1 q2 < <($PY -c "
import sys; sys.path.insert(0, '$top/etc/python')
from foamLagrangian import read_field
q = read_field('$work/charging/0.0002/lagrangian/cloud/q')
print(*q)")
check cyclicContact.charging "(charges after a charging contact through the cyclic patch: $q1 and $q2 C from 1e-12 and -3e-12; total kept to 1e-12 relative)" \
    $PY -c "import sys; sys.exit(0 if abs($q1 + $q2 + 2e-12) < 1e-12*2e-12 and abs($q1 - 1e-12) > 1e-16 else 1)"
