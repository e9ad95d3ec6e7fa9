#!/usr/bin/env bash
# How fast a generated effect fits beside the catalog effect of its form
# (docs/discovery.md, "Proposing a missing term"): on 12 000 samples of the
# planted hardening spring (tests/planted_physics.hpp), fit msd, propose on
# it, build the generated force (msd plus c·x³) and fit it; with OLD_SOURCE=F,
# also fit the effect of source F (e.g. one generated before effects were
# batched) on the same data. Prints wall time and evaluations of each fit.
#
#   benchmarks/generated_effect.sh [BUILD_DIR]
set -euo pipefail
repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="$(cd "${1:-$repo/build}" && pwd)"
exe="$build/hystbench"
[[ -x "$exe" && -x "$build/tests/hystbench_planted_data" ]] ||
  { echo "generated_effect.sh: build hystbench and its tests first" >&2; exit 2; }
old_source=${OLD_SOURCE:+$(realpath "$OLD_SOURCE")}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
"$build/tests/hystbench_planted_data" cubic_stiffness cubic.csv 12000 >/dev/null

# Fits model $2 (with plugin $3, if any) into folder $1; prints its time and evaluations.
timed_fit() {
  local t0 t1
  t0=$(date +%s.%N)
  "$exe" fit --data cubic.csv --model "$2" ${3:+--plugin "$3"} --out "$1" --force >/dev/null
  t1=$(date +%s.%N)
  printf '%-28s %6.1f s  %s evaluations\n' "$1 ($2)" "$(awk -v a="$t0" -v b="$t1" 'BEGIN { print b - a }')" \
    "$(sed -n 's/.*"evaluations_used": \([0-9]*\).*/\1/p' "$1/fit.json")"
}

timed_fit msd msd
"$exe" propose --data cubic.csv --fit msd/fit.json --out proposal >/dev/null
build_plugin() {
  cmake -S "$1" -B "$1/build" -DCMAKE_BUILD_TYPE=Release -Dhystbench_DIR="$build" >/dev/null
  cmake --build "$1/build" >/dev/null
}
build_plugin proposal/effect
timed_fit generated proposed_term proposal/effect/build/proposed_term.so
if [[ -n $old_source ]]; then
  mkdir old && cp "$old_source" old/proposed_term.cpp && cp proposal/effect/CMakeLists.txt old/
  build_plugin old
  timed_fit old proposed_term old/build/proposed_term.so
fi
