#!/usr/bin/python3
"""Post-process the shortDuct tutorial with the flagship's functions
(tutorials/chargedDuct/chargedDuct.py): prints the summary (results.txt via
Allrun) and writes one figure, charging.png:

  (a) charge of the particles and of the grounded walls vs time, and their
      sum with the outflow (zero: contact charging conserves charge);
  (b) the particle charge distribution, in units of the saturation charge
      q_sat = eps0 |Gamma| S;
  (c) the mesh far field |E| in the mid-plane of the duct at the end, with
      the particles.

The parcel count (injected, in the duct, escaped) and the solver's clock
time come from log.chargedDPMFoam.

    shortDuct.py [caseDir]
"""
import os
import re
import sys

import numpy as np
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

here = os.path.dirname(os.path.abspath(__file__))
top = os.environ.get("CHARGEDFOAM_DIR") or os.path.join(here, "..", "..")
sys.path.insert(0, os.path.join(top, "tutorials", "chargedDuct"))
sys.path.insert(0, os.path.join(top, "etc", "python"))
import chargedDuct as cd  # noqa: E402
from foamLagrangian import read_positions  # noqa: E402


def solver_log(case):
    """From the last cloud report of log.chargedDPMFoam: parcels injected,
    in the system, escaped through open patches; the steps and the clock
    time of the run."""
    log = open(os.path.join(case, "log.chargedDPMFoam")).read()

    def last(pattern):
        m = re.findall(pattern, log)
        return int(m[-1]) if m else None

    return {
        "added": last(r"parcels added\s*=\s*(\d+)"),
        "current": last(r"Current number of parcels\s*=\s*(\d+)"),
        "escaped": last(r"Parcel fate: system \(number, mass\)\s*\n"
                        r"\s*- escape\s*=\s*(\d+)"),
        "steps": len(re.findall(r"^Time = ", log, re.M)),
        "clock": last(r"ClockTime = (\d+) s"),
    }


def main():
    case = sys.argv[1] if len(sys.argv) > 1 else "."
    ts, q, b, s = cd.summary(case)
    par = cd.case_params(case)
    qSat = s["qSat"]
    log = solver_log(case)
    cd.report(s, "shortDuct")
    print(f"  parcels: {log['added']} injected, {log['current']} in the duct"
          f" at the end, {log['escaped']} escaped through the outlet")
    print(f"  charging contacts: {b[:, 5].sum():.0f} particle-wall,"
          f" {b[:, 4].sum():.0f} particle-particle")
    print(f"  charge at the end: particles {b[-1, 1]:.4g} C + walls"
          f" {b[-1, 2]:.4g} C + outflow {b[-1, 6]:.4g} C = {b[-1, 3]:.2g} C")
    field = cd.mid_plane_field(case, ts[-1], par)
    if field:
        cd.report_field(field[1], field[2])
    print(f"  solver: {log['steps']} fluid steps, clock time"
          f" {log['clock']} s")

    fig = plt.figure(figsize=(11, 7.5))
    grid = fig.add_gridspec(2, 2, height_ratios=(1.25, 1))
    fig.suptitle(f"shortDuct: {s['parcels']} PTFE ellipsoids conveyed by air"
                 f" through a grounded steel duct, t = 0 - {ts[-1]} s")

    ax = fig.add_subplot(grid[0, 0])
    cd.plot_charge_balance(ax, b)
    ax.set_title("(a) charge of the PTFE particles and the steel walls")
    lo, hi = ax.get_ylim()
    ax.set_ylim(lo, hi + 0.3*(hi - lo))       # room for the legend
    ax.legend(loc="upper left", fontsize="small")

    ax = fig.add_subplot(grid[0, 1])
    cd.plot_distribution(ax, ts, q, qSat)
    ax.set_xlabel(f"particle charge q / q_sat   (q_sat = eps0 |Gamma| S ="
                  f" {qSat*1e12:.0f} pC)")
    ax.set_ylabel("particles")
    ax.set_title(f"(b) charge distribution; mean {s['mean']:.3f} q_sat at"
                 f" the end")
    ax.legend(loc="upper left")
    ax.text(0.93, 0.9, "uncharged: no charging\ncontact yet  \u2192",
            ha="right", va="top", transform=ax.transAxes)

    ax = fig.add_subplot(grid[1, :])
    if field:
        cd.plot_field(fig, ax, field[0], par)
        title = (f"(c) mesh far field |E| in the mid-plane z = "
                 f"{par['size'][2]*500:g} mm (max {field[1]:.3g} V/m)")
    else:
        title = "(c) particles"
    x = read_positions(os.path.join(case, ts[-1], "lagrangian", "cloud",
                                    "positions"))
    ax.plot(x[:, 0], x[:, 1], ".", color="w", mec="k", mew=0.3, ms=4,
            label="particles (all, projected on the plane)")
    ax.set_xlim(0, par["size"][0])
    ax.set_ylim(0, par["size"][1])
    U = open(os.path.join(case, "0", "U.air")).read()
    Uin = re.search(r"inlet\s*\{[^}]*uniform\s*\(\s*(\S+)", U).group(1)
    ax.set_xlabel(f"x [m]   (air enters at x = 0 at {Uin} m/s)")
    ax.set_ylabel("y [m] (gravity -y)")
    ax.set_title(f"{title}, t = {ts[-1]} s")
    ax.legend(loc="upper right", fontsize="small")

    fig.tight_layout()
    fig.savefig(os.path.join(case, "charging.png"), dpi=110)


if __name__ == "__main__":
    main()
