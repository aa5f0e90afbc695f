#!/usr/bin/python3
"""Many PTFE spheres shaken together (Rasera 2022 section 4.3, Figs. 10-14).

    multi.py --kappa RUN                 print kappa_c of particle pairs
    multi.py --kappa RUN --seeds RUN... --packing RUN... [--png multi.png]

--kappa: a run of the thirteen spheres whose chargeBalance.dat counts the
particle-particle impacts and the contact area they swept (each impact's
largest area A = pi R* delta); their mean is the dA of Rasera Eq. (23),
kappa_c = 4 pi r^2/dA (like, nearly neutral particles).
--seeds: repetitions of the thirteen-sphere run (different random starts):
bulk charge at the sampling times of Fig. 13, particle minimum, maximum and
mean (Fig. 11), the run-to-run spread and the bulk charge against the
idealised 13 q_sat (q_sat = eps0 Gamma 4 pi r^2, Eq. 17).
--packing: runs with different numbers of spheres (Fig. 14): the bulk charge
at the end as a fraction of N q_sat and the share of wall contacts among all
impacts, against the volume fraction.
Prints PASS/FAIL lines: particles + walls balance to round-off in every
run, every bulk charge between N q_sat and 0, and (with three or more
packings) both Fig. 14 quantities lower at the largest volume fraction than
at the smallest.
"""
import argparse
import glob
import math
import os
import re

import numpy as np

eps0 = 8.8541878128e-12
R, H = 30e-3, 60e-3                     # the capsule (radius, height)
SAMPLES = [0, 1, 3, 5, 10, 20, 30, 60]  # Rasera Fig. 13 [s]


def balance(run):
    f = os.path.join(run, "postProcessing/lagrangian/cloud/triboCharging/0/chargeBalance.dat")
    head = [l for l in open(f) if l.startswith("# time")][0].split()[1:]
    d = np.loadtxt(f, ndmin=2)
    return {h: d[:, i] for i, h in enumerate(head)}


def params(run):
    s = open(os.path.join(run, "constant/cloudProperties")).read()
    G = float(re.search(r'"\.\*" \{ kappaC [0-9.eE+-]+; Gamma ([0-9.eE+-]+);', s).group(1))
    p = open(os.path.join(run, "constant/parcels")).read()
    d = [float(x) for x in re.findall(r" d ([0-9.eE+-]+);", p)]
    return G, d


def history(run):
    """Per-particle charge over time: times, q[time, particle]."""
    files = sorted(glob.glob(os.path.join(run, "postProcessing/lagrangian/cloud/particleHistory/*/particleHistory.dat")))
    h = np.vstack([np.loadtxt(f, ndmin=2) for f in files])
    times = np.unique(h[:, 0])
    ids = np.unique(h[:, 2])
    q = np.full((len(times), len(ids)), np.nan)
    ti = np.searchsorted(times, h[:, 0])
    pi = np.searchsorted(ids, h[:, 2])
    q[ti, pi] = h[:, 11]
    return times, q


def kappa(run):
    b = balance(run)
    n, area = b["nPairImpacts"].sum(), b["pairImpactArea"].sum()
    G, d = params(run)
    r = 0.5*d[0]
    dA = area/n
    return 4*math.pi*r*r/dA, dA, int(n)


def check(ok, name, detail):
    print(f"{'PASS' if ok else 'FAIL'}: triboShaker.multi.{name} ({detail})")
    return ok


checked = set()


def runChecks(run):
    b = balance(run)
    G, d = params(run)
    qsat = sum(eps0*G*math.pi*x*x for x in d)
    q = b["parcels"]
    drift = np.abs(b["balance"] - b["balance"][0]).max()/max(np.abs(q).max(), 1e-300)
    name = os.path.basename(os.path.normpath(run))
    if name in checked:
        return b, qsat, d
    checked.add(name)
    check(drift < 1e-12, f"{name}.balance", f"particles + walls drift {drift:.1e} of the charge")
    inside = np.all(q <= 1e-12*abs(qsat)) and np.all(q >= qsat*(1 + 1e-9))
    check(inside, f"{name}.bounds", f"bulk charge from {q.min():.3e} to {q.max():.3e} C, "
          f"between N q_sat = {qsat:.3e} C and 0")
    return b, qsat, d


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--kappa", required=True)
    ap.add_argument("--seeds", nargs="*", default=[])
    ap.add_argument("--packing", nargs="*", default=[])
    ap.add_argument("--png")
    a = ap.parse_args()

    k, dA, n = kappa(a.kappa)
    if not a.seeds and not a.packing:
        print(f"{k:.6g}")
        return
    G, d = params(a.kappa)
    r = 0.5*d[0]
    print(f"Particle-particle kappa_c (Rasera Eq. 23): {n} impacts in the "
          f"{balance(a.kappa)['time'][-1]:.3g}-s run of {len(d)} spheres, mean "
          f"largest contact area dA = {dA:.4e} m2, kappa_c = 4 pi r^2/dA = {k:.0f} "
          f"(Rasera: about 3600)")
    runChecks(a.kappa)

    # Thirteen spheres, several seeds: Figs. 10, 11, 13
    curves = []
    table = {}
    for run in a.seeds:
        b, qsat, d = runChecks(run)
        t, q = b["time"], b["parcels"]
        tb = [tt for tt in SAMPLES if tt <= t[-1] + 1e-9]
        table[run] = [q[np.argmin(np.abs(t - tt))] if tt > 0 else 0.0 for tt in tb]
        curves.append((run, t, q, qsat))
    if a.seeds:
        run0 = a.seeds[0]
        th, qh = history(run0)
        qsat = curves[0][3]
        N = qh.shape[1]
        print()
        print(f"Bulk charge of {N} spheres [nC] at the sampling times of Rasera "
              f"Fig. 13 ({len(a.seeds)} runs; idealised bulk charge N q_sat = "
              f"{qsat*1e9:.2f} nC, q_sat = eps0 Gamma 4 pi r^2 = {qsat/N*1e9:.3f} nC); "
              f"particles of the first run: minimum, maximum, mean [nC] (Fig. 11)")
        print()
        names = [os.path.basename(os.path.normpath(r)) for r in a.seeds]
        print("| t [s] | " + " | ".join(names) + " | mean | spread (max - min) | bulk / N q_sat "
              "| particle min | particle max | particle mean |")
        print("|---" * (len(names) + 7) + "|")
        tb = [tt for tt in SAMPLES if tt <= min(c[1][-1] for c in curves) + 1e-9]
        for j, tt in enumerate(tb):
            vals = np.array([table[r][j] for r in a.seeds])
            i = np.argmin(np.abs(th - tt))
            qp = qh[i] if tt > 0 else np.zeros(N)
            print(f"| {tt:g} | " + " | ".join(f"{v*1e9:.3f}" for v in vals)
                  + f" | {vals.mean()*1e9:.3f} | {(vals.max() - vals.min())*1e9:.3f}"
                  f" | {vals.mean()/qsat + 0.0:.3f} | {qp.min()*1e9:.3f} | {qp.max()*1e9:.3f}"
                  f" | {qp.mean()*1e9:.3f} |")

    # Packing: Fig. 14
    rows = []
    for run in a.packing:
        b, qsat, d = runChecks(run)
        N = len(d)
        phi = sum(math.pi/6*x**3 for x in d)/(math.pi*R*R*H)
        nW, nP = b["nWallImpacts"].sum(), b["nPairImpacts"].sum()
        rows.append((phi, N, b["parcels"][-1]/qsat, nW/(nW + nP), b["time"][-1]))
    rows.sort()
    if rows:
        print()
        print("Packing (Rasera Fig. 14): bulk charge at the end over N q_sat, and the"
              " share of particle-wall impacts, against the volume fraction")
        print()
        print("| N | volume fraction | t_end [s] | bulk / N q_sat | wall impacts / all impacts |")
        print("|---|---|---|---|---|")
        for phi, N, f, w, te in rows:
            print(f"| {N} | {phi:.4f} | {te:g} | {f:.3f} | {w:.3f} |")
        if len(rows) >= 3:
            check(rows[-1][2] < rows[0][2], "packingCharge",
                  f"bulk / N q_sat falls from {rows[0][2]:.3f} at volume fraction "
                  f"{rows[0][0]:.4f} to {rows[-1][2]:.3f} at {rows[-1][0]:.4f}")
        if len(rows) >= 2:
            check(rows[-1][3] < rows[0][3], "packingWallShare",
                  f"wall impacts / all falls from {rows[0][3]:.3f} to {rows[-1][3]:.3f}")

    if a.png:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        fig, axs = plt.subplots(1, 3, figsize=(15, 4.2))
        ax = axs[0]
        for run, t, q, qsat in curves:
            ax.plot(t, q*1e9, lw=0.8, label=os.path.basename(os.path.normpath(run)))
            ts = [tt for tt in SAMPLES if tt <= t[-1] + 1e-9]
            ax.plot(ts, [0 if tt == 0 else q[np.argmin(np.abs(t - tt))]*1e9 for tt in ts], "ko", ms=3)
        if curves:
            ax.axhline(curves[0][3]*1e9, color="k", ls="--", lw=0.8, label="13 q_sat")
        ax.set_xlabel("shaking time [s]"); ax.set_ylabel("bulk charge [nC]")
        ax.set_title("13 PTFE spheres, 12.7 mm (Fig. 13)"); ax.legend(fontsize=8); ax.grid(alpha=0.3)
        ax = axs[1]
        if a.seeds:
            ax.fill_between(th, np.nanmin(qh, axis=1)*1e9, np.nanmax(qh, axis=1)*1e9, alpha=0.3, label="min - max")
            ax.plot(th, np.nanmean(qh, axis=1)*1e9, "k-", lw=1, label="mean")
            ax.axhline(qsat/qh.shape[1]*1e9, color="k", ls="--", lw=0.8, label="q_sat")
        ax.set_xlabel("shaking time [s]"); ax.set_ylabel("particle charge [nC]")
        ax.set_title("Particle charges, first run (Fig. 11)"); ax.legend(fontsize=8); ax.grid(alpha=0.3)
        ax = axs[2]
        if rows:
            phis = [x[0] for x in rows]
            ax.plot(phis, [x[2] for x in rows], "o-", label="bulk / N q_sat")
            ax.plot(phis, [x[3] for x in rows], "s-", label="wall impacts / all")
            for phi, N, f, w, te in rows:
                ax.annotate(str(N), (phi, f), textcoords="offset points", xytext=(3, 3), fontsize=8)
        ax.set_xlabel("volume fraction"); ax.set_ylim(0, 1.05)
        ax.set_title("Packing (Fig. 14)"); ax.legend(fontsize=8); ax.grid(alpha=0.3)
        fig.tight_layout(); fig.savefig(a.png, dpi=110)


if __name__ == "__main__":
    main()
