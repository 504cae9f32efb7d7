#!/usr/bin/env python3
"""The issue-15 goal grid: lambdamat's `smith --json` against PARI/GP's
matsnf(M,3) and Singular's jacobson.lib smith(M,1) (U, D, V in all three),
on seeded random dense n×n matrices of degree d (smith_peers.gen) and on
B·diag(1, …, 1, chain)·C (B of degree d, C of degree 1, both smith_peers.gen;
the chain's factors are non-trivial). CPU seconds everywhere: lambdamat's
user+sys of the whole process (/usr/bin/time, 10 ms resolution), PARI's
getabstime() around matsnf, Singular's `timer` around smith. Peers get a
CPU-time limit (RLIMIT_CPU, --timeout seconds) and are reported as "> T". The invariant factors' degrees are compared where a
peer finished.

Usage: peers_grid.py BIN OUTDIR [--ns 8,12,...] [--ds 1,2,3]
       [--shapes dense,bdc2,bdc3] [--timeout 60] [--singular-timeout 30]
       [--ours-timeout 600] [--no-singular] [--no-pari]
"""
import argparse, json, os, re, resource, subprocess, sys, time

sys.path.insert(0, os.environ.get("SMITH_PEERS_DIR", "/work/shared/bench"))
import smith_peers as sp  # noqa: E402

CHAINS = {
    # non-trivial factors, each a coefficient list (constant first)
    "bdc2": [[-1, 1], [-2, 1, 1]],                  # x−1, (x−1)(x+2)
    "bdc3": [[-1, 1], [-2, 1, 1], [0, -2, 1, 1]],   # …, (x−1)(x+2)x
}


def pmul(a, b):
    r = [0] * (len(a) + len(b) - 1)
    for i, x in enumerate(a):
        if x:
            for j, y in enumerate(b):
                r[i + j] += x * y
    return r


def padd(a, b):
    r = [0] * max(len(a), len(b))
    for i, x in enumerate(a):
        r[i] += x
    for i, x in enumerate(b):
        r[i] += x
    return r


def matmul(a, b):
    n, m, k = len(a), len(b[0]), len(b)
    out = []
    for i in range(n):
        row = []
        for j in range(m):
            acc = [0]
            for t in range(k):
                acc = padd(acc, pmul(a[i][t], b[t][j]))
            while len(acc) > 1 and acc[-1] == 0:
                acc.pop()
            row.append(acc)
        out.append(row)
    return out


def build(shape, n, d, seed):
    if shape == "dense":
        return sp.gen(n, d, seed)
    chain = CHAINS[shape]
    b = sp.gen(n, d, seed)
    c = sp.gen(n, 1, seed + 1000)
    diag = [[1]] * (n - len(chain)) + chain
    bd = [[pmul(b[i][j], diag[j]) for j in range(n)] for i in range(n)]
    return matmul(bd, c)


def lmx(m):
    rows = ";\n  ".join(
        ", ".join(re.sub(r"\*x\^1\b", "*x", sp.poly_str(e)) for e in row) for row in m
    )
    return f"var x\nmatrix A = [\n  {rows}\n]\nsmith A\n"


def run_lambdamat(binary, path, timeout):
    t0 = time.time()
    try:
        p = subprocess.run(
            ["/usr/bin/time", "-f", "%U %S %M", binary, "smith", path, "--json"],
            capture_output=True, text=True, timeout=timeout,
        )
    except subprocess.TimeoutExpired:
        return {"cpu": None, "wall": time.time() - t0}
    u, s, kb = p.stderr.strip().splitlines()[-1].split()
    out = {"cpu": float(u) + float(s), "kb": int(kb), "rc": p.returncode, "wall": time.time() - t0}
    if p.returncode == 0:
        v = json.loads(p.stdout)
        inv = v["invariant_factors"]
        out["degs"] = [0 if f in ("1",) else poly_degree(f) for f in inv]
        out["uv"] = v.get("U") is not None
        out["verified"] = v.get("verified")
    return out


def poly_degree(s):
    degs = [int(e) if e else 1 for e in re.findall(r"x(?:\^(\d+))?", s)]
    return max(degs) if degs else 0


def cpu_limit(seconds):
    """A preexec_fn: the peer is killed after `seconds` of CPU time (the
    machine is shared, so wall-clock limits would be unfair to it)."""
    def set_limit():
        s = int(seconds)
        resource.setrlimit(resource.RLIMIT_CPU, (s, s + 1))
    return set_limit


def run_pari(m, timeout):
    rows = ";".join(",".join(sp.poly_str(e) for e in row) for row in m)
    prog = (f"M=[{rows}];t=getabstime();r=matsnf(M,3);t=getabstime()-t;D=r[3];"
            "print(t);print(vector(#D,i,poldegree(D[i,i])));")
    try:
        p = subprocess.run(["gp", "-q", "-s", "1G"], input=prog, capture_output=True,
                           text=True, timeout=20 * timeout, preexec_fn=cpu_limit(timeout))
    except subprocess.TimeoutExpired:
        return {"cpu": None}
    out = [l for l in p.stdout.splitlines() if l.strip()]
    if len(out) < 2:
        if p.returncode < 0:  # killed at the CPU limit
            return {"cpu": None}
        return {"cpu": None, "error": (p.stderr or p.stdout)[-2000:]}
    return {"cpu": int(out[0]) / 1000.0, "degs": json.loads(out[1])}


def run_singular(m, timeout):
    n = len(m)
    ent = ",".join(sp.poly_str(e) for row in m for e in row)
    prog = (
        'LIB "jacobson.lib";\nring R = 0, x, dp;\n'
        f"matrix M[{n}][{n}] = {ent};\n"
        'system("--ticks-per-sec", 1000);\nint t0 = timer;\n'
        "list L = smith(M, 1);\nint t1 = timer;\n"
        'print(string(t1 - t0));\nmatrix D = L[2];\nint i; string s = "";\n'
        "for (i = 1; i <= " + str(n) + '; i++) { s = s + string(deg(D[i, i])) + " "; }\n'
        "print(s);\nquit;\n"
    )
    try:
        p = subprocess.run(["Singular", "-q", "--no-warn"], input=prog, capture_output=True,
                           text=True, timeout=20 * timeout, preexec_fn=cpu_limit(timeout))
    except subprocess.TimeoutExpired:
        return {"cpu": None}
    lines = [l for l in p.stdout.splitlines() if l.strip()]
    if len(lines) < 2:
        if p.returncode < 0:  # killed at the CPU limit
            return {"cpu": None}
        return {"cpu": None, "error": (p.stderr or p.stdout)[-2000:]}
    degs = sorted(int(x) for x in lines[1].split())
    return {"cpu": int(lines[0]) / 1000.0, "degs": degs}


def fmt(t, timeout):
    return f"> {timeout:.0f}" if t is None else f"{t:.3f}"


def peer_cell(r, timeout):
    """A peer's time, "> T" at its CPU limit, or the reason it failed (e.g.
    PARI's stack overflow at -s 1G), which is not a time."""
    if r.get("skipped"):
        return "–"
    err = r.get("error")
    if err is not None:
        clean = re.sub(r"\x1b\[[0-9;]*m", "", err)
        return "fails: stack overflow" if "stack overflows" in clean else "fails"
    return fmt(r["cpu"], timeout)


def ratio(peer, ours, timeout):
    if ours is None or ours <= 0:
        return "–"
    if peer is None:
        return f"> {timeout / ours:.0f}×"
    return f"{peer / ours:.1f}×"


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("binary")
    ap.add_argument("outdir")
    ap.add_argument("--ns", default="8,12,16,20,32")
    ap.add_argument("--ds", default="1,2,3")
    ap.add_argument("--shapes", default="dense,bdc3")
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--timeout", type=float, default=60)
    ap.add_argument("--singular-timeout", type=float, default=None,
                    help="Singular's CPU limit (default: --timeout)")
    ap.add_argument("--ours-timeout", type=float, default=600)
    ap.add_argument("--no-singular", action="store_true")
    ap.add_argument("--no-pari", action="store_true")
    a = ap.parse_args()
    os.makedirs(a.outdir, exist_ok=True)
    print("| shape | n | d | lambdamat CPU s | peak MB | U, V | PARI matsnf(M,3) CPU s | ratio | Singular smith(M,1) CPU s | ratio | factor degrees agree |")
    print("|---|---|---|---|---|---|---|---|---|---|---|")
    for shape in a.shapes.split(","):
        for d in map(int, a.ds.split(",")):
            for n in map(int, a.ns.split(",")):
                m = build(shape, n, d, a.seed)
                path = os.path.join(a.outdir, f"{shape}_{n}_{d}_{a.seed}.lmx")
                with open(path, "w") as f:
                    f.write(lmx(m))
                ours = run_lambdamat(a.binary, path, a.ours_timeout)
                pari = {"cpu": None, "skipped": True} if a.no_pari else run_pari(m, a.timeout)
                st = a.singular_timeout or a.timeout
                sing = {"cpu": None, "skipped": True} if a.no_singular else run_singular(m, st)
                agree = []
                for name, r in (("PARI", pari), ("Singular", sing)):
                    if "degs" in r and "degs" in ours:
                        agree.append(f"{name} {'yes' if sorted(r['degs']) == sorted(ours['degs']) else 'NO'}")
                nontriv = [x for x in ours.get("degs", []) if x > 0]
                uv = "yes" if ours.get("uv") else "no"
                mb = f"{ours['kb'] / 1024:.0f}" if "kb" in ours else "–"
                ps = peer_cell(pari, a.timeout)
                ss = peer_cell(sing, st)
                pr = "–" if pari.get("skipped") or "error" in pari else ratio(pari["cpu"], ours["cpu"], a.timeout)
                sr = "–" if sing.get("skipped") or "error" in sing else ratio(sing["cpu"], ours["cpu"], st)
                status = "" if ours.get("rc") == 0 else f" (exit {ours.get('rc')})"
                print(f"| {shape} | {n} | {d} | {fmt(ours['cpu'], a.ours_timeout)}{status} | {mb} | {uv} | {ps} | {pr} | {ss} | {sr} | "
                      f"{', '.join(agree) or '–'}; non-trivial degrees {nontriv} |", flush=True)
    print(f"\nload average at the end: {open('/proc/loadavg').read().split()[:3]}")


if __name__ == "__main__":
    main()
