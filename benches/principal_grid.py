#!/usr/bin/env python3
"""Principal-mode timings on seeded random matrices in several symbols,
against PARI/GP's matsnf(M, 3) over Q(others)[principal].

Usage:
  principal_grid.py BIN [--ns 2,3,4] [--nvs 2,3] [--degs 1,2] [--seeds 1-8]
                        [--terms T] [--extra-cols K] [--timeout S] [--no-pari]

The matrices are benches/multi_peers.py's (same generator, same seeds); the
principal symbol is the last one; --extra-cols K makes them n×(n+K) (bordered
to a square for PARI). lambdamat: user CPU of the whole
`BIN smith FILE --principal s --json` process (RLIMIT_CPU = timeout);
PARI: matsnf's own time (getabstime, the call repeated until 200 ms
have passed, time per call), under the same CPU limit. One line
per case (route, whether U and V were given, the degrees in the principal
symbol of the invariant factors, times, ratio), then a summary."""
import json
import os
import resource
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import multi_peers  # noqa: E402


def arg(a, name, default):
    return a[a.index(name) + 1] if name in a else default


def ints(spec):
    out = []
    for part in spec.split(","):
        if "-" in part:
            lo, hi = part.split("-")
            out.extend(range(int(lo), int(hi) + 1))
        else:
            out.append(int(part))
    return out


def limit(seconds):
    def set_limits():
        resource.setrlimit(resource.RLIMIT_CPU, (seconds, seconds + 1))

    return set_limits


def run_ours(binary, path, principal, timeout):
    before = resource.getrusage(resource.RUSAGE_CHILDREN).ru_utime
    p = subprocess.run(
        [binary, "smith", path, "--principal", principal, "--json"],
        capture_output=True, text=True, preexec_fn=limit(timeout),
    )
    t = resource.getrusage(resource.RUSAGE_CHILDREN).ru_utime - before
    if p.returncode != 0:
        return t, None
    v = json.loads(p.stdout)
    rep = v[0] if isinstance(v, list) else v
    if "results" in rep:
        rep = rep["results"][0]["result"]
    return t, rep


def run_pari(m, nv, principal, timeout):
    """matsnf(M, 3) over Q(others)[x], repeated until 200 ms have passed
    (getabstime counts milliseconds): the time per call and the degrees of
    the nonzero invariant factors. matsnf takes square matrices only: a
    non-square input is bordered with zero rows or columns (the same
    nonzero invariant factors)."""
    size = max(len(m), len(m[0]))
    m = [list(row) + [{}] * (size - len(row)) for row in m]
    m += [[{}] * size for _ in range(size - len(m))]
    names = [f"a{i}" for i in range(nv)]
    names[principal] = "x"
    rows = ";".join(",".join(multi_peers.poly_str(e, names) for e in row) for row in m)
    prog = (
        f"M=[{rows}];t0=getabstime();r=matsnf(M,3);k=1;"
        "while(getabstime()-t0<200,r=matsnf(M,3);k++);"
        "t=(getabstime()-t0)/k;D=r[3];print(t*1.0);print(k);"
        "print(vector(#D,i,poldegree(D[i,i],x)));"
    )
    out = subprocess.run(
        ["gp", "-q", "-s", "1G"], input=prog, capture_output=True, text=True,
        preexec_fn=limit(timeout),
    ).stdout.splitlines()
    if len(out) < 3:
        raise TimeoutError  # killed by the CPU limit (or a PARI error)
    degs = [d for d in out[2].strip("[]").replace(" ", "").split(",") if d != "-oo"]
    return float(out[0]) / 1000.0, "[" + ",".join(degs) + "]"


def main():
    a = sys.argv[1:]
    binary = a[0]
    grid = Grid(a, ns="2,3,4", nvs="2,3", degs="1,2", seeds="1-8")
    timeout, extra = grid.timeout, grid.extra
    multi_peers.TIMEOUT = timeout + 5
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        for n, nv, names, deg, seed, m, path in grid.cases(tmp):
            t, rep = run_ours(binary, path, names[-1], timeout)
            if rep is None:
                route, uv, degs_ours = "FAILED/limit", "-", "-"
            else:
                alg = rep.get("algorithm", "")
                route = (
                    "ff" if alg.startswith("fraction-free")
                    else "det-adj" if alg.startswith("det and adj")
                    else "field" if alg.startswith("elimination")
                    else "max-minors" if "minors over Q[all] by expansion" in alg
                    else "divisors" if alg.startswith("determinantal divisors")
                    else alg[:20]
                )
                uv = "yes" if rep.get("U") else "no"
                degs_ours = "[" + ",".join(
                    str(len(c) - 1)
                    for c in rep.get("invariant_factor_coefficients") or []
                ) + "]"
            pt, pdeg = None, "-"
            if "--no-pari" not in a:
                try:
                    pt, pdeg = run_pari(m, nv, nv - 1, timeout)
                except Exception as e:  # noqa: BLE001
                    pdeg = type(e).__name__
            ratio = f"{pt / t:.2f}" if pt is not None and t > 0 else "-"
            try:
                agree = sorted(json.loads(pdeg)) == sorted(json.loads(degs_ours))
            except (ValueError, TypeError):
                agree = "-"
            line = (
                f"n={n}x{n + extra} nv={nv} deg={deg} seed={seed} route={route} uv={uv} "
                f"ours={t:.3f}s degs={degs_ours} pari={'-' if pt is None else f'{pt:.3f}s'} "
                f"pari_degs={pdeg} agree={agree} pari/ours={ratio}"
            )
            print(line, flush=True)
            rows.append((n, t, pt, route))
    print_summary(rows, grid.ns, "PARI")


class Grid:
    """The seeded grid both grid scripts run: options --ns, --nvs, --degs,
    --seeds (defaults given), --terms, --extra-cols and --timeout, and the
    cases over them."""

    def __init__(self, a, ns, nvs, degs, seeds):
        self.ns = ints(arg(a, "--ns", ns))
        self.nvs = ints(arg(a, "--nvs", nvs))
        self.degs = ints(arg(a, "--degs", degs))
        self.seeds = ints(arg(a, "--seeds", seeds))
        self.terms = int(arg(a, "--terms", "3"))
        self.extra = int(arg(a, "--extra-cols", "0"))
        self.timeout = int(arg(a, "--timeout", "60"))

    def cases(self, tmp):
        """Per case (n, nv, names, deg, seed, m, path): multi_peers.gen's
        n×(n + extra) matrix and its lambdamat file, written in `tmp`."""
        for n in self.ns:
            for nv in self.nvs:
                names = multi_peers.NAMES[:nv]
                for deg in self.degs:
                    for seed in self.seeds:
                        m = multi_peers.gen(n, nv, deg, seed, self.terms, n + self.extra)
                        path = os.path.join(tmp, f"m_{n}_{nv}_{deg}_{seed}.lmx")
                        with open(path, "w") as f:
                            f.write(multi_peers.lmx(m, names))
                        yield n, nv, names, deg, seed, m, path


def print_summary(rows, ns, peer):
    """Per n: cases, max and median of ours, how often `peer` was faster,
    its max; `rows` holds (n, ours seconds, peer seconds or None, ...)."""
    print(f"summary (per n: cases, max ours s, median ours s, {peer} faster in how many, max {peer} s)")
    for n in ns:
        r = [x for x in rows if x[0] == n]
        ts = sorted(x[1] for x in r)
        slower = sum(1 for x in r if x[2] is not None and x[2] < x[1])
        pmax = max((x[2] for x in r if x[2] is not None), default=None)
        print(
            f"n={n}: {len(r)} cases, max {ts[-1]:.3f} s, median {ts[len(ts) // 2]:.3f} s, "
            f"{peer} faster in {slower}, {peer} max {pmax}"
        )


if __name__ == "__main__":
    main()
