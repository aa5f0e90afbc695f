#!/usr/bin/env python3
"""Static check of the cloud's induced-dipole near field (issue: dielectric
parcels): writes, for one configuration of two parcels, a chargedParticleFoam
case (directCoulomb far field + inducedDipole near field + applied field,
parcels held by a huge density) and the bemElectrostatics dictionary of the
same configuration (model inducedDipole), or compares their forces and
torques.

  polarisationStatic.py write <case> <config>
  polarisationStatic.py compare <case> <config>    -> PASS/FAIL line

Configurations: spheres (unequal radii, permittivities and charges),
prolateSide, prolateTip, prolateOblique (prolate spheroids a/b = 3 in three
orientations). All with an applied field.
"""
import glob
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import heldCloud  # noqa: E402

E_APPLIED = (1e5, 2e5, -5e4)     # [V/m]

CONFIGS = {
    # name: list of (centre [m], semiAxes [m], eulerAngles [deg], epsilonR, q [C])
    "spheres": [
        ((-1.0e-4, 0, 0), (5e-5, 5e-5, 5e-5), (0, 0, 0), 4.0, 2e-13),
        ((0.6e-4, 0.1e-4, 0), (1e-4, 1e-4, 1e-4), (0, 0, 0), 10.0, -5e-13),
    ],
    "prolateSide": [
        ((-0.6e-4, 0, 0), (1.5e-4, 5e-5, 5e-5), (90, 0, 0), 5.0, 1e-13),
        ((0.6e-4, 0, 0), (1.5e-4, 5e-5, 5e-5), (90, 0, 0), 5.0, -1e-13),
    ],
    "prolateTip": [
        ((-1.6e-4, 0, 0), (1.5e-4, 5e-5, 5e-5), (0, 0, 0), 5.0, 1e-13),
        ((1.6e-4, 0, 0), (1.5e-4, 5e-5, 5e-5), (0, 0, 0), 5.0, 1e-13),
    ],
    "prolateOblique": [
        ((-1.2e-4, 0.2e-4, 0), (1.5e-4, 5e-5, 5e-5), (30, 40, 10), 5.0, 1e-13),
        ((1.2e-4, -0.2e-4, 0.3e-4), (1.5e-4, 5e-5, 5e-5), (70, 20, 50), 20.0, 0.0),
    ],
}

ELECTROSTATICS = """    electrostaticsModel directCoulomb;
    appliedField (%r %r %r);
    directCoulombCoeffs
    {
        epsilonR 1;
        nearField { type inducedDipole; rNear 1; tolerance 1e-14; }
    }
"""

BEM = """FoamFile {{ version 2.0; format ascii; class dictionary; object bemElectrostaticsDict; }}
kappa0 1;
externalField ({ex} {ey} {ez});
models (inducedDipole);
interactionEnergy no;
writeVtk no;
outputDir "postProcessing/bemElectrostatics";
particles
{{
{particles}
}}
"""


def vec(v):
    return "(%s)" % " ".join("%.17g" % x for x in v)


def write(case, config):
    parts = CONFIGS[config]
    parcels = "\n".join(
        "                { position %s; semiAxes %s; eulerAngles %s; epsilonR %.17g; q %.17g; }"
        % (vec(c), vec(s), vec(e), k, q) for c, s, e, k, q in parts)
    open(os.path.join(case, "constant/cloudProperties"), "w").write(
        heldCloud.cloudProperties(ELECTROSTATICS % E_APPLIED, parcels))
    ex, ey, ez = E_APPLIED
    particles = "\n".join(
        "    p%d { centre %s; orientation { type euler; angles %s; } semiAxes %s;"
        " kappa %.17g; charge %.17g; }" % (i, vec(c), vec(e), vec(s), k, q)
        for i, (c, s, e, k, q) in enumerate(parts))
    open(os.path.join(case, "system/bemElectrostaticsDict"), "w").write(
        BEM.format(ex=ex, ey=ey, ez=ez, particles=particles))


def compare(case, config):
    f = sorted(glob.glob(os.path.join(
        case, "postProcessing/lagrangian/cloud/particleHistory/*/particleHistory.dat")))[0]
    header = open(f).readlines()[1].lstrip("# ").split()
    h = np.loadtxt(f, ndmin=2)
    h = h[h[:, 0] == h[0, 0]]            # the first step
    col = {k: i for i, k in enumerate(header)}
    Fc = h[:, [col["fEx"], col["fEy"], col["fEz"]]]
    Mc = h[:, [col["tEx"], col["tEy"], col["tEz"]]]
    d = np.loadtxt(os.path.join(case, "postProcessing/bemElectrostatics/inducedDipole.dat"), ndmin=2)[0]
    n = len(CONFIGS[config])
    Fu = np.array([d[4 + 6*i: 7 + 6*i] for i in range(n)])
    Mu = np.array([d[7 + 6*i: 10 + 6*i] for i in range(n)])
    eF = np.abs(Fc - Fu).max()/np.abs(Fu).max()
    # Spheres have no torque (round-off only): the torque scale is then
    # force x size
    aMax = max(max(s) for _, s, _, _, _ in CONFIGS[config])
    eM = np.abs(Mc - Mu).max()/max(np.abs(Mu).max(), np.abs(Fu).max()*aMax)
    spheres = all(min(s) == max(s) for _, s, _, _, _ in CONFIGS[config])
    ok = eF < 1e-10 and eM < 1e-10 and (spheres or np.abs(Mu).max() > 1e-6*np.abs(Fu).max()*aMax)
    print("%s: polarisation.static.%s (cloud vs bemElectrostatics inducedDipole:"
          " max force difference %.2e, torque %.2e of the largest; tol 1e-10;"
          " |F| %.3e N, |M| %.3e N m)"
          % ("PASS" if ok else "FAIL", config, eF, eM, np.abs(Fu).max(), np.abs(Mu).max()))
    return 0 if ok else 1


if __name__ == "__main__":
    what, case, config = sys.argv[1:4]
    sys.exit(write(case, config) if what == "write" else compare(case, config))
