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

#include "support/default_table.hpp"

namespace {

template <class T> using V3 = glm::vec<3, T>;
template <class T> using V2 = glm::vec<2, T>;

// --- the scenes ---------------------------------------------------------------------------------

/// A disk light seen from o, and a receiver normal at o (for CosineWeighted).
template <class T> struct Scene {
    V3<T> o, c, n;
    T r;
    V3<T> receiver;
};

/// The disk {z = −1, |p − (0.5, 0, −1)| <= 1} seen from the origin: an oblique, close light.
/// Its solid angle, 1.63710354934542635408343292152 sr, is the mpmath reference of
/// tests/data/projection/disks.csv (row 2, tools/gen_projection_reference.py).
template <class T> Scene<T> normal_scene() {
    return {V3<T>(0), V3<T>(T(0.5), T(0), T(-1)), V3<T>(0, 0, 1), T(1), V3<T>(T(0.2), T(0.1), T(-1))};
}
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

// --- the samplers: one factory each, with docs/usage.md's table as constants -----------------------

template <class T> apse::SphericalEllipse<T> ellipse_of(const Scene<T>& s) { return apse::project_disk(s.o, s.c, s.n, s.r); }

enum class Shape { disk, square };

/// The maps' building blocks a sampler has as public members (docs/math.md §4–§6): the local
/// coordinates of a direction (RadialMap, TabulatedMap), the cumulative areas (RadialMap's
/// quadrant_area, ParallelMap's half_area). A bit mask; none for every other sampler.
enum Blocks : int { no_blocks = 0, local_coords = 1, quadrant = 2, half = 4 };

struct Radial {
    static constexpr const char* name = "RadialMap";
    static constexpr bool invertible = true, has_solid_angle = true, counts = true;
    static constexpr Shape shape = Shape::disk;
    static constexpr int blocks = local_coords | quadrant;
    template <class T> static auto make(const Scene<T>& s) { return apse::RadialMap<T>(ellipse_of(s)); }
};
struct LdRadial {
    static constexpr const char* name = "LdRadialMap";
    static constexpr bool invertible = true, has_solid_angle = true, counts = true;
    static constexpr Shape shape = Shape::disk;
    static constexpr int blocks = no_blocks;
    template <class T> static auto make(const Scene<T>& s) { return apse::LdRadialMap<T>(ellipse_of(s)); }
};
struct Parallel {
    static constexpr const char* name = "ParallelMap";
    static constexpr bool invertible = true, has_solid_angle = true, counts = true;
    static constexpr Shape shape = Shape::disk;
    static constexpr int blocks = half;
    template <class T> static auto make(const Scene<T>& s) { return apse::ParallelMap<T>(ellipse_of(s)); }
};
struct Tabulated {  // no solid_angle(): the tabulated maps never compute Omega (docs/usage.md)
    static constexpr const char* name = "TabulatedMap";
    static constexpr bool invertible = true, has_solid_angle = false, counts = true;
    static constexpr Shape shape = Shape::disk;
    static constexpr int blocks = local_coords;
    template <class T> static auto make(const Scene<T>& s) {
        return apse::TabulatedMap<T>(ellipse_of(s), apse_test::default_table().view());
    }
};
struct TabulatedLdRadial {
    static constexpr const char* name = "TabulatedLdRadialMap";
    static constexpr bool invertible = true, has_solid_angle = false, counts = true;
    static constexpr Shape shape = Shape::disk;
    static constexpr int blocks = no_blocks;
    template <class T> static auto make(const Scene<T>& s) {
        return apse::TabulatedLdRadialMap<T>(ellipse_of(s), apse_test::default_table().view());
    }
};
template <class Plain> struct Cosine {  // CosineWeighted over a map, with the scene's receiver normal
    static constexpr const char* name = "CosineWeighted";
    static constexpr bool invertible = true, has_solid_angle = false, counts = false;
    static constexpr Shape shape = Shape::disk;
    static constexpr int blocks = no_blocks;
    template <class T> static auto make(const Scene<T>& s) {
        using Map = decltype(Plain::make(s));
        return apse::CosineWeighted<Map>(Plain::make(s), s.receiver);
    }
};
struct Area {  // from the light's stored frame
    static constexpr const char* name = "DiskAreaSampler(o, frame)";
    static constexpr bool invertible = true, has_solid_angle = false, counts = false;
    static constexpr Shape shape = Shape::disk;
    static constexpr int blocks = no_blocks;
    template <class T> static auto make(const Scene<T>& s) {
        return apse::DiskAreaSampler<T>(s.o, apse::DiskFrame<T>::make(s.c, s.n, s.r));
    }
};
struct AreaDirect {  // the convenience constructor
    static constexpr const char* name = "DiskAreaSampler(o, c, n, r)";
    static constexpr bool invertible = true, has_solid_angle = false, counts = false;
    static constexpr Shape shape = Shape::disk;
    static constexpr int blocks = no_blocks;
    template <class T> static auto make(const Scene<T>& s) { return apse::DiskAreaSampler<T>(s.o, s.c, s.n, s.r); }
};
struct GamitoSingle {  // no invert(): rejection is not a bijection; no solid_angle(): never computed
    static constexpr const char* name = "GamitoSingleShot";
    static constexpr bool invertible = false, has_solid_angle = false, counts = false;
    static constexpr Shape shape = Shape::disk;
    static constexpr int blocks = no_blocks;
    template <class T> static auto make(const Scene<T>& s) { return apse::GamitoSingleShot<T>(s.o, s.c, s.n, s.r); }
};
struct GamitoRetry {
    static constexpr const char* name = "GamitoRetry";
    static constexpr bool invertible = false, has_solid_angle = true, counts = false;
    static constexpr Shape shape = Shape::disk;
    static constexpr int blocks = no_blocks;
    template <class T> static auto make(const Scene<T>& s) { return apse::GamitoRetry<T>(s.o, s.c, s.n, s.r, 8); }
};
struct Rectangle {  // the disk's circumscribed square
    static constexpr const char* name = "SphericalRectangle";
    static constexpr bool invertible = true, has_solid_angle = true, counts = false;
    static constexpr Shape shape = Shape::square;
    static constexpr int blocks = no_blocks;
    template <class T> static auto make(const Scene<T>& s) {
        return apse::SphericalRectangle<T>::from_center(s.o, s.c, V3<T>(s.r, 0, 0), V3<T>(0, s.r, 0));
    }
};

/// The printed names of MapKind's maps (in its order) and of the map types.
constexpr const char* kind_names[5] = {"radial", "ld_radial", "parallel", "tabulated", "tabulated_ld"};
template <template <class> class Map> constexpr const char* map_name = "?";
template <> constexpr const char* map_name<apse::RadialMap> = "RadialMap";
template <> constexpr const char* map_name<apse::LdRadialMap> = "LdRadialMap";
template <> constexpr const char* map_name<apse::ParallelMap> = "ParallelMap";
template <> constexpr const char* map_name<apse::TabulatedMap> = "TabulatedMap";
template <> constexpr const char* map_name<apse::TabulatedLdRadialMap> = "TabulatedLdRadialMap";

/// The map chosen at run time (runtime_sampler.hpp), plain or with the scene's receiver normal;
/// the tabulated kinds read the default table.
template <apse::MapKind K, bool Cosine> struct Runtime {
    static inline const std::string name =
        std::string("RuntimeSampler ") + kind_names[int(K)] + (Cosine ? ", cosine" : "");
    static constexpr bool invertible = true, has_solid_angle = false, counts = false;
    static constexpr Shape shape = Shape::disk;
    static constexpr int blocks = no_blocks;
    template <class T> static auto make(const Scene<T>& s) {
        if constexpr (Cosine) return apse::RuntimeSampler<T>(ellipse_of(s), K, apse_test::default_table().view(), s.receiver);
        else return apse::RuntimeSampler<T>(ellipse_of(s), K, apse_test::default_table().view());
    }
};

/// DiskLight<RuntimeSampler>: the map chosen at run time, plain or with the receiver's normal
/// (the tabulated kinds read the default table).
template <apse::MapKind K, bool Cosine> struct Light {
    static inline const std::string name =
        std::string("DiskLight<Runtime> ") + kind_names[int(K)] + (Cosine ? ", cosine" : "");
    static constexpr bool invertible = true, has_solid_angle = true, counts = false;
    static constexpr Shape shape = Shape::disk;
    static constexpr int blocks = no_blocks;
    template <class T> static auto make(const Scene<T>& s) {
        using L = apse::DiskLight<apse::RuntimeSampler<T>>;
        if constexpr (Cosine) return L(s.o, s.c, s.n, s.r, K, apse_test::default_table().view(), s.receiver);
        else return L(s.o, s.c, s.n, s.r, K, apse_test::default_table().view());
    }
};

/// DiskLight over the map Map chosen at compile time (the tabulated maps read the default table),
/// plain or CosineWeighted<Map> with the receiver's normal; from (c, n, r) or from the stored
/// DiskFrame.
template <template <class> class Map, bool Cosine, bool Framed = false> struct TypedLight {
    static inline const std::string name = std::string("DiskLight<") + (Cosine ? "Cosine<" : "") + map_name<Map> +
                                           (Cosine ? ">>" : ">") + (Framed ? "(frame)" : "");
    static constexpr bool invertible = true, has_solid_angle = true, counts = false;
    static constexpr Shape shape = Shape::disk;
    static constexpr int blocks = no_blocks;
    template <class T, class... Args> static auto light(const Scene<T>& s, const Args&... args) {
        using S = std::conditional_t<Cosine, apse::CosineWeighted<Map<T>>, Map<T>>;
        if constexpr (Framed) return apse::DiskLight<S>(s.o, apse::DiskFrame<T>::make(s.c, s.n, s.r), args...);
        else return apse::DiskLight<S>(s.o, s.c, s.n, s.r, args...);
    }
    template <class T> static auto make(const Scene<T>& s) {
        return apse::detail::with_table_if_read<Map<T>>(apse_test::default_table().view(), [&](const auto&... table) {
            if constexpr (Cosine) return light(s, table..., s.receiver);
            else return light(s, table...);
        });
    }
};

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

/// Interior points of the square (away from the edges, the radial seam u1 ∈ {0, 1} and the
/// LD maps' centre, where invert is ambiguous): a 7 × 7 grid in [0.08, 0.92]².
template <class T> V2<T> grid_point(int i, int j) {
    return V2<T>(T(0.08 + 0.84 * (i + 0.31) / 7.0), T(0.08 + 0.84 * (j + 0.67) / 7.0));
}

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

/// Budgets shared by every sampler on this moderate light: pdf(sample) vs the reported pdf and
/// the round trip invert(sample(u)) − u measured at most 4e-7 (float) and 7e-16 (double) over all
/// of them (the printout); the budgets, 1e-5 and 1e-13, leave ~25× and ~150× for other
/// compilers' FMA contraction and vector paths. A sample on the light within 1e-4 float / 1e-10
/// double of its size (a unit direction's rounding carried to a plane ~1 away, with slack for the
/// rim). A wrong pdf, a wrong inverse or a direction off the light errs by far more (a pdf 0.2 %
/// off fails).
template <class T> struct Budget {
    static constexpr double pdf = sizeof(T) == 4 ? 1e-5 : 1e-13;
    static constexpr double round_trip = sizeof(T) == 4 ? 1e-5 : 1e-13;
    static constexpr double on_light = sizeof(T) == 4 ? 1e-4 : 1e-10;
};

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
    int accepted = 0;
    double worst_pdf = 0, worst_u = 0;
    for (int i = 0; i < 7; ++i)
        for (int j = 0; j < 7; ++j) {
            const V2<T> u = grid_point<T>(i, j);
            const auto smp = s.sample(u);
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
            if constexpr (std::is_base_of<apse::PointSample<T>, decltype(smp)>::value) {
                // the point on the light: where point_on_plane puts it, at its distance along the direction
                const apse::PointSample<T> p = apse::point_on_plane(apse::DirectionSample<T>(smp), scene.o, scene.c, scene.n);
                CHECK(glm::length(glm::dvec3(smp.point) - glm::dvec3(p.point)) <= Budget<T>::on_light);
                CHECK(std::fabs(double(smp.distance) - double(p.distance)) <= Budget<T>::on_light);
            }
            if (!(smp.pdf > T(0))) continue;  // rejected (Gamito single shot): no sample
            ++accepted;
            CHECK(on_light(scene, F::shape, smp, Budget<T>::on_light));
            worst_pdf = std::max(worst_pdf, std::fabs(double(s.pdf(smp.direction)) / double(smp.pdf) - 1));
            if constexpr (F::invertible) {
                const V2<T> back = s.invert(smp.direction);
                worst_u = std::max(worst_u, double(std::max(std::fabs(back.x - u.x), std::fabs(back.y - u.y))));
            }
        }
    // every sampler but Gamito's single shot accepts every point; it accepts ~75 % (pi/4 of the
    // far-field square): at least half of the 49 points
    CHECK(accepted >= (std::string(F::name) == "GamitoSingleShot" ? 25 : 49));
    CHECK(worst_pdf <= Budget<T>::pdf);
    CHECK(worst_u <= Budget<T>::round_trip);
    std::printf("[%s] %-42s accepted %2d/49, max |pdf(sample)/pdf - 1| %.1e, max |invert(sample(u)) - u| %.1e\n",
                sizeof(T) == 4 ? "float" : "double", std::string(F::name).c_str(), accepted, worst_pdf, worst_u);
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
    for (int i = 0; i < 7; ++i)
        for (int j = 0; j < 7; ++j) {
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
    check_map_and_cosine<Radial, TestType>();
    check_map_and_cosine<LdRadial, TestType>();
    check_map_and_cosine<Parallel, TestType>();
    check_map_and_cosine<Tabulated, TestType>();
    check_map_and_cosine<TabulatedLdRadial, TestType>();
}

TEMPLATE_TEST_CASE("sampler concept: the baselines", "[concept]", float, double) {
    check_sampler<Area, TestType>();
    check_sampler<AreaDirect, TestType>();
    check_sampler<GamitoSingle, TestType>();
    check_sampler<GamitoRetry, TestType>();
    check_sampler<Rectangle, TestType>();
}

TEMPLATE_TEST_CASE("sampler concept: RuntimeSampler, each map, plain and cosine-weighted", "[concept]", float, double) {
    using T = TestType;
    using K = apse::MapKind;
    check_sampler<Runtime<K::radial, false>, T>();
    check_sampler<Runtime<K::ld_radial, false>, T>();
    check_sampler<Runtime<K::parallel, false>, T>();
    check_sampler<Runtime<K::tabulated, false>, T>();
    check_sampler<Runtime<K::tabulated_ld_radial, false>, T>();
    check_sampler<Runtime<K::radial, true>, T>();
    check_sampler<Runtime<K::ld_radial, true>, T>();
    check_sampler<Runtime<K::parallel, true>, T>();
    check_sampler<Runtime<K::tabulated, true>, T>();
    check_sampler<Runtime<K::tabulated_ld_radial, true>, T>();
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
    check_sampler<Light<K::radial, false>, T>();
    check_sampler<Light<K::ld_radial, false>, T>();
    check_sampler<Light<K::parallel, false>, T>();
    check_sampler<Light<K::tabulated, false>, T>();
    check_sampler<Light<K::tabulated_ld_radial, false>, T>();
    check_sampler<Light<K::radial, true>, T>();
    check_sampler<Light<K::ld_radial, true>, T>();
    check_sampler<Light<K::parallel, true>, T>();
    check_sampler<Light<K::tabulated, true>, T>();
    check_sampler<Light<K::tabulated_ld_radial, true>, T>();
    check_degenerate<Light<K::ld_radial, true>, T>(Degenerate::behind);  // below the receiver's horizon
}

TEMPLATE_TEST_CASE("sampler concept: DiskLight<Sampler>, each map, plain and cosine-weighted", "[concept]", float, double) {
    using T = TestType;
    static_assert(std::is_same<decltype(std::declval<const apse::DiskLight<apse::LdRadialMap<T>>&>().sample(
                                   std::declval<const V2<T>&>())),
                               apse::PointSample<T>>::value,
                  "DiskLight::sample -> PointSample");
    check_sampler<TypedLight<apse::RadialMap, false>, T>();
    check_sampler<TypedLight<apse::LdRadialMap, false>, T>();
    check_sampler<TypedLight<apse::ParallelMap, false>, T>();
    check_sampler<TypedLight<apse::TabulatedMap, false>, T>();
    check_sampler<TypedLight<apse::TabulatedLdRadialMap, false>, T>();
    check_sampler<TypedLight<apse::RadialMap, true>, T>();
    check_sampler<TypedLight<apse::LdRadialMap, true>, T>();
    check_sampler<TypedLight<apse::ParallelMap, true>, T>();
    check_sampler<TypedLight<apse::TabulatedMap, true>, T>();
    check_sampler<TypedLight<apse::TabulatedLdRadialMap, true>, T>();
    // from the light's stored frame
    check_sampler<TypedLight<apse::LdRadialMap, false, true>, T>();
    check_sampler<TypedLight<apse::TabulatedLdRadialMap, true, true>, T>();
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
