#!/usr/bin/env bash
# Installs what is missing, builds, and runs the default example: relax a (5,5) nanotube
# as a 2-atom helical cell and print its energy.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
scripts/build.sh
./build/mesochain run examples/cnt55.toml --json build/cnt55-result.json --structure build/cnt55-relaxed
