# Where gravity is the carrier's only force (no dispersion, no coupling) the
# parcels kick without OpenFOAM's force list (EllipsoidParcel::calc). The
# ellipsoidPour tutorial (300 ellipsoids) in a water-like carrier (rho
# 1000 kg/m3, cellPoint interpolation: buoyancy 1 - rhoc/rho = 0.6) to
# 0.015 s (the first wall contacts from 0.008 s):
#  - the log names the short kick; with an extra force of zero (an
#    oscillatingFrame of amplitude 0) the force list is used instead, and
#    every parcel field written at 0.015 s is the same to the last bit;
#  - momentum: at 0.008 s, before any contact (the log's counts), the
#    parcels' mean velocity has changed by g (1 - rhoc/rho) t from the
#    velocities given in constant/parcels (an independent reference: the
#    kick's arithmetic is not in it).
. "$(dirname "$0")/common.sh.inc"

# prepare <case> <particleForces body>
prepare()
{
    copyCase ellipsoidPour "$1"
    cd "$1" || exit 1
    $PY makeParcels.py 300 > log.makeParcels 2>&1
    setEndTime 0.015
    setWriteInterval 10
    printf 'FoamFile { version 2.0; format ascii; class dictionary; object carrierProperties; }\nrho 1000;\n' \
        > constant/carrierProperties
    regexEdit constant/cloudProperties \
        "rho.carrier(\s+)cell;" "rho.carrier\g<1>cellPoint;" \
        "particleForces\s*\{\s*gravity;\s*\}" "particleForces\n    {\n$2\n    }"
    run blockMesh blockMesh
}

prepare "$work/kick" "        gravity;"
run solver chargedParticleFoam || fail "gravityKick.kickRun (solver failed)"

prepare "$work/forceList" "        gravity;
        oscillatingFrame { amplitude (0 0 0); frequency 1; }"
run solver chargedParticleFoam || fail "gravityKick.forceListRun (solver failed)"

cd "$work" || exit 1
line="Carrier forces: gravity alone"
check gravityKick.log "(kick: '$line' in the log; force list: not)" \
    eval "grep -q '$line' kick/log.solver && ! grep -q '$line' forceList/log.solver"

nf=0; nd=0
for f in kick/0.015/lagrangian/cloud/*
do
    nf=$((nf + 1))
    cmp -s "$f" "forceList/0.015/lagrangian/cloud/${f##*/}" || nd=$((nd + 1))
done
check gravityKick.identical "(t = 0.015 s: $nd of $nf parcel fields differ from the force list's)" \
    test "$nf" -gt 10 -a "$nd" = 0

$PY - "$work" "$top/etc/python" <<'PYEOF'
import re, sys
import numpy as np
work = sys.argv[1]
sys.path.insert(0, sys.argv[2])
from foamLagrangian import read_field
t = 0.008
d = f"{work}/kick/{t}/lagrangian/cloud"
ids = read_field(f"{d}/origId").astype(int)
U = read_field(f"{d}/U").reshape(-1, 3)
text = open(f"{work}/kick/constant/parcels").read()
U0 = np.array([[float(v) for v in m.split()]
               for m in re.findall(r"U \(([^()]*)\)", text)])[ids]
dU = (U - U0).mean(axis=0)
log = open(f"{work}/kick/log.solver").read()
steps = re.findall(r"^Time = (\S+)$(.*?)Contacts: particle-particle\s*=\s*(\d+), particle-wall = (\d+)",
                   log, re.M | re.S)
touched = sum(int(a) + int(b) for ts, _, a, b in steps if float(ts) <= t + 1e-12)
nSteps = sum(1 for ts, _, a, b in steps if float(ts) <= t + 1e-12)
expect = np.array([0, 0, -9.81*(1 - 1000/2500)*t])
err = np.abs(dU - expect).max()/abs(expect[2])
ok = len(ids) == 300 and err < 1e-9 and nSteps >= 80 and touched == 0
print(f"{'PASS' if ok else 'FAIL'}: gravityKick.momentum (t = {t} s, {len(ids)} parcels, {touched} contacts "
      f"in {nSteps} steps: mean velocity change {dU[2]:.12e} m/s vs g (1 - rhoc/rho) t = {expect[2]:.12e}; "
      f"x, y {dU[0]:.1e}, {dU[1]:.1e}: {err:.1e} of g t, tol 1e-9)")
PYEOF
