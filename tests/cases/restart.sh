# Restart continues the same run: stop the tutorial half-way, restart from
# the written state (positions, velocities, charges, stored forces) and
# compare with the uninterrupted run at the end (1e-12 relative).
. "$(dirname "$0")/common.sh.inc"

copyCase twoChargedSpheres "$work/full"
cd "$work/full" || exit 1
run blockMesh blockMesh && run solver chargedParticleFoam \
    || fail "restart.fullRun (solver failed)"

copyCase twoChargedSpheres "$work/restarted"
cd "$work/restarted" || exit 1
setEndTime 2.95e-3
run blockMesh blockMesh && run solver1 chargedParticleFoam \
    || fail "restart.firstHalf (solver failed)"
setEndTime 5.9e-3
run solver2 chargedParticleFoam || fail "restart.secondHalf (solver failed)"
check restart.resumed "(second run started from t = 0.00295)" \
    grep -q "Time = 0.002951" log.solver2

$PY "$tools/compareClouds.py" "$work/full/0.0059" "$work/restarted/0.0059" \
    --tol 1e-12 --name restart
