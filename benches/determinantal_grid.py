#!/usr/bin/env python3
"""Determinantal-mode timings (invariant factors over Q[x, y, z] from the
gcds of the k×k minors) on seeded random matrices in several symbols,
against Singular computing the same gcds (`minor(M, k)` and `gcd`).

Usage:
  determinantal_grid.py BIN [--ns 3,4,5,6,7] [--nvs 3] [--degs 2,6,10]
                            [--seeds 1-2] [--terms T] [--extra-cols K]
                            [--timeout S] [--no-singular]

The matrices are benches/multi_peers.py's (same generator, same seeds);
--extra-cols K makes them n×(n+K). lambdamat: user CPU of the whole
`BIN smith FILE --json` process (RLIMIT_CPU = timeout); Singular: its own
timer around the minors and gcds, the computation repeated until 200 ms
have passed (time per run), under the same CPU limit. One line per case
(the degrees of the determinantal divisors from both, times, ratio), then
a summary per n."""
import json
import os
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import multi_peers  # noqa: E402
from principal_grid import Grid, limit, print_summary  # noqa: E402


def run_ours(binary, path, timeout):
    import resource
    before = resource.getrusage(resource.RUSAGE_CHILDREN).ru_utime
    p = subprocess.run(
        [binary, "smith", path, "--json"],
        capture_output=True, text=True, preexec_fn=limit(timeout),
    )
    t = resource.getrusage(resource.RUSAGE_CHILDREN).ru_utime - before
    if p.returncode != 0:
        return t, None
    v = json.loads(p.stdout)
    rep = v[0] if isinstance(v, list) else v
    return t, rep


def total_degree(poly):
    """The total degree of a polynomial as lambdamat prints it."""
    best = 0
    for term in poly.replace(" - ", " + ").split(" + "):
        d = 0
        for f in term.split("*"):
            f = f.strip()
            if f and f[0].isalpha():
                d += int(f.split("^")[1]) if "^" in f else 1
        best = max(best, d)
    return best


def run_singular(m, names, timeout):
    rows, cols = len(m), len(m[0])
    ents = ",".join(multi_peers.poly_str(e, names) for row in m for e in row)
    prog = f"""ring r=0,({','.join(names)}),dp;
system("--ticks-per-sec",1000);
matrix M[{rows}][{cols}]={ents};
list d; int k; int i; poly g; ideal I; int runs=0;
int t0=timer;
while (runs==0 || timer-t0<200) {{
  d=list();
  for (k=1;k<={min(rows, cols)};k++) {{
    I=minor(M,k); g=0;
    for (i=1;i<=ncols(I);i++) {{ g=gcd(g,I[i]); }}
    if (g==0) {{ break; }}
    d=insert(d,g,size(d));
  }}
  runs++;
}}
print(timer-t0);
print(runs);
for (k=1;k<=size(d);k++) {{ print(deg(d[k])); }}
quit;
"""
    out = subprocess.run(
        ["Singular", "-q"], input=prog, capture_output=True, text=True,
        preexec_fn=limit(timeout),
    ).stdout.split()
    return int(out[0]) / 1000.0 / int(out[1]), [int(x) for x in out[2:]]


def main():
    a = sys.argv[1:]
    binary = a[0]
    grid = Grid(a, ns="3,4,5,6,7", nvs="3", degs="2,6,10", seeds="1-2")
    timeout, extra = grid.timeout, grid.extra
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        for n, nv, names, deg, seed, m, path in grid.cases(tmp):
            t, rep = run_ours(binary, path, timeout)
            ours = None
            if rep is not None:
                acc, ours = 0, []
                for f in rep["invariant_factors"]:
                    acc += total_degree(f)
                    ours.append(acc)
            st, sdeg = None, "-"
            if "--no-singular" not in a:
                try:
                    st, sdeg = run_singular(m, names, timeout)
                except Exception as e:  # noqa: BLE001
                    sdeg = type(e).__name__
            ratio = f"{st / t:.2f}" if st is not None and t > 0 else "-"
            agree = "-" if st is None or ours is None else sdeg == ours
            print(
                f"n={n}x{n + extra} nv={nv} deg={deg} seed={seed} "
                f"ours={t:.3f}s d_k degrees={ours if ours is not None else 'FAILED/limit'} "
                f"singular={'-' if st is None else f'{st:.3f}s'} singular_degrees={sdeg} "
                f"agree={agree} singular/ours={ratio}",
                flush=True,
            )
            rows.append((n, t, st))
    print_summary(rows, grid.ns, "Singular")


if __name__ == "__main__":
    main()
