// disk_light.hpp: the one-call disk-light sampler DiskLight<Sampler> — directions, points on the
// disk, distances and pdfs, against an independent quadrature of the disk's solid angle; MIS pdf
// (the stateless disk_light_pdf<Sampler> equals every sampler's own density: exact, tabulated,
// cosine-weighted); the map chosen at run time (DiskLight<RuntimeSampler<T>>: bit for bit the
// light of the map's own type); its size; mixed scalar arguments; bad input.
#include <apse/disk_light.hpp>
#include <apse/projection.hpp>
#include <apse/baselines/area.hpp>
#include <apse/math.hpp>
#include <apse/comparison.hpp>
#include <apse/cosine_weighted.hpp>
#include <apse/runtime_sampler.hpp>

#include "support/map_testing.hpp"

#include "support/catch.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <limits>
#include <type_traits>

namespace {
template <class T> using Vec2 = glm::vec<2, T>;
template <class T> using Vec3 = glm::vec<3, T>;
/// The light whose map is chosen at run time.
template <class T> using RuntimeLight = apse::DiskLight<apse::RuntimeSampler<T>>;
const apse::MapKind kMaps[] = {apse::MapKind::radial, apse::MapKind::ld_radial, apse::MapKind::parallel};
const apse::MapKind kAllMaps[] = {apse::MapKind::radial, apse::MapKind::ld_radial, apse::MapKind::parallel,
                                  apse::MapKind::tabulated, apse::MapKind::tabulated_ld_radial};
/// True for the maps that read a tabulation table.
constexpr bool is_tabulated(apse::MapKind m) {
    return m == apse::MapKind::tabulated || m == apse::MapKind::tabulated_ld_radial;
}
// Passed to GPU kernels by value: plain data. DiskLight<RuntimeSampler> holds only the chosen map
// (a union); DiskLight<Map> the map itself.
static_assert(std::is_trivially_copyable<RuntimeLight<float>>::value, "DiskLight must be trivially copyable");
static_assert(std::is_trivially_copyable<RuntimeLight<double>>::value, "DiskLight must be trivially copyable");
static_assert(std::is_trivially_copyable<apse::DiskLight<apse::TabulatedLdRadialMap<float>>>::value,
              "DiskLight must be trivially copyable");
static_assert(std::is_trivially_copyable<apse::DiskLight<apse::CosineWeighted<apse::ParallelMap<double>>>>::value,
              "DiskLight must be trivially copyable");
static_assert(sizeof(RuntimeLight<double>) <
                  sizeof(apse::CosineWeighted<apse::LdRadialMap<double>>) + sizeof(apse::ParallelMap<double>),
              "DiskLight<RuntimeSampler> holds one sampler, not several");

/// f(static_cast<Map*>(nullptr)) for the map type of the kind `m` (a type tag: the test names the
/// compile-time type the RuntimeSampler of that kind stands for).
template <class T, class F> void with_map_type(apse::MapKind m, F&& f) {
    switch (m) {
    case apse::MapKind::radial: f(static_cast<apse::RadialMap<T>*>(nullptr)); return;
    case apse::MapKind::ld_radial: f(static_cast<apse::LdRadialMap<T>*>(nullptr)); return;
    case apse::MapKind::parallel: f(static_cast<apse::ParallelMap<T>*>(nullptr)); return;
    case apse::MapKind::tabulated: f(static_cast<apse::TabulatedMap<T>*>(nullptr)); return;
    case apse::MapKind::tabulated_ld_radial: f(static_cast<apse::TabulatedLdRadialMap<T>*>(nullptr)); return;
    }
    FAIL("unknown MapKind " << int(m));
}

using apse::detail::reads_table;  // whether Map is built from an ellipse and a table

/// DiskLight<Map> of the disk (c, n, r) seen from o; the tabulated maps read `table`.
template <class Map, class T>
apse::DiskLight<Map> typed_light(const Vec3<T>& o, const Vec3<T>& c, const Vec3<T>& n, T r, const apse::TabulationView& table) {
    if constexpr (reads_table<Map>) return apse::DiskLight<Map>(o, c, n, r, table);
    else return apse::DiskLight<Map>(o, c, n, r);
}

/// DiskLight<CosineWeighted<Map>> of the same disk for the receiver normal nr.
template <class Map, class T>
apse::DiskLight<apse::CosineWeighted<Map>> typed_cosine_light(const Vec3<T>& o, const Vec3<T>& c, const Vec3<T>& n, T r,
                                                              const apse::TabulationView& table, const Vec3<T>& nr) {
    if constexpr (reads_table<Map>) return apse::DiskLight<apse::CosineWeighted<Map>>(o, c, n, r, table, nr);
    else return apse::DiskLight<apse::CosineWeighted<Map>>(o, c, n, r, nr);
}

/// The same bits (NaN payloads and the sign of zero included).
template <class T> bool same_bits(T a, T b) { return std::memcmp(&a, &b, sizeof(T)) == 0; }
}  // namespace

TEMPLATE_TEST_CASE("disk light: point, distance and pdf", "[disk_light]", float, double) {
    using T = TestType;
    // A tilted disk in a general position: o, centre, a non-unit normal, radius 0.8. The
    // solid angle is checked against apse_test::DiskCells quadrature (independent of apse) in the
    // disk's own frame: 1e-12 relative in double (the quadrature's own accuracy with 24 x 24
    // nodes per cell on 4 x 16 cells), 1e-5 in float (a few float eps of the projection and R_J).
    const Vec3<T> o(T(0.3), T(-0.2), T(1.5)), c(T(1), T(0.5), T(-0.5)), n(T(0.2), T(-0.1), T(2));
    const T r = T(0.8);
    // independent solid angle: disk frame with d = height of o, h = distance of its foot to c
    const glm::dvec3 nd = glm::normalize(glm::dvec3(n)), od(o), cd(c);
    const double d = std::fabs(glm::dot(od - cd, nd));
    const glm::dvec3 foot = od - glm::dot(od - cd, nd) * nd;
    const double h = glm::length(cd - foot);
    const apse_test::DiskCells cells{d, h, double(r), 4, 16};
    double omega_ref = 0;
    for (double v : cells.solid_angles(24)) omega_ref += v;
    const double tol_omega = sizeof(T) == 4 ? 1e-5 : 1e-12;
    // hit-point tolerance: |p - c| <= r (1 + 64 eps (1 + |c - o| / d))
    const double eps = double(apse::epsilon<T>());
    const double tol_hit = 64 * eps * (1 + glm::length(cd - od) / d);
    apse_test::Rng rng(9);
    const apse::DiskFrame<T> frame = apse::DiskFrame<T>::make(c, n, r);
    for (int from_frame = 0; from_frame < 2; ++from_frame)
    for (apse::MapKind m : kMaps) {
        // the light from the disk's parameters, or from its stored frame (the same checks)
        const RuntimeLight<T> light = from_frame ? RuntimeLight<T>(o, frame, m) : RuntimeLight<T>(o, c, n, r, m);
        INFO("map " << int(m) << (from_frame ? ", from the stored frame" : ""));
        CHECK(std::fabs(double(light.solid_angle()) - omega_ref) / omega_ref <= tol_omega);
        for (int i = 0; i < 500; ++i) {
            const Vec2<T> u(rng.uniform<T>(), rng.uniform<T>());
            const auto s = light.sample(u);
            REQUIRE(s.pdf > T(0));
            CHECK(std::fabs(double(s.pdf) * omega_ref - 1) <= tol_omega);
            // the point is on the disk, along the direction, at the distance
            const glm::dvec3 p(s.point);
            CHECK(std::fabs(glm::dot(p - cd, nd)) <= tol_hit * (1 + glm::length(cd)));
            CHECK(glm::length(p - cd) <= double(r) * (1 + tol_hit));
            CHECK(glm::length(p - (od + double(s.distance) * glm::dvec3(s.direction))) <= tol_hit * (1 + glm::length(p)));
            CHECK(std::fabs(glm::length(glm::dvec3(s.direction)) - 1) <= 8 * eps);
            // MIS: the pdf of the sampled direction, by the light and by the free function
            CHECK(light.pdf(s.direction) == s.pdf);
            if (!from_frame) CHECK(apse::disk_light_pdf<apse::LdRadialMap<T>>(o, c, n, r, s.direction) == s.pdf);
            // the inverse gives the square point back (away from seams)
            if (u.x > T(0.01) && u.x < T(0.99) && u.y > T(0.01) && u.y < T(0.99)) {
                const Vec2<T> back = light.invert(s.direction);
                CHECK(std::fabs(double(back.x - u.x)) <= (sizeof(T) == 4 ? 1e-3 : 1e-9));
                CHECK(std::fabs(double(back.y - u.y)) <= (sizeof(T) == 4 ? 1e-3 : 1e-9));
            }
        }
        // directions that miss the disk have pdf 0
        CHECK(light.pdf(-light.ellipse().z) == T(0));
        CHECK(apse::disk_light_pdf<apse::LdRadialMap<T>>(o, c, n, r, Vec3<T>(-light.ellipse().z)) == T(0));
        // a one-shot light (built and sampled in one expression) agrees with the kept one
        if (from_frame) continue;
        const auto s1 = RuntimeLight<T>(o, c, n, r, m).sample(Vec2<T>(T(0.3), T(0.8)));
        const auto s2 = light.sample(Vec2<T>(T(0.3), T(0.8)));
        CHECK(s1.direction == s2.direction);
        CHECK(s1.pdf == s2.pdf);
    }
}

// The stored-frame constructors for every map, plain and cosine-weighted: each light's own
// consistency (pdf(direction) == reported pdf, points on the disk) and agreement with the light
// built from the disk's parameters. Tolerance: the two ellipses agree within the projection's
// budget (a few eps times its condition, "project_disk from a stored DiskFrame"); every density
// here is a smooth function of the ellipse and of u, so the pdfs agree to 1e-4 (float) / 1e-10
// (double) relative, ~100 times that budget for this moderate configuration (a sample at a
// tabulated bin edge could differ by up to 1 %: none in this configuration).
TEMPLATE_TEST_CASE("disk light from a stored DiskFrame: every map, plain and cosine-weighted", "[disk_light]", float,
                   double) {
    using T = TestType;
    const Vec3<T> o(T(0.3), T(-0.2), T(1.5)), c(T(1), T(0.5), T(-0.5)), n(T(0.2), T(-0.1), T(2)), nr(T(0.1), T(0.3), T(-1));
    const T r = T(0.8);
    const apse::DiskFrame<T> frame = apse::DiskFrame<T>::make(c, n, r);
    const apse::TabulationView table = apse::default_table().view();
    const double tol = sizeof(T) == 4 ? 1e-4 : 1e-10;
    // pdf(direction) recomputes the density from the direction's azimuth: within 1e-3 (float) /
    // 1e-9 (double) of the sampled pdf, as in "the stateless pdf is every sampler's own density"
    const double self_tol = sizeof(T) == 4 ? 1e-3 : 1e-9;
    const glm::dvec3 cd(c), nd = glm::normalize(glm::dvec3(n));
    apse_test::Rng rng(17);
    for (int cosine = 0; cosine < 2; ++cosine)
        for (apse::MapKind m : kAllMaps) {
            INFO("map " << int(m) << (cosine ? ", cosine-weighted" : ""));
            const RuntimeLight<T> framed = cosine ? RuntimeLight<T>(o, frame, m, table, nr) : RuntimeLight<T>(o, frame, m, table);
            const RuntimeLight<T> plain = cosine ? RuntimeLight<T>(o, c, n, r, m, table, nr) : RuntimeLight<T>(o, c, n, r, m, table);
            REQUIRE_FALSE(framed.empty());
            CHECK(framed.cosine_weighted() == bool(cosine));
            for (int i = 0; i < 200; ++i) {
                const Vec2<T> u(rng.uniform<T>(), rng.uniform<T>());
                const auto s = framed.sample(u), p = plain.sample(u);
                REQUIRE(s.pdf > T(0));
                if (!cosine && !is_tabulated(m)) CHECK(framed.pdf(s.direction) == s.pdf);  // 1/Omega
                else CHECK(std::fabs(double(framed.pdf(s.direction)) / double(s.pdf) - 1) <= self_tol);
                CHECK(std::fabs(double(s.pdf) / double(p.pdf) - 1) <= tol);
                CHECK(glm::length(glm::dvec3(s.direction) - glm::dvec3(p.direction)) <= tol);
                CHECK(std::fabs(glm::dot(glm::dvec3(s.point) - cd, nd)) <= tol);
            }
        }
    // the table-free constructors: exact maps (the map's own type, or its kind without a table);
    // a tabulated map without a table is the empty light
    const apse::DiskLight<apse::LdRadialMap<T>> ld(o, frame);
    CHECK_FALSE(ld.empty());
    CHECK(RuntimeLight<T>(o, frame, apse::MapKind::ld_radial).sampler().kind() == apse::MapKind::ld_radial);
    CHECK(RuntimeLight<T>(o, frame, apse::MapKind::ld_radial).sample(Vec2<T>(T(0.4), T(0.6))).pdf ==
          ld.sample(Vec2<T>(T(0.4), T(0.6))).pdf);
    CHECK(RuntimeLight<T>(o, frame, apse::MapKind::parallel, nr).cosine_weighted());
    CHECK(apse::DiskLight<apse::CosineWeighted<apse::ParallelMap<T>>>(o, frame, nr).cosine_weighted());
    // cosine_weighted() is whether the samples are: not for a zero receiver normal (the plain
    // map) nor for the light below the receiver's horizon (empty)
    CHECK_FALSE(RuntimeLight<T>(o, frame, apse::MapKind::parallel, Vec3<T>(0)).cosine_weighted());
    CHECK_FALSE(RuntimeLight<T>(o, frame, apse::MapKind::tabulated_ld_radial, table, Vec3<T>(0)).cosine_weighted());
    CHECK_FALSE(apse::DiskLight<apse::CosineWeighted<apse::ParallelMap<T>>>(o, frame, Vec3<T>(0)).cosine_weighted());
    const RuntimeLight<T> below(o, frame, apse::MapKind::tabulated_ld_radial, table, -(frame.center - o));
    CHECK(below.empty());
    CHECK_FALSE(below.cosine_weighted());
    const apse::DiskLight<apse::CosineWeighted<apse::TabulatedLdRadialMap<T>>> below_typed(o, frame, table,
                                                                                           -(frame.center - o));
    CHECK(below_typed.empty());
    CHECK_FALSE(below_typed.cosine_weighted());
    CHECK(RuntimeLight<T>(o, frame, apse::MapKind::tabulated).empty());
    // an invalid frame gives the empty light
    const T nan = std::numeric_limits<T>::quiet_NaN();
    for (const apse::DiskFrame<T>& bad : {apse::DiskFrame<T>::make(c, n, T(0)), apse::DiskFrame<T>::make(c, Vec3<T>(0), r),
                                          apse::DiskFrame<T>::make(Vec3<T>(nan, 0, 0), n, r)}) {
        CHECK(apse::project_disk(o, bad).empty());
        const RuntimeLight<T> light(o, bad, apse::MapKind::tabulated_ld_radial, table, nr);
        CHECK(light.empty());
        CHECK(light.sample(Vec2<T>(T(0.4), T(0.6))).pdf == T(0));
    }
    // o in the disk's plane (exactly: a disk in the plane z = -0.5), or not finite: empty
    const apse::DiskFrame<T> flat = apse::DiskFrame<T>::make(c, Vec3<T>(0, 0, 1), r);
    CHECK(apse::project_disk(Vec3<T>(T(3), T(-1), T(-0.5)), flat).empty());
    CHECK_FALSE(apse::project_disk(Vec3<T>(T(3), T(-1), T(-0.25)), flat).empty());
    CHECK(apse::project_disk(Vec3<T>(nan, 0, 0), frame).empty());
}

TEMPLATE_TEST_CASE("disk light: degenerate and bad input", "[disk_light][robust]", float, double) {
    using T = TestType;
    const T nan = std::numeric_limits<T>::quiet_NaN(), inf = std::numeric_limits<T>::infinity();
    auto finite3 = [](const Vec3<T>& v) { return apse::detail::is_finite(v.x) && apse::detail::is_finite(v.y) && apse::detail::is_finite(v.z); };
    const Vec3<T> o(0), c(0, 0, -1), n(0, 0, 1);
    struct Case { Vec3<T> o, c, n; T r; };
    const Case bad[] = {
        {o, c, n, T(0)},                    // zero radius
        {o, c, n, T(-1)},                   // negative radius
        {o, c, Vec3<T>(0), T(1)},           // zero normal
        {o, c, n, nan},                     // NaN radius
        {Vec3<T>(nan, 0, 0), c, n, T(1)},   // NaN origin
        {o, Vec3<T>(inf, 0, -1), n, T(1)},  // infinite centre
        {Vec3<T>(0, 0, -1), c, n, T(1)},    // o on the disk
        {Vec3<T>(5, 0, -1), c, n, T(1)},    // o in the disk's plane
    };
    for (const Case& b : bad)
        for (apse::MapKind m : kMaps) {
            const RuntimeLight<T> light(b.o, b.c, b.n, b.r, m);
            const auto s = light.sample(Vec2<T>(T(0.4), T(0.6)));
            CHECK(s.pdf == T(0));
            CHECK(finite3(s.direction));
            CHECK(light.pdf(Vec3<T>(0, 0, -1)) == T(0));
            CHECK(apse::disk_light_pdf<apse::LdRadialMap<T>>(b.o, b.c, b.n, b.r, Vec3<T>(0, 0, -1)) == T(0));
        }
    for (apse::MapKind m : kMaps) {
        const RuntimeLight<T> light(o, c, n, T(1), m);
        CHECK(light.sample(Vec2<T>(nan, T(0.5))).pdf == T(0));
        const auto s = light.sample(Vec2<T>(T(2), T(-1)));  // clamped onto the square
        CHECK(s.pdf > T(0));
        CHECK(finite3(s.point));
        // o behind the disk: the same ellipse (two-sided), the point on the disk
        const RuntimeLight<T> behind(Vec3<T>(0, 0, -2), c, n, T(1), m);
        const auto sb = behind.sample(Vec2<T>(T(0.25), T(0.75)));
        CHECK(sb.pdf > T(0));
        CHECK(std::fabs(double(sb.point.z) + 1) <= 1e-5);
    }
}

namespace {
/// A random disk light and shading point: centre in [-2, 2]^3, a random non-unit normal,
/// radius log-uniform in [0.05, 3], o in [-3, 3]^3 (either side of the disk), and a random
/// receiver normal (half of them facing the disk's centre).
template <class T> struct Scene {
    Vec3<T> o, c, n, rn;
    T r;
};
template <class T> Scene<T> random_scene(apse_test::Rng& rng) {
    auto u = [&](double a, double b) { return T(a + (b - a) * rng.uniform<double>()); };
    Scene<T> s;
    s.c = Vec3<T>(u(-2, 2), u(-2, 2), u(-2, 2));
    s.n = Vec3<T>(u(-1, 1), u(-1, 1), u(-1, 1));
    s.r = T(0.05 * std::pow(60.0, rng.uniform<double>()));
    s.o = Vec3<T>(u(-3, 3), u(-3, 3), u(-3, 3));
    s.rn = Vec3<T>(u(-1, 1), u(-1, 1), u(-1, 1));
    if (rng.uniform<double>() < 0.5 && glm::dot(s.rn, s.c - s.o) < T(0)) s.rn = -s.rn;
    return s;
}
}  // namespace

TEMPLATE_TEST_CASE("disk light: the stateless pdf is every sampler's own density (MIS)", "[disk_light][mis]", float,
                   double) {
    using T = TestType;
    // For every map, plain and cosine-weighted, at random lights and shading points:
    // * disk_light_pdf<RuntimeSampler<T>>(o, c, n, r, w, map, table[, n_r]) ==
    //   DiskLight<RuntimeSampler<T>>(o, c, n, r, map, table[, n_r]).pdf(w) bit for bit, for
    //   sampled directions and for random directions (hits and misses): a renderer's stateless MIS
    //   query and its light object agree exactly — where the compiler cannot contract a·b + c
    //   into an FMA (__FP_FAST_FMA undefined). With contraction (-march=x86-64-v3
    //   -ffp-contract=fast, AArch64) one source inlined at two call sites may round differently:
    //   then they agree to the tolerance below (measured: only the cosine-weighted parallel map,
    //   whose Newton inversion differs by ~1e-6 float, differs at all), a flip across a tabulated
    //   bin edge or the rim being allowed in < 1 % of the directions;
    // * at a sampled direction it equals the pdf sample() reported: exactly for the exact maps (1/Omega
    //   both ways); for the maps that recompute a density from the direction (tabulated, cosine)
    //   to rounding — relative 1e-3 float / 1e-9 double: the tabulated density is recomputed from the
    //   direction's azimuth through atan2 and the cosine warp from the map's inverse, whose float
    //   error grows for small lights (a direction rounded to float is ~1e-5 of a 0.01-rad ellipse,
    //   times the warp's slope: measured worst 1.5e-4 float), except within a few ulps of a tabulated bin edge,
    //   where the recomputed azimuth may fall into the neighbouring bin (densities of adjacent bins
    //   differ by < 1 %: allowed 2 %, and such samples must stay rare, < 1 %);
    // * the point is on the disk, along the direction, at the distance (as the exact maps' test).
    // So the balance-heuristic weights p_l/(p_l + p_b) of the light sample and p_b/(p_l + p_b) of a
    // BSDF sample use one density and sum to 1.
    const double tol = sizeof(T) == 4 ? 1e-3 : 1e-9;
    const double eps = double(apse::epsilon<T>());
    const apse::TabulationView table = apse::default_table().view();
    apse_test::Rng rng(sizeof(T) == 4 ? 31 : 32);
    int checked = 0, edge = 0, hits = 0, misses = 0, exact_checked = 0, flips = 0;
#if defined(__FP_FAST_FMA) || defined(__FP_FAST_FMAF)
    const bool may_contract = true;
#else
    const bool may_contract = false;
#endif
    for (int scene = 0; scene < 60; ++scene) {
        const Scene<T> sc = random_scene<T>(rng);
        for (apse::MapKind m : kAllMaps)
            for (int cosine = 0; cosine < 2; ++cosine) {
                INFO("scene " << scene << " map " << int(m) << " cosine " << cosine);
                const RuntimeLight<T> light = cosine ? RuntimeLight<T>(sc.o, sc.c, sc.n, sc.r, m, table, sc.rn)
                                                     : RuntimeLight<T>(sc.o, sc.c, sc.n, sc.r, m, table);
                const auto stateless = [&](const Vec3<T>& w) {
                    return cosine ? apse::disk_light_pdf<apse::RuntimeSampler<T>>(sc.o, sc.c, sc.n, sc.r, w, m, table, sc.rn)
                                  : apse::disk_light_pdf<apse::RuntimeSampler<T>>(sc.o, sc.c, sc.n, sc.r, w, m, table);
                };
                const auto agree = [&](T p, T q) {  // stateless p, light q
                    if (!may_contract || p == q) {
                        CHECK(p == q);
                        return;
                    }
                    const double rel = p > T(0) && q > T(0) ? std::fabs(double(p) / double(q) - 1) : 1.0;
                    INFO("stateless " << p << " light " << q);
                    if (rel > tol) {
                        ++flips;
                        CHECK((rel < 0.02 || !(p > T(0)) || !(q > T(0))));
                    }
                };
                const glm::dvec3 od(sc.o), cd(sc.c), nd = glm::normalize(glm::dvec3(sc.n));
                const double height = std::fabs(glm::dot(od - cd, nd));
                const double tol_hit = 64 * eps * (1 + glm::length(cd - od) / height);
                for (int i = 0; i < 40; ++i) {
                    const Vec2<T> u(rng.uniform<T>(), rng.uniform<T>());
                    const auto s = light.sample(u);
                    if (!(s.pdf > T(0))) continue;  // light below the receiver's horizon
                    const T p = stateless(s.direction);
                    agree(p, light.pdf(s.direction));
                    const double rel = std::fabs(double(p) / double(s.pdf) - 1);
                    INFO("pdf " << p << " sampled " << s.pdf << " relative difference " << rel);
                    if (!cosine && !is_tabulated(m)) {
                        agree(p, s.pdf);
                        ++exact_checked;
                    } else if (rel > tol) {
                        ++edge;
                        CHECK(is_tabulated(m));  // only the tabulated bins have edges
                        CHECK(rel < 0.02);
                    }
                    ++checked;
                    const glm::dvec3 pt(s.point);
                    CHECK(std::fabs(glm::dot(pt - cd, nd)) <= tol_hit * (1 + glm::length(cd)));
                    CHECK(glm::length(pt - cd) <= double(sc.r) * (1 + tol_hit));
                    CHECK(glm::length(pt - (od + double(s.distance) * glm::dvec3(s.direction))) <=
                          tol_hit * (1 + glm::length(pt)));
                }
                // random directions: towards random points of the disk's plane around it (hits and
                // misses near the rim) and uniform on the sphere (mostly misses)
                const Vec3<T> e1 = Vec3<T>(apse::detail::any_perpendicular(nd)), e2 = Vec3<T>(glm::cross(nd, glm::dvec3(e1)));
                for (int i = 0; i < 40; ++i) {
                    const T a = T(6.283185307179586) * rng.uniform<T>(), rho = T(1.3) * sc.r * std::sqrt(rng.uniform<T>());
                    const Vec3<T> w = i % 2 ? sc.c + rho * (std::cos(a) * e1 + std::sin(a) * e2) - sc.o
                                            : Vec3<T>(rng.uniform<T>() - T(0.5), rng.uniform<T>() - T(0.5),
                                                      rng.uniform<T>() - T(0.5));
                    const T p = stateless(w);
                    agree(p, light.pdf(w));
                    (p > T(0) ? hits : misses) += 1;
                }
            }
    }
    std::printf("[%s] stateless pdf: %d sampled directions (%d exact maps), %d near a tabulated bin edge; "
                "%d random directions hit, %d missed; FMA contraction %s, %d flips\n", sizeof(T) == 4 ? "float" : "double",
                checked, exact_checked, edge, hits, misses, may_contract ? "possible" : "impossible", flips);
    CHECK(edge * 100 < checked);
    CHECK(flips * 100 < checked + hits + misses);
    CHECK(hits > 1000);    // both branches of the query are exercised
    CHECK(misses > 1000);
}

TEMPLATE_TEST_CASE("disk light: its size is the sampler's and three vectors", "[disk_light][api]", float, double) {
    using T = TestType;
    // DiskLight<Sampler> holds the shading point, the disk's centre and normal, and the sampler:
    // nothing else (the former DiskLight<T> held a union of every sampler it could be, whatever
    // the map; DiskLight<RuntimeSampler<T>> still does, a static_assert above bounds it).
    using V = glm::vec<3, T>;
    INFO("sizeof(DiskLight<TabulatedLdRadialMap>) " << sizeof(apse::DiskLight<apse::TabulatedLdRadialMap<T>>)
                                                    << ", sizeof(TabulatedLdRadialMap) "
                                                    << sizeof(apse::TabulatedLdRadialMap<T>) << ", 3 vectors "
                                                    << 3 * sizeof(V));
    CHECK(sizeof(apse::DiskLight<apse::TabulatedLdRadialMap<T>>) <= sizeof(apse::TabulatedLdRadialMap<T>) + 3 * sizeof(V));
}

TEMPLATE_TEST_CASE("disk light: RuntimeSampler is bit for bit the map's own type", "[disk_light]", float, double) {
    using T = TestType;
    // DiskLight<RuntimeSampler<T>>(..., kind, table[, n_r]) and DiskLight<Map>(...[, table])
    // (DiskLight<CosineWeighted<Map>>(...[, table], n_r)) run the same code on the same inputs:
    // the same sample (direction, pdf, point, distance), pdf and invert, bit for bit, for every
    // kind, plain and cosine-weighted, at random lights and shading points (sampled directions,
    // directions towards the disk's plane around it, uniform directions). Where the compiler may
    // contract a·b + c into FMAs (__FP_FAST_FMA; the fma-nosimd configuration) the map's code
    // inlined at two call sites may round differently, as for the stateless pdf above: then
    // they agree to 1e-3 (float) / 1e-9 (double) relative (absolute below 1), with < 1 % flips
    // (a tabulated bin edge, the rim, a seam of the square) beyond that.
#if defined(__FP_FAST_FMA) || defined(__FP_FAST_FMAF)
    const bool may_contract = true;
#else
    const bool may_contract = false;
#endif
    const double tol = sizeof(T) == 4 ? 1e-3 : 1e-9;
    const apse::TabulationView table = apse::default_table().view();
    apse_test::Rng rng(sizeof(T) == 4 ? 41 : 42);
    long compared = 0, flips = 0, sampled = 0;
    const auto match = [&](T a, T b) {  // runtime a, typed b
        ++compared;
        if (same_bits(a, b)) return;
        INFO("runtime " << a << " typed " << b);
        if (!may_contract) {
            CHECK(same_bits(a, b));
            return;
        }
        const double scale = std::max({1.0, std::fabs(double(a)), std::fabs(double(b))});
        if (!(std::fabs(double(a) - double(b)) <= tol * scale)) ++flips;
    };
    const auto match2 = [&](const Vec2<T>& a, const Vec2<T>& b) {
        match(a.x, b.x);
        match(a.y, b.y);
    };
    const auto match3 = [&](const Vec3<T>& a, const Vec3<T>& b) {
        match(a.x, b.x);
        match(a.y, b.y);
        match(a.z, b.z);
    };
    for (int scene = 0; scene < 30; ++scene) {
        const Scene<T> sc = random_scene<T>(rng);
        const glm::dvec3 nd = glm::normalize(glm::dvec3(sc.n));
        const Vec3<T> e1 = Vec3<T>(apse::detail::any_perpendicular(nd)), e2 = Vec3<T>(glm::cross(nd, glm::dvec3(e1)));
        for (apse::MapKind m : kAllMaps)
            for (int cosine = 0; cosine < 2; ++cosine)
                with_map_type<T>(m, [&](auto* tag) {
                    using Map = std::remove_pointer_t<decltype(tag)>;
                    INFO("scene " << scene << " map " << int(m) << " cosine " << cosine);
                    const RuntimeLight<T> runtime = cosine ? RuntimeLight<T>(sc.o, sc.c, sc.n, sc.r, m, table, sc.rn)
                                                           : RuntimeLight<T>(sc.o, sc.c, sc.n, sc.r, m, table);
                    const auto compare = [&](const auto& typed) {
                        CHECK(runtime.sampler().kind() == m);
                        CHECK(runtime.sampler().cosine() == bool(cosine));
                        CHECK(runtime.empty() == typed.empty());
                        CHECK(runtime.cosine_weighted() == typed.cosine_weighted());
                        for (int i = 0; i < 24; ++i) {
                            const Vec2<T> u(rng.uniform<T>(), rng.uniform<T>());
                            const auto a = runtime.sample(u), b = typed.sample(u);
                            match3(a.direction, b.direction);
                            match(a.pdf, b.pdf);
                            match3(a.point, b.point);
                            match(a.distance, b.distance);
                            if (a.pdf > T(0)) ++sampled;
                            // at the sampled direction (each light's own: equal where the samples are)
                            match(runtime.pdf(a.direction), typed.pdf(a.direction));
                            match2(runtime.invert(a.direction), typed.invert(a.direction));
                        }
                        for (int i = 0; i < 24; ++i) {
                            const T a = T(6.283185307179586) * rng.uniform<T>(), rho = T(1.3) * sc.r * std::sqrt(rng.uniform<T>());
                            const Vec3<T> w = i % 2 ? sc.c + rho * (std::cos(a) * e1 + std::sin(a) * e2) - sc.o
                                                    : Vec3<T>(rng.uniform<T>() - T(0.5), rng.uniform<T>() - T(0.5),
                                                              rng.uniform<T>() - T(0.5));
                            match(runtime.pdf(w), typed.pdf(w));
                            match2(runtime.invert(w), typed.invert(w));
                        }
                    };
                    if (cosine) compare(typed_cosine_light<Map>(sc.o, sc.c, sc.n, sc.r, table, sc.rn));
                    else compare(typed_light<Map>(sc.o, sc.c, sc.n, sc.r, table));
                });
    }
    std::printf("[%s] RuntimeSampler vs the map's type: %ld values compared (%ld samples), FMA contraction %s, %ld flips\n",
                sizeof(T) == 4 ? "float" : "double", compared, sampled, may_contract ? "possible" : "impossible", flips);
    CHECK(sampled > 5000);
    CHECK(flips * 100 < compared);
}

TEMPLATE_TEST_CASE("disk light: the exact maps' pdf is not the tabulated density", "[disk_light][mis]", float, double) {
    using T = TestType;
    // Why the tabulated maps need their own stateless query: the exact maps' disk_light_pdf
    // (disk_light_pdf<LdRadialMap<T>>: 1/Omega) differs from the tabulated density by up to the table's error (0.44 % for the
    // default table, docs/tabulated.md), far above rounding, for a close, large light (a unit
    // disk seen from 0.03 above its plane, 0.9 from its centre: alpha ~ 1.50).
    const Vec3<T> o(0), c(T(0.9), T(0), T(-0.03)), n(0, 0, 1);
    const apse::TabulationView table = apse::default_table().view();
    const apse::DiskLight<apse::TabulatedLdRadialMap<T>> light(o, c, n, T(1), table);
    double worst = 0;
    for (int i = 0; i < 32; ++i)
        for (int j = 0; j < 32; ++j) {
            const auto s = light.sample(Vec2<T>(T((i + 0.5) / 32), T((j + 0.5) / 32)));
            REQUIRE(s.pdf > T(0));
            worst = std::max(worst, std::fabs(double(apse::disk_light_pdf<apse::LdRadialMap<T>>(o, c, n, T(1), s.direction)) /
                                                  double(s.pdf) - 1));
        }
    // 1e-3: a thousand times float's rounding of either pdf (measured: 1.7e-3 in double at 64 x 64 points)
    std::printf("[%s] max |1/Omega / tabulated pdf − 1| = %.3g\n", sizeof(T) == 4 ? "float" : "double", worst);
    CHECK(worst > 1e-3);
    CHECK(worst < 0.0044 + 1e-4);  // the default table's documented bound (+ float rounding)
}

TEMPLATE_TEST_CASE("disk light: tabulated maps need a valid table", "[disk_light][robust]", float, double) {
    using T = TestType;
    const Vec3<T> o(0), c(T(0.3), T(0), T(-1)), n(0, 0, 1), w(T(0.3), T(0), T(-1));
    const apse::TabulationView none{nullptr, 0, 0, 0};
    for (apse::MapKind m : {apse::MapKind::tabulated, apse::MapKind::tabulated_ld_radial}) {
        // no table (the constructors without one) or an invalid view: the empty light
        const RuntimeLight<T> lights[] = {RuntimeLight<T>(o, c, n, T(1), m), RuntimeLight<T>(o, c, n, T(1), m, none),
                                          RuntimeLight<T>(o, c, n, T(1), m, Vec3<T>(0, 0, -1))};
        for (const auto& light : lights) {
            CHECK(light.sample(Vec2<T>(T(0.4), T(0.6))).pdf == T(0));
            CHECK(light.pdf(w) == T(0));
            CHECK(light.sampler().kind() == m);
        }
        // the map's own type with an invalid view, plain and cosine-weighted: the empty light too
        with_map_type<T>(m, [&](auto* tag) {
            using Map = std::remove_pointer_t<decltype(tag)>;
            if constexpr (reads_table<Map>) {
                const apse::DiskLight<Map> typed(o, c, n, T(1), none);
                const apse::DiskLight<apse::CosineWeighted<Map>> typed_lit(o, c, n, T(1), none, Vec3<T>(0, 0, -1));
                CHECK(typed.empty());
                CHECK(typed.sample(Vec2<T>(T(0.4), T(0.6))).pdf == T(0));
                CHECK(typed.pdf(w) == T(0));
                CHECK(typed_lit.empty());
                CHECK(typed_lit.sample(Vec2<T>(T(0.4), T(0.6))).pdf == T(0));
                CHECK(typed_lit.pdf(w) == T(0));
                CHECK(apse::disk_light_pdf<Map>(o, c, n, T(1), w, none) == T(0));
            } else {
                FAIL("a tabulated kind without a table-reading type");
            }
        });
        CHECK(apse::disk_light_pdf<apse::RuntimeSampler<T>>(o, c, n, T(1), w, m, none) == T(0));
        CHECK(apse::disk_light_pdf<apse::RuntimeSampler<T>>(o, c, n, T(1), w, m, none, Vec3<T>(0, 0, -1)) == T(0));
        CHECK(RuntimeLight<T>(o, c, n, T(1), m, none).sample(Vec2<T>(T(0.4), T(0.6))).pdf == T(0));
        // with the table: a sample, and the solid angle is the ellipse's
        const RuntimeLight<T> ok(o, c, n, T(1), m, apse::default_table().view());
        CHECK(ok.sample(Vec2<T>(T(0.4), T(0.6))).pdf > T(0));
        CHECK(ok.pdf(w) > T(0));
        CHECK(ok.solid_angle() == apse::detail::solid_angle_of(ok.ellipse()));
        // invert(sample(u)) = u (tolerance as test_tabulated's round trip: 2e-3 float, 1e-8
        // double, the conditioning of the azimuth of a direction rounded to T; u away from the
        // seams and the centre)
        for (const Vec2<T> u : {Vec2<T>(T(0.3), T(0.8)), Vec2<T>(T(0.7), T(0.2)), Vec2<T>(T(0.15), T(0.35))}) {
            const Vec2<T> back = ok.invert(ok.sample(u).direction);
            CHECK(std::fabs(double(back.x - u.x)) <= (sizeof(T) == 4 ? 2e-3 : 1e-8));
            CHECK(std::fabs(double(back.y - u.y)) <= (sizeof(T) == 4 ? 2e-3 : 1e-8));
        }
        const auto s1 = RuntimeLight<T>(o, c, n, T(1), m, apse::default_table().view()).sample(Vec2<T>(T(0.3), T(0.8)));
        const auto s2 = ok.sample(Vec2<T>(T(0.3), T(0.8)));
        CHECK(s1.direction == s2.direction);
        CHECK(s1.pdf == s2.pdf);
        const auto s3 = RuntimeLight<T>(o, c, n, T(1), m, apse::default_table().view(), Vec3<T>(0, 0, -1))
                            .sample(Vec2<T>(T(0.3), T(0.8)));
        const RuntimeLight<T> lit(o, c, n, T(1), m, apse::default_table().view(), Vec3<T>(0, 0, -1));
        CHECK(lit.cosine_weighted());
        CHECK(s3.pdf == lit.sample(Vec2<T>(T(0.3), T(0.8))).pdf);
    }
}

TEST_CASE("disk light: mixed scalar arguments (float vectors, double or int radius)", "[disk_light][api]") {
    // T comes from the vectors; the radius converts to it. Each call must compile, be the float
    // overload and give exactly the float call's result.
    const glm::vec3 o(0.1f, 0.2f, 0.0f), c(0.3f, 0.0f, -1.0f), n(0.0f, 0.2f, 1.0f), w(0.3f, -0.1f, -1.0f);
    const glm::vec2 u(0.3f, 0.7f);
    const auto e_f = apse::project_disk(o, c, n, 1.5f);
    const auto e_d = apse::project_disk(o, c, n, 1.5);
    const auto e_i = apse::project_disk(o, c, n, 2);
    static_assert(std::is_same<decltype(e_d), const apse::SphericalEllipse<float>>::value, "float result");
    static_assert(std::is_same<decltype(e_i), const apse::SphericalEllipse<float>>::value, "float result");
    CHECK(e_d.tan_alpha == e_f.tan_alpha);
    CHECK(e_d.z == e_f.z);
    CHECK(e_i.tan_beta == apse::project_disk(o, c, n, 2.0f).tan_beta);
    CHECK(apse::project_sphere(o, c, 0.5).tan_alpha == apse::project_sphere(o, c, 0.5f).tan_alpha);
    const apse::TabulationView table = apse::default_table().view();
    using RS = apse::RuntimeSampler<float>;
    static_assert(std::is_same<decltype(apse::disk_light_pdf<RS>(o, c, n, 1.5, w, apse::MapKind::ld_radial, table)), float>::value,
                  "float result");
    static_assert(std::is_same<decltype(apse::disk_light_pdf<apse::LdRadialMap<float>>(o, c, n, 2, w)), float>::value,
                  "float result");
    for (apse::MapKind m : kAllMaps) {
        CHECK(RuntimeLight<float>(o, c, n, 1.5, m, table).sample(u).pdf == RuntimeLight<float>(o, c, n, 1.5f, m, table).sample(u).pdf);
        CHECK(apse::disk_light_pdf<RS>(o, c, n, 1.5, w, m, table) == apse::disk_light_pdf<RS>(o, c, n, 1.5f, w, m, table));
        CHECK(apse::disk_light_pdf<RS>(o, c, n, 1.5, w, m, table, n) == apse::disk_light_pdf<RS>(o, c, n, 1.5f, w, m, table, n));
    }
    CHECK(RuntimeLight<float>(o, c, n, 1, apse::MapKind::parallel).sample(u).pdf ==
          RuntimeLight<float>(o, c, n, 1.0f, apse::MapKind::parallel).sample(u).pdf);
    CHECK(apse::disk_light_pdf<apse::LdRadialMap<float>>(o, c, n, 1.5, w) ==
          apse::disk_light_pdf<apse::LdRadialMap<float>>(o, c, n, 1.5f, w));
    // a double radius for a float light: converted (DiskLight<Sampler>'s sampler type is named,
    // not deduced, so its scalar comes from the sampler); class template argument deduction of
    // the area sampler: the radius does not take part either
    const apse::DiskLight<apse::LdRadialMap<float>> light(o, c, n, 1.5);
    const apse::DiskAreaSampler area(o, c, n, 1.5);
    static_assert(std::is_same<decltype(light)::T, float>::value, "float light");
    static_assert(std::is_same<decltype(area), const apse::DiskAreaSampler<float>>::value, "float sampler");
    CHECK(light.pdf(w) == apse::disk_light_pdf<apse::LdRadialMap<float>>(o, c, n, 1.5f, w));
    CHECK(area.pdf(w) == apse::DiskAreaSampler<float>(o, apse::DiskFrame<float>::make(c, n, 1.5f)).pdf(w));
    CHECK(apse::DiskFrame<float>::make(c, n, 2).radius == 2.0f);
    // double vectors with a float radius: the double overload
    const glm::dvec3 od(o), cd(c), nd(n);
    static_assert(std::is_same<decltype(apse::project_disk(od, cd, nd, 1.5f)), apse::SphericalEllipse<double>>::value,
                  "double result");
    CHECK(apse::project_disk(od, cd, nd, 1.5f).tan_alpha == apse::project_disk(od, cd, nd, 1.5).tan_alpha);
}
