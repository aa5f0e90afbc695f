#!/usr/bin/env python3
"""Error against cost of the electrostatics rungs measured by
chargedFoamAdvisor -rungs (postProcessing/advisor/<time>/rungs.dat).

    plotRungs.py rungs.dat [rungs.png]

One point per rung: rms force error against the scene's reference (log
axis) and cost per evaluation relative to the cheapest rung (log axis);
the accuracy target as a dashed line, the recommended rung filled in red.
The rung 'none' (no far field, 100 % error) and the near-field rows are
left out."""
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt


def read(path):
    header, rows = {}, []
    for line in open(path):
        if line.startswith("#"):
            parts = line[1:].split(None, 1)
            if len(parts) == 2:
                header[parts[0]] = parts[1].strip()
            continue
        f = line.split()
        if len(f) == 7:
            rows.append(dict(name=f[0], rms=float(f[1]), p95=float(f[2]),
                             cost=float(f[3]), ratio=float(f[4]),
                             memory=float(f[5]), recommended=f[6] == "1"))
    return header, rows


def main():
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    src = sys.argv[1]
    out = sys.argv[2] if len(sys.argv) > 2 else src.rsplit(".", 1)[0] + ".png"
    header, rows = read(src)
    # The far-field rungs (the near-field rows have their own reference)
    rows = [r for r in rows
            if r["name"] != "none" and not r["name"].startswith("nearField:")]
    floor = 1e-7  # exact rungs (the reference itself) at the bottom
    fig, ax = plt.subplots(figsize=(8, 5))
    ax.set_xscale("log")
    ax.set_yscale("log")
    for i, r in enumerate(sorted(rows, key=lambda r: (r["ratio"], r["rms"]))):
        y = max(100*r["rms"], 100*floor)
        ax.scatter(r["ratio"], y, s=70 if r["recommended"] else 30,
                   color="tab:red" if r["recommended"] else "tab:blue",
                   zorder=3)
        # Alternate the labels' side: close points stay readable
        ax.annotate(r["name"], (r["ratio"], y), textcoords="offset points",
                    xytext=(6, 5 if i % 2 == 0 else -11), fontsize=7)
    xs = [r["ratio"] for r in rows] or [1]
    ax.set_xlim(min(xs)/1.5, max(xs)*4)
    acc = 100*float(header.get("accuracy", "0.05"))
    ax.axhline(acc, ls="--", color="gray", lw=1)
    ax.text(0.01, acc, f" accuracy {acc:g} %", va="bottom", fontsize=8,
            color="gray", transform=ax.get_yaxis_transform())
    ax.set_xlabel("cost per evaluation / cheapest rung")
    ax.set_ylabel("rms force error [%]")
    ax.set_title(f"scene {header.get('scene', '?')}, reference "
                 f"{header.get('reference', '?')}, "
                 f"{header.get('parcelsCompared', '?')} parcels compared\n"
                 f"recommended (red): {header.get('recommended', 'none')}",
                 fontsize=9)
    ax.grid(True, which="both", lw=0.3)
    fig.tight_layout()
    fig.savefig(out, dpi=120)
    print(f"Plot written to {out}")


if __name__ == "__main__":
    main()
