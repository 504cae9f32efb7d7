#!/usr/bin/env python3
"""CPU time of every point of issue 13's sweep, one process per point.

`lambdamat hertz sweep --nu -0.9:0.5:15 --mu log:0.01:100:13 --tol 1e-10`
prints no time per point, and the issue's speed goal is per point (at most
0.5 s). This runs `BIN hertz --nu NU --mu MU --tol TOL --json` for every
(ν, μ) of that grid (the same values the sweep solves: its inner values are
rounded to 12 significant digits, as `cli/hertz.rs`'s `parse_range` does)
and records the child's user and system CPU seconds (from `os.wait4`), wall
seconds, exit code, levels, c, P* and the error estimate. It prints the
slowest points and the sum, and writes one CSV row per point.

Usage: sweep_times.py BIN OUT.csv [--jobs 1] [--tol 1e-10] [--top 10]
       [--nu -0.9:0.5:15] [--mu log:0.01:100:13]

CPU time, not wall time, is the measure on a shared machine; say the load
beside the figures (it is printed at the start and the end). `--jobs 2`
runs two points at a time (the CPU time per point barely changes; the
assembly uses rayon, so one point alone can use both cores).
"""
import argparse
import csv
import json
import math
import os
import sys
import time
from concurrent.futures import ThreadPoolExecutor


def spaced(a, b, n, interior):
    """n values from a to b, the ends exact, the inner ones interior(s)
    for s = k/(n − 1)."""
    return [a if k == 0 else b if k == n - 1 else interior(k / (n - 1)) for k in range(n)]


def linear(a, b, n):
    """START:END:COUNT as parse_range gives it (12 digits of the scale)."""
    scale = max(abs(a), abs(b))
    digits = min(max(11 - math.floor(math.log10(scale)), 0), 400)
    return spaced(a, b, n, lambda s: float(f"{a * (1 - s) + b * s:.{digits}f}") + 0.0)


def logspace(a, b, n):
    """log:START:END:COUNT as parse_range gives it (12 significant digits)."""
    return spaced(a, b, n, lambda s: float(f"{math.exp(math.log(a) * (1 - s) + math.log(b) * s):.11e}"))


def parse(spec):
    log = spec.startswith("log:")
    a, b, n = spec[4:].split(":") if log else spec.split(":")
    a, b, n = float(a), float(b), int(n)
    if n == 1:
        return [a]
    return logspace(a, b, n) if log else linear(a, b, n)


def run_rusage(binary, nu, mu, tol):
    cmd = [binary, "hertz", "--nu", repr(nu), "--mu", repr(mu),
           "--tol", repr(tol), "--json"]
    t0 = time.monotonic()
    r, w = os.pipe()
    pid = os.fork()
    if pid == 0:
        os.close(r)
        os.dup2(w, 1)
        devnull = os.open(os.devnull, os.O_WRONLY)
        os.dup2(devnull, 2)
        try:
            os.execv(binary, cmd)
        finally:
            os._exit(127)
    os.close(w)
    chunks = []
    while True:
        b = os.read(r, 1 << 16)
        if not b:
            break
        chunks.append(b)
    os.close(r)
    _, status, ru = os.wait4(pid, 0)
    wall = time.monotonic() - t0
    code = os.waitstatus_to_exitcode(status)
    row = {"nu": nu, "mu": mu, "user": ru.ru_utime, "sys": ru.ru_stime,
           "wall": wall, "exit": code, "levels": "", "c": "", "P": "",
           "estimate": ""}
    try:
        j = json.loads(b"".join(chunks))
        row["levels"] = j.get("levels", "")
        row["c"] = j.get("c", "")
        row["P"] = j.get("compliance", "")
        row["estimate"] = j.get("error_estimate", "")
    except (ValueError, AttributeError):
        pass
    return row


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("binary")
    ap.add_argument("out")
    ap.add_argument("--jobs", type=int, default=1)
    ap.add_argument("--tol", type=float, default=1e-10)
    ap.add_argument("--top", type=int, default=10)
    ap.add_argument("--nu", default="-0.9:0.5:15")
    ap.add_argument("--mu", default="log:0.01:100:13")
    a = ap.parse_args()
    points = [(nu, mu) for nu in parse(a.nu) for mu in parse(a.mu)]
    print(f"load at start: {os.getloadavg()}", file=sys.stderr)
    with ThreadPoolExecutor(max_workers=a.jobs) as ex:
        rows = list(ex.map(lambda p: run_rusage(a.binary, p[0], p[1], a.tol),
                           points))
    print(f"load at end: {os.getloadavg()}", file=sys.stderr)
    fields = ["nu", "mu", "user", "sys", "wall", "exit", "levels", "c", "P",
              "estimate"]
    with open(a.out, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=fields)
        w.writeheader()
        w.writerows(rows)
    total = sum(r["user"] for r in rows)
    print(f"{len(rows)} points, user CPU sum {total:.2f} s, "
          f"max {max(r['user'] for r in rows):.2f} s, "
          f"{sum(r['user'] > 0.5 for r in rows)} above 0.5 s, "
          f"{sum(r['user'] > 0.4 for r in rows)} above 0.4 s, "
          f"{sum(r['exit'] != 0 for r in rows)} exit ≠ 0")
    for r in sorted(rows, key=lambda r: -r["user"])[: a.top]:
        print(f"  ({r['nu']}, {r['mu']}): {r['user']:.2f} s user, "
              f"{r['wall']:.2f} s wall, {r['levels']} levels, exit {r['exit']}")


if __name__ == "__main__":
    main()
