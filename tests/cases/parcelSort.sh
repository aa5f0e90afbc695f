# Sorting the parcels by cell (solution/sortInterval) changes only the order
# of the sums. The ellipsoidPour tutorial (300 ellipsoids falling onto the
# floor and each other), sorted every 7 steps (sortMinParcels 0), against
# the same run never sorted: at 0.05 s (the first landings) the parcels'
# positions, velocities, orientations and angular momenta differ by no more
# than those of a control run that only injects the parcels in reverse
# order (also a change of the sums' order; a granular bed amplifies
# round-off, so the control sets the scale), and by less than 1e-6
# relative. The sorted run writes its parcels in the order of their cells,
# the unsorted one in injection order (not cell order). Stopped at 0.05 s
# and restarted, the sorted run continues exactly to 0.1 s (sorted on time
# indices and write steps: a restart reads the order the uninterrupted run
# has). On 4 processors (slabs in z: the top one never holds a parcel, the
# parcels fall across the others' boundaries), each sorting its own, the
# run matches the serial sorted one at 0.05 s within the control.
. "$(dirname "$0")/common.sh.inc"

# prepare <case> <sortInterval> [reverse]
prepare()
{
    copyCase ellipsoidPour "$1"
    cd "$1" || exit 1
    $PY makeParcels.py 300 > log.makeParcels 2>&1
    if [ "${3:-}" = reverse ]
    then
        $PY - <<'PYEOF'
lines = open("constant/parcels").read().splitlines()
parcels = [l for l in lines if l.strip().startswith("{")]
rest = [l for l in lines if not l.strip().startswith("{")]
i = rest.index("(")
open("constant/parcels", "w").write("\n".join(rest[:i + 1] + parcels[::-1] + rest[i + 1:]) + "\n")
PYEOF
    fi
    setEndTime 0.1
    setWriteInterval 500
    run blockMesh blockMesh
    regexEdit constant/cloudProperties \
        "maxCo(\s+)0.3;" "maxCo\g<1>0.3;\n    sortInterval $2;\n    sortMinParcels 0;"
}

prepare "$work/unsorted" 0
run solver chargedParticleFoam || fail "parcelSort.unsortedRun (solver failed)"

prepare "$work/reversed" 0 reverse
run solver chargedParticleFoam || fail "parcelSort.reversedRun (solver failed)"

prepare "$work/sorted" 7
run solver chargedParticleFoam || fail "parcelSort.sortedRun (solver failed)"

prepare "$work/restarted" 7
setEndTime 0.05
run solver1 chargedParticleFoam || fail "parcelSort.firstHalf (solver failed)"
setEndTime 0.1
run solver2 chargedParticleFoam || fail "parcelSort.secondHalf (solver failed)"

prepare "$work/parallel" 7
setEndTime 0.05
setDecomposition 4 "1 1 4"
run decomposePar decomposePar || fail "parcelSort.parallel (decomposePar failed)"
run solver mpirun -np 4 chargedParticleFoam -parallel \
    || fail "parcelSort.parallel (mpirun failed)"
run reconstructPar reconstructPar -latestTime \
    || fail "parcelSort.parallel (reconstructPar failed)"

$PY - "$work" "$top/etc/python" <<'PYEOF'
import re, sys
import numpy as np
work = sys.argv[1]
sys.path.insert(0, sys.argv[2])
from foamLagrangian import read_field, read_positions

def load(case, t, reversed=False):
    # parcels by injection-file line (origId counts the injected parcels)
    d = f"{work}/{case}/{t}/lagrangian/cloud"
    ids = read_field(f"{d}/origId")
    order = np.argsort(len(ids) - 1 - ids if reversed else ids)
    x = read_positions(f"{d}/positions")
    fields = {"positions": x, "velocities": read_field(f"{d}/U").reshape(-1, 3),
              "angularMomenta": read_field(f"{d}/angularMomentum").reshape(-1, 3)}
    # orientation (eta, eps) of each parcel as a quaternion, sign fixed
    q = np.column_stack([read_field(f"{d}/orientationEta"),
                         read_field(f"{d}/orientationEps").reshape(-1, 3)])
    fields["orientations"] = q*np.sign(q[:, :1] + (q[:, :1] == 0))
    return {k: v[order] for k, v in fields.items()}

def differences(a, b):
    return {k: np.abs(a[k] - b[k]).max()/np.abs(a[k]).max() for k in a}

u, s, r = load("unsorted", 0.05), load("sorted", 0.05), load("reversed", 0.05, True)
ds, dr = differences(u, s), differences(u, r)
for k in ds:
    ok = ds[k] <= max(dr[k], 1e-14) and ds[k] < 1e-6
    print(f"{'PASS' if ok else 'FAIL'}: parcelSort.sameRun.{k} (sorted against unsorted "
          f"{ds[k]:.2e}, reversed injection against unsorted {dr[k]:.2e}, relative)")

import os
# origId counts per processor in parallel: parcels matched by position
p = load("parallel", 0.05)
near = np.argmin(((s["positions"][:, None, :] - p["positions"][None, :, :])**2).sum(axis=2), axis=1)
oneToOne = len(set(near)) == len(near)
p = {k: v[near] for k, v in p.items()}
dp = differences(s, p)
emptyTop = not os.path.exists(f"{work}/parallel/processor3/0.05/lagrangian/cloud/origId")
ok = all(dp[k] <= max(dr[k], 1e-14) and dp[k] < 1e-6 for k in dp) and len(p["positions"]) == 300 \
    and oneToOne and emptyTop
print(f"{'PASS' if ok else 'FAIL'}: parcelSort.parallel (4 processors, processor3 empty: {emptyTop}; "
      f"{len(p['positions'])} parcels against the serial sorted run: "
      + ", ".join(f"{k} {dp[k]:.1e} (control {dr[k]:.1e})" for k in dp) + ")")

def cells(case):
    text = open(f"{work}/{case}/0.1/lagrangian/cloud/positions").read()
    return [int(c) for c in re.findall(r"^\([^()]*\)\s+(-?\d+)", text, re.M)]
c, cu = cells("sorted"), cells("unsorted")
ok = len(c) == 300 and all(a <= b for a, b in zip(c, c[1:]))
print(f"{'PASS' if ok else 'FAIL'}: parcelSort.cellOrder (sorted run: {len(c)} parcels written in cell order)")
ok = len(cu) == 300 and any(a > b for a, b in zip(cu, cu[1:]))
print(f"{'PASS' if ok else 'FAIL'}: parcelSort.unsortedOrder (unsorted run: {len(cu)} parcels, not in cell order)")
PYEOF

$PY "$tools/compareClouds.py" "$work/sorted/0.1" "$work/restarted/0.1" \
    --tol 1e-12 --rotation --name parcelSort.restart
