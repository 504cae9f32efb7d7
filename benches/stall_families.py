#!/usr/bin/env python3
"""The stall families of issue 29 over Q[x], seeded, and peer timings.

Each family is a seeded generator (`FAMILIES`); every matrix is written in
lambdamat's syntax and given to `lambdamat smith F --json` (CPU time of the
whole process), PARI/GP's `matsnf(M, 3)` (its own `getabstime()`) and
Singular's jacobson.lib `smith(M, 1)` (its own `timer`), interleaved: the
three runs of one matrix follow each other. Peers get a CPU limit and are
reported as "> T". The invariant factors' degrees are compared where a
peer finished. PARI's `matsnf` takes square matrices only, so a non-square
input goes to PARI bordered with zero rows or columns (same nonzero
invariant factors).

Usage: stall_families.py BIN OUTDIR [--only NAME,...] [--timeout 30]
       [--ours-timeout 60] [--no-pari] [--no-singular] [--emit-only]
       [--list]
"""
import argparse
import fractions
import json
import os
import random
import re
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.environ.get("SMITH_PEERS_DIR", "/work/shared/bench"))
import peers_grid as pg  # noqa: E402
import smith_peers as sp  # noqa: E402


def rnd_poly(rnd, d, lo=-9, hi=9):
    return [rnd.randint(lo, hi) for _ in range(d + 1)]


def dense(m, n, d, seed):
    rnd = random.Random(seed)
    return [[rnd_poly(rnd, d) for _ in range(n)] for _ in range(m)]


def rank_deficient(n, r, db, dc, seed):
    """B (n×r, degree db) · C (r×n, degree dc): rank r < n."""
    return pg.matmul(dense(n, r, db, seed), dense(r, n, dc, seed + 1000))


def diagonal(m, n):
    """diag(x − 1, …, x − min(m, n)) padded with zero rows or columns."""
    return [[[-(i + 1), 1] if i == j else [0] for j in range(n)] for i in range(m)]


def big_rational(n, d, digits, seed):
    """Dense n×n of degree d whose coefficients are rationals with
    numerators and denominators of about `digits` digits."""
    rnd = random.Random(seed)

    def q():
        num = rnd.randint(10 ** (digits - 1), 10**digits) * rnd.choice([-1, 1])
        den = rnd.randint(10 ** (digits - 1), 10**digits)
        return fractions.Fraction(num, den)

    return [[[q() for _ in range(d + 1)] for _ in range(n)] for _ in range(n)]


def one_big_coefficient(d, bits, seed):
    """2×2 of degree d with small coefficients but one of `bits` bits."""
    m = dense(2, 2, d, seed)
    rnd = random.Random(seed + 7)
    m[0][0][d // 2] = rnd.getrandbits(bits) | (1 << (bits - 1))
    return m


def sparse(n, extra, d, seed, diag=True):
    """n×n with random degree-d entries on the diagonal (if `diag`) and
    `extra` more entries at random off-diagonal places."""
    rnd = random.Random(seed)
    m = [[[0] for _ in range(n)] for _ in range(n)]
    if diag:
        for i in range(n):
            m[i][i] = rnd_poly(rnd, d)
    placed = 0
    while placed < extra:
        i, j = rnd.randrange(n), rnd.randrange(n)
        if i != j and m[i][j] == [0]:
            m[i][j] = rnd_poly(rnd, d)
            placed += 1
    return m


def singular_sparse(n, nnz, d, seed):
    """n×n with `nnz` random entries and one row a combination of two
    others (so it is singular)."""
    m = sparse(n, nnz, d, seed, diag=False)
    for j in range(n):
        m[n - 1][j] = pg.padd(m[0][j], m[1][j])
    return m


FAMILIES = {
    # rank-deficient B·C
    "rankdef_12_d2": lambda: rank_deficient(12, 9, 1, 1, 1),
    "rankdef_16_d1": lambda: rank_deficient(16, 12, 1, 0, 1),
    # rectangular dense
    "rect_13x10_d2": lambda: dense(13, 10, 2, 1),
    "rect_16x19_d2": lambda: dense(16, 19, 2, 1),
    "rect_8x11_d1": lambda: dense(8, 11, 1, 1),
    # non-square diagonal and its square twin
    "diag_39x40": lambda: diagonal(39, 40),
    "diag_40x41": lambda: diagonal(40, 41),
    "diag_39x39": lambda: diagonal(39, 39),
    # large rational coefficients
    "bigq_4_d2": lambda: big_rational(4, 2, 45, 1),
    "bigq_6_d2": lambda: big_rational(6, 2, 60, 1),
    "bigc_2_d50": lambda: one_big_coefficient(50, 2322, 1),
    "bigc_2_d100": lambda: one_big_coefficient(100, 3322, 1),
    # sparse
    "sparse_24_e24": lambda: sparse(24, 24, 1, 1),
    "sparse_24_e24_d2": lambda: sparse(24, 24, 2, 1),
    "sparse_sing_17": lambda: singular_sparse(17, 45, 1, 1),
    "sparse_64": lambda: sparse(64, 64, 1, 1),
    "sparse_100": lambda: sparse(100, 100, 1, 1),
    # high degree
    "dense_4_d200": lambda: dense(4, 4, 200, 1),
}


def coef_str(c):
    if isinstance(c, fractions.Fraction):
        return f"{c.numerator}/{c.denominator}" if c.denominator != 1 else str(c.numerator)
    return str(c)


def poly_str(c, var="x"):
    terms = []
    for k, a in enumerate(c):
        if a == 0:
            continue
        a = coef_str(a)
        terms.append(f"({a})*{var}^{k}" if k else f"({a})")
    return "+".join(terms) or "0"


def lmx(m):
    rows = ";\n  ".join(
        ", ".join(re.sub(r"\*x\^1\b", "*x", poly_str(e)) for e in row) for row in m
    )
    return f"var x\nmatrix A = [\n  {rows}\n]\nsmith A\n"


def padded_square(m):
    """m bordered with zero rows or columns to a square: the same nonzero
    invariant factors (PARI's `matsnf` takes square matrices only)."""
    rows, cols = len(m), len(m[0])
    k = max(rows, cols)
    return [[m[i][j] if i < rows and j < cols else [0] for j in range(k)] for i in range(k)]


def run_pari(m, timeout):
    m = padded_square(m)
    rows = ";".join(",".join(poly_str(e) for e in row) for row in m)
    prog = (
        f"M=[{rows}];t=getabstime();r=matsnf(M,3);t=getabstime()-t;D=r[3];"
        "print(t);print(vector(min(#D[,1],#D),i,if(D[i,i]==0,-1,poldegree(D[i,i]))));"
    )
    return pari_like(["gp", "-q", "-s", "1G"], prog, timeout, pari=True)


def run_singular(m, timeout):
    rows, cols = len(m), len(m[0])
    ent = ",".join(poly_str(e) for row in m for e in row)
    k = min(rows, cols)
    prog = (
        'LIB "jacobson.lib";\nring R = 0, x, dp;\n'
        f"matrix M[{rows}][{cols}] = {ent};\n"
        'system("--ticks-per-sec", 1000);\nint t0 = timer;\n'
        "list L = smith(M, 1);\nint t1 = timer;\n"
        'print(string(t1 - t0));\nmatrix D = L[2];\nint i; string s = "";\n'
        f"for (i = 1; i <= {k}; i++) {{ if (D[i, i] == 0) {{ s = s + \"-1 \"; }} "
        'else { s = s + string(deg(D[i, i])) + " "; } }\n'
        "print(s);\nquit;\n"
    )
    return pari_like(["Singular", "-q", "--no-warn"], prog, timeout, pari=False)


def pari_like(cmd, prog, timeout, pari):
    try:
        p = subprocess.run(
            cmd, input=prog, capture_output=True, text=True,
            timeout=20 * timeout, preexec_fn=pg.cpu_limit(timeout),
        )
    except subprocess.TimeoutExpired:
        return {"cpu": None}
    lines = [l for l in p.stdout.splitlines() if l.strip()]
    if len(lines) < 2:
        if p.returncode < 0:
            return {"cpu": None}
        return {"cpu": None, "error": (p.stderr or p.stdout)[-2000:]}
    toks = lines[1].strip("[]").split(",") if pari else lines[1].split()
    try:
        degs = [int(x) for x in toks if x.strip()]
    except ValueError:
        # e.g. Singular prints "?" for a diagonal entry it could not read.
        return {"cpu": None, "error": "unreadable degrees: " + lines[1][:200]}
    return {"cpu": int(lines[0]) / 1000.0, "degs": sorted(d for d in degs if d >= 0)}


def run_ours(binary, path, timeout):
    """`lambdamat smith F --json` under a CPU limit of `timeout` seconds
    (RLIMIT_CPU, so nothing is left running); CPU time from wait4."""
    p = subprocess.Popen([binary, "smith", path, "--json"], stdout=subprocess.PIPE,
                         stderr=subprocess.DEVNULL, preexec_fn=pg.cpu_limit(timeout))
    stdout = p.stdout.read()
    _, status, ru = os.wait4(p.pid, 0)
    p.returncode = os.waitstatus_to_exitcode(status)
    if p.returncode < 0:
        return {"cpu": None}
    out = {"cpu": ru.ru_utime + ru.ru_stime, "kb": ru.ru_maxrss, "rc": p.returncode}
    if p.returncode == 0:
        v = json.loads(stdout)
        out["degs"] = [pg.poly_degree(f) for f in v["invariant_factors"]]
        out["uv"] = v.get("U") is not None
    return out


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("binary")
    ap.add_argument("outdir")
    ap.add_argument("--only", default=None)
    ap.add_argument("--timeout", type=float, default=30)
    ap.add_argument("--ours-timeout", type=float, default=60)
    ap.add_argument("--no-pari", action="store_true")
    ap.add_argument("--no-singular", action="store_true")
    ap.add_argument("--emit-only", action="store_true")
    a = ap.parse_args()
    os.makedirs(a.outdir, exist_ok=True)
    names = a.only.split(",") if a.only else list(FAMILIES)
    if not a.emit_only:
        print("| family | lambdamat CPU s | peak MB | U, V | PARI CPU s | ratio | Singular CPU s | ratio | degrees agree |")
        print("|---|---|---|---|---|---|---|---|---|")
    for name in names:
        m = FAMILIES[name]()
        path = os.path.join(a.outdir, f"{name}.lmx")
        with open(path, "w") as f:
            f.write(lmx(m))
        if a.emit_only:
            print(path)
            continue
        ours = run_ours(a.binary, path, a.ours_timeout)
        pari = {"cpu": None, "skipped": True} if a.no_pari else run_pari(m, a.timeout)
        sing = {"cpu": None, "skipped": True} if a.no_singular else run_singular(m, a.timeout)
        agree = []
        mine = sorted(d for d in ours.get("degs", []))
        for peer, r in (("PARI", pari), ("Singular", sing)):
            if "degs" in r and "degs" in ours:
                agree.append(f"{peer} {'yes' if r['degs'] == mine else 'NO'}")
        uv = "yes" if ours.get("uv") else "no"
        mb = f"{ours['kb'] / 1024:.0f}" if "kb" in ours else "–"
        status = "" if ours.get("rc") in (0, None) else f" (exit {ours.get('rc')})"
        pr = "–" if pari.get("skipped") or "error" in pari else pg.ratio(pari["cpu"], ours["cpu"], a.timeout)
        sr = "–" if sing.get("skipped") or "error" in sing else pg.ratio(sing["cpu"], ours["cpu"], a.timeout)
        print(
            f"| {name} | {pg.fmt(ours['cpu'], a.ours_timeout)}{status} | {mb} | {uv} | "
            f"{pg.peer_cell(pari, a.timeout)} | {pr} | {pg.peer_cell(sing, a.timeout)} | {sr} | "
            f"{', '.join(agree) or '–'} |",
            flush=True,
        )
    print(f"\nload average at the end: {open('/proc/loadavg').read().split()[:3]}")


if __name__ == "__main__":
    main()
