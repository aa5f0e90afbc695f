#!/usr/bin/python3
"""Boutsikakis 2023 Figs. 6-7: the quasi-periodic direct sum against the
number of periodic layers, from `periodicElectrostaticsBenchmark -layers`.

    layers.py [--N 100] [--NperMax 8] [--seed 1] [--png layers.png]

Prints the benchmark's table and plots the mean particle energy over the
uniformly charged cube's limit (it grows as (2 Nper - 1)^2), the mean force
and the errors against Nper = NperMax, against Ewald and, with the
minimum-image dipole term removed, against Ewald.
"""
import argparse
import subprocess

import numpy as np

ap = argparse.ArgumentParser()
ap.add_argument("--N", type=int, default=100)
ap.add_argument("--NperMax", type=int, default=8)
ap.add_argument("--seed", type=int, default=1)
ap.add_argument("--png", default="layers.png")
a = ap.parse_args()

out = subprocess.run(["periodicElectrostaticsBenchmark", "-N", "(%d)" % a.N, "-layers", str(a.NperMax),
                      "-seed", str(a.seed), "-noLammps"], capture_output=True, text=True, check=True).stdout
table = out[out.index("### Periodic layers"):]
print(table)
rows = [l.split("|")[1:-1] for l in table.splitlines() if l.startswith("| ") and l[2].isdigit()]
nper = np.array([int(r[0]) for r in rows])
ue, ratio, meanF = (np.array([float(r[i]) for r in rows]) for i in (1, 2, 3))
errMax, errEw, errDip = (np.array([float(r[i]) for r in rows]) for i in (4, 7, 9))

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
fig, ax = plt.subplots(1, 3, figsize=(13, 3.8))
ax[0].plot(nper, ue, "o-", label="<u_e> = <q phi>")
ax[0].plot(nper, ue/ratio, "k--", lw=0.8, label="uniform cube: k rho a^2 C Q")
ax[0].set_xlabel("Nper"); ax[0].set_ylabel("<u_e> [J]"); ax[0].legend(fontsize=8)
ax[0].set_title("Energy diverges as (2 Nper - 1)^2 (Fig. 6 left)", fontsize=9)
ax[1].plot(nper, 100*(meanF/meanF[-1] - 1), "o-")
ax[1].set_xlabel("Nper"); ax[1].set_ylabel("<|F|> / <|F|>(Nper = %d) - 1 [%%]" % a.NperMax)
ax[1].set_title("Mean force converges (Fig. 6 right)", fontsize=9)
ax[2].semilogy(nper[:-1], errMax[:-1], "o-", label="vs Nper = %d" % a.NperMax)
ax[2].semilogy(nper, errEw, "s-", label="vs Ewald")
ax[2].semilogy(nper, errDip, "^-", label="minus dipole term vs Ewald")
ax[2].set_xlabel("Nper"); ax[2].set_ylabel("rms relative force difference")
ax[2].set_title("Convergence (Fig. 7): to Ewald plus the dipole term", fontsize=9)
ax[2].legend(fontsize=8)
for x in ax:
    x.grid(alpha=0.3)
fig.suptitle("Quasi-periodic direct sum, %d like charges (Boutsikakis 2023 Figs. 6-7)" % a.N)
fig.tight_layout()
fig.savefig(a.png, dpi=100)
