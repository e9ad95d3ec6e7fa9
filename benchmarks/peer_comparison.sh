#!/usr/bin/env bash
# Regenerates results/performance/peer.md and peer.csv: hystbench against
# pagmo2 on the same data, fitness code and evaluation budget.
# Usage, from anywhere: benchmarks/peer_comparison.sh [hystbench_peer options]
# (e.g. --budget 50000 --trials 10; see build/hystbench_peer --help).
# Builds in $BUILD (default build/). Timings depend on the machine and its
# load: run it on an otherwise idle machine.
set -euo pipefail
cd "$(dirname "$0")/.."
build=${BUILD:-build}

scripts/install-deps.sh
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release >/dev/null
if ! grep -q "^Pagmo_DIR:PATH=/" "$build/CMakeCache.txt"; then
  echo "pagmo (libpagmo-dev) was not found: the peer comparison cannot be built" >&2
  exit 1
fi
cmake --build "$build" -j "$(nproc)" --target hystbench_peer
"$build"/hystbench_peer --out results/performance "$@"
