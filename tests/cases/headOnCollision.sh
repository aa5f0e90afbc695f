# Hertz contact: head-on sphere collisions for e = 0.3 ... 1, a sphere-wall
# impact and a sub-cycled run: measured restitution within 1 % of the
# input e, contact duration within 1 % of the Hertz-dashpot theory.
. "$(dirname "$0")/common.sh.inc"

copyCase headOnCollision "$work/case"
cd "$work/case" || exit 1
./Allrun > log.Allrun 2>&1 || fail "headOn.run (Allrun failed)"
grep -E '^(PASS|FAIL): ' results.txt
check headOn.subcycling "($(grep -o '[0-9]* sub-cycles of [0-9.e-]* s' results.txt))" \
    grep -q " 13 sub-cycles" results.txt
check headOn.plot "(restitution.png written)" test -s restitution.png
