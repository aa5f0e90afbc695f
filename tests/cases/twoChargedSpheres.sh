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
