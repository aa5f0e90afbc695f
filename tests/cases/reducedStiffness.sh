# Ruan 2022 Table 1 / Fig. 11: charged head-on collision for the four
# stiffness ratios chi: dimensionless overlap and velocity collapse within
# 2 %; the electrostatic force of the pair in contact is chi^(2/5) times
# Coulomb's (Eq. 44) and Coulomb's otherwise.
. "$(dirname "$0")/common.sh.inc"

copyCase reducedStiffness "$work/case"
cd "$work/case" || exit 1
./Allrun > log.Allrun 2>&1 || fail "reducedStiffness.run (Allrun failed)"
grep -E '^(PASS|FAIL): ' results.txt
check reducedStiffness.plot "(collapse.png written)" test -s collapse.png
