# Parallel run (2 processors) reproduces the serial run: decomposePar,
# mpirun -np 2 chargedParticleFoam -parallel, reconstructPar; same particle
# count, positions and velocities to 1e-10 relative, identical charges.
# Eight charged particles, several crossing the processor boundary (x = 0).
. "$(dirname "$0")/common.sh.inc"

copyCase twoChargedSpheres "$work/serial"
cd "$work/serial" || exit 1
$PY - <<'PYEOF'
import re
path = "constant/cloudProperties"
s = open(path).read()
parcels = []
for i in range(8):
    x = -0.45e-3 + 0.9e-3*(i % 2)             # left/right of x = 0
    y = -0.6e-3 + 0.4e-3*(i//2)               # four lanes
    z = 0.1e-3*((i % 3) - 1)
    ux = 0.2 if i % 2 == 0 else -0.2          # towards and across x = 0
    q = (1 if i % 3 else -1)*(0.5 + 0.1*i)*1e-12
    parcels.append(f"{{ position ({x:.6e} {y:.6e} {z:.6e}); U ({ux} 0.01 0); "
                   f"d 1e-4; rho 1000; q {q:.6e}; }}")
s = re.sub(r"parcels\s*\(.*?\n\s*\);", "parcels\n            (\n                "
           + "\n                ".join(parcels) + "\n            );", s, flags=re.S)
open(path, "w").write(s)
PYEOF
setEndTime 4e-3
setWriteInterval 1000
cp -r "$work/serial" "$work/parallel"

run blockMesh blockMesh || fail "parallel.serialRun (blockMesh)"
run solver chargedParticleFoam || fail "parallel.serialRun (solver failed)"

cd "$work/parallel" || exit 1
run blockMesh blockMesh || fail "parallel.parallelRun (blockMesh)"
run decomposePar decomposePar || fail "parallel.parallelRun (decomposePar)"
run solver mpirun -np 2 chargedParticleFoam -parallel \
    || fail "parallel.parallelRun (mpirun failed)"
run reconstructPar reconstructPar -latestTime \
    || fail "parallel.parallelRun (reconstructPar)"

# Particles really crossed the processor boundary: processor1 ends up
# holding particles injected on processor0 (origProcId 0)
crossed=$(movedToProcessor1 0.004)
check parallel.transfer "($crossed particles moved from processor0 to processor1)" \
    test "${crossed:-0}" -gt 0

$PY "$tools/compareClouds.py" "$work/serial/0.004" "$work/parallel/0.004" \
    --tol 1e-10 --name parallel
