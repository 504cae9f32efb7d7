"""Times Problem.solve from Python against the same solves in Rust
(`cargo build --release --example api_timing` first), in CPU time of the
process, three rounds alternating Rust and Python (the smallest median of
each is kept); and two threads solving different problems at once against
one after the other (wall time). Not a test: run
`python python/tests/timing.py N` from the repository's root."""
import statistics
import subprocess
import sys
import threading
import time

import lambdamat

N = int(sys.argv[1]) if len(sys.argv) > 1 else 21
CASES = [
    ("mms", "examples/mms.lmx", None, 1e-10),
    ("hertz", "examples/hertz.lmx", {"nu": "0.3", "mu": "0.5"}, 1e-8),
]


def python_medians():
    out = {}
    for label, path, sets, tol in CASES:
        p = lambdamat.Problem.from_file(path)
        times = []
        for _ in range(N):
            t = time.process_time()
            s = p.solve(set=sets, tol=tol)
            times.append((time.process_time() - t) * 1e3)
            assert s.converged
        out[label] = statistics.median(times)
    return out


def rust_medians():
    out = {}
    for line in subprocess.run(
        ["target/release/examples/api_timing", str(N)], capture_output=True, text=True, check=True
    ).stdout.splitlines():
        label, ms = line.split()
        out[label] = float(ms)
    return out


rust, py = {}, {}
for _ in range(3):
    for label, ms in rust_medians().items():
        rust[label] = min(ms, rust.get(label, ms))
    for label, ms in python_medians().items():
        py[label] = min(ms, py.get(label, ms))
for label in py:
    print(f"{label}: Rust {rust[label]:.3f} ms, Python {py[label]:.3f} ms (CPU), ratio {py[label] / rust[label]:.3f}")

# Two different problems (ν = 0.2 and ν = 0.4), one after the other vs two threads.
p = lambdamat.Problem.from_file("examples/hertz.lmx")
sets = [{"nu": "0.2", "mu": "0.5"}, {"nu": "0.4", "mu": "0.5"}]


def one(s):
    p.solve(set=s, tol=1e-10)


serial, parallel = [], []
for _ in range(max(3, N // 4)):
    t = time.perf_counter()
    for s in sets:
        one(s)
    serial.append(time.perf_counter() - t)
    threads = [threading.Thread(target=one, args=(s,)) for s in sets]
    t = time.perf_counter()
    for th in threads:
        th.start()
    for th in threads:
        th.join()
    parallel.append(time.perf_counter() - t)
a, b = statistics.median(serial), statistics.median(parallel)
print(f"two solves: one after the other {a * 1e3:.1f} ms, two threads {b * 1e3:.1f} ms, ratio {b / a:.2f}")
