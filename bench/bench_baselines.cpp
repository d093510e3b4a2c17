// Benchmarks of the rectangle and Gamito baselines: cost per fresh shading point (set-up + one
// sample), float and double, over a fixed seeded set of disk configurations (unit disk, shading
// points 0.1–1000 radii from the centre, log-uniform; directions and normals uniform on the
// sphere). Uniform-by-area sampling of the same disks is measured in the same run as the cost
// floor. Counters: accepted = fraction of calls that return a sample (pdf > 0).
//   bench_baselines --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
#include <apse/baselines/area.hpp>
#include <apse/baselines/gamito.hpp>
#include <apse/baselines/rectangle.hpp>

#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdint>
#include <vector>

namespace {

template <class T> struct Scene {
    using vec3 = glm::vec<3, T>;
    struct Disk {
        vec3 o, c, n, half_x, half_y;  // half edges of the circumscribed square (rectangle bench)
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
            const glm::dvec3 o = c + dist * dir;
            glm::dvec3 yd = (c - o) - glm::dot(c - o, n) * n;
            yd = glm::length(yd) > 1e-12 ? glm::normalize(yd) : glm::normalize(glm::cross(n, glm::dvec3(0.6, 0.8, 0)));
            const glm::dvec3 xd = glm::cross(yd, n);
            disks.push_back({vec3(o), vec3(c), vec3(n), vec3(xd), vec3(yd), T(1)});
        }
        for (int i = 0; i < 4096; ++i) u.emplace_back(T(next()), T(next()));
    }
};

template <class T> const Scene<T>& scene() {
    static const Scene<T> s;
    return s;
}

template <class T, class Make>
void run(benchmark::State& state, Make&& make) {
    const Scene<T>& s = scene<T>();
    std::size_t i = 0, j = 0;
    double accepted = 0;
    for (auto _ : state) {
        const auto& d = s.disks[i];
        const auto sample = make(d).sample(s.u[j]);
        benchmark::DoNotOptimize(sample);
        accepted += sample.pdf > T(0) ? 1.0 : 0.0;
        i = (i + 1) & 1023;
        j = (j + 1) & 4095;
    }
    state.counters["accepted"] = benchmark::Counter(accepted, benchmark::Counter::kAvgIterations);
}

template <class T> void BM_area(benchmark::State& state) {
    run<T>(state, [](const auto& d) { return apse::DiskAreaSampler<T>(d.o, d.c, d.n, d.r); });
}
template <class T> void BM_rectangle(benchmark::State& state) {
    run<T>(state, [](const auto& d) {
        return apse::SphericalRectangle<T>::from_center(d.o, d.c, d.r * d.half_x, d.r * d.half_y);
    });
}
template <class T> void BM_gamito_single_shot(benchmark::State& state) {
    run<T>(state, [](const auto& d) { return apse::GamitoSingleShot<T>(d.o, d.c, d.n, d.r); });
}
template <class T> void BM_gamito_retry8(benchmark::State& state) {
    run<T>(state, [](const auto& d) { return apse::GamitoRetry<T>(d.o, d.c, d.n, d.r, 8); });
}

}  // namespace

BENCHMARK_TEMPLATE(BM_area, float);
BENCHMARK_TEMPLATE(BM_area, double);
BENCHMARK_TEMPLATE(BM_rectangle, float);
BENCHMARK_TEMPLATE(BM_rectangle, double);
BENCHMARK_TEMPLATE(BM_gamito_single_shot, float);
BENCHMARK_TEMPLATE(BM_gamito_single_shot, double);
BENCHMARK_TEMPLATE(BM_gamito_retry8, float);
BENCHMARK_TEMPLATE(BM_gamito_retry8, double);

BENCHMARK_MAIN();
