#!/usr/bin/env python3
"""Plot simulated vs analytic separation of the two charged spheres.

Usage: plotSeparation.py <caseDir> [--cloud cloud] [--output <caseDir>/separation.png]

Top panel: separation r(t) (simulation markers, analytic line from
twoBodyCoulomb.analytic_separation, contact separation dashed); bottom panel:
|r_num - r_exact|/r_exact on a log scale.  Exit code 2 on missing/invalid data.
"""

import argparse
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import twoBodyCoulomb as tbc  # noqa: E402


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("caseDir")
    ap.add_argument("--cloud", default="cloud")
    ap.add_argument("--output", help="PNG file (default: <caseDir>/separation.png)")
    args = ap.parse_args(argv)
    out = args.output or os.path.join(args.caseDir, "separation.png")
    try:
        res = tbc.compare(tbc.load_history(args.caseDir, args.cloud),
                          *tbc.initial_state(args.caseDir, args.cloud))
    except (tbc.HistoryError, OSError) as e:
        print(f"ERROR: {e}", file=sys.stderr)
        return 2

    t, mm = res["t"]*1e3, 1e3                      # plot in ms and mm
    step = max(1, len(t)//200)
    idx = np.unique(np.r_[np.arange(0, len(t), step), len(t) - 1])
    t_line = np.linspace(0.0, res["t_contact"], 1000)
    r_line = tbc.analytic_separation(t_line, res["r0"], res["mu"], res["kQ"])

    fig, (ax1, ax2) = plt.subplots(2, 1, sharex=True, figsize=(7, 7))
    ax1.plot(t[idx], res["r_num"][idx]*mm, "o", ms=3, mfc="none", color="C1",
             label="simulation")
    ax1.plot(t_line*1e3, r_line*mm, "-", color="C0", zorder=3, label="analytic")
    ax1.axhline(res["r_contact"]*mm, ls="--", color="k",
                label="contact $(d_1+d_2)/2$")
    ax1.set_ylabel("separation $r$ [mm]")
    ax1.set_title("Two oppositely charged spheres: simulation vs analytic")
    ax1.legend()
    ax1.grid(alpha=0.3)

    err = res["rel_err"]
    pos = err > 0                                   # log scale: skip exact zeros
    ax2.semilogy(t[pos], err[pos], "-", color="C3")
    ax2.set_xlabel("time $t$ [ms]")
    ax2.set_ylabel(r"$|r_{num} - r_{exact}| / r_{exact}$ [-]")
    ax2.grid(alpha=0.3, which="both")

    fig.tight_layout()
    fig.savefig(out, dpi=120)
    print(f"wrote {out}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
