#!/usr/bin/env bash
# apse's GPU check: builds tests/cuda/runtime_test.cu (device results against the host's) and
# bench/cuda/throughput.cu (samples/s, registers, occupancy) with nvcc for the GPU it finds,
# runs them, and prints a summary ending in "N passed, N failed" (exit code 0 when none failed).
# Needs only nvcc, a C++17 host compiler and GLM's headers: nothing is downloaded or installed.
#
#   tools/gpu_check.sh [--glm DIR] [--arch sm_XX] [--build DIR] [--report FILE] [--archive FILE.tar.gz]
#                      [--jobs N] [--build-timeout S]
#
#   --glm DIR       directory holding glm/vec3.hpp (default: $GLM_INCLUDE_DIR, else the first of
#                   build/gpu-deps, /usr/include, /usr/local/include that has it)
#   --arch sm_XX    GPU architecture (default: -arch=native if nvcc can use it, else sm_90)
#   --build DIR     where binaries and logs go (default: build/gpu_check)
#   --report FILE   also write the summary and every program's output to FILE
#   --archive FILE  also pack the build logs (ptxas -v output included) into FILE (.tar.gz)
#   --jobs N        at most N nvcc processes at a time (default: all 11 at once)
#   --build-timeout S  time limit of each nvcc process (default 280 s)
#
# The translation units are compiled in parallel (8 runtime-test groups, 3 benchmark groups), so
# the build takes about as long as the slowest one. Each step has a time limit; the whole check is
# meant to finish within 5 minutes on a machine with one GPU.
set -u -o pipefail

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
glm=${GLM_INCLUDE_DIR:-}
arch=
build=$root/build/gpu_check
report=
archive=
jobs_max=11
build_timeout=280
while [ $# -gt 0 ]; do
  case $1 in
    --glm) glm=$2; shift 2 ;;
    --arch) arch=$2; shift 2 ;;
    --build) build=$2; shift 2 ;;
    --report) report=$2; shift 2 ;;
    --archive) archive=$2; shift 2 ;;
    --jobs) jobs_max=$2; shift 2 ;;
    --build-timeout) build_timeout=$2; shift 2 ;;
    -h|--help) sed -n '2,24p' "$0"; exit 0 ;;
    *) echo "gpu_check: unknown option $1 (see --help)"; exit 2 ;;
  esac
done

start=$(date +%s)
mkdir -p "$build" || exit 2
summary=$build/summary.md
: > "$summary"
say() { echo "$@" | tee -a "$summary"; }

# --- what the check needs from the system ---------------------------------------------------
if [ -z "$glm" ]; then
  for d in "$root/build/gpu-deps" /usr/include /usr/local/include; do
    if [ -f "$d/glm/vec3.hpp" ]; then glm=$d; break; fi
  done
fi
if [ -z "$glm" ] || [ ! -f "$glm/glm/vec3.hpp" ]; then
  echo "gpu_check: GLM headers not found${glm:+ in $glm}. Pass --glm DIR (or set GLM_INCLUDE_DIR) to a"
  echo "directory holding glm/vec3.hpp, e.g. a copy of /usr/include/glm in build/gpu-deps/glm."
  echo "0 passed, 1 failed"
  exit 1
fi
glm=$(cd "$glm" && pwd)
nvcc=${NVCC:-$(command -v nvcc || true)}
[ -z "$nvcc" ] && [ -x /usr/local/cuda/bin/nvcc ] && nvcc=/usr/local/cuda/bin/nvcc
if [ -z "$nvcc" ]; then
  echo "gpu_check: nvcc not found (set NVCC or put CUDA's bin directory on PATH)"
  echo "0 passed, 1 failed"
  exit 1
fi

say "# apse GPU check"
say ""
commit=unknown
if git -C "$root" rev-parse --short HEAD > /dev/null 2>&1; then
  commit=$(git -C "$root" rev-parse --short HEAD)
  git -C "$root" diff --quiet HEAD -- include tests bench tools 2> /dev/null || commit="$commit (with local changes)"
fi
say "- date: $(date -u '+%Y-%m-%d %H:%M UTC'); commit: $commit"
say "- nvcc: $("$nvcc" --version | tail -1)"
say "- host compiler: $(${CXX:-g++} --version 2>/dev/null | head -1)"
say "- GPU: $(nvidia-smi --query-gpu=name,driver_version,memory.total --format=csv,noheader 2>/dev/null | head -1 || echo 'nvidia-smi unavailable')"
say "- GLM: $glm"

# --- the architecture -------------------------------------------------------------------------
if [ -z "$arch" ]; then
  probe=$build/arch_probe.cu
  echo '__global__ void k() {} int main() { k<<<1, 1>>>(); return 0; }' > "$probe"
  # (without a visible GPU nvcc warns "Cannot find valid GPU" and uses its default: not native)
  if timeout 60 "$nvcc" -arch=native "$probe" -o "$build/arch_probe" > "$build/arch_probe.log" 2>&1 &&
     ! grep -q "Cannot find valid GPU" "$build/arch_probe.log"; then
    arch=native
  else
    arch=sm_90
    say "- -arch=native failed ($(head -1 "$build/arch_probe.log")): falling back to sm_90 (H100/H200)"
  fi
fi
case $arch in native) archflag=-arch=native ;; *) archflag=-arch=$arch ;; esac
say "- architecture: $archflag"
say ""

# --- build: every translation unit in parallel ------------------------------------------------
flags=(-std=c++17 -O3 "$archflag" -Xcompiler -Wall,-Wextra -Xptxas -v -I"$root/include" -I"$glm")
build_one() {  # name source define
  local name=$1 src=$2 def=$3
  rm -f "$build/$name" "$build/$name.build.rc" "$build/$name.out"
  while [ "$(jobs -rp | wc -l)" -ge "$jobs_max" ]; do wait -n; done
  ( s=$(date +%s.%N)
    timeout "$build_timeout" "$nvcc" "${flags[@]}" "$def" "$src" -o "$build/$name" > "$build/$name.build.log" 2>&1
    rc=$?
    e=$(date +%s.%N)
    echo "$rc $(awk -v a="$s" -v b="$e" 'BEGIN { printf "%.1f", b - a }')" > "$build/$name.build.rc" ) &
}
rt_groups=8
bench_groups=3
for g in $(seq 0 $((rt_groups - 1))); do build_one "runtime_test_g$g" "$root/tests/cuda/runtime_test.cu" "-DAPSE_RT_GROUP=$g"; done
for g in $(seq 0 $((bench_groups - 1))); do build_one "throughput_g$g" "$root/bench/cuda/throughput.cu" "-DAPSE_BENCH_GROUP=$g"; done
wait
build_end=$(date +%s)

passed=0
failed=0
say "## Build ($((build_end - start)) s wall, translation units in parallel)"
say ""
say "| program | nvcc s | result |"
say "|---|---|---|"
names=()
for g in $(seq 0 $((rt_groups - 1))); do names+=("runtime_test_g$g"); done
for g in $(seq 0 $((bench_groups - 1))); do names+=("throughput_g$g"); done
for n in "${names[@]}"; do
  rc=missing secs=-
  [ -f "$build/$n.build.rc" ] && read -r rc secs < "$build/$n.build.rc"
  if [ "$rc" = 0 ]; then r=ok; passed=$((passed + 1)); else r="FAILED (rc $rc, $build/$n.build.log)"; failed=$((failed + 1)); fi
  say "| $n | $secs | $r |"
done
say ""

# --- ptxas: registers, stack and spills per kernel ----------------------------------------------
say "## Kernels (ptxas -v): registers, stack frame, spills"
say ""
say "| program | kernel | regs | stack B | spill stores B | spill loads B |"
say "|---|---|---|---|---|---|"
demangle() { if command -v c++filt > /dev/null; then c++filt; else cat; fi; }
spilling=0
for n in "${names[@]}"; do
  awk -v prog="$n" '
    /Compiling entry function/ { match($0, /function .[^ ]*. for/); fn = substr($0, RSTART + 10, RLENGTH - 15); entry = 1; next }
    entry && /bytes stack frame/ { stack = $1; stores = $5; loads = $9; next }
    entry && /Used [0-9]+ registers/ { match($0, /Used [0-9]+ registers/); regs = substr($0, RSTART + 5, RLENGTH - 15);
      printf "%s\t%s\t%s\t%s\t%s\t%s\n", prog, fn, regs, stack, stores, loads; entry = 0 }
  ' "$build/$n.build.log" 2>/dev/null
done > "$build/kernels.tsv"
while IFS=$'\t' read -r prog fn regs stack stores loads; do
  short=$(echo "$fn" | demangle | sed -e 's/(anonymous namespace):://g' -e 's/apse_rt:://g' -e 's/(.*//' | cut -c1-110)
  say "| $prog | \`$short\` | $regs | $stack | $stores | $loads |"
  [ "${stores:-0}" != 0 ] && spilling=$((spilling + 1))
done < "$build/kernels.tsv"
say ""
say "kernels with spill stores: $spilling of $(wc -l < "$build/kernels.tsv") (a spill is reported, not failed)"
say ""

# --- run -----------------------------------------------------------------------------------------
say "## Runtime test (device against host)"
say ""
for g in $(seq 0 $((rt_groups - 1))); do
  n=runtime_test_g$g
  [ -x "$build/$n" ] || continue
  timeout 120 "$build/$n" > "$build/$n.out" 2>&1
  rc=$?
  cat "$build/$n.out"
  last=$(grep -E '^[0-9]+ passed, [0-9]+ failed$' "$build/$n.out" | tail -1)
  if [ "$rc" = 77 ]; then
    say "$n: skipped (no CUDA device): counted as failed, the check needs a GPU"
    failed=$((failed + 1))
  elif [ -n "$last" ]; then
    p=${last%% passed*}
    f=${last#*, }
    f=${f%% failed}
    passed=$((passed + p))
    failed=$((failed + f))
    [ "$rc" != 0 ] && [ "$f" = 0 ] && failed=$((failed + 1))
    say "$n: $last (rc $rc)"
  else
    say "$n: no result (rc $rc; $build/$n.out)"
    failed=$((failed + 1))
  fi
done
say ""
say "## Throughput"
say ""
for g in $(seq 0 $((bench_groups - 1))); do
  n=throughput_g$g
  [ -x "$build/$n" ] || continue
  timeout 150 "$build/$n" > "$build/$n.out" 2>&1
  rc=$?
  if [ "$rc" = 0 ]; then passed=$((passed + 1)); else failed=$((failed + 1)); fi
  say "### $n (rc $rc)"
  say ""
  tee -a "$summary" < "$build/$n.out"
  say ""
done

end=$(date +%s)
say "total: $((end - start)) s"
if [ -n "$report" ]; then
  { cat "$summary"; echo; echo "## Runtime test output"; echo; for g in $(seq 0 $((rt_groups - 1))); do
      echo "### runtime_test_g$g"; echo '```'; cat "$build/runtime_test_g$g.out" 2>/dev/null; echo '```'; done; } > "$report"
fi
if [ -n "$archive" ]; then
  tar -czf "$archive" -C "$build" $(cd "$build" && ls *.log *.out *.tsv summary.md 2>/dev/null)
fi
echo
echo "$passed passed, $failed failed"
[ "$failed" = 0 ]
