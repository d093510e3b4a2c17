#!/usr/bin/env bash
# Builds and runs apse's whole test suite (the README's second Quick-start command; .ci/run runs
# exactly this). Installs missing Debian packages first. Builds, each into build/<name>:
#   release : g++, Release, all tests + consumer tests (find_package / add_subdirectory /
#             FetchContent) + the nvcc device-compile test + benchmark smoke runs + the Mitsuba 3
#             plugin tests (venv with the pinned wheels in build/release/mitsuba3) + the Doxygen
#             API reference (warnings are errors)
#   sanitize: g++, Debug, AddressSanitizer + UndefinedBehaviorSanitizer
#   clang   : clang++, Release, plus libFuzzer runs from the committed corpora (85 s in all)
#   fastmath: g++ -O3 -ffast-math -fno-finite-math-only: the cosine-weighted, robustness (except denormal
#             arguments, flushed to zero), statistics and fuzz-corpus tests
#   fma-nosimd: g++ -march=x86-64-v3 (FMA contraction on) with APSE_NO_SIMD (the scalar pairs):
#             the whole suite
#   aarch64 : g++-aarch64-linux-gnu cross build, run under qemu-user: every test except the
#             statistical ones (chi-square, unbiasedness, stratification: minutes each under qemu)
# Prints "N passed, N failed" over all builds at the end; exits non-zero on any failure.
set -euo pipefail
cd "$(dirname "$0")/.."
. tools/deps.sh
apse_install_deps "${APSE_BASE_PACKAGES[@]}" clang libclang-rt-14-dev libboost-math-dev \
  g++-aarch64-linux-gnu qemu-user doxygen
# the Mitsuba 3 tests (release build) make a venv: Debian's python3 needs python3-venv for that
python3 -c 'import venv, ensurepip' 2>/dev/null || apse_install_deps python3 python3-venv

jobs=${APSE_JOBS:-2}
passed=0
failed=0

run_build() {  # run_build <name> <cmake args...>
  local name=$1; shift
  echo "== [$name] configure"
  cmake -S . -B "build/$name" -G Ninja -DAPSE_BUILD_EXAMPLES=ON "$@" > "build/$name.configure.log" 2>&1 \
    || { cat "build/$name.configure.log"; return 1; }
  echo "== [$name] build"
  cmake --build "build/$name" -j "$jobs"
  echo "== [$name] test"
  local log="build/$name.ctest.log"
  (cd "build/$name" && ctest -j "$jobs" --output-on-failure) 2>&1 | tee "$log" || true
  local line total nfail
  line=$(grep -E "tests passed, [0-9]+ tests failed out of [0-9]+" "$log" | tail -n1 || true)
  total=$(sed -E 's/.* out of ([0-9]+).*/\1/' <<<"$line")
  nfail=$(sed -E 's/.* ([0-9]+) tests failed.*/\1/' <<<"$line")
  if [ -z "$line" ]; then total=0; nfail=1; fi
  passed=$((passed + total - nfail))
  failed=$((failed + nfail))
  return 0
}

mkdir -p build
start=$(date +%s)
run_build release -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_COMPILER=g++ -DAPSE_TEST_MITSUBA=ON -DAPSE_BUILD_DOCS=ON
cat build/release/mitsuba3/skipped.txt 2>/dev/null || true  # why the Mitsuba 3 tests were skipped
run_build sanitize -DCMAKE_BUILD_TYPE=Debug -DCMAKE_CXX_COMPILER=g++ \
  "-DCMAKE_CXX_FLAGS=-fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer" \
  -DAPSE_TEST_CONSUMERS=OFF -DAPSE_TEST_CUDA=OFF -DAPSE_BUILD_BENCHMARKS=OFF
run_build clang -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_COMPILER=clang++ -DAPSE_BUILD_FUZZERS=ON \
  -DAPSE_TEST_CONSUMERS=OFF -DAPSE_TEST_CUDA=OFF
run_build fastmath -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_COMPILER=g++ \
  "-DCMAKE_CXX_FLAGS=-O3 -ffast-math -fno-finite-math-only" \
  "-DAPSE_TEST_SPEC=[robust]~[denormals]~[extreme],[robustness],[chi2],[unbiased],[mc],[cosine]" -DAPSE_TEST_CONSUMERS=OFF \
  -DAPSE_TEST_CUDA=OFF -DAPSE_BUILD_BENCHMARKS=OFF -DAPSE_BUILD_EXAMPLES=OFF
if grep -qw avx2 /proc/cpuinfo && grep -qw fma /proc/cpuinfo; then
  run_build fma-nosimd -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_COMPILER=g++ \
    "-DCMAKE_CXX_FLAGS=-march=x86-64-v3 -ffp-contract=fast -DAPSE_NO_SIMD" -DAPSE_TEST_CONSUMERS=OFF \
    -DAPSE_TEST_CUDA=OFF -DAPSE_BUILD_BENCHMARKS=OFF -DAPSE_BUILD_EXAMPLES=OFF
else
  echo "== [fma-nosimd] skipped: this CPU lacks AVX2/FMA, so -march=x86-64-v3 binaries cannot run here"
fi
run_build aarch64 -DCMAKE_BUILD_TYPE=Release -DCMAKE_TOOLCHAIN_FILE=cmake/aarch64-linux-gnu.cmake \
  "-DAPSE_TEST_SPEC=~[chi2]~[unbiased]~[mc]~[stratification]" -DAPSE_TEST_CONSUMERS=OFF \
  -DAPSE_TEST_CUDA=OFF -DAPSE_BUILD_BENCHMARKS=OFF -DAPSE_BUILD_EXAMPLES=OFF
echo "== all builds done in $(( $(date +%s) - start )) s"
echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
