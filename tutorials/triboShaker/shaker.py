#!/usr/bin/python3
"""Charge vs time of the shaken PTFE spheres (Rasera 2022 section 4.2).

    shaker.py runs/d3.18 runs/d7.14 ...  [--png shaker.png]

Reads postProcessing/.../chargeBalance.dat of each run; prints PASS/FAIL
lines (particles + walls balance; charge monotonic towards and never beyond
the saturation charge q_sat = eps0 Gamma 4 pi r^2, Rasera Eq. 17) and a
table: q at the end, q/q_sat, time to 63 % of q_sat.
"""
import argparse, math, os, re
import numpy as np

eps0 = 8.8541878128e-12


def params(run):
    s = open(os.path.join(run, "constant", "cloudProperties")).read()
    d = float(re.search(r" d ([0-9.eE+-]+);", s).group(1))
    G = float(re.search(r"Gamma ([0-9.eE+-]+);", s).group(1))
    k = float(re.search(r'"\.\*" \{ kappaC ([0-9.eE+-]+);', s).group(1))
    return d, G, k


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("runs", nargs="+")
    ap.add_argument("--png")
    a = ap.parse_args()
    rows = []
    curves = []
    for run in a.runs:
        d, G, k = params(run)
        qsat = eps0*G*math.pi*d**2
        f = os.path.join(run, "postProcessing", "lagrangian", "cloud",
                         "triboCharging", "0", "chargeBalance.dat")
        x = np.loadtxt(f)
        header = [l for l in open(f) if l.startswith("# time")][0].split()[1:]
        t, q, bal = x[:, 0], x[:, 1], x[:, header.index("balance")]
        name = os.path.basename(run)
        drift = np.abs(bal - bal[0]).max()/max(np.abs(q).max(), 1e-300)
        print("%s: triboShaker.%s.balance (particles + walls drift %.1e of the charge)"
              % ("PASS" if drift < 1e-12 else "FAIL", name, drift))
        r = q/qsat
        mono = np.all(np.diff(r) >= -1e-12) and r.max() <= 1 + 1e-12 and r[-1] > 0
        print("%s: triboShaker.%s.saturation (q/q_sat rises monotonically to %.3f, never above 1)"
              % ("PASS" if mono else "FAIL", name, r[-1]))
        i63 = np.argmax(r >= 1 - math.exp(-1)) if (r >= 1 - math.exp(-1)).any() else None
        rows.append((d*1e3, G, k, qsat, q[-1], r[-1],
                     t[i63] if i63 is not None else float("nan"), t[-1]))
        curves.append((d, t, r))
    print()
    print("| d [mm] | Gamma [V/m] | kappa_c | q_sat (Eq. 17) [C] | q(t_end) [C] | q/q_sat | t(63 %) [s] | t_end [s] |")
    print("|---|---|---|---|---|---|---|---|")
    for row in rows:
        print("| %.2f | %.3g | %.3g | %.3e | %.3e | %.3f | %.2f | %g |" % row)
    if a.png:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        fig, ax = plt.subplots(figsize=(7, 4))
        for d, t, r in curves:
            ax.plot(t, r, label="%.2f mm" % (d*1e3))
        ax.axhline(1, color="k", lw=0.8, ls="--")
        ax.set_xlabel("shaking time [s]")
        ax.set_ylabel("q / q_sat")
        ax.set_title("PTFE in a grounded steel shaker, 30 Hz, 1 mm (Rasera Table 5)")
        ax.legend()
        ax.grid(alpha=0.3)
        fig.tight_layout()
        fig.savefig(a.png, dpi=120)


if __name__ == "__main__":
    main()
