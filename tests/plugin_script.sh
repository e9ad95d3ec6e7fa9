# shellcheck shell=bash
# Sourced by the test scripts that build a plugin out of the tree. Their
# arguments: BUILD_DIR SOURCE_DIR [CORE_FLAGS] [CORE_COMPILER]. The core's
# compiler flags (a sanitizer build's -fsanitize=...) and compiler (clang
# for ThreadSanitizer) build the plugin too, so that it is linked and
# checked like the core: two sanitizer runtimes cannot share a process.
set -euo pipefail
build_dir=$1
source_dir=$2
core_flags=${3:-}
core_compiler=${4:-c++}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }

# Configures and builds the plugin project SOURCE in BUILD with the core's
# compiler and flags; further arguments go to cmake (where hystbench is:
# -DCMAKE_PREFIX_PATH=... or -Dhystbench_DIR=...).
build_plugin() {
  local src=$1 build=$2
  shift 2
  cmake -S "$src" -B "$build" -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_COMPILER="$core_compiler" \
        -DCMAKE_CXX_FLAGS="$core_flags" -DCMAKE_MODULE_LINKER_FLAGS="$core_flags" "$@" >/dev/null
  cmake --build "$build" >/dev/null
}
