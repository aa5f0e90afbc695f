#!/bin/bash
#------------------------------------------------------------------------------
# Where chargedParticleFoam spends the time of the settling-bed window:
# `perf record` with DWARF call graphs of STEPS steps of the cfSpheres case of
# a finished Allrun (copied, not changed), then the inclusive (children) and
# self shares of the main functions, with template arguments stripped.
#
#   applications/benchmarks/settlingBed/profile.sh [full|quick] [STEPS]
#
# Needs linux-perf (Debian package linux-perf) and kernel.perf_event_paranoid
# <= 2. Setup (reading the parcels) is in the profile too: the shares of the
# time loop are printed relative to KinematicCloud::evolveCloud.
#------------------------------------------------------------------------------
cd "${0%/*}" || exit 1
here="$PWD"
root="$(cd ../../.. && pwd -P)"
mode="${1:-full}"
steps="${2:-300}"
src="$here/runs/$mode/spheres/cfSpheres.1"   # the first of the repeated runs
[ -d "$src" ] || { echo "profile.sh: $src missing: run Allrun (-quick for quick) first" 1>&2; exit 1; }
command -v perf >/dev/null || { echo "profile.sh: perf not found (apt-get install linux-perf)" 1>&2; exit 1; }
if [ -z "$CHARGEDFOAM_DIR" ] || [ "$CHARGEDFOAM_DIR" != "$root" ]
then
    . "$root/etc/bashrc" || exit 1
fi
# The snapshot of the binary and libraries the benchmark ran
snap="$here/runs/$mode/snapshot"
export LD_LIBRARY_PATH="$snap/lib:$LD_LIBRARY_PATH"
export PATH="$snap/bin:$PATH"

case="$here/runs/$mode/profile"
rm -rf "$case" && mkdir -p "$case"
cp -r "$src/system" "$src/constant" "$case/"
dt=$(sed -n 's/^deltaT *\([^;]*\);/\1/p' "$case/system/controlDict")
end=$(/usr/bin/python3 -c "print(f'{$steps*$dt:.12g}')")
sed -i "s/^endTime .*/endTime         $end;/; s/^writeInterval .*/writeInterval   100000;/" "$case/system/controlDict"
(cd "$case" && blockMesh > log.blockMesh 2>&1 \
 && perf record -q -F 250 --call-graph dwarf,32768 -o perf.data chargedParticleFoam > log.chargedParticleFoam 2>&1) \
 || { echo "profile.sh: run failed, see $case" 1>&2; exit 1; }
perf report -i "$case/perf.data" --stdio --children --sort symbol -g none 2>/dev/null > "$case/report.txt"

/usr/bin/python3 - "$case/report.txt" <<'PYEOF'
import re
import sys

rows = []
for line in open(sys.argv[1]):
    m = re.match(r"\s*([\d.]+)%\s+([\d.]+)%\s+\[.\]\s+(.*)", line)
    if not m:
        continue
    name = m.group(3).strip()
    prev = None
    while prev != name:
        prev, name = name, re.sub(r"<[^<>]*>", "", name)
    name = re.sub(r"\s+-\s+-\s*$", "", name)
    name = re.sub(r"\(.*", "", name).strip()
    rows.append((float(m.group(1)), float(m.group(2)), name))
loop = next((c for c, s, n in rows if n.endswith("KinematicCloud::evolveCloud")), 100.0)
print(f"time loop (KinematicCloud::evolveCloud) = {loop:.1f} % of the samples; shares below are of the loop\n")
print("| function | inclusive [% of loop] | self [% of loop] |")
print("|---|--:|--:|")
seen = set()
for c, s, n in rows:
    if n in seen or c < 0.02*loop or not n.startswith(("Foam::", "std::", "_int", "malloc", "cfree")):
        continue
    if n.endswith(("::solve", "::evolveCloud", "::evolve")):
        continue
    if any(k in n for k in ("::New", "Constructor", "dictionary", "Entry", "IOobject", "::read",
                            "indexedOctree", "treeDataCell", "findCell", "cellTree", "operator>>", "stream",
                            "InjectionModel", "::KinematicCloud::KinematicCloud",
                            "ChargedCloud::ChargedCloud", "CollidingCloud::CollidingCloud",
                            "EllipsoidCollision::EllipsoidCollision", "contactLaw::properties", "restitution",
                            "InteractionLists::InteractionLists", "buildInteractionLists")):
        continue
    seen.add(n)
    print(f"| `{n}` | {100*c/loop:.1f} | {100*s/loop:.1f} |")
PYEOF
