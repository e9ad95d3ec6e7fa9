#!/usr/bin/env bash
# Builds the libFuzzer targets of fuzz/ (clang, preset `fuzz`, build-fuzz/)
# and runs one of them with AddressSanitizer, UndefinedBehaviorSanitizer and
# leak detection:
#   scripts/fuzz.sh csv [seconds]          the measurement CSV reader
#   scripts/fuzz.sh experiment [seconds]   the experiment-file loader
# 600 seconds unless told. It starts from the seeds in fuzz/corpus/<target>/
# and keeps what it finds in build-fuzz/corpus/<target>/ (not committed). A
# finding stops it with a report and a reproducer build-fuzz/crash-* (or
# leak-*, timeout-*, oom-*), and the script exits non-zero; replay it with
# build-fuzz/fuzz/<target>_fuzzer FILE.
set -euo pipefail
cd "$(dirname "$0")/.."

target=${1:-}
seconds=${2:-600}
case "$target" in
  csv) fuzzer=csv_reader_fuzzer ;;
  experiment) fuzzer=experiment_loader_fuzzer ;;
  *) echo "usage: $0 csv|experiment [seconds]" >&2; exit 2 ;;
esac
scripts/install-deps.sh fuzz  # adds clang and its libFuzzer runtime

cmake --preset fuzz >/dev/null
env -u MAKEFLAGS -u MFLAGS -u MAKELEVEL cmake --build --preset fuzz --target "$fuzzer"

corpus=build-fuzz/corpus/$target
mkdir -p "$corpus"
export ASAN_OPTIONS=detect_leaks=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
# -timeout: one input taking 10 s is a hang; -rss_limit_mb: 2 GB is a blow-up.
build-fuzz/fuzz/$fuzzer "$corpus" "fuzz/corpus/$target" -dict="fuzz/$target.dict" \
  -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 \
  -artifact_prefix=build-fuzz/ -print_final_stats=1
