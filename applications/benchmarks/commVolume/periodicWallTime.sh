#!/bin/bash
#------------------------------------------------------------------------------
# Wall time of the periodic cloud on 2 ranks against serial, in turns:
# tutorials/monoChargedCloud (N like charges, P3M at its default accuracy),
# injected in one serial step and decomposed (2 1 1), then S steps serially
# and on 2 ranks, and optionally on 2 ranks with another build of the
# project (a worktree of another commit, built), R rounds; the
# ExecutionTime after the first step of each run, per-round ratios.
#
#   periodicWallTime.sh [--n 10000] [--steps 100] [--rounds 5]
#                       [--other <project root of another build>]
#                       [--work /tmp/periodicWallTime]
#------------------------------------------------------------------------------
set -e
here="$(cd "$(dirname "$0")" && pwd)"
top="$(cd "$here/../../.." && pwd)"
n=10000; steps=100; rounds=5; other=""; work=/tmp/periodicWallTime
while [ $# -gt 0 ]; do
    case "$1" in
        --n) n=$2; shift ;;
        --steps) steps=$2; shift ;;
        --rounds) rounds=$2; shift ;;
        --other) other=$(cd "$2" && pwd); shift ;;
        --work) work=$2; shift ;;
        *) echo "periodicWallTime.sh: unknown option $1" 1>&2; exit 1 ;;
    esac
    shift
done
[ "$(id -u)" = 0 ] && export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1

# inBuild <project root> <command>: the command in that build's environment
inBuild() { env -i HOME="$HOME" PATH=/usr/bin:/bin OMPI_ALLOW_RUN_AS_ROOT=1 \
    OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 bash -c ". '$1/etc/bashrc' && $2"; }

# prepare <dir> <project root>: injected, restart set up, decomposed
prepare()
{
    rm -rf "$1"
    cp -r "$top/tutorials/monoChargedCloud" "$1"
    cd "$1"
    inBuild "$2" "/usr/bin/python3 makeParcels.py $n > /dev/null
        sed -i -E 's/^endTime .*/endTime 0.01;/; s/^writeInterval .*/writeInterval 1;/' system/controlDict
        blockMesh > log.blockMesh 2>&1 && chargedParticleFoam > log.inject 2>&1"
    sed -i -E "s/^endTime .*/endTime $(awk -v s="$steps" 'BEGIN {print 0.01*(1 + s)}');/; s/^writeInterval .*/writeInterval 100000;/; s/^startFrom .*/startFrom latestTime;/" system/controlDict
    /usr/bin/python3 - <<'PYEOF'
import re
p = "constant/cloudProperties"
s = open(p).read()
s = re.sub(r"injectionModels\s*\{.*?\n    \}", "injectionModels\n    {\n    }", s, flags=re.S)
open(p, "w").write(s)
PYEOF
    inBuild "$2" "decomposePar -latestTime > log.decomposePar 2>&1"
}
elapsed() { awk '/^ExecutionTime/ {t[n++] = $3} END {print t[n-1] - t[0]}' "$1"; }
ratio() { awk -v a="$1" -v b="$2" 'BEGIN {printf "%.3f", a/b}'; }
clean() { rm -rf "$1"/0.0[2-9]* "$1"/0.[1-9]* "$1"/[1-9]* "$1"/processor*/0.0[2-9]* "$1"/processor*/0.[1-9]* "$1"/processor*/[1-9]*; }

mkdir -p "$work"
prepare "$work/this" "$top"
[ -n "$other" ] && prepare "$work/other" "$other"
echo "monoChargedCloud, $n charges, $steps steps after the first, 2 ranks (2 1 1) against serial"
for r in $(seq "$rounds"); do
    clean "$work/this"; [ -n "$other" ] && clean "$work/other"
    cd "$work/this"
    inBuild "$top" "chargedParticleFoam > log.serial 2>&1"
    s=$(elapsed log.serial)
    inBuild "$top" "mpirun -np 2 chargedParticleFoam -parallel > log.parallel 2>&1"
    p=$(elapsed log.parallel)
    line="round $r: serial $s s, 2 ranks $p s, serial/2 ranks $(ratio "$s" "$p")"
    if [ -n "$other" ]; then
        cd "$work/other"
        inBuild "$other" "mpirun -np 2 chargedParticleFoam -parallel > log.parallel 2>&1"
        o=$(elapsed log.parallel)
        line="$line; other build 2 ranks $o s, other/this $(ratio "$o" "$p")"
    fi
    echo "$line"
done
