# The exact two-sphere reference (etc/python/twoDielectricSpheres.py) against
# independent closed forms: Coulomb's law when nothing polarises, Kelvin's
# image of a point charge at an isolated charged conducting sphere, the
# single-sphere Legendre series of a point charge at a dielectric sphere
# (Jackson 3rd ed. Problem 4.x form, summed here independently), and the
# symmetry U(1, 2) = U(2, 1) for unequal radii and permittivities.
. "$(dirname "$0")/common.sh.inc"

$PY - <<PYEOF
import math, sys
sys.path.insert(0, "$top/etc/python")
import twoDielectricSpheres as tds
eps0 = tds.eps0
k = 1 / (4 * math.pi * eps0)

def report(name, err, tol, detail):
    ok = abs(err) <= tol
    print("%s: twoDielectricSpheres.%s (%s: rel. error %.2e, tol %.0e)"
          % ("PASS" if ok else "FAIL", name, detail, abs(err), tol))

# 1. k1 = k2 = k0: Coulomb in the medium, any radii
e = 0
for a1, a2, d, k0 in ((1, 0.3, 1.4, 1), (0.5, 2, 2.6, 3.5)):
    F = tds.force(2e-9, -3e-9, a1, a2, d, k0, k0, k0)
    e = max(e, abs(F / (k * 2e-9 * -3e-9 / (k0 * d * d)) - 1))
report("coulomb", e, 1e-8, "no contrast, two radii ratios and media")

# 2. point charge q (a2 -> 0, k2 = k0) at an isolated conducting sphere
# (charge Q, radius a): Kelvin images q' = -q a/d at a^2/d, Q - q' at the centre
e = 0
q, Q, a = 1e-9, 3e-9, 1.0
for d in (1.05, 1.3, 2.0, 5.0):
    Fk = k * q * ((Q + q * a / d) / d**2 - q * a / d / (d - a * a / d)**2)
    F = tds.force(Q, q, a, 1e-7, d, math.inf, 1.0)
    e = max(e, abs(F / Fk - 1))
report("kelvinImage", e, 1e-6, "point charge at a charged conductor, d/a 1.05-5")

# 3. point charge at a neutral dielectric sphere (radius a, kappa kp, medium k0):
# F = -q^2 k/k0 sum_n n (n+1) (kp - k0)/(n kp + (n+1) k0) a^(2n+1)/d^(2n+3)
e = 0
for kp, k0, d in ((2.5, 1, 1.2), (40, 1, 1.1), (4, 2, 1.5), (1.5, 3, 1.05)):
    s, n = 0.0, 1
    while True:
        t = n * (n + 1) * (kp - k0) / (n * kp + (n + 1) * k0) * a**(2 * n + 1) / d**(2 * n + 3)
        s += t
        if abs(t) < 1e-17 * abs(s):
            break
        n += 1
    Fs = -k / k0 * q * q * s
    F = tds.force(0.0, q, a, 1e-7, d, kp, k0, k0)
    e = max(e, abs(F / Fs - 1))
report("dielectricSeries", e, 1e-6, "point charge at a neutral dielectric sphere, kp/k0 0.5-40")

# 4. symmetry: exchanging the spheres leaves U unchanged
U12 = tds.energy(1e-9, 2.5e-9, 1.0, 0.4, 1.5, 7.0, 2.0, 1.3)
U21 = tds.energy(2.5e-9, 1e-9, 0.4, 1.0, 1.5, 2.0, 7.0, 1.3)
report("symmetry", U12 / U21 - 1, 1e-12, "unequal radii and permittivities")
PYEOF
