# BEM clusters in the cloud (nearField bem, Ruan 2022 Section 2.1 in
# dynamics): forces and energies of close dielectric sphere pairs against
# the exact two-sphere solution (radii 1:1, 1:2, 1:5, epsilonR 2-1000, like
# and opposite charges, gaps 0.05-0.5 of the smaller radius), the far
# field's own pair taken out again (directCoulomb = none for a lone pair),
# 2 processors = serial, and two spheres released at a small gap against
# the trajectory integrated from the exact force, solving every step and
# every 5th (the bound charge carried in between); prolates near a cluster
# (multipoles both ways) against all-particle BEM.
. "$(dirname "$0")/common.sh.inc"

staticCase()    # staticCase <dir> <bemClusterStatic.py write options>
{
    local dir="$1"
    shift
    copyCase twoChargedSpheres "$dir"
    (
        cd "$dir" || exit 1
        sed -i 's/^scale   1e-3;/scale   5e-2;/' system/blockMeshDict
        $PY "$tools/bemClusterStatic.py" write . "$@"
        setEndTime 1e-6
        setWriteInterval 1
        run blockMesh blockMesh
    )
}

for ratio in 1 2 5
do
    staticCase "$work/static$ratio" --ratio $ratio
    (
        cd "$work/static$ratio" || exit 1
        run solver chargedParticleFoam || fail "bemClusters.exactTwoSpheres$ratio (solver failed)"
        $PY "$tools/bemClusterStatic.py" compare . --ratio $ratio | tee table.md | grep -E '^(PASS|FAIL)'
    )
done
check bemClusters.log "(24 clusters of 2 in the log)" \
    grep -q "BEM clusters  *= 24 (48 parcels, largest 2; 24 solved)" "$work/static2/log.solver"
staticCase "$work/parallel"

# The parallel run: parcels on both processors, clusters across them
(
    cd "$work/parallel" || exit 1
    run decomposePar decomposePar || fail "bemClusters.parallel (decomposePar)"
    run solver mpirun -np 2 chargedParticleFoam -parallel || fail "bemClusters.parallel (mpirun)"
    run reconstructPar reconstructPar -latestTime || fail "bemClusters.parallel (reconstructPar)"
    # Each processor solves its share of the clusters; all keep every
    # member's bound charge (the master writes it for a restart)
    grep -q "BEM clusters  *= 24 (48 parcels, largest 2; 24 solved)" log.solver \
        && pass "bemClusters.parallel.log (24 clusters solved once in all)" \
        || fail "bemClusters.parallel.log (the log does not show 24 clusters solved)"
    $PY - <<'PYEOF'
import re
props = open("1e-06/uniform/lagrangian/cloud/cloudOutputProperties").read()
m = re.search(r"bemNearField\s*\{.*?\bids\s+(?:List<label>\s*)?(\d+)", props, re.S)
n = int(m.group(1))//2 if m else 0
print("%s: bemClusters.parallel.state (bound charge of %d of 48 members written by the master)"
      % ("PASS" if n == 48 else "FAIL", n))
PYEOF
)

$PY - "$work" "$top" <<'PYEOF'
import os, sys
import numpy as np
work, top = sys.argv[1], sys.argv[2]
sys.path.insert(0, top + "/etc/python")
from foamLagrangian import read_field, read_positions

def load(case):
    t = max((d for d in os.listdir(case) if d.replace(".", "").replace("e-", "").isdigit() and float(d) > 0), key=float)
    c = f"{case}/{t}/lagrangian/cloud"
    return (read_positions(c + "/positions"), read_field(c + "/fE").reshape(-1, 3),
            read_field(c + "/tE").reshape(-1, 3))

xs, fs, ts = load(work + "/static2")
xp, fp, tp = load(work + "/parallel")
# match by position (the processors' meshes move the parcels by round-off)
m = np.array([int(np.argmin(np.linalg.norm(xp - x, axis=1))) for x in xs])
ok = len(xs) == len(xp) == 48 and sorted(m) == list(range(48))
fp, tp = fp[m], tp[m]
eF = np.abs(fs - fp).max()/np.abs(fs).max()
eT = np.abs(ts - tp).max()/np.abs(fs).max()/1e-4
print("%s: bemClusters.parallel (2 processors vs serial, 48 parcels: force difference %.1e,"
      " torque %.1e (of |F| x 100 um); tol 1e-10)" % ("PASS" if ok and eF < 1e-10 and eT < 1e-10 else "FAIL", eF, eT))
PYEOF

# A lone pair under directCoulomb: the far field's point-charge pair is
# taken out of the cluster's external field, so the forces equal those
# without a far field; under cutoffCoulomb with rCut below the pair's
# distance the far field has no pair, and nothing is taken out
for far in none directCoulomb cutoffCoulomb
do
    staticCase "$work/pair-$far" --far $far --pairs 1
    (cd "$work/pair-$far" && run solver chargedParticleFoam) || fail "bemClusters.farFieldPair ($far failed)"
done
$PY - "$work" "$top" <<'PYEOF'
import sys
import numpy as np
work, top = sys.argv[1], sys.argv[2]
sys.path.insert(0, top + "/etc/python")
from foamLagrangian import read_field
f = [read_field(f"{work}/pair-{m}/1e-06/lagrangian/cloud/fE").reshape(-1, 3)
     for m in ("none", "directCoulomb", "cutoffCoulomb")]
e = np.abs(f[0] - f[1]).max()/np.abs(f[0]).max()
print("%s: bemClusters.farFieldPair (a lone pair: directCoulomb + bem vs bem alone:"
      " force difference %.1e of the force, tol 1e-12)" % ("PASS" if e < 1e-12 else "FAIL", e))
e = np.abs(f[0] - f[2]).max()/np.abs(f[0]).max()
print("%s: bemClusters.cutoffPair (a lone pair beyond rCut: cutoffCoulomb + bem vs bem alone:"
      " force difference %.1e of the force, tol 1e-12)" % ("PASS" if e < 1e-12 else "FAIL", e))
PYEOF

# What clusters and the parcels near them see of each other: a third
# prolate 1.2-3 b from a cluster of two, its multipoles at the members'
# patches and the reaction, against all-particle BEM (and the far field's
# point charges alone, neighbours pointCharges)
neighbourCase()     # neighbourCase <dir> <variant>: bemNeighbours.py's scene
{
    copyCase twoChargedSpheres "$1"
    (
        cd "$1" || exit 1
        sed -i 's/^scale   1e-3;/scale   5e-2;/' system/blockMeshDict
        $PY "$tools/bemNeighbours.py" write . "$2"
        setEndTime 1e-6
        run blockMesh blockMesh
    )
}
mkdir -p "$work/neighbours"
for v in multipoles pointCharges allBem
do
    neighbourCase "$work/neighbours/$v" $v
    (cd "$work/neighbours/$v" && run solver chargedParticleFoam) \
        || fail "bemClusters.neighbours ($v failed)"
done
$PY "$tools/bemNeighbours.py" compare "$work/neighbours" | tee "$work/neighbours/table.md" \
    | grep -E '^(PASS|FAIL)'
# The same on 2 processors: the reactions summed, the members' multipoles
# shared (the second step uses them)
neighbourCase "$work/neighbours/parallel" multipoles
(
    cd "$work/neighbours/parallel" || exit 1
    setEndTime 2e-6
    run decomposePar decomposePar
    run solver mpirun -np 2 chargedParticleFoam -parallel
) || fail "bemClusters.neighbours.parallel (failed)"
(
    cd "$work/neighbours/multipoles" || exit 1
    setEndTime 2e-6
    run solver2 chargedParticleFoam
) || fail "bemClusters.neighbours.parallel (serial run failed)"
# A restart after the first step (the members' multipoles in the state) =
# the uninterrupted run
neighbourCase "$work/neighbours/restart" multipoles
(
    cd "$work/neighbours/restart" || exit 1
    setWriteInterval 1
    run solver chargedParticleFoam
    grep -q "quadrupoles" 1e-06/uniform/lagrangian/cloud/cloudOutputProperties \
        || fail "bemClusters.neighbours.restart (no multipoles in the state)"
    setEndTime 2e-6
    run solver2 chargedParticleFoam
) || fail "bemClusters.neighbours.restart (failed)"
# The same restart on 2 processors (each member's state kept by the
# processor that solved it, the state's reader keeping its own parcels')
# = the uninterrupted 2-processor run
neighbourCase "$work/neighbours/parallelRestart" multipoles
(
    cd "$work/neighbours/parallelRestart" || exit 1
    setWriteInterval 1
    run decomposePar decomposePar
    run solver mpirun -np 2 chargedParticleFoam -parallel
    setEndTime 2e-6
    run solver2 mpirun -np 2 chargedParticleFoam -parallel
) || fail "bemClusters.neighbours.parallelRestart (failed)"
$PY - "$work/neighbours" "$top" <<'PYEOF'
import sys
import numpy as np
top = sys.argv[2]
sys.path.insert(0, top + "/etc/python")
from foamLagrangian import read_particle_history
def last(case):
    h, c = read_particle_history(case)
    h = h[h[:, c["time"]] == h[:, c["time"]].max()]
    return (h[:, [c[a] for a in "xyz"]], h[:, [c["fE" + a] for a in "xyz"]],
            h[:, [c["tE" + a] for a in "xyz"]], h[0, c["time"]])
xs, fs, ts, t1 = last(sys.argv[1] + "/multipoles")
xp, fp, tp, t2 = last(sys.argv[1] + "/parallel")
# match by position (the ids differ: parcels are injected by the processor
# that holds them)
m = np.array([int(np.argmin(np.linalg.norm(xp - x, axis=1))) for x in xs])
fp, tp = fp[m], tp[m]
eF = np.abs(fs - fp).max()/np.abs(fs).max()
eT = np.abs(ts - tp).max()/np.abs(ts).max()
ok = (abs(t1 - 2e-6) < 1e-12 and abs(t2 - 2e-6) < 1e-12 and sorted(m) == list(range(len(xs)))
      and eF < 1e-10 and eT < 1e-10)
print("%s: bemClusters.neighbours.parallel (second step, 2 processors vs serial: force difference"
      " %.1e, torque %.1e; tol 1e-10)" % ("PASS" if ok else "FAIL", eF, eT))
xr, fr, tr, t3 = last(sys.argv[1] + "/restart")
eF = np.abs(fs - fr).max()/np.abs(fs).max()
eT = np.abs(ts - tr).max()/np.abs(ts).max()
ok = abs(t3 - 2e-6) < 1e-12 and np.abs(xs - xr).max() < 1e-12 and eF < 1e-10 and eT < 1e-10
print("%s: bemClusters.neighbours.restart (second step after a restart vs uninterrupted: force"
      " difference %.1e, torque %.1e; tol 1e-10)" % ("PASS" if ok else "FAIL", eF, eT))
xr, fr, tr, t4 = last(sys.argv[1] + "/parallelRestart")
# fp, tp are in the serial run's order (matched above)
m = np.array([int(np.argmin(np.linalg.norm(xr - x, axis=1))) for x in xs])
xr, fr, tr = xr[m], fr[m], tr[m]
eF = np.abs(fp - fr).max()/np.abs(fp).max()
eT = np.abs(tp - tr).max()/np.abs(tp).max()
ok = (abs(t4 - 2e-6) < 1e-12 and sorted(m) == list(range(len(xs))) and np.abs(xs - xr).max() < 1e-12
      and eF < 1e-10 and eT < 1e-10)
print("%s: bemClusters.neighbours.parallelRestart (second step on 2 processors after a restart vs"
      " uninterrupted: force difference %.1e, torque %.1e; tol 1e-10)" % ("PASS" if ok else "FAIL", eF, eT))
PYEOF

# The same scene with 8 more parcels far from every triad, solved every
# third step, serial and on 2 and 4 processors for 7 steps (every cluster
# across the plane x = 0): only the parcels in or near clusters take part
# (24 of 32, each processor marking its own from a halo, each cluster
# solved by the processor of its smallest-id member), the far ones keep
# their point charges and dipoles, the bound charge is carried between
# solves (kept by the processor that solved it, fetched by the next solver),
# and the runs agree
for np_ in 1 2 4
do
    neighbourCase "$work/neighbours/dilute$np_" dilute
    (
        cd "$work/neighbours/dilute$np_" || exit 1
        setEndTime 7e-6
        if [ "$np_" = 1 ]
        then
            run solver chargedParticleFoam
        else
            [ "$np_" = 4 ] && setDecomposition 4 "2 2 1"
            run decomposePar decomposePar && run solver mpirun -np $np_ chargedParticleFoam -parallel
        fi
    ) || fail "bemClusters.dilute$np_ (failed)"
    grep -Eq "BEM parcels in or near clusters = 24 of 32" "$work/neighbours/dilute$np_/log.solver" \
        && pass "bemClusters.dilute$np_.gathered (24 of 32 parcels gathered, in or near clusters)" \
        || fail "bemClusters.dilute$np_.gathered (the log does not show 24 of 32 parcels gathered)"
    grep -Eq "BEM clusters += 8 \(16 parcels, largest 2; 0 solved\)" "$work/neighbours/dilute$np_/log.solver" \
        && pass "bemClusters.dilute$np_.carried (steps without a solve: the bound charge carried)" \
        || fail "bemClusters.dilute$np_.carried (no step without a solve in the log)"
done
$PY - "$work/neighbours" "$top" <<'PYEOF'
import sys
import numpy as np
sys.path.insert(0, sys.argv[2] + "/etc/python")
from foamLagrangian import read_particle_history
def last(case):
    h, c = read_particle_history(case)
    h = h[h[:, c["time"]] == h[:, c["time"]].max()]
    return (h[:, [c[a] for a in "xyz"]], h[:, [c["fE" + a] for a in "xyz"]],
            h[:, [c["tE" + a] for a in "xyz"]], h[0, c["time"]])
xs, fs, ts, t1 = last(sys.argv[1] + "/dilute1")
for n in (2, 4):
    xp, fp, tp, t2 = last(sys.argv[1] + "/dilute%d" % n)
    m = np.array([int(np.argmin(np.linalg.norm(xp - x, axis=1))) for x in xs])
    fp, tp = fp[m], tp[m]
    eF = np.abs(fs - fp).max()/np.abs(fs).max()
    eT = np.abs(ts - tp).max()/np.abs(ts).max()
    ok = (len(xs) == len(xp) == 32 and abs(t1 - 7e-6) < 1e-12 and abs(t2 - 7e-6) < 1e-12
          and sorted(m) == list(range(32)) and eF < 1e-10 and eT < 1e-10)
    print("%s: bemClusters.dilute.parallel%d (seventh step, %d processors vs serial, 24 parcels in"
          " or near clusters and 8 far ones: force difference %.1e, torque %.1e; tol 1e-10)"
          % ("PASS" if ok else "FAIL", n, n, eF, eT))
PYEOF

# Two like-charged spheres (radii 50 and 100 um, epsilonR 10) released
# 0.3 a1 apart attract; their gap against the exact two-sphere force
# integrated (RK4) until 0.1 a1, and the total momentum
for interval in 1 5
do
copyCase dielectricSpheres "$work/attraction$interval"
(
    cd "$work/attraction$interval" || exit 1
    sed -i "s/type    inducedDipole;  \/\/ monopole + induced dipoles/type bem; solveInterval $interval;/" constant/cloudProperties
    sed -i -E "s/^deltaT .*/deltaT          1e-5;/" system/controlDict
    setEndTime 3.5e-3
    setWriteInterval 175
    run blockMesh blockMesh
    [ $interval = 5 ] && cp -r . ../restart5
    run solver chargedParticleFoam || fail "bemClusters.attraction$interval (solver failed)"
    $PY - $interval <<'PYEOF'
import math, sys
import numpy as np
sys.path.insert(0, ".")
import attraction as A
interval = int(sys.argv[1])
t, p1, p2, c = A.read_history(".")
d0 = 9e-5 + 7.5e-5
times = np.concatenate([[0.0], t])
dSim = np.concatenate([[d0], p2[:, c["x"]] - p1[:, c["x"]]])
gaps = np.geomspace(0.01*A.a1, 2*(d0 - A.a1 - A.a2), 200)
Fex = np.array([A.tds.force(A.q1, A.q2, A.a1, A.a2, A.a1 + A.a2 + g, A.k1, A.k2) for g in gaps])
dEx = A.integrate(lambda dd: np.interp(math.log(dd - A.a1 - A.a2), np.log(gaps), Fex), d0, times)
err = np.abs(dSim - dEx).max()/(d0 - dEx.min())
P = A.m1*p1[:, c["Ux"]] + A.m2*p2[:, c["Ux"]]
pErr = np.abs(P).max()/np.abs(A.m2*p2[:, c["Ux"]]).max()
gap = lambda dd: (dd - A.a1 - A.a2)/A.a1
# Every step solved: the 1 % of the BEM's force error; every 5th, the
# bound charge carried in between: 2 %
tol = 0.01 if interval == 1 else 0.02
ok = err < tol and pErr < 1e-10 and gap(dEx[-1]) < 0.12
print("%s: bemClusters.attraction%d (solveInterval %d: gap 0.3 -> %.4f a1 in 3.5 ms, exact force"
      " %.4f a1: max difference %.2e of the travel, tol %g; momentum %.1e of the largest, tol 1e-10)"
      % ("PASS" if ok else "FAIL", interval, interval, gap(dSim[-1]), gap(dEx[-1]), err, tol, pErr))
PYEOF
)
done

# A mesh cache of 1 MB frees every mesh the step did not use (the pair's
# grading follows the gap): the rebuilt meshes give the same run
copyCase dielectricSpheres "$work/attractionCache"
(
    cd "$work/attractionCache" || exit 1
    sed -i "s/type    inducedDipole;  \/\/ monopole + induced dipoles/type bem; meshCache 1;/" constant/cloudProperties
    sed -i -E "s/^deltaT .*/deltaT          1e-5;/" system/controlDict
    setEndTime 3.5e-3
    setWriteInterval 175
    run blockMesh blockMesh
    run solver chargedParticleFoam || fail "bemClusters.meshCache (solver failed)"
    $PY - <<'PYEOF'
import re, sys
import numpy as np
sys.path.insert(0, ".")
import attraction as A
t, p1, p2, c = A.read_history(".")
t0, q1, q2, c0 = A.read_history("../attraction1")
n = min(len(t), len(t0))
d = np.abs(p2[:n, c["x"]] - q2[:n, c0["x"]]).max()/A.a1
count = lambda log: [int(m) for m in re.findall(r"BEM clusters .*, (\d+) meshes", open(log).read())]
capped, uncapped = count("log.solver"), count("../attraction1/log.solver")
# At most the old and new meshes of the two spheres in a remeshing step
ok = n == len(t0) and d < 1e-12 and capped and max(capped) <= 4 < max(uncapped)
print("%s: bemClusters.meshCache (meshCache 1 MB: at most %d meshes kept (tol 4), %d in the uncapped"
      " run; the run differs by %.1e a1 in position, tol 1e-12)"
      % ("PASS" if ok else "FAIL", max(capped) if capped else -1, max(uncapped), d))
PYEOF
)

# Restart half-way (solveInterval 5, GMRES warm start: the bound charge is
# in the written time's output properties) = the uninterrupted run
(
    cd "$work/restart5" || exit 1
    setEndTime 1.75e-3
    run solver1 chargedParticleFoam || fail "bemClusters.restart (first half failed)"
    setEndTime 3.5e-3
    run solver2 chargedParticleFoam || fail "bemClusters.restart (second half failed)"
    check bemClusters.restartState "(bound charge in the output properties)" \
        grep -q "bemNearField" 0.00175/uniform/lagrangian/cloud/cloudOutputProperties
)
$PY "$tools/compareClouds.py" "$work/attraction5/0.0035" "$work/restart5/0.0035" \
    --tol 1e-12 --rotation --name bemClusters.restart

# A conservative two-body run (e = 1, no friction): two oppositely charged
# dielectric spheres (radius 100 um, epsilonR 10) released 0.5 R apart
# attract, collide elastically and bounce; the same with a third charged
# sphere near the pair (the energy of what cluster and neighbour see of
# each other). Kinetic + contact elastic +
# electrostatic energy (the log's books, the cluster's BEM energy Eq. 51
# included) against its change, relative to the largest change of the
# electrostatic energy: at the end of the run (after the bounce) and the
# largest on the way, both within 1e-3. The
# BEM force is the gradient of the books' energy only to the
# discretisation error, a reversible function of the gap; the energy's
# bound-charge part by reciprocity (bemSolver) keeps it to a few 1e-4
# with the default 1200 patches per parcel.
for bodies in 2 3
do
copyCase reducedStiffness "$work/energy$bodies"
(
    cd "$work/energy$bodies" || exit 1
    cp=constant/cloudProperties
    sed -i -E 's/^( +youngsModulus +)1e9;/\11e7;/; s/^( +e +)0\.7;/\11;/; s/^( +mu +)0\.3;/\10;/' $cp
    sed -i -E 's/^( +stiffnessRatio .*)$/\1\n    epsilonR        10;/' $cp
    sed -i -E 's/^( +electrostaticsModel directCoulomb;)$/\1\n    directCoulombCoeffs { nearField { type bem; } }/' $cp
    if [ $bodies = 3 ]
    then
        # A third charged sphere 1.5 R from both (outside the cluster,
        # within rNear: multipoles both ways), in a taller box
        sed -i -E 's|^( +\{ position \(250e-6 0 0\); d 2e-4; q -8.0425e-13; \})$|\1\n                { position (125e-6 330e-6 0); d 2e-4; q 4e-13; }|' $cp
        sed -i -E 's/^( +\( *-?[0-9]+ +)(-?)300( +)(-?)300\)/\1\2600\3\4600)/' system/blockMeshDict
    fi
    sed -i -E 's/^deltaT .*/deltaT          5e-7;/' system/controlDict
    setEndTime 2e-3
    setWriteInterval 4000
    run blockMesh blockMesh
    run solver chargedParticleFoam || fail "bemClusters.energy$bodies (solver failed)"
    $PY - $bodies <<'PYEOF'
import re
import sys
import numpy as np
bodies = int(sys.argv[1])
log = open("log.solver").read()
f = lambda key: np.array([float(v) for v in re.findall(key + r"\s*=\s*(\S+)", log)])
U = f("Electrostatic energy")
parts = [f("Linear kinetic energy"), f(r"Rotational kinetic energy \(ellipsoids\)"),
         f("Contact elastic energy"), f("Contact dissipated energy")]
n = min(len(U), *(len(p) for p in parts))
E = U[:n] + sum(p[:n] for p in parts)
dU = np.abs(U[:n] - U[0]).max()
drift = np.abs(E - E[0]).max()/dU
final = abs(E[-1] - E[0])/dU
contacts = len(re.findall(r"particle-particle\s*=\s*1,", log))
bem = len(re.findall(r"BEM clusters\s*=\s*1 \(2 parcels", log))
parcels = re.findall(r"Current number of parcels\s*=\s*(\d+)", log)
ok = (final < 1e-3 and drift < 1e-3 and contacts > 0 and bem >= n - 1
      and parcels and int(parcels[-1]) == bodies)
print("%s: bemClusters.energy%s (e = 1, mu = 0, %d spheres epsilonR 10, two through a contact%s:"
      " total energy at the end %.2e of the electrostatic energy change %.3e J (tol 1e-3), largest"
      " %.2e (tol 1e-3); %d steps in contact, %d of %d with the pair in a BEM cluster)"
      % ("PASS" if ok else "FAIL", "" if bodies == 2 else "3", bodies,
         "" if bodies == 2 else ", the third near them", final, dU, drift, contacts, bem, n))
PYEOF
)
done
