"""Numerical checks of the intermediate steps of the small-μ derivation in
docs/hertz_asymptotics.md (parts a to d there). Needs mpmath only:

    python3 docs/hertz_asymptotics_checks.py

The solver-side checks (the inner shear, the power law of p, and the
formula for c) are in tests/hertz_limits.rs.
"""
from mpmath import mp, mpf, gamma as G, cot, pi, findroot, quad, sqrt, asin, log, beta as B

mp.dps = 30

print("(a) step 1: full-slip exponent s0, root of cot(pi z) = mu g z G(z)^2/G(z+1/2)^2, s = 2z-1")
for g in [mpf(1) / 2, mpf(1) / 3]:
    for mu in [mpf("0.01"), mpf("0.001")]:
        z = findroot(lambda z: cot(pi * z) - mu * g * z * G(z) ** 2 / G(z + 0.5) ** 2,
                     mpf("0.5") - mu * g / 2)
        s0 = 2 * z - 1
        beta = g * (2 * log(2) - 1)
        print(f"  gamma={float(g):.4f} mu={float(mu)}: s0={mp.nstr(s0, 12)}"
              f"  -s0/(mu gamma)-1 = {mp.nstr(-s0 / (mu * g) - 1, 8)}  beta*mu = {mp.nstr(beta * mu, 8)}")

print("(b) step 4: T[(2/pi) asin](xi) = int_xi^1 (2/pi) asin(t)/sqrt(t^2-xi^2) dt vs ln(1+sqrt(1-xi^2))")
for xi in [mpf("0.1"), mpf("0.5"), mpf("0.9")]:
    # t = sqrt(xi^2 + u^2): dt/sqrt(t^2 - xi^2) = du/t
    lhs = quad(lambda u: (2 / pi) * asin(sqrt(xi ** 2 + u ** 2)) / sqrt(xi ** 2 + u ** 2),
               [0, sqrt(1 - xi ** 2)])
    print(f"  xi={float(xi)}: {mp.nstr(mp.re(lhs), 15)}  {mp.nstr(log(1 + sqrt(1 - xi ** 2)), 15)}")
xi = mpf("0.3")
lhs = quad(lambda t: 1 / sqrt(t * t - xi * xi) - 1 / sqrt(t * t - 1), [1, 2, mp.inf])
print(f"  int_1^inf [1/sqrt(t^2-xi^2) - 1/sqrt(t^2-1)] dt at xi=0.3: {mp.nstr(lhs, 12)}"
      f"  -ln(1+sqrt(1-xi^2)) = {mp.nstr(-log(1 + sqrt(1 - xi * xi)), 12)}")

print("(c) steps 3 and 5: the constants")
print("  int_0^1 u ln u/sqrt(1-u^2) du =", mp.nstr(quad(lambda u: u * log(u) / sqrt(1 - u * u), [0, 1]), 15),
      "  ln2-1 =", mp.nstr(log(2) - 1, 15))
print("  int_0^1 (1/sqrt(1-t^2)-1)/t dt =", mp.nstr(quad(lambda t: (1 / sqrt(1 - t * t) - 1) / t, [0, 1]), 15),
      "  ln2 =", mp.nstr(log(2), 15))
for s in [mpf("-1e-3"), mpf("-1e-4")]:
    print(f"  s={float(s)}: B(-s/2,1/2)/2 - (-1/s) = {mp.nstr(B(-s / 2, 0.5) / 2 + 1 / s, 10)}"
          f" (-> ln2 = {mp.nstr(log(2), 10)});"
          f"  (B(1+s/2,1/2)/2 - 1)/s = {mp.nstr((B(1 + s / 2, 0.5) / 2 - 1) / s, 10)}"
          f" (-> ln2-1 = {mp.nstr(log(2) - 1, 10)})")

print("(d) step 4, the lemma: v = (2/pi)/(x0^2 - xi^2) solves int_0^tau v/sqrt(tau^2-xi^2) dxi")
print("    = 1/(x0 sqrt(x0^2-tau^2)) for tau < x0 and = 0 (principal value) for tau > x0")
x0 = mpf("0.7")
for tau in [mpf("0.3"), mpf("0.6")]:
    v = quad(lambda ph: (2 / pi) / (x0 ** 2 - (tau * mp.sin(ph)) ** 2), [0, pi / 2])
    print(f"  tau={float(tau)}: {mp.nstr(v, 15)}  {mp.nstr(1 / (x0 * sqrt(x0 ** 2 - tau ** 2)), 15)}")
for tau in [mpf("0.9"), mpf("1.5")]:
    f = lambda xi: 1 / ((x0 ** 2 - xi ** 2) * sqrt(tau ** 2 - xi ** 2))
    w = min(x0, tau - x0)  # pair x0 - u with x0 + u: the principal value
    pv = quad(lambda u: f(x0 - u) + f(x0 + u), [0, w])
    if x0 - w > 0:
        pv += quad(f, [0, x0 - w])
    if x0 + w < tau:
        pv += quad(f, [x0 + w, tau])
    print(f"  tau={float(tau)}: PV = {mp.nstr(pv, 6)}")
