#!/usr/bin/env bash
# Discovery on public measured benchmarks, scored the way their literature
# scores them (docs/discovery.md, "Measured benchmarks"). For each benchmark:
#   discover/     discover from msd on the estimation record, with the
#                 benchmark's warm-up (the first samples initialise the model
#                 and are never scored; on the tanks they also set the level
#                 the record starts from, --initial-state held). Where that
#                 ladder says a start-up transient dominates its error and
#                 advises a longer warm-up, it is kept as discover_first/ and
#                 discover runs again with the advised warm-up, as a user
#                 would (not on a held start); every fit below uses it, the
#                 test records are still scored after the benchmark's own
#                 warm-up
#   proposals/    where the ladder ends beyond the catalog: propose given the
#                 discover folder (its sound rung: the last before a doubtful
#                 addition); proposals/effect/ holds the first term as a plugin
#   with_effect/  discover from that rung's model offered only that effect
#   hold_spline/, hold_bandlimited/
#                 the model to score fitted afresh twice, alike but for how
#                 ODE effects read the input between samples (docs/models.md,
#                 "Input hold"): where the band-limited one holds out lower
#                 on the estimation record than both its spline twin and
#                 the fit found so far, it is the fit scored
#   grey_box/     where the benchmark has one, its physical law written by hand
#                 as a user's effect (examples/), fitted on the estimation
#                 record; estimation_*/ score it and discovery's fit there,
#                 and the lower estimation RMSE is the fit scored on test
#   test_*/       compare of the scored fit on each official test record
# then <name>/README.md, README.md and summary.csv (one row per benchmark and
# test record; RMSE after the warm-up, in the benchmark's unit).
#
#   benchmarks/real.sh DATA_ROOT [OUT_DIR]
#
# DATA_ROOT holds silverbox/ and cascaded_tanks/, each with estimation.csv and
# its test records (columns t, u, y; the split of the nonlinear_benchmarks
# loader; see each folder's README). OUT_DIR defaults to results/real.
# BENCHMARKS="cascaded_tanks" runs one; MAX_STEPS (default 8) bounds the
# effects discover adds; DISCOVER_OPTIONS adds options to every discover
# (the test runs the excerpts with a smaller search budget); GREY_BOX_OPTIONS
# (default --restarts 8) does the same for the grey box's fit, FIT_OPTIONS
# (default none) for the two fits of the input holds; BUILD_DIR
# (default build) holds hystbench. Needs python3 to read the JSON results and
# cmake to build a proposed effect.
set -euo pipefail
repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
usage="usage: benchmarks/real.sh DATA_ROOT [OUT_DIR]"
[[ $# -ge 1 && $1 != -h && $1 != --help ]] || { echo "$usage" >&2; exit 2; }
# Paths stay as given: the results record them, so relative ones keep the
# machine's folders out of committed files.
data_root=$1
[[ -d $data_root ]] || { echo "real.sh: no folder $data_root; $usage" >&2; exit 2; }
out="${2:-$repo/results/real}"
build="$(cd "${BUILD_DIR:-$repo/build}" && pwd)"
exe="$build/hystbench"
max_steps="${MAX_STEPS:-8}"
read -r -a discover_options <<<"${DISCOVER_OPTIONS:-}"
read -r -a grey_box_options <<<"${GREY_BOX_OPTIONS:---restarts 8}"
read -r -a fit_options <<<"${FIT_OPTIONS:-}"
[[ -x "$exe" ]] || { echo "real.sh: $exe is missing; build hystbench first" >&2; exit 2; }
command -v python3 >/dev/null || { echo "real.sh: python3 is needed" >&2; exit 2; }

# name  warm-up  initial state  test records
declare -A warmup=([silverbox]=50 [cascaded_tanks]=5)
# The tanks' records start half full, not at rest: their first outputs set
# the level (docs/discovery.md, "Initial state"). Silverbox starts at rest.
declare -A initial=([silverbox]=rest [cascaded_tanks]=held)
declare -A tests=([silverbox]="test_multisine test_arrow_full test_arrow_no_extrapolation" [cascaded_tanks]="test")
# A benchmark's physical law as a user's effect: example folder, library,
# model, and fit options of its own (the tanks' pump voltage is held between
# samples). Silverbox's law, a cubic spring, is what propose generates.
declare -A grey_box=([cascaded_tanks]="examples/cascaded_tanks_effect cascaded_tanks cascaded_tanks,offset --input-hold zoh")
benchmarks=${BENCHMARKS:-silverbox cascaded_tanks}
for b in $benchmarks; do
  [[ -n ${warmup[$b]:-} ]] || { echo "real.sh: unknown benchmark $b (silverbox, cascaded_tanks)" >&2; exit 2; }
  for f in estimation ${tests[$b]}; do
    [[ -f "$data_root/$b/$f.csv" ]] || { echo "real.sh: $data_root/$b/$f.csv is missing" >&2; exit 2; }
  done
done
mkdir -p "$out"

# Where the ladder ends beyond the catalog (completeness kind), the first
# proposed term as an effect, and discovery from the rung propose extended
# offered it.
# Prints the fit to score.
with_proposal() {
  local dir=$1 data=$2 kind
  kind=$(python3 -c 'import json,sys; print(json.load(open(sys.argv[1]))["completeness"]["kind"])' \
         "$dir/discover/ladder.json")
  if [[ $kind != beyond_catalog ]]; then echo "$dir/discover/fit.json"; return; fi
  "$exe" propose --data "$data" --fit "$dir/discover" --out "$dir/proposals" --force >"$dir/proposals.log"
  if [[ ! -f "$dir/proposals/effect/CMakeLists.txt" ]]; then echo "$dir/discover/fit.json"; return; fi
  cmake -S "$dir/proposals/effect" -B "$dir/effect-build" -DCMAKE_BUILD_TYPE=Release -Dhystbench_DIR="$build" >/dev/null
  cmake --build "$dir/effect-build" >/dev/null
  local start
  start=$(python3 -c 'import json,sys; print(json.load(open(sys.argv[1]))["propose_from"]["model"])' \
          "$dir/discover/ladder.json")
  "$exe" discover --data "$data" --start "$start" --plugin "$dir/effect-build/proposed_term.so" \
    --candidates proposed_term --max-steps 1 --warmup "$fit_warmup" --initial-state "${initial[$b]}" \
    --input-unit V --output-unit V \
    ${discover_options[@]+"${discover_options[@]}"} \
    --out "$dir/with_effect" --force >"$dir/with_effect.log"
  echo "$dir/with_effect/fit.json"
}

# The library a fit needs to be simulated (none for catalog effects).
plugin_of() {
  local fit=$1 dir=$2
  case ${fit#"$dir/"} in
    with_effect/*) echo "--plugin $dir/effect-build/proposed_term.so" ;;
    hold_*) if [[ -f "$dir/effect-build/proposed_term.so" ]]; then echo "--plugin $dir/effect-build/proposed_term.so"; fi ;;
    grey_box/*) echo "--plugin $dir/grey_box-build/$(cut -d' ' -f2 <<<"${grey_box[$b]}").so" ;;
  esac
}

# RMSE on the estimation record after the fits' warm-up, simulated as the
# test records are (compare writes the report into OUT).
estimation_rmse() {
  local fit=$1 dir=$2 out=$3 data=$4 plugin
  read -r -a plugin <<<"$(plugin_of "$fit" "$dir")"
  "$exe" compare --data "$data" --fit "$fit" ${plugin[@]+"${plugin[@]}"} --warmup "$fit_warmup" --out "$out" \
    --force >"$out.log"
  python3 -c 'import json,sys; print(json.load(open(sys.argv[1]))["all"]["rmse"])' "$out/metrics.json"
}

# Where the benchmark has a grey box: builds and fits it, and prints
# whichever of it and FIT scores lower on the estimation record. The test
# records never take part in the choice.
with_grey_box() {
  local dir=$1 data=$2 fit=$3 example library model options
  if [[ -z ${grey_box[$b]:-} ]]; then echo "$fit"; return; fi
  read -r example library model options <<<"${grey_box[$b]}"
  local extra; read -r -a extra <<<"$options"
  cmake -S "$repo/$example" -B "$dir/grey_box-build" -DCMAKE_BUILD_TYPE=Release -Dhystbench_DIR="$build" >/dev/null
  cmake --build "$dir/grey_box-build" >/dev/null
  "$exe" fit --data "$data" --model "$model" --plugin "$dir/grey_box-build/$library.so" --warmup "$fit_warmup" \
    --initial-state "${initial[$b]}" --holdout none --input-unit V --output-unit V ${extra[@]+"${extra[@]}"} \
    ${grey_box_options[@]+"${grey_box_options[@]}"} --out "$dir/grey_box" --force 2>&1 | tee "$dir/grey_box.log" >&2
  local from=${fit#"$dir/"} found law
  from=${from%%/*}
  found=$(estimation_rmse "$fit" "$dir" "$dir/estimation_$from" "$data")
  law=$(estimation_rmse "$dir/grey_box/fit.json" "$dir" "$dir/estimation_grey_box" "$data")
  { echo "estimation_rmse_$from=$found"; echo "estimation_rmse_grey_box=$law"
    echo "grey_box=$example $model ${extra[*]} ${grey_box_options[*]}"; } >>"$dir/timings.txt"
  python3 -c 'import sys; print(sys.argv[3] if float(sys.argv[2]) < float(sys.argv[1]) else sys.argv[4])' \
    "$found" "$law" "$dir/grey_box/fit.json" "$fit"
}

# The held-out RMSE a fit.json records.
heldout_rmse() {
  python3 -c 'import json,sys; print(json.load(open(sys.argv[1]))["errors"]["heldout_rmse"])' "$1"
}

# Fits FIT's model afresh under the spline and under the band-limited hold,
# with the same seed and options, and prints the band-limited fit where it
# holds out lower on the estimation record than both its spline twin and
# FIT (a smaller search budget must not swap in a worse fit), else FIT. A
# model without an ODE effect fits the same under both and keeps FIT; the
# test records take no part. Discover's own fits use the spline: the kernel costs an
# oscillator 40 % more time a simulation (benchmarks/feedback_hysteresis_bench.cpp).
with_input_hold() {
  local dir=$1 data=$2 fit=$3 plugin model hold
  read -r -a plugin <<<"$(plugin_of "$fit" "$dir")"
  model=$(python3 -c 'import json,sys; print(json.load(open(sys.argv[1]))["model"])' "$fit")
  for hold in spline bandlimited; do
    "$exe" fit --data "$data" --model "$model" ${plugin[@]+"${plugin[@]}"} --warmup "$fit_warmup" \
      --initial-state "${initial[$b]}" --input-hold "$hold" --input-unit V --output-unit V \
      ${fit_options[@]+"${fit_options[@]}"} --out "$dir/hold_$hold" --force 2>&1 | tee "$dir/hold_$hold.log" >&2
  done
  local spline band found
  spline=$(heldout_rmse "$dir/hold_spline/fit.json")
  band=$(heldout_rmse "$dir/hold_bandlimited/fit.json")
  found=$(heldout_rmse "$fit")
  printf 'heldout_rmse_spline=%s\nheldout_rmse_bandlimited=%s\nheldout_rmse_found=%s\n' "$spline" "$band" "$found" \
    >>"$dir/timings.txt"
  python3 -c 'import sys; s, b, f = map(float, sys.argv[1:4]); print(sys.argv[4] if b < min(s, f) else sys.argv[5])' \
    "$spline" "$band" "$found" "$dir/hold_bandlimited/fit.json" "$fit"
}

# discover from msd on DATA with warm-up W into DIR (its log beside it).
discover_from_msd() {
  local data=$1 w=$2 to=$3
  "$exe" discover --data "$data" --start msd --warmup "$w" --initial-state "${initial[$b]}" --max-steps "$max_steps" \
    --input-unit V --output-unit V ${discover_options[@]+"${discover_options[@]}"} --out "$to" --force | tee "$to.log" >&2
}

# The warm-up the ladder in DIR advises when a start-up transient dominated
# its error and the advice exceeds W (docs/discovery.md, "Start-up
# transients"); empty otherwise, and on a held start, whose warm-up outputs
# set the level: a long warm-up would average a moving stretch.
advised_warmup() {
  [[ ${initial[$b]} == held ]] && return 0
  python3 -c 'import json, sys
s = json.load(open(sys.argv[1]))["startup_transient"]
print(s["warmup"] if s["dominates"] and s["warmup"] > int(sys.argv[2]) else "")' "$1/ladder.json" "$2"
}

run_benchmark() {
  local b=$1 dir="$out/$1" data="$data_root/$1/estimation.csv"
  rm -rf "$dir" && mkdir -p "$dir"
  local t0=$SECONDS fit_warmup=${warmup[$b]} advised
  discover_from_msd "$data" "$fit_warmup" "$dir/discover"
  { echo "max_steps=$max_steps"; echo "discover_options=${DISCOVER_OPTIONS:-}"; } >"$dir/timings.txt"
  advised=$(advised_warmup "$dir/discover" "$fit_warmup")
  if [[ -n $advised ]]; then
    # That ladder's fits were decided by the transient, not by the physics
    # of the rest of the record.
    echo "first_discover_seconds=$((SECONDS - t0))" >>"$dir/timings.txt"
    mv "$dir/discover" "$dir/discover_first" && mv "$dir/discover.log" "$dir/discover_first.log"
    fit_warmup=$advised t0=$SECONDS
    discover_from_msd "$data" "$fit_warmup" "$dir/discover"
  fi
  { echo "discover_seconds=$((SECONDS - t0))"; echo "fit_warmup=$fit_warmup"; echo "score_warmup=${warmup[$b]}"; } \
    >>"$dir/timings.txt"
  t0=$SECONDS
  local fit
  fit=$(with_proposal "$dir" "$data")
  echo "proposal_seconds=$((SECONDS - t0))" >>"$dir/timings.txt"
  t0=$SECONDS
  fit=$(with_input_hold "$dir" "$data" "$fit")
  { echo "hold_seconds=$((SECONDS - t0))"; echo "hold_fit=${fit#"$dir/"}"; } >>"$dir/timings.txt"
  t0=$SECONDS
  fit=$(with_grey_box "$dir" "$data" "$fit")
  [[ -z ${grey_box[$b]:-} ]] || echo "grey_box_seconds=$((SECONDS - t0))" >>"$dir/timings.txt"
  echo "scored_fit=${fit#"$dir/"}" >>"$dir/timings.txt"
  local plugin
  read -r -a plugin <<<"$(plugin_of "$fit" "$dir")"
  for t in ${tests[$b]}; do
    "$exe" compare --data "$data_root/$b/$t.csv" --fit "$fit" ${plugin[@]+"${plugin[@]}"} --warmup "${warmup[$b]}" \
      --out "$dir/$t" --force >"$dir/$t.log"
  done
  # What is committed: reports, JSON, gnuplot scripts and PNG figures.
  rm -rf "$dir/effect-build" "$dir/grey_box-build"
  find "$dir" \( -name '*.pdf' -o -name '*.svg' -o -name '*.dat' -o -name fit_model.csv -o -name gnuplot.log \
                 -o -name checkpoint.json \) -delete
}

for b in $benchmarks; do
  echo "== $b" >&2
  run_benchmark "$b"
done
python3 "$repo/benchmarks/real_summary.py" "$out" $benchmarks
echo "wrote $out/summary.csv and $out/README.md" >&2
