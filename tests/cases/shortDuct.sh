# The default tutorial shortDuct (the root Allrun's scene), run as the user
# runs it (serial, about a minute): Allrun writes results.txt and the plot;
# the solver's fields are finite; no parcel is lost (injected = in the duct +
# escaped, the count of constant/parcels); the charge is conserved (the
# parcels' written charges + the walls + the outflow = 0 to round-off, and
# the balance column of every line); PTFE charges negative on steel (Gamma <
# 0, Rasera 2022 Table 5) and the walls positive, no particle beyond the
# saturation charge q_sat = eps0 |Gamma| S. The ParaView picture is checked
# only where pvbatch is installed (the render test is paraviewPicture).
. "$(dirname "$0")/common.sh.inc"

# The case folder keeps the tutorial's name (the picture is <name>.png)
case="$work/shortDuct"
copyCase shortDuct "$case"
cd "$case" || exit 1
./Allrun > log.Allrun 2>&1
ok=$?
nIn=$(grep -c '^{' constant/parcels 2>/dev/null)
grep -q "^shortDuct: $nIn parcels at t = 0.05 s" results.txt 2>/dev/null
check shortDuct.run "(Allrun exit status $ok; results.txt: $nIn parcels at t = 0.05 s)" \
    test $ok = 0 -a $? = 0 -a "${nIn:-0}" -gt 0
check shortDuct.plot "(charging.png written, results.txt has the wall time)" \
    bash -c "test -s charging.png && grep -q 'wall time: [0-9]* s' results.txt"

$PY - "$case" "$top" "$nIn" <<'PYEOF'
import os, re, sys
import numpy as np
case, top, nIn = sys.argv[1], sys.argv[2], int(sys.argv[3] or 0)
sys.path.insert(0, top + "/tutorials/chargedDuct")
sys.path.insert(0, top + "/etc/python")
import chargedDuct as cd
from foamLagrangian import read_field, read_internal_field

def report(name, ok, detail):
    print(f"{'PASS' if ok else 'FAIL'}: shortDuct.{name} ({detail})")

try:
    ts, q, b, s = cd.summary(case)
    log = open(os.path.join(case, "log.chargedDPMFoam")).read()
except Exception as e:
    report("read", False, f"{type(e).__name__}: {e}")
    sys.exit(0)
t = ts[-1]

# Finite: the solver log and the fields of the last time
bad = [f for f in ("q", "U", "E")
       if not np.isfinite(read_field(f"{case}/{t}/lagrangian/cloud/{f}")).all()]
bad += [f for f in ("U.air", "p", "Phi", "E")
        if not np.isfinite(read_internal_field(f"{case}/{t}/{f}")).all()]
nanLog = re.search(r"\bnan\b", log, re.I) is not None
report("finite", not bad and not nanLog,
       f"t = {t} s: parcel q, U, E and mesh U.air, p, Phi, E finite"
       f"{': not ' + ', '.join(bad) if bad else ''}; nan in the log: {nanLog}")

# Parcels: injected = in the duct + escaped (log), = constant/parcels
last = lambda p: int(re.findall(p, log)[-1])
added = last(r"parcels added\s*=\s*(\d+)")
current = last(r"Current number of parcels\s*=\s*(\d+)")
escaped = last(r"Parcel fate: system \(number, mass\)\s*\n\s*- escape\s*=\s*(\d+)")
nq = len(q[-1])
report("parcels", added == nIn and current == nq and added == current + escaped,
       f"{nIn} in constant/parcels, {added} injected = {current} in the duct"
       f" ({nq} written) + {escaped} escaped")

# Charge: the written parcel charges + walls + outflow (the balance line of
# the last write) = 0 within the rounding of the written q (writePrecision
# digits: at most 0.5e(1 - digits) of each |q|); every line's balance column
# (full precision) to round-off
bt = b[np.argmin(np.abs(b[:, 0] - float(t)))]
digits = int(re.search(r"^writePrecision\s+(\d+);", open(
    f"{case}/system/controlDict").read(), re.M).group(1))
tol = 0.5*10.0**(1 - digits)
res = abs(q[-1].sum() + bt[2] + bt[6])/np.abs(q[-1]).sum()
col = np.abs(b[:, 3]).max()/np.abs(b[:, 1]).max()
report("chargeConservation", res < tol and col < 1e-12,
       f"t = {t} s: sum of the written q {q[-1].sum():.9e} C + walls"
       f" {bt[2]:.9e} C + outflow {bt[6]:.3e} C = {res:.1e} of sum |q|,"
       f" tol {tol:.0e} (writePrecision {digits}); balance column"
       f" <= {col:.1e} of the parcel charge, tol 1e-12")

# Sign and bound: PTFE on steel (Gamma < 0) charges negative, walls positive
par = cd.case_params(case)
qq = q[-1]/s["qSat"]
report("chargeSign", par["Gamma"] < 0 and qq.mean() < 0 and bt[2] > 0
       and np.abs(qq).max() < 1,
       f"Gamma = {par['Gamma']:g} V/m; q/q_sat in [{qq.min():.3e},"
       f" {qq.max():.3e}], mean {qq.mean():.3e} < 0; walls {bt[2]:.3e} C > 0;"
       f" |q| < q_sat = {s['qSat']:.4g} C")
report("contacts", b[:, 5].sum() > 0 and b[:, 4].sum() > 0,
       f"charging contacts: {b[:, 5].sum():.0f} particle-wall,"
       f" {b[:, 4].sum():.0f} particle-particle")
PYEOF

if command -v pvbatch > /dev/null && [ -x "$top/etc/paraview/render" ]
then
    check shortDuct.picture "(ParaView picture shortDuct.png from Allrun)" \
        test -s shortDuct.png
else
    echo "(shortDuct.picture not checked: no pvbatch or etc/paraview/render)"
fi
