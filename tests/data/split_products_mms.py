"""Right sides of tests/data/split_products_mms.lmx, derived exactly.

Run once (python3 tests/data/split_products_mms.py, sympy 1.14, mpmath 1.3):
prints the right sides as lmx expressions and checks them against the
operators applied by mpmath quadrature (50 digits) at a few points.

System on [0, 1], A = int(0..x) dt, B = int(0..1) (x + t)^2 dt, J = int(0..1) dt:
  p - J p - 2*A*B p + A*B q = f1            on [0, 1]
  q - J q + B*A q - 2*B*A p = f2            on [0, 1/2)
  q = 2*p                                   on [1/2, 1]
  condition int(0..1) p(x) dx = sin(1)
Exact p = cos x, q = e^x on [0, 1/2), q = 2 cos x on [1/2, 1].
(p, q) = (1, 2) solves the homogeneous system, so the side condition is
what makes the solution unique.
"""
import sympy as sp
import mpmath as mp

x, t, s = sp.symbols("x t s", real=True)
h = sp.Rational(1, 2)
p = sp.cos(t)
q0 = sp.exp(t)          # q on [0, 1/2)
q1 = 2 * sp.cos(t)      # q on [1/2, 1]


def integ(f0, f1, lo, hi):
    """Integral over [lo, hi] of the piecewise function (f0 below 1/2, f1 above)."""
    total = 0
    if lo < h:
        total += sp.integrate(f0, (t, lo, min(hi, h)))
    if hi > h:
        total += sp.integrate(f1, (t, max(lo, h), hi))
    return total


def B(f0, f1):
    return integ((x + t) ** 2 * f0, (x + t) ** 2 * f1, 0, 1)


def A_of(expr_x):
    """A applied to a function of x given as an expression in x: int_0^x."""
    return sp.integrate(expr_x.subs(x, s), (s, 0, x))


def J(f0, f1):
    return integ(f0, f1, 0, 1)


# eq1 on [0, 1]
ABp = A_of(B(p, p))
ABq = A_of(B(q0, q1))
f1 = sp.cos(x) - J(p, p) - 2 * ABp + ABq
# eq2 on [0, 1/2): (A u)(t) for the piecewise u, then B of it
Ap_t = sp.integrate(sp.cos(s), (s, 0, t))
Aq_lo = sp.integrate(sp.exp(s), (s, 0, t))
Aq_hi = sp.integrate(sp.exp(s), (s, 0, h)) + sp.integrate(2 * sp.cos(s), (s, h, t))
BAq = B(Aq_lo, Aq_hi)
BAp = B(Ap_t, Ap_t)
f2 = sp.exp(x) - J(q0, q1) + BAq - 2 * BAp
f1 = sp.collect(sp.expand(sp.simplify(f1)), x)
f2 = sp.collect(sp.expand(sp.simplify(f2)), x)


def lmx(e):
    return str(e).replace("**", "^").replace("E", "exp(1)")


print("f1 =", lmx(f1))
print("f2 =", lmx(f2))

# Independent check: the operators applied by quadrature.
mp.mp.dps = 50
P = lambda u: mp.cos(u)
Q = lambda u: mp.exp(u) if u < 0.5 else 2 * mp.cos(u)
quad = lambda f, a, b: mp.quad(f, [a, 0.5, b] if a < 0.5 < b else [a, b])
Bm = lambda u, X: quad(lambda T: (X + T) ** 2 * u(T), 0, 1)
Am = lambda u, X: quad(u, 0, X)
Jm = lambda u: quad(u, 0, 1)
for X in [mp.mpf("0.1"), mp.mpf("0.37"), mp.mpf("0.8")]:
    g1 = P(X) - Jm(P) - 2 * Am(lambda s_: Bm(P, s_), X) + Am(lambda s_: Bm(Q, s_), X)
    e1 = abs(g1 - sp.N(f1.subs(x, sp.Float(str(X), 50)), 50))
    print(f"x = {X}: |f1 - direct| = {mp.nstr(e1, 3)}", end="")
    if X < 0.5:
        g2 = Q(X) - Jm(Q) + Bm(lambda s_: Am(Q, s_), X) - 2 * Bm(lambda s_: Am(P, s_), X)
        e2 = abs(g2 - sp.N(f2.subs(x, sp.Float(str(X), 50)), 50))
        print(f", |f2 - direct| = {mp.nstr(e2, 3)}", end="")
    print()
    assert e1 < 1e-30
print("side condition value: int(0..1) cos = sin(1)")
