# A PTFE sphere shaken in a grounded steel cylinder (Rasera 2022 section
# 4.2; the oscillatingFrame force shakes the mesh): its charge rises
# monotonically towards, and never beyond, the saturation charge of Eq. 17,
# and particle + walls balance to round-off. One second of the 3.18 mm
# sphere (the tutorial runs 60 s of three sizes). Section 4.3 (Allrun
# multi), one second: the particle-particle kappa_c from the impacts'
# contact area (Eq. 23), thirteen 12.7 mm spheres and four: every run
# balances to round-off, its bulk charge stays between N q_sat and 0, and
# the share of wall impacts falls with the number of spheres.
. "$(dirname "$0")/common.sh.inc"

copyCase triboShaker "$work/case"
cd "$work/case" || exit 1
./Allrun 1 3.18 > log.Allrun 2>&1 || fail "triboShaker.run (Allrun failed)"
grep -E '^(PASS|FAIL): ' results.txt
check triboShaker.plot "(shaker.png written)" test -s shaker.png

cd "$work" || exit 1
copyCase triboShaker "$work/multi"
cd "$work/multi" || exit 1
./Allrun multi 1 1 "4 13" > log.Allrun 2>&1 || fail "triboShaker.multi (Allrun multi failed)"
grep -E '^(PASS|FAIL): ' results.multi.txt
check triboShaker.multiPlot "(multi.png written)" test -s multi.png
