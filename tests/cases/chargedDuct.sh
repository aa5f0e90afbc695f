# Flagship tutorial chargedDuct, shortened to 20 fluid steps (2 ms): the
# gas-coupled solver with ellipsoid contact, wall charging and the mesh far
# field runs in serial and on 2, 4 and 8 processors; no parcel lost, no NaN; charge
# balance of parcels and walls to round-off (a pair across processors is
# charged by one side, which sends the partner's share); the PTFE parcels
# charge negatively and stay below saturation; serial and parallel agree;
# charge leaving through the outlet is booked in the balance.
. "$(dirname "$0")/common.sh.inc"

for mode in serial parallel parallel4 parallel8
do
    copyCase chargedDuct "$work/$mode"
    cd "$work/$mode" || exit 1
    sed -i 's/balanceInterval 50;/balanceInterval 5;/' constant/cloudProperties
    if [ "$mode" = parallel4 ]
    then
        setDecomposition 4 "1 2 2"
    elif [ "$mode" = parallel8 ]
    then
        setDecomposition 8 "2 2 2"
    fi
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

# Outflow: 60 charged parcels start just before the outlet at 5 m/s; the
# charge they carry out is booked (balance = parcels + walls + outflow)
copyCase chargedDuct "$work/outflow"
cd "$work/outflow" || exit 1
$PY - <<'PYEOF'
import numpy as np
rng = np.random.default_rng(3)
x = []
while len(x) < 60:      # bounding spheres (1 mm) apart: no initial overlap
    p = np.array([0.575 + 0.023*rng.random(), 0.0012 + 0.0176*rng.random(), 0.0012 + 0.0176*rng.random()])
    if all(np.sum((p - y)**2) > 2.1e-3**2 for y in x):
        x.append(p)
with open("constant/parcels", "w") as f:
    for p in x:
        f.write("{ position (%.9g %.9g %.9g); U (5 0 0); semiAxes (1e-3 5e-4 5e-4); q -1e-12; }\n" % tuple(p))
PYEOF
sed -i 's/balanceInterval 50;/balanceInterval 5;/' constant/cloudProperties
foamDictionary -entry endTime -set 0.004 system/controlDict > /dev/null
foamDictionary -entry writeInterval -set 10 system/controlDict > /dev/null
run blockMesh blockMesh
run chargedDPMFoam chargedDPMFoam
check "chargedDuct.outflow.run" "(chargedDPMFoam ended)" grep -q "^End" log.chargedDPMFoam

$PY - "$work" "$top" <<'PYEOF'
import os, sys
import numpy as np
work, top = sys.argv[1], sys.argv[2]
sys.path.insert(0, top + "/tutorials/chargedDuct")
import chargedDuct as cd

def report(name, ok, detail):
    print(f"{'PASS' if ok else 'FAIL'}: chargedDuct.{name} ({detail})")

res = {}
for mode in ("serial", "parallel", "parallel4", "parallel8"):
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
    qq = q[-1]/s["qSat"]
    # Walls make PTFE negative; pair contacts can leave a few particles
    # slightly positive (field-driven, Gamma = 0 between like particles)
    report(f"{mode}.charging", qq.mean() < 0 and np.abs(qq).max() < 1,
           f"q/q_sat in [{qq.min():.3e}, {qq.max():.3e}], mean {qq.mean():.3e}: mean negative, |q| < q_sat")
b = np.loadtxt(f"{work}/outflow/postProcessing/lagrangian/cloud/triboCharging/0/chargeBalance.dat")
q0 = -60e-12
drift = np.abs(b[:, 3] - q0).max()/abs(q0)
out = b[-1, 6]
ts = cd.times(f"{work}/outflow")
n = len(cd.parcel_q(f"{work}/outflow", ts[-1])) if ts else 60
report("outflow", n < 60 and out < 0 and drift < 1e-12,
       f"{60 - n} of 60 parcels left through the outlet carrying {out:.4e} C; parcels + walls + outflow = initial charge to {drift:.1e}, tol 1e-12")

for mode, label in (("parallel", "2 processors"), ("parallel4", "4 processors"), ("parallel8", "8 processors")):
    if "serial" in res and mode in res:
        ms, mp = res["serial"][1]["mean"], res[mode][1]["mean"]
        d = abs(ms - mp)/abs(ms)
        report(mode, d < 1e-3,
               f"mean q/q_sat serial {ms:.6e}, {label} {mp:.6e}: rel. difference {d:.1e}, tol 1e-3")
    else:
        report(mode, False, "a run is missing")
PYEOF
