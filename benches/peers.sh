#!/usr/bin/env bash
# Times the whole `lambdamat smith` process against PARI/GP's matsnf(M,3)
# (transforms included) on the seeded random matrices of
# ../shared/bench/smith_peers.py, interleaving runs so both see the same
# machine load. SymPy is much slower; run smith_peers.py itself for it.
# Usage: benches/peers.sh [RUNS]   (needs gp: apt-get install -y pari-gp)
set -euo pipefail
cd "$(dirname "$0")/.."
runs=${1:-5}
cargo build --release -q
peers=../shared/bench
for case in "10 2 1" "8 4 1" "12 3 1"; do
  set -- $case
  f=benches/data/peers_$1_$2_$3.lmx
  for _ in $(seq "$runs"); do
    python3 -c "import sys; sys.path.insert(0,'$peers'); import smith_peers as s; print('pari', s.run_pari(s.gen($1,$2,$3))[0])"
    /usr/bin/time -f "lambdamat %e %M" ./target/release/lambdamat smith "$f" 2>&1 >/dev/null | tail -1
  done | python3 -c "
import sys, statistics
t = {}; rss = 0
for line in sys.stdin:
    k, v, *rest = line.split()
    t.setdefault(k, []).append(float(v))
    if rest: rss = max(rss, int(rest[0]))
p, l = statistics.median(t['pari']), statistics.median(t['lambdamat'])
print(f'$1x$1 deg $2: pari {p:.3f} s, lambdamat {l:.3f} s, ratio {p/l:.1f}x, lambdamat peak RSS {rss} KB')"
done
