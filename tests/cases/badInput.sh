# Bad input stops with an OpenFOAM FatalIOError naming the entry:
# missing or out-of-range charge, diameter, density, rho0, epsilonR;
# contact charging: negative kappaC, a wall patch without parameters, a
# missing Gamma, a non-positive cutoff distance, charging without
# ellipsoidCollision; lazy-tracking tolerance, log interval and neighbour
# skin out of range; particle permittivity, the applied field's type and
# the near field's entries; stiffnessRatio outside (0, 1] without
# ellipsoidCollision; the dipoles' maxIter (a label >= 1); non-finite
# parcel U, omega, eulerAngles; NaN p3m rCut, a non-bool fastErfc, Ne < 0;
# the BEM solver's maxPreconditionerPatches, directOutputMax, nearFactor;
# several materials: an unknown name, an unlike pair without Gamma, a
# Gamma for like materials, a pair given twice, a material's rho0, an
# OpenFOAM injection model's material without an injectorID;
# non-finite carrierProperties (rho, mu, U). Non-finite values come from
# #eval with FOAM_SIGFPE=false (the reader refuses nan and inf).
# The escapes of the dictionary fuzzer (doc/extremes.md): maxCo out of
# [1e-3, 1] (a hang), huge, nan or far values of the parcels' U, d, q,
# position, semiAxes, of rho0, epsilonR, shape, SOI, the medium's epsilonR,
# the mesh-Poisson radius, the carrier's U and rho, youngsModulus, mu,
# maxInteractionDistance, deltaBl, a tiny restitution coefficient, Gamma,
# a charge from contact charging beyond 1e12 V/m, more than 1e6 collision
# sub-cycles, a parcel kicked to the speed of light, coupled true without a
# carrier, standardWallInteraction's e above 1; chargedDPMFoam's
# nOuterCorrectors, pRefValue, a missing solvers dictionary, the parcels
# of OpenFOAM's manualInjection (U0, sizeDistribution, nParticle), and a
# copy of an injection model (parcels at one position).
. "$(dirname "$0")/common.sh.inc"

copyCase twoChargedSpheres "$work/base"
cd "$work/base" || exit 1
run blockMesh blockMesh || fail "badInput.mesh (blockMesh failed)"
copyCase triboSingleContact "$work/tribo"
cd "$work/tribo" || exit 1
run blockMesh blockMesh || fail "badInput.mesh (blockMesh failed)"
copyCase gasSettling "$work/dpm"
cd "$work/dpm" || exit 1
{ run makePositions $PY makePositions.py --n 20 && run blockMesh blockMesh; } \
    || fail "badInput.mesh (gasSettling: makePositions or blockMesh failed)"
solver=chargedParticleFoam
base=base
file=constant/cloudProperties

# badCase <name> <python re.sub pattern> <replacement> <expected message regex>
#     [<pattern> <replacement> ...]
# (a copy of $work/$base with one change, or several, in its $file)
badCase()
{
    local name="$1" pattern="$2" repl="$3" expect="$4" dir="$work/$1"
    shift 4
    rm -rf "$dir"
    cp -r "$work/$base" "$dir"
    (
        cd "$dir" || exit 1
        regexEdit "$file" "$pattern" "$repl" "$@" || exit 1
        $solver > log.solver 2>&1
        expectFatalIO "badInput.$name" "$dir/log.solver" $? "$expect"
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
    'Entry epsilonR .* = 0 in .* is out of range'
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

# Reduced stiffness is checked where constantProperties is read, whatever
# the collision model (here none: only the Coulomb contact correction)
badCase negativeStiffnessRatio 'rho0 +1000;' 'rho0 1000; stiffnessRatio -0.5;' \
    'Entry stiffnessRatio \(chi = E_R/E_O, Ruan Eq. 44\) = -0.5 in .* is out of range \(0, 1\]'
badCase zeroDipoleMaxIter 'epsilonR +1;' 'epsilonR 1; nearField { type inducedDipole; maxIter 0; }' \
    'Entry maxIter = 0 in .*nearField is out of range: >= 1'
# (a label: 0.5 is OpenFOAM's token error at the entry, not 0 iterations)
badCase fractionalDipoleMaxIter 'epsilonR +1;' 'epsilonR 1; nearField { type inducedDipole; maxIter 0.5; }' \
    'directCoulombCoeffs\.nearField\.maxIter at line [0-9]+'

# Non-finite values cannot be typed (the reader refuses nan, inf, 1e400)
# but an expression gives them (#eval, floating-point traps off)
FOAM_SIGFPE=false badCase infiniteParcelVelocity \
    'U \(0 0 0\); d 1e-4; rho 1000; q  1e-12;' \
    'U (#eval{1e300*1e300} 0 0); d 1e-4; rho 1000; q  1e-12;' \
    'Entry U of parcel 0 .* out of range \(\(inf 0 0\)\): all components must be finite'
FOAM_SIGFPE=false badCase nanParcelOmega \
    'd 1e-4; rho 1000; q -1e-12;' 'd 1e-4; rho 1000; q -1e-12; omega (0 #eval{sqrt(-1)} 0);' \
    'Entry omega of parcel 1 .* out of range \(\(0 -?nan 0\)\): all components must be finite'
FOAM_SIGFPE=false badCase infiniteEulerAngles \
    'd 1e-4; rho 1000; q  1e-12;' 'd 1e-4; rho 1000; q  1e-12; eulerAngles (0 0 #eval{-1e300*1e300});' \
    'Entry eulerAngles of parcel 0 .* out of range \(\(0 0 -inf\)\): all components must be finite'

# Tri-periodic kernels (on this non-periodic box: a warning only)
FOAM_SIGFPE=false badCase nanP3mCutoff 'electrostaticsModel directCoulomb;' \
    'electrostaticsModel periodic; periodicCoeffs { method p3m; rCut #eval{sqrt(-1)}; }' \
    "Entry 'rCut' = -?nan is out of range \[0, "
badCase numericFastErfc 'electrostaticsModel directCoulomb;' \
    'electrostaticsModel periodic; periodicCoeffs { method p3m; fastErfc 2; }' \
    "Entry 'fastErfc' = 2 is out of range: auto, or a bool"
badCase negativePseudoParticleNe 'electrostaticsModel directCoulomb;' \
    'electrostaticsModel periodic; periodicCoeffs { method pseudoParticle; Ne -1; }' \
    "Entry 'Ne' = -1 is out of range \[0, 1000\]"
badCase negativePotentialInterval 'electrostaticsModel directCoulomb;' \
    'electrostaticsModel periodic; periodicCoeffs { method p3m; potentialInterval -1; }' \
    'Entry potentialInterval = -1 in .* is out of range \[0, inf\)'
badCase potentialsOfPseudoParticle 'electrostaticsModel directCoulomb;' \
    'electrostaticsModel periodic; periodicCoeffs { method pseudoParticle; potentialInterval 5; }' \
    'Entry potentialInterval = 5: method pseudoParticle gives no potentials'

# BEM solver controls (read as in the bemElectrostatics utility)
badCase negativePreconditionerPatches 'epsilonR +1;' \
    'epsilonR 1; nearField { type bem; solver { maxPreconditionerPatches -1; } }' \
    'Entry maxPreconditionerPatches = -1 in .*solver is out of range: >= 0'
badCase negativeDirectOutputMax 'epsilonR +1;' \
    'epsilonR 1; nearField { type bem; solver { directOutputMax -1; } }' \
    'Entry directOutputMax = -1 in .*solver is out of range: >= 0'
FOAM_SIGFPE=false badCase infiniteNearFactor 'epsilonR +1;' \
    'epsilonR 1; nearField { type bem; solver { nearFactor #eval{1e300*1e300}; } }' \
    'Entry nearFactor = inf in .*solver is out of range: it must be finite and >= 0'

# chargedParticleFoam's carrier medium, constant/carrierProperties
cp -r "$work/base" "$work/carrier"
printf '%s\n' \
    'FoamFile { version 2.0; format ascii; class dictionary; object carrierProperties; }' \
    'rho 0;' 'mu  0;' 'U   (0 0 0);' > "$work/carrier/constant/carrierProperties"
base=carrier
file=constant/carrierProperties
FOAM_SIGFPE=false badCase nanCarrierDensity 'rho 0;' 'rho #eval{sqrt(-1)};' \
    'Entry rho \(carrier density \[kg/m3\]\) = -?nan in .* is out of range: it must be finite and >= 0'
FOAM_SIGFPE=false badCase infiniteCarrierViscosity 'mu  0;' 'mu #eval{1e300*1e300};' \
    'Entry mu \(carrier dynamic viscosity \[Pa s\]\) = inf in .* is out of range: it must be finite and >= 0'
FOAM_SIGFPE=false badCase infiniteCarrierVelocity 'U   \(0 0 0\);' 'U (0 #eval{1e300*1e300} 0);' \
    'Entry U \(carrier velocity \[m/s\]\) = \(0 inf 0\) in .* is out of range: all components must be finite'
file=constant/cloudProperties

# -- Escapes of the dictionary fuzzer (applications/benchmarks/fuzzDictionaries) --
base=base
badCase zeroMaxCo 'maxCo +0.3;' 'maxCo 0;' \
    'Entry maxCo \(tracking Courant number\) = 0 in .* is out of range \[0.001, 1\]'
badCase hugeParcelVelocity 'U \(0 0 0\); d 1e-4; rho 1000; q  1e-12;' \
    'U (0 1e300 0); d 1e-4; rho 1000; q  1e-12;' \
    'Entry U of parcel 0 .* its magnitude must be below [0-9.e+]+ \(the speed of light'
badCase hugeParcelDiameter 'd 1e-4; rho 1000; q  1e-12' 'd 1e300; rho 1000; q  1e-12' \
    'Entry d of parcel 0 .* out of range \(1[.0-9]*e\+300\): it must be given, finite and > 0, in \[1[.0-9]*e-09, '
badCase hugeParcelCharge 'q  1e-12;' 'q 1e300;' \
    'Entry q of parcel 0 .* out of range \(1[.0-9]*e\+300\): \|q\| must be at most'
badCase farParcelPosition 'position \(-0.5e-3 0 0\)' 'position (-0.5e-3 0 1e300)' \
    "Entry position of parcel 0 .* it must lie in the mesh's bounding box"
FOAM_SIGFPE=false badCase nanParcelPosition 'position \(-0.5e-3 0 0\)' \
    'position (-0.5e-3 #eval{sqrt(-1)} 0)' \
    'Entry position of parcel 0 .* all components must be finite'
FOAM_SIGFPE=false badCase nanSemiAxes 'd 1e-4; rho 1000; q  1e-12' \
    'semiAxes (1e-4 #eval{sqrt(-1)} 5e-5); rho 1000; q  1e-12' \
    'Entry semiAxes of parcel 0 .* all must be finite and > 0'
badCase needleSemiAxes 'd 1e-4; rho 1000; q  1e-12' \
    'semiAxes (1e-4 1e-8 1e-8); rho 1000; q  1e-12' \
    'Entry semiAxes of parcel 0 .* the longest at most 1000 times the shortest'
FOAM_SIGFPE=false badCase nanRho0 'rho0 +1000;' 'rho0 #eval{sqrt(-1)};' \
    'Entry rho0 \(particle density \[kg/m3\]\) = -?nan in .* is out of range'
badCase hugeParticleEpsilonR 'rho0 +1000;' 'rho0 1000; epsilonR 1e300;' \
    'Entry epsilonR \(relative permittivity of the particles\) = 1[.0-9]*e\+300 .* at most 1e\+30'
badCase hugeShape 'rho0 +1000;' 'rho0 1000; shape (2 1e300 1);' \
    'Entry shape \(semi-axes ratios a:b:c\) = .* the largest at most 1000 times the smallest'
badCase tinyMediumEpsilonR 'epsilonR +1;' 'epsilonR 1e-200;' \
    'Entry epsilonR \(relative permittivity of the medium\) = [.0-9]+e-20[01] in .* is out of range: it must be finite and >= 1'
FOAM_SIGFPE=false badCase nanSOI 'SOI +0;' 'SOI #eval{sqrt(-1)};' \
    'Entry SOI \(start of injection \[s\]\) = -?nan'
badCase coupledWithoutCarrier 'coupled +false;' 'coupled true;' \
    'Entry coupled in .* is true: chargedParticleFoam solves no carrier flow'
badCase reboundAboveOne 'rebound;(\s*)e +1;' 'rebound;\1e 2;' \
    'Entry e \(restitution coefficient\) = 2 in .*standardWallInteractionCoeffs is out of range \[0, 1\]'
badCase lightSpeedParcel 'd 1e-4; rho 1000; q  1e-12' 'd 1e-9; rho 1000; q  1e-12' \
    'Parcel \(origProc 0, origId 0\) at .* has the velocity U = .* not below the speed of light'
badCase hugeMeshPoissonRadius 'electrostaticsModel directCoulomb;' \
    'electrostaticsModel meshPoisson; meshPoissonCoeffs { radius 1e300; }' \
    'Entry radius = 1[.0-9]*e\+300 in .* is out of range: it must be finite and > 0, in \[1[.0-9]*e-09, '
badCase negativeNonOrthCorrectors 'electrostaticsModel directCoulomb;' \
    'electrostaticsModel meshPoisson; meshPoissonCoeffs { radius 1e-3; nNonOrthogonalCorrectors -1; }' \
    'Entry nNonOrthogonalCorrectors = -1 in .* must be >= 0'
badCase smallSelfFieldRadius 'electrostaticsModel directCoulomb;' \
    'electrostaticsModel meshPoisson; meshPoissonCoeffs { radius 1e-3; selfFieldRadius 1; }' \
    'Entry selfFieldRadius = 1 in .* must be 0 .* or in \[2, 10\] shape radii'
badCase negativeLatticeCorrectionSources 'electrostaticsModel directCoulomb;' \
    'electrostaticsModel meshPoisson; meshPoissonCoeffs { radius 1e-3; latticeCorrectionSources -1; }' \
    'Entry latticeCorrectionSources = -1 in .* must be >= 0'
badCase negativePatchPairCorrectionCharges 'electrostaticsModel directCoulomb;' \
    'electrostaticsModel meshPoisson; meshPoissonCoeffs { radius 1e-3; patchPairCorrectionCharges -2; }' \
    'Entry patchPairCorrectionCharges = -2 in .* must be >= 0'
badCase unknownSelfFieldSampling 'electrostaticsModel directCoulomb;' \
    'electrostaticsModel meshPoisson; meshPoissonCoeffs { radius 1e-3; selfFieldSampling cells; }' \
    'Entry selfFieldSampling = cells in .* must be one of 3\(points charges auto\)'
badCase unknownGradient 'electrostaticsModel directCoulomb;' \
    'electrostaticsModel meshPoisson; meshPoissonCoeffs { radius 1e-3; gradient linear; }' \
    'Entry gradient = linear in .* must be one of 2\(leastSquares Gauss\)'
badCase negativeNonOrthTolerance 'electrostaticsModel directCoulomb;' \
    'electrostaticsModel meshPoisson; meshPoissonCoeffs { radius 1e-3; nonOrthogonalTolerance -1; }' \
    'Entry nonOrthogonalTolerance = -1 in .* must be in \[0, 1\)'
badCase repeatedInjector '(\);\s*\}\s*)\}' '\1    twin { $twoSpheres; }\n    }' \
    "The parcels' positions must differ: check the injection models 2\(twoSpheres twin\)"
base=carrier
file=constant/carrierProperties
badCase hugeCarrierVelocity 'U   \(0 0 0\);' 'U (1e300 0 0);' \
    'Entry U \(carrier velocity \[m/s\]\) = \(1[.0-9]*e\+300 0 0\) .* below the speed of light'
badCase hugeCarrierDensity 'rho 0;' 'rho 1e300;' \
    'Entry rho \(carrier density \[kg/m3\]\) = 1[.0-9]*e\+300 .* at most 1e\+30'
file=constant/cloudProperties

base=tribo
badCase hugeYoungsModulus 'youngsModulus +0.564e9;' 'youngsModulus 1e300;' \
    'Entry youngsModulus = 1[.0-9]*e\+300 in .* is out of range: it must be finite and > 0, at most 1e\+30'
badCase hugeFriction 'mu +0.065; +// Table 2' 'mu 1e300;' \
    'Entry mu \(friction coefficient\) = 1[.0-9]*e\+300 in .* at most 1e\+30'
badCase longInteractionDistance 'maxInteractionDistance +4e-3;' 'maxInteractionDistance 10;' \
    "Entry maxInteractionDistance = 10 is out of range \(0, [0-9.e-]+\] \(the diagonal of the mesh's bounding box\)"
FOAM_SIGFPE=false badCase infiniteBufferLayer 'deltaBlRatio +0;' 'deltaBl #eval{1e300*1e300};' \
    'Entry deltaBl = inf is out of range: >= 0, at most maxInteractionDistance'
badCase tinyRestitution 'e +1;(\s*mu +0.065; +// Table 2)' 'e 1e-200;\1' \
    'Entry e \(restitution coefficient\) = [.0-9]+e-20[01] in .* is out of range \[1e-06, 1\]'
badCase hugeGamma 'Gamma -2.34e6;' 'Gamma -1e300;' \
    'Entry Gamma of wall patch plate in .* gives Gamma = -1[.0-9]*e\+300 V/m: out of range'
badCase hugeKappaC 'plate +\{ kappaC 9.64;' 'plate { kappaC 1e300;' \
    'Entry kappaC = 1[.0-9]*e\+300 in .* is out of range: it must be finite and >= 0, at most 1e\+30'
badCase chargeBeyondFieldMax 'plate +\{ kappaC 9.64;' 'plate { kappaC 1e25;' \
    'Contact charging gave parcel .* V/m above [0-9e+]+ V/m, beyond any material: the charging entries kappaC = 1[.0-9]*e\+25'
badCase tooManySubCycles 'youngsModulus +0.564e9;' 'youngsModulus 1e30;' \
    'needs more than [0-9e+]+ collision sub-cycles of the time step'

# chargedDPMFoam (gasSettling): fvSolution as OpenFOAM's solvers read it,
# and the parcels of OpenFOAM's manualInjection
base=dpm
solver=chargedDPMFoam
file=system/fvSolution
badCase negativeOuterCorrectors 'nOuterCorrectors 1;' 'nOuterCorrectors -1;' \
    'Entry nOuterCorrectors = -1 in .*PIMPLE is out of range: >= 1'
badCase hugePRefValue 'pRefValue +0;' 'pRefValue 1e300;' \
    'Entry pRefValue = 1[.0-9]*e\+300 in .*PIMPLE is out of range'
badCase missingSolvers '\nsolvers\s*\n\{' '\nsolvesr\n{' \
    'Entry solvers \{ p ...; U.air ...; \} is missing'
file=constant/cloudProperties
badCase hugeU0 'U0 +\(0 0 0\);' 'U0 (0 1e300 0);' \
    'A parcel injected at t = .* by one of the injection models .* U = .*: its magnitude must be below the speed of light'
FOAM_SIGFPE=false badCase nanSizeDistribution 'value +8e-5;' 'value #eval{sqrt(-1)};' \
    'The parcels of injection model column in .* have a total volume of -?nan m3'
badCase hugeNParticle 'nParticle +20;' 'nParticle 1e300;' \
    'A parcel \(origProc 0, origId [0-9]+\) of the injection models .* carries nParticle = 1[.0-9]*e\+300 particles of .* out of range'
badCase injectorWithoutId 'shape +\(2 1 1\);' \
    'shape (2 1 1); materials { glass {} light { rho0 1000; } }' \
    'Entry material of injection model column in .* needs an entry injectorID' \
    'type +manualInjection;' 'type manualInjection; material light;'
solver=chargedParticleFoam

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
    'Entry trackingTolerance = -0.001 in .* is out of range \[0, 0.5\]'
badCase zeroLogInterval 'maxCo +0.3;' 'maxCo 0.3; logInterval 0;' \
    'Entry logInterval = 0 in .* is out of range: >= 1'
badCase negativeSortInterval 'maxCo +0.3;' 'maxCo 0.3; sortInterval -1;' \
    'Entry sortInterval = -1 in .* is out of range: it must be >= 0'
badCase negativeSortMinParcels 'maxCo +0.3;' 'maxCo 0.3; sortMinParcels -5;' \
    'Entry sortMinParcels = -5 in .* is out of range: it must be >= 0'
badCase unknownMomentumCoupling 'maxCo +0.3;' 'maxCo 0.3; momentumCoupling implicit;' \
    'Entry momentumCoupling = implicit is not one of: conservativeImplicit'
# Several materials: an unknown material, an unlike pair without Gamma,
# a Gamma of like materials, a pair listed twice, a material's rho0
M='poissonsRatio   0.42;(.*)\n\}'
badCase unknownMaterial "$M" \
    'poissonsRatio 0.42; materials { PTFE {} nylon { rho0 1140; } }\1\n}' \
    'Entry material in .* names material steel, which the cloud does not have: its materials \(constantProperties/materials\) are' \
    'q -1.71e-10; \}' 'q -1.71e-10; material steel; }'
badCase unlikeWithoutGamma "$M" \
    'poissonsRatio 0.42; materials { PTFE {} nylon { rho0 1140; } }\1\n}' \
    'Materials PTFE and nylon have no charging field Gamma in .*: give materialPairs'
badCase likeGamma "$M" \
    'poissonsRatio 0.42; materials { PTFE {} nylon { rho0 1140; } }\1\n}' \
    'Entry Gamma in .* is not used: like materials have Gamma = 0' \
    'particles \{ kappaC 0; \}' \
    'particles { kappaC 0; } materialPairs { a { materials (nylon nylon); Gamma 1e5; } b { materials (PTFE nylon); Gamma 1e5; } }'
badCase pairTwice "$M" \
    'poissonsRatio 0.42; materials { PTFE {} nylon { rho0 1140; } }\1\n}' \
    'The material pair \(nylon PTFE\) of .* is also given by .*: list each pair once' \
    'particles \{ kappaC 0; \}' \
    'particles { kappaC 0; } materialPairs { a { materials (PTFE nylon); Gamma 1e5; } b { materials (nylon PTFE); Gamma -1e5; } }'
badCase materialDensity "$M" \
    'poissonsRatio 0.42; materials { PTFE {} nylon { rho0 -1; } }\1\n}' \
    'Entry rho0 \(particle density \[kg/m3\]\) = -1 in .*nylon is out of range'
badCase zeroNeighbourSkin 'maxInteractionDistance +4e-3;' \
    'maxInteractionDistance 4e-3; neighbourSkin 0;' \
    'Entry neighbourSkin = 0 is out of range \(0, maxInteractionDistance = 0.004\]'
badCase largeNeighbourSkin 'maxInteractionDistance +4e-3;' \
    'maxInteractionDistance 4e-3; neighbourSkin 5e-3;' \
    'Entry neighbourSkin = 0.005 is out of range \(0, maxInteractionDistance = 0.004\]'
badCase smallInteractionDistance 'maxInteractionDistance +4e-3;' \
    'maxInteractionDistance 1e-5; neighbourSkin 1e-6;' \
    'Entry maxInteractionDistance = 1e-05 is too small for parcel'
