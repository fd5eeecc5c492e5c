#!/usr/bin/env bash
# Installs the Debian 12 packages mms needs, only those that are missing. Idempotent; run as root.
set -euo pipefail

packages=(
  cmake g++ make
  clang libclang-rt-14-dev
  libcgal-dev libgmp-dev libmpfr-dev
  libboost-graph-dev libboost-filesystem-dev libeigen3-dev
  libompl-dev
  nlohmann-json3-dev libcli11-dev
  libgtest-dev googletest libbenchmark-dev
  librsvg2-bin
  libpugixml-dev libpng-dev
  libjemalloc-dev
  chromium
  libjs-three
  ompl-demos
  pybind11-dev python3-dev python3-pytest
)

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed'; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "setup: all ${#packages[@]} packages present"
  exit 0
fi

if [ "$(id -u)" -ne 0 ]; then
  echo "setup: missing packages: ${missing[*]}; run this script as root (or install them)" >&2
  exit 1
fi

echo "setup: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
apt-get update -qq
apt-get install -y -qq --no-install-recommends "${missing[@]}"
