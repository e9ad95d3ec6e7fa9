#!/usr/bin/env bash
# Installs hystbench into a temporary prefix, builds the example effect in
# examples/thermal_drift_effect/ against that installed copy with
# find_package(hystbench) (and once against the build tree), and checks that
# the installed command picks it up through `--plugin`: listed, exactly
# neutral at k = 0, simulated, named by `diagnose` as what a model without it
# is missing (and not named when nothing is missing), added by `discover`,
# which then stops and recovers k and tau.
source "$(dirname "${BASH_SOURCE[0]}")/plugin_script.sh" || exit 1

cmake --install "$build_dir" --prefix "$work/prefix" >/dev/null
build_plugin "$source_dir/examples/thermal_drift_effect" "$work/plugin" -DCMAKE_PREFIX_PATH="$work/prefix"

hystbench="$work/prefix/bin/hystbench"
plugin="$work/plugin/thermal_drift.so"
[[ -f "$plugin" ]] || fail "the example did not build $plugin"

# The same example builds against the build tree, without installing.
build_plugin "$source_dir/examples/thermal_drift_effect" "$work/plugin_from_build" -Dhystbench_DIR="$build_dir"
"$build_dir/hystbench" list effects --plugin "$work/plugin_from_build/thermal_drift.so" \
  > "$work/list_from_build.txt"
grep -q "^  thermal_drift \[nonlinearity\]" "$work/list_from_build.txt" ||
  fail "the example built against the build tree is not listed by its hystbench"

# Listed with its stage and parameters only when the plugin is loaded.
"$hystbench" list effects --plugin "$plugin" > "$work/list.txt"
grep -q "^  thermal_drift \[nonlinearity\] - thermal expansion" "$work/list.txt" ||
  fail "list effects --plugin does not show thermal_drift"
grep -q "^      tau in \[0.1, 30\], neutral 3 (s)" "$work/list.txt" ||
  fail "list effects --plugin does not show the parameter tau"
# Through a file, not a pipe into `grep -q` (whose early exit SIGPIPEs the writer).
"$hystbench" list effects > "$work/list_without.txt"
if grep -q thermal_drift "$work/list_without.txt"; then
  fail "thermal_drift is listed without --plugin"
fi

# The example's excitation.json, 8 s at 500 Hz: a zero-mean 5 Hz sine that
# heats the actuator for 4 s, then no drive for 4 s while it cools. Without
# the thermal term the output would be symmetric about zero and vanish with
# the drive. Its true.json: k = 0.3, tau = 1.5 s.
example="$source_dir/examples/thermal_drift_effect"
cp "$example/excitation.json" "$example/true.json" "$work/"
cat > "$work/msd.json" <<'JSON'
{"gain": 1.0, "msd.period": 0.02, "msd.zeta": 0.2}
JSON
cat > "$work/neutral.json" <<'JSON'
{"gain": 1.0, "msd.period": 0.02, "msd.zeta": 0.2, "thermal_drift.k": 0, "thermal_drift.tau": 1.5}
JSON

# At its neutral value the effect leaves the model's output exactly unchanged.
"$hystbench" simulate --model msd --params "$work/msd.json" --excitation "$work/excitation.json" \
  --noise 0.01 --seed 3 --out "$work/base.csv" >/dev/null
"$hystbench" simulate --model msd,thermal_drift --plugin "$plugin" --params "$work/neutral.json" \
  --excitation "$work/excitation.json" --noise 0.01 --seed 3 --out "$work/neutral.csv" >/dev/null
cmp -s <(grep -v '^#' "$work/base.csv") <(grep -v '^#' "$work/neutral.csv") ||
  fail "thermal_drift at k = 0 changes the simulated output"

# Data with the thermal term hidden in it.
"$hystbench" simulate --model msd,thermal_drift --plugin "$plugin" --params "$work/true.json" \
  --excitation "$work/excitation.json" --noise 0.01 --seed 3 --out "$work/data.csv" >/dev/null
if cmp -s <(grep -v '^#' "$work/base.csv") <(grep -v '^#' "$work/data.csv"); then
  fail "thermal_drift at k = 0.3 does not change the simulated output"
fi

# diagnose: among all the registered effects, the plugin's is the one missing.
"$hystbench" diagnose --data "$work/data.csv" --model msd --plugin "$plugin" \
  --out "$work/diagnose" >/dev/null
grep -q '"effect": "thermal_drift"' "$work/diagnose/diagnosis.json" ||
  fail "thermal_drift is not among the candidates of diagnose"
grep -q '"verdict": "thermal_drift"' "$work/diagnose/diagnosis.json" ||
  fail "the verdict of diagnose is not thermal_drift: $(grep '"verdict"' "$work/diagnose/diagnosis.json")"

# ... and a diagnosis that always names it would be worthless: on the data
# without the thermal term the verdict is none, and thermal_drift is tried
# but not significant.
"$hystbench" diagnose --data "$work/base.csv" --model msd --plugin "$plugin" \
  --out "$work/diagnose_base" >/dev/null
grep -q '"effect": "thermal_drift"' "$work/diagnose_base/diagnosis.json" ||
  fail "thermal_drift is not among the candidates of diagnose on data without it"
grep -q '"verdict": "none"' "$work/diagnose_base/diagnosis.json" ||
  fail "diagnose of data without a missing effect names one: $(grep '"verdict"' "$work/diagnose_base/diagnosis.json")"

# discover: the ladder from msd adds the plugin's effect, then stops (the
# last diagnosis finds nothing more), and the final fit recovers its truth.
"$hystbench" discover --data "$work/data.csv" --start msd --plugin "$plugin" \
  --out "$work/discover" >/dev/null
sed -n '/"final_effects"/,/]/p' "$work/discover/ladder.json" > "$work/final_effects.txt"
grep -q '"thermal_drift"' "$work/final_effects.txt" ||
  fail "final_effects of discover do not contain thermal_drift"
grep -q '"final_model": "thermal_drift,msd"' "$work/discover/ladder.json" ||
  fail "discover did not end with exactly thermal_drift,msd: $(grep '"final_model"' "$work/discover/ladder.json")"
value() {  # physical value of parameter $1 in the final fit
  grep -A3 "\"name\": \"$1\"" "$work/discover/fit.json" | sed -n 's/.*"value": \([^,]*\).*/\1/p'
}
within() {  # $1 within a relative $3 of $2
  awk -v x="$1" -v t="$2" -v r="$3" 'BEGIN { d = x - t; if (d < 0) d = -d; exit !(x != "" && d <= r * t) }'
}
within "$(value thermal_drift.k)" 0.3 0.05 || fail "fitted k = $(value thermal_drift.k), true 0.3"
within "$(value thermal_drift.tau)" 1.5 0.05 || fail "fitted tau = $(value thermal_drift.tau) s, true 1.5 s"
echo "out-of-tree effect built against the installed package, diagnosed and discovered: ok"
