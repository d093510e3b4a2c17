#!/usr/bin/env bash
# Builds and runs apse's demo (the README's first Quick-start command). Installs missing Debian
# packages first; prints where the pictures and tables were written.
set -euo pipefail
cd "$(dirname "$0")/.."
. tools/deps.sh
apse_install_deps "${APSE_BASE_PACKAGES[@]}" libstb-dev
cmake -S . -B build/demo -G Ninja -DCMAKE_BUILD_TYPE=Release -DAPSE_BUILD_TESTS=OFF \
  -DAPSE_BUILD_BENCHMARKS=OFF -DAPSE_BUILD_EXAMPLES=ON > /dev/null
cmake --build build/demo -j "${APSE_JOBS:-2}"
for example in build/demo/examples/apse_*; do
  [ -x "$example" ] && "$example" "$@"
done
