#!/usr/bin/env bash
# Installs, with apt-get, the Debian packages mesochain needs to build and test.
# Only packages that are missing are installed; run as root on Debian 12 (bookworm).
set -euo pipefail
# --program-only: what the program needs (scripts/demo.sh), without the test-only packages.
packages=(
  g++ cmake ninja-build pkg-config
  libeigen3-dev liblapack-dev libopenblas-dev liblapacke-dev
  libxc-dev
  libtoml11-dev libcli11-dev nlohmann-json3-dev libfmt-dev
  libpng-dev
  python3-dev pybind11-dev python3-numpy python3-pytest python3-ase
  libopenmpi-dev openmpi-bin  # MPI over k-points and scan points (docs/cluster.md)
)
test_packages=(libfftw3-dev libgtest-dev)  # tests only (scripts/test.sh)
[ "${1:-}" = "--program-only" ] || packages+=("${test_packages[@]}")
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
