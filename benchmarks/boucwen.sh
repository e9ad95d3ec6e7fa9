#!/usr/bin/env bash
# The Bouc-Wen benchmark (Noel & Schoukens 2016) through the discovery
# workflow: from the seed chain, discover on the estimation record only, then
# report simulation RMSE on the two official test sets (never used for
# fitting or selection).
#
#   benchmarks/boucwen.sh DATA_DIR [OUT_DIR]
#
# DATA_DIR holds train_multisine_dynonet.csv, test_multisine.csv and
# test_sinesweep.csv (columns t_s, u_N, y_m). OUT_DIR defaults to
# results/boucwen. Needs a built build/hystbench.
set -euo pipefail
data=${1:?usage: benchmarks/boucwen.sh DATA_DIR [OUT_DIR]}
out=${2:-results/boucwen}
hystbench=${HYSTBENCH:-build/hystbench}
columns=t=t_s,u=u_N,y=y_m
units=(--input-unit N --output-unit m)

for f in train_multisine_dynonet.csv test_multisine.csv test_sinesweep.csv; do
  [[ -f "$data/$f" ]] || { echo "boucwen.sh: $data/$f is missing" >&2; exit 2; }
done
mkdir -p "$out"
start=$(date +%s)
"$hystbench" discover --data "$data/train_multisine_dynonet.csv" --columns "$columns" "${units[@]}" \
  --start hysteresis,asymmetry,msd,arx --out "$out/discover" --force | tee "$out/discover.log"
discover_seconds=$(( $(date +%s) - start ))
# One steady-state period: simulate eight periods from rest, score the last.
"$hystbench" compare --data "$data/test_multisine.csv" --columns "$columns" "${units[@]}" \
  --fit "$out/discover/fit.json" --periodic 8 --out "$out/test_multisine" --force
"$hystbench" compare --data "$data/test_sinesweep.csv" --columns "$columns" "${units[@]}" \
  --fit "$out/discover/fit.json" --out "$out/test_sinesweep" --force
echo "discover took ${discover_seconds} s" | tee -a "$out/discover.log"
