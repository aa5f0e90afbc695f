# electrostaticsModel imageCoulomb (cutoff pairs + grounded-wall image
# charges, Rasera 2022 section 2.4) in the cloud: 50 charges of both signs
# in a 1 m box with one grounded 'walls' patch (6 planes).
#  - the written forces fE equal an independent numpy truncated image sum
#    (each axis: no reflection, low or high wall; compositions of the
#    perpendicular walls) for rCut = 0.1, 0.3, 1 m in serial, and for
#    rCut = 0.3 m on 2 processors (simple 2 1 1); the box made a duct
#    cyclic in x (images in the 4 walls, pairs and images through the
#    cyclic patch) serially and on a ring of 2 processors;
#  - the error of the truncated image sum against the exact grounded box
#    (tests/tools/groundedBox.py, Ewald sum of the image lattice) is printed
#    for the three cutoffs, with groundedBox.py's own self-test;
#  - a curved wall patch and a patch name that matches nothing stop the
#    run with a FatalIOError naming the entry and the patch.
. "$(dirname "$0")/common.sh.inc"

$PY "$tools/groundedBox.py" --selftest

copyCase twoChargedSpheres "$work/r0.3"
cd "$work/r0.3" || exit 1
$PY "$tools/unitBoxMesh.py" wall
$PY - <<'PYEOF'
import re
import numpy as np
rng = np.random.default_rng(11)
# charges within 0.02 m of the walls too (and near edges and corners)
x = 0.02 + 0.96*rng.random((50, 3))
x[:6] = np.where(rng.random((6, 3)) < 0.5, 0.03, 0.97)*np.ones((6, 3))
x[:6] += 0.01*(rng.random((6, 3)) - 0.5)
q = 1e-9*(2*rng.random(50) - 1)
np.savetxt("charges.txt", np.column_stack([x, q]))
p = "constant/cloudProperties"
s = open(p).read()
parcels = "\n".join("                { position (%.12g %.12g %.12g); d 1e-3; rho 1000; q %.12g; }" % (r[0], r[1], r[2], c) for r, c in zip(x, q))
s = re.sub(r"parcels\s*\(.*?\n\s*\);", "parcels\n            (\n" + parcels + "\n            );", s, flags=re.S)
s = re.sub(r"electrostaticsModel\s+\w+;", "electrostaticsModel imageCoulomb;\n    imageCoulombCoeffs { rCut 0.3; patches (walls); }", s)
open(p, "w").write(s)
p = "system/controlDict"
s = open(p).read()
s = re.sub(r"^endTime .*?;", "endTime 1e-6;", s, flags=re.M)
s = re.sub(r"^deltaT .*?;", "deltaT 1e-6;", s, flags=re.M)
s = re.sub(r"^writeInterval .*?;", "writeInterval 1;", s, flags=re.M)
open(p, "w").write(s)
PYEOF
run blockMesh blockMesh || fail "imageCloud.mesh (blockMesh failed)"
for c in r0.1 r1 parallel duct ductRing
do
    rm -rf "$work/$c"
    cp -r "$work/r0.3" "$work/$c"
done
# The duct cyclic in x (walls y and z): images in the four walls, pairs
# and images through the cyclic patch; serially and on a ring of 2
for c in duct ductRing
do
    $PY "$tools/unitBoxMesh.py" xCyclic "$work/$c"
    (cd "$work/$c" && rm -rf constant/polyMesh && run blockMesh blockMesh) \
        || fail "imageCloud.$c (blockMesh failed)"
done
sed -i 's/rCut 0.3;/rCut 0.1;/' "$work/r0.1/constant/cloudProperties"
sed -i 's/rCut 0.3;/rCut 1;/' "$work/r1/constant/cloudProperties"
# decomposition: simple (2 1 1) as in the tutorial (scotch is not built here)
for c in r0.1 r0.3 r1 duct
do
    cd "$work/$c" || exit 1
    run solver chargedParticleFoam \
        || fail "imageCloud.$c (solver failed, see $work/$c/log.solver)"
done
cd "$work/parallel" || exit 1
run decomposePar decomposePar \
 && run solver mpirun -np 2 chargedParticleFoam -parallel \
 && run reconstructPar reconstructPar -latestTime \
    || fail "imageCloud.parallel (run failed, see $work/parallel)"
cd "$work/ductRing" || exit 1
run decomposePar decomposePar \
 && run solver mpirun -np 2 chargedParticleFoam -parallel \
 && run reconstructPar reconstructPar -latestTime \
    || fail "imageCloud.ductRing (run failed, see $work/ductRing)"
grep -q "6 wall planes" "$work/r0.3/log.solver" \
    && pass "imageCloud.planes (patch walls split into 6 planes)" \
    || fail "imageCloud.planes (no '6 wall planes' in $work/r0.3/log.solver)"

$PY - "$work" "$top/etc/python" "$tools" <<'PYEOF'
import os, sys
import numpy as np
work = sys.argv[1]
sys.path.insert(0, sys.argv[2])
sys.path.insert(0, sys.argv[3])
from foamLagrangian import read_field, read_positions
import groundedBox
k = 1/(4*np.pi*8.8541878128e-12)
d = np.loadtxt(work + "/r0.3/charges.txt")
x0, q0 = d[:, :3], d[:, 3]
N = len(x0)

def truncated(rc, x0, periodicX=False):
    # Images axis by axis: 0 none, 1 low wall (-x), 2 high wall (2 - x) if
    # that wall is closer than rc; charge (-1)^(reflections); every source
    # (real or image) counted if closer than rc to the target, self
    # excluded. periodicX: no walls in x, the copies at x -+ 1 instead
    F = np.zeros_like(x0)
    for s in range(N):
        for m in np.ndindex(3, 3, 3):
            y, qs, ok = x0[s].copy(), q0[s], True
            for c in range(3):
                if m[c] == 0:
                    continue
                if c == 0 and periodicX:
                    y[c] += -1 if m[c] == 1 else 1
                    continue
                dist = x0[s, c] if m[c] == 1 else 1 - x0[s, c]
                ok &= dist < rc
                y[c] = -x0[s, c] if m[c] == 1 else 2 - x0[s, c]
                qs = -qs
            if not ok:
                continue
            r = x0 - y
            rr = np.linalg.norm(r, axis=1)
            msk = (rr < rc) & (rr > 0)
            F[msk] += k*(q0[msk]*qs/rr[msk]**3)[:, None]*r[msk]
    return F

def load(case):
    t = max((e for e in os.listdir(case) if e.replace(".", "").replace("e-", "").isdigit() and e != "0"), key=float)
    p = f"{case}/{t}/lagrangian/cloud"
    x = read_positions(p + "/positions")
    f = read_field(p + "/fE").reshape(-1, 3)
    idx = [int(np.argmin(np.linalg.norm(x0 - xi, axis=1))) for xi in x]
    F = np.full_like(x0, np.nan)
    X = x0.copy()
    F[idx] = f
    X[idx] = x
    return len(set(idx)) == N, F, X

summary = []
# The written fE is evaluated at the written positions (after the step's
# move, ~1e-11 m): the references use those
for name, rc in (("r0.1", 0.1), ("r0.3", 0.3), ("r1", 1.0), ("parallel", 0.3),
                 ("duct", 0.3), ("ductRing", 0.3)):
    try:
        ok, F, X = load(f"{work}/{name}")
    except Exception as e:
        print(f"FAIL: imageCloud.{name} (cannot read the cloud: {e})")
        continue
    duct = name.startswith("duct")
    R = truncated(rc, X, duct)
    err = np.abs(F - R).max()/np.abs(R).max() if ok else np.inf
    what = "the duct cyclic in x: images in 4 walls, copies at x -+ 1 m, " if duct else ""
    print(f"{'PASS' if ok and err < 1e-9 else 'FAIL'}: imageCloud.{name} "
          f"(fE vs a numpy truncated image sum, {what}rCut {rc} m: max rel. difference {err:.1e}, tol 1e-9)")
    if name in ("parallel", "duct", "ductRing"):
        continue
    exact = q0[:, None]*groundedBox.field(X, q0, 1.0)
    rel = np.linalg.norm(F - exact, axis=1)/np.linalg.norm(exact, axis=1)
    relS = np.linalg.norm(F - exact, axis=1)/np.sqrt(np.mean(np.sum(exact**2, axis=1)))
    # the same cutoff without any image (cutoffCoulomb), for context
    r = X[:, None, :] - X[None, :, :]
    rr = np.linalg.norm(r, axis=2) + np.eye(N)
    w = np.where((rr < rc) & ~np.eye(N, dtype=bool), q0[None, :]/rr**3, 0)
    F0 = k*q0[:, None]*np.einsum("ij,ijk->ik", w, r)
    rel0 = np.linalg.norm(F0 - exact, axis=1)/np.sqrt(np.mean(np.sum(exact**2, axis=1)))
    summary.append((rc, np.sqrt(np.mean(relS**2))))
    print(f"INFO: imageCloud.exactError.{name} (vs exact grounded box, groundedBox.py; "
          f"rCut {rc} box lengths, {N} charges: per-charge |dF|/|F| rms {np.sqrt(np.mean(rel**2)):.3f} "
          f"max {rel.max():.3f}; |dF|/rms|F| rms {np.sqrt(np.mean(relS**2)):.3f} max {relS.max():.3f}; "
          f"no images (cutoffCoulomb): |dF|/rms|F| rms {np.sqrt(np.mean(rel0**2)):.3f} max {rel0.max():.3f})")
e = [v for _, v in sorted(summary)]
good = len(e) == 3 and e[0] > e[1] > e[2]
print(f"{'PASS' if good else 'FAIL'}: imageCloud.exactError (rms |dF|/rms|F| vs the exact grounded box falls with rCut: "
      + ", ".join(f"{v:.3f}" for v in e) + " for rCut 0.1, 0.3, 1)")
PYEOF

# Bad input: a curved wall patch; a patch name that matches nothing
cd "$work" || exit 1
rm -rf curved missing
cp -r r0.3 curved
cp -r r0.3 missing
rm -rf curved/constant/polyMesh curved/processor* missing/processor*
$PY - "$work/curved" <<'PYEOF'
import re, sys
p = sys.argv[1] + "/system/blockMeshDict"
s = open(p).read()
s = re.sub(r"edges\s*\(.*?\);", "", s, flags=re.S)
s = s.replace("boundary", "edges\n(\n    arc 4 5 (0.5 0 1.1)\n    arc 7 6 (0.5 1 1.1)\n);\n\nboundary", 1)
s = re.sub(r"walls \{ type wall; faces \(\(0 4 7 3\) \(1 2 6 5\) \(0 1 5 4\) \(3 7 6 2\) \(0 3 2 1\) \(4 5 6 7\)\); \}",
           "walls { type wall; faces ((0 4 7 3) (1 2 6 5) (0 1 5 4) (3 7 6 2) (0 3 2 1)); }\n    top { type wall; faces ((4 5 6 7)); }", s)
open(p, "w").write(s)
p = sys.argv[1] + "/constant/cloudProperties"
s = open(p).read()
open(p, "w").write(s.replace("patches (walls);", 'patches (walls "t.*");'))
PYEOF
sed -i 's/patches (walls);/patches (walls floor);/' missing/constant/cloudProperties
# expectBad <name> <message regex>
expectBad()
{
    (
        cd "$work/$1" || exit 1
        chargedParticleFoam > log.solver 2>&1
        expectFatalIO "imageCloud.bad.$1" "$work/$1/log.solver" $? "$2"
    )
}
(cd curved && run blockMesh blockMesh) || fail "imageCloud.bad.curved (blockMesh failed)"
expectBad curved "patches in .*imageCoulombCoeffs: patch top is not planar"
expectBad missing "patches in .*imageCoulombCoeffs: floor matches no"
