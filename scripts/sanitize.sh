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
# Set before the build too: the build runs the test program to list its tests.
suppressions=$PWD/tests/sanitizers
export ASAN_OPTIONS=detect_leaks=1:check_initialization_order=1
export LSAN_OPTIONS=suppressions=$suppressions/lsan.supp
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
export TSAN_OPTIONS=suppressions=$suppressions/tsan.supp:second_deadlock_stack=1
if [[ "$preset" == tsan ]]; then
  scripts/install-deps.sh tsan  # clang, its TSan runtime, libomp and Archer
  # GCC's libgomp synchronises its threads where ThreadSanitizer cannot see,
  # so the tsan preset builds with clang and LLVM's libomp, whose Archer tool
  # tells ThreadSanitizer about every OpenMP barrier, lock and task. Archer
  # asks that the runtime's own, uninstrumented, accesses be ignored.
  llvm_lib=$(dirname "$(readlink -f "$(command -v clang++)")")/../lib
  export OMP_TOOL_LIBRARIES=$llvm_lib/libarcher.so
  [[ -f "$OMP_TOOL_LIBRARIES" ]] || { echo "no Archer at $OMP_TOOL_LIBRARIES (Debian: libomp-14-dev)" >&2; exit 1; }
  export TSAN_OPTIONS=$TSAN_OPTIONS:ignore_noninstrumented_modules=1
else
  scripts/install-deps.sh  # g++ brings libasan and libubsan
fi

cmake --preset "$preset" >/dev/null
env -u MAKEFLAGS -u MFLAGS -u MAKELEVEL cmake --build --preset "$preset" -j "$jobs"
ctest --preset "$preset" -j "$jobs"
