# The fast subset of the extremes program
# (applications/benchmarks/extremes/extremes.py --fast): pours of aspect
# ratio 10 and 1/10 at 20 and 50 steps per collision (parcels kept, finite,
# no unconverged contact, the energy books' error falling at least as the
# collision step: first order), 5 and 50 steps per collision
# (restitution against the exact Hertz-dashpot impact), chi = 1e-3 (collapse
# onto chi = 1), BEM pairs at gaps 0.02 and 0.05 of the radius with
# epsilonR 2 and 1000 (the exact two-sphere force: within 2 % at 0.05,
# finite at 0.02; GMRES iterations counted), like charges at
# 0.3 and 3 Coulomb-collision steps (warned only above it; exact closest
# approach and energy within 1e-3 below it), surface fields 0.5 and 10 times
# the breakdown of air (warned only above it) and 1.5 C (stops), and 10^4
# steps of a bound charge pair (charge exact, momentum to round-off, energy
# within 1e-3).
. "$(dirname "$0")/common.sh.inc"

$PY "$top/applications/benchmarks/extremes/extremes.py" --fast --work "$work/runs" \
    > "$work/extremes.log" 2>&1
grep -E '^(PASS|FAIL): ' "$work/extremes.log" || fail "extremes.run (no checks, see $work/extremes.log)"
