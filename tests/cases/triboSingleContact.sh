# Single-contact tribocharging (Rasera 2022 Tables 1-4): the charge of each
# impact equals the model integrated by hand over an elastic Hertz loading
# (charge only onto new area), and particles + walls balance to round-off.
. "$(dirname "$0")/common.sh.inc"

copyCase triboSingleContact "$work/case"
cd "$work/case" || exit 1
./Allrun > log.Allrun 2>&1 || fail "triboSingleContact.run (Allrun failed)"
grep -E '^(PASS|FAIL): ' results.txt
check triboSingleContact.plot "(singleContact.png written)" test -s singleContact.png
