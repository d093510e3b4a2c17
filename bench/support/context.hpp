// Benchmark context shared by apse's benchmarks: what tools/bench_table.py prints above its tables.
#pragma once

#include <benchmark/benchmark.h>

#include <fstream>
#include <string>

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

}  // namespace apse_bench
