# Guards of a running scene:
#  - parcels injected into each other (with a collision model): a FOAM FATAL
#    IO ERROR naming both parcels, the overlap and the entry
#    solution/maxInjectionOverlap; two spheres at one point, two spheres
#    10 % of a radius deep, two parallel prolates 20 % of the minor
#    semi-axis deep (the ellipsoid narrow phase);
#  - with maxInjectionOverlap above the overlap the spheres are pushed apart
#    by the contact: they separate, with equal and opposite momenta, no
#    faster than the overlap's Hertz energy allows;
#  - a parcel state that is not finite (a NaN in a binary restart file, run
#    with FOAM_SIGFPE=false as the fuzzer does) stops the run before its
#    first kick, naming the parcel, the time and the term; nothing
#    non-finite is written.
. "$(dirname "$0")/common.sh.inc"

copyCase headOnCollision "$work/spheres"
cd "$work/spheres" || exit 1
run blockMesh blockMesh || fail "guards.mesh (blockMesh failed)"
setEndTime 2e-4
copyCase ellipsoidDrop "$work/prolates"
cd "$work/prolates" || exit 1
run blockMesh blockMesh || fail "guards.mesh (blockMesh failed)"
setEndTime 1e-4

# 5e-05 and 0.1 to the last digits of 17
near5em5='(5e-05|5\.0000000[0-9]*e-05|4\.9999999[0-9]*e-05)'
near0p1='(0\.1|0\.10000000[0-9]*|0\.09999999[0-9]*)'

# overlapCase <name> <base> <expected message regex> <pattern> <repl> [...]
overlapCase()
{
    local name="$1" base="$2" expect="$3" dir="$work/$1"
    shift 3
    rm -rf "$dir"
    cp -r "$work/$base" "$dir"
    regexEdit "$dir/constant/cloudProperties" "$@" || { fail "guards.$name (edit)"; return; }
    (
        cd "$dir" || exit 1
        chargedParticleFoam > log.solver 2>&1
        expectFatalIO "guards.$name" "$dir/log.solver" $? "$expect"
    )
}

overlapCase coincidentSpheres spheres \
    'parcel \(origProc 0, origId 0\) at \([^)]*\) and parcel \(origProc 0, origId 1\) at \([^)]*\) overlap by 0.001 m = 2 of the smaller semi-axis 0\.0005[0-9]* m, more than maxInjectionOverlap = 0 ' \
    'position \(-0.55e-3 0 0\)' 'position (0 0 0)' \
    'position \( 0.55e-3 0 0\)' 'position (0 0 0)'
overlapCase overlappingSpheres spheres \
    "overlap by $near5em5 m = $near0p1 of the smaller semi-axis 0\.0005[0-9]* m, more than maxInjectionOverlap = 0 " \
    'position \(-0.55e-3 0 0\)' 'position (-0.475e-3 0 0)' \
    'position \( 0.55e-3 0 0\)' 'position (0.475e-3 0 0)'
overlapCase tooDeepForOptIn spheres \
    "overlap by $near5em5 m = $near0p1 of the smaller semi-axis 0\.0005[0-9]* m, more than maxInjectionOverlap = 0\.050*[0-9]* " \
    'position \(-0.55e-3 0 0\)' 'position (-0.475e-3 0 0)' \
    'position \( 0.55e-3 0 0\)' 'position (0.475e-3 0 0)' \
    'coupled +false;' 'coupled false; maxInjectionOverlap 0.05;'
overlapCase badOptIn spheres \
    'Entry maxInjectionOverlap = 0.(7|69999[0-9]*) .* is out of range: it must be in \[0, 0.5\]' \
    'coupled +false;' 'coupled false; maxInjectionOverlap 0.7;'
# Long axes along y, side by side along x: 1e-4 m deep = 0.2 b
overlapCase overlappingProlates prolates \
    'parcel \(origProc 0, origId 0\) at \([^)]*\) and parcel \(origProc 0, origId 1\) at \([^)]*\) overlap by (0\.0001|0\.0001000000[0-9]*|9\.999999[0-9]*e-05) m = (0\.2|0\.2000000[0-9]*|0\.1999999[0-9]*) of the smaller semi-axis 0\.0005[0-9]* m' \
    'eulerAngles \(0 85 90\)' 'eulerAngles (0 0 90)' \
    'position \(15e-3 15e-3 4e-3\); semiAxes \(1.5e-3 5e-4 5e-4\); eulerAngles \(0 60 90\)' \
    'position (5.9e-3 15e-3 4e-3); semiAxes (1.5e-3 5e-4 5e-4); eulerAngles (0 0 90)'

# Opt-in: 10 % of a radius at rest, allowed; the contact pushes them apart
dir="$work/optIn"
rm -rf "$dir"; cp -r "$work/spheres" "$dir"
regexEdit "$dir/constant/cloudProperties" \
    'position \(-0.55e-3 0 0\); U \( 0.5 0 0\)' 'position (-0.475e-3 0 0); U (0 0 0)' \
    'position \( 0.55e-3 0 0\); U \(-0.5 0 0\)' 'position (0.475e-3 0 0); U (0 0 0)' \
    'coupled +false;' 'coupled false; maxInjectionOverlap 0.15;' \
    || fail "guards.optIn (edit)"
(
    cd "$dir" || exit 1
    setWriteInterval 200
    if ! chargedParticleFoam > log.solver 2>&1
    then
        fail "guards.optIn (solver failed, see $dir/log.solver)"
        exit 0
    fi
    check guards.optInSeparates "(overlap 0.1 R allowed: apart, equal and opposite momenta, speed within the Hertz energy of the overlap)" \
        $PY - "$top/etc/python" <<'PYEOF'
import os, re, sys
import numpy as np
sys.path.insert(0, sys.argv[1])
from foamLagrangian import read_field, read_positions
t = max((d for d in os.listdir(".") if re.fullmatch(r"[0-9.e-]+", d) and d != "0"), key=float)
c = os.path.join(t, "lagrangian", "cloud")
x = read_positions(os.path.join(c, "positions"))
U = read_field(os.path.join(c, "U")).reshape(-1, 3)
text = open("constant/cloudProperties").read()
E = float(re.search(r"youngsModulus\s+([0-9.e+-]+);", text).group(1))
nu = float(re.search(r"poissonsRatio\s+([0-9.e+-]+);", text).group(1))
rho = float(re.search(r"rho0\s+([0-9.e+-]+);", text).group(1))
R, delta = 0.5e-3, 0.05e-3
m = rho*4/3*np.pi*R**3
Estar = E/(2*(1 - nu**2))
# Hertz: elastic energy (8/15) E* sqrt(R*) delta^(5/2), R* = R/2 (the
# integral of the Hertz force (4/3) E* sqrt(R*) delta^(3/2), Johnson 1985
# Eq. 4.23)
energy = 8/15*Estar*np.sqrt(R/2)*delta**2.5
vMax = np.sqrt(energy/m)          # both spheres at v: m v^2 = energy
gap = np.linalg.norm(x[1] - x[0]) - 2*R
p = U[0] + U[1]
v = np.linalg.norm(U, axis=1)
print(f"t = {t}: gap {gap:.3e} m, speeds {v[0]:.4e} {v[1]:.4e} m/s, bound {vMax:.4e} m/s, |p|/(m v) {np.linalg.norm(p)/max(v[0], 1e-300):.1e}")
ok = gap > 0 and v[0] > 0 and v[0] <= vMax*(1 + 1e-6) and np.linalg.norm(p) <= 1e-9*v[0]
sys.exit(0 if ok else 1)
PYEOF
)

# A NaN in the restart files: the parcel, the time and the term are named
copyCase twoChargedSpheres "$work/nan"
cd "$work/nan" || exit 1
setEndTime 2e-5
setWriteInterval 10
sed -i -E 's/^writeFormat .*/writeFormat     binary;/' system/controlDict
if run blockMesh blockMesh && run solver chargedParticleFoam
then
    $PY - 2e-05/lagrangian/cloud/U <<'PYEOF'
import struct, sys
p = sys.argv[1]
b = open(p, "rb").read()
# The binary list: "2\n(" then 2 x 3 doubles; parcel 1's x component := NaN
i = b.index(b"\n2\n(") + 4
b = b[:i + 24] + struct.pack("<d", float("nan")) + b[i + 32:]
open(p, "wb").write(b)
PYEOF
    setEndTime 3e-5
    FOAM_SIGFPE=false chargedParticleFoam > log.restart 2>&1
    rc=$?
    expect='Parcel \(origProc 0, origId 1\) at .*, t = 2\.10*[0-9]*e-05 s \(time index 21\): the velocity U = \(nan [^)]*\) or the angular momentum \(0 0 0\) before the kick, is not finite'
    if [ "$rc" -ne 0 ] && grep -q "FOAM FATAL ERROR" log.restart && grep -Eq "$expect" log.restart
    then
        pass "guards.nonFinite (exit $rc: $(grep -Eo 'Parcel \(origProc 0, origId 1\).*before the kick' log.restart | head -1))"
    else
        fail "guards.nonFinite (exit $rc; expected '$expect', see $work/nan/log.restart)"
    fi
    check guards.nothingNonFiniteWritten "(no time written after 2e-05)" \
        test ! -d 3e-05 -a ! -d 2.1e-05
else
    fail "guards.nonFinite (base run failed)"
fi
