#!/usr/bin/env bash
# Installs the Debian packages hystbench needs, and only those that are missing.
# As root it installs them (running `apt-get update` first, because a fresh
# machine may have no package lists); otherwise it prints the command to run.
set -euo pipefail

packages=(cmake g++ make libeigen3-dev libnlopt-cxx-dev nlohmann-json3-dev
          libcli11-dev libgtest-dev libbenchmark-dev gnuplot-nox
          libopenmpi-dev openmpi-bin)

missing=()
for p in "${packages[@]}"; do
  status=$(dpkg-query -W -f='${Status}' "$p" 2>/dev/null || true)
  [[ "$status" == "install ok installed" ]] || missing+=("$p")
done

if [[ ${#missing[@]} -eq 0 ]]; then
  exit 0
fi

if [[ $(id -u) -ne 0 ]]; then
  echo "hystbench needs these Debian packages: ${missing[*]}" >&2
  echo "Install them with:" >&2
  echo "  sudo apt-get update && sudo apt-get install -y ${missing[*]}" >&2
  exit 1
fi

echo "Installing missing packages: ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
apt-get update -qq
apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
echo "Packages installed."
