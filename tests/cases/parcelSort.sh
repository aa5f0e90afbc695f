# Sorting the parcels by cell (solution/sortInterval) changes only the order
# of the sums. The ellipsoidPour tutorial (300 ellipsoids falling onto the
# floor and each other), sorted every 7 steps (sortMinParcels 0), against
# the same run never sorted: at 0.05 s (the first landings) the parcels'
# positions, velocities, orientations and angular momenta differ by no more
# than runs that differ from the unsorted one only in the order of the sums
# do, and by less than 1e-6 relative. Those controls inject the parcels in
# reverse order and in four seeded random orders; a granular bed amplifies
# their round-off to 1e-12..1e-9, and one control alone is a coin flip (the
# sorted run's divergence is a draw of the same kind). The bound is the
# largest control's divergence times the controls' own spread
# (max/min): a draw like the controls exceeds it with about 1.5 %
# probability (5 controls, log-normal), a change that is more than a
# reordering by orders of magnitude. The sorted run writes its parcels in
# the order of their cells, the unsorted one in injection order (not cell
# order). Stopped at 0.05 s and restarted, the sorted run continues exactly
# to 0.1 s (sorted on time indices and write steps: a restart reads the
# order the uninterrupted run has). On 4 processors (slabs in z: the top
# one never holds a parcel, the parcels fall across the others'
# boundaries), each sorting its own, the run matches the serial sorted one
# at 0.05 s within the same bound.
. "$(dirname "$0")/common.sh.inc"

# prepare <case> <sortInterval> [reverse | shuffle<seed>]
prepare()
{
    copyCase ellipsoidPour "$1"
    cd "$1" || exit 1
    $PY makeParcels.py 300 > log.makeParcels 2>&1
    if [ -n "${3:-}" ]
    then
        # the injection file's parcels in another order; origId is the
        # injection index, order.txt maps it back to the file's line
        $PY - "$3" <<'PYEOF'
import sys
import numpy as np
lines = open("constant/parcels").read().splitlines()
parcels = [l for l in lines if l.strip().startswith("{")]
rest = [l for l in lines if not l.strip().startswith("{")]
how = sys.argv[1]
if how == "reverse":
    order = np.arange(len(parcels))[::-1]
else:
    order = np.random.default_rng(int(how[len("shuffle"):])).permutation(len(parcels))
np.savetxt("order.txt", order, fmt="%d")
i = rest.index("(")
open("constant/parcels", "w").write(
    "\n".join(rest[:i + 1] + [parcels[k] for k in order] + rest[i + 1:]) + "\n")
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

controls="reversed shuffled1 shuffled2 shuffled3 shuffled4"
for control in $controls
do
    case $control in
        reversed) how=reverse ;;
        *) how=shuffle${control#shuffled} ;;
    esac
    prepare "$work/$control" 0 $how
    setEndTime 0.05
    run solver chargedParticleFoam || fail "parcelSort.$control (solver failed)"
done

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

$PY - "$work" "$top/etc/python" "$controls" <<'PYEOF'
import os, re, sys
import numpy as np
work = sys.argv[1]
sys.path.insert(0, sys.argv[2])
from foamLagrangian import read_field, read_positions

def load(case, t):
    # parcels by injection-file line: origId counts the injected parcels,
    # order.txt (the controls) gives the line each injection came from
    d = f"{work}/{case}/{t}/lagrangian/cloud"
    ids = read_field(f"{d}/origId").astype(int)
    if os.path.exists(f"{work}/{case}/order.txt"):
        ids = np.loadtxt(f"{work}/{case}/order.txt", dtype=int)[ids]
    order = np.argsort(ids)
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

u, s = load("unsorted", 0.05), load("sorted", 0.05)
controls = sys.argv[3].split()
dc = [differences(u, load(c, 0.05)) for c in controls]
ds = differences(u, s)
# round-off scale: the largest control times the controls' spread
# (divergences below 1e-14 count as 1e-14)
bound = {}
for k in ds:
    d = [max(x[k], 1e-14) for x in dc]
    bound[k] = max(d)*max(d)/min(d)
for k in ds:
    ok = ds[k] <= bound[k] and ds[k] < 1e-6
    print(f"{'PASS' if ok else 'FAIL'}: parcelSort.sameRun.{k} (sorted against unsorted "
          f"{ds[k]:.2e}; {len(dc)} reordered injections against unsorted "
          f"{min(x[k] for x in dc):.2e} to {max(x[k] for x in dc):.2e}, bound {bound[k]:.2e}; relative)")

# origId counts per processor in parallel: parcels matched by position
p = load("parallel", 0.05)
near = np.argmin(((s["positions"][:, None, :] - p["positions"][None, :, :])**2).sum(axis=2), axis=1)
oneToOne = len(set(near)) == len(near)
p = {k: v[near] for k, v in p.items()}
dp = differences(s, p)
emptyTop = not os.path.exists(f"{work}/parallel/processor3/0.05/lagrangian/cloud/origId")
ok = all(dp[k] <= bound[k] and dp[k] < 1e-6 for k in dp) and len(p["positions"]) == 300 \
    and oneToOne and emptyTop
print(f"{'PASS' if ok else 'FAIL'}: parcelSort.parallel (4 processors, processor3 empty: {emptyTop}; "
      f"{len(p['positions'])} parcels against the serial sorted run: "
      + ", ".join(f"{k} {dp[k]:.1e} (bound {bound[k]:.1e})" for k in dp) + ")")

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
