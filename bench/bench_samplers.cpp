// apse's sampler benchmark: every disk sampler, per fresh shading point — set-up (projection +
// map, or the baseline's own set-up) + 1 sample, and set-up + 16 samples — in float and double,
// over the same 1024 seeded disk configurations and the same points of the square
// (support/disk_configs.hpp). The reference is lean area sampling (DiskAreaSampler built from the
// light's stored DiskFrame, as a renderer keeps it: per shading point only c − o); "area_frame_
// per_point" is the same sampler building the frame at every shading point. Compare ratios to
// the reference measured in the same run, never absolute times. Timing goals live here, never in
// tests.
//
// Sphere lights (tools/bench_table.py's sphere table): the same measurements over 1024 seeded
// sphere lights (support/sphere_configs.hpp: shading points 1.05–50 radii from the centre), named
// sphere_<sampler>/<type>/<samples>. Their reference is pbrt-v4's sphere-light sampling (the
// direction part of Sphere::Sample: the cone the sphere subtends, sampled uniformly in a frame
// built per shading point, as pbrt does), "sphere_cone"; "sphere_cone_point" adds the point on the
// sphere and its distance, the reference of the SphereLight rows. The cosine-weighted rows come in
// two sets of receivers: the cap above the horizon (…_above) and cut by it (…_cut). Every sphere
// factory, the reference's and apse's alike, is inlined into the timed loop (APSE_BENCH_INLINE,
// support/context.hpp), as a renderer builds its light sampler in its shading code. (The disk
// factories are left to the compiler, as docs/speed.md's disk table was measured.)
//
// Cost breakdown (tools/bench_table.py's second table): <sampler>/<type>/0 is the set-up alone
// (every field of the map kept observable), "projection" is project_disk alone and
// "projection_solid_angle" project_disk + solid_angle; per sample = (set-up + 16 − set-up + 1)/15.
//
// Names: <sampler>/<float|double>/<samples>. Counters (means per sample):
//   accepted   — fraction of samples with pdf > 0 (Gamito's acceptance; 1 for the maps);
//   mean_iterations — inversion iterations (RadialMap, LdRadialMap, ParallelMap) or table-walk
//                     steps (TabulatedMap, TabulatedLdRadialMap), from apse::sample_with_diagnostics
//                     (every sampler is called through it; the counter is reported for the
//                     samplers that count, apse::counts_iterations).
// The JSON context records the compiler and CPU; tools/bench_table.py makes docs/speed.md's tables:
//   bench_samplers --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
//                  --benchmark_min_time=0.2 --benchmark_enable_random_interleaving=true
//                  --benchmark_format=json > samplers.json
//   python3 tools/bench_table.py samplers.json
#include "support/disk_configs.hpp"
#include "support/cone_sampler.hpp"
#include "support/sphere_configs.hpp"

#include <apse/baselines/area.hpp>
#include <apse/baselines/gamito.hpp>
#include <apse/spherical_rectangle.hpp>
#include <apse/cosine_weighted.hpp>
#include <apse/maps/ld_radial.hpp>
#include <apse/maps/parallel.hpp>
#include <apse/comparison.hpp>
#include <apse/maps/tabulated_ld_radial.hpp>
#include <apse/projection.hpp>
#include <apse/runtime_sampler.hpp>
#include <apse/sphere_light.hpp>
#include <apse/diagnostics.hpp>

#include <benchmark/benchmark.h>

#include "support/context.hpp"

#include <string>
#include <type_traits>

namespace {

using apse_bench::DiskConfig;
using apse_bench::DiskConfigs;

// Sampler factories: make(disk, table view) builds the sampler for one shading point.
struct Area {  // the reference: the light's frame stored with the light (DiskConfig::frame)
    static constexpr const char* name = "area";
    template <class T> static auto make(const DiskConfig<T>& d, const apse::TabulationView&) {
        return apse::DiskAreaSampler<T>(d.o, d.frame);
    }
};
struct AreaFramePerPoint {  // the same sampler, its frame rebuilt at every shading point
    static constexpr const char* name = "area_frame_per_point";
    template <class T> static auto make(const DiskConfig<T>& d, const apse::TabulationView&) {
        return apse::DiskAreaSampler<T>(d.o, d.c, d.n, d.r);
    }
};
// Parts of the set-up (cost breakdown only; set-up runs, no samples).
struct Projection {
    static constexpr const char* name = "projection";
    template <class T> static auto make(const DiskConfig<T>& d, const apse::TabulationView&) {
        return apse::project_disk(d.o, d.frame);
    }
};
template <class T> struct EllipseAndSolidAngle {
    apse::SphericalEllipse<T> ellipse;
    T solid_angle;
};
struct ProjectionSolidAngle {
    static constexpr const char* name = "projection_solid_angle";
    template <class T> static auto make(const DiskConfig<T>& d, const apse::TabulationView&) {
        const apse::SphericalEllipse<T> e = apse::project_disk(d.o, d.frame);
        return EllipseAndSolidAngle<T>{e, e.solid_angle()};
    }
};
struct Rectangle {  // the disk's circumscribed square, sampled without rejection
    static constexpr const char* name = "rectangle";
    template <class T> static auto make(const DiskConfig<T>& d, const apse::TabulationView&) {
        return apse::SphericalRectangle<T>::from_center(d.o, d.c, d.r * d.half_x, d.r * d.half_y);
    }
};
struct GamitoSingleShot {
    static constexpr const char* name = "gamito_single_shot";
    template <class T> static auto make(const DiskConfig<T>& d, const apse::TabulationView&) {
        return apse::GamitoSingleShot<T>(d.o, d.c, d.n, d.r);
    }
};
struct GamitoRetry8 {
    static constexpr const char* name = "gamito_retry8";
    template <class T> static auto make(const DiskConfig<T>& d, const apse::TabulationView&) {
        return apse::GamitoRetry<T>(d.o, d.c, d.n, d.r, 8);
    }
};
struct Radial {
    static constexpr const char* name = "radial";
    template <class T> static auto make(const DiskConfig<T>& d, const apse::TabulationView&) {
        return apse::RadialMap<T>(apse::project_disk(d.o, d.frame));
    }
};
struct LdRadial {
    static constexpr const char* name = "ld_radial";
    template <class T> static auto make(const DiskConfig<T>& d, const apse::TabulationView&) {
        return apse::LdRadialMap<T>(apse::project_disk(d.o, d.frame));
    }
};
struct Parallel {
    static constexpr const char* name = "parallel";
    template <class T> static auto make(const DiskConfig<T>& d, const apse::TabulationView&) {
        return apse::ParallelMap<T>(apse::project_disk(d.o, d.frame));
    }
};
struct Tabulated {
    static constexpr const char* name = "tabulated";
    template <class T> static auto make(const DiskConfig<T>& d, const apse::TabulationView& v) {
        return apse::TabulatedMap<T>(apse::project_disk(d.o, d.frame), v);
    }
};
struct TabulatedLdRadial {
    static constexpr const char* name = "tabulated_ld_radial";
    template <class T> static auto make(const DiskConfig<T>& d, const apse::TabulationView& v) {
        return apse::TabulatedLdRadialMap<T>(apse::project_disk(d.o, d.frame), v);
    }
};
// Cosine-weighted samplers: the receiver's normal is the config's half_y (the in-plane direction
// from o's foot point towards the disk's centre; unit): the centre is never below the horizon,
// and nearby disks straddle it.
// Nodes = 0: the default.
template <class Plain, const char* Name, int Nodes = 0> struct Cosine {
    static constexpr const char* name = Name;
    template <class T> static auto make(const DiskConfig<T>& d, const apse::TabulationView& v) {
        using Map = decltype(Plain::make(d, v));
        if constexpr (Nodes == 0) return apse::CosineWeighted<Map>(Plain::make(d, v), d.half_y);
        else return apse::CosineWeighted<Map, Nodes>(Plain::make(d, v), d.half_y);
    }
};
constexpr char cosine_radial[] = "cosine_radial";
constexpr char cosine_ld_radial[] = "cosine_ld_radial";
constexpr char cosine_parallel[] = "cosine_parallel";
constexpr char cosine_tabulated[] = "cosine_tabulated";
constexpr char cosine_tabulated_ld_radial[] = "cosine_tabulated_ld_radial";
constexpr char cosine_tabulated_ld_radial_16[] = "cosine_tabulated_ld_radial_16_nodes";
constexpr char cosine_tabulated_ld_radial_32[] = "cosine_tabulated_ld_radial_32_nodes";

// --- sphere lights ---------------------------------------------------------------------------
using apse_bench::SphereConfig;

// Sphere factories: make(sphere, table view) builds the sampler for one shading point.
struct SphereTag {};
struct SphereCone : SphereTag {
    static constexpr const char* name = "sphere_cone";
    template <class T> APSE_BENCH_INLINE static auto make(const SphereConfig<T>& s, const apse::TabulationView&) {
        return apse_bench::ConeSampler<T, false>(s.o, s.c, s.r);
    }
};
struct SphereConePoint : SphereTag {
    static constexpr const char* name = "sphere_cone_point";
    template <class T> APSE_BENCH_INLINE static auto make(const SphereConfig<T>& s, const apse::TabulationView&) {
        return apse_bench::ConeSampler<T, true>(s.o, s.c, s.r);
    }
};
/// f(v) for the tabulated maps (built with the table), f() for the others.
template <template <class> class Map, class T, class F> APSE_BENCH_INLINE auto with_map_args(const apse::TabulationView& v, F&& f) {
    return apse::detail::with_table_if_read<Map<T>>(v, f);
}
/// project_sphere + Map<T> (the tabulated maps take the table).
template <template <class> class Map, class T>
APSE_BENCH_INLINE Map<T> sphere_map(const SphereConfig<T>& s, const apse::TabulationView& v) {
    return with_map_args<Map, T>(v, [&](const auto&... a) APSE_BENCH_INLINE_LAMBDA { return Map<T>(apse::project_sphere(s.o, s.c, s.r), a...); });
}
template <template <class> class Map, const char* Name> struct SphereMap : SphereTag {
    static constexpr const char* name = Name;
    template <class T> APSE_BENCH_INLINE static auto make(const SphereConfig<T>& s, const apse::TabulationView& v) {
        return sphere_map<Map>(s, v);
    }
};
/// CosineWeighted<Map<T>> for the receiver normal of the configuration with the cap cut by the
/// horizon (Cut) or above it.
template <template <class> class Map, const char* Name, bool Cut> struct SphereCosine : SphereTag {
    static constexpr const char* name = Name;
    template <class T> APSE_BENCH_INLINE static auto make(const SphereConfig<T>& s, const apse::TabulationView& v) {
        return apse::CosineWeighted<Map<T>>(sphere_map<Map>(s, v), Cut ? s.cut : s.above);
    }
};
/// Map<T>::CapSampler built from project_sphere: what SphereLight<Map<T>> samples with (the
/// map's samples on a cap, without its general-ellipse path), direction only.
template <template <class> class Map, const char* Name> struct SphereCapSampler : SphereTag {
    static constexpr const char* name = Name;
    template <class T> APSE_BENCH_INLINE static auto make(const SphereConfig<T>& s, const apse::TabulationView& v) {
        return with_map_args<Map, T>(v, [&](const auto&... a) APSE_BENCH_INLINE_LAMBDA {
            return typename Map<T>::CapSampler(apse::project_sphere(s.o, s.c, s.r), a...);
        });
    }
};
/// SphereLight<Map<T>>: the direction, the point on the sphere and its distance.
template <template <class> class Map, const char* Name> struct SphereLightOf : SphereTag {
    static constexpr const char* name = Name;
    template <class T> APSE_BENCH_INLINE static auto make(const SphereConfig<T>& s, const apse::TabulationView& v) {
        return with_map_args<Map, T>(v, [&](const auto&... a) APSE_BENCH_INLINE_LAMBDA { return apse::SphereLight<Map<T>>(s.o, s.c, s.r, a...); });
    }
};
/// SphereLight<CosineWeighted<Map<T>>> for the receiver normal with the cap cut by the horizon
/// (Cut) or above it.
template <template <class> class Map, const char* Name, bool Cut> struct SphereLightCosine : SphereTag {
    static constexpr const char* name = Name;
    template <class T> APSE_BENCH_INLINE static auto make(const SphereConfig<T>& s, const apse::TabulationView& v) {
        return with_map_args<Map, T>(v, [&](const auto&... a) APSE_BENCH_INLINE_LAMBDA {
            return apse::SphereLight<apse::CosineWeighted<Map<T>>>(s.o, s.c, s.r, a..., Cut ? s.cut : s.above);
        });
    }
};
constexpr char sphere_radial[] = "sphere_radial";
constexpr char sphere_ld_radial[] = "sphere_ld_radial";
constexpr char sphere_parallel[] = "sphere_parallel";
constexpr char sphere_tabulated[] = "sphere_tabulated";
constexpr char sphere_tabulated_ld_radial[] = "sphere_tabulated_ld_radial";
constexpr char sphere_cap_radial[] = "sphere_cap_radial";
constexpr char sphere_cap_ld_radial[] = "sphere_cap_ld_radial";
constexpr char sphere_cap_tabulated[] = "sphere_cap_tabulated";
constexpr char sphere_cap_tabulated_ld_radial[] = "sphere_cap_tabulated_ld_radial";
constexpr char sphere_light_radial[] = "sphere_light_radial";
constexpr char sphere_light_ld_radial[] = "sphere_light_ld_radial";
constexpr char sphere_light_parallel[] = "sphere_light_parallel";
constexpr char sphere_light_tabulated[] = "sphere_light_tabulated";
constexpr char sphere_light_tabulated_ld_radial[] = "sphere_light_tabulated_ld_radial";
constexpr char sphere_light_cosine_ld_radial_above[] = "sphere_light_cosine_ld_radial_above";
constexpr char sphere_light_cosine_ld_radial_cut[] = "sphere_light_cosine_ld_radial_cut";
constexpr char sphere_light_cosine_tabulated_ld_radial_above[] = "sphere_light_cosine_tabulated_ld_radial_above";
constexpr char sphere_light_cosine_tabulated_ld_radial_cut[] = "sphere_light_cosine_tabulated_ld_radial_cut";
constexpr char sphere_cosine_ld_radial_above[] = "sphere_cosine_ld_radial_above";
constexpr char sphere_cosine_ld_radial_cut[] = "sphere_cosine_ld_radial_cut";
constexpr char sphere_cosine_tabulated_ld_radial_above[] = "sphere_cosine_tabulated_ld_radial_above";
constexpr char sphere_cosine_tabulated_ld_radial_cut[] = "sphere_cosine_tabulated_ld_radial_cut";
constexpr char sphere_cosine_parallel_above[] = "sphere_cosine_parallel_above";
constexpr char sphere_cosine_parallel_cut[] = "sphere_cosine_parallel_cut";

/// The configurations a factory samples: the disks, or the spheres for the sphere factories.
template <class Factory, class T> const auto& configs_of() {
    if constexpr (std::is_base_of<SphereTag, Factory>::value) return apse_bench::sphere_configs<T>().spheres;
    else return apse_bench::disk_configs<T>().disks;
}

/// The set-up alone for one fresh shading point per benchmark iteration, every field of the
/// result kept observable (cost breakdown).
template <class Factory, class T> void bm_setup(benchmark::State& state) {
    const auto& lights = configs_of<Factory, T>();
    const apse::TabulationView view = apse::default_table().view();
    std::size_t i = 0;
    for (auto _ : state) {
        const auto& light = lights[i++ & (lights.size() - 1)];
        auto sampler = Factory::make(light, view);
        benchmark::DoNotOptimize(sampler);
    }
}

/// True for a light's samples (apse::PointSample: direction, pdf, point and distance), whose
/// point and distance the timed loop consumes too (otherwise the compiler drops their work).
template <class S, class = void> struct has_point : std::false_type {};
template <class S> struct has_point<S, std::void_t<decltype(std::declval<S&>().distance)>> : std::true_type {};

/// One fresh shading point per benchmark iteration: build the sampler, draw `Samples` samples.
template <class Factory, class T, int Samples> void bm_sampler(benchmark::State& state) {
    const DiskConfigs<T>& s = apse_bench::disk_configs<T>();
    const auto& lights = configs_of<Factory, T>();
    const apse::TabulationView view = apse::default_table().view();
    using Sampler = decltype(Factory::make(lights[0], view));
    std::size_t i = 0, k = 0;
    long iterations = 0, accepted = 0;
    for (auto _ : state) {
        const auto& light = lights[i++ & (lights.size() - 1)];
        const Sampler sampler = Factory::make(light, view);
        T acc = T(0);
        for (int j = 0; j < Samples; ++j) {
            const glm::vec<2, T>& u = s.u[k++ & (DiskConfigs<T>::u_count - 1)];
            apse::SampleDiagnostics diag{};
            const auto smp = apse::sample_with_diagnostics(sampler, u, diag);
            iterations += diag.iterations;
            accepted += smp.pdf > T(0);
            acc += smp.direction.x + smp.pdf;
            if constexpr (has_point<decltype(smp)>::value) acc += smp.distance + smp.point.x;  // a light's shadow ray
        }
        benchmark::DoNotOptimize(acc);
    }
    const double samples = double(state.iterations()) * Samples;
    state.counters["accepted"] = benchmark::Counter(double(accepted) / samples);
    if (apse::counts_iterations_v<Sampler>)
        state.counters["mean_iterations"] = benchmark::Counter(double(iterations) / samples);
}

template <class Factory> void register_sampler() {
    auto add = [](const char* type, int samples, void (*fn)(benchmark::State&)) {
        benchmark::RegisterBenchmark(
            (std::string(Factory::name) + "/" + type + "/" + std::to_string(samples)).c_str(), fn);
    };
    add("double", 1, bm_sampler<Factory, double, 1>);
    add("double", 16, bm_sampler<Factory, double, 16>);
    add("float", 1, bm_sampler<Factory, float, 1>);
    add("float", 16, bm_sampler<Factory, float, 16>);
}

/// The set-up alone (cost breakdown): <name>/<type>/0.
template <class Factory> void register_setup() {
    benchmark::RegisterBenchmark((std::string(Factory::name) + "/double/0").c_str(), bm_setup<Factory, double>);
    benchmark::RegisterBenchmark((std::string(Factory::name) + "/float/0").c_str(), bm_setup<Factory, float>);
}

}  // namespace

int main(int argc, char** argv) {
    if (!apse_bench::initialize(argc, argv)) return 1;
    // Everything shared is built before any timing.
    (void)apse::default_table();
    (void)apse_bench::disk_configs<float>();
    (void)apse_bench::disk_configs<double>();
    (void)apse_bench::sphere_configs<float>();
    (void)apse_bench::sphere_configs<double>();

    register_sampler<Area>();  // the reference
    register_sampler<AreaFramePerPoint>();
    register_sampler<GamitoSingleShot>();
    register_sampler<GamitoRetry8>();
    register_sampler<Rectangle>();
    register_sampler<Radial>();
    register_sampler<LdRadial>();
    register_sampler<Parallel>();
    register_sampler<Tabulated>();
    register_sampler<TabulatedLdRadial>();
    // cost breakdown: the parts of the set-up
    register_setup<Projection>();
    register_setup<ProjectionSolidAngle>();
    register_setup<Radial>();
    register_setup<LdRadial>();
    register_setup<Parallel>();
    register_setup<Tabulated>();
    register_setup<TabulatedLdRadial>();
    register_setup<Cosine<Tabulated, cosine_tabulated>>();  // the map's set-up + the warp's
    register_setup<Cosine<TabulatedLdRadial, cosine_tabulated_ld_radial>>();
    register_sampler<Cosine<Radial, cosine_radial>>();
    register_sampler<Cosine<LdRadial, cosine_ld_radial>>();
    register_sampler<Cosine<Parallel, cosine_parallel>>();
    register_sampler<Cosine<Tabulated, cosine_tabulated>>();
    register_sampler<Cosine<TabulatedLdRadial, cosine_tabulated_ld_radial>>();
    register_sampler<Cosine<TabulatedLdRadial, cosine_tabulated_ld_radial_16, 16>>();
    register_sampler<Cosine<TabulatedLdRadial, cosine_tabulated_ld_radial_32, 32>>();
    // sphere lights: the cone reference, every map, SphereLight, cosine-weighted
    register_sampler<SphereCone>();  // the reference of the sphere table
    register_sampler<SphereConePoint>();
    register_sampler<SphereMap<apse::RadialMap, sphere_radial>>();
    register_sampler<SphereMap<apse::LdRadialMap, sphere_ld_radial>>();
    register_sampler<SphereMap<apse::ParallelMap, sphere_parallel>>();
    register_sampler<SphereMap<apse::TabulatedMap, sphere_tabulated>>();
    register_sampler<SphereMap<apse::TabulatedLdRadialMap, sphere_tabulated_ld_radial>>();
    register_sampler<SphereCapSampler<apse::RadialMap, sphere_cap_radial>>();
    register_sampler<SphereCapSampler<apse::LdRadialMap, sphere_cap_ld_radial>>();
    register_sampler<SphereCapSampler<apse::TabulatedMap, sphere_cap_tabulated>>();
    register_sampler<SphereCapSampler<apse::TabulatedLdRadialMap, sphere_cap_tabulated_ld_radial>>();
    register_sampler<SphereLightOf<apse::RadialMap, sphere_light_radial>>();
    register_sampler<SphereLightOf<apse::LdRadialMap, sphere_light_ld_radial>>();
    register_sampler<SphereLightOf<apse::ParallelMap, sphere_light_parallel>>();
    register_sampler<SphereLightOf<apse::TabulatedMap, sphere_light_tabulated>>();
    register_sampler<SphereLightOf<apse::TabulatedLdRadialMap, sphere_light_tabulated_ld_radial>>();
    register_sampler<SphereLightCosine<apse::LdRadialMap, sphere_light_cosine_ld_radial_above, false>>();
    register_sampler<SphereLightCosine<apse::LdRadialMap, sphere_light_cosine_ld_radial_cut, true>>();
    register_sampler<SphereLightCosine<apse::TabulatedLdRadialMap, sphere_light_cosine_tabulated_ld_radial_above, false>>();
    register_sampler<SphereLightCosine<apse::TabulatedLdRadialMap, sphere_light_cosine_tabulated_ld_radial_cut, true>>();
    register_sampler<SphereCosine<apse::LdRadialMap, sphere_cosine_ld_radial_above, false>>();
    register_sampler<SphereCosine<apse::LdRadialMap, sphere_cosine_ld_radial_cut, true>>();
    register_sampler<SphereCosine<apse::TabulatedLdRadialMap, sphere_cosine_tabulated_ld_radial_above,
                                  false>>();
    register_sampler<SphereCosine<apse::TabulatedLdRadialMap, sphere_cosine_tabulated_ld_radial_cut,
                                  true>>();
    register_sampler<SphereCosine<apse::ParallelMap, sphere_cosine_parallel_above, false>>();
    register_sampler<SphereCosine<apse::ParallelMap, sphere_cosine_parallel_cut, true>>();
    apse_bench::run();
    return 0;
}
