// Geometric properties of the three area-preserving maps, in float and double: area
// preservation (finite-difference Jacobian = Omega), inverse round trips, the square's boundary
// onto the ellipse's boundary, continuity and seams, samples hitting projected disks, and
// degenerate / bad input.
#include <apse/maps/ld_radial.hpp>
#include <apse/maps/parallel.hpp>
#include <apse/comparison.hpp>
#include <apse/projection.hpp>
#include <apse/math.hpp>
#include <apse/diagnostics.hpp>

#include "support/map_testing.hpp"

#include "support/catch.hpp"

#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

namespace {

template <class T> using Vec2 = glm::vec<2, T>;
template <class T> using Vec3 = glm::vec<3, T>;

const double kHalfPi = 1.57079632679489661923;

/// The shapes of the issue: tiny (alpha = 1e-5) to nearly hemispherical (alpha = pi/2 - 1e-4),
/// round to very thin (beta/alpha = 1e-4), as (tan alpha, tan beta).
std::vector<std::pair<double, double>> shapes() {
    std::vector<std::pair<double, double>> s;
    for (double alpha : {1e-5, 0.05, 0.4, 1.0, 1.4, kHalfPi - 1e-4})
        for (double ratio : {1.0, 0.5, 0.05, 1e-4}) s.emplace_back(std::tan(alpha), std::tan(alpha * ratio));
    return s;
}

template <class T> apse::SphericalEllipse<T> local_ellipse(double ta, double tb) {
    return apse::SphericalEllipse<T>::from_tangents(Vec3<T>(1, 0, 0), Vec3<T>(0, 1, 0), Vec3<T>(0, 0, 1), T(ta), T(tb));
}

/// Calls f(name, map) for each of the three maps of ellipse e.
template <class T, class F> void for_each_map(const apse::SphericalEllipse<T>& e, F&& f) {
    f(std::string("radial"), apse::RadialMap<T>(e));
    f(std::string("ld_radial"), apse::LdRadialMap<T>(e));
    f(std::string("parallel"), apse::ParallelMap<T>(e));
}

/// Angle between two directions (any length), computed in double.
template <class T> double angle(const Vec3<T>& a, const Vec3<T>& b) {
    const glm::dvec3 x(a), y(b);
    return std::atan2(glm::length(glm::cross(x, y)), glm::dot(x, y));
}

/// Points where a map is not differentiable: the radial maps' quadrant folds (u1 = k/4 for the
/// radial map; the concentric map's diagonals for LD-radial), the parallel fold at u1 = 1/2 is
/// smooth. Finite differences must not straddle them.
bool near_kink(const std::string& name, double u1, double u2, double h) {
    if (name == "radial") return std::fabs(4 * u1 - std::round(4 * u1)) < 8 * h;
    if (name == "ld_radial") {
        const double a = 2 * u1 - 1, b = 2 * u2 - 1;
        return std::fabs(std::fabs(a) - std::fabs(b)) < 8 * h || std::fabs(a) < 8 * h || std::fabs(b) < 8 * h;
    }
    return false;
}

}  // namespace

TEMPLATE_TEST_CASE("maps preserve area: Jacobian equals the solid angle", "[maps][jacobian]", float, double) {
    using T = TestType;
    // |dw/du1 x dw/du2| by central differences of the gnomonic coordinates (x/z, y/z) (accurate
    // to relative rounding even when z rounds to 1), times z^3 (the gnomonic area element).
    // Richardson-extrapolated (O(h^4)) differences. double: h = 1e-4, truncation ~h^4 * (derivatives
    // of the map) and rounding ~eps/h = 2e-12: tolerance 1e-5 (the goal). float: h = 2^-7;
    // rounding ~eps/h = 1e-5 per derivative, amplified on the most eccentric shapes: 4e-3
    // (measured 1.8e-3; double measured 3e-10).
    const double h = sizeof(T) == 4 ? 0x1p-7 : 1e-4;
    const double tol = sizeof(T) == 4 ? 4e-3 : 1e-5;
    apse_test::Rng rng(4);
    double worst = 0;
    for (const auto& s : shapes()) {
        const auto e = local_ellipse<T>(s.first, s.second);
        for_each_map(e, [&](const std::string& name, const auto& map) {
            const double omega = double(map.solid_angle());
            for (int i = 0; i < 24; ++i) {
                const double u1 = 0.05 + 0.9 * rng.uniform<double>(), u2 = 0.05 + 0.9 * rng.uniform<double>();
                if (near_kink(name, u1, u2, 2 * h)) continue;
                auto gnomonic = [&](double a, double b) {
                    const Vec3<T> w = map.sample(Vec2<T>(T(a), T(b))).direction;
                    return glm::dvec2(double(w.x) / double(w.z), double(w.y) / double(w.z));
                };
                // Richardson-extrapolated central differences (steps h and 2h): O(h^4) truncation
                auto diff = [&](double du1, double du2) {
                    const glm::dvec2 a = (gnomonic(u1 + du1, u2 + du2) - gnomonic(u1 - du1, u2 - du2)) / (2 * h);
                    const glm::dvec2 b = (gnomonic(u1 + 2 * du1, u2 + 2 * du2) - gnomonic(u1 - 2 * du1, u2 - 2 * du2)) / (4 * h);
                    return (4.0 * a - b) / 3.0;
                };
                const glm::dvec2 d1 = diff(h, 0), d2 = diff(0, h);
                const Vec3<T> w = map.sample(Vec2<T>(T(u1), T(u2))).direction;
                const double z = double(w.z) / glm::length(glm::dvec3(w));
                const double jac = std::fabs(d1.x * d2.y - d1.y * d2.x) * z * z * z;
                const double err = std::fabs(jac - omega) / omega;
                worst = std::max(worst, err);
                INFO(name << " tan alpha " << s.first << " tan beta " << s.second << " u " << u1 << " " << u2
                          << " jacobian " << jac << " omega " << omega);
                CHECK(err <= tol);
            }
        });
    }
    std::printf("[%s] Jacobian max rel err %.2e\n", sizeof(T) == 4 ? "float" : "double", worst);
}

TEMPLATE_TEST_CASE("inverse round trips", "[maps][inverse]", float, double) {
    using T = TestType;
    // invert(sample(u)) = u on [0.01, 0.99]^2 (away from the documented seams: the radial map's
    // centre u2 = 0 and its +x seam u1 in {0, 1}, the parallel map's minor-axis ends u1 in {0, 1},
    // LD-radial's centre). double: 1e-9 (the goal; the inverse evaluates the same closed
    // form as the solver, so the error is the solver's 4 eps of area divided by the local density,
    // amplified near u2 = 0.01 by 1/sqrt(u2) in LD-radial). float: 2e-3, the same budget with
    // float's eps on the most eccentric shapes (measured values printed).
    // sample(invert(w)) = w for random directions inside: angle <= tol_w * sin(alpha) plus 4 times
    // the image of a change of u by 8 eps (the resolution of the inverse in T at u).
    const double tol_u = sizeof(T) == 4 ? 2e-3 : 1e-9;
    const double tol_w = sizeof(T) == 4 ? 2e-3 : 1e-9;
    apse_test::Rng rng(5);
    double worst_u = 0, worst_w = 0;
    for (const auto& s : shapes()) {
        const auto e = local_ellipse<T>(s.first, s.second);
        const double size = s.first / std::sqrt(1 + s.first * s.first);
        for_each_map(e, [&](const std::string& name, const auto& map) {
            for (int i = 0; i < 64; ++i) {
                const Vec2<T> u(T(0.01 + 0.98 * rng.uniform<double>()), T(0.01 + 0.98 * rng.uniform<double>()));
                const auto smp = map.sample(u);
                const Vec2<T> back = map.invert(smp.direction);
                const double err = std::max(std::fabs(double(back.x - u.x)), std::fabs(double(back.y - u.y)));
                worst_u = std::max(worst_u, err);
                INFO(name << " tan alpha " << s.first << " tan beta " << s.second << " u " << u.x << " " << u.y
                          << " -> " << back.x << " " << back.y);
                CHECK(err <= tol_u);
                // a direction inside: uniform in the gnomonic ellipse, shrunk by 0.999
                const double rho = 0.999 * std::sqrt(rng.uniform<double>()), t = double(apse_test::kTwoPi) * rng.uniform<double>();
                const glm::dvec3 g(s.first * rho * std::cos(t), s.second * rho * std::sin(t), 1.0);
                const Vec3<T> w(glm::normalize(g));
                const Vec2<T> uw = map.invert(w);
                const Vec3<T> w2 = map.sample(uw).direction;
                // resolution of u in T: how far the image moves when u moves by 8 eps, the inverse's
                // accuracy in u (the solver stops within 4 eps of the area); directions near the
                // horizon of nearly hemispherical ellipses live within ~1e-5 of u1 = 1 in the
                // parallel map, where that moves the slice far
                auto nudge = [](T v) { const T d = T(8) * apse::epsilon<T>();
                                       return v + d <= T(1) ? v + d : v - d; };
                const double resolution = angle(w2, map.sample(Vec2<T>(nudge(uw.x), uw.y)).direction) +
                                          angle(w2, map.sample(Vec2<T>(uw.x, nudge(uw.y))).direction);
                const double ew = angle(w, w2) / (tol_w * size + 4 * resolution);
                worst_w = std::max(worst_w, angle(w, w2) / size);
                INFO("direction round trip error " << angle(w, w2) / size << " resolution " << resolution / size);
                CHECK(ew <= 1);
            }
        });
    }
    std::printf("[%s] round trip max err: u %.2e, direction %.2e (of sin alpha)\n",
                sizeof(T) == 4 ? "float" : "double", worst_u, worst_w);
}

TEMPLATE_TEST_CASE("the square's boundary maps onto the ellipse's boundary, and the seams", "[maps][boundary]", float, double) {
    using T = TestType;
    // Boundary: g = (x/(z tan a))^2 + (y/(z tan b))^2 = 1; its rounding error is a few eps times
    // 1/z (z = cos theta is computed as 1 - (1 - cos theta), absolute error eps): tolerance
    // 32 eps (1 + 1/z).
    const double eps = double(apse::epsilon<T>());
    for (const auto& s : shapes()) {
        const auto e = local_ellipse<T>(s.first, s.second);
        const double ta = double(e.tan_alpha), tb = double(e.tan_beta);
        auto boundary_error = [&](const Vec3<T>& w) {
            const double x = double(w.x) / double(w.z), y = double(w.y) / double(w.z);
            return std::fabs((x / ta) * (x / ta) + (y / tb) * (y / tb) - 1) / (32 * eps * (1 + 1 / double(w.z)));
        };
        const apse::RadialMap<T> radial(e);
        const apse::LdRadialMap<T> ld(e);
        const apse::ParallelMap<T> parallel(e);
        for (int i = 0; i <= 64; ++i) {
            const T t = T(i / 64.0);
            INFO("tan alpha " << ta << " tan beta " << tb << " t " << t);
            CHECK(boundary_error(radial.sample(Vec2<T>(t, T(1))).direction) <= 1);
            for (const Vec2<T> u : {Vec2<T>(t, T(0)), Vec2<T>(t, T(1)), Vec2<T>(T(0), t), Vec2<T>(T(1), t)})
                CHECK(boundary_error(ld.sample(u).direction) <= 1);
            for (const Vec2<T> u : {Vec2<T>(t, T(0)), Vec2<T>(t, T(1)), Vec2<T>(T(0), t), Vec2<T>(T(1), t)})
                CHECK(boundary_error(parallel.sample(u).direction) <= 1);
            // seams (docs/math.md §4): radial u1 = 0 and u1 = 1 meet on the +x axis; u2 = 0 is the centre
            const Vec3<T> a = radial.sample(Vec2<T>(T(0), t)).direction, b = radial.sample(Vec2<T>(T(1), t)).direction;
            CHECK(angle(a, b) <= 8 * eps * (1 + std::fabs(double(a.x))));
            CHECK(std::fabs(double(a.y)) <= 8 * eps);
            const Vec3<T> c = radial.sample(Vec2<T>(t, T(0))).direction;
            CHECK(c.x == T(0));
            CHECK(c.y == T(0));
            // parallel: the edges u1 = 0, 1 are the ends of the minor axis
            const Vec3<T> p0 = parallel.sample(Vec2<T>(T(0), t)).direction;
            CHECK(p0.x == T(0));
            CHECK(p0.y < T(0));
        }
    }
}

TEMPLATE_TEST_CASE("LD-radial is continuous on the whole square", "[maps][continuity]", float, double) {
    using T = TestType;
    // The largest angle between images of neighbouring grid points must shrink with the grid step
    // (a jump would not): from n = 64 to n = 256 the ratio of the continuous maps' maximum
    // neighbour distances is ~4; require > 2.5. The radial map behaves the same on the square (its
    // seam identifies edges u1 = 0 and u1 = 1, which are not neighbours in the square).
    for (const auto& s : {std::make_pair(1.0, 0.3), std::make_pair(0.1, 1e-5), std::make_pair(1e4, 0.2)}) {
        const auto e = local_ellipse<T>(s.first, s.second);
        const apse::LdRadialMap<T> ld(e);
        auto max_jump = [&](int n) {
            std::vector<Vec3<T>> g((n + 1) * (n + 1));
            for (int i = 0; i <= n; ++i)
                for (int j = 0; j <= n; ++j) g[i * (n + 1) + j] = ld.sample(Vec2<T>(T(i) / T(n), T(j) / T(n))).direction;
            double m = 0;
            for (int i = 0; i <= n; ++i)
                for (int j = 0; j <= n; ++j) {
                    if (i < n) m = std::max(m, angle(g[i * (n + 1) + j], g[(i + 1) * (n + 1) + j]));
                    if (j < n) m = std::max(m, angle(g[i * (n + 1) + j], g[i * (n + 1) + j + 1]));
                }
            return m;
        };
        const double coarse = max_jump(64), fine = max_jump(256);
        INFO("tan alpha " << s.first << " tan beta " << s.second << " jumps " << coarse << " " << fine);
        CHECK(coarse / fine > 2.5);
    }
}

TEMPLATE_TEST_CASE("samples hit the projected disk", "[maps][disk]", float, double) {
    using T = TestType;
    // Disks (o = 0, centre (h, 0, -d), normal +z, radius 1) from docs/math.md §10 and harder ones. A
    // sample hits the disk if the ray meets the plane within |p - c| <= 1 + tol. The projection
    // loses ~log10(distance/d) digits near grazing (projection.hpp), and a direction error of eps
    // moves the hit point by ~eps |c|: tol = 16 eps (1 + |c|/d) (1 + |c|).
    const double eps = double(apse::epsilon<T>());
    const double cfg[][2] = {{1, 0}, {1, 0.5}, {1, 1}, {1, 2}, {0.1, 3}, {10, 5}, {1e-3, 0.5}, {100, 0}, {1e-2, 1.01}, {1e3, 1e3}};
    apse_test::Rng rng(6);
    for (const auto& c : cfg) {
        const double d = c[0], h = c[1];
        const Vec3<T> center(T(h), T(0), T(-d));
        const auto e = apse::project_disk(Vec3<T>(0), center, Vec3<T>(0, 0, 1), T(1));
        REQUIRE_FALSE(e.empty());
        const double dist = std::sqrt(h * h + d * d);
        const double tol = 16 * eps * (1 + dist / d) * (1 + dist);
        for_each_map(e, [&](const std::string& name, const auto& map) {
            for (int i = 0; i < 200; ++i) {
                const Vec2<T> u = i < 100 ? Vec2<T>(rng.uniform<T>(), rng.uniform<T>())
                                          : Vec2<T>(T((i - 100) / 99.0), T(1));  // the rim
                const Vec3<T> w = map.sample(u).direction;
                const glm::dvec3 wd(w);
                REQUIRE(wd.z < 0);
                const glm::dvec3 p = wd * (-d / wd.z);
                const double off = glm::length(p - glm::dvec3(center)) - 1;
                INFO(name << " d " << d << " h " << h << " u " << u.x << " " << u.y << " off " << off);
                CHECK(off <= tol);
            }
        });
    }
}

TEMPLATE_TEST_CASE("degenerate and bad input: pdf 0 or a valid direction, never NaN", "[maps][robust]", float, double) {
    using T = TestType;
    const T nan = std::numeric_limits<T>::quiet_NaN(), inf = std::numeric_limits<T>::infinity();
    auto finite3 = [](const Vec3<T>& v) { return apse::detail::is_finite(v.x) && apse::detail::is_finite(v.y) && apse::detail::is_finite(v.z); };
    // empty ellipse
    const auto empty = apse::SphericalEllipse<T>::make_empty();
    for_each_map(empty, [&](const std::string& name, const auto& map) {
        INFO(name);
        const auto s = map.sample(Vec2<T>(T(0.3), T(0.7)));
        CHECK(s.pdf == T(0));
        CHECK(finite3(s.direction));
        CHECK(map.pdf(Vec3<T>(0, 0, 1)) == T(0));
        const Vec2<T> u = map.invert(Vec3<T>(0, 0, 1));
        CHECK((apse::detail::is_finite(u.x) && apse::detail::is_finite(u.y)));
        CHECK(map.solid_angle() == T(0));
    });
    // bad u on a good ellipse; bad directions
    const auto e = local_ellipse<T>(0.5, 0.2);
    for_each_map(e, [&](const std::string& name, const auto& map) {
        INFO(name);
        const T inv = T(1) / map.solid_angle();
        for (const Vec2<T> u : {Vec2<T>(nan, T(0.5)), Vec2<T>(T(0.5), nan), Vec2<T>(nan, nan)}) {
            const auto s = map.sample(u);
            CHECK(s.pdf == T(0));
            CHECK(finite3(s.direction));
        }
        for (const Vec2<T> u : {Vec2<T>(T(-0.5), T(2)), Vec2<T>(inf, -inf), Vec2<T>(T(1), T(1)), Vec2<T>(T(0), T(0)),
                                Vec2<T>(T(1e30), T(-1e-30))}) {
            const auto s = map.sample(u);
            CHECK(s.pdf == inv);
            CHECK(finite3(s.direction));
            CHECK(e.contains(s.direction * T(1 - 1e-3) + Vec3<T>(0, 0, T(1e-3))));  // inside (up to the rim)
        }
        for (const Vec3<T> w : {Vec3<T>(0), Vec3<T>(nan, 0, 1), Vec3<T>(inf, 0, 1), Vec3<T>(0, 0, -1), Vec3<T>(1, 0, 0)}) {
            const Vec2<T> u = map.invert(w);
            CHECK((u.x >= T(0) && u.x <= T(1) && u.y >= T(0) && u.y <= T(1)));
            CHECK(apse::detail::is_finite(map.pdf(w)));
        }
        CHECK(map.pdf(Vec3<T>(0, 0, 1)) == inv);
        CHECK(map.pdf(Vec3<T>(0, 0, -1)) == T(0));
    });
    // extreme ellipses: every tangent from the smallest non-empty to beyond the cap
    const double tans[] = {1e-300, 1e-150, 1e-40, 1e-19, 1e-12, 1e-6, 1e-2, 1, 1e2, 1e6, 1e12, 1e30, 1e300};
    for (double ta : tans)
        for (double tb : tans) {
            if (tb > ta) continue;
            const auto x = local_ellipse<T>(ta, tb);
            for_each_map(x, [&](const std::string& name, const auto& map) {
                for (int i = 0; i <= 8; ++i)
                    for (int j = 0; j <= 8; ++j) {
                        apse::SampleDiagnostics diag{-1};
                        const auto s = apse::sample_with_diagnostics(map, Vec2<T>(T(i / 8.0), T(j / 8.0)), diag);
                        const int it = diag.iterations;
                        INFO(name << " tan alpha " << ta << " tan beta " << tb << " u " << i / 8.0 << " " << j / 8.0);
                        CHECK(finite3(s.direction));
                        CHECK(apse::detail::is_finite(s.pdf));
                        CHECK(s.pdf >= T(0));
                        CHECK(it <= 12);
                        if (s.pdf > 0) CHECK(std::fabs(glm::length(glm::dvec3(s.direction)) - 1) <= 1e-5);
                    }
            });
        }
}
