#!/usr/bin/env bash
# Installs hystbench into a temporary prefix, builds the example plugin in
# examples/ against that installed copy with find_package(hystbench), and
# runs it through `--plugin` with the installed command; then builds it
# against the build tree (-Dhystbench_DIR) and lists it with that command.
source "$(dirname "${BASH_SOURCE[0]}")/plugin_script.sh" || exit 1

cmake --install "$build_dir" --prefix "$work/prefix" >/dev/null
build_plugin "$source_dir/examples/random_search_plugin" "$work/plugin" -DCMAKE_PREFIX_PATH="$work/prefix"

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
build_plugin "$source_dir/examples/random_search_plugin" "$work/plugin_from_build" -Dhystbench_DIR="$build_dir"
"$build_dir/hystbench" list --plugin "$work/plugin_from_build/random_search.so" > "$work/list_from_build.txt"
grep -q "random_search - uniform random sampling" "$work/list_from_build.txt"
echo "out-of-tree plugin built against the installed package and the build tree, and run: ok"
