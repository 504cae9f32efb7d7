"""Numerical checks of the intermediate steps of the derivations in
docs/hertz_asymptotics.md: the small-μ limit (parts a to d, and j for the
O(μ²) term of P*) and the large-μ limit (parts e to i). Needs mpmath only:

    python3 docs/hertz_asymptotics_checks.py        # about 2 minutes

The solver-side checks (the inner shear, the power law of p, the formula
for c at both ends, the rate 1/μ and P*) are in tests/hertz_limits.rs.
"""
from mpmath import mp, mpf, mpc, gamma as G, cot, pi, findroot, quad, sqrt, asin, log, beta as B

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

print("(e) large mu, inner problem: the Mellin symbol of k(r) = ln r/(pi^2 (r-1)),")
print("    int_0^inf k(r) r^(-z) dr, against 1/sin^2(pi z)  (r = e^x)")
for z in [mpf("0.3"), mpc("0.25", "0.4")]:
    v = quad(lambda x: mp.exp(x * (1 - z)) * x / mp.expm1(x), [-mp.inf, 0, mp.inf]) / pi ** 2
    print(f"  z={mp.nstr(z, 3)}: {mp.nstr(v, 15)}  {mp.nstr(1 / mp.sin(pi * z) ** 2, 15)}")

print("(f) the full-stick (outer) problem: the Abel reduction and its solution")
# lower Abel of p from F = kappa1 p: (2x/pi) PV int_0^1 F/(x^2 - xi^2); test p = 1, F = sqrt(1-x^2)
def pv0(f, x):
    """PV int_0^1 f(xi)/(x^2 - xi^2) dxi, subtracting the pole at xi = x."""
    fx = f(x)
    reg = quad(lambda t: (f(t) - fx) / (x * x - t * t), [0, x, 1])
    return reg + fx * mp.log((1 + x) / (1 - x)) / (2 * x)
for x in [mpf("0.3"), mpf("0.8")]:
    print(f"  p=1, x={float(x)}: (2x/pi) PV int F/(x^2-xi^2) = {mp.nstr(2 * x / pi * pv0(lambda t: sqrt(1 - t * t), x), 15)}"
          f"  lower Abel of p = x = {float(x)}")
    Gq = lambda t: mp.acosh(1 / t)  # G(xi)/xi for q = 1
    print(f"  q=1, x={float(x)}: (2x^2/pi) PV int (G/xi)/(x^2-xi^2) = {mp.nstr(2 * x * x / pi * pv0(Gq, x), 15)}"
          f"  x int_0^x q/sqrt(x^2-t^2) = pi x/2 = {mp.nstr(pi * x / 2, 15)}")
for nu in [mpf(0), mpf("-0.5")]:
    g = (1 - 2 * nu) / (2 - 2 * nu)
    e = mp.atanh(g) / pi
    W = lambda x: mp.cosh(pi * e) * mp.exp(1j * e * mp.log((1 + x) / (1 - x)))
    def H(f, x):
        """(1/pi) PV int_{-1}^1 f(xi)/(xi - x) dxi."""
        fx = f(x)
        return (quad(lambda t: (f(t) - fx) / (t - x), [-1, x, 1]) + fx * mp.log((1 - x) / (1 + x))) / pi
    for x in [mpf("0.3"), mpf("0.9")]:
        F = lambda t: mp.re(W(t))
        Gf = lambda t: mp.im(W(t))
        r1 = F(x) - g * H(Gf, x) - 1
        r2 = Gf(x) + g * H(F, x)
        print(f"  nu={float(nu)} x={float(x)}: F - g H G - 1 = {mp.nstr(r1, 3)},  G + g H F = {mp.nstr(r2, 3)}")
    Pstar = quad(lambda x: mp.re(W(x)), [0, 0.5, 0.9, 0.99, 1])
    print(f"  nu={float(nu)}: P* = int_0^1 F = {mp.nstr(Pstar, 15)}  artanh(g)/g = {mp.nstr(mp.atanh(g) / g, 15)}")

print("(g) the edge field of the outer solution and the phase identity")
e = mp.atanh(mpf(1) / 2) / pi
for s in [mpf("1e-4"), mpf("1e-6")]:
    t = 1 - s
    # u = t + v^2 removes the root at u = t
    lhs = quad(lambda v: 2 * (t + v * v) * (s - v * v) ** (-1j * e) / sqrt(2 * t + v * v), [0, sqrt(s)])
    lead = B(1 - 1j * e, 0.5) * s ** (0.5 - 1j * e) / sqrt(2)
    print(f"  s={float(s)}: int_t^1 u(1-u)^(-ie)/sqrt(u^2-t^2) du / leading term - 1 = {mp.nstr(lhs / lead - 1, 4)}")
for nu in [mpf("0.3"), mpf(0), mpf("-0.9")]:
    g = (1 - 2 * nu) / (2 - 2 * nu)
    e = mp.atanh(g) / pi
    ag = lambda z: mp.im(mp.loggamma(z))
    psi_in = ag(2j * e) - 2 * ag(0.5 + 1j * e)
    psi_out = -e * log(2) + ag(1 + 1j * e) - ag(0.5 + 1j * e)
    d = psi_in - psi_out - (3 * e * log(2) - pi / 2)
    print(f"  nu={float(nu)}: psi_in - psi_out - (3 e ln2 - pi/2) = {mp.nstr(d - mp.nint(d / pi) * pi, 3)} (mod pi);"
          f"  delta0 = 8 exp(-pi/(2e)) = {mp.nstr(8 * mp.exp(-pi / (2 * e)), 10)}")

print("(h) the inner solution in real space (nu = 0): P(t) = sum of the residues of")
print("    G(1/2-z-ie) G(1/2-z+ie)/G(1-z)^2 t^(-z); (1-g^2) P(t) against K P(t)")
mp.dps = 15
g = mpf(1) / 2
e = mp.atanh(g) / pi
cn = [(-1) ** n * G(2j * e - n) / (mp.factorial(n) * G(0.5 + 1j * e - n) ** 2) for n in range(3000)]
def Pin(t):
    s, tn = mpc(0), t ** (-0.5 + 1j * e)
    for n in range(len(cn)):
        term = cn[n] * tn
        s += term
        tn /= t
        if abs(term) < 1e-17 and n > 5:
            break
    return 2 * mp.re(s)
def KP(t):
    f = lambda s: Pin(s) * (log(s / t) / (s - t) if s != t else 1 / t)
    return quad(f, [1, 1.001, 1.01, 1.1, t, 2 * t, 10 * t, 100 * t, mp.inf]) / pi ** 2
for t in [mpf("1.5"), mpf(3)]:
    print(f"  t={float(t)}: (1-g^2)P = {mp.nstr((1 - g * g) * Pin(t), 12)}  KP = {mp.nstr(KP(t), 12)}")
print(f"  c1/c0 = {mp.nstr(cn[1] / cn[0], 12)}  against (1/2 - ie)/2 = {mp.nstr((0.5 - 1j * e) / 2, 12)}")

print("(i) the rate: -cosh^2(pi e) Im S+(z1), partial sums over the poles z = k of S (tends to -1/2);")
print("    zeta = cosh^2(pi e)(S+(z3) - S+(z1)), z3 = 3/2 - ie: the first-order change of c1/c0")
mp.dps = 20
for nu in [mpf(0), mpf("-0.5")]:
    g = (1 - 2 * nu) / (2 - 2 * nu)
    e = mp.atanh(g) / pi
    ch = mp.cosh(pi * e)
    Fm = lambda z: -mp.hyp3f2(0.5 - 1j * e, 0.5 + 1j * e, z, 1, z + 1, 1) / (g * ch * z)
    h = lambda z: G(0.5 + z + 1j * e) * G(0.5 + z - 1j * e) * Fm(z) / pi ** 2
    z1 = mpf("0.5") - 1j * e
    z3 = mpf("1.5") - 1j * e
    S, S3 = mpc(0), mpc(0)
    out = []
    for k in range(1, 41):
        hk, dh = h(k), mp.diff(h, k)
        a = hk / mp.factorial(k - 1) ** 2
        b = (dh - 2 * mp.digamma(k) * hk) / mp.factorial(k - 1) ** 2
        S += a / (z1 - k) ** 2 + b / (z1 - k)
        S3 += a / (z3 - k) ** 2 + b / (z3 - k)
        if k in (10, 20, 40):
            out.append(f"K={k}: {mp.nstr(-ch ** 2 * mp.im(S), 8)}")
    print(f"  nu={float(nu)}: " + ", ".join(out))
    zeta = ch ** 2 * (S3 - S)
    kappa = 1 / (2 * e)
    print(f"    zeta = {mp.nstr(zeta, 6)} (K=40); P* rate -(kappa + Re zeta)/2 = {mp.nstr(-(kappa + mp.re(zeta)) / 2, 6)}")

print("(j) small mu: the mu^2 coefficient of P*, g^2 J with")
print("    J = -(2/pi) int_0^1 (-1 + (2/pi) x K(x)) (K(x) - E(x))/x dx  (K, E of modulus x)")
mp.dps = 20
J = -(2 / pi) * quad(lambda x: (-1 + (2 / pi) * x * mp.ellipk(x * x)) * (mp.ellipk(x * x) - mp.ellipe(x * x)) / x, [0, 1])
print(f"  J = {mp.nstr(J, 15)}")
x = mpf("0.6")
v = (2 / pi) * (mp.ellipk(x * x) - mp.ellipe(x * x)) / x
lhs = quad(lambda u: (2 / pi) * (mp.ellipk((x * mp.sin(u)) ** 2) - mp.ellipe((x * mp.sin(u)) ** 2)) / (x * mp.sin(u)), [0, pi / 2])
print(f"  K v = w at tau = 0.6: tau int_0^tau v/sqrt(tau^2-xi^2) = {mp.nstr(x * lhs, 15)}  1 - sqrt(1-tau^2) = {mp.nstr(1 - sqrt(1 - x * x), 15)}")
