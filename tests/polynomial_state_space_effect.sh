#!/usr/bin/env bash
# The second-order polynomial state space of examples/polynomial_state_space_effect,
# in both its forms (the state's monomials only, 25 parameters; with the
# input's too, 52), built against the build tree, batched like the catalog's
# effects, and simulated from a step (docs/discovery.md, "A polynomial state
# space beside the ladder"): at period 0 it passes the signal through
# exactly; its linear part has unit static gain whatever `lead` and
# `feedthrough` are; and output terms c·x1² and c·x1³ move the output
# settled at 2 to 2 + 4c and 2 + 8c, as by hand.
source "$(dirname "${BASH_SOURCE[0]}")/plugin_script.sh" || exit 1

hystbench="$build_dir/hystbench"
# Builds the form FORM (state, full) and checks its listing: parameter
# count COUNT, and a coefficient of a monomial holding the input only in the
# full form.
check_form() {
  local form=$1 count=$2 option=OFF
  [[ $form == full ]] && option=ON
  build_plugin "$source_dir/examples/polynomial_state_space_effect" "$work/$form" -Dhystbench_DIR="$build_dir" \
    -DPSS_INPUT_MONOMIALS=$option
  "$hystbench" list effects --plugin "$work/$form/polynomial_state_space.so" > "$work/$form.txt"
  local listed
  listed=$(awk '/^  polynomial_state_space \[dynamics\]/ { on = 1; next } /^  [a-z]/ { on = 0 }
                on && /^      [a-z0-9_]+ in \[/ { n++ } END { print n + 0 }' "$work/$form.txt")
  [[ $listed == "$count" ]] || fail "$form form: $listed parameters listed, not $count"
  if grep -q "^      f_x1x1v in" "$work/$form.txt"; then
    [[ $form == full ]] || fail "the state form has an input monomial"
  else
    [[ $form == state ]] || fail "the full form has no input monomial"
  fi
  # Batched, and its blocks equal to single candidates.
  "$build_dir/tests/hystbench_lane_check" "$work/$form/polynomial_state_space.so" polynomial_state_space ||
    fail "$form form: not batched, or its blocks differ from single candidates"
}
check_form state 25
check_form full 52
plugin="$work/state/polynomial_state_space.so"

# 2 s at 500 Hz: a sine, then a step to 2 held for 1.5 s (the resonance,
# period 20 ms and zeta 0.7, settles within a tenth of that).
cat > "$work/excitation.json" <<'JSON'
{"sample_rate": 500, "segments": [
  {"type": "sine", "frequency": 5, "amplitude": 1, "offset": 0, "duration": 0.5},
  {"type": "steps", "levels": [2], "hold": 1.5, "ramp": 0}]}
JSON
# Parameters PERIOD LEAD FEEDTHROUGH F_X1X1 F_X1X1X1 (physical values), gain
# 1, zeta 0.7, every other coefficient 0.
params() {
  python3 - "$@" <<'PY'
import json, sys
period, lead, feedthrough, f2, f3 = map(float, sys.argv[1:])
names = ["x1x1", "x1x2", "x2x2", "x1x1x1", "x1x1x2", "x1x2x2", "x2x2x2"]
p = {"gain": 1.0, "polynomial_state_space.period": period, "polynomial_state_space.zeta": 0.7,
     "polynomial_state_space.lead": lead, "polynomial_state_space.feedthrough": feedthrough}
for row in ("e1_", "e2_", "f_"):
    for n in names:
        p["polynomial_state_space." + row + n] = 0.0
p["polynomial_state_space.f_x1x1"], p["polynomial_state_space.f_x1x1x1"] = f2, f3
print(json.dumps(p))
PY
}
# Simulates with the parameters PERIOD LEAD FEEDTHROUGH F_X1X1 F_X1X1X1 into NAME.csv.
simulate() {
  local name=$1; shift
  params "$@" > "$work/$name.json"
  "$hystbench" simulate --model polynomial_state_space --plugin "$plugin" --params "$work/$name.json" \
    --excitation "$work/excitation.json" --noise 0 --out "$work/$name.csv" >/dev/null
}
simulate neutral 0 0.4 -0.3 0.05 0.05
simulate linear 0.02 0 0 0 0
simulate bent 0.02 0.5 0.3 0 0
simulate square 0.02 0 0 0.05 0
simulate cube 0.02 0 0 0 0.05

python3 - "$work" <<'PY'
import csv, sys
work = sys.argv[1]
def fail(msg):
    sys.exit("FAIL: polynomial_state_space: " + msg)
def read(name):
    rows = [r for r in csv.reader(open(f"{work}/{name}.csv")) if r and not r[0].startswith("#")]
    head = rows[0]
    return [(float(r[head.index("u")]), float(r[head.index("y")])) for r in rows[1:]]
neutral = read("neutral")
if any(y != u for u, y in neutral):
    fail("at period 0 the output is not the input exactly")
# Settled at x1 = 2, x2 = 0: y = 2 + c·2² or 2 + c·2³.
for name, settled in (("linear", 2.0), ("bent", 2.0), ("square", 2.2), ("cube", 2.4)):
    y = read(name)[-1][1]
    if abs(y - settled) > 1e-9:
        fail(f"{name}: settles at {y!r}, by hand {settled}")
if max(abs(a[1] - b[1]) for a, b in zip(read("linear"), read("bent"))) < 1e-3:
    fail("lead and feedthrough do not change the response")
print("polynomial_state_space: both forms listed and batched; pass-through, unit static gain and the "
      "output terms as by hand")
PY
