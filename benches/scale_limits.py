#!/usr/bin/env python3
"""The largest n each Smith mode handles within a CPU budget (issue 15).

Usage:
  scale_limits.py BIN [--modes M1,M2] [--degs 1,2,3] [--budget 10]
                      [--limit 20] [--seed 1] [--start N] [--out DIR]
                      [--need-uv]

Modes (the matrices are the peers' generators, seeded):
  dense, bdc2, bdc3   one symbol, `BIN smith F --json` (peers_grid.build:
                      random dense, B·diag·C with two / three factors);
                      U, V given or not as the binary's policy decides
  principal2, principal3
                      `--principal` on the last of 2 / 3 symbols
                      (multi_peers.gen, 3 terms per entry, exponents ≤ d)
  divisors2, divisors3
                      determinantal divisors over Q[all] (no principal)
For each mode and degree: n doubles from --start while the whole process
stays under the budget (user + sys CPU, RLIMIT_CPU = --limit), then
bisects between the last n under and the first over. Prints one line per
run (n, CPU, peak RSS, exit code, whether U and V were printed) and a
summary line per (mode, degree): the largest n under the budget (with
--need-uv: the largest n whose run also printed U and V; the binary's
policy omits them above a size, so this bisects that switch too)."""
import json
import os
import resource
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.path.insert(0, "/work/shared/bench")
import multi_peers  # noqa: E402
import peers_grid  # noqa: E402


def arg(a, name, default):
    return a[a.index(name) + 1] if name in a else default


def source(mode, n, d, seed):
    if mode in ("dense", "bdc2", "bdc3"):
        return peers_grid.lmx(peers_grid.build(mode, n, d, seed)), []
    nv = int(mode[-1])
    names = multi_peers.NAMES[:nv]
    text = multi_peers.lmx(multi_peers.gen(n, nv, d, seed, 3), names)
    extra = ["--principal", names[-1]] if mode.startswith("principal") else []
    return text, extra


def run(binary, path, extra, limit):
    def lim():
        resource.setrlimit(resource.RLIMIT_CPU, (limit, limit + 1))

    p = subprocess.run(
        ["/usr/bin/time", "-f", "%U %S %M", binary, "smith", path, "--json", *extra],
        capture_output=True, text=True, preexec_fn=lim,
    )
    u, s, kb = p.stderr.strip().splitlines()[-1].split()[-3:]
    out = {"cpu": float(u) + float(s), "mb": int(kb) / 1024, "rc": p.returncode, "uv": None}
    if p.returncode == 0:
        v = json.loads(p.stdout)
        v = v[0] if isinstance(v, list) else v
        out["uv"] = v.get("U") is not None
    return out


def main():
    a = sys.argv[1:]
    binary = a[0]
    modes = arg(a, "--modes", "dense,bdc2,bdc3,principal2,principal3,divisors2,divisors3").split(",")
    degs = [int(x) for x in arg(a, "--degs", "1,2,3").split(",")]
    budget = float(arg(a, "--budget", "10"))
    limit = int(arg(a, "--limit", "20"))
    seed = int(arg(a, "--seed", "1"))
    start = int(arg(a, "--start", "4"))
    out = arg(a, "--out", "/tmp/scale_limits")
    need_uv = "--need-uv" in a
    os.makedirs(out, exist_ok=True)
    for mode in modes:
        for d in degs:
            seen = {}

            def ok(n):
                if n not in seen:
                    text, extra = source(mode, n, d, seed)
                    path = os.path.join(out, f"{mode}_{n}_{d}_{seed}.lmx")
                    with open(path, "w") as f:
                        f.write(text)
                    r = run(binary, path, extra, limit)
                    seen[n] = r
                    print(f"{mode} d={d} n={n}: {r['cpu']:.2f} s CPU, {r['mb']:.0f} MB, "
                          f"rc={r['rc']}, U/V={r['uv']}  ({binary} smith {path} --json {' '.join(extra)})",
                          flush=True)
                r = seen[n]
                return r["rc"] == 0 and r["cpu"] < budget and (r["uv"] or not need_uv)

            lo, hi = None, None
            n = start
            while n <= 512:
                if ok(n):
                    lo, n = n, n * 2
                else:
                    hi = n
                    break
            if lo is None:
                n = start - 1
                while n >= 1 and not ok(n):
                    n -= 1
                lo = n if n >= 1 else 0
            if hi is not None:
                while hi - lo > 1:
                    mid = (lo + hi) // 2
                    if ok(mid):
                        lo = mid
                    else:
                        hi = mid
            best = seen.get(lo)
            detail = f"{best['cpu']:.2f} s, {best['mb']:.0f} MB, U/V={best['uv']}" if best else "-"
            print(f"SUMMARY {mode} d={d}: largest n = {lo} ({detail}); first over: {hi}", flush=True)


if __name__ == "__main__":
    main()
