#!/usr/bin/env bash
# Installs what is missing, builds only the program (the `mesochain` target, not the tests),
# and runs the default example: relax a (5,5) nanotube as a 2-atom helical cell and print its
# energy. scripts/test.sh builds the rest.
set -euo pipefail
cd "$(dirname "$0")/.."
echo "demo: 1/3 installing missing Debian packages of the program (scripts/install-deps.sh --program-only)"
scripts/install-deps.sh --program-only
echo "demo: 2/3 building the mesochain program only, without the tests (scripts/build.sh mesochain)"
start=$(date +%s)
MESOCHAIN_BUILD_TESTS=OFF scripts/build.sh mesochain
echo "demo: built in $(( $(date +%s) - start )) s"
echo "demo: 3/3 relaxing the (5,5) nanotube of examples/cnt55.toml"
echo "      ./build/mesochain run examples/cnt55.toml --json build/cnt55-result.json --structure build/cnt55-relaxed"
./build/mesochain run examples/cnt55.toml --json build/cnt55-result.json --structure build/cnt55-relaxed
echo "demo: done; results in build/cnt55-result.json, structure in build/cnt55-relaxed.xyz and .gen"
