// Benchmarks of the per-shading-point set-up: projecting a light to its spherical ellipse
// (projection.hpp) and its solid angle (spherical_ellipse.hpp), next to the cost floor every
// apse ratio is measured against, lean area sampling of the disk (baselines/area.hpp: the
// sampler from the light's stored DiskFrame, one concentric point, its solid-angle pdf), in
// float and double, in one run.
//
// Every benchmark cycles through the same fixed, seeded array of 1024 shading points (above,
// below, near and far from a unit disk), so the branch predictor cannot learn one input; the
// calls are independent, so this measures throughput (ns per shading point).
//
//   bench_projection --benchmark_repetitions=11 --benchmark_min_time=0.1
//       --benchmark_enable_random_interleaving=true --benchmark_report_aggregates_only=true
//
// At the end the ratio (project_disk + solid_angle) / area sampling is printed per type, from
// the medians when repetitions are requested (the goal: <= 2 in double). On a shared machine
// the timings drift by up to +-30 % between runs; random interleaving of the repetitions
// spreads that drift over all benchmarks alike. "project_disk + solid_angle" keeps the whole ellipse observable
// (DoNotOptimize), since a sampler needs all of it: otherwise the compiler drops the frame and
// the sines and cosines the solid angle does not use, and the time depends on its inlining.
#include <apse/baselines/area.hpp>
#include <apse/projection.hpp>

#include <benchmark/benchmark.h>

#include "support/context.hpp"

#include <array>
#include <cmath>
#include <cstdio>
#include <map>
#include <random>
#include <string>
#include <vector>

namespace {

constexpr std::size_t kInputs = 1024;  // a power of two: the index wraps with a mask

template <class T> struct Inputs {
    std::array<glm::vec<3, T>, kInputs> o;  // shading points
    std::array<glm::vec<2, T>, kInputs> u;  // sample points
    std::array<apse::SphericalEllipse<T>, kInputs> ellipses;
};

template <class T> const Inputs<T>& inputs() {
    static const Inputs<T> in = [] {
        Inputs<T> r{};
        std::mt19937_64 rng(20170619);
        std::uniform_real_distribution<double> u(0.0, 1.0);
        for (std::size_t i = 0; i < kInputs; ++i) {
            // heights from 1e-3 to 1e2 radii (log-uniform), both sides, lateral offsets up to 4 radii
            const double d = 1e-3 * std::pow(1e5, u(rng)) * (u(rng) < 0.8 ? 1 : -1);
            r.o[i] = glm::vec<3, T>(T(8 * u(rng) - 4), T(8 * u(rng) - 4), T(d));
            r.u[i] = glm::vec<2, T>(T(u(rng)), T(u(rng)));
            r.ellipses[i] = apse::project_disk(r.o[i], glm::vec<3, T>(0), glm::vec<3, T>(0, 0, 1), T(1));
        }
        return r;
    }();
    return in;
}

template <class T> void area_sample(benchmark::State& state) {
    const Inputs<T>& in = inputs<T>();
    // the light's frame is built once, as a renderer stores it with the light
    const apse::DiskFrame<T> frame = apse::DiskFrame<T>::make(glm::vec<3, T>(0), glm::vec<3, T>(0, 0, 1), T(1));
    std::size_t i = 0;
    for (auto _ : state) {
        const apse::DiskAreaSampler<T> s(in.o[i], frame);
        benchmark::DoNotOptimize(s.sample(in.u[i]));
        i = (i + 1) & (kInputs - 1);
    }
}

template <class T> void project_disk_only(benchmark::State& state) {
    const Inputs<T>& in = inputs<T>();
    // from the light's stored frame, as the area sampler
    const apse::DiskFrame<T> frame = apse::DiskFrame<T>::make(glm::vec<3, T>(0), glm::vec<3, T>(0, 0, 1), T(1));
    std::size_t i = 0;
    for (auto _ : state) {
        apse::SphericalEllipse<T> e = apse::project_disk(in.o[i], frame);
        benchmark::DoNotOptimize(e);
        i = (i + 1) & (kInputs - 1);
    }
}

template <class T> void project_disk_solid_angle(benchmark::State& state) {
    const Inputs<T>& in = inputs<T>();
    // from the light's stored frame, as the area sampler
    const apse::DiskFrame<T> frame = apse::DiskFrame<T>::make(glm::vec<3, T>(0), glm::vec<3, T>(0, 0, 1), T(1));
    std::size_t i = 0;
    for (auto _ : state) {
        apse::SphericalEllipse<T> e = apse::project_disk(in.o[i], frame);
        benchmark::DoNotOptimize(e);  // the whole ellipse: a sampler needs every field
        benchmark::DoNotOptimize(e.solid_angle());
        i = (i + 1) & (kInputs - 1);
    }
}

template <class T> void solid_angle_only(benchmark::State& state) {
    const Inputs<T>& in = inputs<T>();
    std::size_t i = 0;
    for (auto _ : state) {
        benchmark::DoNotOptimize(in.ellipses[i].solid_angle());
        i = (i + 1) & (kInputs - 1);
    }
}

template <class T> void project_ellipse_solid_angle(benchmark::State& state) {
    const Inputs<T>& in = inputs<T>();
    const glm::vec<3, T> c(0), u(1, 0, 0), v(0, T(0.5), 0);
    std::size_t i = 0;
    for (auto _ : state) {
        apse::SphericalEllipse<T> e = apse::project_ellipse(in.o[i], c, u, v);
        benchmark::DoNotOptimize(e);
        benchmark::DoNotOptimize(e.solid_angle());
        i = (i + 1) & (kInputs - 1);
    }
}

template <class T> void project_sphere_solid_angle(benchmark::State& state) {
    const Inputs<T>& in = inputs<T>();
    const glm::vec<3, T> c(0, 0, T(-1.5));
    std::size_t i = 0;
    for (auto _ : state) {
        apse::SphericalEllipse<T> e = apse::project_sphere(in.o[i], c, T(1));
        benchmark::DoNotOptimize(e);
        benchmark::DoNotOptimize(e.solid_angle());
        i = (i + 1) & (kInputs - 1);
    }
}

template <class T> void project_ellipsoid_solid_angle(benchmark::State& state) {
    const Inputs<T>& in = inputs<T>();
    const glm::vec<3, T> c(0, 0, T(-1.5)), a1(1, 0, 0), a2(0, T(0.5), 0), a3(0, 0, T(0.25));
    std::size_t i = 0;
    for (auto _ : state) {
        apse::SphericalEllipse<T> e = apse::project_ellipsoid(in.o[i], c, a1, a2, a3);
        benchmark::DoNotOptimize(e);
        benchmark::DoNotOptimize(e.solid_angle());
        i = (i + 1) & (kInputs - 1);
    }
}

/// Console output, plus the per-benchmark time kept for the ratio printed at the end (the
/// median aggregate when there are repetitions, else the single run).
class RatioReporter : public benchmark::ConsoleReporter {
public:
    void ReportRuns(const std::vector<Run>& runs) override {
        ConsoleReporter::ReportRuns(runs);
        for (const Run& r : runs) {
            const std::string name = r.run_name.function_name;
            if (r.run_type == Run::RT_Aggregate) {
                if (r.aggregate_name == "median") median_[name] = r.GetAdjustedRealTime();
            } else {
                single_[name] = r.GetAdjustedRealTime();
            }
        }
    }
    void print_ratios() const {
        for (const char* type : {"float", "double"}) {
            const std::string t = std::string("<") + type + ">";
            const double area = time("area_sample" + t), proj = time("project_disk+solid_angle" + t);
            if (area > 0 && proj > 0)
                std::printf("ratio (project_disk + solid_angle) / area sampling <%s>: %.2f  (%.1f ns / %.1f ns, %s)\n",
                            type, proj / area, proj, area, median_.empty() ? "single run" : "medians");
        }
    }

private:
    double time(const std::string& name) const {
        const auto m = median_.find(name);
        if (m != median_.end()) return m->second;
        const auto s = single_.find(name);
        return s != single_.end() ? s->second : 0;
    }
    std::map<std::string, double> median_, single_;
};

template <class T> void register_all(const char* type) {
    const std::string t = std::string("<") + type + ">";
    benchmark::RegisterBenchmark(("area_sample" + t).c_str(), area_sample<T>);
    benchmark::RegisterBenchmark(("project_disk" + t).c_str(), project_disk_only<T>);
    benchmark::RegisterBenchmark(("solid_angle" + t).c_str(), solid_angle_only<T>);
    benchmark::RegisterBenchmark(("project_disk+solid_angle" + t).c_str(), project_disk_solid_angle<T>);
    benchmark::RegisterBenchmark(("project_ellipse+solid_angle" + t).c_str(), project_ellipse_solid_angle<T>);
    benchmark::RegisterBenchmark(("project_sphere+solid_angle" + t).c_str(), project_sphere_solid_angle<T>);
    benchmark::RegisterBenchmark(("project_ellipsoid+solid_angle" + t).c_str(), project_ellipsoid_solid_angle<T>);
}

}  // namespace

int main(int argc, char** argv) {
    register_all<float>("float");
    register_all<double>("double");
    if (!apse_bench::initialize(argc, argv)) return 1;
    RatioReporter reporter;
    apse_bench::run(&reporter);
    reporter.print_ratios();
    return 0;
}
