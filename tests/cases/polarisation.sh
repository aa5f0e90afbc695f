# Dielectric parcels and the induced-dipole near field (Ruan 2022 Eqs.
# 45-50): static forces and torques of the cloud against the
# bemElectrostatics utility's inducedDipole model (two spheres, two prolates
# in three orientations), the libration of a dielectric prolate in a uniform
# field (period and energy), and two like-charged dielectric spheres that
# attract (trajectory against the integrated model force).
. "$(dirname "$0")/common.sh.inc"

for config in spheres prolateSide prolateTip prolateOblique
do
    copyCase twoChargedSpheres "$work/static-$config"
    (
        cd "$work/static-$config" || exit 1
        $PY "$tools/polarisationStatic.py" write . $config
        setEndTime 1e-6
        run blockMesh blockMesh
        run chargedParticleFoam chargedParticleFoam
        run bemElectrostatics bemElectrostatics
        $PY "$tools/polarisationStatic.py" compare . $config
    ) || fail "polarisation.static.$config (run failed, see $work/static-$config)"
done

copyCase dielectricLibration "$work/libration"
(
    cd "$work/libration" || exit 1
    ./Allrun > log.Allrun 2>&1
    result=$(tail -1 log.python3.check)
    case "$result" in
        PASS*) pass "polarisation.libration ${result#PASS: }" ;;
        *)     fail "polarisation.libration ${result}" ;;
    esac
    check polarisation.librationPlot "(libration.png written)" test -s libration.png
)

# Dipoles in parallel and on restart: eight charged dielectric prolates
# (several orientations and spins, epsilonR 3-12) drift together across
# the processor boundary (x = 0) in an applied field that turns them,
# with directCoulomb and the inducedDipole near field. Parallel = serial to 1e-10, a restart
# continues the run exactly (1e-12), the dipoles are written.
copyCase twoChargedSpheres "$work/serial"
cd "$work/serial" || exit 1
$PY - <<'PYEOF'
import re
path = "constant/cloudProperties"
s = open(path).read()
parcels = []
for i in range(8):
    x = -0.45e-3 + 0.9e-3*(i % 2)             # left/right of x = 0
    y = -0.6e-3 + 0.4e-3*(i//2)               # four lanes
    z = 0.1e-3*((i % 3) - 1)
    q = (1 if i % 3 else -1)*(0.5 + 0.1*i)*1e-13
    parcels.append(f"{{ position ({x:.6e} {y:.6e} {z:.6e}); U (0.2 0.01 0); "
                   f"semiAxes (1.5e-4 5e-5 5e-5); eulerAngles ({20*i} {35*i % 90} {10*i}); "
                   f"omega (0 0 {50*(i % 3)}); epsilonR {3 + 1.3*i}; rho 1000; q {q:.6e}; }}")
s = re.sub(r"parcels\s*\(.*?\n\s*\);", "parcels\n            (\n                "
           + "\n                ".join(parcels) + "\n            );", s, flags=re.S)
s = s.replace("electrostaticsModel directCoulomb;",
              "electrostaticsModel directCoulomb;\n    appliedField (0 1e5 2e4);")
s = s.replace("epsilonR    1;          // vacuum",
              "epsilonR    1;\n        nearField { type inducedDipole; rNear 1e-3; }")
open(path, "w").write(s)
PYEOF
setEndTime 4e-3
setWriteInterval 1000
cp -r "$work/serial" "$work/parallel"
cp -r "$work/serial" "$work/restarted"

run blockMesh blockMesh || fail "polarisation.serialRun (blockMesh)"
run solver chargedParticleFoam || fail "polarisation.serialRun (solver failed)"
check polarisation.dipolesWritten "(dipole, tE and epsilonR fields at 0.004)" \
    test -s 0.004/lagrangian/cloud/dipole -a -s 0.004/lagrangian/cloud/tE \
         -a -s 0.004/lagrangian/cloud/epsilonR
check polarisation.nearFieldLog "(the log reports the dipole solve)" \
    grep -q "Induced dipoles  *= 8 polarisable" log.solver

cd "$work/parallel" || exit 1
run blockMesh blockMesh
run decomposePar decomposePar || fail "polarisation.parallel (decomposePar)"
run solver mpirun -np 2 chargedParticleFoam -parallel \
    || fail "polarisation.parallel (mpirun failed)"
run reconstructPar reconstructPar -latestTime \
    || fail "polarisation.parallel (reconstructPar)"
crossed=$($PY -c "
import sys; sys.path.insert(0, '$top/etc/python')
from foamLagrangian import read_field
print(int((read_field('processor1/0.004/lagrangian/cloud/origProcId') == 0).sum()))")
check polarisation.transfer "($crossed parcels moved from processor0 to processor1)" \
    test "${crossed:-0}" -gt 0
$PY "$tools/compareClouds.py" "$work/serial/0.004" "$work/parallel/0.004" \
    --tol 1e-10 --rotation --name polarisation.parallel

cd "$work/restarted" || exit 1
setEndTime 2e-3
run blockMesh blockMesh && run solver1 chargedParticleFoam \
    || fail "polarisation.restart (first half failed)"
setEndTime 4e-3
run solver2 chargedParticleFoam || fail "polarisation.restart (second half failed)"
$PY "$tools/compareClouds.py" "$work/serial/0.004" "$work/restarted/0.004" \
    --tol 1e-12 --rotation --name polarisation.restart

# Like charges that attract: the tutorial's gap against the integrated
# monopole + induced-dipole force, and momentum conservation
copyCase dielectricSpheres "$work/attraction"
(
    cd "$work/attraction" || exit 1
    ./Allrun > log.Allrun 2>&1
    result=$(tail -1 log.python3.check)
    case "$result" in
        PASS*) pass "polarisation.attraction ${result#PASS: }" ;;
        *)     fail "polarisation.attraction ${result}" ;;
    esac
    check polarisation.attractionPlot "(attraction.png written)" test -s attraction.png
)
