#!/usr/bin/env python3
"""Analytic check of the twoChargedSpheres tutorial (two-body Coulomb collapse).

Two uniformly charged spheres (diameters d1, d2, densities rho1, rho2, masses
m = rho*pi*d^3/6, charges q1*q2 < 0) are released at rest at separation r0 in
vacuum without gravity.  The separation r obeys

    mu r'' = -K / r^2,   mu = m1 m2/(m1 + m2),   K = k |q1 q2|,   k = 1/(4 pi eps0)

Energy conservation, mu r'^2/2 = K (1/r - 1/r0), gives the relative speed
|r'| = sqrt(2K/mu (1/r - 1/r0)) and, with x = r/r0 = cos^2(theta), the
radial free-fall time (radial Kepler problem)

    t(r) = tau [ sqrt(x (1 - x)) + arccos(sqrt(x)) ],   tau = sqrt(mu r0^3 / (2K))

which decreases monotonically from 0 at x = 1 to tau*pi/2 at x = 0 and is
inverted here by vectorised bisection.  Contact occurs at r = (d1 + d2)/2.
`--self-test` verifies the formula against an RK4 integration of the ODE.

Usage:
    twoBodyCoulomb.py <caseDir> [--cloud cloud] [--tolerance 1e-3]
    twoBodyCoulomb.py --self-test

Reads <caseDir>/postProcessing/lagrangian/<cloud>/particleHistory/*/particleHistory.dat,
writes <caseDir>/postProcessing/twoBodyCoulomb.txt.  Exit code: 0 PASS,
1 FAIL (max relative separation error >= tolerance), 2 missing/invalid data.
"""

import argparse
import glob
import os
import re
import sys
import warnings

import numpy as np

EPS0 = 8.8541878128e-12            # vacuum permittivity [F/m], CODATA 2018
K_COULOMB = 1.0/(4.0*np.pi*EPS0)   # Coulomb constant [N m^2/C^2]
REQUIRED = ("time", "origProc", "origId", "x", "y", "z",
            "Ux", "Uy", "Uz", "d", "rho", "q")


class HistoryError(Exception):
    """Missing or invalid particle history data."""


# ---------------------------------------------------------------- analytic

def free_fall_tau(r0, mu, kQ):
    """Time scale tau = sqrt(mu r0^3/(2 kQ)); kQ = k|q1 q2|."""
    return np.sqrt(mu*r0**3/(2.0*kQ))


def time_of_separation(r, r0, mu, kQ):
    """Time t(r) for the separation to fall from r0 (at rest) to r."""
    x = np.clip(np.asarray(r, dtype=float)/r0, 0.0, 1.0)
    return free_fall_tau(r0, mu, kQ)*(np.sqrt(x*(1.0 - x)) + np.arccos(np.sqrt(x)))


def analytic_separation(t, r0, mu, kQ, iterations=64):
    """Separation r(t), inverting t(r) by vectorised bisection in x = r/r0."""
    t = np.asarray(t, dtype=float)
    lo, hi = np.zeros_like(t), np.ones_like(t)
    for _ in range(iterations):
        mid = 0.5*(lo + hi)
        later = time_of_separation(mid*r0, r0, mu, kQ) > t   # mid reached after t
        lo = np.where(later, mid, lo)
        hi = np.where(later, hi, mid)
    return 0.5*(lo + hi)*r0


def analytic_speed(r, r0, mu, kQ):
    """Relative speed |dr/dt| at separation r (energy conservation)."""
    r = np.asarray(r, dtype=float)
    return np.sqrt(np.maximum(2.0*kQ/mu*(1.0/r - 1.0/r0), 0.0))


def contact_time(r0, mu, kQ, r_contact):
    """Time at which the separation reaches r_contact = (d1 + d2)/2."""
    return float(time_of_separation(r_contact, r0, mu, kQ))


# ---------------------------------------------------------------- data

def _read_table(path):
    header = None
    with open(path) as f:
        for line in f:
            s = line.strip()
            if s.startswith("#"):
                header = s.lstrip("#").split()
            elif s:
                break
    if not header:
        raise HistoryError(f"{path}: no '#' header line naming the columns")
    missing = [c for c in REQUIRED if c not in header]
    if missing:
        raise HistoryError(f"{path}: header lacks column(s) {missing}")
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")          # empty-file warning
            data = np.loadtxt(path, comments="#", ndmin=2)
    except ValueError as e:
        raise HistoryError(f"{path}: cannot parse data ({e})") from None
    if data.size and data.shape[1] != len(header):
        raise HistoryError(f"{path}: {data.shape[1]} data columns but "
                           f"{len(header)} header names")
    return header, data.reshape(-1, len(header))


def _start_time(path):
    name = os.path.basename(os.path.dirname(path))
    try:
        return (0, float(name), name)
    except ValueError:
        return (1, 0.0, name)


def load_history(case_dir, cloud="cloud"):
    """Read particleHistory.dat of all start-time folders (time-ordered,
    duplicates (time, origProc, origId) dropped).

    Returns {(origProc, origId): {column: 1-D array, 'pos': (N,3), 'U': (N,3)}}
    sorted by time; raises HistoryError unless exactly two particles exist.
    """
    pattern = os.path.join(case_dir, "postProcessing", "lagrangian", cloud,
                           "particleHistory", "*", "particleHistory.dat")
    files = sorted(glob.glob(pattern), key=_start_time)
    if not files:
        raise HistoryError(f"no history file matching {pattern}")
    header, blocks = None, []
    for path in files:
        h, data = _read_table(path)
        if header is not None and h != header:
            raise HistoryError(f"{path}: columns differ from {files[0]}")
        header = h
        blocks.append(data)
    data = np.vstack(blocks)
    if len(data) == 0:
        raise HistoryError("history file(s) contain no data rows")
    col = {name: data[:, i] for i, name in enumerate(header)}
    ids = sorted(set(zip(col["origProc"].astype(int), col["origId"].astype(int))))
    if len(ids) != 2:
        raise HistoryError(f"expected exactly 2 particles, found {len(ids)}: {ids}")
    history = {}
    for proc, pid in ids:
        rows = np.flatnonzero((col["origProc"] == proc) & (col["origId"] == pid))
        _, first = np.unique(col["time"][rows], return_index=True)  # sorted, dedup
        rows = rows[first]
        p = {name: values[rows] for name, values in col.items()}
        p["pos"] = np.column_stack([p["x"], p["y"], p["z"]])
        p["U"] = np.column_stack([p["Ux"], p["Uy"], p["Uz"]])
        history[(proc, pid)] = p
    return history


# ---------------------------------------------------------------- comparison

def initial_state(case_dir, cloud="cloud"):
    """Start time (system/controlDict startTime) and initial separation r0
    (the two 'position (x y z)' entries of constant/<cloud>Properties)."""
    def read(path):
        try:
            with open(path) as f:
                return re.sub(r"//.*", "", f.read())
        except OSError as e:
            raise HistoryError(f"cannot read {path}: {e}") from None
    control = read(os.path.join(case_dir, "system", "controlDict"))
    m = re.search(r"\bstartTime\s+([-+0-9.eE]+)\s*;", control)
    t0 = float(m.group(1)) if m else 0.0
    props = read(os.path.join(case_dir, "constant", cloud + "Properties"))
    pos = [np.array(p.split(), dtype=float)
           for p in re.findall(r"\bposition\s*\(([^)]*)\)", props)]
    if len(pos) != 2:
        raise HistoryError(f"expected 2 'position' entries in {cloud}Properties, "
                           f"found {len(pos)}")
    return t0, float(np.linalg.norm(pos[0] - pos[1]))


def compare(history, t0, r0):
    """Compare simulated and analytic separation; returns a dict of results.
    t0, r0: start time and initial separation (particles at rest)."""
    (id1, a), (id2, b) = sorted(history.items())
    _, i1, i2 = np.intersect1d(a["time"], b["time"], assume_unique=True,
                               return_indices=True)
    if len(i1) < 2:
        raise HistoryError("fewer than two common sample times for both particles")
    a = {k: v[i1] for k, v in a.items()}
    b = {k: v[i2] for k, v in b.items()}
    m1, m2 = (p["rho"][0]*np.pi*p["d"][0]**3/6.0 for p in (a, b))
    q1, q2 = a["q"][0], b["q"][0]
    if not (m1 > 0 and m2 > 0 and q1*q2 < 0):
        raise HistoryError(f"need positive masses and opposite charges "
                           f"(m = {m1:g}, {m2:g} kg; q = {q1:g}, {q2:g} C)")
    mu, kQ = m1*m2/(m1 + m2), K_COULOMB*abs(q1*q2)
    r_contact = 0.5*(a["d"][0] + b["d"][0])
    # The solver writes the state after each step; the initial state (t0, r0)
    # is the case's start time and the injected positions
    t = a["time"] - t0
    r_all = np.linalg.norm(a["pos"] - b["pos"], axis=1)
    if r0 <= r_contact:
        raise HistoryError(f"initial separation {r0:g} m <= contact {r_contact:g} m")
    t_contact = contact_time(r0, mu, kQ, r_contact)
    v_scale = analytic_speed(r_contact, r0, mu, kQ)
    u0 = max(np.linalg.norm(a["U"][0]), np.linalg.norm(b["U"][0]))
    notes = []
    if u0 > 1e-3*v_scale:
        notes.append(f"initial speed {u0:.3e} m/s is not ~0 "
                         f"(contact speed {v_scale:.3e} m/s)")

    keep = (r_all > r_contact) & (t <= t_contact)
    n = int(np.argmin(keep)) if not keep.all() else len(keep)  # up to contact
    if n < 2:
        raise HistoryError("fewer than two samples before contact")
    sl = slice(0, n)
    r_num = r_all[sl]
    r_exact = analytic_separation(t[sl], r0, mu, kQ)
    rel_err = np.abs(r_num - r_exact)/r_exact
    v_num = np.linalg.norm(a["U"][n - 1] - b["U"][n - 1])
    v_exact = analytic_speed(r_exact[-1], r0, mu, kQ)

    mass = m1 + m2
    com = (m1*a["pos"][sl] + m2*b["pos"][sl])/mass
    mom = np.linalg.norm(m1*a["U"][sl] + m2*b["U"][sl], axis=1)
    p1 = m1*np.linalg.norm(a["U"][sl], axis=1)
    res = dict(
        ids=(id1, id2), m1=m1, m2=m2, q1=q1, q2=q2, mu=mu, kQ=kQ, r0=r0,
        r_contact=r_contact, t_contact=t_contact, t0=t0,
        t=t[sl], r_num=r_num, r_exact=r_exact, rel_err=rel_err,
        n=n, t_end=t[n - 1], max_rel_err=float(rel_err.max()),
        v_num=v_num, v_exact=v_exact,
        speed_rel_err=abs(v_num - v_exact)/v_exact if v_exact > 0 else np.nan,
        com_drift=float(np.linalg.norm(com - com[0], axis=1).max()/r0),
        momentum=float((mom[p1 > 0]/p1[p1 > 0]).max()) if (p1 > 0).any() else 0.0,
        warnings=notes)
    if "fEx" in a:  # report only: written electric force vs Coulomb's law
        f_num = np.linalg.norm(np.column_stack([a["fEx"], a["fEy"], a["fEz"]])[sl], axis=1)
        res["force_rel_err"] = float(np.max(np.abs(f_num/(kQ/r_num**2) - 1.0)))
    return res


def report(res, tolerance):
    """Summary lines; the last one says PASS or FAIL."""
    ok = res["max_rel_err"] < tolerance
    lines = [f"WARNING: {w}" for w in res["warnings"]] + [
        f"particles (origProc, origId)  : {res['ids'][0]}, {res['ids'][1]}",
        f"m1, m2 [kg]                   : {res['m1']:.6e}, {res['m2']:.6e}",
        f"q1, q2 [C]                    : {res['q1']:.6e}, {res['q2']:.6e}",
        f"r0, r_contact [m]             : {res['r0']:.6e}, {res['r_contact']:.6e}",
        f"samples before contact        : {res['n']}",
        f"t_end / t_contact [s]         : {res['t_end']:.6e} / {res['t_contact']:.6e}"
        f" ({res['t_end']/res['t_contact']:.4f})",
        f"max |r_num - r_exact|/r_exact : {res['max_rel_err']:.3e}",
        f"relative speed at last sample : {res['v_num']:.6e} vs {res['v_exact']:.6e} m/s"
        f" (rel. error {res['speed_rel_err']:.3e})",
        f"centre-of-mass drift / r0     : {res['com_drift']:.3e}",
        f"max |m1U1 + m2U2|/(m1|U1|)    : {res['momentum']:.3e}"]
    if "force_rel_err" in res:
        lines.append(f"max |fE|/(k|q1q2|/r^2) - 1    : {res['force_rel_err']:.3e}")
    lines.append(f"{'PASS' if ok else 'FAIL'}: max relative separation error "
                 f"{res['max_rel_err']:.3e} {'<' if ok else '>='} tolerance "
                 f"{tolerance:.1e} ({res['n']} samples, t_end/t_contact = "
                 f"{res['t_end']/res['t_contact']:.4f})")
    return lines, ok


# ---------------------------------------------------------------- self test

def self_test():
    """Check t(r)/r(t) against an RK4 integration of mu r'' = -kQ/r^2."""
    m1, m2, q1, q2, r0, r_c = 2.0e-9, 5.0e-10, 3.0e-12, -1.5e-12, 2.0e-3, 2.5e-4
    mu, kQ = m1*m2/(m1 + m2), K_COULOMB*abs(q1*q2)
    t_c = contact_time(r0, mu, kQ, r_c)
    nsteps = 20000
    dt = t_c/nsteps

    def acc(r):
        return -kQ/(mu*r*r)

    r, v, ts, rs, vs = r0, 0.0, [0.0], [r0], [0.0]
    for i in range(nsteps):
        k1r, k1v = v, acc(r)
        k2r, k2v = v + 0.5*dt*k1v, acc(r + 0.5*dt*k1r)
        k3r, k3v = v + 0.5*dt*k2v, acc(r + 0.5*dt*k2r)
        k4r, k4v = v + dt*k3v, acc(r + dt*k3r)
        r += dt/6.0*(k1r + 2*k2r + 2*k3r + k4r)
        v += dt/6.0*(k1v + 2*k2v + 2*k3v + k4v)
        ts.append((i + 1)*dt), rs.append(r), vs.append(v)
    ts, rs, vs = map(np.array, (ts, rs, vs))
    err_r = np.max(np.abs(analytic_separation(ts, r0, mu, kQ)/rs - 1.0))
    err_v = np.max(np.abs(analytic_speed(rs[1:], r0, mu, kQ)/np.abs(vs[1:]) - 1.0))
    err_c = abs(rs[-1]/r_c - 1.0)
    print(f"self-test: mu = {mu:.4e} kg, k|q1q2| = {kQ:.4e} N m^2, r0 = {r0:g} m, "
          f"t_contact = {t_c:.6e} s, RK4 {nsteps} steps")
    print(f"  max rel. error r(t) analytic vs RK4     : {err_r:.3e}")
    print(f"  max rel. error |v|(r) analytic vs RK4   : {err_v:.3e}")
    print(f"  rel. error RK4 r(t_contact) vs r_contact: {err_c:.3e}")
    ok = max(err_r, err_v, err_c) < 1e-6
    print(f"{'PASS' if ok else 'FAIL'}: analytic vs RK4 max relative difference "
          f"{max(err_r, err_v, err_c):.3e} {'<' if ok else '>='} 1e-06")
    return ok


# ---------------------------------------------------------------- CLI

def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("caseDir", nargs="?", help="OpenFOAM case directory")
    ap.add_argument("--cloud", default="cloud", help="cloud name (default: cloud)")
    ap.add_argument("--tolerance", type=float, default=1e-3,
                    help="max relative separation error for PASS (default 1e-3)")
    ap.add_argument("--self-test", action="store_true",
                    help="check the analytic solution against RK4 and exit")
    args = ap.parse_args(argv)
    if args.self_test:
        return 0 if self_test() else 1
    if args.caseDir is None:
        ap.error("caseDir is required unless --self-test is given")
    try:
        t0, r0 = initial_state(args.caseDir, args.cloud)
        res = compare(load_history(args.caseDir, args.cloud), t0, r0)
    except (HistoryError, OSError) as e:
        print(f"ERROR: {e}", file=sys.stderr)
        print("FAIL: missing or invalid particle history data")
        return 2
    lines, ok = report(res, args.tolerance)
    print("\n".join(lines))
    out = os.path.join(args.caseDir, "postProcessing", "twoBodyCoulomb.txt")
    with open(out, "w") as f:
        f.write("\n".join(lines) + "\n")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
