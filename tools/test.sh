#!/usr/bin/env bash
# Builds and runs apse's tests (the README's second Quick-start command). Installs the Debian
# packages it misses first (timed apart from the builds). Each configuration is a CMake preset
# (CMakePresets.json says what it builds and which CTest labels it runs), built into
# build/<preset>:
#   bash tools/test.sh        the quick suite, preset dev: g++ Release — the unit and statistical
#                             tests, the examples that guard the README, the fuzz corpus replays
#                             and the source checks (~4 minutes on 2 cores from a clean clone)
#   bash tools/test.sh --all  the full matrix, what CI runs (.ci/run):
#     release   : g++ Release, every test: + the build matrix (self-contained headers, GLM's
#                 configuration macros, rejected input, -fno-exceptions), the consumer projects
#                 (find_package / add_subdirectory / FetchContent), the nvcc device-compile test,
#                 the Mitsuba 3 plugin tests (venv with the pinned wheels in build/release/mitsuba3),
#                 the Doxygen API reference (warnings are errors), benchmark smoke runs
#     sanitize  : g++ Debug, AddressSanitizer + UndefinedBehaviorSanitizer: unit tests, fuzz
#                 replays, examples
#     clang     : clang++ Release against Catch2 3, built from Debian's source package by
#                 tools/catch2_v3.sh (Debian 12 ships Catch2 2): unit and statistical tests,
#                 fuzz replays, libFuzzer runs from the corpora (105 s)
#     fastmath  : g++ -O3 -ffast-math -fno-finite-math-only: robustness (except denormal
#                 arguments, flushed to zero), statistics, cosine-weighted, fuzz replays
#     fma-nosimd: g++ -march=x86-64-v3 (FMA contraction) with APSE_NO_SIMD (the scalar pairs):
#                 unit tests, fuzz replays
#     aarch64   : g++-aarch64-linux-gnu cross build run under qemu-user: unit tests, fuzz replays
# Prints configure / build / test seconds per configuration and ends with "N passed, N failed"
# over all of them; exits non-zero on any failure. APSE_JOBS sets the parallelism (default 2).
set -euo pipefail
cd "$(dirname "$0")/.."

all=0
case "${1:-}" in
  "") ;;
  --all) all=1 ;;
  *) echo "usage: bash tools/test.sh [--all]" >&2; exit 2 ;;
esac

. tools/deps.sh
t0=$(date +%s)
# python3, python3-mpmath: the source checks; libclang-rt-14-dev: FuzzedDataProvider.h for the
# fuzz corpus replays
packages=("${APSE_BASE_PACKAGES[@]}" python3 python3-mpmath libclang-rt-14-dev)
if [ "$all" -eq 1 ]; then
  packages+=(clang libboost-math-dev g++-aarch64-linux-gnu qemu-user doxygen curl)
fi
apse_install_deps "${packages[@]}"
if [ "$all" -eq 1 ]; then
  # the Mitsuba 3 tests (release) make a venv: Debian's python3 needs python3-venv for that
  python3 -c 'import venv, ensurepip' 2>/dev/null || apse_install_deps python3-venv
fi
echo "== packages checked/installed in $(( $(date +%s) - t0 )) s"

jobs=${APSE_JOBS:-2}
passed=0
failed=0
summary=()

run_preset() {  # run_preset <preset>: configure, build, test; adds to the totals
  local name=$1 log="build/$1.ctest.log" t1 t2 t3 t4
  t1=$(date +%s)
  echo "== [$name] configure"
  cmake --preset "$name" > "build/$name.configure.log" 2>&1 || { cat "build/$name.configure.log"; return 1; }
  t2=$(date +%s)
  echo "== [$name] build"
  cmake --build --preset "$name" -j "$jobs"
  t3=$(date +%s)
  echo "== [$name] test"
  ctest --preset "$name" -j "$jobs" 2>&1 | tee "$log" || true
  t4=$(date +%s)
  local line total nfail
  line=$(grep -E "tests passed, [0-9]+ tests failed out of [0-9]+" "$log" | tail -n1 || true)
  total=$(sed -E 's/.* out of ([0-9]+).*/\1/' <<<"$line")
  nfail=$(sed -E 's/.* ([0-9]+) tests failed.*/\1/' <<<"$line")
  if [ -z "$line" ]; then total=0; nfail=1; fi
  passed=$((passed + total - nfail))
  failed=$((failed + nfail))
  summary+=("$(printf '%-10s configure %4d s, build %4d s, test %4d s: %d passed, %d failed' \
    "$name" $((t2 - t1)) $((t3 - t2)) $((t4 - t3)) $((total - nfail)) "$nfail")")
  return 0
}

mkdir -p build
start=$(date +%s)
if [ "$all" -eq 0 ]; then
  run_preset dev
else
  run_preset release
  cat build/release/mitsuba3/skipped.txt 2>/dev/null || true  # why the Mitsuba 3 tests were skipped
  run_preset sanitize
  t=$(date +%s)
  bash tools/catch2_v3.sh
  summary+=("$(printf '%-10s built from source in %d s (tools/catch2_v3.sh)' "Catch2 3" $(( $(date +%s) - t )))")
  run_preset clang
  run_preset fastmath
  if grep -qw avx2 /proc/cpuinfo && grep -qw fma /proc/cpuinfo; then
    run_preset fma-nosimd
  else
    echo "== [fma-nosimd] skipped: this CPU lacks AVX2/FMA, so -march=x86-64-v3 binaries cannot run here"
  fi
  run_preset aarch64
fi
echo "== per configuration:"
printf '   %s\n' "${summary[@]}"
echo "== all builds done in $(( $(date +%s) - start )) s"
echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
