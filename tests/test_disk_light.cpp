// disk_light.hpp: the one-call disk-light sampler — directions, points on the disk, distances and
// pdfs, against an independent quadrature of the disk's solid angle; MIS pdf; bad input.
#include <apse/disk_light.hpp>

#include "support/map_testing.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <type_traits>

namespace {
template <class T> using Vec2 = glm::vec<2, T>;
template <class T> using Vec3 = glm::vec<3, T>;
const apse::DiskMap kMaps[] = {apse::DiskMap::radial, apse::DiskMap::ld_radial, apse::DiskMap::parallel};
// Passed to GPU kernels by value: plain data. It holds only the chosen map (a union).
static_assert(std::is_trivially_copyable<apse::DiskLight<float>>::value, "DiskLight must be trivially copyable");
static_assert(std::is_trivially_copyable<apse::DiskLight<double>>::value, "DiskLight must be trivially copyable");
static_assert(sizeof(apse::DiskLight<double>) <
                  sizeof(apse::CosineWeighted<apse::LdRadialMap<double>>) + sizeof(apse::ParallelMap<double>),
              "DiskLight holds one sampler, not several");
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
    for (apse::DiskMap m : kMaps) {
        const apse::DiskLight<T> light(o, c, n, r, m);
        INFO("map " << int(m));
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
            CHECK(apse::disk_light_pdf(o, c, n, r, s.direction) == s.pdf);
            // the inverse gives the square point back (away from seams)
            if (u.x > T(0.01) && u.x < T(0.99) && u.y > T(0.01) && u.y < T(0.99)) {
                const Vec2<T> back = light.invert(s.direction);
                CHECK(std::fabs(double(back.x - u.x)) <= (sizeof(T) == 4 ? 1e-3 : 1e-9));
                CHECK(std::fabs(double(back.y - u.y)) <= (sizeof(T) == 4 ? 1e-3 : 1e-9));
            }
        }
        // directions that miss the disk have pdf 0
        CHECK(light.pdf(-light.ellipse().z) == T(0));
        CHECK(apse::disk_light_pdf(o, c, n, r, Vec3<T>(-light.ellipse().z)) == T(0));
        // the free function agrees with the class
        const auto s1 = apse::sample_disk_light(o, c, n, r, m, Vec2<T>(T(0.3), T(0.8)));
        const auto s2 = light.sample(Vec2<T>(T(0.3), T(0.8)));
        CHECK(s1.direction == s2.direction);
        CHECK(s1.pdf == s2.pdf);
    }
}

TEMPLATE_TEST_CASE("disk light: degenerate and bad input", "[disk_light][robust]", float, double) {
    using T = TestType;
    const T nan = std::numeric_limits<T>::quiet_NaN(), inf = std::numeric_limits<T>::infinity();
    auto finite3 = [](const Vec3<T>& v) { return apse::is_finite(v.x) && apse::is_finite(v.y) && apse::is_finite(v.z); };
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
        for (apse::DiskMap m : kMaps) {
            const apse::DiskLight<T> light(b.o, b.c, b.n, b.r, m);
            const auto s = light.sample(Vec2<T>(T(0.4), T(0.6)));
            CHECK(s.pdf == T(0));
            CHECK(finite3(s.direction));
            CHECK(light.pdf(Vec3<T>(0, 0, -1)) == T(0));
            CHECK(apse::disk_light_pdf(b.o, b.c, b.n, b.r, Vec3<T>(0, 0, -1)) == T(0));
        }
    for (apse::DiskMap m : kMaps) {
        const apse::DiskLight<T> light(o, c, n, T(1), m);
        CHECK(light.sample(Vec2<T>(nan, T(0.5))).pdf == T(0));
        const auto s = light.sample(Vec2<T>(T(2), T(-1)));  // clamped onto the square
        CHECK(s.pdf > T(0));
        CHECK(finite3(s.point));
        // o behind the disk: the same ellipse (two-sided), the point on the disk
        const apse::DiskLight<T> behind(Vec3<T>(0, 0, -2), c, n, T(1), m);
        const auto sb = behind.sample(Vec2<T>(T(0.25), T(0.75)));
        CHECK(sb.pdf > T(0));
        CHECK(std::fabs(double(sb.point.z) + 1) <= 1e-5);
    }
}
