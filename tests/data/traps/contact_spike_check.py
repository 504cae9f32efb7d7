"""Independent check of contact_spike.lmx (mpmath only; run: python3 contact_spike_check.py).

The file's problem: find a and p on [0, a) with
    int_x^a t p(t)/sqrt(t^2 - x^2) dt + x s = delta - x^2 + G x,   s = int_0^a g(t) p(t) dt,
g(t) = exp(-((t - c)/w)^2)/(w sqrt(pi)), c = 1/(2 pi), p = 0 on [a, 2], B = 0, p >= 0.
For a given a the Abel part inverts in closed form: with q_a the inverse of delta - x^2,
q_a(t) = (2/pi)(delta + a^2 - 2 t^2)/sqrt(a^2 - t^2), and r_a the inverse of x,
r_a(t) = -(1/pi) d/du I(u) at u = t^2, I(u) = 2 (sqrt(A) sqrt(A - u) + u ln((sqrt(A) + sqrt(A - u))/sqrt(u))),
A = a^2, the solution is p = q_a + (G - s) r_a with s = (Q + G R)/(1 + R), Q = int g q_a,
R = int g r_a. Its coefficient of 1/sqrt(a^2 - t^2) is (2/pi)(delta - a^2 + (G - s) a), so
B = 0 is delta - a^2 + (G - s(a)) a = 0. This scans that function over (0, 2), locates its sign
changes and checks p >= 0 at each root. Output for w = 1e-4 (20 digits, a few minutes):
    root a = 0.70710678118654752  s = 0.877214643962  min p on [0, a) = 0.0636222 (admissible)
      s = G: p is the Hertz pressure (4/pi) sqrt(a^2 - t^2), P = (8/3) a^3 = 0.94280904158206336
    a = 1.058621631 : a pole of B (1 + R = 0), not a root
    root a = 1.5337231241010336  s = -0.330504397562  min p on [0, a) = -3.18672 (violates p >= 0)
"""
import sys

import mpmath as mp

mp.mp.dps = 20
delta = mp.mpf(1) / 2
c = 1 / (2 * mp.pi)
# The spike's width (contact_spike.lmx: 1e-4; contact_spike_2.lmx: 1e-2).
w = mp.mpf(sys.argv[1] if len(sys.argv) > 1 else "1e-4")


def g(t):
    return mp.exp(-(((t - c) / w) ** 2)) / (w * mp.sqrt(mp.pi))


def q(t, a):
    return 2 / mp.pi * (delta + a * a - 2 * t * t) / mp.sqrt(a * a - t * t)


def r(t, a):
    A = a * a
    big_i = lambda u: 2 * (mp.sqrt(A) * mp.sqrt(A - u) + u * mp.log((mp.sqrt(A) + mp.sqrt(A - u)) / mp.sqrt(u)))
    return -mp.diff(big_i, t * t) / mp.pi


def s_of(a):
    lo, hi = max(mp.mpf(0), c - 12 * w), min(a, c + 12 * w)
    if hi <= lo:
        return mp.mpf(0), mp.mpf(0)
    pts = mp.linspace(lo, hi, 9)
    Q = mp.quad(lambda t: g(t) * q(t, a), pts)
    R = mp.quad(lambda t: g(t) * r(t, a), pts)
    return (Q + G * R) / (1 + R), R


def b_of(a):
    return delta - a * a + (G - s_of(a)[0]) * a


# G itself: int g(t) (4/pi) sqrt(delta - t^2) dt (the spike's tails beyond 12 w are below e^-144).
with mp.workdps(40):
    G = mp.quad(lambda t: g(t) * 4 / mp.pi * mp.sqrt(delta - t * t), mp.linspace(c - 12 * w, c + 12 * w, 9))
    print("w =", mp.nstr(w, 3), " G =", mp.nstr(G, 30))


def report(lo, hi):
    for _ in range(50):
        m = (lo + hi) / 2
        if mp.sign(b_of(m)) == mp.sign(b_of(lo)):
            lo = m
        else:
            hi = m
    root = (lo + hi) / 2
    if abs(b_of(root)) > mp.mpf("1e-6"):
        print("a =", mp.nstr(root, 10), ": a pole of B (1 + R = 0), not a root")
        return
    s = s_of(root)[0]
    p = lambda t: q(t, root) + (G - s) * r(t, root)
    pmin = min(p(root * j / 400) for j in range(1, 400))
    print("root a =", mp.nstr(root, 17), " s =", mp.nstr(s, 12), " min p on [0, a) =", mp.nstr(pmin, 6),
          "(admissible)" if pmin >= 0 else "(violates p >= 0)")
    if abs(s - G) < mp.mpf("1e-12"):
        print("  s = G: p is the Hertz pressure (4/pi) sqrt(a^2 - t^2), P = (8/3) a^3 =", mp.nstr(8 * root**3 / 3, 17))


prev = None
for k in range(1, 100):
    a = mp.mpf(k) / 50
    v = b_of(a)
    if prev is not None and mp.sign(v) != mp.sign(prev[1]):
        report(prev[0], a)
    prev = (a, v)
