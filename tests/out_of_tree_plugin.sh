#!/usr/bin/env bash
# Installs hystbench into a temporary prefix, builds the example plugin in
# examples/ against that installed copy with find_package(hystbench), and
# runs it through `--plugin` with the installed command; then builds it
# against the build tree (-Dhystbench_DIR) and lists it with that command.
set -euo pipefail
build_dir=$1
source_dir=$2
# The core's compiler flags (a sanitizer build's -fsanitize=...) and compiler
# (clang for ThreadSanitizer), so that the plugin is built, linked and checked
# like the core: two sanitizer runtimes cannot share a process.
core_flags=${3:-}
core_compiler=${4:-c++}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

cmake --install "$build_dir" --prefix "$work/prefix" >/dev/null
cmake -S "$source_dir/examples/random_search_plugin" -B "$work/plugin" \
      -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH="$work/prefix" -DCMAKE_CXX_COMPILER="$core_compiler" \
      -DCMAKE_CXX_FLAGS="$core_flags" -DCMAKE_MODULE_LINKER_FLAGS="$core_flags" >/dev/null
cmake --build "$work/plugin" >/dev/null

hystbench="$work/prefix/bin/hystbench"
plugin="$work/plugin/random_search.so"
# Output goes to a file, not straight into `grep -q`: grep stops reading at the
# first match, and under pipefail the SIGPIPE that then hits hystbench fails
# the script whenever hystbench is still writing.
"$hystbench" list --plugin "$plugin" > "$work/list.txt"
grep -q "random_search - uniform random sampling" "$work/list.txt"

cat > "$work/experiment.json" <<JSON
{"name": "oot", "problem": {"type": "function", "name": "sphere", "dimension": 3},
 "budget": {"evaluations": 640}, "trials": 2, "seed": 1,
 "algorithms": [{"name": "random_search", "params": {"batch": 64}}]}
JSON
"$hystbench" run --plugin "$plugin" "$work/experiment.json" --out "$work/results" >/dev/null
grep -q '"name": "random_search"' "$work/results/summary.json"
grep -q '"evaluations": 640' "$work/results/summary.json"
# The same example builds against the build tree, without installing, and
# the build tree's command loads it.
cmake -S "$source_dir/examples/random_search_plugin" -B "$work/plugin_from_build" \
      -DCMAKE_BUILD_TYPE=Release -Dhystbench_DIR="$build_dir" -DCMAKE_CXX_COMPILER="$core_compiler" \
      -DCMAKE_CXX_FLAGS="$core_flags" -DCMAKE_MODULE_LINKER_FLAGS="$core_flags" >/dev/null
cmake --build "$work/plugin_from_build" >/dev/null
"$build_dir/hystbench" list --plugin "$work/plugin_from_build/random_search.so" > "$work/list_from_build.txt"
grep -q "random_search - uniform random sampling" "$work/list_from_build.txt"
echo "out-of-tree plugin built against the installed package and the build tree, and run: ok"
