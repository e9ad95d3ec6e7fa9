#!/usr/bin/env bash
# Builds like `cmake --build`, then fails if the compiler warned: `make test`
# (and so CI) builds through this, so a new warning fails there, not only
# in someone's terminal. The project compiles with -Wall -Wextra; Eigen's
# false positives are silenced where it is included (framework/core/eigen.hpp).
# Only the files compiled in this build are seen, so a clean build checks all.
#
#   scripts/build-without-warnings.sh BUILD_DIR JOBS [cmake --build options...]
set -euo pipefail
build=$1 jobs=$2
shift 2
log="$build/build.log"
env -u MAKEFLAGS -u MFLAGS -u MAKELEVEL cmake --build "$build" -j "$jobs" "$@" 2>&1 | tee "$log"
warnings=$(grep -E ': warning: ' "$log" || true)
if [[ -n "$warnings" ]]; then
  echo >&2
  echo "error: the build warned ($(grep -c . <<< "$warnings") warnings; all of them are in $log):" >&2
  grep -m 10 . <<< "$warnings" >&2
  echo "Fix them: the project builds without warnings under -Wall -Wextra (docs/development.md#warnings)." >&2
  exit 1
fi
