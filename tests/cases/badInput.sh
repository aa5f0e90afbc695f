# Bad input stops with an OpenFOAM FatalIOError naming the entry:
# missing or out-of-range charge, diameter, density, rho0, epsilonR;
# contact charging: negative kappaC, a wall patch without parameters, a
# missing Gamma, a non-positive cutoff distance, charging without
# ellipsoidCollision; lazy-tracking tolerance, log interval and neighbour
# skin out of range; particle permittivity, the applied field's type and
# the near field's entries.
. "$(dirname "$0")/common.sh.inc"

copyCase twoChargedSpheres "$work/base"
cd "$work/base" || exit 1
run blockMesh blockMesh || fail "badInput.mesh (blockMesh failed)"
copyCase triboSingleContact "$work/tribo"
cd "$work/tribo" || exit 1
run blockMesh blockMesh || fail "badInput.mesh (blockMesh failed)"
base=base

# badCase <name> <python re.sub pattern> <replacement> <expected message regex>
#     [<pattern> <replacement> ...]
# (a copy of $work/$base with one change, or several)
badCase()
{
    local name="$1" pattern="$2" repl="$3" expect="$4" dir="$work/$1"
    shift 4
    rm -rf "$dir"
    cp -r "$work/$base" "$dir"
    (
        cd "$dir" || exit 1
        $PY - "$pattern" "$repl" "$@" <<'PYEOF' || exit 1
import re, sys
p = "constant/cloudProperties"
s = open(p).read()
for pattern, repl in zip(sys.argv[1::2], sys.argv[2::2]):
    s, n = re.subn(pattern, repl, s, count=1)
    if n != 1:
        sys.exit("pattern not found: " + pattern)
open(p, "w").write(s)
PYEOF
        chargedParticleFoam > log.solver 2>&1
        rc=$?
        if [ "$rc" -ne 0 ] && grep -q "FOAM FATAL IO ERROR" log.solver \
            && grep -Eq "$expect" log.solver
        then
            pass "badInput.$name (exit $rc: $(grep -Eo "$expect" log.solver | head -1))"
        else
            fail "badInput.$name (exit $rc; expected a FatalIOError matching '$expect', see $dir/log.solver)"
        fi
    )
}

badCase missingCharge   'rho 1000; q  1e-12; '  'rho 1000; ' \
    'Entry q of parcel 0 .* is missing'
badCase missingDiameter 'd 1e-4; rho 1000; q  1e-12' 'rho 1000; q  1e-12' \
    'Entry d of parcel 0 .* is missing'
badCase zeroDiameter    'd 1e-4; rho 1000; q -1e-12' 'd 0; rho 1000; q -1e-12' \
    'Entry d of parcel 1 .* out of range \(0\).*> 0'
badCase negativeDiameter 'd 1e-4; rho 1000; q  1e-12' 'd -1e-4; rho 1000; q  1e-12' \
    'Entry d of parcel 0 .* out of range \(-0.0001\).*> 0'
badCase zeroDensity     'rho 1000; q  1e-12' 'rho 0; q  1e-12' \
    'Entry rho of parcel 0 .* out of range \(0\).*> 0'
badCase negativeDensity 'rho 1000; q -1e-12' 'rho -5; q -1e-12' \
    'Entry rho of parcel 1 .* out of range \(-5\).*> 0'
badCase missingRho0     'rho0 +1000;' '' \
    "Entry 'rho0' not found|Entry rho0 .* is missing"
badCase zeroRho0        'rho0 +1000;' 'rho0 0;' \
    'Entry rho0 .* is out of range'
badCase zeroPermittivity 'epsilonR +1;' 'epsilonR 0;' \
    'Entry epsilonR .* = 0 is out of range'
badCase unknownModel    'electrostaticsModel directCoulomb;' 'electrostaticsModel coulombic;' \
    'Unknown electrostaticsModel type coulombic'

badCase chargingWithoutEllipsoidCollision 'electrostaticsModel directCoulomb;' \
    'electrostaticsModel directCoulomb; triboChargingModel GammaKappa; GammaKappaCoeffs { particles { kappaC 1; } walls { ".*" { kappaC 1; Gamma 0; } } }' \
    'Entry triboChargingModel GammaKappa needs collisionModel ellipsoidCollision'
badCase missingCutoff 'electrostaticsModel directCoulomb;' 'electrostaticsModel cutoffCoulomb;' \
    'Entry rCut .* is missing: it must be given, finite and > 0'

# Dielectric parcels, applied field and near field
badCase zeroParticleEpsilonR 'rho0 +1000;' 'rho0 1000; epsilonR 0;' \
    'Entry epsilonR \(relative permittivity of the particles\) = 0 .* out of range: it must be finite and > 0'
badCase negativeParcelEpsilonR 'rho 1000; q  1e-12; ' 'rho 1000; q  1e-12; epsilonR -2; ' \
    'Entry epsilonR of parcel 0 .* out of range \(-2\).*> 0'
badCase scalarAppliedField 'electrostaticsModel directCoulomb;' \
    'electrostaticsModel directCoulomb; appliedField 1e5;' \
    'Entry appliedField in .* must be a vector \[V/m\]'
badCase misplacedNearField 'electrostaticsModel directCoulomb;' \
    'electrostaticsModel directCoulomb; nearField { type inducedDipole; }' \
    'Entry nearField in .* is misplaced: the near field is selected in the far field.s coefficients, directCoulombCoeffs'
badCase nearFieldNotDictionary 'epsilonR +1;' 'epsilonR 1; nearField inducedDipole;' \
    'Entry nearField in .* must be a dictionary'
badCase unknownNearField 'epsilonR +1;' 'epsilonR 1; nearField { type multipole; }' \
    'Unknown type type multipole'
badCase negativeRNear 'epsilonR +1;' 'epsilonR 1; nearField { type inducedDipole; rNear -1; }' \
    'Entry rNear = -1 in .* is out of range: it must be finite and > 0'
badCase negativeClusterGap 'epsilonR +1;' 'epsilonR 1; nearField { type bem; clusterGap -0.5; }' \
    'Entry clusterGap = -0.5 in .* is out of range: finite and >= 0'
badCase fewPatches 'epsilonR +1;' 'epsilonR 1; nearField { type bem; nPatches 4; }' \
    'Entry nPatches = 4 in .* is out of range: >= 8'
badCase zeroSolveInterval 'epsilonR +1;' 'epsilonR 1; nearField { type bem; solveInterval 0; }' \
    'Entry solveInterval = 0 in .* is out of range: >= 1'
badCase unknownIsolated 'epsilonR +1;' 'epsilonR 1; nearField { type bem; isolated multipole; }' \
    'Entry isolated multipole in .* is not one of: inducedDipole none'
badCase unknownNeighbours 'epsilonR +1;' 'epsilonR 1; nearField { type bem; neighbours dipoles; }' \
    'Entry neighbours dipoles in .* is not one of: multipoles pointCharges'
badCase zeroMeshCache 'epsilonR +1;' 'epsilonR 1; nearField { type bem; meshCache 0; }' \
    'Entry meshCache = 0 in .* is out of range: > 0'

base=tribo
badCase negativeKappaC 'plate +\{ kappaC 9.64;' 'plate { kappaC -9.64;' \
    'Entry kappaC = -9.64[0-9]* in .* is out of range: it must be finite and >= 0'
badCase missingWallPatch 'box +\{ kappaC 0; +Gamma 0; \}' '' \
    'Wall patch box has no entry'
badCase missingGamma 'kappaC 9.64; Gamma -2.34e6;' 'kappaC 9.64;' \
    'Entry Gamma is missing'
badCase missingParticles 'particles \{ kappaC 0; \}' '' \
    'Entry particles .* is missing'
badCase zeroCutoffDistance 'triboChargingModel +GammaKappa;\s*GammaKappaCoeffs' \
    'triboChargingModel workFunction; workFunctionCoeffs' \
    'Entry cutoffDistance is missing'
badCase negativeTrackingTolerance 'maxCo +0.3;' 'maxCo 0.3; trackingTolerance -1e-3;' \
    'Entry trackingTolerance = -0.001 is out of range \[0, 0.5\]'
badCase zeroLogInterval 'maxCo +0.3;' 'maxCo 0.3; logInterval 0;' \
    'Entry logInterval = 0 is out of range: >= 1'
badCase unknownMomentumCoupling 'maxCo +0.3;' 'maxCo 0.3; momentumCoupling implicit;' \
    'Entry momentumCoupling = implicit is not one of: conservativeImplicit'
badCase zeroNeighbourSkin 'maxInteractionDistance +4e-3;' \
    'maxInteractionDistance 4e-3; neighbourSkin 0;' \
    'Entry neighbourSkin = 0 is out of range \(0, maxInteractionDistance = 0.004\]'
badCase largeNeighbourSkin 'maxInteractionDistance +4e-3;' \
    'maxInteractionDistance 4e-3; neighbourSkin 5e-3;' \
    'Entry neighbourSkin = 0.005 is out of range \(0, maxInteractionDistance = 0.004\]'
badCase smallInteractionDistance 'maxInteractionDistance +4e-3;' \
    'maxInteractionDistance 1e-5; neighbourSkin 1e-6;' \
    'Entry maxInteractionDistance = 1e-05 is too small for parcel'
