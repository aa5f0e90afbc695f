#!/usr/bin/env python3
"""Write the bemElectrostatics dictionaries of the validation sweeps."""
import math, os, sys

quick = len(sys.argv) > 1 and sys.argv[1] == "quick"
os.makedirs("dicts", exist_ok=True)

HEAD = "FoamFile { version 2.0; format ascii; class dictionary; object bemElectrostaticsDict; }\n"


def particle(name, centre, axes, kappa, sigma, n, euler=(0, 0, 0), grading=None, charge=None,
             beta=0):
    g = "" if beta == 0 else "curvatureGrading %g;" % beta
    q = "sigmaF %g;" % sigma if charge is None else "charge %.16g;" % charge
    if grading:
        g += " grading { lambda %g; focus (%g %g %g); }" % (grading[0], *grading[1])
    return ("%s { centre (%g %g %g); orientation { type euler; angles (%g %g %g); }"
            " semiAxes (%g %g %g); kappa %g; %s nPatches %d; %s }\n"
            % (name, *centre, *euler, *axes, kappa, q, n, g))


os.makedirs("meta", exist_ok=True)


def write(name, body, gap0=0.0):
    with open(os.path.join("dicts", name), "w") as f:
        f.write(HEAD + body)
    with open(os.path.join("meta", name), "w") as f:   # sweep value 0 = gap0
        f.write("%g\n" % gap0)


# Torque on a neutral prolate spheroid (Ruan Fig. 8c); patches refined
# towards the tips (size ~ H^-0.5)
s3 = 3 ** -0.5
for a in ([1, 2, 5, 10] if quick else range(1, 11)):
    n = max(1000, 200 * a)
    write("torque_a%02d" % a,
          "kappa0 1; externalField (%.16g %.16g %.16g);\n" % (s3, s3, s3)
          + "models (bem); interactionEnergy no; writeVtk %s;\n" % ("yes" if a in (1, 10) else "no")
          + 'outputDir "postProcessing/torque_a%02d";\n' % a
          + "particles {\n" + particle("p", (0, 0, 0), (a, 1, 1), 2.5, 0, n, beta=0.5) + "}\n")

# Two charged spheres (Ruan Fig. 7): p2 starts at gap 0.05 R; free charge
# Q = 4 pi R^2 sigma exactly (sigma_f = Q/meshed area), as in the exact series
gaps = [0.05, 0.1, 0.2, 0.5, 1, 2, 3] if not quick else [0.05, 0.5, 2]
vals = " ".join("%g" % (g - gaps[0]) for g in gaps)
for kp in ([10, 40, 100] if not quick else [100]):
    for sgn in (1, -1):
        for n in ((500, 2000) if not quick else (500,)):
            tag = "spheres_k%d_%s_n%d" % (kp, "like" if sgn > 0 else "opp", n)
            write(tag,
                  "kappa0 1; models (bem%s); interactionEnergy yes; writeVtk no;\n"
                  % (" inducedDipole" if n == 500 else "")
                  + 'outputDir "postProcessing/%s";\n' % tag
                  + "particles {\n"
                  + particle("p1", (0, 0, 0), (1, 1, 1), kp, 1, n, grading=(0.35, (1, 0, 0)),
                             charge=4 * math.pi)
                  + particle("p2", (2 + gaps[0], 0, 0), (1, 1, 1), kp, sgn, n, euler=(180, 0, 0),
                             grading=(0.35, (1, 0, 0)), charge=sgn * 4 * math.pi)
                  + "}\nsweep { type translate; particle p2; direction (1 0 0); values (%s); }\n" % vals,
                  gaps[0])

# Two prolate spheroids a = 2, b = c = 1 (Ruan Figs. 9-10), approach along x
gaps = [0.05, 0.1, 0.2, 0.5, 1, 2] if not quick else [0.1, 1]
vals = " ".join("%g" % (g - gaps[0]) for g in gaps)
n = 1000 if not quick else 600
for cfg, (e1, e2, eu1, eu2) in {"headToTail": (2, 2, (0, 0, 0), (0, 0, 0)),
                                 "perpendicular": (2, 1, (0, 0, 0), (90, 0, 0)),
                                 "sideBySide": (1, 1, (90, 0, 0), (90, 0, 0))}.items():
    for sgn in (1, -1):
        tag = "prolates_%s_%s" % (cfg, "like" if sgn > 0 else "opp")
        write(tag,
              "kappa0 1; models (bem inducedDipole); interactionEnergy yes; writeVtk %s;\n"
              % ("yes" if sgn < 0 else "no")
              + 'outputDir "postProcessing/%s";\n' % tag
              + "particles {\n"
              + particle("p1", (0, 0, 0), (2, 1, 1), 10, 1, n, euler=eu1, beta=0.5)
              + particle("p2", (e1 + gaps[0] + e2, 0, 0), (2, 1, 1), 10, sgn, n, euler=eu2, beta=0.5)
              + "}\nsweep { type translate; particle p2; direction (1 0 0); values (%s); }\n" % vals,
              gaps[0])
