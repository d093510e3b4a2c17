// The sampler concept (docs/usage.md, "The sampler concept"), checked for every sampler in float and
// double — the maps, CosineWeighted over each, RuntimeSampler (each MapKind, plain and cosine),
// DiskLight<Sampler> over each map and CosineWeighted map and over RuntimeSampler, the baselines:
// what each one must provide (compile time: member functions, their return types and
// noexcept, trivially copyable samplers and results, which samplers have invert() and
// solid_angle() and which count iterations — the table of docs/usage.md — and which expose the
// maps' building blocks), and how the members must agree
// (run time): empty() false for a normal light and true for degenerate ones, pdf 0 everywhere
// when empty, samples inside the light with pdf(sample) = the reported pdf, invert(sample(u)) = u,
// solid_angle() against references independent of apse (mpmath table, closed form),
// sample_with_diagnostics and the maps' sample_counted identical to sample, and point_on_plane's
// points on the light.
//
// The samplers, the light, the grid of points, the budgets and the measure are those of
// tests/support/concept_measures.hpp (tools/concept_report prints what the measure finds:
// docs/reliability.md).

#include "support/catch.hpp"

#include <apse/apse.hpp>
#include <apse/baselines/area.hpp>
#include <apse/baselines/gamito.hpp>
#include <apse/math.hpp>
#include <apse/spherical_rectangle.hpp>
#include <apse/diagnostics.hpp>
#include <apse/comparison.hpp>
#include <apse/runtime_sampler.hpp>

#include <cmath>
#include <cstdio>
#include <string>
#include <type_traits>
#include <utility>

#include "support/concept_measures.hpp"

namespace {

using namespace apse_test::sampler_concept;

// --- the scenes ---------------------------------------------------------------------------------

/// The solid angle of normal_scene's disk, 1.63710354934542635408343292152 sr: the mpmath
/// reference of tests/data/projection/disks.csv (row 2, tools/gen_projection_reference.py).
const double kDiskOmega = 1.63710354934542635408343292152;

/// The disk's circumscribed square [−0.5, 1.5] × [−1, 1] at z = −1 (what SphericalRectangle
/// samples in these tests): solid angle by the textbook corner formula, sum of ±atan(x y / (d
/// sqrt(x² + y² + d²))) over the corners (not apse's cancellation-free form), in long double.
double square_omega() {
    auto f = [](long double x, long double y) { return std::atan(x * y / std::sqrt(x * x + y * y + 1.0L)); };
    return double(f(1.5L, 1.0L) - f(-0.5L, 1.0L) - f(1.5L, -1.0L) + f(-0.5L, -1.0L));
}

/// Degenerate scenes: every sampler built from them must be empty.
enum class Degenerate {
    in_plane,     ///< o in the disk's plane (solid angle 0)
    zero_radius,  ///< radius 0
    nan_centre,   ///< a NaN coordinate
    behind,       ///< (CosineWeighted only) the light entirely below the receiver's horizon
};
template <class T> Scene<T> degenerate_scene(Degenerate d) {
    Scene<T> s = normal_scene<T>();
    if (d == Degenerate::in_plane) s.o = V3<T>(T(3), T(0), T(-1));
    if (d == Degenerate::zero_radius) s.r = T(0);
    if (d == Degenerate::nan_centre) s.c.x = apse::quiet_nan<T>();
    if (d == Degenerate::behind) s.receiver = V3<T>(T(0.1), T(0), T(1));  // faces away from the light
    return s;
}

// --- compile-time checks --------------------------------------------------------------------------

template <class S, class = void> struct has_invert : std::false_type {};
template <class S>
struct has_invert<S, std::void_t<decltype(std::declval<const S&>().invert(std::declval<typename S::vec3>()))>>
    : std::true_type {};
template <class S, class = void> struct has_solid_angle : std::false_type {};
template <class S>
struct has_solid_angle<S, std::void_t<decltype(std::declval<const S&>().solid_angle())>> : std::true_type {};

// The maps' building blocks (local frame, cumulative areas, the inversion's pieces) are public
// members of the maps that have them (F::blocks), for apse's compositions and the tests; no
// other sampler — CosineWeighted, RuntimeSampler, DiskLight, the baselines — exposes them, and no
// sampler exposes its stored areas or kappa.
template <class S, class = void> struct exposes_local_coordinates : std::false_type {};
template <class S>
struct exposes_local_coordinates<S, std::void_t<decltype(std::declval<const S&>().local_coordinates(
                                        std::declval<typename S::vec3>()))>> : std::true_type {};
template <class S, class = void> struct exposes_areas : std::false_type {};
template <class S>
struct exposes_areas<S, std::void_t<decltype(std::declval<const S&>().areas())>> : std::true_type {};
template <class S, class = void> struct exposes_kappa : std::false_type {};
template <class S>
struct exposes_kappa<S, std::void_t<decltype(std::declval<const S&>().kappa())>> : std::true_type {};
template <class S, class T, class = void> struct exposes_quadrant_area : std::false_type {};
template <class S, class T>
struct exposes_quadrant_area<S, T, std::void_t<decltype(std::declval<const S&>().quadrant_area(T(0)))>>
    : std::true_type {};
template <class S, class T, class = void> struct exposes_half_area : std::false_type {};
template <class S, class T>
struct exposes_half_area<S, T, std::void_t<decltype(std::declval<const S&>().half_area(T(0)))>> : std::true_type {};

/// The concept's static part for the sampler type S of the factory F in type T.
template <class F, class T> constexpr bool static_checks() {
    using S = decltype(F::make(std::declval<const Scene<T>&>()));
    using R = decltype(std::declval<const S&>().sample(std::declval<const V2<T>&>()));
    static_assert(std::is_trivially_copyable<S>::value, "samplers are trivially copyable (kernel arguments)");
    static_assert(std::is_same<typename S::vec2, V2<T>>::value && std::is_same<typename S::vec3, V3<T>>::value,
                  "vec2 / vec3 are GLM's vectors of T");
    // sample(u): the result family (DirectionSample or a type derived from it), an aggregate
    static_assert(std::is_base_of<apse::DirectionSample<T>, R>::value, "sample() returns the result family");
    static_assert(std::is_aggregate<R>::value && std::is_trivially_copyable<R>::value, "results are plain data");
    static_assert(noexcept(std::declval<const S&>().sample(std::declval<const V2<T>&>())), "sample is noexcept");
    // empty(), pdf(direction)
    static_assert(std::is_same<decltype(std::declval<const S&>().empty()), bool>::value, "empty() -> bool");
    static_assert(noexcept(std::declval<const S&>().empty()), "empty is noexcept");
    static_assert(std::is_same<decltype(std::declval<const S&>().pdf(std::declval<const V3<T>&>())), T>::value,
                  "pdf(direction) -> T");
    static_assert(noexcept(std::declval<const S&>().pdf(std::declval<const V3<T>&>())), "pdf is noexcept");
    // invert and solid_angle exactly where docs/usage.md's table says
    static_assert(has_invert<S>::value == F::invertible, "invert() where docs/usage.md says");
    static_assert(has_solid_angle<S>::value == F::has_solid_angle, "solid_angle() where docs/usage.md says");
    if constexpr (F::invertible) {
        static_assert(std::is_same<decltype(std::declval<const S&>().invert(std::declval<const V3<T>&>())), V2<T>>::value,
                      "invert(direction) -> vec2");
        static_assert(noexcept(std::declval<const S&>().invert(std::declval<const V3<T>&>())), "invert is noexcept");
    }
    if constexpr (F::has_solid_angle) {
        static_assert(std::is_same<decltype(std::declval<const S&>().solid_angle()), T>::value, "solid_angle() -> T");
        static_assert(noexcept(std::declval<const S&>().solid_angle()), "solid_angle is noexcept");
    }
    static_assert(exposes_local_coordinates<S>::value == bool(F::blocks & local_coords) &&
                      exposes_quadrant_area<S, T>::value == bool(F::blocks & quadrant) &&
                      exposes_half_area<S, T>::value == bool(F::blocks & half),
                  "the maps' building blocks are public on the maps that have them, on no other sampler");
    static_assert(!exposes_areas<S>::value && !exposes_kappa<S>::value, "no sampler exposes its stored areas or kappa");
    // diagnostics: one free function for every sampler, the same result type as sample()
    static_assert(apse::counts_iterations_v<S> == F::counts, "the maps count their iterations, no other sampler");
    apse::SampleDiagnostics* diag = nullptr;
    static_assert(std::is_same<decltype(apse::sample_with_diagnostics(std::declval<const S&>(),
                                                                      std::declval<const V2<T>&>(), *diag)),
                               R>::value,
                  "sample_with_diagnostics returns what sample returns");
    static_assert(noexcept(apse::sample_with_diagnostics(std::declval<const S&>(), std::declval<const V2<T>&>(), *diag)),
                  "sample_with_diagnostics is noexcept");
    return true;
}

// The result family itself.
template <class T> constexpr bool result_family_checks() {
    static_assert(std::is_base_of<apse::DirectionSample<T>, apse::PointSample<T>>::value, "PointSample is a DirectionSample");
    static_assert(std::is_base_of<apse::PointSample<T>, apse::RectanglePoint<T>>::value, "RectanglePoint is a PointSample");
    static_assert(std::is_aggregate<apse::DirectionSample<T>>::value && std::is_aggregate<apse::PointSample<T>>::value &&
                      std::is_aggregate<apse::RectanglePoint<T>>::value,
                  "results are aggregates");
    static_assert(std::is_trivially_copyable<apse::PointSample<T>>::value &&
                      std::is_trivially_copyable<apse::RectanglePoint<T>>::value,
                  "results are trivially copyable");
    static_assert(std::is_same<decltype(std::declval<const apse::SphericalRectangle<T>&>().sample_point(
                                   std::declval<const V2<T>&>())),
                               apse::RectanglePoint<T>>::value,
                  "sample_point -> RectanglePoint");
    return true;
}
static_assert(result_family_checks<float>() && result_family_checks<double>(), "");

// --- run-time checks ------------------------------------------------------------------------------

/// True if the ray o + t·direction meets the scene's light (disk or circumscribed square), up to
/// a relative slack `tol` of its size; checked through point_on_plane.
template <class T> bool on_light(const Scene<T>& s, Shape shape, const apse::DirectionSample<T>& d, double tol) {
    const apse::PointSample<T> p = apse::point_on_plane(d, s.o, s.c, s.n);
    if (!(p.pdf > T(0))) return false;
    const glm::dvec3 q = glm::dvec3(p.point) - glm::dvec3(s.c);
    const glm::dvec3 w = glm::dvec3(p.point) - glm::dvec3(s.o);
    // the point is on the ray (distance·direction) and in the plane
    if (glm::length(w - double(p.distance) * glm::dvec3(p.direction)) > tol * glm::length(w)) return false;
    if (std::fabs(q.z) > tol) return false;
    const double r = double(s.r) * (1 + tol);
    return shape == Shape::disk ? q.x * q.x + q.y * q.y <= r * r : std::fabs(q.x) <= r && std::fabs(q.y) <= r;
}

template <class F, class T> void check_normal() {
    static_assert(static_checks<F, T>(), "");
    const Scene<T> scene = normal_scene<T>();
    const auto s = F::make(scene);
    INFO(F::name << " (" << (sizeof(T) == 4 ? "float" : "double") << "), normal light");
    CHECK_FALSE(s.empty());
    if constexpr (F::has_solid_angle) {
        // the disk's Omega against mpmath; the square's against the corner formula; both computed
        // natively in T: 64 eps covers the float/double rounding of a well-conditioned Omega
        const double ref = F::shape == Shape::disk ? kDiskOmega : square_omega();
        CHECK(std::fabs(double(s.solid_angle()) / ref - 1) <= 64 * double(apse::epsilon<T>()));
    }
    const Measure m = measure<F, T>(s, [&](const V2<T>& u, const auto& smp) {
        using R = std::decay_t<decltype(smp)>;
        apse::SampleDiagnostics diag{-1};
        const auto same = apse::sample_with_diagnostics(s, u, diag);
        // the same computation, bit for bit, and a count only where the sampler counts
        CHECK(same.pdf == smp.pdf);
        CHECK(same.direction == smp.direction);
        CHECK(diag.iterations >= 0);
        CHECK(diag.iterations <= (F::counts ? apse::detail::max_area_iterations : 0));
        if constexpr (F::counts) {
            // the public counting member: the same sample and count as sample_with_diagnostics
            int iterations = -1;
            const auto counted = s.sample_counted(u, iterations);
            CHECK(counted.pdf == smp.pdf);
            CHECK(counted.direction == smp.direction);
            CHECK(iterations == diag.iterations);
        }
        CHECK(apse::detail::is_finite(smp.pdf));
        CHECK(std::fabs(double(glm::length(smp.direction)) - 1) <= Budget<T>::on_light);
        if constexpr (std::is_base_of<apse::PointSample<T>, R>::value) {
            // the point on the light: where point_on_plane puts it, at its distance along the direction
            const apse::PointSample<T> p = apse::point_on_plane(apse::DirectionSample<T>(smp), scene.o, scene.c, scene.n);
            CHECK(glm::length(glm::dvec3(smp.point) - glm::dvec3(p.point)) <= Budget<T>::on_light);
            CHECK(std::fabs(double(smp.distance) - double(p.distance)) <= Budget<T>::on_light);
        }
        // a sample (pdf > 0; Gamito's single shot may reject) lies on the light
        if (smp.pdf > T(0)) CHECK(on_light(scene, F::shape, smp, Budget<T>::on_light));
    });
    CHECK(m.accepted >= required_accepted<F>());
    CHECK(m.pdf <= Budget<T>::pdf);
    CHECK(m.round_trip <= Budget<T>::round_trip);
    std::printf("[%s] %-42s accepted %2d/%d, max |pdf(sample)/pdf - 1| %.1e, max |invert(sample(u)) - u| %.1e\n",
                sizeof(T) == 4 ? "float" : "double", std::string(F::name).c_str(), m.accepted, kPoints, m.pdf,
                m.round_trip);
    // away from the light: density 0
    CHECK(s.pdf(V3<T>(0, 0, 1)) == T(0));
    CHECK(s.pdf(V3<T>(T(-1), T(0), T(-0.1))) == T(0));
}

template <class F, class T> void check_degenerate(Degenerate d) {
    const Scene<T> scene = degenerate_scene<T>(d);
    const auto s = F::make(scene);
    INFO(F::name << " (" << (sizeof(T) == 4 ? "float" : "double") << "), degenerate case " << int(d));
    CHECK(s.empty());
    // Omega is the light's: 0 for a degenerate light, not for one merely below the receiver's horizon
    if constexpr (F::has_solid_angle)
        if (d != Degenerate::behind) CHECK(s.solid_angle() == T(0));
    for (int i = 0; i < kGrid; ++i)
        for (int j = 0; j < kGrid; ++j) {
            const auto smp = s.sample(grid_point<T>(i, j));
            CHECK(smp.pdf == T(0));
            CHECK(apse::detail::is_finite(smp.direction.x + smp.direction.y + smp.direction.z));
            // pdf 0 everywhere, also towards where the light would be
            CHECK(s.pdf(glm::normalize(V3<T>(T(0.5), T(0.1 * i - 0.3), T(-1)))) == T(0));
            if constexpr (F::invertible) {
                const V2<T> back = s.invert(glm::normalize(V3<T>(T(0.5), T(0.1 * j - 0.3), T(-1))));
                CHECK(apse::detail::is_finite(back.x + back.y));
            }
        }
}

template <class F, class T> void check_sampler() {
    check_normal<F, T>();
    for (Degenerate d : {Degenerate::in_plane, Degenerate::zero_radius, Degenerate::nan_centre}) check_degenerate<F, T>(d);
}

template <class Plain, class T> void check_map_and_cosine() {
    check_sampler<Plain, T>();
    check_sampler<Cosine<Plain>, T>();
    check_degenerate<Cosine<Plain>, T>(Degenerate::behind);  // light below the receiver's horizon
}

}  // namespace

TEMPLATE_TEST_CASE("sampler concept: the maps and their cosine-weighted versions", "[concept]", float, double) {
    for_each_map([](auto f) { check_map_and_cosine<typename decltype(f)::type, TestType>(); });
}

TEMPLATE_TEST_CASE("sampler concept: the baselines", "[concept]", float, double) {
    for_each_baseline([](auto f) { check_sampler<typename decltype(f)::type, TestType>(); });
}

TEMPLATE_TEST_CASE("sampler concept: RuntimeSampler, each map, plain and cosine-weighted", "[concept]", float, double) {
    using T = TestType;
    using K = apse::MapKind;
    for_each_runtime([](auto f) { check_sampler<typename decltype(f)::type, T>(); });
    check_degenerate<Runtime<K::ld_radial, true>, T>(Degenerate::behind);  // below the receiver's horizon
    check_degenerate<Runtime<K::tabulated_ld_radial, true>, T>(Degenerate::behind);
}

TEMPLATE_TEST_CASE("sampler concept: DiskLight<RuntimeSampler>, each map, plain and cosine-weighted", "[concept]", float,
                   double) {
    using T = TestType;
    using K = apse::MapKind;
    static_assert(std::is_same<decltype(std::declval<const apse::DiskLight<apse::RuntimeSampler<T>>&>().sample(
                                   std::declval<const V2<T>&>())),
                               apse::PointSample<T>>::value,
                  "DiskLight::sample -> PointSample");
    for_each_runtime_light([](auto f) { check_sampler<typename decltype(f)::type, T>(); });
    check_degenerate<Light<K::ld_radial, true>, T>(Degenerate::behind);  // below the receiver's horizon
}

TEMPLATE_TEST_CASE("sampler concept: DiskLight<Sampler>, each map, plain and cosine-weighted", "[concept]", float, double) {
    using T = TestType;
    static_assert(std::is_same<decltype(std::declval<const apse::DiskLight<apse::LdRadialMap<T>>&>().sample(
                                   std::declval<const V2<T>&>())),
                               apse::PointSample<T>>::value,
                  "DiskLight::sample -> PointSample");
    // each map, plain and cosine-weighted, and two from the light's stored frame
    for_each_typed_light([](auto f) { check_sampler<typename decltype(f)::type, T>(); });
    // below the receiver's horizon
    check_degenerate<TypedLight<apse::LdRadialMap, true>, T>(Degenerate::behind);
    check_degenerate<TypedLight<apse::TabulatedLdRadialMap, true>, T>(Degenerate::behind);
}

TEMPLATE_TEST_CASE("sampler concept: point_on_plane completes a direction sample", "[concept]", float, double) {
    using T = TestType;
    const Scene<T> s = normal_scene<T>();
    // the ray through the disk's centre: the centre, at distance |c − o|
    const V3<T> dir = glm::normalize(s.c - s.o);
    const apse::PointSample<T> p = apse::point_on_plane(apse::DirectionSample<T>{dir, T(2)}, s.o, s.c, s.n);
    const double tol = Budget<T>::on_light;  // rounding of a unit direction carried ~1 away
    CHECK(p.pdf == T(2));
    CHECK(p.direction == dir);
    CHECK(glm::length(glm::dvec3(p.point) - glm::dvec3(s.c)) <= tol);
    CHECK(std::fabs(double(p.distance) - std::sqrt(1.25)) <= tol);
    // either orientation of the plane's normal, any length
    const apse::PointSample<T> q = apse::point_on_plane(apse::DirectionSample<T>{dir, T(2)}, s.o, s.c, T(-7) * s.n);
    CHECK(glm::length(glm::dvec3(q.point) - glm::dvec3(s.c)) <= tol);
    // no sample: pdf 0 in, a ray pointing away, a ray parallel to the plane, a NaN direction
    const V3<T> away = -dir, parallel(T(1), T(0), T(0)), nan(apse::quiet_nan<T>(), T(0), T(-1));
    for (const auto& in : {apse::DirectionSample<T>{dir, T(0)}, apse::DirectionSample<T>{away, T(1)},
                           apse::DirectionSample<T>{parallel, T(1)}, apse::DirectionSample<T>{nan, T(1)}}) {
        const apse::PointSample<T> r = apse::point_on_plane(in, s.o, s.c, s.n);
        CHECK(r.pdf == T(0));
        CHECK(r.distance == T(0));
        CHECK(r.point == s.o);
    }
    // a hit beyond T's range (a ray at 1e-3 rad to a plane as far as T's largest values): no sample
    const T big = T(sizeof(T) == 4 ? 1e38 : 1e307);
    const apse::DirectionSample<T> grazing{glm::normalize(V3<T>(T(1), T(0), T(-1e-3))), T(1)};
    CHECK(apse::point_on_plane(grazing, s.o, V3<T>(T(0), T(0), -big), s.n).pdf == T(0));
}
