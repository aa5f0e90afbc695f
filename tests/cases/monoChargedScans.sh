# The scans of Boutsikakis 2023 section 3 (tutorial monoChargedCloud,
# ./Allrun scan) at their cheapest: the charge, inertia, time-step and
# kernel scans at 500 particles for 8 tau_el. In units of n^(-1/3) and
# tau_el (deltaT and endTime are set in them) a run of another charge or
# mass is the base run, so the normalised agitation, integral time and
# acceleration must equal the base's to round-off amplified by the chaotic
# dynamics (tol 1e-3; a term that breaks the scaling - a fixed length, an
# absolute tolerance, the drag's tau_p - shows at O(1e-2) or more); the
# leapfrog's time-step cliff (converged from d_C/delta_l = 18, heated at
# 6.5 and below); the pseudo-particle method with Nv = 0 hot, with Nv >= 1
# close to the direct sum (Table 3); every converged run's power balance
# (Eq. 29) closes.
. "$(dirname "$0")/common.sh.inc"

copyCase monoChargedCloud "$work/case"
cd "$work/case" || exit 1
$PY scan.py --only Q,rho,dt,pseudo --size 500 --endTauEl 8 -j 2 --check 1e-3 --no-plots \
    > log.scan 2>&1
grep -E '^(PASS|FAIL): ' log.scan || fail "monoChargedScans.run (no check lines, see $work/case/log.scan)"
