// Benchmarks of the stateless MIS query a renderer makes for a BSDF-sampled direction: the
// light's pdf from the shading point, the light and the direction (disk_light.hpp's
// disk_light_pdf), per map, next to lean area sampling's pdf of the same direction
// (DiskAreaSampler from the light's stored DiskFrame: a ray-disk intersection) and the floor of
// every query, the projection and the containment test — in float and double, in one run.
//
// Two direction sets over the same 1024 seeded shading points (as bench_projection: above,
// below, near and far from a unit disk): "hit", directions the light sampled (every query hits
// the disk: the costly case), and "bsdf", cosine-distributed directions about the +z receiver
// normal, of which most miss the disk (the query returns after the projection).
//
//   bench_mis_query --benchmark_repetitions=11 --benchmark_min_time=0.1
//       --benchmark_enable_random_interleaving=true --benchmark_report_aggregates_only=true
#include <apse/baselines/area.hpp>
#include <apse/apse.hpp>

#include <benchmark/benchmark.h>

#include "support/context.hpp"

#include <array>
#include <cmath>
#include <random>
#include <string>

namespace {

constexpr std::size_t kInputs = 1024;  // a power of two: the index wraps with a mask

template <class T> struct Inputs {
    std::array<glm::vec<3, T>, kInputs> o;     // shading points
    std::array<glm::vec<3, T>, kInputs> hit;   // directions sampled from the light
    std::array<glm::vec<3, T>, kInputs> bsdf;  // cosine-distributed about +z
    double hit_fraction_bsdf = 0;              // of the bsdf directions
};

template <class T> const Inputs<T>& inputs() {
    static const Inputs<T> in = [] {
        Inputs<T> r{};
        std::mt19937_64 rng(20170619);
        std::uniform_real_distribution<double> u(0.0, 1.0);
        const glm::vec<3, T> c(0), n(0, 0, 1);
        int hits = 0;
        for (std::size_t i = 0; i < kInputs; ++i) {
            // heights from 1e-3 to 1e2 radii (log-uniform), both sides, lateral offsets up to 4 radii
            const double d = 1e-3 * std::pow(1e5, u(rng)) * (u(rng) < 0.8 ? 1 : -1);
            r.o[i] = glm::vec<3, T>(T(8 * u(rng) - 4), T(8 * u(rng) - 4), T(d));
            const glm::vec<2, T> uv(T(u(rng)), T(u(rng)));
            r.hit[i] = apse::DiskLight<apse::LdRadialMap<T>>(r.o[i], c, n, T(1)).sample(uv).direction;
            const double rr = std::sqrt(u(rng)), phi = 6.283185307179586 * u(rng);
            const double z = std::sqrt(1 - rr * rr) * (d > 0 ? -1 : 1);  // the receiver faces the disk
            r.bsdf[i] = glm::vec<3, T>(T(rr * std::cos(phi)), T(rr * std::sin(phi)), T(z));
            hits += apse::disk_light_pdf<apse::LdRadialMap<T>>(r.o[i], c, n, T(1), r.bsdf[i]) > T(0);
        }
        r.hit_fraction_bsdf = double(hits) / kInputs;
        return r;
    }();
    return in;
}

enum class Query { area, projection, exact, tabulated, cosine_tabulated };

template <class T, Query Q> void query(benchmark::State& state, bool hits) {
    const Inputs<T>& in = inputs<T>();
    const auto& dirs = hits ? in.hit : in.bsdf;
    const glm::vec<3, T> c(0), n(0, 0, 1), receiver(0, 0, 1);
    const apse::DiskFrame<T> frame = apse::DiskFrame<T>::make(c, n, T(1));  // stored with the light
    const apse::TabulationView table = apse::default_table().view();
    std::size_t i = 0;
    for (auto _ : state) {
        T p;
        if (Q == Query::area) p = apse::DiskAreaSampler<T>(in.o[i], frame).pdf(dirs[i]);
        else if (Q == Query::projection) p = apse::project_disk(in.o[i], c, n, T(1)).contains(dirs[i]) ? T(1) : T(0);
        else if (Q == Query::exact) p = apse::disk_light_pdf<apse::LdRadialMap<T>>(in.o[i], c, n, T(1), dirs[i]);
        else if (Q == Query::tabulated)
            p = apse::disk_light_pdf<apse::TabulatedLdRadialMap<T>>(in.o[i], c, n, T(1), dirs[i], table);
        else
            p = apse::disk_light_pdf<apse::CosineWeighted<apse::TabulatedLdRadialMap<T>>>(
                in.o[i], c, n, T(1), dirs[i], table, in.o[i].z > T(0) ? -receiver : receiver);
        benchmark::DoNotOptimize(p);
        i = (i + 1) & (kInputs - 1);
    }
    state.counters["hit_fraction"] = hits ? 1.0 : in.hit_fraction_bsdf;
}

template <class T> void register_all(const char* type) {
    for (const bool hits : {true, false}) {
        const std::string t = std::string(hits ? "/hit<" : "/bsdf<") + type + ">";
        benchmark::RegisterBenchmark(("area_pdf" + t).c_str(), query<T, Query::area>, hits);
        benchmark::RegisterBenchmark(("project_disk+contains" + t).c_str(), query<T, Query::projection>, hits);
        benchmark::RegisterBenchmark(("disk_light_pdf_exact" + t).c_str(), query<T, Query::exact>, hits);
        benchmark::RegisterBenchmark(("disk_light_pdf_tabulated" + t).c_str(), query<T, Query::tabulated>, hits);
        benchmark::RegisterBenchmark(("disk_light_pdf_cosine_tabulated" + t).c_str(), query<T, Query::cosine_tabulated>,
                                     hits);
    }
}

}  // namespace

int main(int argc, char** argv) {
    register_all<float>("float");
    register_all<double>("double");
    if (!apse_bench::initialize(argc, argv)) return 1;
    apse_bench::run();
    return 0;
}
