# Faults on restart: a run killed while writing, and damaged parcel files.
#  - every write leaves uniform/lagrangian/cloud/cloudFieldsRecord, "complete
#    yes" with the list of the parcels' files;
#  - a record left "complete no" (the run stopped while writing), a listed
#    file missing or empty, or a time without parcels after one with a
#    record: the restart stops with a message naming the time, the latest
#    complete one and how to restart from it;
#  - every file of the parcels truncated in turn: the restart stops with a
#    FOAM FATAL error naming that file, or (files the cloud only writes)
#    runs with every parcel;
#  - the solver killed (SIGKILL) at random moments of a run writing every
#    step, eight times: each restart from the latest time either continues
#    with every parcel, stops with the message above, or stops with
#    OpenFOAM's error naming a file of the cut time (a kill while the
#    cloud's output properties were written), never silently with fewer
#    parcels or defaults.
. "$(dirname "$0")/common.sh.inc"

copyCase twoChargedSpheres "$work/base"
cd "$work/base" || exit 1
setEndTime 2e-5
setWriteInterval 10
run blockMesh blockMesh && run solver chargedParticleFoam \
    || fail "faults.baseRun (solver failed)"
last=2e-05
record=$last/uniform/lagrangian/cloud/cloudFieldsRecord
check faults.record "(complete, listing the parcels' files)" \
    $PY - "$record" "$last/lagrangian/cloud" <<'PYEOF'
import os, re, sys
text = open(sys.argv[1]).read()
files = re.search(r"files\s+\d+\s*\(([^)]*)\)", text).group(1).split()
sys.exit(0 if re.search(r"complete\s+true;", text)
         and sorted(files) == sorted(os.listdir(sys.argv[2])) else 1)
PYEOF

# restart <name> <edit...>: a copy of the base case, edited, restarted to 3e-5
restart()
{
    local name="$1"; shift
    rm -rf "$work/$name"; cp -r "$work/base" "$work/$name"
    (cd "$work/$name" && "$@" && setEndTime 3e-5 \
        && chargedParticleFoam > log.restart 2>&1)
}
stopsNaming()
{
    grep -q "not completely written" "$work/$1/log.restart" \
 && grep -q "Restart from time 1e-05, the latest complete one" "$work/$1/log.restart"
}

restart clean true
check faults.cleanRestart "(continues from $last with both parcels)" \
    grep -q "Current number of parcels *= 2" "$work/clean/log.restart"

restart cut sed -i 's/^complete .*/complete        false;/' "$record"
check faults.cut "(record left incomplete: stops naming time 1e-05)" stopsNaming cut

restart missing rm "$last/lagrangian/cloud/q"
check faults.missing "(q deleted: stops naming q and time 1e-05)" \
    eval 'stopsNaming missing && grep -q "missing or empty 1(q)" "$work/missing/log.restart"'

restart empty eval ": > $last/lagrangian/cloud/epsilonR"
check faults.empty "(epsilonR emptied: stops naming it)" \
    eval 'stopsNaming empty && grep -q "missing or empty 1(epsilonR)" "$work/empty/log.restart"'

restart noParcels rm -r "$last/lagrangian" "$record"
check faults.noParcels "(no parcels and no record after a recorded time: stops)" \
    eval 'grep -q "the run stopped while writing them" "$work/noParcels/log.restart" && stopsNaming noParcels'

# Every file of the parcels truncated to 90 %
bad=""
nFiles=0
for f in $(ls "$work/base/$last/lagrangian/cloud")
do
    nFiles=$((nFiles + 1))
    restart trunc eval "p=$last/lagrangian/cloud/$f; head -c \$((\$(stat -c %s \$p)*9/10)) \$p > \$p.t && mv \$p.t \$p"
    rc=$?
    log="$work/trunc/log.restart"
    if [ $rc -ne 0 ]
    then
        grep -q "FOAM FATAL" "$log" && grep -q "lagrangian/cloud/$f" "$log" \
            || bad="$bad $f(rc=$rc,unnamed)"
    else
        grep -q "Current number of parcels *= 2" "$log" || bad="$bad $f(lost)"
    fi
done
check faults.truncated "($nFiles files truncated in turn: each a named error or a full run${bad:+; escapes:$bad})" \
    test -z "$bad"

# SIGKILL at random moments of a run that writes every step
rm -rf "$work/kill"; cp -r "$work/base" "$work/kill"
cd "$work/kill" || exit 1
rm -rf 1e-05 2e-05
setEndTime 1
setWriteInterval 1
outcomes=""
badKill=""
for k in 1 2 3 4 5 6 7 8
do
    chargedParticleFoam > log.run$k 2>&1 &
    pid=$!
    sleep "$($PY -c "import random; random.seed($k); print(round(0.5 + 1.5*random.random(), 2))")"
    kill -9 $pid 2>/dev/null; wait $pid 2>/dev/null
    latest=$(ls -d [0-9]* | sort -g | tail -1)
    next=$($PY -c "print($latest + 3e-6)")
    setEndTime "$next"
    if chargedParticleFoam > log.restart$k 2>&1
    then
        grep -q "Current number of parcels *= 2" log.restart$k \
            && outcomes="$outcomes continued" || badKill="$badKill $k(lost)"
    elif grep -q "were not completely written" log.restart$k
    then
        outcomes="$outcomes stopped"
        # The named earlier time restarts
        earlier=$(grep -o "Restart from time [^,]*" log.restart$k | awk '{print $4}')
        sed -i -E "s/^startFrom .*/startFrom       startTime;/; s/^startTime .*/startTime       $earlier;/" system/controlDict
        chargedParticleFoam > log.earlier$k 2>&1 \
            && grep -q "Current number of parcels *= 2" log.earlier$k \
            || badKill="$badKill $k(earlier $earlier failed)"
        sed -i -E "s/^startFrom .*/startFrom       latestTime;/" system/controlDict
        rm -rf "$latest"
    elif grep -q "FOAM FATAL" log.restart$k && grep -q "/$latest/" log.restart$k
    then
        # OpenFOAM's own error on a file of the cut time (e.g. the cloud's
        # output properties, written after the parcels): named, not silent
        outcomes="$outcomes named"
        rm -rf "$latest"
    else
        badKill="$badKill $k(rc, unnamed)"
    fi
    setEndTime 1
done
check faults.kill "(8 kills:$outcomes${badKill:+; escapes:$badKill})" test -z "$badKill"
