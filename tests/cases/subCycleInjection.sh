# The collision sub-cycles of a step are set from the parcels' speeds at its
# start: the cloud's terms are taken in the last kick of the step before,
# those of the parcels injected since are added. The ellipsoidPour
# tutorial's 300 ellipsoids, the lower 150 injected at t = 0 and the upper
# 150 at SOI 0.003 s, one of these at 3 m/s downwards: the step that injects
# them (the first with 300 parcels) must already use the count the Hertz
# time of that parcel needs, from t_c = 2.868 (m*^2/(R* E*^2 v))^(1/5)
# (m* = m/2, R* = c^2/(2a), v = 2|U|, E* = E/(2(1 - nu^2)), the worst case
# of EllipsoidCollision::collisionTime) over collisionResolutionSteps; the
# step before uses fewer. A count taken without the injected parcels would
# rise one step late.
. "$(dirname "$0")/common.sh.inc"

copyCase ellipsoidPour "$work/case"
cd "$work/case" || exit 1
$PY makeParcels.py 300 > log.makeParcels 2>&1
$PY - <<'PYEOF'
import re
lines = open("constant/parcels").read().splitlines()
parcels = [l for l in lines if l.strip().startswith("{")]
rest = [l for l in lines if not l.strip().startswith("{")]
i = rest.index("(")
late = parcels[150:]
late[75] = re.sub(r"U \([^)]*\)", "U (0 0 -3)", late[75])
open("constant/parcels", "w").write("\n".join(rest[:i + 1] + parcels[:150] + rest[i + 1:]) + "\n")
open("constant/parcelsLate", "w").write("\n".join(rest[:i + 1] + late + rest[i + 1:]) + "\n")
PYEOF
regexEdit constant/cloudProperties \
    '#include(\s+)"parcels"\s*\}' \
    '#include\g<1>"parcels"\n        }\n        late\n        {\n            type            explicitParcels;\n            SOI             0.003;\n            #include        "parcelsLate"\n        }'
setEndTime 0.0036
setWriteInterval 1000
run blockMesh blockMesh
run solver chargedParticleFoam || fail "subCycleInjection.run (solver failed)"

$PY - <<'PYEOF'
import math, re
props = open("constant/cloudProperties").read()
def entry(key):
    return float(re.search(r"^\s*" + key + r"\s+([^;\s]+);", props, re.M).group(1))
E, nu, rho = entry("youngsModulus"), entry("poissonsRatio"), entry("rho0")
steps = entry("collisionResolutionSteps")
dt = float(re.search(r"^deltaT\s+([^;]+);", open("system/controlDict").read(), re.M).group(1))
late = open("constant/parcelsLate").read()
fast = [l for l in late.splitlines() if "U (0 0 -3)" in l][0]
a, b, c = sorted((float(x) for x in re.search(r"semiAxes \(([^)]*)\)", fast).group(1).split()), reverse=True)
m = rho*4/3*math.pi*a*b*c
Estar = E/(2*(1 - nu**2))
tc = 2.868*((m/2)**2/((c*c/a)/2*Estar**2*(2*3.0)))**0.2
need = max(1, math.ceil(dt/(tc/steps) - 1e-9))

blocks = re.split(r"^Time = ", open("log.solver").read(), flags=re.M)[1:]
def count(block):
    m = re.search(r"^\s*(\d+) move-collide subCycles", block, re.M)
    return int(m.group(1)) if m else 1
first = next(k for k, b in enumerate(blocks) if re.search(r"Current number of parcels\s*=\s*300", b))
n, before = count(blocks[first]), count(blocks[first - 1])
ok = n == need and before < need
print(f"{'PASS' if ok else 'FAIL'}: subCycleInjection.injectionStep (the step injecting the 3 m/s "
      f"parcel, t = {blocks[first].split()[0]} s: {n} sub-cycles, Hertz time {tc:.4g} s / {steps:g} "
      f"steps needs {need}; the step before {before})")
PYEOF
