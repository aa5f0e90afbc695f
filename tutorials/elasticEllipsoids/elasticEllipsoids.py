#!/usr/bin/python3
"""Energy of elastic, frictionless ellipsoid impacts (elasticEllipsoids).

    elasticEllipsoids.py <case>          one run: per aspect ratio, the
                                         kinetic energy after/before of
                                         each pair and wall impact
    elasticEllipsoids.py --table <N>=<case> ...
                                         the same for several collision
                                         resolutions N (steps per collision
                                         time) and the observed order
    elasticEllipsoids.py --summary <case> <label>
                                         one line: the largest error
    elasticEllipsoids.py --deltaT <case> <N>
                                         the step that resolves the worst
                                         impact of the case with N steps

The state before comes from constant/parcels (makeParcels.py), the state
after from the last time of the run; energies are translational plus
rotational (principal moments of the ellipsoid), computed here from the
written fields, not taken from the solver's log. A pair or wall impact
counts only if its velocities changed; its bodies must be apart at the end
(Perram-Wertheim test, wall height), or the energy is not all kinetic."""
import os, re, sys
import numpy as np
from foamLagrangian import read_field, read_positions
from ellipsoids import mass, principal_moments, rotation
from ellipsoidGeometry import kinetic_energy, perram_wertheim, shape_inverse

RATIOS = [1.5, 2, 5, 10]


def read_parcels(case):
    text = open(os.path.join(case, "constant", "parcels")).read()
    vec = lambda key, s: np.array(re.search(key + r"\s*\(([^)]*)\)", s).group(1).split(), float)
    rows = re.findall(r"\{([^}]*)\}", text.split("parcels", 1)[1])
    return [dict(x=vec("position", r), U=vec("U", r), axes=vec("semiAxes", r),
                 q=vec("quaternion", r), omega=vec("omega", r)) for r in rows]


def last_time(case):
    times = [d for d in os.listdir(case) if re.fullmatch(r"[0-9.eE+-]+", d) and float(d) > 0]
    return max(times, key=float)


def analyse(case, rho=2500.0):
    """Rows (kind, aspect ratio, E_after/E_before - 1, hit, apart, dP, dL)
    per impact: dP, dL the change of a pair's momentum and angular momentum
    relative to m |U| and m |U| a (0 for wall impacts)."""
    before = read_parcels(case)
    lag = os.path.join(case, last_time(case), "lagrangian", "cloud")
    ids = read_field(os.path.join(lag, "origId")).astype(int)
    order = np.argsort(ids)
    f = lambda name: read_field(os.path.join(lag, name))[order]
    U, w, axes = f("U"), f("omegaBody"), f("semiAxes")
    # Centres from the Cartesian positions file: the drift of lazy tracking
    # is below the mesh tolerance, far below the separation test's margin
    x = read_positions(os.path.join(lag, "positions"))[order]
    qv, qw = f("orientationEps"), f("orientationEta")
    q = np.column_stack([qw, qv])
    if len(U) != len(before):
        sys.exit(f"{case}: {len(U)} parcels at the end, {len(before)} injected")
    # constant/parcels lists the pairs first (2 per pair), then wall impacts
    header = open(os.path.join(case, "constant", "parcels")).readline()
    nPairs = int(re.search(r"(\d+) pairs", header).group(1))
    rows = []
    for k in range(nPairs):
        i, j = 2*k, 2*k + 1
        E0 = sum(kinetic_energy(before[m]["axes"], rho, before[m]["U"], before[m]["omega"]) for m in (i, j))
        E1 = sum(kinetic_energy(axes[m], rho, U[m], w[m]) for m in (i, j))
        hit = np.linalg.norm(U[i] - before[i]["U"]) > 1e-9
        apart = perram_wertheim(shape_inverse(axes[i], q[i]), shape_inverse(axes[j], q[j]), x[j] - x[i]) > 1
        P0 = sum(momenta(before[m]["axes"], rho, before[m]["x"], before[m]["U"], before[m]["q"], before[m]["omega"]) for m in (i, j))
        P1 = sum(momenta(axes[m], rho, x[m], U[m], q[m], w[m]) for m in (i, j))
        pScale = mass(before[i]["axes"], rho)*np.linalg.norm(before[i]["U"])
        dP = np.linalg.norm(P1[0] - P0[0])/pScale
        # angular momentum about the origin (the pair feels no net force)
        dL = np.linalg.norm(P1[1] - P0[1])/(pScale*axes[i][0])
        rows.append(("pair", axes[i][0]/axes[i][1], E1/E0 - 1, hit, apart, dP, dL))
    for m in range(2*nPairs, len(before)):
        E0 = kinetic_energy(before[m]["axes"], rho, before[m]["U"], before[m]["omega"])
        E1 = kinetic_energy(axes[m], rho, U[m], w[m])
        hit = np.linalg.norm(U[m] - before[m]["U"]) > 1e-9
        apart = x[m][2] > np.sqrt(shape_inverse(axes[m], q[m])[2, 2])
        rows.append(("wall", axes[m][0]/axes[m][1], E1/E0 - 1, hit, apart, 0, 0))
    return rows


def momenta(axes, rho, x, U, q, omega_body):
    """Linear momentum m U and angular momentum x x m U + Q I omega_body
    about the origin (with x relative to a point near the pair: the
    positions are written to 17 digits)."""
    m = mass(axes, rho)
    I = principal_moments(axes, m)
    return np.array([m*np.asarray(U), np.cross(x, m*np.asarray(U)) + rotation(*q) @ (I*np.asarray(omega_body))])


def hertz_leapfrog_floor(N, phases=40):
    """Largest relative energy error of plain velocity Verlet
    (kick-drift-kick, the force at the point) over a 1D Hertz impact,
    x'' = -x^3/2 for x > 0 (units delta0, t0: every head-on Hertz impact),
    at deltaT = t_c/N with t_c = 3.2187 t0 (Johnson's
    2.868 (m*^2/(R E*^2 v))^(1/5)), over the phase of the first touch
    within a step: the integrator's error for an exactly conservative
    contact force without the cloud's step-averaged Hertz force."""
    tc = 3.2187
    dt = tc/N
    F = lambda x: -x**1.5 if x > 0 else 0.0
    worst = 0.0
    for phase in np.arange(phases)/phases:
        x, v = -phase*dt, 1.0
        a = F(x)
        for _ in range(3*N):
            v += 0.5*dt*a
            x += dt*v
            a = F(x)
            v += 0.5*dt*a
        worst = max(worst, abs(0.5*v*v + (0.4*x**2.5 if x > 0 else 0) - 0.5)/0.5)
    return worst


def summary(rows):
    """Per (kind, aspect ratio): number of impacts, max |dE/E|, and flags."""
    out = {}
    for kind in ("pair", "wall"):
        for ar in RATIOS:
            sel = [r for r in rows if r[0] == kind and abs(r[1] - ar) < 1e-6 and r[3]]
            errs = [abs(r[2]) for r in sel]
            out[(kind, ar)] = (len(sel), max(errs) if errs else float("nan"),
                               all(r[4] for r in sel))
    return out


def fixed_step(case, N, E=1e8, nu=0.3, rho=2500.0):
    """deltaT = t_c/N for the cloud's worst case (its fastest parcel at 1.2x
    its initial speed, head-on against a copy of itself at its sharpest tip:
    m* = m/2, R* = b^2/(2a), v = 2|U|), Johnson's t_c = 2.868 (m*^2/(R*
    E*^2 v))^(1/5) with E* = E/(2(1 - nu^2)): every impact then gets at least
    N steps and the cloud does not sub-cycle."""
    Estar = E/(2*(1 - nu*nu))
    tc = min(2.868*((mass(p["axes"], rho)/2)**2
                    /(min(p["axes"])**2/max(p["axes"])/2*Estar**2*2*1.2*np.linalg.norm(p["U"])))**0.2
             for p in read_parcels(case))
    return tc/N


if __name__ == "__main__":
    if sys.argv[1] == "--deltaT":
        print(f"{fixed_step(sys.argv[2], int(sys.argv[3])):.17g}")
    elif sys.argv[1] == "--table":
        runs = [(int(a.split("=", 1)[0]), a.split("=", 1)[1]) for a in sys.argv[2:]]
        rowsOf = {N: analyse(c) for N, c in runs}
        sums = [(N, summary(rowsOf[N])) for N, _ in runs]
        print("max |E_after/E_before - 1| over the impacts of each kind and aspect ratio")
        print(f"{'impact':6} {'AR':>5} {'n':>3} " + " ".join(f"{'N=' + str(N):>10}" for N, _ in sums)
              + " " + " ".join(f"{'order ' + str(a) + '/' + str(b):>12}" for (a, _), (b, _) in zip(sums, sums[1:])))
        for key in sums[0][1]:
            errs = [s[key][1] for _, s in sums]
            orders = [np.log(e0/e1)/np.log(N1/N0) if e0 > 0 and e1 > 0 else float("nan")
                      for (N0, _), (N1, _), e0, e1 in zip(sums, sums[1:], errs, errs[1:])]
            apart = all(s[key][2] for _, s in sums)
            print(f"{key[0]:6} {key[1]:5g} {sums[0][1][key][0]:3d} "
                  + " ".join(f"{e:10.2e}" for e in errs) + " "
                  + " ".join(f"{o:12.2f}" for o in orders) + ("" if apart else "  NOT APART"))
        pooled = [max(v[1] for v in s.values()) for _, s in sums]
        orders = [np.log(e0/e1)/np.log(N1/N0) for (N0, _), (N1, _), e0, e1
                  in zip(sums, sums[1:], pooled, pooled[1:])]
        print(f"{'all':6} {'':5} {sum(v[0] for v in sums[0][1].values()):3d} "
              + " ".join(f"{e:10.2e}" for e in pooled) + " "
              + " ".join(f"{o:12.2f}" for o in orders))
        print(f"{'1D':6} {'plain':5} {'':3} "
              + " ".join(f"{hertz_leapfrog_floor(N):10.2e}" for N, _ in runs)
              + "   (plain velocity Verlet, head-on Hertz impact at deltaT = t_c/N)")
        for N, _ in runs:
            pr = [r for r in rowsOf[N] if r[0] == "pair"]
            print(f"N={N}: pairs' momentum change max {max(r[5] for r in pr):.1e} of m|U|,"
                  f" angular momentum change max {max(r[6] for r in pr):.1e} of m|U|a")
    elif sys.argv[1] == "--summary":
        rows = analyse(sys.argv[2])
        hit = [r for r in rows if r[3]]
        print(f"{sys.argv[3]}: max |E_after/E_before - 1| {max(abs(r[2]) for r in hit):.2e}"
              f" over {len(hit)} of {len(rows)} impacts"
              + ("" if all(r[4] for r in hit) else "  NOT APART"))
    else:
        for kind, ar, dE, hit, apart, dP, dL in analyse(sys.argv[1]):
            print(f"{kind} AR {ar:5g} dE/E {dE:+.3e} {'hit' if hit else 'miss'} {'apart' if apart else 'IN CONTACT'}")
