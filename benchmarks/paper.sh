#!/usr/bin/env bash
# Regenerates results/paper/: the seed papers' comparisons on the bundled
# data, each experiment's tables, statistics and figures in a folder of its
# own (see results/paper/README.md for what each one is).
#
#   benchmarks/paper.sh [HYSTBENCH_EXE] [OUT_DIR]
#
# HYSTBENCH_EXE defaults to build/hystbench, OUT_DIR to results/paper (both
# relative to the repository). `make paper` builds and runs it.
set -euo pipefail

repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
exe="${1:-$repo/build/hystbench}"
out="${2:-$repo/results/paper}"

if [[ ! -x "$exe" ]]; then
  echo "paper.sh: $exe is not an executable; run \`make paper\` or build hystbench first" >&2
  exit 2
fi

# experiment file, then the algorithm the significance marks compare against
runs=(
  "mede_table1 MEDE"
  "mede_table1_fair MEDE"
  "amfmmde_convergence AmFMMDE"
  "league jSO"
)
cd "$repo"  # experiment files name their data relative to the repository
for run in "${runs[@]}"; do
  read -r name reference <<<"$run"
  echo "== $name (reference $reference)"
  "$exe" run "benchmarks/experiments/$name.json" --out "$out/$name" --reference "$reference" --force
done
echo "results in $out"
