# Ellipsoids (aspect ratio 3) dropped on a wall in four orientations:
# the energy books close (kinetic + potential + contact elastic + contact
# dissipated stays at its initial value within 5 % of the dissipated
# energy: the first-order error of contacts starting inside a step), the
# dissipation never decreases, and each comes to rest on its flat side.
. "$(dirname "$0")/common.sh.inc"

copyCase ellipsoidDrop "$work/case"
cd "$work/case" || exit 1
./Allrun > log.Allrun 2>&1 || fail "ellipsoidDrop.run (Allrun failed)"
grep -E '^(PASS|FAIL): ' results.txt
check ellipsoidDrop.plot "(drop.png written)" test -s drop.png
