# Fifty ellipsoids (aspect ratio 2, random orientations) falling into a box
# with Hertz-Mindlin contacts: no particle lost, state finite; a restart
# (contact histories and the dissipated energy read back) continues the
# run exactly; a 2-processor
# run (contacts across the processor boundary through InteractionLists)
# reproduces the serial run to round-off growth: 1e-10 at 0.04 s. Contact
# dynamics is chaotic (round-off doubles every few collisions), so later
# the runs are compared statistically (count, mean bed height to 1e-6).
# The neighbour list's skin changes nothing (bit-identical to a list
# rebuilt every step); lazy tracking matches tracking every step to 1e-10
# at 0.02 s.
. "$(dirname "$0")/common.sh.inc"

copyCase ellipsoidPour "$work/serial"
cd "$work/serial" || exit 1
$PY makeParcels.py 50 > /dev/null
setEndTime 0.08
setWriteInterval 200
cp -r "$work/serial" "$work/restarted"
cp -r "$work/serial" "$work/parallel"
cp -r "$work/serial" "$work/eager"
cp -r "$work/serial" "$work/eagerList"

run blockMesh blockMesh && run solver chargedParticleFoam \
    || fail "ellipsoidPour.serialRun (solver failed)"
$PY packing.py . --expect 50 --state-only

cd "$work/restarted" || exit 1
setEndTime 0.04
run blockMesh blockMesh && run solver1 chargedParticleFoam \
    || fail "ellipsoidPour.firstHalf (solver failed)"
setEndTime 0.08
run solver2 chargedParticleFoam || fail "ellipsoidPour.secondHalf (solver failed)"
$PY "$tools/compareClouds.py" "$work/serial/0.08" "$work/restarted/0.08" \
    --tol 1e-12 --name ellipsoidPour.restart
# The dissipated energy in the log continues across the restart
lastDissipated() { grep "Contact dissipated energy" "$1" | tail -1 | awk '{print $NF}'; }
dS=$(lastDissipated "$work/serial/log.solver")
dR=$(lastDissipated "$work/restarted/log.solver2")
check ellipsoidPour.restartDissipatedEnergy "(at 0.08 s: $dS J in one run, $dR J restarted)" \
    $PY -c "import sys; a, b = float('$dS'), float('$dR'); sys.exit(0 if a > 0 and abs(a - b) <= 1e-10*a else 1)"

cd "$work/parallel" || exit 1
run blockMesh blockMesh
run decomposePar decomposePar || fail "ellipsoidPour.parallel (decomposePar)"
run solver mpirun -np 2 chargedParticleFoam -parallel \
    || fail "ellipsoidPour.parallel (mpirun failed)"
run reconstructPar reconstructPar || fail "ellipsoidPour.parallel (reconstructPar)"
$PY "$tools/compareClouds.py" "$work/serial/0.04" "$work/parallel/0.04" \
    --tol 1e-10 --name ellipsoidPour.parallel

# The neighbour list changes nothing, lazy tracking only round-off:
# - tracked every step (trackingTolerance 0), the run with the default
#   skin is identical to one whose list is rebuilt every step (skin 1 nm):
#   the pairs are evaluated in cloud order whenever the list was built;
# - the default run (lazy tracking) matches them to round-off growth at
#   0.02 s (its centres are summed in Cartesian space between trackings;
#   the difference grows chaotically, 1e-13 at 0.02 s, ~1e-9 at 0.04 s)
cd "$work/eagerList" || exit 1
sed -i 's/^\( *\)maxCo .*/&\n\1trackingTolerance 0;/' constant/cloudProperties
setEndTime 0.02
run blockMesh blockMesh && run solver chargedParticleFoam \
    || fail "ellipsoidPour.eagerList (solver failed)"
cd "$work/eager" || exit 1
sed -i 's/^\( *\)maxCo .*/&\n\1trackingTolerance 0;/; s/^\( *\)maxInteractionDistance .*/&\n\1neighbourSkin 1e-9;/' \
    constant/cloudProperties
setEndTime 0.02
run blockMesh blockMesh && run solver chargedParticleFoam \
    || fail "ellipsoidPour.eager (solver failed)"
check ellipsoidPour.eagerSettings "(the solver reads neighbourSkin 1e-9)" \
    grep -Eq "Neighbour list \(skin 1(\.0+1)?e-09 m\)" log.solver
$PY "$tools/compareClouds.py" "$work/eagerList/0.02" "$work/eager/0.02" \
    --tol 0 --name ellipsoidPour.neighbourList
$PY "$tools/compareClouds.py" "$work/serial/0.02" "$work/eager/0.02" \
    --tol 1e-10 --name ellipsoidPour.lazyTracking

# Late times: same count, same mean height
meanZ()
{
    $PY -c "
import sys; sys.path.insert(0, '$top/etc/python')
from foamLagrangian import read_positions
x = read_positions('$1/lagrangian/cloud/positions')
print(len(x), x[:, 2].mean())"
}
read -r nS zS < <(meanZ "$work/serial/0.08")
read -r nP zP < <(meanZ "$work/parallel/0.08")
check ellipsoidPour.parallelLate "(count $nS vs $nP, mean height $zS vs $zP m)" \
    $PY -c "import sys; sys.exit(0 if $nS == $nP and abs($zS - $zP) <= 1e-6*abs($zS) else 1)"

# A mixed cloud, every third parcel a sphere (radius 0.7 mm) among the
# ellipsoids: a pair of a sphere and an ellipsoid keeps no separation gap
# (ContactBodies sums the travel of the bodies with a shell only). The run
# completes with no particle lost and a finite state, and the neighbour
# list changes nothing: tracked every step, the default skin against a list
# rebuilt every step, bit-identical at 0.08 s
copyCase ellipsoidPour "$work/mixed"
cd "$work/mixed" || exit 1
regexEdit makeParcels.py 'semiAxes \(1e-3 5e-4 5e-4\)' \
    "semiAxes ({'7e-4 7e-4 7e-4' if i % 3 == 0 else '1e-3 5e-4 5e-4'})"
$PY makeParcels.py 50 > /dev/null
check ellipsoidPour.mixedParcels "(17 spheres among 50 parcels)" \
    test "$(grep -c 'semiAxes (7e-4 7e-4 7e-4)' constant/parcels)" -eq 17
setEndTime 0.08
setWriteInterval 200
sed -i 's/^\( *\)maxCo .*/&\n\1trackingTolerance 0;/' constant/cloudProperties
cp -r "$work/mixed" "$work/mixedList"
run blockMesh blockMesh && run solver chargedParticleFoam \
    || fail "ellipsoidPour.mixedRun (solver failed)"
$PY packing.py . --expect 50 --state-only \
  | sed 's/: ellipsoidPour\./: ellipsoidPour.mixed./'
cd "$work/mixedList" || exit 1
sed -i 's/^\( *\)maxInteractionDistance .*/&\n\1neighbourSkin 1e-9;/' \
    constant/cloudProperties
run blockMesh blockMesh && run solver chargedParticleFoam \
    || fail "ellipsoidPour.mixedList (solver failed)"
$PY "$tools/compareClouds.py" "$work/mixed/0.08" "$work/mixedList/0.08" \
    --tol 0 --name ellipsoidPour.mixedNeighbourList
