#!/usr/bin/env bash
# Installs, with apt-get, the Debian packages mesochain needs to build and test.
# Only packages that are missing are installed; run as root on Debian 12 (bookworm).
set -euo pipefail
# --program-only: what the program needs (scripts/demo.sh), without the Python, MPI and test packages.
packages=(
  g++ cmake ninja-build pkg-config
  libeigen3-dev liblapack-dev libopenblas-dev liblapacke-dev
  libxc-dev
  libtoml11-dev libcli11-dev nlohmann-json3-dev libfmt-dev
  libpng-dev
)
# Beyond the program (scripts/demo.sh builds without them; CMake finds them when present): the
# Python module and its tests, MPI over k-points and scan points (docs/cluster.md), the test-only
# libraries (scripts/test.sh).
full_packages=(
  python3-dev pybind11-dev python3-numpy python3-pytest python3-ase
  libopenmpi-dev openmpi-bin
  libfftw3-dev libgtest-dev
)
[ "${1:-}" = "--program-only" ] || packages+=("${full_packages[@]}")
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "install-deps: installing ${missing[*]}"
  SUDO=""
  [ "$(id -u)" -eq 0 ] || SUDO="sudo"
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
else
  echo "install-deps: all packages present"
fi
