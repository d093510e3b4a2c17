// sphere_light.hpp: the one-call sphere-light sampler over every map — points on the sphere,
// shadow-ray distances against a long-double reference, pdf(direction) and the stateless MIS pdf
// equal to the sampler's own density, an unbiased irradiance estimate against the closed form,
// sizes, mixed scalar arguments and bad input.
#include <apse/sphere_light.hpp>
#include <apse/cosine_weighted.hpp>
#include <apse/maps/ld_radial.hpp>
#include <apse/maps/parallel.hpp>
#include <apse/comparison.hpp>
#include <apse/maps/tabulated_ld_radial.hpp>
#include <apse/math.hpp>
#include <apse/runtime_sampler.hpp>

#include "support/default_table.hpp"
#include "support/map_testing.hpp"

#include "support/catch.hpp"

#include <cmath>
#include <limits>
#include <type_traits>
#include <vector>

namespace {
template <class T> using Vec2 = glm::vec<2, T>;
template <class T> using Vec3 = glm::vec<3, T>;

// Passed to GPU kernels by value: plain data, holding the chosen sampler's cap form and the
// shadow-ray data (shading point, centre, radius, distance, distance cos² alpha) only — smaller than the map.
template <class T> constexpr bool sized_by_its_map() {
    using Map = apse::TabulatedLdRadialMap<T>;
    using Cap = typename Map::CapSampler;
    return sizeof(apse::SphereLight<Map>) <= sizeof(Cap) + 2 * sizeof(Vec3<T>) + 3 * sizeof(T) + alignof(Cap) &&
           sizeof(Cap) < sizeof(Map);
}
static_assert(std::is_trivially_copyable<apse::SphereLight<apse::LdRadialMap<float>>>::value, "trivially copyable");
static_assert(std::is_trivially_copyable<apse::SphereLight<apse::TabulatedLdRadialMap<double>>>::value,
              "trivially copyable");
static_assert(sized_by_its_map<float>() && sized_by_its_map<double>(), "a sphere light is its map + shadow-ray data");

// The sampler's arguments after the sphere: none for the exact maps, the table for the tabulated.
template <class Sampler> struct Args {
    template <class F> static auto apply(F&& f) { return f(); }
};
template <class T> struct Args<apse::TabulatedMap<T>> {
    template <class F> static auto apply(F&& f) { return f(apse_test::default_table().view()); }
};
template <class T> struct Args<apse::TabulatedLdRadialMap<T>> {
    template <class F> static auto apply(F&& f) { return f(apse_test::default_table().view()); }
};

template <class Sampler, class T = typename Sampler::vec3::value_type>
apse::SphereLight<Sampler> make_light(const Vec3<T>& o, const Vec3<T>& c, T r) {
    return Args<Sampler>::apply([&](const auto&... a) { return apse::SphereLight<Sampler>(o, c, r, a...); });
}
template <class Sampler, class T = typename Sampler::vec3::value_type>
T stateless_pdf(const Vec3<T>& o, const Vec3<T>& c, T r, const Vec3<T>& w) {
    return Args<Sampler>::apply([&](const auto&... a) { return apse::sphere_light_pdf<Sampler>(o, c, r, w, a...); });
}

/// Half-angle of the cap between the unit direction w and the centre direction, in long double.
long double angle_from(const glm::dvec3& w, const glm::dvec3& axis) {
    const glm::dvec3 a = glm::normalize(axis);
    return std::atan2((long double)glm::length(glm::cross(w, a)), (long double)glm::dot(w, a));
}

/// Nearest hit distance of the ray o + t w (w unit) on the sphere, in long double from the
/// quadratic's stable root.
long double hit_reference(const glm::dvec3& o, const glm::dvec3& c, double r, const glm::dvec3& w) {
    const long double px = (long double)c.x - o.x, py = (long double)c.y - o.y, pz = (long double)c.z - o.z;
    const long double wl = std::sqrt((long double)w.x * w.x + (long double)w.y * w.y + (long double)w.z * w.z);
    const long double wx = w.x / wl, wy = w.y / wl, wz = w.z / wl;
    const long double b = px * wx + py * wy + pz * wz;
    const long double qx = px - b * wx, qy = py - b * wy, qz = pz - b * wz;
    const long double disc = (long double)r * r - (qx * qx + qy * qy + qz * qz);
    const long double d2 = px * px + py * py + pz * pz;
    return (d2 - (long double)r * r) / (b + std::sqrt(std::max(disc, 0.0L)));
}

/// The geometry of one light sample s with pdf > 0 drawn from o towards the sphere (c, r): a
/// unit direction inside the cap (to rounding of the direction: a few eps in angle), the nearest
/// point of the sphere along it at the reference distance, and that point o + t w, on the sphere
/// and on the side facing o. Distance: T's rounding of o, c and the direction is amplified near
/// the surface by dist / (dist - r) (the hit distance is ~dist - r there); 64 eps of that covers
/// every operation of the computation.
template <class S, class T> void check_point_geometry(const S& s, const Vec3<T>& o, const Vec3<T>& c, T r) {
    const glm::dvec3 od(o), cd(c), w(s.direction), p(s.point);
    const double dist = glm::length(cd - od), eps = double(apse::epsilon<T>());
    const long double alpha = std::asin((long double)r / dist);
    CHECK(std::fabs(glm::length(w) - 1) <= 8 * eps);
    CHECK(angle_from(w, cd - od) <= alpha * (1 + 16 * eps) + 16 * eps);
    const long double t_ref = hit_reference(od, cd, double(r), w);
    CHECK(std::fabs(s.distance - t_ref) <= 64 * eps * (1 + dist / (dist - r)) * t_ref);
    CHECK(glm::length(p - (od + double(s.distance) * w)) <= 16 * eps * (glm::length(od) + s.distance));
    CHECK(std::fabs(glm::length(p - cd) - r) <= 64 * eps * (r + glm::length(cd) + dist));
    CHECK(glm::dot(p - cd, w) <= 64 * eps * (r + glm::length(cd) + dist));
}

/// Every sample of `light`: a unit direction inside the cap, its nearest point on the sphere at
/// the reference distance, pdf(direction) and the stateless pdf equal to the sample's pdf.
template <class Sampler, class T>
void check_points(const Vec3<T>& o, const Vec3<T>& c, T r, int n, apse_test::Rng& rng) {
    const apse::SphereLight<Sampler> light = make_light<Sampler>(o, c, r);
    REQUIRE_FALSE(light.empty());
    const glm::dvec3 od(o), cd(c);
    const double dist = glm::length(cd - od), eps = double(apse::epsilon<T>());
    const long double alpha = std::asin((long double)r / dist);
    int rim_misses = 0;
    for (int i = 0; i < n; ++i) {
        const Vec2<T> u(rng.uniform<T>(), rng.uniform<T>());
        const auto s = light.sample(u);
        INFO("u = (" << u.x << ", " << u.y << "), dist/r = " << dist / r);
        REQUIRE(s.pdf > T(0));
        check_point_geometry(s, o, c, r);
        const glm::dvec3 w(s.direction);
        // the density of that direction: the sample's own (0 only on the rim, from rounding)
        const T p_light = light.pdf(s.direction);
        if (p_light == T(0)) {
            ++rim_misses;
            CHECK(angle_from(w, cd - od) >= alpha * (1 - 64 * eps) - 64 * eps);
        } else {
            CHECK(p_light == s.pdf);
        }
        CHECK(stateless_pdf<Sampler>(o, c, r, s.direction) == p_light);
    }
    CHECK(rim_misses <= n / 100);
}

/// Every sample of the cosine-weighted `light` (receiver normal n_r) with pdf > 0: a unit
/// direction inside the cap and above the receiver's horizon, its nearest point on the sphere
/// at the reference distance (tolerance as check_points), and pdf(direction) the sample's pdf to
/// rounding: the sample's density is z / Omega_perp from the sampler's own construction, pdf()'s
/// n_r·w / Omega_perp from the rounded w, whose height n_r·w carries a few eps of absolute
/// rounding — relative 1/(n_r·w) times that near the horizon — so 64 eps (1 + 1/(n_r·w))
/// relative; within rounding of the rim pdf() may read 0. Returns the number of samples with
/// pdf > 0.
template <class Light, class T>
int check_cosine_points(const Light& light, const Vec3<T>& o, const Vec3<T>& c, T r, const Vec3<T>& n_r, int n,
                        apse_test::Rng& rng) {
    const glm::dvec3 od(o), cd(c), nd = glm::normalize(glm::dvec3(n_r));
    const double dist = glm::length(cd - od), eps = double(apse::epsilon<T>());
    const long double alpha = std::asin((long double)r / dist);
    int accepted = 0;
    for (int i = 0; i < n; ++i) {
        const Vec2<T> u(rng.uniform<T>(), rng.uniform<T>());
        const auto s = light.sample(u);
        INFO("u = (" << u.x << ", " << u.y << "), dist/r = " << dist / r);
        REQUIRE(s.pdf >= T(0));
        if (s.pdf == T(0)) continue;
        ++accepted;
        check_point_geometry(s, o, c, r);
        const glm::dvec3 w(s.direction);
        CHECK(glm::dot(w, nd) > 0);
        const T p_light = light.pdf(s.direction);
        const double height = glm::dot(w, nd);
        if (p_light != T(0)) CHECK(std::fabs(double(p_light) - double(s.pdf)) <= 64 * eps * (1 + 1 / height) * double(s.pdf));
        else CHECK(angle_from(w, cd - od) >= alpha * (1 - 64 * eps) - 64 * eps);
    }
    return accepted;
}

template <class T> struct Sphere {
    Vec3<T> o, c;
    T r;
};
/// Shading points from 1.0001 radii (the surface) to 1e4 radii (float) / 1e6 (double), in
/// general positions.
template <class T> std::vector<Sphere<T>> spheres() {
    const Vec3<T> c(T(0.4), T(-1.2), T(2.5));
    const T r = T(0.7);
    const glm::dvec3 dir = glm::normalize(glm::dvec3(0.3, 0.8, -0.52));
    std::vector<Sphere<T>> out;
    for (double k : {1.0001, 1.05, 2.0, 50.0, 1e4, sizeof(T) == 8 ? 1e6 : 3e4})
        out.push_back({Vec3<T>(glm::dvec3(c) + k * double(r) * dir), c, r});
    return out;
}

template <class T, class... Maps> void check_every_map(int n) {
    apse_test::Rng rng(25);
    for (const Sphere<T>& s : spheres<T>()) (check_points<Maps>(s.o, s.c, s.r, n, rng), ...);
}
}  // namespace

// SphereLight<Sampler> holds Sampler::CapSampler, not Sampler: its samples, pdfs and inverts must
// be the sampler's own, built from project_sphere's cap. The same steps run in both, so they are
// equal bit for bit — except where the compiler may fuse multiply-adds differently at the two
// call sites (-ffp-contract with FMA hardware, -ffast-math: __FP_FAST_FMA / __FAST_MATH__), one
// rounding per fused operation: there within 16 eps (relative; the cut-cap inversion's stopping
// rule is 16 eps of its area), and the inverse, away from the square's seams, within its
// conditioning (same_u).
#if defined(__FP_FAST_FMA) || defined(__FAST_MATH__)
constexpr bool exact_equality = false;
#else
constexpr bool exact_equality = true;
#endif

template <class T> bool same(T a, T b) {
    if (exact_equality) return a == b || (std::isnan(double(a)) && std::isnan(double(b)));
    return std::fabs(double(a) - double(b)) <= 16 * double(apse::epsilon<T>()) * std::fmax(1.0, std::fmax(std::fabs(double(a)), std::fabs(double(b))));
}
template <class T> bool same(const Vec3<T>& a, const Vec3<T>& b) { return same(a.x, b.x) && same(a.y, b.y) && same(a.z, b.z); }
template <class T> bool same(const Vec2<T>& a, const Vec2<T>& b) { return same(a.x, b.x) && same(a.y, b.y); }

/// The same point on the sphere, or — where the two call sites may round differently — within
/// 16 eps of `scale`, the size of the summands the point is made of (o + t w: |o| + t), not of
/// the point itself: a far shading point's rounding dominates the point's.
template <class T> bool same_point(const Vec3<T>& a, const Vec3<T>& b, double scale) {
    if (same(a, b)) return true;
    if (exact_equality) return false;
    return glm::length(glm::dvec3(a) - glm::dvec3(b)) <= 16 * double(apse::epsilon<T>()) * scale;
}

/// The same point of the square, or — where the two call sites may round differently — within the
/// invert's own conditioning, twice (one rounding per call site): the direction's components carry
/// a few eps of absolute rounding, a relative one of ~eps / sin alpha in the offset from the axis
/// that the azimuth and the radial coordinate are read from (test_caps' round-trip budget,
/// 64 eps + 8 eps / sin alpha: 2e-4 in float for a cap 200 radii away).
template <class T> bool same_u(const Vec2<T>& a, const Vec2<T>& b, const apse::SphericalEllipse<T>& cap) {
    if (same(a, b)) return true;
    if (exact_equality) return false;
    const double tol = 2 * (64 + 8 / double(cap.sin_alpha)) * double(apse::epsilon<T>());
    return std::fabs(double(a.x) - double(b.x)) <= tol && std::fabs(double(a.y) - double(b.y)) <= tol;
}

/// The same density at d, or — where the two call sites may round differently — one of them 0
/// and d on the cap's rim to rounding (the cone test then falls either way: SphericalEllipse::
/// contains): the direction's local components carry ~eps absolute error, and its gnomonic
/// radius |l_xy| / (l_z tan alpha) (1 on the rim, where |l_xy| = sin alpha and l_z = cos alpha)
/// is their ratio, known to ~eps (1/sin alpha + 1/cos alpha) <= eps (2 + 1/tan alpha + tan alpha)
/// relative: small caps are limited by their offset from the axis, caps near a hemisphere by
/// their height over the tangent plane.
template <class T> bool same_pdf(T a, T b, const apse::SphericalEllipse<T>& cap, const Vec3<T>& d) {
    if (same(a, b)) return true;
    if (exact_equality || (a > T(0) && b > T(0))) return false;
    const glm::dvec3 l(cap.to_local(d));
    const double ta = double(cap.tan_alpha);
    const double rho = std::sqrt(l.x * l.x + l.y * l.y) / (l.z * ta);
    return std::fabs(rho - 1) <= 16 * double(apse::epsilon<T>()) * (2 + 1 / ta + ta);
}

/// The light against Sampler(project_sphere(o, c, r), args...) at the points `us` and
/// directions `ws`.
template <class Sampler, class T, class... A>
void check_same_as_sampler(const Vec3<T>& o, const Vec3<T>& c, T r, const std::vector<Vec2<T>>& us,
                           const std::vector<Vec3<T>>& ws, const A&... args) {
    const apse::SphereLight<Sampler> light(o, c, r, args...);
    const Sampler ref(apse::project_sphere(o, c, r), args...);
    REQUIRE(light.empty() == ref.empty());
    for (const Vec2<T>& u : us) {
        const auto a = light.sample(u);
        const auto b = ref.sample(u);
        INFO("u = (" << u.x << ", " << u.y << ")");
        CHECK(same(a.pdf, b.pdf));
        CHECK(same(a.direction, b.direction));
        CHECK(same_pdf(light.pdf(b.direction), ref.pdf(b.direction), ref.ellipse(), b.direction));
        const bool off_seam = u.x > T(0.05) && u.x < T(0.95) && u.y > T(0.05) && u.y < T(0.95);
        if (exact_equality || off_seam) CHECK(same_u(light.invert(b.direction), ref.invert(b.direction), ref.ellipse()));
    }
    for (const Vec3<T>& w : ws) {
        CHECK(same_pdf(light.pdf(w), ref.pdf(w), ref.ellipse(), w));
        CHECK(same(apse::sphere_light_pdf<Sampler>(o, c, r, w, args...), ref.ellipse().contains(w) ? ref.pdf(w) : T(0)));
        if (exact_equality) CHECK(same(light.invert(w), ref.invert(w)));
    }
}

TEMPLATE_TEST_CASE("sphere light: the samples, pdfs and inverts of its sampler built from project_sphere",
                   "[sphere_light]", float, double) {
    using T = TestType;
    apse_test::Rng rng(20261204);
    const apse::TabulationView table = apse_test::default_table().view(), no_table{nullptr, 0, 0, 0};
    auto unit = [&] {
        const T z = T(2) * rng.uniform<T>() - T(1), phi = T(6.283185307179586) * rng.uniform<T>();
        const T s = std::sqrt(std::fmax(T(0), T(1) - z * z));
        return Vec3<T>(s * std::cos(phi), s * std::sin(phi), z);
    };
    std::vector<Vec2<T>> us = {Vec2<T>(T(0)), Vec2<T>(T(1)), Vec2<T>(T(0.5)), Vec2<T>(T(0), T(1)),
                               Vec2<T>(std::numeric_limits<T>::quiet_NaN(), T(0.5))};
    for (int i = 0; i < 12; ++i) us.push_back(Vec2<T>(rng.uniform<T>(), rng.uniform<T>()));
    for (int k = 0; k < 160; ++k) {
        const Vec3<T> c(T(4) * rng.uniform<T>() - T(2), T(4) * rng.uniform<T>() - T(2), T(4) * rng.uniform<T>() - T(2));
        const T r = std::pow(T(10), T(-3) * rng.uniform<T>());
        // 1 + 2^-20 to 1e4 radii from the centre (log-uniform), and a few exactly-rounded surfaces
        const T ratio = k % 16 == 0 ? T(1) + std::ldexp(T(1), -int(8 + k % 13)) : std::pow(T(1e4), rng.uniform<T>()) + T(1e-6);
        const Vec3<T> o = c + unit() * (r * ratio);
        // receiver normals: random (caps above, cut by and below the horizon), zero, NaN
        const Vec3<T> n = k % 20 == 1 ? Vec3<T>(T(0)) : k % 20 == 2 ? Vec3<T>(std::numeric_limits<T>::quiet_NaN()) : unit();
        std::vector<Vec3<T>> ws = {glm::normalize(c - o), Vec3<T>(T(0)), -glm::normalize(c - o)};
        for (int j = 0; j < 6; ++j) ws.push_back(glm::normalize(c - o) + unit() * (r / glm::length(c - o)));
        INFO("sphere " << k << ": c = (" << c.x << ", " << c.y << ", " << c.z << "), r = " << r << ", ratio = " << ratio);
        check_same_as_sampler<apse::RadialMap<T>>(o, c, r, us, ws);
        check_same_as_sampler<apse::LdRadialMap<T>>(o, c, r, us, ws);
        check_same_as_sampler<apse::ParallelMap<T>>(o, c, r, us, ws);
        check_same_as_sampler<apse::TabulatedMap<T>>(o, c, r, us, ws, table);
        check_same_as_sampler<apse::TabulatedLdRadialMap<T>>(o, c, r, us, ws, k % 10 == 3 ? no_table : table);
        check_same_as_sampler<apse::CosineWeighted<apse::RadialMap<T>>>(o, c, r, us, ws, n);
        check_same_as_sampler<apse::CosineWeighted<apse::LdRadialMap<T>>>(o, c, r, us, ws, n);
        check_same_as_sampler<apse::CosineWeighted<apse::ParallelMap<T>>>(o, c, r, us, ws, n);
        check_same_as_sampler<apse::CosineWeighted<apse::TabulatedLdRadialMap<T>>>(o, c, r, us, ws,
                                                                                   k % 10 == 3 ? no_table : table, n);
        // the map chosen at run time: the light holds the same choice among the cap samplers
        for (int m = 0; m < 5; ++m) {
            const apse::MapKind kind = apse::MapKind(m);
            const apse::TabulationView view = k % 10 == 3 ? no_table : table;
            INFO("MapKind " << m);
            check_same_as_sampler<apse::RuntimeSampler<T>>(o, c, r, us, ws, kind, view);
            check_same_as_sampler<apse::RuntimeSampler<T>>(o, c, r, us, ws, kind, view, n);
            const apse::SphereLight<apse::RuntimeSampler<T>> runtime(o, c, r, kind, view, n);
            CHECK(runtime.cosine_weighted() == apse::RuntimeSampler<T>(apse::project_sphere(o, c, r), kind, view, n).weighted());
        }
        const apse::SphereLight<apse::CosineWeighted<apse::LdRadialMap<T>>> light(o, c, r, n);
        const apse::CosineWeighted<apse::LdRadialMap<T>> ref(apse::project_sphere(o, c, r), n);
        CHECK(light.cosine_weighted() == ref.weighted());
        CHECK_FALSE(apse::SphereLight<apse::LdRadialMap<T>>(o, c, r).cosine_weighted());
    }
}

TEMPLATE_TEST_CASE("sphere light: the smallest caps, at the limit of a finite density", "[sphere_light][robust]", float,
                   double) {
    using T = TestType;
    // Caps just above the smallest tangent project_sphere keeps (tan alpha = 2^-63 in float,
    // 2^-511 in double), seen by receivers ever closer to grazing, so that the projected solid
    // angle Omega_perp = pi sin^2 alpha cos g (and, cut by the horizon, less) crosses the limit
    // below which the cosine-weighted sampler is empty (1/Omega_perp within a factor 2 of the
    // largest T). The light must stay the sampler built from project_sphere (same emptiness,
    // same samples), and whenever it samples cosine-weighted the plain map must be able to sample
    // the same cap: the sampler's margin is what lets the light skip the map's density check.
    const int e_min = sizeof(T) == 4 ? 63 : 511;
    const std::vector<Vec2<T>> us = {Vec2<T>(T(0.5)), Vec2<T>(T(0.25), T(0.75)), Vec2<T>(T(0.9), T(0.1))};
    int weighted = 0, plain_or_empty = 0;
    for (double k : {1.0, 1.5, 4.0, 64.0}) {
        const Vec3<T> o(T(0)), c(T(0), T(0), T(std::ldexp(1.0, e_min) / k));  // sin alpha ~ k 2^-e_min
        for (int j = 0; j <= 40; ++j) {
            // cos g from 1 down to ~2^-(e_min + 40): above the horizon, then cut by it
            const double cg = j == 0 ? 1.0 : std::ldexp(1.0, -int(j * (e_min + 40) / 40));
            const Vec3<T> n(T(std::sqrt(1 - cg * cg)), T(0), T(cg));
            INFO((sizeof(T) == 4 ? "float" : "double") << " sin alpha ~ " << k << " 2^-" << e_min << ", cos g = " << cg);
            const apse::SphereLight<apse::CosineWeighted<apse::LdRadialMap<T>>> light(o, c, T(1), n);
            const apse::CosineWeighted<apse::LdRadialMap<T>> ref(apse::project_sphere(o, c, T(1)), n);
            REQUIRE(light.empty() == ref.empty());
            CHECK(light.cosine_weighted() == ref.weighted());
            if (light.cosine_weighted()) {
                ++weighted;
                CHECK_FALSE(apse::LdRadialMap<T>(apse::project_sphere(o, c, T(1))).empty());
            } else {
                ++plain_or_empty;
            }
            for (const Vec2<T>& u : us) {
                const auto a = light.sample(u);
                const auto b = ref.sample(u);
                CHECK(same(a.pdf, b.pdf));
                CHECK(same(a.direction, b.direction));
                CHECK(std::isfinite(double(a.pdf)));
                CHECK(a.pdf >= T(0));
            }
        }
    }
    // both sides of the limit were reached
    CHECK(weighted > 0);
    CHECK(plain_or_empty > 0);
}

TEMPLATE_TEST_CASE("sphere light: points on the sphere, distances, pdf and the stateless pdf", "[sphere_light]", float,
                   double) {
    using T = TestType;
    check_every_map<T, apse::RadialMap<T>, apse::LdRadialMap<T>, apse::ParallelMap<T>, apse::TabulatedMap<T>,
                    apse::TabulatedLdRadialMap<T>>(200);
}

TEMPLATE_TEST_CASE("sphere light: cosine-weighted points on the sphere and distances", "[sphere_light]", float, double) {
    using T = TestType;
    apse_test::Rng rng(26);
    const apse::TabulationView table = apse_test::default_table().view();
    for (const Sphere<T>& s : spheres<T>()) {
        const glm::dvec3 axis = glm::normalize(glm::dvec3(s.c) - glm::dvec3(s.o));
        const glm::dvec3 side = glm::normalize(glm::cross(axis, glm::dvec3(0, 0, 1)));
        const double alpha = std::asin(double(s.r) / glm::length(glm::dvec3(s.c) - glm::dvec3(s.o)));
        // receivers: facing the centre (cap above the horizon), the horizon through the cap with
        // its centre above (g = pi/2 − alpha/2) and below (g = pi/2 + alpha/2)
        for (double g : {0.3 * (1.5707963267948966 - alpha), 1.5707963267948966 - 0.5 * alpha, 1.5707963267948966 + 0.5 * alpha}) {
            const Vec3<T> n_r(std::cos(g) * axis + std::sin(g) * side);
            INFO("dist/r = " << glm::length(glm::dvec3(s.c) - glm::dvec3(s.o)) / s.r << ", g = " << g);
            const apse::SphereLight<apse::CosineWeighted<apse::LdRadialMap<T>>> ld(s.o, s.c, s.r, n_r);
            const apse::SphereLight<apse::CosineWeighted<apse::ParallelMap<T>>> parallel(s.o, s.c, s.r, n_r);
            const apse::SphereLight<apse::CosineWeighted<apse::TabulatedLdRadialMap<T>>> tab(s.o, s.c, s.r, table, n_r);
            REQUIRE(ld.cosine_weighted());
            CHECK(check_cosine_points(ld, s.o, s.c, s.r, n_r, 200, rng) >= 190);
            CHECK(check_cosine_points(parallel, s.o, s.c, s.r, n_r, 200, rng) >= 190);
            CHECK(check_cosine_points(tab, s.o, s.c, s.r, n_r, 200, rng) >= 190);
            // the run-time choice places each sample exactly where the typed light does
            for (int m = 0; m < 5; ++m) {
                const apse::SphereLight<apse::RuntimeSampler<T>> runtime(s.o, s.c, s.r, apse::MapKind(m), table, n_r);
                CHECK(check_cosine_points(runtime, s.o, s.c, s.r, n_r, 50, rng) >= 45);
            }
            const apse::SphereLight<apse::RuntimeSampler<T>> runtime(s.o, s.c, s.r, apse::MapKind::ld_radial, table, n_r);
            for (int i = 0; i < 50; ++i) {
                const Vec2<T> u(rng.uniform<T>(), rng.uniform<T>());
                const auto a = ld.sample(u), b = runtime.sample(u);
                CHECK(same(a.pdf, b.pdf));
                CHECK(same(a.distance, b.distance));
                CHECK(same_point(a.point, b.point, double(glm::length(s.o) + a.distance)));
            }
        }
    }
}

TEMPLATE_TEST_CASE("sphere light: solid angle and the stateless pdf of misses", "[sphere_light]", float, double) {
    using T = TestType;
    for (const Sphere<T>& s : spheres<T>()) {
        const apse::SphereLight<apse::LdRadialMap<T>> light(s.o, s.c, s.r);
        const double dist = glm::length(glm::dvec3(s.c) - glm::dvec3(s.o));
        // 2 pi (1 - cos alpha) = 2 pi (1 - sqrt(1 - (r/dist)^2)), in the cancellation-free long
        // double form; the cap's own rounding: a few eps relative, amplified near the surface
        // (alpha's rounding from dist - r).
        const long double s2 = (long double)s.r * s.r / ((long double)dist * dist);
        const long double omega = apse_test::kTwoPi * s2 / (1 + std::sqrt(1 - s2));
        const double eps = double(apse::epsilon<T>());
        CHECK(std::fabs(light.solid_angle() - omega) <= 16 * eps * (1 + dist / (dist - s.r)) * omega);
        // directions away from the sphere and just outside its cap miss it
        const glm::dvec3 axis = glm::normalize(glm::dvec3(s.c) - glm::dvec3(s.o));
        const glm::dvec3 side = glm::normalize(glm::cross(axis, glm::dvec3(0, 0, 1)));
        const double alpha = std::asin(double(s.r) / dist);
        for (double k : {1.01, 1.5, 3.0}) {
            const double a = std::min(alpha * k, 3.0);
            const Vec3<T> w(std::cos(a) * axis + std::sin(a) * side);
            CHECK(light.pdf(w) == T(0));
            CHECK(apse::sphere_light_pdf<apse::LdRadialMap<T>>(s.o, s.c, s.r, w) == T(0));
        }
        CHECK(light.pdf(Vec3<T>(-axis)) == T(0));
    }
}

TEMPLATE_TEST_CASE("sphere light: irradiance estimate against the closed form", "[sphere_light][mc]", float, double) {
    using T = TestType;
    // Unoccluded irradiance from a uniform sphere (radiance 1) whose cap is above the receiver's
    // horizon: E = pi sin^2 alpha cos gamma (gamma the centre's angle from the normal), the
    // exact view-factor formula. The estimate cos / pdf over 4096 independent samples must lie
    // within 5 standard errors (estimated from the same samples) plus float's rounding of E.
    const Vec3<T> c(T(1), T(2), T(-0.5));
    const T r = T(0.5);
    apse_test::Rng rng(2017);
    for (double k : {1.2, 3.0, 20.0}) {
        const glm::dvec3 dir = glm::normalize(glm::dvec3(-0.2, 0.5, 0.9));
        const Vec3<T> o(glm::dvec3(c) + k * double(r) * dir);
        const double gamma = 0.6 * (1.5707963267948966 - std::asin(1 / k));  // cap above the horizon
        const glm::dvec3 side = glm::normalize(glm::cross(dir, glm::dvec3(1, 0, 0)));
        const glm::dvec3 n = std::cos(gamma) * (-dir) + std::sin(gamma) * side;
        const double e_ref = 3.141592653589793 / (k * k) * std::cos(gamma);
        auto run = [&](const auto& light) {
            const int count = 4096;
            double sum = 0, sum2 = 0;
            for (int i = 0; i < count; ++i) {
                const auto s = light.sample(Vec2<T>(rng.uniform<T>(), rng.uniform<T>()));
                REQUIRE(s.pdf > T(0));
                const double f = std::max(0.0, glm::dot(n, glm::dvec3(s.direction))) / double(s.pdf);
                sum += f;
                sum2 += f * f;
            }
            const double mean = sum / count, se = std::sqrt(std::max(sum2 / count - mean * mean, 0.0) / count);
            INFO("k = " << k << ", E = " << mean << " +- " << se << ", reference " << e_ref);
            CHECK(std::fabs(mean - e_ref) <= 5 * se + 1e-5 * e_ref);
        };
        run(apse::SphereLight<apse::LdRadialMap<T>>(o, c, r));
        run(apse::SphereLight<apse::ParallelMap<T>>(o, c, r));
        run(apse::SphereLight<apse::TabulatedLdRadialMap<T>>(o, c, r, apse_test::default_table().view()));
    }
}

TEST_CASE("sphere light: mixed scalar arguments", "[sphere_light]") {
    const glm::vec3 o(0, 0, 0), c(0, 0, 3);
    const apse::SphereLight<apse::LdRadialMap<float>> a(o, c, 1);    // int radius
    const apse::SphereLight<apse::LdRadialMap<float>> b(o, c, 1.0);  // double radius
    CHECK(a.solid_angle() == b.solid_angle());
    CHECK(apse::sphere_light_pdf<apse::LdRadialMap<float>>(o, c, 1.0, glm::vec3(0, 0, 1)) == a.pdf(glm::vec3(0, 0, 1)));
}

TEMPLATE_TEST_CASE("sphere light: bad input gives an empty light, never NaN", "[sphere_light][robust]", float, double) {
    using T = TestType;
    const T inf = std::numeric_limits<T>::infinity(), nan = std::numeric_limits<T>::quiet_NaN();
    const Vec3<T> c(T(1), T(2), T(3));
    struct Case {
        Vec3<T> o, c;
        T r;
        const char* what;
    };
    const Case cases[] = {
        {c, c, T(1), "o at the centre"},
        {c + Vec3<T>(T(0.5), T(0), T(0)), c, T(1), "o inside"},
        {c + Vec3<T>(T(0), T(2), T(0)), c, T(2), "o on the surface"},
        {Vec3<T>(T(0)), c, T(0), "zero radius"},
        {Vec3<T>(T(0)), c, T(-1), "negative radius"},
        {Vec3<T>(T(0)), c, nan, "NaN radius"},
        {Vec3<T>(T(0)), c, inf, "infinite radius"},
        {Vec3<T>(nan, T(0), T(0)), c, T(1), "NaN shading point"},
        {Vec3<T>(T(0)), Vec3<T>(inf, T(0), T(0)), T(1), "infinite centre"},
    };
    for (const Case& k : cases) {
        INFO(k.what);
        auto check = [&](const auto& light) {
            CHECK(light.empty());
            CHECK(light.solid_angle() == T(0));
            for (const Vec2<T> u : {Vec2<T>(T(0.3), T(0.6)), Vec2<T>(T(0), T(1)), Vec2<T>(nan, T(0.5))}) {
                const auto s = light.sample(u);
                CHECK(s.pdf == T(0));
                CHECK(s.distance == T(0));
                CHECK(std::isfinite(double(s.direction.x + s.direction.y + s.direction.z)));
            }
            CHECK(light.pdf(Vec3<T>(T(0), T(0), T(1))) == T(0));
            const Vec2<T> v = light.invert(Vec3<T>(T(0), T(0), T(1)));
            CHECK((std::isfinite(double(v.x)) && std::isfinite(double(v.y))));
        };
        check(apse::SphereLight<apse::LdRadialMap<T>>(k.o, k.c, k.r));
        check(apse::SphereLight<apse::ParallelMap<T>>(k.o, k.c, k.r));
        check(apse::SphereLight<apse::TabulatedLdRadialMap<T>>(k.o, k.c, k.r, apse_test::default_table().view()));
        CHECK(apse::sphere_light_pdf<apse::LdRadialMap<T>>(k.o, k.c, k.r, Vec3<T>(T(0), T(0), T(1))) == T(0));
    }
    // a NaN u on a valid light: no sample
    const apse::SphereLight<apse::LdRadialMap<T>> light(Vec3<T>(T(0)), c, T(1));
    CHECK(light.sample(Vec2<T>(nan, T(0.5))).pdf == T(0));
    CHECK(light.sample(Vec2<T>(nan, T(0.5))).distance == T(0));
}

TEMPLATE_TEST_CASE("sphere light: far and near spheres at the range limits", "[sphere_light][robust]", float, double) {
    using T = TestType;
    // Coordinates near T's largest and smallest scales: the distance stays finite and accurate
    // (robust_length and the overflow-free hit distance), relative to the reference.
    const T big = sizeof(T) == 4 ? T(1e30) : T(1e300), tiny = sizeof(T) == 4 ? T(1e-30) : T(1e-300);
    for (T scale : {big, tiny}) {
        const Vec3<T> c(scale * T(0.5), scale * T(-0.25), scale * T(0.75)), o(T(0));
        const T r = scale * T(0.1);
        const apse::SphereLight<apse::LdRadialMap<T>> light(o, c, r);
        REQUIRE_FALSE(light.empty());
        const auto s = light.sample(Vec2<T>(T(0.3), T(0.7)));
        REQUIRE(s.pdf > T(0));
        const long double t_ref = hit_reference(glm::dvec3(o), glm::dvec3(c), double(r), glm::dvec3(s.direction));
        CHECK(std::fabs(s.distance - t_ref) <= 64 * double(apse::epsilon<T>()) * t_ref);
    }
}
