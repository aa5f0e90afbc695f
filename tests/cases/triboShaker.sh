# A PTFE sphere shaken in a grounded steel cylinder (Rasera 2022 section
# 4.2; the oscillatingFrame force shakes the mesh): its charge rises
# monotonically towards, and never beyond, the saturation charge of Eq. 17,
# and particle + walls balance to round-off. One second of the 3.18 mm
# sphere (the tutorial runs 60 s of three sizes).
. "$(dirname "$0")/common.sh.inc"

copyCase triboShaker "$work/case"
cd "$work/case" || exit 1
./Allrun 1 3.18 > log.Allrun 2>&1 || fail "triboShaker.run (Allrun failed)"
grep -E '^(PASS|FAIL): ' results.txt
check triboShaker.plot "(shaker.png written)" test -s shaker.png
