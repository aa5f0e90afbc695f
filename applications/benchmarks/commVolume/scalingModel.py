#!/usr/bin/env python3
"""A model of strong scaling to 1000 ranks and beyond, from measured
quantities only: the per-step communication of the duct (commVolume.py
--rungs shortDuct: messages, bytes, all-reduce and all-to-all calls per rank
and fluid step), the machine's latency and bandwidth (commVolume.py
--pingpong) and the compute per parcel and fluid step (the duct runs'
ExecutionTime).

    scalingModel.py --tables commVolume.log --pingpong pingpong.log
                    [--parcels 1e7] [--ranks 2,8,64,256,1000,4096]
                    [--latency s] [--bandwidth B/s] [--compute s]

Per rank and fluid step, with n = N/P parcels per rank (cells in
proportion, subdomains as cubes, 26 neighbours of which 6 share faces):
    compute    n c
    halo       M (26/2) alpha + B (n/n_m)^(2/3) (6/2)/beta   (M: the
               point-to-point messages per rank, the tally's messages less
               its collective calls; B: the largest rank's bytes; both at
               the largest measured P, n_m parcels per rank there, 2
               neighbours in a row of slabs)
    all-reduce A 2 log2(P) alpha                 (recursive doubling)
    all-to-all X (P - 1) alpha                   (pairwise exchange of the
               sizes that OpenFOAM's PstreamBuffers sends before data; a
               Bruck algorithm would take log2(P) alpha)
and, for the rungs that still all-gather (directCoulomb, periodic, the near
fields), 32 N / beta per step and 32 N bytes of memory on every rank.
Efficiency = compute / (compute + communication), without overlap.
"""
import argparse
import math
import re
import sys


def parse_tables(path):
    """{rung: {P: row}} from commVolume.py's output; row: bytes mean, max,
    messages, all-reduces, all-to-alls, memory; and the header's n"""
    rungs, rung, n, compute = {}, None, {}, {}
    for line in open(path):
        m = re.match(r"^(\w+)( \((strong|weak) scaling: (\d+) parcels.*\))?\s*$", line)
        if m:
            rung = m.group(1)
            rungs[rung] = {}
            n[rung] = int(m.group(4)) if m.group(3) == "strong" else None
            continue
        m = re.match(r"^compute at (\d+) ranks: ([0-9.e+-]+)", line)
        if m and rung:
            compute.setdefault(rung, {})[int(m.group(1))] = float(m.group(2))
            continue
        if rung and line.startswith("| ") and not line.startswith("| ranks") \
                and not line.startswith("| ---"):
            f = [v.strip() for v in line.strip().strip("|").split("|")]
            rungs[rung][int(f[0])] = [float(v) for v in f[1:]]
    return rungs, n, compute


def parse_pingpong(path):
    text = open(path).read()
    lat = float(re.search(r"latency ([0-9.e+-]+)", text).group(1))
    bw = float(re.search(r"bandwidth ([0-9.e+-]+)", text).group(1))
    return lat, bw


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--tables", required=True)
    ap.add_argument("--pingpong")
    ap.add_argument("--latency", type=float)
    ap.add_argument("--bandwidth", type=float)
    ap.add_argument("--compute", type=float,
                    help="CPU seconds per parcel and fluid step (default: the duct's "
                         "at the fewest ranks in the tables)")
    ap.add_argument("--parcels", type=float, default=1e7)
    ap.add_argument("--ranks", default="2,8,64,256,1000,4096")
    a = ap.parse_args()
    rungs, nOf, computeOf = parse_tables(a.tables)
    if "shortDuct" not in rungs:
        sys.exit("scalingModel: no shortDuct table in " + a.tables)
    alpha, beta = (parse_pingpong(a.pingpong) if a.pingpong else (None, None))
    alpha = a.latency or alpha
    beta = a.bandwidth or beta
    duct = rungs["shortDuct"]
    Pm = max(duct)
    bytesMean, bytesMax, msgs, allreduce, alltoall, mem = duct[Pm]
    # The tally counts each collective call as a message too
    msgs -= allreduce + alltoall
    nm = nOf["shortDuct"]/Pm
    N = a.parcels
    c = a.compute or computeOf["shortDuct"][min(computeOf["shortDuct"])]
    print(f"measured: latency {alpha:.2e} s, bandwidth {beta:.2e} B/s; duct at {Pm} ranks "
          f"({nm:.0f} parcels per rank): {msgs:.0f} point-to-point messages, {bytesMax:.3g} bytes (largest rank), "
          f"{allreduce:.0f} all-reduces, {alltoall:.0f} all-to-alls per rank and fluid step; "
          f"compute {c:.2e} s per parcel and fluid step")
    print(f"\nmodel: {N:.0e} parcels, seconds per rank and fluid step")
    print("| ranks | parcels per rank | compute | halo | all-reduce | all-to-all | all-gather rungs | efficiency (halo rungs) | largest communication term |")
    print("| --- | --- | --- | --- | --- | --- | --- | --- | --- |")
    for P in (int(v) for v in a.ranks.split(",")):
        n = N/P
        tc = n*c
        th = msgs*(26/2)*alpha + bytesMax*(n/nm)**(2/3)*(6/2)/beta
        tr = allreduce*2*math.log2(P)*alpha
        ta = alltoall*(P - 1)*alpha
        tg = 32*N/beta
        comm = {"halo": th, "all-reduce": tr, "all-to-all": ta}
        worst = max(comm, key=comm.get)
        eff = tc/(tc + th + tr + ta)
        print(f"| {P} | {n:.3g} | {tc:.3g} | {th:.2g} | {tr:.2g} | {ta:.2g} | {tg:.2g} "
              f"({32*N/1e6:.0f} MB per rank) | {eff:.3f} | {worst} |")
    # Where the all-to-all equals the compute: n c = X (P - 1) alpha
    Pstar = math.sqrt(N*c/(alltoall*alpha))
    print(f"\nthe all-to-all term equals the compute at P = sqrt(N c/(X alpha)) = {Pstar:.0f} ranks")


if __name__ == "__main__":
    main()
