#!/usr/bin/env bash
# Physics the catalog lacks, end to end with the built command (docs/discovery.md,
# "Beyond the catalog" and "Proposing a missing term"), on short records
# written by tests/planted_data.cpp:
#   - rate-dependent gain: discover from the seed chain ends with complete: false
#     and the kind beyond_catalog; propose on its fit ranks v·|v'| first at the
#     static stage; the generated effect, built against the build tree, fitted
#     with the seed chain brings the held-out RMSE within 1.2 × the noise sd;
#   - cubic stiffness: propose on a fitted msd ranks x³ first in the dynamics;
#     the generated effect (msd with the force) fitted in msd's place does the same.
# benchmarks/beyond_catalog.sh runs the same at full size.
set -euo pipefail
build_dir=$1
source_dir=$2
core_flags=${3:-}
core_compiler=${4:-c++}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }

hystbench="$build_dir/hystbench"
planted="$build_dir/tests/hystbench_planted_data"
json() { python3 -c "import json,sys; d=json.load(open(sys.argv[1])); print(eval(sys.argv[2]))" "$@"; }
noise=0.01
seed_chain=hysteresis,asymmetry,msd,arx
cd "$work"

# Builds the generated effect of proposal folder $1 against the build tree.
build_effect() {
  cmake -S "$1/effect" -B "$1/effect/build" -DCMAKE_BUILD_TYPE=Release -Dhystbench_DIR="$build_dir" \
        -DCMAKE_CXX_COMPILER="$core_compiler" -DCMAKE_CXX_FLAGS="$core_flags" \
        -DCMAKE_MODULE_LINKER_FLAGS="$core_flags" >/dev/null
  cmake --build "$1/effect/build" >/dev/null
  [[ -f "$1/effect/build/proposed_term.so" ]] || fail "the effect proposed in $1 did not build"
}

# Fits the model proposal $1 names with its effect; checks the held-out RMSE.
fit_with_effect() {
  local model
  model=$(json "$1/proposals.json" "d['effect']['model']")
  "$hystbench" fit --data "$2" --model "$model" --plugin "$1/effect/build/proposed_term.so" \
    --restarts 1 --out "$1/fit" >/dev/null
  local rmse
  rmse=$(json "$1/fit/fit.json" "d['errors']['heldout_rmse']")
  python3 -c "import sys; sys.exit(0 if $rmse <= 1.2 * $noise else 1)" ||
    fail "$2: $model with the proposed effect has held-out RMSE $rmse, more than 1.2 x $noise"
}

# Rate-dependent gain.
"$planted" rate_gain rate.csv 4000
"$hystbench" discover --data rate.csv --start "$seed_chain" --out discover >/dev/null
[[ $(json discover/ladder.json "d['complete']") == False ]] || fail "rate_gain: discover calls the seed chain complete"
[[ $(json discover/ladder.json "d['completeness']['kind']") == beyond_catalog ]] ||
  fail "rate_gain: the ladder does not say the missing physics is beyond the catalog"
grep -q "## Beyond the catalog" discover/ladder.md || fail "rate_gain: ladder.md has no Beyond the catalog section"
"$hystbench" propose --data rate.csv --fit discover/fit.json --out rate >/dev/null
[[ $(json rate/proposals.json "d['terms'][0]['stage'] + ' ' + d['terms'][0]['term']") == "static v·|v'|" ]] ||
  fail "rate_gain: the first proposal is not static v·|v'|: $(json rate/proposals.json "d['terms'][0]")"
build_effect rate
fit_with_effect rate rate.csv

# Cubic stiffness.
"$planted" cubic_stiffness cubic.csv 4000
"$hystbench" fit --data cubic.csv --model msd --out msd >/dev/null
"$hystbench" propose --data cubic.csv --fit msd/fit.json --out cubic >/dev/null
[[ $(json cubic/proposals.json "d['terms'][0]['stage'] + ' ' + d['terms'][0]['term']") == "dynamics x³" ]] ||
  fail "cubic_stiffness: the first proposal is not dynamics x³: $(json cubic/proposals.json "d['terms'][0]")"
build_effect cubic
fit_with_effect cubic cubic.csv
echo "beyond_catalog: both planted cases found, proposed and fitted"
