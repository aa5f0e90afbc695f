# Tri-periodic electrostatics in the cloud (electrostaticsModel periodic):
# 40 like-charged parcels in a 1 m box with cyclic patches in x, y and z.
# The written forces fE of the p3m (default) and ewald kernels equal an
# independent Ewald sum written here in numpy (tinfoil, neutralising
# background); the 2-, 4- and 8-processor runs (p3m: a halo and a mesh
# distributed in slabs, nothing gathered) give the serial forces. The
# p3m runs log the potentials' mean and variance (potentialInterval 1):
# those of the numpy Ewald potentials, in serial and in parallel.
. "$(dirname "$0")/common.sh.inc"

copyCase twoChargedSpheres "$work/p3m"
cd "$work/p3m" || exit 1
$PY "$tools/unitBoxMesh.py" cyclic
$PY - <<'PYEOF'
import re
import numpy as np
rng = np.random.default_rng(3)
x = 0.02 + 0.96*rng.random((40, 3))
np.savetxt("positions.txt", x)
p = "constant/cloudProperties"
s = open(p).read()
parcels = "\n".join("                { position (%.12g %.12g %.12g); d 1e-3; rho 1000; q 1e-9; }" % tuple(r) for r in x)
s = re.sub(r"parcels\s*\(.*?\n\s*\);", "parcels\n            (\n" + parcels + "\n            );", s, flags=re.S)
s = re.sub(r"electrostaticsModel\s+\w+;", "electrostaticsModel periodic;\n    periodicCoeffs { method p3m; accuracy 1e-7; }", s)
open(p, "w").write(s)
p = "system/controlDict"
s = open(p).read()
s = re.sub(r"^endTime .*?;", "endTime 1e-6;", s, flags=re.M)
s = re.sub(r"^deltaT .*?;", "deltaT 1e-6;", s, flags=re.M)
s = re.sub(r"^writeInterval .*?;", "writeInterval 1;", s, flags=re.M)
open(p, "w").write(s)
PYEOF
cp -r "$work/p3m" "$work/ewald"
cp -r "$work/p3m" "$work/parallel"
cp -r "$work/p3m" "$work/parallel4"
cp -r "$work/p3m" "$work/parallel8"
sed -i 's/method p3m; accuracy 1e-7;/method ewald;/' "$work/ewald/constant/cloudProperties"
for c in p3m parallel parallel4 parallel8
do
    sed -i 's/method p3m; accuracy 1e-7;/method p3m; accuracy 1e-7; potentialInterval 1;/' \
        "$work/$c/constant/cloudProperties"
done
for c in p3m ewald
do
    cd "$work/$c" || exit 1
    run blockMesh blockMesh && run solver chargedParticleFoam \
        || fail "periodicCloud.$c (solver failed, see $work/$c/log.solver)"
done
# 2, 4 and 8 processors: the cyclic directions split one, two and three
# times
for split in "2:2 1 1" "4:2 2 1" "8:2 2 2"
do
    np=${split%%:*}
    case=parallel; [ "$np" = 2 ] || case=parallel$np
    cd "$work/$case" || exit 1
    setDecomposition "$np" "${split#*:}"
    run blockMesh blockMesh && run decomposePar decomposePar \
     && run solver mpirun -np "$np" chargedParticleFoam -parallel \
     && run reconstructPar reconstructPar -latestTime \
        || fail "periodicCloud.$case (run failed, see $work/$case)"
done

# Dipoles across the periodic faces: six pairs of charged dielectric
# spheres (epsilonR 10, gap 0.01 m at 0.04 m apart) that face each other
# through the x, y and z faces, p3m + the inducedDipole near field: serial
# against 8 processors (2 x 2 x 2), where every pair is split between
# processors through a periodic translation (the dipoles' halo and the
# CG's sums over the processors)
copyCase twoChargedSpheres "$work/dipoles"
cd "$work/dipoles" || exit 1
$PY "$tools/unitBoxMesh.py" cyclic
$PY - <<'PYEOF'
import re
# (position a, position b) facing each other through a periodic face
pairs = []
for k, (y, z) in enumerate([(0.3, 0.6), (0.7, 0.2)]):
    pairs.append(((0.02, y, z), (0.98, y, z)))
    pairs.append(((y, 0.02, z), (y, 0.98, z)))
    pairs.append(((y, z, 0.02), (y, z, 0.98)))
parcels = []
for i, (a, b) in enumerate(pairs):
    for j, x in enumerate((a, b)):
        q = (1 if (i + j) % 3 else -1)*(0.5 + 0.1*i)*1e-9
        parcels.append("{ position (%g %g %g); d 0.03; rho 1000; epsilonR 10; q %.6e; }"
                       % (x + (q,)))
p = "constant/cloudProperties"
s = open(p).read()
s = re.sub(r"parcels\s*\(.*?\n\s*\);", "parcels\n            (\n                "
           + "\n                ".join(parcels) + "\n            );", s, flags=re.S)
s = re.sub(r"electrostaticsModel\s+\w+;", "electrostaticsModel periodic;\n    periodicCoeffs"
           " { method p3m; accuracy 1e-7; nearField { type inducedDipole; } }", s)
open(p, "w").write(s)
p = "system/controlDict"
s = open(p).read()
s = re.sub(r"^endTime .*?;", "endTime 1e-6;", s, flags=re.M)
s = re.sub(r"^deltaT .*?;", "deltaT 1e-6;", s, flags=re.M)
s = re.sub(r"^writeInterval .*?;", "writeInterval 1;", s, flags=re.M)
open(p, "w").write(s)
PYEOF
cp -r "$work/dipoles" "$work/dipoles8"
run blockMesh blockMesh && run solver chargedParticleFoam \
    || fail "periodicCloud.dipoles (solver failed, see $work/dipoles/log.solver)"
cd "$work/dipoles8" || exit 1
setDecomposition 8 "2 2 2"
run blockMesh blockMesh && run decomposePar decomposePar \
 && run solver mpirun -np 8 chargedParticleFoam -parallel \
 && run reconstructPar reconstructPar -latestTime \
    || fail "periodicCloud.dipoles8 (run failed, see $work/dipoles8)"
$PY - "$work" "$top/etc/python" <<'PYEOF'
import sys
import numpy as np
work = sys.argv[1]
sys.path.insert(0, sys.argv[2])
from foamLagrangian import read_field, read_positions
def load(case):
    d = f"{case}/1e-06/lagrangian/cloud"
    return (read_positions(d + "/positions"), read_field(d + "/dipole").reshape(-1, 3),
            read_field(d + "/fE").reshape(-1, 3))
xs, ps, fs = load(work + "/dipoles")
xp, pp, fp = load(work + "/dipoles8")
idx = [int(np.argmin(np.linalg.norm(xs - x, axis=1))) for x in xp]
dp = np.abs(pp - ps[idx]).max()/np.abs(ps).max()
df = np.abs(fp - fs[idx]).max()/np.abs(fs).max()
ok = len(set(idx)) == len(xs) == 12 and dp < 1e-10 and df < 1e-10
print(f"{'PASS' if ok else 'FAIL'}: periodicCloud.dipoles8 (8 processors vs serial, 12 dielectric "
      f"parcels in pairs through the periodic faces: dipoles {dp:.1e}, forces {df:.1e} of the "
      f"largest, tol 1e-10)")
PYEOF
grep -Eq "Induced dipoles += 12 polarisable, 6 pairs" "$work/dipoles/log.solver" \
 && grep -Eq "Induced dipoles += 12 polarisable, 6 pairs" "$work/dipoles8/log.solver" \
    && pass "periodicCloud.dipoles.pairs (serial and 8 processors find the 6 pairs through the faces)" \
    || fail "periodicCloud.dipoles.pairs (the logs do not show 6 pairs within rNear, see $work/dipoles*/log.solver)"

$PY - "$work" "$top/etc/python" <<'PYEOF'
import math, sys
import numpy as np
work = sys.argv[1]
sys.path.insert(0, sys.argv[2])
from foamLagrangian import read_field, read_positions

# Independent Ewald sum (tinfoil, neutralising background: no force)
k = 8.9875517923e9
L = 1.0
x0 = np.loadtxt(work + "/p3m/positions.txt")
q = np.full(len(x0), 1e-9)
alpha = 6.0/L
F = np.zeros_like(x0)
# Potentials: self term and the background's -pi Q/(V alpha^2)
phi = np.full(len(x0), -2*alpha/math.sqrt(math.pi)*q[0] - math.pi*q.sum()/(L**3*alpha**2))
rng = range(-3, 4)
for i in range(len(x0)):
    d = x0[i] - x0
    for n in np.array([(a, b, c) for a in rng for b in rng for c in rng]):
        r = d + n*L
        rr = np.linalg.norm(r, axis=1)
        m = rr > 0
        rr, rv = rr[m], r[m]
        erfc = np.array([math.erfc(alpha*v) for v in rr])
        g = erfc/rr**2 + 2*alpha/math.sqrt(math.pi)*np.exp(-(alpha*rr)**2)/rr
        F[i] += k*q[i]*np.sum((q[m]*g/rr)[:, None]*rv, axis=0)
        phi[i] += np.sum(q[m]*erfc/rr)
kmax = 12
for a in range(-kmax, kmax + 1):
    for b in range(-kmax, kmax + 1):
        for c in range(-kmax, kmax + 1):
            if a == b == c == 0:
                continue
            kv = 2*math.pi/L*np.array([a, b, c])
            k2 = kv @ kv
            w = 4*math.pi/L**3*math.exp(-k2/(4*alpha**2))/k2
            ph = x0 @ kv
            S_c, S_s = np.sum(q*np.cos(ph)), np.sum(q*np.sin(ph))
            F += (k*w*q*(np.sin(ph)*S_c - np.cos(ph)*S_s))[:, None]*kv
            phi += w*(np.cos(ph)*S_c + np.sin(ph)*S_s)
phi *= k
phiMean, phiVar = phi.mean(), phi.var()
phiScale = k*q[0]*len(x0)**(1/3)/L

scale = np.sqrt(np.mean(np.sum(F**2, axis=1)))
ok_all = True
def load(case):
    import glob, os
    t = max((d for d in os.listdir(case) if d.replace(".", "").replace("e-", "").isdigit() and d != "0"), key=float)
    d = f"{case}/{t}/lagrangian/cloud"
    return read_positions(d + "/positions"), read_field(d + "/fE").reshape(-1, 3)
for name in ("p3m", "ewald", "parallel", "parallel4", "parallel8"):
    x, f = load(f"{work}/{name}")
    # match parcels by position (wrapped into the box)
    idx = [np.argmin(np.linalg.norm(((x0 - xi + 0.5*L) % L) - 0.5*L, axis=1)) for xi in x]
    err = np.sqrt(np.mean(np.sum((f - F[idx])**2, axis=1)))/scale
    # p3m asked for 1e-7 of the force scale; ewald is converged to ~1e-10
    tol = 1e-9 if name == "ewald" else 1e-6
    ok = len(set(idx)) == len(x0) and err < tol
    print(f"{'PASS' if ok else 'FAIL'}: periodicCloud.{name} (rms force error vs an independent "
          f"Ewald sum {err:.1e} of the rms force, tol {tol:g}; {len(x)} parcels)")
    if name != "ewald":
        # The logged potential statistics against numpy's (scale: a charge
        # at the mean spacing)
        import re
        m = re.search(r"<phi>_p = (\S+) V, <phi'\^2>_p = (\S+) V2", open(f"{work}/{name}/log.solver").read())
        dm = abs(float(m.group(1)) - phiMean)/phiScale if m else float("inf")
        dv = abs(float(m.group(2)) - phiVar)/phiScale**2 if m else float("inf")
        ok = dm < 1e-6 and dv < 1e-6
        print(f"{'PASS' if ok else 'FAIL'}: periodicCloud.{name}.potentials (<phi>_p and <phi'^2>_p "
              f"vs the numpy Ewald potentials: {dm:.1e}, {dv:.1e} of k q n^(1/3) and its square, tol 1e-6)")
        if name == "p3m":
            phiSerial = (float(m.group(1)), float(m.group(2)))
        else:
            rel = max(abs(float(m.group(1)) - phiSerial[0])/phiScale,
                      abs(float(m.group(2)) - phiSerial[1])/phiScale**2)
            print(f"{'PASS' if rel < 1e-12 else 'FAIL'}: periodicCloud.{name}.potentials.serial (the "
                  f"potentials' statistics as in serial to {rel:.1e}, tol 1e-12)")
    if name == "p3m":
        serial = dict(zip(map(int, idx), f))
    elif name.startswith("parallel"):
        # The distributed mesh and the halo give the serial P3M forces
        # (same parameters) to round-off
        diff = max(np.linalg.norm(fi - serial[int(i)]) for i, fi in zip(idx, f))
        rel = diff/max(np.linalg.norm(v) for v in serial.values())
        print(f"{'PASS' if rel < 1e-12 else 'FAIL'}: periodicCloud.{name}.serial (largest force "
              f"difference from the serial P3M run {rel:.1e} of the largest force, tol 1e-12)")
PYEOF
