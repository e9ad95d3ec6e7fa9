#!/usr/bin/env bash
# Every shell command line of the README, run as written in a fresh folder
# that looks like a checkout (the source tree's folders linked in, the
# built tree as build/), in the order the README gives them. A command that
# fails, or that writes into results/, fails the test. `make demo` and
# `make test` are this suite's own set-up and are not run again.
#
# The bundled SVR experiment simulates its records when they are missing;
# they must equal what benchmarks/svr_piezo_data.sh writes, but for the
# output path the script records in them.
#
#   tests/readme_commands.sh BUILD_DIR SOURCE_DIR
set -euo pipefail
build_dir=$(cd "$1" && pwd)
source_dir=$(cd "$2" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }

# A checkout: folders linked, results/ rebuilt so that records made on
# demand land in the work folder, never in the source tree.
for entry in "$source_dir"/*; do
  name=$(basename "$entry")
  [[ $name == build* || $name == out || $name == results ]] && continue
  ln -s "$entry" "$work/$name"
done
ln -s "$build_dir" "$work/build"
mkdir "$work/results"
for entry in "$source_dir"/results/*; do ln -s "$entry" "$work/results/$(basename "$entry")"; done
rm "$work/results/svr" && cp -r "$source_dir/results/svr" "$work/results/svr" && rm -rf "$work/results/svr/data"

# The ```sh blocks, continuation lines joined.
commands=$(awk '/^```sh$/ { inside = 1; next } /^```/ { inside = 0 } inside' "$source_dir/README.md" |
           sed -e ':a' -e '/\\$/N; s/\\\n//; ta' | sed -E 's/[[:space:]]+#.*$//' | grep -v '^[[:space:]]*$')
[[ -n "$commands" ]] || fail "no shell commands found in README.md"
count=0
assignments=""  # a line such as D=file holds for the commands after it
cd "$work"
while IFS= read -r line; do
  [[ $line == make\ * ]] && continue
  if [[ $line =~ ^[A-Z_]+=[^[:space:]]+$ ]]; then assignments+="$line; "; continue; fi
  [[ $line =~ --out[[:space:]]+results/ ]] && fail "a README command writes into results/: $line"
  count=$((count + 1))
  start=$(date +%s)
  if ! bash -c "set -euo pipefail; $assignments$line" > "command-$count.log" 2>&1 < /dev/null; then
    tail -20 "command-$count.log" >&2
    fail "README command $count failed: $line"
  fi
  echo "ok ($(( $(date +%s) - start )) s): $line"
done <<< "$commands"
(( count >= 10 )) || fail "only $count README commands ran; the README's shell blocks were not read"

# Records made by the SVR experiment against the script's.
[[ -f results/svr/data/train.csv ]] || fail "the SVR experiment did not make its missing records"
HYSTBENCH=build/hystbench benchmarks/svr_piezo_data.sh script-data > /dev/null
for file in train.csv test.csv train.truth.json test.truth.json; do
  cmp -s <(sed -E 's#--out [^ "]*##' "results/svr/data/$file") <(sed -E 's#--out [^ "]*##' "script-data/$file") ||
    fail "results/svr/data/$file made by the experiment differs from benchmarks/svr_piezo_data.sh's"
done
echo "readme_commands: $count command lines ran as written; the records made on demand equal the script's"
