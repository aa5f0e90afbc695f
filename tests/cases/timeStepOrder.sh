# The electrostatic leapfrog is second order: halving deltaT divides the
# max trajectory error of the tutorial by 4 (observed order within 2 +- 0.1).
. "$(dirname "$0")/common.sh.inc"

cd "$work" || exit 1
"$top/tutorials/twoChargedSpheres/timeStepStudy" "$work" 4e-6 2e-6 1e-6 | tee table
$PY - <<'PYEOF'
rows = [l.split() for l in open("table") if l[:1].isdigit()]
orders = [float(r[4]) for r in rows if r[4] != "-"]
for r in rows[1:]:
    ok = abs(float(r[4]) - 2) <= 0.1
    print(f"{'PASS' if ok else 'FAIL'}: timeStepOrder.dt{r[0]} (observed order {r[4]}, error {r[2]})")
if len(orders) < 2:
    print("FAIL: timeStepOrder.table (fewer than 3 runs)")
PYEOF
