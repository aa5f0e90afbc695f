#!/usr/bin/env python3
"""Tables and plots of the BEM validation sweeps (run by Allrun).

References computed here, independently of the C++ code:
  - Ruan Eqs. 49-50: torque on a dielectric ellipsoid in a uniform field,
    depolarisation factors by numerical quadrature;
  - Coulomb's law for the two-sphere forces (kappa_p -> 1 limit);
  - the exact two-sphere multipole series (etc/python/twoDielectricSpheres.py).
"""
import glob, math, os
import sys
import numpy as np
sys.path.insert(0, os.path.join(os.environ.get("CHARGEDFOAM_DIR", ""), "etc", "python"))
import twoDielectricSpheres
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

eps0 = 8.8541878128e-12
PP = "postProcessing"


def exactForce(gap, kp, sgn):
    # R = 1, free surface charge density 1 and sgn: Q = 4 pi, sgn 4 pi
    Q = 4 * math.pi
    return twoDielectricSpheres.force(Q, sgn * Q, 1.0, 1.0, 2 + gap, kp, kp)


def load(path):
    return np.atleast_2d(np.loadtxt(path, comments="#"))


def depol(a, b, c):
    # Eq. 50, s = t^2/(1-t)^2 ... use s = exp(u), trapezoid on a wide range
    u = np.linspace(-30, 30, 200001)
    s = np.exp(u)
    Rs = np.sqrt((s + a * a) * (s + b * b) * (s + c * c))
    L = [a * b * c / 2 * np.trapz(s / ((s + k * k) * Rs), u) for k in (a, b, c)]
    return np.array(L)


def torque49(a, b, c, kt, E):
    L = depol(a, b, c)
    pref = 4 * math.pi * eps0 * a * b * c / 3 * (kt - 1) ** 2
    d = 1 + (kt - 1) * L
    return np.array([pref * (L[2] - L[1]) * E[2] * E[1] / (d[2] * d[1]),
                     pref * (L[0] - L[2]) * E[0] * E[2] / (d[0] * d[2]),
                     pref * (L[1] - L[0]) * E[1] * E[0] / (d[1] * d[0])])


# ---------------------------------------------------------------- torque
rows = []
for f in sorted(glob.glob(PP + "/torque_a*/bem.dat")):
    a = int(f.split("torque_a")[1][:2])
    d = load(f)[0]
    M = d[7:10]
    E = np.ones(3) / math.sqrt(3)
    Mex = torque49(a, 1, 1, 2.5, E)
    M0 = 4 * math.pi * eps0 / 3
    rows.append((a, M / M0, Mex / M0))
if rows:
    print("## Torque on a neutral prolate spheroid, kp 2.5, E0 [1,1,1]/sqrt(3) (Ruan Fig. 8c); curvature-graded meshes (size ~ H^-0.5)")
    print("| a | n | My/M0 BEM | Eq. 49 | rel. err | Mz/M0 BEM | Eq. 49 | rel. err | |Mx|/|M| |")
    print("|---|---|---|---|---|---|---|---|---|")
    for a, M, Mex in rows:
        n = max(1000, 200 * a)
        ey = M[1] / Mex[1] - 1 if a > 1 else float("nan")
        ez = M[2] / Mex[2] - 1 if a > 1 else float("nan")
        print("| %d | %d | %.5f | %.5f | %+.4f | %.5f | %.5f | %+.4f | %.1e |"
              % (a, n, M[1], Mex[1], ey, M[2], Mex[2], ez,
                 abs(M[0]) / max(np.linalg.norm(M), 1e-300)))
    plt.figure(figsize=(5, 4))
    A = [r[0] for r in rows]
    aa = np.linspace(1, max(A), 100)
    ex = np.array([torque49(x, 1, 1, 2.5, np.ones(3) / math.sqrt(3)) for x in aa]) / (4 * math.pi * eps0 / 3)
    for k, lab in enumerate("xyz"):
        plt.plot(aa, ex[:, k], "-", label="Eq. 49 M_%s" % lab)
        plt.plot(A, [r[1][k] for r in rows], "o", label="BEM M_%s" % lab)
    plt.xlabel("a/b"); plt.ylabel("M/M0"); plt.legend(fontsize=7); plt.tight_layout()
    plt.savefig("torque.png", dpi=120)
    print()

# ---------------------------------------------------------------- spheres
F0 = math.pi / eps0
cases = sorted(set(os.path.basename(p).rsplit("_n", 1)[0] for p in glob.glob(PP + "/spheres_*")))
if cases:
    print("## Two charged spheres R = 1, sigma_f 1 and +-1 (Ruan Fig. 7): F/|F0| on sphere 2, F0 = pi R^2 sigma^2/eps0")
    print("| kp | charges | d/R | BEM n500 | BEM n2000 | est. rel. error n2000 (= |n2000 - n500|/3) | exact series | BEM/exact - 1 (finest) | dipole model | Coulomb |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    fig, axs = plt.subplots(1, 2, figsize=(9, 4))
    for c in cases:
        kp = int(c.split("_k")[1].split("_")[0])
        like = c.endswith("like")
        lo = load(PP + "/%s_n500/bem.dat" % c)
        hi = PP + "/%s_n2000/bem.dat" % c
        hi = load(hi) if os.path.exists(hi) else None
        dm = load(PP + "/%s_n500/inducedDipole.dat" % c)
        gap = lo[:, 1] + float(open("meta/%s_n500" % c).read())
        sgn = 1 if like else -1
        coul = sgn * (4 * math.pi) ** 2 / (4 * math.pi * eps0 * (2 + gap) ** 2) / F0
        for i, g in enumerate(gap):
            fl = lo[i, 10] / F0
            fh = hi[i, 10] / F0 if hi is not None else float("nan")
            fe = exactForce(g, kp, sgn) / F0
            fb = fh if hi is not None else fl
            print("| %d | %s | %.2f | %.4f | %.4f | %.4f | %.4f | %+.4f | %.4f | %.4f |"
                  % (kp, "like" if like else "opposite", g, fl, fh,
                     abs(fh - fl) / 3 / abs(fh) if hi is not None else float("nan"),
                     fe, fb / fe - 1, dm[i, 10] / F0, coul[i]))
        ax = axs[0 if like else 1]
        best = hi if hi is not None else lo
        ax.plot(gap, best[:, 10] / F0, "o-", label="BEM kp %d" % kp)
        ax.plot(gap, dm[:, 10] / F0, "--", label="dipole kp %d" % kp)
        ge = np.linspace(0.05, 3, 40)
        ax.plot(ge, [exactForce(x, kp, sgn) / F0 for x in ge], ":", label="exact kp %d" % kp)
    for k, ax in enumerate(axs):
        g = np.linspace(0.05, 3, 100)
        ax.plot(g, (1 if k == 0 else -1) * 4 * math.pi / (eps0 * (2 + g) ** 2) / F0, "k-", label="Coulomb")
        ax.set_xlabel("d/R"); ax.set_ylabel("F/|F0|"); ax.legend(fontsize=6)
        ax.set_title("like charges" if k == 0 else "opposite charges")
    plt.tight_layout(); plt.savefig("spheres.png", dpi=120)
    print("(estimated error: Richardson-type |F_2000 - F_500|/3 for first-order convergence in 1/n^(1/2) ~ h"
          " with h ratio 2)")
    print()

# ---------------------------------------------------------------- prolates
pro = sorted(glob.glob(PP + "/prolates_*"))
if pro:
    print("## Two prolate spheroids a = 2, b = c = 1, kp 10 (Ruan Figs. 9-10): F/|F0|, F0 = pi c^2 sigma^2/eps0;"
          " interaction energy U/(sigma^2 c^3/eps0)")
    print("| configuration | charges | d/c | F/|F0| BEM | F/|F0| dipole model | U_int BEM | U dipole model |")
    print("|---|---|---|---|---|---|---|")
    fig, axs = plt.subplots(1, 2, figsize=(9, 4))
    for p in pro:
        name = os.path.basename(p)[len("prolates_"):]
        cfg, ch = name.rsplit("_", 1)
        b = load(p + "/bem.dat")
        dmf = p + "/inducedDipole.dat"
        dm = load(dmf) if os.path.exists(dmf) else None
        gaps = b[:, 1] + float(open("meta/" + os.path.basename(p)).read())
        for i, g in enumerate(gaps):
            print("| %s | %s | %.2f | %.4f | %.4f | %.4f | %.4f |"
                  % (cfg, ch, g, b[i, 10] / F0, dm[i, 10] / F0 if dm is not None else float("nan"),
                     b[i, 3] * eps0, dm[i, 3] * eps0 if dm is not None else float("nan")))
        if ch == "opp":
            axs[0].plot(gaps, b[:, 10] / F0, "o-", label=cfg)
        axs[1].plot(gaps, b[:, 3] * eps0, "o-", label="%s %s" % (cfg, ch))
    axs[0].set_xlabel("d/c"); axs[0].set_ylabel("F/|F0| (opposite charges)"); axs[0].legend(fontsize=7)
    axs[1].set_xlabel("d/c"); axs[1].set_ylabel("U_int eps0/(sigma^2 c^3)"); axs[1].legend(fontsize=6)
    plt.tight_layout(); plt.savefig("prolates.png", dpi=120)
