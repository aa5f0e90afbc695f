# Flagship tutorial chargedDuct, shortened to 20 fluid steps (2 ms): the
# gas-coupled solver with ellipsoid contact, wall charging and the mesh far
# field runs in serial and on 2 processors; no parcel lost, no NaN; charge
# balance of parcels and walls to round-off (a pair across processors is
# charged by one side, which sends the partner's share); the PTFE parcels
# charge negatively and stay below saturation; serial and parallel agree.
. "$(dirname "$0")/common.sh.inc"

for mode in serial parallel
do
    copyCase chargedDuct "$work/$mode"
    cd "$work/$mode" || exit 1
    sed -i 's/balanceInterval 50;/balanceInterval 5;/' constant/cloudProperties
    if [ "$mode" = serial ]
    then
        ./Allrun -serial 0.002 > log.Allrun 2>&1
    else
        ./Allrun 0.002 > log.Allrun 2>&1
    fi
    ok=$?
    [ -f results.txt ] && grep -q "2000 parcels at t = 0.002 s" results.txt
    check "chargedDuct.$mode.run" "(Allrun -> results.txt: 2000 parcels at t = 0.002 s)" \
        test $ok = 0 -a $? = 0
    check "chargedDuct.$mode.noNaN" "(no nan in the solver log)" \
        bash -c "! grep -qi 'nan' log.chargedDPMFoam"
done

$PY - "$work" "$top" <<'PYEOF'
import os, sys
import numpy as np
work, top = sys.argv[1], sys.argv[2]
sys.path.insert(0, top + "/tutorials/chargedDuct")
import chargedDuct as cd

def report(name, ok, detail):
    print(f"{'PASS' if ok else 'FAIL'}: chargedDuct.{name} ({detail})")

res = {}
for mode in ("serial", "parallel"):
    case = f"{work}/{mode}"
    try:
        ts, q, b, s = cd.summary(case)
    except Exception as e:
        report(f"{mode}.read", False, str(e))
        continue
    res[mode] = (q[-1], s)
    bal = np.abs(b[:, 3]).max()/np.abs(b[:, 1]).max()
    report(f"{mode}.balance", bal < 1e-12,
           f"max |parcels + walls| / |parcel charge| = {bal:.1e}, tol 1e-12")
    qq = q[-1]/cd.Q_SAT
    # Walls make PTFE negative; pair contacts can leave a few particles
    # slightly positive (field-driven, Gamma = 0 between like particles)
    report(f"{mode}.charging", qq.mean() < 0 and np.abs(qq).max() < 1,
           f"q/q_sat in [{qq.min():.3e}, {qq.max():.3e}], mean {qq.mean():.3e}: mean negative, |q| < q_sat")
if len(res) == 2:
    ms, mp = res["serial"][1]["mean"], res["parallel"][1]["mean"]
    d = abs(ms - mp)/abs(ms)
    report("parallel", d < 1e-3,
           f"mean q/q_sat serial {ms:.6e}, 2 processors {mp:.6e}: rel. difference {d:.1e}, tol 1e-3")
PYEOF
