#!/usr/bin/env python3
"""The induced-dipole rung against surface-resolved BEM (and, for spheres,
the exact multipole series): force and torque ratios against the gap.

Static configurations, swept with bemElectrostatics (models bem and
inducedDipole; the inducedDipole model is the cloud's near-field kernel):

  spheresLike     radii 1 and 2, epsilonR 10, like charges q2 = 30 q1 (the
                  polarisation attraction of unequal charges)
  spheresOpposite radii 1 and 2, epsilonR 10, opposite charges q2 = -2 q1
  prolatesSide    prolates a = 2, b = c = 1, epsilonR 10, side by side,
                  opposite charges
  prolatesTilted  neutral prolates at 30 and 60 degrees to an applied field
                  along x, side by side: the torque on each

Gap in units of the smaller semi-axis. Prints markdown tables (ratio of the
dipole model to BEM; for spheres also BEM and the dipole model against the
exact series, etc/python/twoDielectricSpheres.py).

    dipoleVsBem.py [--patches 1200] [--gaps 0.05,0.1,0.2,0.5,1,2]
"""
import argparse
import math
import os
import subprocess
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.abspath(os.path.join(HERE, "..", "..", ".."))
sys.path.insert(0, os.path.join(ROOT, "etc", "python"))
import twoDielectricSpheres as tds  # noqa: E402

HEAD = "FoamFile { version 2.0; format ascii; class dictionary; object bemElectrostaticsDict; }\n"


def particle(name, centre, axes, kappa, charge, n, euler=(0, 0, 0), grading=None, beta=0.0):
    g = "curvatureGrading %g;" % beta if beta else ""
    if grading:
        g += " grading { lambda %g; focus (%g %g %g); }" % (grading[0], *grading[1])
    return ("%s { centre (%.16g %.16g %.16g); orientation { type euler; angles (%g %g %g); }"
            " semiAxes (%g %g %g); kappa %g; charge %.16g; nPatches %d; %s }\n"
            % (name, *centre, *euler, *axes, kappa, charge, n, g))


def run(case, name, body):
    d = os.path.join(case, name)
    os.makedirs(os.path.join(d, "system"), exist_ok=True)
    open(os.path.join(d, "system", "bemElectrostaticsDict"), "w").write(HEAD + body)
    with open(os.path.join(d, "log.bemElectrostatics"), "w") as f:
        subprocess.run(["bemElectrostatics", "-case", d], stdout=f, stderr=subprocess.STDOUT, check=True)
    out = os.path.join(d, "postProcessing", "bemElectrostatics")
    return (np.loadtxt(os.path.join(out, "bem.dat"), ndmin=2),
            np.loadtxt(os.path.join(out, "inducedDipole.dat"), ndmin=2))


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--patches", type=int, default=1200)
    ap.add_argument("--gaps", default="0.05,0.1,0.2,0.5,1,2")
    args = ap.parse_args()
    gaps = [float(g) for g in args.gaps.split(",")]
    vals = " ".join("%.16g" % (g - gaps[0]) for g in gaps)
    case = os.path.join(HERE, "runs", "dipoleVsBem")
    n = args.patches
    sweep = "sweep { type translate; particle p2; direction (1 0 0); values (%s); }\n" % vals
    common = "kappa0 1; models (bem inducedDipole); interactionEnergy no; writeVtk no;\n"
    # Columns: step value U Uint then per particle Fx Fy Fz Mx My Mz
    F2x = lambda t: t[:, 4 + 6]

    print("Dipole rung against BEM (%d patches per particle, graded towards the"
          " neighbour / the tips); gap in units of the smaller semi-axis\n" % n)

    q1 = 4*math.pi*8.8541878128e-12       # unit potential scale
    for name, q2 in (("spheresLike", 30*q1), ("spheresOpposite", -2*q1)):
        bem, dip = run(case, name, common + "particles {\n"
                       + particle("p1", (0, 0, 0), (1, 1, 1), 10, q1, n, grading=(0.35, (1, 0, 0)))
                       + particle("p2", (3 + gaps[0], 0, 0), (2, 2, 2), 10, q2, n, euler=(180, 0, 0),
                                  grading=(0.35, (1, 0, 0)))
                       + "}\n" + sweep)
        print("%s (radii 1 and 2, epsilonR 10, q2/q1 = %g): force on sphere 2 along the line\n" % (name, q2/q1))
        print("| gap | F_bem | F_dipole/F_bem |" + " F_bem/F_exact | F_dipole/F_exact |")
        print("| --- | --- | --- |" + " --- | --- |")
        for k, g in enumerate(gaps):
            row = "| %g | %+.4e | %.3f |" % (g, F2x(bem)[k], F2x(dip)[k]/F2x(bem)[k])
            fe = tds.force(q1, q2, 1.0, 2.0, 3 + g, 10, 10)
            row += " %.4f | %.3f |" % (F2x(bem)[k]/fe, F2x(dip)[k]/fe)
            print(row)
        print()

    bem, dip = run(case, "prolatesSide", common + "particles {\n"
                   + particle("p1", (0, 0, 0), (2, 1, 1), 10, q1, n, euler=(90, 0, 0), beta=0.5)
                   + particle("p2", (2 + gaps[0], 0, 0), (2, 1, 1), 10, -q1, n, euler=(90, 0, 0), beta=0.5)
                   + "}\n" + sweep)
    print("prolatesSide (a = 2, b = c = 1, epsilonR 10, side by side, opposite charges): force on p2 along the line\n")
    print("| gap | F_bem | F_dipole/F_bem |")
    print("| --- | --- | --- |")
    for k, g in enumerate(gaps):
        print("| %g | %+.4e | %.3f |" % (g, F2x(bem)[k], F2x(dip)[k]/F2x(bem)[k]))
    print()

    bem, dip = run(case, "prolatesTilted",
                   "kappa0 1; externalField (1 0 0); models (bem inducedDipole); interactionEnergy no;"
                   " writeVtk no;\nparticles {\n"
                   + particle("p1", (0, 0, 0), (2, 1, 1), 10, 0, n, euler=(30, 0, 0), beta=0.5)
                   + particle("p2", (3.2 + gaps[0], 0, 0), (2, 1, 1), 10, 0, n, euler=(60, 0, 0), beta=0.5)
                   + "}\n" + sweep)
    Mz = lambda t, i: t[:, 4 + 6*i + 5]
    print("prolatesTilted (neutral, at 30 and 60 degrees to a field along x, centres 3.2 + s apart; they touch at 3.12): torque M_z\n")
    print("| s | M1_bem | M1_dipole/M1_bem | M2_bem | M2_dipole/M2_bem |")
    print("| --- | --- | --- | --- | --- |")
    for k, g in enumerate(gaps):
        print("| %g | %+.4e | %.3f | %+.4e | %.3f |" % (g, Mz(bem, 0)[k], Mz(dip, 0)[k]/Mz(bem, 0)[k],
                                                    Mz(bem, 1)[k], Mz(dip, 1)[k]/Mz(bem, 1)[k]))


if __name__ == "__main__":
    main()
