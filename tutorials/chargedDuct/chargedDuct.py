#!/usr/bin/python3
"""Post-process the chargedDuct tutorial: charge build-up, particle charge
distribution and the electric field.

Reads the charge balance of the contact charging (postProcessing/lagrangian/
cloud/triboCharging/0/chargeBalance.dat), the parcel charges q and fields E
of every time directory, and the mesh field E (volume field of the mesh far
field) of the last time. Writes chargeBuildUp.png, chargeDistribution.png,
field.png and prints a summary (results.txt via Allrun).

The saturation charge of a particle is q_sat = eps0 Gamma S (Rasera 2022
Eq. 17 with the surface S of the ellipsoid in place of 4 pi r^2).

    chargedDuct.py [caseDir] [otherCaseDir]   (the second: compare runs)
"""
import os
import re
import sys

import numpy as np
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(here, "..", "..", "etc", "python"))
from foamLagrangian import read_field, read_internal_field  # noqa: E402

EPS0 = 8.8541878128e-12


def ellipsoid_area(a, b, c, n=400):
    """Surface area by midpoint quadrature of the parametric surface."""
    u = (np.arange(n) + 0.5)*np.pi/n             # polar
    v = (np.arange(2*n) + 0.5)*np.pi/n           # azimuth
    U, V = np.meshgrid(u, v, indexing="ij")
    su, cu, sv, cv = np.sin(U), np.cos(U), np.sin(V), np.cos(V)
    # |r_u x r_v| for r = (a su cv, b su sv, c cu)
    nx = b*c*su**2*cv
    ny = a*c*su**2*sv
    nz = a*b*su*cu
    return np.sum(np.sqrt(nx**2 + ny**2 + nz**2))*(np.pi/n)**2


def case_params(case):
    """Gamma (constant/cloudProperties), the parcels' semi-axes (constant/
    parcels), the cells and size of the duct (system/blockMeshDict), and
    q_sat = eps0 |Gamma| S."""
    cloud = open(os.path.join(case, "constant", "cloudProperties")).read()
    gamma = float(re.search(r"Gamma\s+([-0-9.eE+]+)\s*;", cloud).group(1))
    parcels = open(os.path.join(case, "constant", "parcels")).read()
    axes = [float(v) for v in
            re.search(r"semiAxes\s*\(([^)]*)\)", parcels).group(1).split()]
    mesh = open(os.path.join(case, "system", "blockMeshDict")).read()
    cells = [int(v) for v in
             re.search(r"hex\s*\([^)]*\)\s*\(([^)]*)\)", mesh).group(1).split()]
    verts = re.search(r"vertices\s*\((.*?)\);", mesh, re.S).group(1)
    pts = np.array([[float(v) for v in t.split()]
                    for t in re.findall(r"\(([^()]*)\)", verts)])
    return {"Gamma": gamma, "axes": axes, "cells": cells,
            "size": pts.max(axis=0) - pts.min(axis=0),
            "qSat": EPS0*abs(gamma)*ellipsoid_area(*axes)}


def times(case):
    t = [d for d in os.listdir(case)
         if re.fullmatch(r"[0-9.eE+-]+", d) and float(d) > 0
         and os.path.isdir(os.path.join(case, d, "lagrangian", "cloud"))]
    return sorted(t, key=float)


def parcel_q(case, t):
    return read_field(os.path.join(case, t, "lagrangian", "cloud", "q"))


def balance(case):
    p = os.path.join(case, "postProcessing", "lagrangian", "cloud",
                     "triboCharging", "0", "chargeBalance.dat")
    return np.loadtxt(p, comments="#")


def summary(case):
    ts = times(case)
    q = [parcel_q(case, t) for t in ts]
    b = balance(case)
    last = q[-1]
    qSat = case_params(case)["qSat"]
    U = read_field(os.path.join(case, ts[-1], "lagrangian", "cloud", "U"))
    return ts, q, b, {
        "U": U.mean(axis=0),
        "UxStd": U[:, 0].std(),
        "qSat": qSat,
        "time": float(ts[-1]),
        "parcels": len(last),
        "parcels0": len(q[0]),
        "total": last.sum(),
        "mean": last.mean()/qSat,
        "std": last.std()/qSat,
        "balance": np.abs(b[:, 3]).max()/max(np.abs(b[:, 1]).max(), 1e-300),
        "wallContacts": b[:, 5].sum(),
    }


def report(s, name="chargedDuct"):
    """Print the summary s of summary() (results.txt)."""
    print(f"{name}: {s['parcels']} parcels at t = {s['time']:g} s "
          f"({s['parcels0']} at the first write)")
    print(f"  q_sat = eps0 |Gamma| S = {s['qSat']:.4g} C per particle")
    print(f"  total parcel charge {s['total']:.4g} C; mean q/q_sat = "
          f"{s['mean']:.4f}, std {s['std']:.4f}")
    print(f"  charge balance (parcels + walls) / max |parcel charge| <= "
          f"{s['balance']:.1e}; charging wall contacts {s['wallContacts']:.0f}")
    print(f"  parcel velocity: mean {np.array2string(s['U'], precision=4)} m/s,"
          f" std of U_x {s['UxStd']:.4f} m/s")


def report_field(maxE, Ep):
    """Print the largest |E| of the mesh and the mean |E| at the parcels Ep
    (of mid_plane_field())."""
    print(f"  field: max |E| on the mesh {maxE:.4g} V/m; "
          f"at the parcels mean {Ep.mean():.4g}"
          f" V/m (breakdown of air ~3e6 V/m)")


def plot_build_up(ax, b, ts, q, N, qSat):
    """Charge build-up on ax: minus the parcel charge and the wall charge
    per N q_sat (chargeBalance.dat b), minus the mean parcel charge per q_sat
    at the written times ts (charges q)."""
    ax.plot(b[:, 0], -b[:, 1]/(N*qSat), label="-(parcel charge)/(N q_sat)")
    ax.plot(b[:, 0], b[:, 2]/(N*qSat), "--", label="wall charge/(N q_sat)")
    tq = [float(t) for t in ts]
    ax.plot(tq, [-x.mean()/qSat for x in q], "o", label="-mean q/q_sat")
    ax.set_xlabel("t [s]")
    ax.set_ylabel("charge / saturation")


def plot_charge_balance(ax, b, unit=1e-9, unitName="nC"):
    """Signed charges of chargeBalance.dat b on ax: the parcels, the walls
    and their sum with the outflow (zero: contact charging conserves
    charge)."""
    ax.plot(b[:, 0], b[:, 1]/unit, label="particles")
    ax.plot(b[:, 0], b[:, 2]/unit, "--", label="walls (grounded)")
    ax.plot(b[:, 0], b[:, 3]/unit, ":", color="k",
            label=f"particles + walls + outflow\n(|sum| <= "
                  f"{np.abs(b[:, 3]).max():.0e} C)")
    ax.axhline(0, color="0.8", lw=0.5, zorder=0)
    ax.set_xlabel("t [s]")
    ax.set_ylabel(f"charge [{unitName}]")


def plot_distribution(ax, ts, q, qSat, which=None, bins=40):
    """Histograms of the parcel charges per q_sat on ax, at the written
    times of the indices which (default: a third, two thirds and the end);
    returns the bin edges (to add other runs)."""
    bins = np.linspace(min(x.min() for x in q)/qSat,
                       max(0, max(x.max() for x in q)/qSat), bins + 1)
    if which is None:
        which = sorted({len(ts)//3, 2*len(ts)//3, len(ts) - 1})
    for i in which:
        ax.hist(q[i]/qSat, bins=bins, histtype="step",
                label=f"t = {ts[i]} s")
    ax.set_xlabel("q / q_sat")
    ax.set_ylabel("parcels")
    return bins


def mid_plane_field(case, t, par):
    """|E| of the mesh field at time t in the duct's mid-plane z = W/2 (the
    mean of the two cell layers next to it, (NY, NX)), the largest |E| of
    the mesh, and |E| at the parcels; None if t has no E."""
    Epath = os.path.join(case, t, "E")
    if not os.path.exists(Epath):
        return None
    NX, NY, NZ = par["cells"]
    E = read_internal_field(Epath)
    magE = np.linalg.norm(E, axis=1).reshape(NZ, NY, NX)
    mid = 0.5*(magE[NZ//2 - 1] + magE[NZ//2])
    Ep = read_field(os.path.join(case, t, "lagrangian", "cloud",
                                 "E")).reshape(-1, 3)
    return mid, np.abs(magE).max(), np.linalg.norm(Ep, axis=1)


def plot_field(fig, ax, mid, par):
    """The mid-plane |E| of mid_plane_field() on ax, with a colour bar."""
    L, W = par["size"][0], par["size"][1]
    im = ax.imshow(mid, origin="lower", extent=(0, L, 0, W),
                   aspect="auto", cmap="viridis")
    fig.colorbar(im, ax=ax, label="|E| [V/m]")
    ax.set_xlabel("x [m]")
    ax.set_ylabel("y [m]")


def main():
    case = sys.argv[1] if len(sys.argv) > 1 else "."
    other = sys.argv[2] if len(sys.argv) > 2 else None
    ts, q, b, s = summary(case)
    par = case_params(case)
    Q_SAT = s["qSat"]
    N = s["parcels"]
    report(s)

    # Charge build-up
    fig, ax = plt.subplots(figsize=(6, 4))
    plot_build_up(ax, b, ts, q, N, Q_SAT)
    ax.set_title("PTFE ellipsoids charging on steel walls")
    ax.legend()
    fig.tight_layout()
    fig.savefig(os.path.join(case, "chargeBuildUp.png"), dpi=120)

    # Charge distribution at a few times (and of the other run)
    fig, ax = plt.subplots(figsize=(6, 4))
    bins = plot_distribution(ax, ts, q, Q_SAT)
    if other:
        _, qo, _, so = summary(other)
        ax.hist(qo[-1]/Q_SAT, bins=bins, histtype="step", ls="--",
                label=f"t = {so['time']:g} s, {other}")
        print(f"  {other}: mean q/q_sat = {so['mean']:.4f}, std "
              f"{so['std']:.4f}, {so['parcels']} parcels")
        print(f"  difference of the means: {abs(so['mean'] - s['mean']):.4f}"
              f" (standard error of a mean "
              f"{np.hypot(s['std'], so['std'])/np.sqrt(s['parcels']):.4f})")
        print(f"  {other}: parcel velocity: mean"
              f" {np.array2string(so['U'], precision=4)} m/s, std of U_x"
              f" {so['UxStd']:.4f} m/s; difference of the mean U_x"
              f" {abs(so['U'][0] - s['U'][0]):.4f} m/s (standard error"
              f" {np.hypot(s['UxStd'], so['UxStd'])/np.sqrt(s['parcels']):.4f})")
    ax.legend()
    fig.tight_layout()
    fig.savefig(os.path.join(case, "chargeDistribution.png"), dpi=120)

    # Mesh field in the mid-plane z = W/2 (the cells next to it)
    field = mid_plane_field(case, ts[-1], par)
    if field:
        mid, maxE, Ep = field
        fig, ax = plt.subplots(figsize=(9, 2.4))
        plot_field(fig, ax, mid, par)
        ax.set_title(f"mesh far field |E|, mid-plane, t = {ts[-1]} s")
        fig.tight_layout()
        fig.savefig(os.path.join(case, "field.png"), dpi=120)
        report_field(maxE, Ep)


if __name__ == "__main__":
    main()
