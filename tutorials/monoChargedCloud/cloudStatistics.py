#!/usr/bin/python3
"""Statistics of the mono-charged cloud vs Boutsikakis 2023 Eqs. 25-28.

    cloudStatistics.py [--png cloud.png] [--from T]

From log.chargedParticleFoam: agitation q_p^2 and mean electrostatic
acceleration <|F|>/m per step; stationary means over t >= T (default: the
second half). From the particleHistory sample: the Lagrangian velocity
autocorrelation R(tau) and its integral time scale tau_p^t (to the first
zero of R). Prints a table against Eq. 25 (q_p^2 ~ k Q^2 n^(1/3)/m),
Eq. 28 (<|F|>/m ~ 5/2 k Q^2 n^(2/3)/m), Eq. 26 (tau_el) and tau_pq^C =
tau_el/sqrt(6) (Eq. 26), which the paper finds of the order of tau_p^t.
PASS/FAIL lines: Eqs. 25 and 28 within --tol, the agitation's power
balance (Eq. 29), the isotropy of the force covariance (Eq. 10), the
solver's Eq. 23 reports.
"""
import argparse, glob, math, re
from pathlib import Path

import numpy as np

k = 8.9875517923e9


def readCase(case="."):
    """Parameters (log.makeParcels) and per-step series of a run: t, qp2,
    acc, power (None if not logged), cov (the normalised force covariance,
    xx xy xz yy yz zz, None if not logged), and where logged the potential
    statistics tPhi, phiMean, phiVar."""
    case = Path(case)
    log = (case/"log.chargedParticleFoam").read_text()
    steps = re.split(r"^Time = ", log, flags=re.M)[1:]
    num = r"\s*=\s*(\S+)"
    rows, cov, phi = [], [], []
    for b in steps:
        t = float(b.split(None, 1)[0])
        m = [re.search(pat + num, b) for pat in (r"Particle agitation q_p\^2",
                                                 r"Mean electrostatic acceleration",
                                                 r"Electrostatic power <a'\.u'>")]
        if m[0] is None or m[1] is None:
            continue
        rows.append((t, float(m[0].group(1)), float(m[1].group(1)),
                     float(m[2].group(1)) if m[2] else np.nan))
        mc = re.search(r"Force covariance <F'F'>/F\^2\s*=\s*\(([^)]*)\)", b)
        cov.append([float(v) for v in mc.group(1).split()] if mc else [np.nan]*6)
        mp = re.search(r"Potential at the charges <phi>_p = (\S+) V, <phi'\^2>_p = (\S+) V2", b)
        if mp:
            phi.append((t, float(mp.group(1)), float(mp.group(2))))
    r = np.array(rows)
    par = (case/"log.makeParcels").read_text()
    m_ = re.search(r"N = (\d+), L = (\S+) m, n = (\S+) /m3, d = (\S+) m, tau_el = (\S+) s, tau_p = (\S+) s", par)
    c = {"t": r[:, 0], "qp2": r[:, 1], "acc": r[:, 2],
         "power": None if np.isnan(r[:, 3]).any() else r[:, 3],
         "cov": None if np.isnan(cov).any() else np.array(cov),
         "N": int(m_.group(1)), "L": float(m_.group(2)), "n": float(m_.group(3)),
         "d": float(m_.group(4)), "tau_el": float(m_.group(5)), "tau_p": float(m_.group(6))}
    if phi:
        p = np.array(phi)
        c["tPhi"], c["phiMean"], c["phiVar"] = p[:, 0], p[:, 1], p[:, 2]
    qm = re.search(r"Q = (\S+) C, m = (\S+) kg", par)
    c["Q"], c["m"] = (float(qm.group(1)), float(qm.group(2))) if qm else (5e-9, 1.8e-4)
    dt = re.findall(r"^deltaT\s+(\S+);", (case/"system/controlDict").read_text(), re.M)
    c["dt"] = float(dt[0])
    return c


def batchMean(x, nBatch=10):
    """Mean and its standard error from nBatch consecutive batches (the
    series is correlated over ~tau_el: batch means are nearly independent)."""
    b = np.array([y.mean() for y in np.array_split(x, nBatch)])
    return x.mean(), b.std(ddof=1)/math.sqrt(nBatch)


def sampleHistory(case):
    """The particleHistory sample: times, U[time, parcel, 3], fE[time, parcel, 3]."""
    f = glob.glob(str(Path(case)/"postProcessing/lagrangian/cloud/sample/*/particleHistory.dat"))[0]
    h = np.loadtxt(f)
    times = np.unique(h[:, 0])
    ids = np.unique(h[:, 2])
    shape = (len(times), len(ids), 3)
    return times, h[:, 6:9].reshape(shape), h[:, 12:15].reshape(shape)


def autocorrelationTime(case, t0):
    """tau_p^t = integral of the Lagrangian velocity autocorrelation R(tau)
    of the particleHistory sample to its first zero (t >= t0)."""
    times, U, _ = sampleHistory(case)
    Us = U[times >= t0]
    dt = times[1] - times[0]
    nlag = len(Us)//2
    R = np.array([np.mean(np.sum(Us[:len(Us) - l]*Us[l:], axis=2)) for l in range(nlag)])
    R /= R[0]
    zero = np.argmax(R <= 0) if (R <= 0).any() else len(R)
    return np.trapz(R[:zero], dx=dt), R, dt


def powerBalance(c):
    """Residual of Eq. (29) with the Stokes dissipation of tau_p,
    d q_p^2/dt = <a'.u'> - 2 q_p^2/tau_p, and the rate d q_p^2/dt, both at
    the logged steps but the first and last (central differences)."""
    t, q, P = c["t"], c["qp2"], c["power"]
    rate = (q[2:] - q[:-2])/(t[2:] - t[:-2])
    return rate - (P[1:-1] - 2*q[1:-1]/c["tau_p"]), rate


def predictions(c):
    """Boutsikakis Eqs. 21-28 at the run's Q, m, n (lambda = k)."""
    Q, m, n = c["Q"], c["m"], c["n"]
    qp2 = k*Q**2*n**(1/3)/m                                     # Eq. (25)
    w = math.sqrt(16/math.pi*2/3*qp2)                           # Eq. (22)
    return {"qp2": qp2, "acc": 2.5*k*Q**2*n**(2/3)/m,           # Eq. (28)
            "tau_el": math.sqrt(3*m/(2*k*n))/Q,                 # Eq. (26)
            "dC": 3*math.pi/16*n**(-1/3), "w": w}               # Eq. (27)


def statistics(case=".", t0=None):
    """Stationary means (t >= t0, default the second half) of a run with
    their batch-means standard errors, tau_p^t, d_C/delta_l of the run's
    deltaT at the measured agitation (Eqs. 21-22)."""
    c = readCase(case)
    t = c["t"]
    t0 = 0.5*t[-1] if t0 is None else t0
    s = t >= t0
    c["t0"] = t0
    c["qp2Mean"], c["qp2Err"] = batchMean(c["qp2"][s])
    c["accMean"], c["accErr"] = batchMean(c["acc"][s])
    c["tau_t"], c["R"], c["Rdt"] = autocorrelationTime(case, t0)
    w = math.sqrt(16/math.pi*2/3*c["qp2Mean"])                  # Eq. (22)
    dC = k*c["Q"]**2/(0.5*c["m"]*w**2)                          # Eq. (21)
    c["dCoverDl"] = dC/(w*c["dt"])
    return c


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--png")
    ap.add_argument("--from", dest="t0", type=float)
    ap.add_argument("--tol", type=float, default=0.1,
                    help="relative tolerance of the PASS/FAIL lines (default 0.1)")
    a = ap.parse_args()
    c = statistics(".", a.t0)
    log = open("log.chargedParticleFoam").read()
    t, qp2, acc, N, n, tau_el, Q, m = (c[x] for x in ("t", "qp2", "acc", "N", "n", "tau_el", "Q", "m"))
    t0 = c["t0"]
    s = t >= t0
    pr = predictions(c)
    qp2_eq25, acc_eq28, dC_eq27 = pr["qp2"], pr["acc"], pr["dC"]
    tau_t, R, dt = c["tau_t"], c["R"], c["Rdt"]
    nlag = len(R)

    ok25 = abs(qp2[s].mean()/qp2_eq25 - 1)
    ok28 = abs(acc[s].mean()/acc_eq28 - 1)
    print("| quantity | simulated (t >= %.3g s) | Boutsikakis | ratio |" % t0)
    print("|---|---|---|---|")
    print("| agitation q_p^2 [m2/s2] | %.4g | %.4g (Eq. 25) | %.3f |" % (qp2[s].mean(), qp2_eq25, qp2[s].mean()/qp2_eq25))
    print("| <abs(F)>/m [m/s2] | %.4g | %.4g (Eq. 28) | %.3f |" % (acc[s].mean(), acc_eq28, acc[s].mean()/acc_eq28))
    print("| integral time tau_p^t [s] | %.4g | tau_pq^C = tau_el/sqrt(6) = %.4g (Eq. 26) | %.3f |" % (tau_t, tau_el/math.sqrt(6), tau_t/(tau_el/math.sqrt(6))))
    print("| integral time tau_p^t [s] | %.4g | tau_el = %.4g (Eq. 26) | %.3f |" % (tau_t, tau_el, tau_t/tau_el))
    print("| d_C [m] (Eq. 27) | - | %.4g | - |" % dC_eq27)
    print()
    print("%s: monoChargedCloud.agitation (vs Eq. 25: %.1f %%, tol %g %%)" % ("PASS" if ok25 < a.tol else "FAIL", 100*ok25, 100*a.tol))
    print("%s: monoChargedCloud.acceleration (vs Eq. 28: %.1f %%, tol %g %%)" % ("PASS" if ok28 < a.tol else "FAIL", 100*ok28, 100*a.tol))

    # The agitation's balance, Eq. (29) with the Stokes dissipation:
    # d q_p^2/dt = <a'.u'> - 2 q_p^2/tau_p, the rate by central differences
    if c["power"] is not None:
        res, rate = powerBalance(c)
        r = math.sqrt(np.mean(res**2)/np.mean(rate**2))
        print("%s: monoChargedCloud.powerBalance (Eq. 29: rms residual %.1e of the rms rate, tol 1e-2)"
              % ("PASS" if r < 1e-2 else "FAIL", r))

    # Isotropy, Eq. (10): the time mean of the normalised force covariance
    # is the identity (sampling noise of a few % at 2000 particles)
    if c["cov"] is not None:
        cm = c["cov"][s].mean(axis=0)
        worst = max(abs(cm[0] - 1), abs(cm[3] - 1), abs(cm[5] - 1), abs(cm[1]), abs(cm[2]), abs(cm[4]))
        print("%s: monoChargedCloud.isotropy (Eq. 10: <F'F'>/F^2 = I to %.3f, tol 0.1)"
              % ("PASS" if worst < 0.1 else "FAIL", worst))

    # The solver's Eq. 23 report against Eqs. 21-23 evaluated here
    rep = re.findall(r"q_p\^2 = (\S+) \((measured|Eq. 25[^)]*)\) m2/s2, d_C = (\S+) m, .*?Eq. 23 time step (\S+) s", log)
    worst = 0.0
    for q2, _, dC, dtm in rep:
        q2, dC, dtm = float(q2), float(dC), float(dtm)
        w = math.sqrt(16/math.pi*2/3*q2)                # Eq. (22)
        dC_ref = k*Q*Q/(0.5*m*w**2)                     # Eq. (21), m_pq = m/2
        dt_ref = 0.01*dC_ref/w                          # Eq. (23)
        worst = max(worst, abs(dC/dC_ref - 1), abs(dtm/dt_ref - 1))
    ok = len(rep) > 0 and worst < 1e-6
    print("%s: monoChargedCloud.eq23 (%d time-step reports vs Eqs. 21-23: max rel. difference %.1e)"
          % ("PASS" if ok else "FAIL", len(rep), worst))
    if a.png:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        fig, (a1, a2, a3) = plt.subplots(1, 3, figsize=(13, 3.8))
        a1.plot(t/tau_el, qp2/qp2_eq25)
        a1.axhline(1, color="k", ls="--", lw=0.8)
        a1.set_xlabel("t / tau_el"); a1.set_ylabel("q_p^2 / Eq. 25")
        a2.plot(t/tau_el, acc/acc_eq28)
        a2.axhline(1, color="k", ls="--", lw=0.8)
        a2.set_xlabel("t / tau_el"); a2.set_ylabel("<|F|>/m / Eq. 28")
        a3.plot(np.arange(nlag)*dt/tau_el, R)
        a3.axhline(0, color="k", lw=0.8)
        a3.set_xlabel("lag / tau_el"); a3.set_ylabel("R_p(lag)")
        for ax in (a1, a2, a3):
            ax.grid(alpha=0.3)
        fig.suptitle("Mono-charged cloud, N = %d, P3M (Boutsikakis 2023 Sec. 3)" % N)
        fig.tight_layout()
        fig.savefig(a.png, dpi=110)


if __name__ == "__main__":
    main()
