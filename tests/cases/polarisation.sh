# Dielectric parcels and the induced-dipole near field (Ruan 2022 Eqs.
# 45-50): static forces and torques of the cloud against the
# bemElectrostatics utility's inducedDipole model (two spheres, two prolates
# in three orientations), the libration of a dielectric prolate in a uniform
# field (period and energy), and two like-charged dielectric spheres that
# attract (trajectory against the integrated model force).
. "$(dirname "$0")/common.sh.inc"

for config in spheres prolateSide prolateTip prolateOblique
do
    copyCase twoChargedSpheres "$work/static-$config"
    (
        cd "$work/static-$config" || exit 1
        $PY "$tools/polarisationStatic.py" write . $config
        setEndTime 1e-6
        run blockMesh blockMesh
        run chargedParticleFoam chargedParticleFoam
        run bemElectrostatics bemElectrostatics
        $PY "$tools/polarisationStatic.py" compare . $config
    ) || fail "polarisation.static.$config (run failed, see $work/static-$config)"
done

# bemElectrostatics with an absolute outputDir writes there (not under the
# case), with the same numbers as the relative default
(
    cd "$work/static-spheres" || exit 1
    sed -i -E "s|^outputDir .*;|outputDir \"$work/bemAbsolute\";|" system/bemElectrostaticsDict
    run bemElectrostaticsAbsolute bemElectrostatics
    check polarisation.absoluteOutputDir "(inducedDipole.dat in $work/bemAbsolute, equal to the case's)" \
        cmp -s "$work/bemAbsolute/inducedDipole.dat" postProcessing/bemElectrostatics/inducedDipole.dat
)

copyCase dielectricLibration "$work/libration"
(
    cd "$work/libration" || exit 1
    ./Allrun > log.Allrun 2>&1
    result=$(tail -1 log.python3.check)
    case "$result" in
        PASS*) pass "polarisation.libration ${result#PASS: }" ;;
        *)     fail "polarisation.libration ${result}" ;;
    esac
    check polarisation.librationPlot "(libration.png written)" test -s libration.png
)

# Dipoles in parallel and on restart: eight charged dielectric prolates
# (several orientations and spins, epsilonR 3-12) drift together across
# the processor boundary (x = 0) in an applied field that turns them,
# with directCoulomb and the inducedDipole near field. Parallel = serial to 1e-10, a restart
# continues the run exactly (1e-12), the dipoles are written.
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
    q = (1 if i % 3 else -1)*(0.5 + 0.1*i)*1e-13
    parcels.append(f"{{ position ({x:.6e} {y:.6e} {z:.6e}); U (0.2 0.01 0); "
                   f"semiAxes (1.5e-4 5e-5 5e-5); eulerAngles ({20*i} {35*i % 90} {10*i}); "
                   f"omega (0 0 {50*(i % 3)}); epsilonR {3 + 1.3*i}; rho 1000; q {q:.6e}; }}")
s = re.sub(r"parcels\s*\(.*?\n\s*\);", "parcels\n            (\n                "
           + "\n                ".join(parcels) + "\n            );", s, flags=re.S)
s = s.replace("electrostaticsModel directCoulomb;",
              "electrostaticsModel directCoulomb;\n    appliedField (0 1e5 2e4);")
s = s.replace("epsilonR    1;          // vacuum",
              "epsilonR    1;\n        nearField { type inducedDipole; rNear 1e-3; }")
open(path, "w").write(s)
PYEOF
setEndTime 4e-3
setWriteInterval 1000
cp -r "$work/serial" "$work/parallel"
cp -r "$work/serial" "$work/restarted"

run blockMesh blockMesh || fail "polarisation.serialRun (blockMesh)"
run solver chargedParticleFoam || fail "polarisation.serialRun (solver failed)"
check polarisation.dipolesWritten "(dipole, tE and epsilonR fields at 0.004)" \
    test -s 0.004/lagrangian/cloud/dipole -a -s 0.004/lagrangian/cloud/tE \
         -a -s 0.004/lagrangian/cloud/epsilonR
check polarisation.nearFieldLog "(the log reports the dipole solve)" \
    grep -q "Induced dipoles  *= 8 polarisable" log.solver

cd "$work/parallel" || exit 1
run blockMesh blockMesh
run decomposePar decomposePar || fail "polarisation.parallel (decomposePar)"
run solver mpirun -np 2 chargedParticleFoam -parallel \
    || fail "polarisation.parallel (mpirun failed)"
run reconstructPar reconstructPar -latestTime \
    || fail "polarisation.parallel (reconstructPar)"
crossed=$(movedToProcessor1 0.004)
check polarisation.transfer "($crossed parcels moved from processor0 to processor1)" \
    test "${crossed:-0}" -gt 0
$PY "$tools/compareClouds.py" "$work/serial/0.004" "$work/parallel/0.004" \
    --tol 1e-10 --rotation --name polarisation.parallel

cd "$work/restarted" || exit 1
setEndTime 2e-3
run blockMesh blockMesh && run solver1 chargedParticleFoam \
    || fail "polarisation.restart (first half failed)"
setEndTime 4e-3
run solver2 chargedParticleFoam || fail "polarisation.restart (second half failed)"
$PY "$tools/compareClouds.py" "$work/serial/0.004" "$work/restarted/0.004" \
    --tol 1e-12 --rotation --name polarisation.restart

# Like charges that attract: the tutorial's gap against the integrated
# monopole + induced-dipole force, and momentum conservation
copyCase dielectricSpheres "$work/attraction"
(
    cd "$work/attraction" || exit 1
    ./Allrun > log.Allrun 2>&1
    result=$(tail -1 log.python3.check)
    case "$result" in
        PASS*) pass "polarisation.attraction ${result#PASS: }" ;;
        *)     fail "polarisation.attraction ${result}" ;;
    esac
    check polarisation.attractionPlot "(attraction.png written)" test -s attraction.png
)

# A time-dependent applied field (Function1 sine): one charged sphere in
# E(t) = E0 sin(w t) x moves as x(t) = x0 + q E0/(m w) (t - sin(w t)/w)
copyCase twoChargedSpheres "$work/sine"
cd "$work/sine" || exit 1
$PY - <<'PYEOF'
import re
p = "constant/cloudProperties"
s = open(p).read()
s = re.sub(r"\{ position \( 0.5e-3 0 0\);.*?\}\n", "", s)
s = s.replace("electrostaticsModel directCoulomb;",
              "electrostaticsModel directCoulomb;\n"
              "    appliedField sine;\n"
              "    appliedFieldCoeffs { frequency 200; amplitude 1; scale (1e4 0 0); level (0 0 0); }")
open(p, "w").write(s)
PYEOF
setEndTime 5e-3
run blockMesh blockMesh && run solver chargedParticleFoam \
    || fail "polarisation.sineField (solver failed)"
$PY - <<'PYEOF'
import glob, math
import numpy as np
f = sorted(glob.glob("postProcessing/lagrangian/cloud/particleHistory/*/particleHistory.dat"))[0]
h = np.loadtxt(f, ndmin=2)
t, x = h[:, 0], h[:, 3]
q, E0, w = 1e-12, 1e4, 2*math.pi*200
m = 1000*math.pi/6*1e-4**3
xa = -0.5e-3 + q*E0/(m*w)*(t - np.sin(w*t)/w)
err = np.abs(x - xa).max()/np.abs(xa - xa[0]).max()
print("%s: polarisation.sineField (x(t) against the analytic motion in E0 sin(wt):"
      " max error %.2e of the displacement, tol 1e-4)" % ("PASS" if err < 1e-4 else "FAIL", err))
PYEOF

# The near field on other far fields:
# - cutoffCoulomb with a cutoff beyond the scene = directCoulomb, with the
#   near field on top (same forces and torques to round-off);
# - periodic (ewald): two prolates across the periodic boundary x = 0 and
#   the same two shifted by half a box (adjacent, inside): a periodic scene
#   is translation invariant, so the near field must pair them by the
#   minimum image (forces and torques equal to the Ewald sum's accuracy);
# - cutoffCoulomb in a duct cyclic in x (below).
history()   # history <case>: fE and tE of the first step, one row per parcel (by charge)
{
    $PY - "$1" <<'PYEOF'
import glob, sys
import numpy as np
f = sorted(glob.glob(sys.argv[1] + "/postProcessing/lagrangian/cloud/particleHistory/*/particleHistory.dat"))[0]
header = open(f).readlines()[1].lstrip("# ").split()
h = np.loadtxt(f, ndmin=2)
h = h[h[:, 0] == h[0, 0]]
h = h[np.argsort(-h[:, header.index("q")], kind="stable")]   # parcels by charge (processors write in turn)
c = [header.index(k) for k in ("fEx", "fEy", "fEz", "tEx", "tEy", "tEz")]
np.savetxt(sys.argv[1] + "/forces.txt", h[:, c])
PYEOF
}
compareForces()     # compareForces <name> <caseA> <caseB> <tol>
{
    $PY - "$@" <<'PYEOF'
import sys
import numpy as np
name, a, b, tol = sys.argv[1], sys.argv[2], sys.argv[3], float(sys.argv[4])
A, B = np.loadtxt(a + "/forces.txt", ndmin=2), np.loadtxt(b + "/forces.txt", ndmin=2)
eF = np.abs(A[:, :3] - B[:, :3]).max()/np.abs(A[:, :3]).max()
eT = np.abs(A[:, 3:] - B[:, 3:]).max()/np.abs(A[:, 3:]).max()
ok = eF < tol and eT < tol and np.abs(A[:, 3:]).max() > 0
print("%s: polarisation.%s (force difference %.2e, torque %.2e of the largest; tol %g)"
      % ("PASS" if ok else "FAIL", name, eF, eT, tol))
PYEOF
}

for far in direct cutoff
do
    copyCase twoChargedSpheres "$work/far-$far"
    (
        cd "$work/far-$far" || exit 1
        $PY "$tools/polarisationStatic.py" write . prolateOblique
        [ $far = cutoff ] && sed -i 's/electrostaticsModel directCoulomb;/electrostaticsModel cutoffCoulomb;/; s/directCoulombCoeffs/cutoffCoulombCoeffs/; s/epsilonR 1;/epsilonR 1; rCut 1;/' constant/cloudProperties
        setEndTime 1e-6
        run blockMesh blockMesh && run solver chargedParticleFoam && history .
    ) || fail "polarisation.cutoffFarField (run failed, see $work/far-$far)"
done
compareForces cutoffFarField "$work/far-direct" "$work/far-cutoff" 1e-12

for shift in 0 0.5
do
    copyCase twoChargedSpheres "$work/periodic-$shift"
    (
        cd "$work/periodic-$shift" || exit 1
        $PY "$tools/unitBoxMesh.py" cyclic
        $PY - $shift <<'PYEOF'
import re, sys
shift = float(sys.argv[1])
# Two prolates 0.1 apart across x = 0 (shift 0) or at 0.45, 0.55 (shift 0.5)
xs = [(0.95 + shift) % 1.0, (0.05 + shift) % 1.0]
parcels = "\n".join(
    "                { position (%.12g %g %g); semiAxes (0.04 0.02 0.02); eulerAngles (%g 20 0); epsilonR 6; rho 1e30; q %g; }"
    % (x, 0.5 + 0.01*i, 0.5, 30 + 40*i, (1e-9, -2e-9)[i]) for i, x in enumerate(xs))
p = "constant/cloudProperties"
s = open(p).read()
s = re.sub(r"parcels\s*\(.*?\n\s*\);", "parcels\n            (\n" + parcels + "\n            );", s, flags=re.S)
s = re.sub(r"electrostaticsModel\s+\w+;", "electrostaticsModel periodic;\n    appliedField (0 1e3 0);\n"
           "    periodicCoeffs { method ewald; nearField { type inducedDipole; tolerance 1e-14; } }", s)
open(p, "w").write(s)
PYEOF
        setEndTime 1e-6
        run blockMesh blockMesh && run solver chargedParticleFoam && history .
    ) || fail "polarisation.periodicNearField (run failed, see $work/periodic-$shift)"
done
check polarisation.periodicPairs "(the near field pairs the prolates across x = 0)" \
    grep -q "2 polarisable, 1 pairs" "$work/periodic-0/log.solver"
compareForces periodicNearField "$work/periodic-0" "$work/periodic-0.5" 1e-8

# - cutoffCoulomb in a duct cyclic in x (walls y and z): two parcels
#   across the cyclic patch x = 0 and the same two shifted by half the
#   period; along the duct the scene is translation invariant, so the far
#   field's pairs and the near field's through the cyclic patch (the
#   parcels' copies) must give the same forces and torques; and the pair
#   across x = 0 on a ring of 2 processors (split at x = 0.5) as serially.
#   Two prolates with the inducedDipole near field; two spheres 0.3 radii
#   apart with the bem near field (a cluster solved with the BEM).
cyclicPair()    # cyclicPair <name> <x of the first> <x of the second> <shape> <nearField>
{
    local name=$1 shift
    for shift in 0 0.5 ring
    do
        copyCase twoChargedSpheres "$work/$name-$shift"
        (
            cd "$work/$name-$shift" || exit 1
            $PY "$tools/unitBoxMesh.py" xCyclic
            $PY - ${shift/ring/0} "$2" "$3" "$4" "$5" <<'PYEOF'
import re, sys
shift, x0, x1, shape, near = float(sys.argv[1]), float(sys.argv[2]), float(sys.argv[3]), sys.argv[4], sys.argv[5]
xs = [(x0 + shift) % 1.0, (x1 + shift) % 1.0]
parcels = "\n".join(
    "                { position (%.12g %g %g); %s; epsilonR 6; rho 1e30; q %g; }"
    % (x, 0.5 + 0.01*i, 0.5, shape.replace("ANGLE", str(30 + 40*i)), (1e-9, -2e-9)[i]) for i, x in enumerate(xs))
p = "constant/cloudProperties"
s = open(p).read()
s = re.sub(r"parcels\s*\(.*?\n\s*\);", "parcels\n            (\n" + parcels + "\n            );", s, flags=re.S)
s = re.sub(r"electrostaticsModel\s+\w+;", "electrostaticsModel cutoffCoulomb;\n    appliedField (0 1e3 0);\n"
           "    cutoffCoulombCoeffs { rCut 0.3; nearField { %s } }" % near, s)
open(p, "w").write(s)
PYEOF
            setEndTime 1e-6
            if [ $shift = ring ]
            then
                setDecomposition 2 "2 1 1"
                run blockMesh blockMesh && run decomposePar decomposePar \
                 && run solver mpirun -np 2 chargedParticleFoam -parallel && history .
            else
                run blockMesh blockMesh && run solver chargedParticleFoam && history .
            fi
        ) || fail "polarisation.$name (run failed, see $work/$name-$shift)"
    done
}
cyclicPair duct 0.95 0.05 "semiAxes (0.04 0.02 0.02); eulerAngles (ANGLE 20 0)" \
    "type inducedDipole; tolerance 1e-14;"
check polarisation.cyclicPairs "(the near field pairs the prolates across the cyclic patch)" \
    grep -q "2 polarisable, 1 pairs" "$work/duct-0/log.solver"
compareForces cyclicNearField "$work/duct-0" "$work/duct-0.5" 1e-10
compareForces cyclicNearFieldRing "$work/duct-0" "$work/duct-ring" 1e-10
cyclicPair bem 0.9775 0.0225 "semiAxes (0.02 0.02 0.02)" \
    "type bem; nPatches 200; solver { tolerance 1e-12; }"
check polarisation.cyclicBemCluster "(the spheres across the cyclic patch form a BEM cluster)" \
    grep -q "BEM parcels in or near clusters = 2 of 2" "$work/bem-0/log.solver"
compareForces cyclicBem "$work/bem-0" "$work/bem-0.5" 1e-8
compareForces cyclicBemRing "$work/bem-0" "$work/bem-ring" 1e-8

# meshPoisson: the electrodes give the applied field, the near field adds
# the dipoles. Two neutral dielectric spheres (radius a, epsilonR 5) on a
# line along the field E0 of electrodes at 0 and 100 V, 1 m apart, centres
# s apart: p = alpha E0/(1 - 2 alpha/(4 pi eps0 s^3)), alpha = 4 pi eps0
# a^3 (k - 1)/(k + 2), and each attracts the other with 6 p^2/(4 pi eps0 s^4)
# (the mutually induced point dipoles written out, not the kernel).
$PY - "$work" "$top" <<'PYEOF'
import math, sys
import numpy as np
work, top = sys.argv[1], sys.argv[2]
sys.path.insert(0, top + "/applications/benchmarks/meshFarField")
from farFieldCase import FarFieldCase, ELECTRODES, electrodesPhi
a, k, s = 0.5e-6, 5.0, 1.6e-6
x = np.array([[0.5, 0.41, 0.52], [0.5 + s, 0.41, 0.52]])
c = FarFieldCase(work + "/meshPoisson", x, np.zeros(2), 1.0, 8, "meshPoisson",
                 "radius 0.3; nearField { type inducedDipole; tolerance 1e-14; }",
                 boundary=ELECTRODES, Phi=electrodesPhi(100), d=2*a, parcelEntries="epsilonR %g;" % k)
try:
    c.run()
    E, fE = c.fields()
except RuntimeError as e:
    print("FAIL: polarisation.meshPoissonNearField (%s)" % e)
    sys.exit(0)
eps0 = 8.8541878128e-12
alpha = 4*math.pi*eps0*a**3*(k - 1)/(k + 2)
p = alpha*100/(1 - 2*alpha/(4*math.pi*eps0*s**3))
F = 6*p*p/(4*math.pi*eps0*s**4)
ref = np.array([[F, 0, 0], [-F, 0, 0]])
err = np.abs(fE - ref).max()/F
print("%s: polarisation.meshPoissonNearField (neutral dielectric pair along the"
      " electrodes' field: force %.4e N vs mutual point dipoles %.4e N, max error"
      " %.1e of it, tol 1e-6)" % ("PASS" if err < 1e-6 else "FAIL", fE[0, 0], F, err))
PYEOF
