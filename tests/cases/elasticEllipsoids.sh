# Elastic (e = 1), frictionless impacts of ellipsoids (aspect ratios 1.5, 2,
# 5, 10; 24 pairs and 24 wall impacts in random orientations with spin).
# With deltaT = the collision step at 50, 100 and 200 steps per collision:
# every impact happens and ends; the largest energy error over all impacts
# is below 1e-5 at the default 50 steps per collision (plain velocity
# Verlet: 8.5e-5 for a 1D Hertz impact; the first and last steps of each
# contact correct the impulse missed where the Hertz law switches on or
# off between steps; a force that is not the gradient of one potential
# would gain or lose energy whatever the step), falls at order >= 1.8
# from 50 to 100 steps and further at 200; each pair's momentum and
# angular momentum are conserved to round-off. As a user runs it
# (sub-cycled at the default resolution): below 1e-5 too.
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
print(f"{'PASS' if pooled[0] <= 1e-5 else 'FAIL'}: elasticEllipsoids.energyN50 (max |dE/E| {pooled[0]:.2e} <= 1e-5; plain velocity Verlet in 1D {floor[0]:.2e})")
ok = orders[0] >= 1.8 and pooled[2] < pooled[1]
print(f"{'PASS' if ok else 'FAIL'}: elasticEllipsoids.order (observed {orders}; max |dE/E| {pooled})")
mom = [r for r in rows if r and r[0].startswith("N=")]
dP = max(float(r[5]) for r in mom)
dL = max(float(r[12]) for r in mom)
print(f"{'PASS' if len(mom) == 3 and dP <= 1e-12 and dL <= 1e-11 else 'FAIL'}: elasticEllipsoids.momentum (pairs: momentum {dP:.1e}, angular momentum {dL:.1e})")
m = re.search(r"^sub-cycled.*?(\S+) over (\d+) of (\d+) impacts(.*)$", open("results.txt").read(), re.M)
ok = m and float(m.group(1)) <= 1e-5 and m.group(2) == m.group(3) == "48" and "APART" not in m.group(4)
print(f"{'PASS' if ok else 'FAIL'}: elasticEllipsoids.subCycled (max |dE/E| {m.group(1) if m else '?'} <= 1e-5)")
PYEOF
