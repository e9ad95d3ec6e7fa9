#!/usr/bin/env bash
# Seed 002's Table 1 protocol at its own 10 kHz (lags m = n = 4), and one
# change at a time from it: each row of results/svr/README.md's ablation
# table is one `hystbench svr` run on the simulated piezo stack.
#
#   benchmarks/svr_ablation.sh [OUT_DIR] [ROW...]
#
# OUT_DIR defaults to results/svr; the 10 kHz run goes to OUT_DIR/piezo_10khz,
# the rows to OUT_DIR/ablation/<row>/ and the table to OUT_DIR/ablation/
# table.{md,csv,tex}. Give row names to rerun only those (the table is
# rebuilt from every row found). The data go to OUT_DIR/data_*/ (not
# committed: remade bit for bit from the seeds). Needs a built
# build/hystbench (or HYSTBENCH=path). About 50 minutes on 2 cores.
set -euo pipefail
out=${1:-results/svr}
shift || true
hystbench=${HYSTBENCH:-build/hystbench}
spec=benchmarks/experiments
base="$spec/svr_piezo_10khz.json"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p "$out/ablation"

# simulate DIR RATE PERIODS NOISE RESOLUTION: train.csv (PERIODS at 1 Hz,
# then the scan) and test.csv at RATE, as benchmarks/svr_piezo_data.sh
# makes them at 2 kHz.
simulate() {
  local dir=$1 rate=$2 periods=$3 noise=$4 resolution=$5
  [[ -f "$dir/train.csv" && -f "$dir/test.csv" ]] && return  # remade bit for bit: delete to remake
  mkdir -p "$dir"
  jq --argjson r "$rate" --argjson p "$periods" \
    '.sample_rate = $r | (.segments[] | select(.label == "train 1 Hz") | .duration) = $p' \
    "$spec/svr_piezo/train.excitation.json" > "$work/train.excitation.json"
  jq --argjson r "$rate" '.sample_rate = $r' "$spec/svr_piezo/test.excitation.json" > "$work/test.excitation.json"
  for record in train:202 test:203; do
    "$hystbench" simulate --model hysteresis,asymmetry,msd --params "$spec/svr_piezo/actuator.params.json" \
      --excitation "$work/${record%%:*}.excitation.json" --noise "$noise" --resolution "$resolution" \
      --seed "${record##*:}" --input-unit V --output-unit µm --out "$dir/${record%%:*}.csv" > /dev/null
  done
}

# row NAME DATA_DIR JQ_FILTER: the 10 kHz experiment changed by the filter,
# on the records in DATA_DIR.
row() {
  local name=$1 data=$2 filter=$3 dir="$out/ablation/$1"
  if [[ ${#wanted[@]} -gt 0 && ! " ${wanted[*]} " == *" $name "* ]]; then return; fi
  jq --arg d "$data" --arg n "$name" "del(.records) | .name = \$n | .stage1.data = (\$d + \"/train.csv\")
      | .stage2.data = (\$d + \"/train.csv\") | .tests = [{\"data\": (\$d + \"/test.csv\")}] | $filter" \
    "$base" > "$work/$name.json"
  echo "== $name"
  "$hystbench" svr "$work/$name.json" --out "$dir" --force > "$dir.log"
  tail -n +2 "$dir.log" | head -1
  # The table needs svr.json and table.csv; the loops of every row would be
  # 60 MB, so only the seed protocol's run (piezo_10khz) keeps its figures.
  rm -f "$dir"/loop_* "$dir"/svr_model.json
}

wanted=("$@")
d10="$out/data_10khz"
simulate "$d10" 10000 3 0.005 0.1
if [[ ${#wanted[@]} -eq 0 || " ${wanted[*]} " == *" piezo_10khz "* ]]; then
  # The experiment names its records under results/svr; elsewhere, a copy names $out.
  experiment="$base"
  if [[ "$out" != results/svr ]]; then
    sed "s#results/svr/#$out/#g" "$base" > "$work/piezo_10khz.json"
    experiment="$work/piezo_10khz.json"
  fi
  "$hystbench" svr "$experiment" --out "$out/piezo_10khz" --force | tee "$out/piezo_10khz.log"
fi
simulate "$out/data_2khz" 2000 3 0.005 0.1
simulate "$out/data_5khz" 5000 3 0.005 0.1
simulate "$out/data_1period" 10000 1 0.005 0.1
simulate "$out/data_10periods" 10000 10 0.005 0.1
simulate "$out/data_ideal_sensor" 10000 3 0 0

row sampling_2khz "$out/data_2khz" '.'
row sampling_5khz "$out/data_5khz" '.'
row train_1_period "$out/data_1period" '.'
# libsvm did not finish all 100 000 rows of 10 periods in 24 minutes: the
# final stage 1 takes every third row, as many as 3 periods give.
row train_10_periods "$out/data_10periods" '.train_rows = 33334'
row box_wide "$d10" '.search.problem.log10_epsilon = [-4, -1] | .search.problem.log10_C = [-1, 5]'
row input_rate "$d10" '.lags.input_rate = true'
row coupling_one_step "$d10" '.coupling = "one_step"'
row stage1_alone "$d10" 'del(.stage2)'
row arx_seed_orders "$d10" '.arx = {"p_max": 2, "q_max": 2}'
row fitness_blocked_cv "$d10" '.search.problem.fitness = "blocked_cv"'
row final_rows_1000 "$d10" '.train_rows = 1000'
row lags_20 "$d10" '.lags = {"m": 20, "n": 20}'
# The seed's reported stage 2 orders with the changes that helped most alone.
row seed_orders_box_wide "$d10" '.arx = {"p_max": 2, "q_max": 2}
    | .search.problem.log10_epsilon = [-4, -1] | .search.problem.log10_C = [-1, 5]'
row seed_orders_2khz "$out/data_2khz" '.arx = {"p_max": 2, "q_max": 2}'
row ideal_sensor "$out/data_ideal_sensor" '.'

python3 benchmarks/svr_ablation_table.py "$out"
