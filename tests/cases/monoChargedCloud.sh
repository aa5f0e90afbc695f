# The mono-charged cloud of Boutsikakis 2023 section 3 with P3M in the
# cloud, at 2000 particles (the tutorial has 1e4) for 30 s (5.5 tau_el):
# the solver's Eq. 23 time-step reports agree with Eqs. 21-23 evaluated
# independently, and the stationary agitation and mean electrostatic
# acceleration (t >= 10 s) are those of Eqs. 25 and 28 within 25 % (the
# sampling error of 2000 particles over 20 s; the tutorial checks 10 %);
# the logged electrostatic power closes the agitation's balance (Eq. 29
# with the Stokes dissipation, central differences: 1e-2) and the force
# covariance is isotropic (Eq. 10, time mean within 0.1 of the identity).
. "$(dirname "$0")/common.sh.inc"

copyCase monoChargedCloud "$work/case"
cd "$work/case" || exit 1
./Allrun 2000 30 > log.Allrun 2>&1 || fail "monoChargedCloud.run (Allrun failed)"
$PY cloudStatistics.py --from 10 --tol 0.25 | grep -E '^(PASS|FAIL): '
