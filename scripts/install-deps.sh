#!/usr/bin/env bash
# Installs the Debian packages hystbench needs, and only those that are missing.
# As root it installs them (running `apt-get update` first, because a fresh
# machine may have no package lists); otherwise it prints the command to run.
set -euo pipefail

packages=(cmake g++ make libeigen3-dev libnlopt-cxx-dev nlohmann-json3-dev
          libcli11-dev libgtest-dev libbenchmark-dev gnuplot-nox
          libopenmpi-dev openmpi-bin libsvm-dev libmatio-dev
          pybind11-dev python3-dev python3-numpy)
# `install-deps.sh fuzz` (run by scripts/fuzz.sh) adds clang and its libFuzzer
# runtime; `install-deps.sh tsan` (scripts/sanitize.sh tsan) adds clang, its
# sanitizer runtimes and LLVM's OpenMP runtime with the Archer tool.
# `make demo` and `make test` never need them.
case "${1:-}" in
  fuzz) packages+=(clang libclang-rt-14-dev) ;;
  tsan) packages+=(clang libclang-rt-14-dev libomp-14-dev) ;;
esac
# Only the peer comparison with pagmo2 (benchmarks/peer) and robust control
# (framework/robust/, SLICOT: GPL-2+, see the README) need these; the build
# skips what is missing, so failing to get them stops nothing.
optional=(libpagmo-dev libslicot-dev liblapack-dev)

missing_of() {
  for p in "$@"; do
    status=$(dpkg-query -W -f='${Status}' "$p" 2>/dev/null || true)
    [[ "$status" == "install ok installed" ]] || echo "$p"
  done
}
mapfile -t missing < <(missing_of "${packages[@]}")
mapfile -t missing_optional < <(missing_of "${optional[@]}")

if [[ ${#missing[@]} -eq 0 && ${#missing_optional[@]} -eq 0 ]]; then
  exit 0
fi

if [[ $(id -u) -ne 0 ]]; then
  if [[ ${#missing[@]} -eq 0 ]]; then
    echo "Optional, for the peer comparison with pagmo2 and robust control: sudo apt-get install -y ${missing_optional[*]}" >&2
    exit 0
  fi
  echo "hystbench needs these Debian packages: ${missing[*]}" >&2
  echo "Install them with:" >&2
  echo "  sudo apt-get update && sudo apt-get install -y ${missing[*]} ${missing_optional[*]}" >&2
  exit 1
fi

export DEBIAN_FRONTEND=noninteractive
apt-get update -qq
if [[ ${#missing[@]} -gt 0 ]]; then
  echo "Installing missing packages: ${missing[*]}"
  apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi
if [[ ${#missing_optional[@]} -gt 0 ]]; then
  echo "Installing optional packages: ${missing_optional[*]}"
  apt-get install -y -qq --no-install-recommends "${missing_optional[@]}" >/dev/null ||
    echo "Could not install ${missing_optional[*]}: the peer comparison with pagmo2 or robust control will not be built." >&2
fi
echo "Packages installed."
