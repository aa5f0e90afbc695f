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
"""
import argparse, glob, math, re
import numpy as np

k = 8.9875517923e9


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--png")
    ap.add_argument("--from", dest="t0", type=float)
    ap.add_argument("--tol", type=float, default=0.1,
                    help="relative tolerance of the PASS/FAIL lines (default 0.1)")
    a = ap.parse_args()
    log = open("log.chargedParticleFoam").read()
    t = np.array([float(x) for x in re.findall(r"^Time = (\S+)", log, re.M)])
    qp2 = np.array([float(x) for x in re.findall(r"Particle agitation q_p\^2\s*=\s*(\S+)", log)])
    acc = np.array([float(x) for x in re.findall(r"Mean electrostatic acceleration\s*=\s*(\S+)", log)])
    nn = min(len(t), len(qp2), len(acc))
    t, qp2, acc = t[:nn], qp2[:nn], acc[:nn]
    m_ = re.search(r"N = (\d+), L = (\S+) m, n = (\S+) /m3, d = (\S+) m, tau_el = (\S+) s",
                   open("log.makeParcels").read())
    N, L, n, d, tau_el = int(m_.group(1)), float(m_.group(2)), float(m_.group(3)), float(m_.group(4)), float(m_.group(5))
    Q, m = 5e-9, 1.8e-4
    t0 = a.t0 if a.t0 is not None else 0.5*t[-1]
    s = t >= t0
    qp2_eq25 = k*Q**2*n**(1/3)/m
    acc_eq28 = 2.5*k*Q**2*n**(2/3)/m
    dC_eq27 = 3*math.pi/16*n**(-1/3)

    # Velocity autocorrelation of the sample
    f = glob.glob("postProcessing/lagrangian/cloud/sample/*/particleHistory.dat")[0]
    h = np.loadtxt(f)
    times = np.unique(h[:, 0])
    ids = np.unique(h[:, 2])
    U = h[:, 6:9].reshape(len(times), len(ids), 3)
    keep = times >= t0
    Us = U[keep]
    dt = times[1] - times[0]
    nlag = len(Us)//2
    R = np.array([np.mean(np.sum(Us[:len(Us) - l]*Us[l:], axis=2)) for l in range(nlag)])
    R /= R[0]
    zero = np.argmax(R <= 0) if (R <= 0).any() else len(R)
    tau_t = np.trapz(R[:zero], dx=dt)

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
