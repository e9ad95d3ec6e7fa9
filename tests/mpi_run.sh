#!/usr/bin/env bash
# `mpirun -np 3 hystbench run` gives the numbers of a single-process run
# (summary.json, trials.jsonl, convergence.csv, wall times and provenance
# aside), and a bad experiment stops all three ranks with one message and
# exit code 2 instead of hanging. Compared with sed, sort and cmp only: a
# clean machine may have no python or jq.
set -euo pipefail
hystbench=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# CI runs as root; OpenMPI refuses that unless told it is meant.
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
# One thread per rank: three ranks on a two-core machine stay quick.
export OMP_NUM_THREADS=1
# Containers often forbid the cross-memory copy Open MPI uses for large
# messages between ranks of one machine; plain copies work everywhere.
export OMPI_MCA_btl_vader_single_copy_mechanism=none
# Under AddressSanitizer (scripts/sanitize.sh asan): Open MPI is built without
# frame pointers, so the leak checker needs the slow unwinder to see that what
# Open MPI leaves allocated at exit is its own (tests/sanitizers/lsan.supp).
if [[ -n "${ASAN_OPTIONS:-}" ]]; then
  export ASAN_OPTIONS="$ASAN_OPTIONS:fast_unwind_on_malloc=0"
fi
mpirun_3() { timeout 120 mpirun --oversubscribe --bind-to none -np 3 "$@"; }

cat > "$work/experiment.json" <<JSON
{"name": "mpi", "problem": {"type": "function", "name": "sphere", "dimension": 4},
 "budget": {"evaluations": 400}, "trials": 6, "seed": 7,
 "algorithms": [{"name": "de", "params": {"np": 20}},
                {"name": "pso", "label": "PSO", "params": {"swarm": 20}}]}
JSON

"$hystbench" run "$work/experiment.json" --out "$work/single" --threads 1 >/dev/null 2>&1
mpirun_3 "$hystbench" run "$work/experiment.json" --out "$work/mpi" > "$work/mpi.out" 2> "$work/mpi.err"

# What may differ between the runs: wall times and the provenance block.
numbers() { sed -e '/"wall_seconds"/d' -e '/"provenance": {/,/^  }/d' "$1"; }
trials() { sed -E 's/,?"wall_seconds":[^,}]*//' "$1" | sort; }
cmp <(numbers "$work/single/summary.json") <(numbers "$work/mpi/summary.json")
cmp <(trials "$work/single/trials.jsonl") <(trials "$work/mpi/trials.jsonl")
cmp "$work/single/convergence.csv" "$work/mpi/convergence.csv"
[[ $(wc -l < "$work/mpi/trials.jsonl") -eq 12 ]]
# Rank 0 alone prints: one results table.
[[ $(grep -c '^Results in ' "$work/mpi.out") -eq 1 ]]

# A bad experiment: exit code 2 on every rank, one message, no hang.
echo '{"name": "bad", "trials": 0}' > "$work/bad.json"
status=0
mpirun_3 "$hystbench" run "$work/bad.json" --out "$work/bad" > /dev/null 2> "$work/bad.err" || status=$?
[[ $status -eq 2 ]] || { echo "bad experiment: exit code $status, expected 2" >&2; cat "$work/bad.err" >&2; exit 1; }
[[ $(grep -c 'hystbench: error' "$work/bad.err") -eq 1 ]] || { cat "$work/bad.err" >&2; exit 1; }
echo "mpirun -np 3 run: same numbers as one process; bad input stops every rank once: ok"
