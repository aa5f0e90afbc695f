# A sphere's orientation changes no force, torque or contact, so the cloud
# integrates it only with the solution entry sphereOrientation yes (or for
# a model that reads it, the BEM near field). Two spheres apart, spinning
# freely in vacuum (omega (0 0 3000) and (1000 2000 -500) rad/s), 2000 steps
# of 1e-7 s:
#   - sphereOrientation yes: each orientation is the exact rotation by
#     |omega| t about omega (q = (cos(|omega| t/2), sin(|omega| t/2)
#     omega/|omega|)), within 1e-10;
#   - by default: the orientations are the initial ones (identity), and
#     every other field is bit-identical to the integrating run;
#   - sphereOrientation maybe: a clear error naming the entry.
. "$(dirname "$0")/common.sh.inc"

copyCase headOnCollision "$work/base"
cd "$work/base" || exit 1
regexEdit constant/cloudProperties \
    '\{ position \(-0\.55e-3 0 0\); U \( 0\.5 0 0\);' \
    '{ position (-0.55e-3 0 0); U (0 0 0); omega (0 0 3000);' \
    '\{ position \( 0\.55e-3 0 0\); U \(-0\.5 0 0\);' \
    '{ position ( 0.55e-3 0 0); U (0 0 0); omega (1000 2000 -500);'
run blockMesh blockMesh
cd "$work" || exit 1

for variant in held integrated bad
do
    rm -rf "$variant"
    cp -r base "$variant"
done
(cd integrated && regexEdit constant/cloudProperties \
    'transient(\s+)yes;' 'transient\g<1>yes;\n    sphereOrientation yes;')
(cd bad && regexEdit constant/cloudProperties \
    'transient(\s+)yes;' 'transient\g<1>yes;\n    sphereOrientation maybe;')

for variant in held integrated
do
    (cd $variant && run solver chargedParticleFoam) \
        || fail "sphereOrientation.$variant (solver failed, see $variant/log.solver)"
done
(cd bad && run solver chargedParticleFoam)
check sphereOrientation.badEntry "(sphereOrientation maybe: the error names the entry)" \
    grep -q "sphereOrientation" bad/log.solver
check sphereOrientation.logLine "(the integrating run says so in its log)" \
    grep -q "Sphere orientations: integrated (sphereOrientation yes)" integrated/log.solver
check sphereOrientation.heldLog "(the default run does not integrate them)" \
    bash -c "! grep -q 'Sphere orientations: integrated' held/log.solver"

PYTHONPATH="$top/etc/python" $PY - <<'PYEOF'
import filecmp, os
import numpy as np
from foamLagrangian import read_field

t = 2000*1e-7
def last(case):
    times = [d for d in os.listdir(case) if d.replace(".", "").replace("e-", "").isdigit() and d != "0"]
    return os.path.join(case, max(times, key=float), "lagrangian", "cloud")

def orientations(d):
    eta = read_field(os.path.join(d, "orientationEta")).reshape(-1)
    eps = read_field(os.path.join(d, "orientationEps")).reshape(-1, 3)
    return np.column_stack([eta, eps])

omegas = np.array([[0, 0, 3000], [1000, 2000, -500]], float)
exact = []
for w in omegas:
    a = np.linalg.norm(w)*t
    exact.append(np.concatenate([[np.cos(a/2)], np.sin(a/2)*w/np.linalg.norm(w)]))
exact = np.array(exact)

q = orientations(last("integrated"))
q = q*np.sign(q[:, :1])
err = np.abs(q - exact).max()
print(f"{'PASS' if err <= 1e-10 else 'FAIL'}: sphereOrientation.exactRotation "
      f"(sphereOrientation yes: max |q - q_exact| {err:.2e} <= 1e-10; turns "
      f"{np.linalg.norm(omegas, axis=1)*t} rad)")

h = orientations(last("held"))
identity = np.tile([1.0, 0, 0, 0], (len(h), 1))
herr = np.abs(h - identity).max()
print(f"{'PASS' if herr == 0 else 'FAIL'}: sphereOrientation.held "
      f"(default: the initial orientations, max deviation {herr:.1e})")

dh, di = last("held"), last("integrated")
orientationFields = {"orientationEta", "orientationEps", "omegaBody", "shape"}
others = sorted(set(os.listdir(dh)) - orientationFields)
same = [f for f in others if filecmp.cmp(os.path.join(dh, f), os.path.join(di, f), shallow=False)]
differ = sorted(set(others) - set(same))
print(f"{'PASS' if not differ and len(same) > 5 else 'FAIL'}: sphereOrientation.otherFields "
      f"({len(same)} fields bit-identical between the two runs"
      f"{', differing: ' + ' '.join(differ) if differ else ''})")
PYEOF
