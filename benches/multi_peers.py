#!/usr/bin/env python3
"""Seeded random polynomial matrices in several symbols, and peer timings.

Usage:
  multi_peers.py N NVARS DEG [SEED] [--terms T] [--principal K]
                 [--emit-lmx FILE] [--pari] [--singular]

Each entry is a random polynomial in the symbols s1..sNVARS (named x, y, z
for up to three symbols) with up to T terms (default 3), every exponent at
most DEG, integer coefficients in [-9, 9]; about one entry in six is zero.
  --emit-lmx FILE  writes the matrix in lambdamat syntax;
  --principal K    (1-based symbol index) PARI computes matsnf(M, 3) over
                   Q(others)[s_K] (the symbol renamed to PARI's highest-
                   priority variable);
  --pari           time PARI/GP (principal mode; needs --principal);
  --pari-flag F    matsnf's flag: 3 (U, V, D; default) or 2 (D only);
  --timeout S      give each peer S seconds (default 120);
  --singular       time Singular's determinantal divisors (gcd of the k×k
                   minors for every k).
Prints one line per peer: peer seconds (CPU, measured inside the peer) and
the degrees / sizes of the invariant factors."""
import random
import subprocess
import sys

NAMES = ["x", "y", "z", "w"]
TIMEOUT = 120


def gen(n, nv, deg, seed, terms, cols=None):
    """An n×n matrix, or n×cols (the square ones are unchanged)."""
    rnd = random.Random(seed)
    m = []
    for _ in range(n):
        row = []
        for _ in range(cols or n):
            if rnd.random() < 1 / 6:
                row.append({})
                continue
            p = {}
            for _ in range(rnd.randint(1, terms)):
                e = tuple(rnd.randint(0, deg) for _ in range(nv))
                c = rnd.choice([c for c in range(-9, 10) if c != 0])
                p[e] = p.get(e, 0) + c
            row.append({e: c for e, c in p.items() if c != 0})
        m.append(row)
    return m


def poly_str(p, names):
    if not p:
        return "0"
    out = []
    for e, c in sorted(p.items(), reverse=True):
        mono = "*".join(
            f"{names[i]}^{k}" if k > 1 else names[i] for i, k in enumerate(e) if k
        )
        out.append(f"({c})*{mono}" if mono else f"({c})")
    return " + ".join(out)


def lmx(m, names):
    rows = ";\n  ".join(", ".join(poly_str(e, names) for e in row) for row in m)
    return f"var {', '.join(names)}\nmatrix A = [\n  {rows}\n]\nsmith A\n"


def run_pari(m, nv, principal, flag):
    # PARI's x has the highest priority: the principal symbol becomes x.
    names = [f"a{i}" for i in range(nv)]
    names[principal] = "x"
    rows = ";".join(",".join(poly_str(e, names) for e in row) for row in m)
    prog = (
        f"M=[{rows}];t=getabstime();r=matsnf(M,{flag});t=getabstime()-t;"
        f"D=if({flag}==3,r[3],matdiagonal(r));print(t);print(vector(#D,i,poldegree(D[i,i],x)));"
    )
    out = subprocess.run(
        ["gp", "-q", "-s", "1G"], input=prog, capture_output=True, text=True,
        timeout=TIMEOUT,
    ).stdout.splitlines()
    return int(out[0]) / 1000.0, out[1]


def run_singular(m, names):
    n = len(m)
    ents = ",".join(poly_str(e, names) for row in m for e in row)
    prog = f"""ring r=0,({','.join(names)}),dp;
system("--ticks-per-sec",1000);
matrix M[{n}][{n}]={ents};
int t=timer;
list d; int k; int i; poly g; ideal I;
for (k=1;k<={n};k++) {{
  I=minor(M,k); g=0;
  for (i=1;i<=ncols(I);i++) {{ g=gcd(g,I[i]); }}
  if (g==0) {{ break; }}
  d=insert(d,g,size(d));
}}
int t2=timer;
print(t2-t);
for (k=1;k<=size(d);k++) {{ print(deg(d[k])); }}
quit;
"""
    out = subprocess.run(
        ["Singular", "-q"], input=prog, capture_output=True, text=True, timeout=TIMEOUT
    ).stdout.split()
    return int(out[0]) / 1000.0, "[" + ",".join(out[1:]) + "]"


def main():
    a = sys.argv[1:]
    pos = [x for i, x in enumerate(a) if not x.startswith("--") and (i == 0 or a[i - 1] not in ("--terms", "--principal", "--emit-lmx", "--pari-flag", "--timeout"))]
    n, nv, deg = int(pos[0]), int(pos[1]), int(pos[2])
    seed = int(pos[3]) if len(pos) > 3 else 1
    terms = int(a[a.index("--terms") + 1]) if "--terms" in a else 3
    global TIMEOUT
    TIMEOUT = int(a[a.index("--timeout") + 1]) if "--timeout" in a else 120
    names = NAMES[:nv] if nv <= len(NAMES) else [f"s{i + 1}" for i in range(nv)]
    m = gen(n, nv, deg, seed, terms)
    if "--emit-lmx" in a:
        with open(a[a.index("--emit-lmx") + 1], "w") as f:
            f.write(lmx(m, names))
    if "--pari" in a:
        k = int(a[a.index("--principal") + 1]) - 1
        try:
            flag = int(a[a.index("--pari-flag") + 1]) if "--pari-flag" in a else 3
            t, degs = run_pari(m, nv, k, flag)
            print(f"pari flag={flag} n={n} nv={nv} deg={deg} seed={seed} seconds={t:.3f} degs={degs}", flush=True)
        except Exception as e:  # noqa: BLE001
            print(f"pari n={n} nv={nv} deg={deg} seed={seed} error={type(e).__name__}", flush=True)
    if "--singular" in a:
        try:
            t, degs = run_singular(m, names)
            print(f"singular n={n} nv={nv} deg={deg} seed={seed} seconds={t:.3f} degs={degs}", flush=True)
        except Exception as e:  # noqa: BLE001
            print(f"singular n={n} nv={nv} deg={deg} seed={seed} error={type(e).__name__}", flush=True)


if __name__ == "__main__":
    main()
