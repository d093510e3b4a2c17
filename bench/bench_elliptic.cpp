// Benchmarks of apse's elliptic integrals against the peers available on the machine:
// libstdc++'s C++17 special functions (std::ellint_1/3, std::comp_ellint_1/3) and, when found,
// Boost.Math (ellint_rf/rd/rj/rc, ellint_1/3) with its default policy (float and double
// promoted to a wider type internally) and with promote_float<false> / promote_double<false>.
//
// Every benchmark cycles through the same fixed, seeded array of 1024 argument tuples, so the
// branch predictor cannot learn one input; the calls are independent, so this measures
// throughput (ns per call in a loop of calls), not the latency of a single call.
// Peers compute the same mathematical function: std:: and Boost take the modulus k = sqrt(m)
// and (checked against mpmath for libstdc++ 12 and Boost 1.74) the DLMF sign of n.
//
//   bench_elliptic --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
//   bench_elliptic --benchmark_format=json ... | python3 tools/bench_table.py
#include <apse/elliptic.hpp>

#include <benchmark/benchmark.h>

#include "support/context.hpp"

#include <array>
#include <cmath>
#include <cstdint>
#include <random>
#include <string>

#if defined(APSE_BENCH_HAVE_BOOST)
#include <boost/math/policies/policy.hpp>
#include <boost/math/special_functions/ellint_1.hpp>
#include <boost/math/special_functions/ellint_3.hpp>
#include <boost/math/special_functions/ellint_rc.hpp>
#include <boost/math/special_functions/ellint_rd.hpp>
#include <boost/math/special_functions/ellint_rf.hpp>
#include <boost/math/special_functions/ellint_rj.hpp>
#include <boost/version.hpp>
#endif

namespace {

constexpr std::size_t kInputs = 1024;  // a power of two: the index wraps with a mask

/// The arguments of one call: up to four values (unused ones are 0).
template <class T> using Args = std::array<T, 4>;
template <class T> using Inputs = std::array<Args<T>, kInputs>;

enum class Kind { rf, rd, rj_solid_angle, rj, rc, f, pi, k, comp_pi };

/// Realistic arguments, drawn once from a fixed seed (the same for float and double).
template <class T> Inputs<T> make_inputs(Kind kind) {
    std::mt19937_64 rng(20170619);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    auto logu = [&](double lo, double hi) { return lo * std::pow(hi / lo, u(rng)); };
    Inputs<T> in{};
    for (Args<T>& a : in) {
        switch (kind) {
            case Kind::rf:
            case Kind::rd:
                a = {T(logu(1e-2, 1e2)), T(logu(1e-2, 1e2)), T(logu(1e-2, 1e2)), T(0)};
                break;
            case Kind::rj:
                a = {T(logu(1e-2, 1e2)), T(logu(1e-2, 1e2)), T(logu(1e-2, 1e2)), T(logu(1e-2, 1e2))};
                break;
            case Kind::rj_solid_angle: {
                // Omega = 4/3 tan a tan b R_J(0, 1 + tan^2 b, 1 + tan^2 a, 1) (docs/math.md §3):
                // tan a from far-away (1e-3) to wide (1e2) ellipses, tan b <= tan a.
                const double ta = logu(1e-3, 1e2), tb = ta * (0.02 + 0.98 * u(rng));
                a = {T(0), T(1 + tb * tb), T(1 + ta * ta), T(1)};
                break;
            }
            case Kind::rc: a = {T(logu(1e-2, 1e2)), T(logu(1e-2, 1e2)), T(0), T(0)}; break;
            case Kind::f:  // phi in (0, pi/2), m in [0, 1) (the peers need m >= 0)
                a = {T(1.5707963 * u(rng)), T(0.999 * u(rng)), T(0), T(0)};
                break;
            case Kind::pi: {
                // Half the parallel map's Pi(-tan^2 b; theta | m) (docs/math.md §5), half n in [0, 1).
                const double ta = logu(1e-2, 1e2), tb = ta * (0.02 + 0.98 * u(rng));
                const double m = (ta * ta - tb * tb) / (1 + ta * ta);
                const double n = u(rng) < 0.5 ? -tb * tb : 0.95 * u(rng);
                a = {T(n), T(1.5707963 * u(rng)), T(m), T(0)};
                break;
            }
            case Kind::k: a = {T(0.999 * u(rng)), T(0), T(0), T(0)}; break;
            case Kind::comp_pi: {
                // Half the parallel-map form Pi(-tan^2 b | m), half Booth's Pi(n | m), m < n < 1.
                const double ta = logu(1e-2, 1e2), tb = ta * (0.02 + 0.98 * u(rng));
                const double m = (ta * ta - tb * tb) / (1 + ta * ta);
                const double n = u(rng) < 0.5 ? -tb * tb : 1 - tb * tb / (ta * ta);
                a = {T(n), T(m), T(0), T(0)};
                break;
            }
        }
    }
    return in;
}

template <class T, class F> void run(benchmark::State& state, Kind kind, F&& f) {
    const Inputs<T> in = make_inputs<T>(kind);
    std::size_t i = 0;
    for (auto _ : state) {
        const Args<T>& a = in[i++ & (kInputs - 1)];
        benchmark::DoNotOptimize(f(a[0], a[1], a[2], a[3]));
    }
    state.SetItemsProcessed(state.iterations());
}

// BM(name, kind, expression in x, y, z, p): one benchmark each for float and double.
#define APSE_BM(name, kind, expr)                                                          \
    template <class T> void name(benchmark::State& state) {                               \
        run<T>(state, Kind::kind, [](T x, T y, T z, T p) {                                \
            (void)x; (void)y; (void)z; (void)p;                                           \
            return expr;                                                                  \
        });                                                                               \
    }                                                                                     \
    BENCHMARK_TEMPLATE(name, float);                                                      \
    BENCHMARK_TEMPLATE(name, double)

// ---- apse ----------------------------------------------------------------------------------
APSE_BM(apse_rf, rf, apse::carlson_rf(x, y, z));
APSE_BM(apse_rd, rd, apse::carlson_rd(x, y, z));
APSE_BM(apse_rj, rj, apse::carlson_rj(x, y, z, p));
APSE_BM(apse_rj_solid_angle, rj_solid_angle, apse::carlson_rj(x, y, z, p));
APSE_BM(apse_rc, rc, apse::carlson_rc(x, y));
APSE_BM(apse_ellint_f, f, apse::ellint_f(x, y));
APSE_BM(apse_ellint_pi, pi, apse::ellint_pi(x, y, z));
APSE_BM(apse_comp_ellint_k, k, apse::comp_ellint_k(x));
APSE_BM(apse_comp_ellint_pi, comp_pi, apse::comp_ellint_pi(x, y));

// ---- apse, float promoted to double (the alternative to native float; see docs/elliptic.md) ---
#define APSE_BM_PROMOTED(name, kind, expr)                                                 \
    void name(benchmark::State& state) {                                                  \
        run<float>(state, Kind::kind, [](float fx, float fy, float fz, float fp) {        \
            const double x = fx, y = fy, z = fz, p = fp;                                  \
            (void)x; (void)y; (void)z; (void)p;                                           \
            return float(expr);                                                           \
        });                                                                               \
    }                                                                                     \
    BENCHMARK(name)->Name(#name "<float>")
APSE_BM_PROMOTED(apsedbl_rf, rf, apse::carlson_rf(x, y, z));
APSE_BM_PROMOTED(apsedbl_rd, rd, apse::carlson_rd(x, y, z));
APSE_BM_PROMOTED(apsedbl_rj, rj, apse::carlson_rj(x, y, z, p));
APSE_BM_PROMOTED(apsedbl_rj_solid_angle, rj_solid_angle, apse::carlson_rj(x, y, z, p));
APSE_BM_PROMOTED(apsedbl_rc, rc, apse::carlson_rc(x, y));
APSE_BM_PROMOTED(apsedbl_ellint_f, f, apse::ellint_f(x, y));
APSE_BM_PROMOTED(apsedbl_ellint_pi, pi, apse::ellint_pi(x, y, z));
APSE_BM_PROMOTED(apsedbl_comp_ellint_k, k, apse::comp_ellint_k(x));
APSE_BM_PROMOTED(apsedbl_comp_ellint_pi, comp_pi, apse::comp_ellint_pi(x, y));

// ---- libstdc++ C++17 special functions: modulus k = sqrt(m), nu = n ---------------------------
APSE_BM(std_ellint_f, f, std::ellint_1(std::sqrt(y), x));
APSE_BM(std_ellint_pi, pi, std::ellint_3(std::sqrt(z), x, y));
APSE_BM(std_comp_ellint_k, k, std::comp_ellint_1(std::sqrt(x)));
APSE_BM(std_comp_ellint_pi, comp_pi, std::comp_ellint_3(std::sqrt(y), x));

#if defined(APSE_BENCH_HAVE_BOOST)
// ---- Boost.Math: default policy (promotes float -> double, double -> long double) ------------
APSE_BM(boost_rf, rf, boost::math::ellint_rf(x, y, z));
APSE_BM(boost_rd, rd, boost::math::ellint_rd(x, y, z));
APSE_BM(boost_rj, rj, boost::math::ellint_rj(x, y, z, p));
APSE_BM(boost_rj_solid_angle, rj_solid_angle, boost::math::ellint_rj(x, y, z, p));
APSE_BM(boost_rc, rc, boost::math::ellint_rc(x, y));
APSE_BM(boost_ellint_f, f, boost::math::ellint_1(std::sqrt(y), x));
APSE_BM(boost_ellint_pi, pi, boost::math::ellint_3(std::sqrt(z), x, y));
APSE_BM(boost_comp_ellint_k, k, boost::math::ellint_1(std::sqrt(x)));
APSE_BM(boost_comp_ellint_pi, comp_pi, boost::math::ellint_3(std::sqrt(y), x));

// ---- Boost.Math without promotion: computes in T itself ----------------------------------------
using no_promotion = boost::math::policies::policy<boost::math::policies::promote_float<false>,
                                                   boost::math::policies::promote_double<false>>;
APSE_BM(boostnp_rf, rf, boost::math::ellint_rf(x, y, z, no_promotion()));
APSE_BM(boostnp_rd, rd, boost::math::ellint_rd(x, y, z, no_promotion()));
APSE_BM(boostnp_rj, rj, boost::math::ellint_rj(x, y, z, p, no_promotion()));
APSE_BM(boostnp_rj_solid_angle, rj_solid_angle, boost::math::ellint_rj(x, y, z, p, no_promotion()));
APSE_BM(boostnp_rc, rc, boost::math::ellint_rc(x, y, no_promotion()));
APSE_BM(boostnp_ellint_f, f, boost::math::ellint_1(std::sqrt(y), x, no_promotion()));
APSE_BM(boostnp_ellint_pi, pi, boost::math::ellint_3(std::sqrt(z), x, y, no_promotion()));
APSE_BM(boostnp_comp_ellint_k, k, boost::math::ellint_1(std::sqrt(x), no_promotion()));
APSE_BM(boostnp_comp_ellint_pi, comp_pi, boost::math::ellint_3(std::sqrt(y), x, no_promotion()));
#endif

}  // namespace

int main(int argc, char** argv) {
    if (!apse_bench::initialize(argc, argv)) return 1;
#if defined(APSE_BENCH_HAVE_BOOST)
    benchmark::AddCustomContext("boost_version", std::to_string(BOOST_VERSION / 100000) + "." +
                                                     std::to_string(BOOST_VERSION / 100 % 1000));
#endif
    apse_bench::run();
    return 0;
}
