# Default tutorial: trajectory of two oppositely charged spheres vs the
# analytic two-body Coulomb solution up to contact (< 0.1 %), energy
# conservation of the leapfrog, and the plot.
. "$(dirname "$0")/common.sh.inc"

copyCase twoChargedSpheres "$work/case"
cd "$work/case" || exit 1
./Allrun || fail "twoChargedSpheres.run (Allrun failed)"

result=$(tail -1 log.python3.check)
case "$result" in
    PASS*) pass "twoChargedSpheres.trajectory ${result#PASS: }" ;;
    *)     fail "twoChargedSpheres.trajectory ${result}" ;;
esac

# Total energy (kinetic + electrostatic) from the solver log: relative
# drift over the run must stay below the trajectory tolerance (1e-3)
drift=$($PY - <<'PYEOF'
import re
ke = [float(v) for v in re.findall(r"Linear kinetic energy\s*=\s*(\S+)", open("log.chargedParticleFoam").read())]
ee = [float(v) for v in re.findall(r"Electrostatic energy\s*=\s*(\S+)", open("log.chargedParticleFoam").read())]
E = [k + e for k, e in zip(ke, ee)]
print(max(abs(x - E[0]) for x in E)/abs(E[0]) if E else "nan")
PYEOF
)
check twoChargedSpheres.energy "(max relative drift of KE + U_el: $drift)" \
    $PY -c "import sys; sys.exit(0 if float('$drift') < 1e-3 else 1)"

check twoChargedSpheres.plot "(separation.png written)" test -s separation.png
check twoChargedSpheres.fields "(q and fE written as lagrangian fields)" \
    test -s 0.0059/lagrangian/cloud/q -a -s 0.0059/lagrangian/cloud/fE

# Progress in the log: a line at every tenth of the run, the last at 100 %
# with the simulated and end times
check twoChargedSpheres.progress "(10 progress lines, the last 'Progress: 100 % (t = 0.0059 s of 0.0059 s)')" \
    $PY - <<'PYEOF'
import re, sys
lines = re.findall(r"^Progress: .*$", open("log.chargedParticleFoam").read(), re.M)
pct = [int(re.match(r"Progress: (\d+) %", l).group(1)) for l in lines]
ok = (pct == list(range(10, 101, 10))
      and lines[-1].startswith("Progress: 100 % (t = 0.0059 s of 0.0059 s)")
      and all(" left" in l for l in lines[:-1]))
sys.exit(0 if ok else 1)
PYEOF
