#!/usr/bin/env bash
# Builds hystbench with a sanitizer preset of CMakePresets.json and runs the
# whole test suite (ctest) under it; any sanitizer report fails its test.
#   scripts/sanitize.sh asan   AddressSanitizer + UndefinedBehaviorSanitizer,
#                              leak detection on (build-asan/)
#   scripts/sanitize.sh tsan   ThreadSanitizer (build-tsan/)
# Far slower than `make test`, so neither `make test` nor CI runs it. The
# suppressions, and why each is there, are in tests/sanitizers/.
set -euo pipefail
cd "$(dirname "$0")/.."

preset=${1:-}
if [[ "$preset" != asan && "$preset" != tsan ]]; then
  echo "usage: $0 asan|tsan" >&2
  exit 2
fi
jobs=${JOBS:-$(nproc 2>/dev/null || echo 2)}
scripts/install-deps.sh  # g++ brings the sanitizer runtimes (libasan, libubsan, libtsan)

# Set before the build too: the build runs the test program to list its tests.
suppressions=$PWD/tests/sanitizers
export ASAN_OPTIONS=detect_leaks=1:check_initialization_order=1
export LSAN_OPTIONS=suppressions=$suppressions/lsan.supp
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
# history_size=7 (the most): older accesses keep their stacks, without which
# the libgomp entry of tsan.supp cannot recognise an OpenMP worker's access.
export TSAN_OPTIONS=suppressions=$suppressions/tsan.supp:second_deadlock_stack=1:history_size=7

cmake --preset "$preset" >/dev/null
env -u MAKEFLAGS -u MFLAGS -u MAKELEVEL cmake --build --preset "$preset" -j "$jobs"
ctest --preset "$preset" -j "$jobs"
