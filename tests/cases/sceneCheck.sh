# The run-time scene check (cloudProperties/sceneCheck): the summary's
# numbers against values computed here from the parcels and the mesh
# (surface field, wall distance, surface gap, Coulomb-collision step of
# Boutsikakis Eqs. 21-23 with Eq. 25), and each warning raised where the
# chosen model is inadequate or idle and absent where it is not; serial =
# parallel; bad entries stop the run naming the entry.
. "$(dirname "$0")/common.sh.inc"

# sceneBlock <log>: the summary of the first check
sceneBlock() { sed -n '/^Scene check of/,/^$/p' "$1" | sed '/^$/q'; }
# value <log> <label> <regex>: first number after <regex> on the summary line <label>
value()
{
    sceneBlock "$1" | grep "^    $2 " | sed -E "s/.*$3 ([-0-9.e+]+).*/\1/" | head -1
}
warned() { grep -q "Scene check: $2" "$1"; }
# rel <a> <b> <tol>: |a/b - 1| <= tol
rel() { $PY -c "import sys; a, b, t = map(float, sys.argv[1:]); sys.exit(0 if abs(a/b - 1) <= t else 1)" "$1" "$2" "$3"; }

twoSpheres()    # twoSpheres <dest> <q1> <q2> <deltaT> <endTime>
{
    copyCase twoChargedSpheres "$1"
    (
        cd "$1" || exit 1
        sed -i -E "s/q +-?1e-12;/q QQ;/" constant/cloudProperties
        sed -i -E "0,/q QQ;/s//q $2;/" constant/cloudProperties
        sed -i -E "0,/q QQ;/s//q $3;/" constant/cloudProperties
        sed -i -E "s/^deltaT .*/deltaT          $4;/" system/controlDict
        setEndTime "$5"
    )
}

# 1. Two opposite charges in the tutorial's walled 4 x 2 x 2 mm box: walls
#    1 mm from the charges, 1 mm apart: (1/(2*1))^2 = 25 %
twoSpheres "$work/pair" -1e-12 1e-12 1e-6 4e-6
cp -r "$work/pair" "$work/open"
cp -r "$work/pair" "$work/pairParallel"
cd "$work/pair" || exit 1
run blockMesh blockMesh && run solver chargedParticleFoam || fail "sceneCheck.pair (solver failed)"
Es=$(value log.solver "surface field" "=")
expect=$($PY -c "import math; print(1e-12/(8.8541878128e-12*4*math.pi*50e-6**2))")
check sceneCheck.surfaceField "($Es vs q/(eps0 4 pi r^2) = $expect V/m)" rel "$Es" "$expect" 1e-3
dW=$(value log.solver "wall distance" "median")
check sceneCheck.wallDistance "(median $dW m vs 1e-3 m to the side walls)" rel "$dW" 1e-3 1e-3
check sceneCheck.freeSpaceWarned "(directCoulomb, walls 1 mm away: ~25 %)" \
    warned log.solver "electrostaticsModel directCoulomb sums charges in free space.*~25 %"
n=$(grep -c "^Scene check of" log.solver)
check sceneCheck.once "(recheckInterval 0: $n check in 4 steps)" test "$n" -eq 1

#    The same box with open boundaries (patch, not wall): nothing to warn
cd "$work/open" || exit 1
setWriteInterval 1
sed -i 's/type wall;/type patch;/' system/blockMeshDict
run blockMesh blockMesh && run solver chargedParticleFoam || fail "sceneCheck.open (solver failed)"
check sceneCheck.openQuiet "(open patches: no warning)" \
    bash -c "! grep -q 'Scene check:' log.solver && grep -q 'walls              none' log.solver"

#    2 processors: the same summary
cd "$work/pairParallel" || exit 1
run blockMesh blockMesh && run decomposePar decomposePar && run parallel mpirun -np 2 chargedParticleFoam -parallel \
    || fail "sceneCheck.parallel (run failed)"
check sceneCheck.parallel "(summary of 2 processors = serial)" \
    bash -c "diff <(sed -n '/^Scene check of/,/^\$/p' '$work/pair/log.solver') <(sed -n '/^Scene check of/,/^\$/p' log.parallel) > /dev/null"

# 2. Two like charges (1 pC, 100 um, 1000 kg/m3) in the same box: a
#    mono-charged cloud. Coulomb-collision step from Eqs. 21-23 with the
#    agitation of Eq. 25 (n = 2/V, at rest) computed here; deltaT 1e-4 s
#    above it is warned, 1e-6 s is not
twoSpheres "$work/like" 1e-12 1e-12 1e-4 2e-4
cd "$work/like" || exit 1
setWriteInterval 1
run blockMesh blockMesh && run solver chargedParticleFoam || fail "sceneCheck.like (solver failed)"
dtC=$(value log.solver "time step" "Eq. 23\)")
expect=$($PY - <<'PYEOF'
import math
eps0 = 8.8541878128e-12
k = 1/(4*math.pi*eps0)
Q, m = 1e-12, 1000*4/3*math.pi*50e-6**3
n = 2/(4e-3*2e-3*2e-3)
qp2 = k*Q*Q*n**(1/3)/m                       # Eq. 25
w = math.sqrt(16/math.pi*2/3*qp2)            # Eq. 22
dC = k*Q*Q/(m/2*w*w)                         # Eq. 21
print(0.01*dC/w)                             # Eq. 23
PYEOF
)
check sceneCheck.coulombStep "($dtC s vs Eqs. 21-23, 25: $expect s)" rel "$dtC" "$expect" 1e-3
#    Volume fraction and plasma period 2 pi sqrt(eps0 m/(n q^2)), n = 2/V
phiV=$(value log.solver parcels "volume fraction")
expect=$($PY -c "import math; print(2*4/3*math.pi*50e-6**3/(4e-3*2e-3*2e-3))")
check sceneCheck.volumeFraction "($phiV vs $expect)" rel "$phiV" "$expect" 1e-3
Tp=$(value log.solver "time scales" "plasma period")
expect=$($PY -c "import math; m = 1000*4/3*math.pi*50e-6**3; n = 2/(4e-3*2e-3*2e-3); print(2*math.pi*math.sqrt(8.8541878128e-12*m/(n*1e-12**2)))")
check sceneCheck.plasmaPeriod "($Tp s vs $expect s)" rel "$Tp" "$expect" 1e-3
check sceneCheck.coulombWarned "(deltaT 1e-4 s above it)" warned log.solver "the force step 0.0001 s exceeds"
check sceneCheck.coulombQuiet "(deltaT 1e-6 s: no such warning in the pair case)" \
    bash -c "! grep -q 'exceeds the Coulomb' '$work/pair/log.solver'"

# 3. Two like-charged dielectric spheres 0.3 a1 apart (tutorial
#    dielectricSpheres): the gap, and the near-field advice per rung
copyCase dielectricSpheres "$work/diel"
cd "$work/diel" || exit 1
setEndTime 2e-6
cp -r "$work/diel" "$work/dielNone"
cp -r "$work/diel" "$work/dielBem"
run blockMesh blockMesh && run solver chargedParticleFoam || fail "sceneCheck.diel (solver failed)"
gap=$(value log.solver "polarisable" "min")
expect=$($PY - <<'PYEOF'
import re
s = open("constant/cloudProperties").read()
p = re.findall(r"position\s*\(([^)]*)\);.*?\bd\s+([0-9.eE+-]+);", s)
(x1, d1), (x2, d2) = [([float(v) for v in a.split()], float(d)) for a, d in p]
dist = sum((a - b)**2 for a, b in zip(x1, x2))**0.5
r1, r2 = d1/2, d2/2
print((dist - r1 - r2)/min(r1, r2))
PYEOF
)
check sceneCheck.gap "(smallest surface gap $gap vs $expect smaller radii from the parcels)" rel "$gap" "$expect" 1e-3
check sceneCheck.dipoleWarned "(inducedDipole, charged pair at 0.3: bem advised)" \
    warned log.solver "nearField inducedDipole: 2 charged polarisable"
cd "$work/dielNone" || exit 1
sed -i -E 's/type +inducedDipole;.*/type none;/' constant/cloudProperties
run blockMesh blockMesh && run solver chargedParticleFoam || fail "sceneCheck.dielNone (solver failed)"
check sceneCheck.pointChargesWarned "(nearField none for the close dielectric pair)" \
    warned log.solver "nearField none: 2 polarisable parcels.*within two smaller"
cd "$work/dielBem" || exit 1
sed -i -E 's/type +inducedDipole;.*/type bem;/' constant/cloudProperties
run blockMesh blockMesh && run solver chargedParticleFoam || fail "sceneCheck.dielBem (solver failed)"
check sceneCheck.bemQuiet "(nearField bem: no near-field warning)" \
    bash -c "! grep -q 'Scene check: nearField' log.solver"

# 4. The flagship duct (gas, 2000 PTFE ellipsoids, one step): quiet with
#    meshPoisson; a free-space sum is warned; a parcel charged beyond the
#    breakdown of air is warned
copyCase chargedDuct "$work/duct"
cd "$work/duct" || exit 1
$PY makeParcels.py 300 > /dev/null
sed -i -E '0,/q 0;/s//q -1e-9;/' constant/parcels
setEndTime 1e-4
cp -r "$work/duct" "$work/ductDirect"
run blockMesh blockMesh && run solver chargedDPMFoam || fail "sceneCheck.duct (solver failed)"
check sceneCheck.ductBreakdown "(-1 nC on a 1 x 0.5 x 0.5 mm ellipsoid in air: the parcel, its charge and the limit named)" \
    warned log.solver "the largest surface field .* V/m, of parcel (origProc 0, origId 0) at (.*) with q = -1e-09 C, exceeds sceneCheck/breakdownField = 3e+06 V/m (1 parcel(s) above)"
check sceneCheck.ductMeshQuiet "(meshPoisson: no model warning)" \
    bash -c "! grep -q 'Scene check: electrostaticsModel' log.solver"
cd "$work/ductDirect" || exit 1
sed -i -E 's/electrostaticsModel meshPoisson;/electrostaticsModel directCoulomb;/' constant/cloudProperties
run blockMesh blockMesh && run solver chargedDPMFoam || fail "sceneCheck.ductDirect (solver failed)"
check sceneCheck.ductDirectWarned "(directCoulomb in the grounded duct)" \
    warned log.solver "electrostaticsModel directCoulomb sums charges in free space"

# 5. An electrostatics model with nothing to do (uncharged pour), and a
#    recheck interval
copyCase ellipsoidPour "$work/idle"
cd "$work/idle" || exit 1
$PY makeParcels.py 50 > /dev/null
sed -i -E 's/electrostaticsModel +none;/electrostaticsModel directCoulomb;/' constant/cloudProperties
cat >> constant/cloudProperties <<'EOF'
sceneCheck { recheckInterval 2; }
EOF
setEndTime 6e-4
run blockMesh blockMesh && run solver chargedParticleFoam || fail "sceneCheck.idle (solver failed)"
check sceneCheck.idleWarned "(directCoulomb, nothing charged)" \
    warned log.solver "electrostaticsModel directCoulomb has nothing to compute"
n=$(grep -c "^Scene check of" log.solver)
check sceneCheck.recheck "(recheckInterval 2 over 6 steps: $n checks, 3 expected)" test "$n" -eq 3

#    The same pour with like charges, contact (a reduction in the step
#    count) and the Coulomb-collision estimate (a volume sum), on 2
#    processors: the same summary as serial, and no processor left waiting
copyCase ellipsoidPour "$work/pourSerial"
cd "$work/pourSerial" || exit 1
$PY makeParcels.py 50 > /dev/null
sed -i -E 's/ q 0; \}/ q 1e-13; }/' constant/parcels
sed -i -E 's/electrostaticsModel +none;/electrostaticsModel directCoulomb;/' constant/cloudProperties
setEndTime 2e-4
setWriteInterval 1
cp -r "$work/pourSerial" "$work/pourParallel"
run blockMesh blockMesh && run solver chargedParticleFoam || fail "sceneCheck.pourSerial (solver failed)"
cd "$work/pourParallel" || exit 1
run blockMesh blockMesh && run decomposePar decomposePar \
 && run parallel timeout 300 mpirun -np 2 chargedParticleFoam -parallel \
    || fail "sceneCheck.pourParallel (run failed or hung, see $work/pourParallel/log.parallel)"
check sceneCheck.pourParallel "(like charges with contact on 2 processors: summary = serial)" \
    bash -c "grep -q 'Coulomb-collision step' log.parallel && diff <(sed -n '/^Scene check of/,/^\$/p' '$work/pourSerial/log.solver') <(sed -n '/^Scene check of/,/^\$/p' log.parallel) > /dev/null"

# 6. The advisor utility: the same check on a written time, without a run
#    (the pair: the free-space and the Coulomb-step warnings); in parallel
#    the same as serial
advise() { chargedFoamAdvisor "$@" > log.advisor 2>&1; sed -n 's/^\([0-9]*\) warning(s)$/\1/p' log.advisor > advisor.warnings; }
cd "$work/like" && advise -latestTime
check sceneCheck.advisorWarns "(like pair at t = 2e-4 s: $(cat advisor.warnings) warnings, the solver's Coulomb warning)" \
    bash -c "[ \$(cat advisor.warnings) = 2 ] && grep -q 'the force step 0.0001 s exceeds' log.advisor \
             && [ \"\$(grep '^    time step' log.advisor)\" = \"\$(grep -m1 '^    time step' log.solver)\" ]"
cd "$work/open" && advise -latestTime
check sceneCheck.advisorQuiet "(open box: $(cat advisor.warnings) warnings)" \
    bash -c "[ \$(cat advisor.warnings) = 0 ] && grep -q '^    no warnings' log.advisor"
cd "$work/pourSerial" && advise -latestTime
cd "$work/pourParallel" && mpirun -np 2 chargedFoamAdvisor -parallel -latestTime > log.advisor 2>&1
check sceneCheck.advisorParallel "(2 processors: summary = serial advisor's)" \
    bash -c "grep -q '^Scene check of' log.advisor && diff <(sed -n '/^Scene check of/,/^\$/p' '$work/pourSerial/log.advisor') <(sed -n '/^Scene check of/,/^\$/p' log.advisor) > /dev/null"

# 7. Bad entries
mkdir -p "$work/bad"
for bad in "recheckInterval -1" "breakdownField 0"
do
    name=${bad%% *}
    twoSpheres "$work/bad/$name" -1e-12 1e-12 1e-6 2e-6
    cd "$work/bad/$name" || exit 1
    echo "sceneCheck { $bad; }" >> constant/cloudProperties
    run blockMesh blockMesh
    run solver chargedParticleFoam
    check "badInput.sceneCheck.$name" "($bad: error names the entry)" \
        bash -c "grep -q 'Entry $name' log.solver && grep -q 'FOAM FATAL IO ERROR' log.solver"
done
