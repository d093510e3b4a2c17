#!/usr/bin/env bash
# Builds and runs apse's demo (the README's first Quick-start command). Installs missing Debian
# packages first; renders the paper's comparison (3 disk-light scenes × 7 samplers, and a sphere
# light × 5 samplers; ~1 minute on 2 cores) and prints where the pictures and the table were written.
#   bash tools/demo.sh [OUTPUT_DIR] [extra apse_demo options, e.g. --threads 4]
set -euo pipefail
cd "$(dirname "$0")/.."
. tools/deps.sh
apse_install_deps "${APSE_BASE_PACKAGES[@]}"
cmake -S . -B build/demo -G Ninja -DCMAKE_BUILD_TYPE=Release -DAPSE_BUILD_TESTS=OFF \
  -DAPSE_BUILD_BENCHMARKS=OFF -DAPSE_BUILD_EXAMPLES=ON > /dev/null
cmake --build build/demo -j "${APSE_JOBS:-2}" --target apse_minimal apse_demo
out=build/demo/out
if [ $# -gt 0 ] && [[ "$1" != -* ]]; then out="$1"; shift; fi
build/demo/examples/apse_minimal
build/demo/examples/apse_demo --out "$out" "$@"
echo "apse demo: pictures, results.md and convergence.png are in $(cd "$out" && pwd)"
