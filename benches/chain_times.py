#!/usr/bin/env python3
"""The sparse chain of issue 29: `u_i + k u_(i+1) = 1` (i < n) and
`u_n + k u_1 = 1`, one smooth operator k, solved for u1. Writes
chain_N.lmx and prints the CPU seconds (user + sys, /usr/bin/time) of
`lambdamat reduce` and `lambdamat codegen` on it.

Usage: chain_times.py BIN OUTDIR [--ns 5,9,10,20,60,100] [--timeout 120]
"""
import argparse
import os
import subprocess


def chain(n):
    lines = ["operator k = int(0..1) exp(-(x-t)^2) dt"]
    lines.append("unknown " + ", ".join(f"u{i}" for i in range(1, n + 1)))
    for i in range(1, n + 1):
        nxt = i + 1 if i < n else 1
        lines.append(f"equation u{i} + k u{nxt} = 1")
    lines.append("solve for u1")
    return "\n".join(lines) + "\n"


def cpu(cmd, timeout):
    try:
        p = subprocess.run(["/usr/bin/time", "-f", "%U %S %M"] + cmd,
                           capture_output=True, text=True, timeout=timeout)
    except subprocess.TimeoutExpired:
        return f"> {timeout:.0f}", "–", None
    u, s, kb = p.stderr.strip().splitlines()[-1].split()
    return f"{float(u) + float(s):.2f}", f"{int(kb) / 1024:.0f}", p.returncode


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("binary")
    ap.add_argument("outdir")
    ap.add_argument("--ns", default="5,9,10,20,60,100")
    ap.add_argument("--timeout", type=float, default=120)
    a = ap.parse_args()
    os.makedirs(a.outdir, exist_ok=True)
    print("| n | reduce CPU s | MB | exit | codegen CPU s | MB | exit |")
    print("|---|---|---|---|---|---|---|")
    for n in map(int, a.ns.split(",")):
        path = os.path.join(a.outdir, f"chain_{n}.lmx")
        with open(path, "w") as f:
            f.write(chain(n))
        r = cpu([a.binary, "reduce", path], a.timeout)
        out = os.path.join(a.outdir, f"chain_{n}_solver.rs")
        c = cpu([a.binary, "codegen", path, "-o", out], a.timeout)
        print(f"| {n} | {r[0]} | {r[1]} | {r[2]} | {c[0]} | {c[1]} | {c[2]} |", flush=True)


if __name__ == "__main__":
    main()
