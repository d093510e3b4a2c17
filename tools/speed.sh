#!/usr/bin/env bash
# The sampler speed table of docs/speed.md, robust to code layout: builds bench_samplers and its
# three layout variants (bench/CMakeLists.txt: functions aligned to 32, 64, 128 bytes) in a Release
# build, runs each on the disk rows (medians of interleaved repetitions; the sphere rows have a run
# of their own: docs/speed.md#sphere-lights), and prints the table of the median ratio
# over the four layouts, their spread, the cost breakdown and docs/cosine_weighted.md's cost table
# (tools/bench_table.py; docs/speed.md#regenerate writes them into the pages).
#
#   bash tools/speed.sh [BUILD_DIR] [REPETITIONS]     (default build/release, 11; ~10 minutes)
#
# Run it on an otherwise idle machine: every ratio is still measured within one run, but a busy
# machine shifts them.
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build/release}
reps=${2:-11}
if [ ! -f "$build/CMakeCache.txt" ]; then
  cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DAPSE_TEST_CUDA=OFF -DAPSE_TEST_CONSUMERS=OFF >&2
fi
targets=(bench_samplers bench_samplers_align32 bench_samplers_align64 bench_samplers_align128)
cmake --build "$build" --target "${targets[@]}" >&2
out="$build/speed"
mkdir -p "$out"
for t in "${targets[@]}"; do
  echo "== $t" >&2
  "$build/bench/$t" --benchmark_filter='-^sphere_' --benchmark_repetitions="$reps" --benchmark_report_aggregates_only=true \
    --benchmark_min_time=0.1 --benchmark_enable_random_interleaving=true --benchmark_format=json \
    > "$out/$t.json"
done
python3 tools/bench_table.py $(printf "$out/%s.json " "${targets[@]}")
