# Gas-particle momentum coupling: two-velocity relaxation in a
# fully periodic box with uniform fields (tests/tools/momentumRelaxation.py
# has the set-up), gas moving and particles at rest and the reverse, mass
# loadings 0.1, 1, 10, 30 and dt/tau_p 0.01, 0.1, 1, 10, against the exact
# solution of Stokes drag. momentumCoupling conservativeImplicit: total
# momentum constant to 1e-8 in every row, the slip never grows, and the
# slip error first order in the step. (DPMFoam's schemes side by side:
# README, "The gas-coupled solver".)
. "$(dirname "$0")/common.sh.inc"

mkdir -p "$work/relaxation"
$PY "$top/tests/tools/momentumRelaxation.py" "$work/relaxation" \
    --schemes conservativeImplicit --check > "$work/relaxation/table.txt" 2>&1 \
    || fail "momentumCoupling.run (see $work/relaxation/table.txt)"
grep -E '^(PASS|FAIL): ' "$work/relaxation/table.txt"
