// Benchmarks of the tabulated maps (TabulatedMap, TabulatedLdRadialMap; default table) per fresh
// shading point — projection + map set-up + 1 sample, and + 16 samples — in float and double,
// next to uniform-by-area sampling (DiskAreaSampler, the cost floor) and the exact RadialMap in
// the same run. The table is built once before timing (shared by all shading points).
// Counter: steps = mean table-walk steps per sample.
// Disks: the seeded set of bench_maps (unit disk, shading points 0.1–1000 radii away).
//   bench_tabulated --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
#include <apse/baselines/area.hpp>
#include <apse/maps/radial.hpp>
#include <apse/maps/tabulated.hpp>
#include <apse/projection.hpp>

#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdint>
#include <memory>
#include <type_traits>
#include <vector>

namespace {

template <class T> struct Scene {
    using vec3 = glm::vec<3, T>;
    struct Disk {
        vec3 o, c, n;
        T r;
    };
    std::vector<Disk> disks;
    std::vector<glm::vec<2, T>> u;

    Scene() {
        std::uint64_t state = 20170619;
        auto next = [&state]() {  // splitmix64
            std::uint64_t z = (state += 0x9e3779b97f4a7c15ULL);
            z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
            z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
            return double((z ^ (z >> 31)) >> 11) * 0x1p-53;
        };
        auto sphere = [&]() {
            const double z = 2 * next() - 1, phi = 6.283185307179586 * next(), s = std::sqrt(1 - z * z);
            return glm::dvec3(s * std::cos(phi), s * std::sin(phi), z);
        };
        for (int i = 0; i < 1024; ++i) {
            const glm::dvec3 c(4 * next() - 2, 4 * next() - 2, 4 * next() - 2);
            const glm::dvec3 n = sphere();
            const double dist = std::pow(10.0, -1 + 4 * next());  // 0.1 .. 1000 radii
            glm::dvec3 dir = sphere();
            if (std::fabs(glm::dot(dir, n)) < 1e-3) dir = glm::normalize(dir + 0.01 * n);  // not in the plane
            disks.push_back({vec3(c + dist * dir), vec3(c), vec3(n), T(1)});
        }
        for (int i = 0; i < 4096; ++i) u.emplace_back(T(next()), T(next()));
    }
};

template <class T> const Scene<T>& scene() {
    static const Scene<T> s;
    return s;
}

const apse::TabulationTable& table() {
    static const std::unique_ptr<apse::TabulationTable> t = [] {
        auto p = std::make_unique<apse::TabulationTable>();
        p->build();
        return p;
    }();
    return *t;
}

struct Area {};
struct Radial {};
struct Tabulated {};
struct TabulatedLd {};

template <class T, class M, int Samples> void bm_setup_and_sample(benchmark::State& state) {
    const Scene<T>& s = scene<T>();
    const apse::TabulationView view = table().view();
    std::size_t i = 0, k = 0;
    long steps = 0, samples = 0;
    for (auto _ : state) {
        const auto& d = s.disks[i++ & 1023];
        T acc = T(0);
        if constexpr (std::is_same<M, Area>::value) {
            const apse::DiskAreaSampler<T> area(d.o, d.c, d.n, d.r);
            for (int j = 0; j < Samples; ++j) {
                const auto smp = area.sample(s.u[k++ & 4095]);
                acc += smp.direction.x + smp.pdf;
            }
        } else if constexpr (std::is_same<M, Radial>::value) {
            const apse::RadialMap<T> map(apse::project_disk(d.o, d.c, d.n, d.r));
            for (int j = 0; j < Samples; ++j) {
                const auto smp = map.sample(s.u[k++ & 4095]);
                acc += smp.direction.x + smp.pdf;
            }
        } else if constexpr (std::is_same<M, Tabulated>::value) {
            const apse::TabulatedMap<T> map(apse::project_disk(d.o, d.c, d.n, d.r), view);
            for (int j = 0; j < Samples; ++j) {
                int it = 0;
                const auto smp = map.sample(s.u[k++ & 4095], it);
                steps += it;
                acc += smp.direction.x + smp.pdf;
            }
            samples += Samples;
        } else {
            const apse::TabulatedLdRadialMap<T> map(apse::project_disk(d.o, d.c, d.n, d.r), view);
            for (int j = 0; j < Samples; ++j) {
                int it = 0;
                const auto smp = map.sample(s.u[k++ & 4095], it);
                steps += it;
                acc += smp.direction.x + smp.pdf;
            }
            samples += Samples;
        }
        benchmark::DoNotOptimize(acc);
    }
    if (samples > 0) state.counters["steps"] = benchmark::Counter(double(steps) / double(samples));
}

}  // namespace

#define APSE_BENCH_ALL(T)                                                  \
    BENCHMARK_TEMPLATE(bm_setup_and_sample, T, Area, 1);                   \
    BENCHMARK_TEMPLATE(bm_setup_and_sample, T, Radial, 1);                 \
    BENCHMARK_TEMPLATE(bm_setup_and_sample, T, Tabulated, 1);              \
    BENCHMARK_TEMPLATE(bm_setup_and_sample, T, TabulatedLd, 1);            \
    BENCHMARK_TEMPLATE(bm_setup_and_sample, T, Area, 16);                  \
    BENCHMARK_TEMPLATE(bm_setup_and_sample, T, Radial, 16);                \
    BENCHMARK_TEMPLATE(bm_setup_and_sample, T, Tabulated, 16);             \
    BENCHMARK_TEMPLATE(bm_setup_and_sample, T, TabulatedLd, 16)

APSE_BENCH_ALL(float);
APSE_BENCH_ALL(double);

BENCHMARK_MAIN();
