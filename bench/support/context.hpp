// Benchmark context shared by apse's benchmarks: what tools/bench_table.py prints above its tables.
#pragma once

#include <benchmark/benchmark.h>

#include <fstream>
#include <string>

/// A sampler factory's `make` (and the lambdas it calls) is inlined into the timed loop, as a
/// renderer constructs its light sampler inline in its shading code: in a translation unit that
/// instantiates every sampler, GCC's inlining budget would otherwise leave some factories as
/// calls and not others, and a call returns the sampler through memory (a large object is then
/// written and read back per shading point), which measures the harness, not the sampler.
#if defined(__GNUC__)
#define APSE_BENCH_INLINE __attribute__((always_inline)) inline
#define APSE_BENCH_INLINE_LAMBDA __attribute__((always_inline))
#else
#define APSE_BENCH_INLINE inline
#define APSE_BENCH_INLINE_LAMBDA
#endif

namespace apse_bench {

/// The compiler and its version.
inline std::string compiler() {
#if defined(__clang__)
    return std::string("clang++ ") + __clang_version__;
#elif defined(__GNUC__)
    return std::string("g++ ") + __VERSION__;
#else
    return "unknown";
#endif
}

/// The CPU model from /proc/cpuinfo (Linux).
inline std::string cpu_model() {
    std::ifstream in("/proc/cpuinfo");
    std::string line;
    while (std::getline(in, line))
        if (line.rfind("model name", 0) == 0) return line.substr(line.find(':') + 2);
    return "unknown";
}

/// Records compiler, CPU model and whether apse's assertions are on in the JSON context.
inline void add_context() {
    benchmark::AddCustomContext("compiler", compiler());
    benchmark::AddCustomContext("cpu_model", cpu_model());
#if defined(NDEBUG)
    benchmark::AddCustomContext("apse_assertions", "off (NDEBUG)");
#else
    benchmark::AddCustomContext("apse_assertions", "on");
#endif
}

/// The start of every benchmark's main(): parses the command line and records the context
/// (add_context). False if an argument was not recognised (already reported: main returns 1).
inline bool initialize(int& argc, char** argv) {
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv)) return false;
    add_context();
    return true;
}

/// The end of every benchmark's main(): runs the benchmarks the command line selected (shown by
/// `reporter` when given, else by the default console or JSON reporter) and shuts the library down.
inline void run(benchmark::BenchmarkReporter* reporter = nullptr) {
    if (reporter != nullptr) benchmark::RunSpecifiedBenchmarks(reporter);
    else benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
}

}  // namespace apse_bench
