// default_table() called concurrently from several threads (scenes loaded on worker threads):
// every thread gets the same object, fully built — equal, bit for bit, to a table built here by
// build() (deterministic) — and a second build() rewrites the same values. Built normally and,
// where possible, with -fsanitize=thread (test default_table_threads_tsan), which fails on a
// data race in the first calls. Returns non-zero on failure.
#include <apse/comparison.hpp>
#include <apse/maps/tabulated_ld_radial.hpp>

#include <cstdio>
#include <cstring>
#include <memory>
#include <thread>
#include <vector>

int main() {
    constexpr int kThreads = 8;
    const apse::TabulationTable* seen[kThreads] = {};
    bool equal[kThreads] = {};
    const auto reference = std::make_unique<apse::TabulationTable>();
    reference->build();
    std::vector<std::thread> threads;
    for (int t = 0; t < kThreads; ++t)
        threads.emplace_back([&, t] {
            const apse::TabulationTable& table = apse::default_table();
            seen[t] = &table;
            equal[t] = std::memcmp(table.cdf, reference->cdf, sizeof(table.cdf)) == 0;
        });
    for (std::thread& th : threads) th.join();
    bool ok = true;
    for (int t = 0; t < kThreads; ++t) ok = ok && seen[t] == &apse::default_table() && equal[t];
    const auto twice = std::make_unique<apse::TabulationTable>();
    twice->build();
    twice->build();
    const bool idempotent = std::memcmp(twice->cdf, reference->cdf, sizeof(twice->cdf)) == 0;
    std::printf("default_table() from %d threads: %s; build() twice: %s\n", kThreads,
                ok ? "one object, equal contents" : "FAILED", idempotent ? "same contents" : "FAILED");
    return ok && idempotent ? 0 : 1;
}
