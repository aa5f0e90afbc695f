# OpenFOAM's pairCollision inside the chargedFoam cloud reads the tracked
# (barycentric) positions, so lazy tracking must be off with it: two
# touching spheres pushed apart from rest (displacements far below the
# tracking tolerance at first) give exactly the run with
# trackingTolerance 0, and the log says lazy tracking is off. The spheres
# start 0.4 % of the radius deep (solution/maxInjectionOverlap allows it).
. "$(dirname "$0")/common.sh.inc"

copyCase twoChargedSpheres "$work/default"
cd "$work/default" || exit 1
$PY - <<'PYEOF'
import re
p = "constant/cloudProperties"
s = open(p).read()
# Two neutral spheres (d = 100 um) overlapping by 0.2 um, at rest
s = re.sub(r"position \(-0.5e-3 0 0\); U \(0 0 0\); d 1e-4; rho 1000; q  1e-12;",
           "position (-0.0499e-3 0 0); U (0 0 0); d 1e-4; rho 1000; q 0;", s)
s = re.sub(r"position \( 0.5e-3 0 0\); U \(0 0 0\); d 1e-4; rho 1000; q -1e-12;",
           "position ( 0.0499e-3 0 0); U (0 0 0); d 1e-4; rho 1000; q 0;", s)
s = re.sub(r"rho0 +1000; +// \[kg/m3\]",
           "rho0 1000; youngsModulus 1e8; poissonsRatio 0.3;", s)
s = re.sub(r"electrostaticsModel directCoulomb;", "electrostaticsModel none;", s)
s = re.sub(r"collisionModel +none;.*", """collisionModel pairCollision;
    pairCollisionCoeffs
    {
        maxInteractionDistance 1.1e-4;
        writeReferredParticleCloud no;
        U U.carrier;
        pairModel pairSpringSliderDashpot;
        pairSpringSliderDashpotCoeffs
        {
            useEquivalentSize no; alpha 0.5; b 1.5; mu 0.3;
            cohesionEnergyDensity 0; collisionResolutionSteps 12;
        }
        wallModel wallSpringSliderDashpot;
        wallSpringSliderDashpotCoeffs
        {
            useEquivalentSize no; collisionResolutionSteps 12;
            youngsModulus 1e8; poissonsRatio 0.3; alpha 0.5; b 1.5; mu 0.3;
            cohesionEnergyDensity 0;
        }
    }""", s)
open(p, "w").write(s)
for k in ("q 0;", "collisionModel pairCollision;", "youngsModulus 1e8;"):
    assert k in s, k
PYEOF
[ $? -eq 0 ] || fail "pairCollisionCloud.setup (case edit failed)"
sed -i -E "s/^endTime .*/endTime         2e-5;/; s/^writeInterval .*/writeInterval   20;/" \
    system/controlDict
# The overlap at injection is deliberate: allowed up to 1 % of the radius
sed -i 's/^\( *\)maxCo .*/&\n\1maxInjectionOverlap 0.01;/' constant/cloudProperties
cp -r "$work/default" "$work/eager"
sed -i 's/^\( *\)maxCo .*/&\n\1trackingTolerance 0;/' "$work/eager/constant/cloudProperties"

for c in default eager
do
    cd "$work/$c" || exit 1
    run blockMesh blockMesh && run solver chargedParticleFoam \
        || fail "pairCollisionCloud.$c (solver failed, see $work/$c)"
done

cd "$work/default" || exit 1
check pairCollisionCloud.lazyOff "(the log says lazy tracking is off)" \
    grep -q "Lazy tracking off: collision model pairCollision" log.solver
check pairCollisionCloud.separating "(the spheres move apart)" \
    $PY -c "
import sys; sys.path.insert(0, '$top/etc/python')
from foamLagrangian import read_positions
x = read_positions('2e-05/lagrangian/cloud/positions')
sys.exit(0 if abs(x[1, 0] - x[0, 0]) > 1.0e-4 else 1)"
$PY "$tools/compareClouds.py" "$work/eager/2e-05" "$work/default/2e-05" \
    --tol 0 --name pairCollisionCloud.sameAsTracked
