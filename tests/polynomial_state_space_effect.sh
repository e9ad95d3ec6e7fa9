#!/usr/bin/env bash
# The second-order polynomial state space of examples/polynomial_state_space_effect,
# built against the build tree, batched like the catalog's effects, and
# simulated from a step (docs/discovery.md,
# "A polynomial state space beside the ladder"): at period 0 it passes the
# signal through exactly; its linear part has unit static gain whatever
# `lead` and `feedthrough` are; and an output term c·x1² moves the settled
# output from 1 to 1 + c, as by hand.
source "$(dirname "${BASH_SOURCE[0]}")/plugin_script.sh"

build_plugin "$source_dir/examples/polynomial_state_space_effect" "$work/plugin" -Dhystbench_DIR="$build_dir"
plugin="$work/plugin/polynomial_state_space.so"
hystbench="$build_dir/hystbench"
"$hystbench" list effects --plugin "$plugin" > "$work/list.txt"
grep -q "^  polynomial_state_space \[dynamics\]" "$work/list.txt" || fail "the example effect is not listed"
# Batched, and its blocks equal to single candidates.
"$build_dir/tests/hystbench_lane_check" "$plugin" polynomial_state_space ||
  fail "the example effect is not batched, or its blocks differ from single candidates"

# 2 s at 500 Hz: a sine, then a step to 1 held for 1.5 s (the resonance,
# period 20 ms and zeta 0.7, settles within a tenth of that).
cat > "$work/excitation.json" <<'JSON'
{"sample_rate": 500, "segments": [
  {"type": "sine", "frequency": 5, "amplitude": 1, "offset": 0, "duration": 0.5},
  {"type": "steps", "levels": [1], "hold": 1.5, "ramp": 0}]}
JSON
# The physical value of every parameter: PERIOD, LEAD, FEEDTHROUGH, F_X1X1; the rest 0.
params() {
  python3 - "$@" <<'PY'
import json, sys
period, lead, feedthrough, f = map(float, sys.argv[1:])
names = ["x1x1", "x1x2", "x2x2", "x1x1x1", "x1x1x2", "x1x2x2", "x2x2x2"]
p = {"gain": 1.0, "polynomial_state_space.period": period, "polynomial_state_space.zeta": 0.7,
     "polynomial_state_space.lead": lead, "polynomial_state_space.feedthrough": feedthrough}
for row in ("e1_", "e2_", "f_"):
    for n in names:
        p["polynomial_state_space." + row + n] = 0.0
p["polynomial_state_space.f_x1x1"] = f
print(json.dumps(p))
PY
}
# Simulates with the parameters PERIOD LEAD FEEDTHROUGH F_X1X1 into NAME.csv.
simulate() {
  local name=$1; shift
  params "$@" > "$work/$name.json"
  "$hystbench" simulate --model polynomial_state_space --plugin "$plugin" --params "$work/$name.json" \
    --excitation "$work/excitation.json" --noise 0 --out "$work/$name.csv" >/dev/null
}
simulate neutral 0 0.4 -0.3 0.2
simulate linear 0.02 0 0 0
simulate bent 0.02 0.5 0.3 0
simulate output_term 0.02 0 0 0.2

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
for name, settled in (("linear", 1.0), ("bent", 1.0), ("output_term", 1.2)):
    y = read(name)[-1][1]
    if abs(y - settled) > 1e-9:
        fail(f"{name}: settles at {y!r}, by hand {settled}")
if max(abs(a[1] - b[1]) for a, b in zip(read("linear"), read("bent"))) < 1e-3:
    fail("lead and feedthrough do not change the response")
print("polynomial_state_space: pass-through, unit static gain and the output term as by hand")
PY
