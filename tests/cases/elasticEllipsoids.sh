# Elastic (e = 1), frictionless impacts of ellipsoids (aspect ratios 1.5, 2,
# 5, 10; 24 pairs and 24 wall impacts in random orientations with spin).
# With deltaT = the collision step at 50, 100 and 200 steps per collision:
# every impact happens and ends; the largest energy error over all impacts
# is at most half the plain velocity Verlet error of a 1D Hertz impact at
# the default 50 steps per collision and no larger at 100 and 200 (plain
# Verlet's error falls as dt^2.5 there). The step-averaged Hertz force
# removes the error of contacts beginning and ending between steps; a
# force that is not the gradient of one potential would gain or lose
# energy whatever the step. The error falls at order >= 1.8; each pair's
# momentum and angular momentum are conserved to round-off. As a user
# runs it (sub-cycled at the default resolution, the step changing
# between fluid steps): within the plain 1D error at 50 steps.
. "$(dirname "$0")/common.sh.inc"

copyCase elasticEllipsoids "$work/case"
cd "$work/case" || exit 1
./Allrun > log.Allrun 2>&1 || fail "elasticEllipsoids.run (Allrun failed)"
cat results.txt
$PY - <<'PYEOF'
import re
rows = [l.split() for l in open("results.txt")]
impacts = [r for r in rows if r and r[0] in ("pair", "wall")]
ok = len(impacts) == 8 and all(r[2] == "6" and "APART" not in " ".join(r) for r in impacts)
print(f"{'PASS' if ok else 'FAIL'}: elasticEllipsoids.impacts ({sum(int(r[2]) for r in impacts)} of 48 impacts happened and ended)")
pooled = [float(v) for v in next(r for r in rows if r and r[0] == "all")[2:5]]
orders = [float(v) for v in next(r for r in rows if r and r[0] == "all")[5:7]]
floor = [float(v) for v in next(r for r in rows if r and r[0] == "1D")[2:5]]
for N, e, f in zip((50, 100, 200), pooled, floor):
    print(f"{'PASS' if e <= (0.5 if N == 50 else 1)*f else 'FAIL'}: elasticEllipsoids.energyN{N} (max |dE/E| {e:.2e}, plain velocity Verlet in 1D {f:.2e})")
print(f"{'PASS' if min(orders) >= 1.8 else 'FAIL'}: elasticEllipsoids.order (observed {orders})")
mom = [r for r in rows if r and r[0].startswith("N=")]
dP = max(float(r[5]) for r in mom)
dL = max(float(r[12]) for r in mom)
print(f"{'PASS' if len(mom) == 3 and dP <= 1e-12 and dL <= 1e-11 else 'FAIL'}: elasticEllipsoids.momentum (pairs: momentum {dP:.1e}, angular momentum {dL:.1e})")
m = re.search(r"^sub-cycled.*?(\S+) over (\d+) of (\d+) impacts(.*)$", open("results.txt").read(), re.M)
ok = m and float(m.group(1)) <= floor[0] and m.group(2) == m.group(3) == "48" and "APART" not in m.group(4)
print(f"{'PASS' if ok else 'FAIL'}: elasticEllipsoids.subCycled (max |dE/E| {m.group(1) if m else '?'}, plain 1D at 50 steps {floor[0]:.2e})")
PYEOF
