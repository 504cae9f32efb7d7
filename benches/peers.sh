#!/usr/bin/env bash
# Issue 15's goal grid: `lambdamat smith --json` (whole process, CPU time)
# against PARI/GP's matsnf(M,3) and Singular's jacobson.lib smith(M,1), all
# three with transforms, on seeded random dense n×n matrices of degree d and
# on B·diag(1, …, 1, x − 1, (x − 1)(x + 2), (x − 1)(x + 2)x)·C (B of degree
# d, C of degree 1), n = 8, 12, 16, 20, 32 and d = 1, 2, 3. Prints a
# markdown table with the CPU ratios (peer / lambdamat) and whether the
# invariant factors' degrees agree. Matrices come from smith_peers.py
# (SMITH_PEERS_DIR, default /work/shared/bench); the .lmx files go to OUTDIR.
#
# Usage: benches/peers.sh [OUTDIR] [peers_grid.py options, e.g.
#        --ns 8,12 --ds 1 --shapes dense,bdc2,bdc3 --timeout 60]
# Needs gp and Singular for the peers (apt-get install -y pari-gp singular);
# --no-pari / --no-singular skip one. Long: run it in the background.
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:-/tmp/lambdamat-peers}
shift || true
cargo build --release -q
exec python3 benches/peers_grid.py target/release/lambdamat "$out" "$@"
