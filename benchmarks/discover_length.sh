#!/usr/bin/env bash
# How the time of `discover` grows with the record length: the same discover
# as benchmarks/real.sh runs (from msd, the benchmark's warm-up), on the
# leading LENGTHS samples of one estimation record, each timed on its own.
# Writes OUT_DIR/length_<N>/ and OUT_DIR/timings.csv (samples,seconds,
# final_model,steps) and prints the table.
#
#   benchmarks/discover_length.sh DATA.csv OUT_DIR [LENGTHS...]
#
# LENGTHS default to 16384 32768 and the whole record. WARMUP (default 50,
# Silverbox's) and DISCOVER_OPTIONS (extra options) as in real.sh; BUILD_DIR
# (default build) holds hystbench. Run it on an idle machine: the times are
# wall-clock seconds.
set -euo pipefail
repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
usage="usage: benchmarks/discover_length.sh DATA.csv OUT_DIR [LENGTHS...]"
[[ $# -ge 2 && $1 != -h && $1 != --help ]] || { echo "$usage" >&2; exit 2; }
data=$1 out=$2
shift 2
[[ -f $data ]] || { echo "discover_length.sh: no file $data; $usage" >&2; exit 2; }
exe="$(cd "${BUILD_DIR:-$repo/build}" && pwd)/hystbench"
[[ -x $exe ]] || { echo "discover_length.sh: $exe is missing; build hystbench first" >&2; exit 2; }
read -r -a discover_options <<<"${DISCOVER_OPTIONS:-}"
total=$(($(wc -l <"$data") - 1))
lengths=("$@")
[[ ${#lengths[@]} -gt 0 ]] || lengths=(16384 32768 "$total")
for n in "${lengths[@]}"; do
  [[ $n =~ ^[0-9]+$ && $n -ge 1000 && $n -le $total ]] ||
    { echo "discover_length.sh: length $n is not between 1000 and the record's $total samples" >&2; exit 2; }
done
mkdir -p "$out"
echo "samples,seconds,final_model,steps" >"$out/timings.csv"
for n in "${lengths[@]}"; do
  dir="$out/length_$n"
  mkdir -p "$dir"
  head -n "$((n + 1))" "$data" >"$dir/data.csv"
  t0=$SECONDS
  "$exe" discover --data "$dir/data.csv" --start msd --warmup "${WARMUP:-50}" \
    ${discover_options[@]+"${discover_options[@]}"} --out "$dir/discover" --force >"$dir/discover.log"
  seconds=$((SECONDS - t0))
  python3 - "$dir/discover/ladder.json" "$n" "$seconds" >>"$out/timings.csv" <<'EOF'
import json, sys
ladder = json.load(open(sys.argv[1]))
print(f'{sys.argv[2]},{sys.argv[3]},"{ladder["final_model"]}",{len(ladder["steps"]) - 1}')
EOF
  rm -f "$dir/data.csv"
  tail -n 1 "$out/timings.csv" >&2
done
column -s, -t <"$out/timings.csv"
