// Tests of spherical_ellipse.hpp: derived fields, degenerate input, solid angle against the
// committed mpmath table (tests/data/projection/solid_angle.csv, tools/gen_projection_reference.py),
// closed-form limits, contains(), frame transforms.
#include <apse/spherical_ellipse.hpp>
#include <apse/math.hpp>

#include "support/catch.hpp"
#include "support/projection_reference.hpp"

#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

namespace {

template <class T> using vec3 = glm::vec<3, T>;

template <class T> apse::SphericalEllipse<T> canonical(T ta, T tb) {
    return apse::SphericalEllipse<T>::from_tangents(vec3<T>(1, 0, 0), vec3<T>(0, 1, 0), vec3<T>(0, 0, 1), ta, tb);
}

double rel_err(double x, double ref) { return ref == 0 ? std::fabs(x) : std::fabs(x - ref) / std::fabs(ref); }

template <class T> void check_invariants(const apse::SphericalEllipse<T>& e) {
    const T tol = T(16) * apse::epsilon<T>();
    CHECK(std::fabs(glm::dot(e.x, e.x) - T(1)) <= tol);
    CHECK(std::fabs(glm::dot(e.y, e.y) - T(1)) <= tol);
    CHECK(std::fabs(glm::dot(e.z, e.z) - T(1)) <= tol);
    CHECK(std::fabs(glm::dot(e.x, e.y)) <= tol);
    CHECK(std::fabs(glm::dot(e.x, e.z)) <= tol);
    CHECK(std::fabs(glm::dot(e.y, e.z)) <= tol);
    CHECK(glm::dot(glm::cross(e.x, e.y), e.z) > T(0.99));
    CHECK(e.alpha() >= e.beta());
    CHECK(e.beta() >= T(0));
    CHECK(e.alpha() <= apse::half_pi_v<T>);
    CHECK(e.tan_alpha >= e.tan_beta);
    CHECK(e.tan_alpha <= apse::detail::tan_cap<T>());
    CHECK(e.m >= T(0));
    CHECK(e.m <= T(1));  // 1 - m (one_minus_m) is the accurate complement
    CHECK(e.one_minus_m > T(0));
    CHECK(e.one_minus_m <= T(1));
    const T fields[] = {e.alpha(), e.beta(), e.tan_alpha, e.tan_beta, e.sin_alpha, e.sin_beta, e.cos_alpha,
                        e.cos_beta, e.one_minus_cos_alpha, e.one_minus_cos_beta, e.m, e.one_minus_m};
    for (T f : fields) CHECK(apse::detail::is_finite(f));
}

}  // namespace

TEMPLATE_TEST_CASE("from_tangents fills consistent derived fields", "[spherical_ellipse]", float, double) {
    using T = TestType;
    const double tans[] = {1e-15, 1e-8, 1e-3, 0.1, 0.5, 1, 2, 10, 1e3, 1e6};
    for (double ta : tans) {
        for (double ratio : {1.0, 0.9, 0.5, 1e-2, 1e-5}) {
            const double tb = ta * ratio;
            if (T(tb) < apse::detail::tan_min<T>()) continue;
            const auto e = canonical(T(ta), T(tb));
            REQUIRE_FALSE(e.empty());
            check_invariants(e);
            const double TA = double(T(ta)), TB = double(T(tb));  // the values actually stored
            const double tol = 4 * double(apse::epsilon<T>());
            CHECK(rel_err(e.tan_alpha, TA) == 0);
            CHECK(rel_err(e.alpha(), std::atan(TA)) <= tol);
            CHECK(rel_err(e.beta(), std::atan(TB)) <= tol);
            const auto cos_of_atan = [](long double t) { return double(1.0L / std::sqrt(1.0L + t * t)); };
            const auto sin_of_atan = [](long double t) { return double(t / std::sqrt(1.0L + t * t)); };
            CHECK(rel_err(e.sin_alpha, sin_of_atan(TA)) <= tol);
            CHECK(rel_err(e.cos_alpha, cos_of_atan(TA)) <= tol);
            CHECK(rel_err(e.sin_beta, sin_of_atan(TB)) <= tol);
            CHECK(rel_err(e.cos_beta, cos_of_atan(TB)) <= tol);
            // 1 - cos(atan t) = t^2 / (sqrt(1 + t^2) (1 + sqrt(1 + t^2))), long double reference
            const auto omc = [](long double t) {
                const long double s = std::sqrt(1.0L + t * t);
                return double(t * t / (s * (1.0L + s)));
            };
            CHECK(rel_err(e.one_minus_cos_alpha, omc(TA)) <= tol);
            CHECK(rel_err(e.one_minus_cos_beta, omc(TB)) <= tol);
            const long double m = ((long double)TA * TA - (long double)TB * TB) / (1.0L + (long double)TA * TA);
            if (m != 0) CHECK(rel_err(e.m, double(m)) <= tol);
            else CHECK(e.m == T(0));
            CHECK(rel_err(e.one_minus_m, double((1.0L + (long double)TB * TB) / (1.0L + (long double)TA * TA))) <= tol);
        }
    }
}

TEMPLATE_TEST_CASE("from_tangents: swapped, capped, tiny and invalid tangents", "[spherical_ellipse]", float, double) {
    using T = TestType;
    const vec3<T> x(0, 0, 1), y(1, 0, 0), z(0, 1, 0);  // right-handed: x × y = z
    // tan_beta > tan_alpha: roles swapped, frame rotated to (y, -x, z), still right-handed
    const auto s = apse::SphericalEllipse<T>::from_tangents(x, y, z, T(0.5), T(2));
    CHECK(s.tan_alpha == T(2));
    CHECK(s.tan_beta == T(0.5));
    CHECK(s.x == y);
    CHECK(s.y == -x);
    CHECK(s.z == z);
    check_invariants(s);
    // +inf and huge tangents are capped
    const T inf = std::numeric_limits<T>::infinity();
    for (T big : {inf, T(1e30), std::numeric_limits<T>::max()}) {
        const auto h = apse::SphericalEllipse<T>::from_tangents(x, y, z, big, T(1));
        CHECK(h.tan_alpha == apse::detail::tan_cap<T>());
        CHECK(h.tan_beta == T(1));
        check_invariants(h);
        CHECK(apse::detail::is_finite(h.solid_angle()));
        const auto hh = apse::SphericalEllipse<T>::from_tangents(x, y, z, big, big);
        CHECK(hh.tan_beta == apse::detail::tan_cap<T>());
        CHECK(rel_err(hh.solid_angle(), 2 * M_PI) <= 4 * double(apse::epsilon<T>()));
    }
    // below tan_min, zero, negative, NaN: empty
    const T nan = std::numeric_limits<T>::quiet_NaN();
    const T bad[][2] = {{T(1), T(0)}, {T(1), apse::detail::tan_min<T>() / T(2)}, {T(-1), T(0.5)},
                        {T(1), T(-0.5)}, {nan, T(1)}, {T(1), nan}, {nan, nan}, {T(0), T(0)}, {-inf, T(1)}};
    for (const auto& b : bad) {
        const auto e = apse::SphericalEllipse<T>::from_tangents(x, y, z, b[0], b[1]);
        CHECK(e.empty());
        CHECK(e.solid_angle() == T(0));
        CHECK_FALSE(e.contains(z));
    }
    CHECK_FALSE(apse::SphericalEllipse<T>::from_tangents(x, y, z, T(1), apse::detail::tan_min<T>()).empty());
    // non-finite frame: empty
    CHECK(apse::SphericalEllipse<T>::from_tangents(vec3<T>(nan, 0, 0), y, z, T(1), T(1)).empty());
    CHECK(apse::SphericalEllipse<T>::from_tangents(x, vec3<T>(0, inf, 0), z, T(1), T(1)).empty());
    // the empty ellipse
    const auto e = apse::SphericalEllipse<T>::make_empty();
    CHECK(e.empty());
    CHECK(e.solid_angle() == T(0));
    CHECK(e.cos_alpha == T(1));
    CHECK(e.one_minus_m == T(1));
    CHECK(glm::dot(glm::cross(e.x, e.y), e.z) == T(1));
}

TEMPLATE_TEST_CASE("from_arcs", "[spherical_ellipse]", float, double) {
    using T = TestType;
    const vec3<T> x(1, 0, 0), y(0, 1, 0), z(0, 0, 1);
    const auto e = apse::SphericalEllipse<T>::from_arcs(x, y, z, T(0.7), T(0.3));
    CHECK(e.tan_alpha == std::tan(T(0.7)));
    CHECK(e.tan_beta == std::tan(T(0.3)));
    const auto h = apse::SphericalEllipse<T>::from_arcs(x, y, z, apse::half_pi_v<T>, apse::half_pi_v<T>);
    CHECK(h.tan_alpha == apse::detail::tan_cap<T>());
    CHECK(rel_err(h.solid_angle(), 2 * M_PI) <= 4 * double(apse::epsilon<T>()));
    CHECK(apse::SphericalEllipse<T>::from_arcs(x, y, z, T(2), T(0.3)).empty());
    CHECK(apse::SphericalEllipse<T>::from_arcs(x, y, z, T(0.5), T(-0.3)).empty());
    CHECK(apse::SphericalEllipse<T>::from_arcs(x, y, z, std::numeric_limits<T>::quiet_NaN(), T(0.3)).empty());
}

TEMPLATE_TEST_CASE("solid angle against the mpmath table", "[spherical_ellipse][solid_angle]", float, double) {
    using T = TestType;
    // the measure and the budget: support/projection_reference.hpp (shared with projection_report)
    const apse_test::SolidAngleReferences table =
        apse_test::read_solid_angle_references(std::string(APSE_TEST_DATA_DIR) + "/projection");
    INFO(table.error);
    REQUIRE(table.error.empty());
    const auto& rows = table.rows;
    REQUIRE(rows.size() >= 100);
    double worst = 0, worst_small = 0;
    int n = 0;
    for (const auto& r : rows) {
        if (!apse_test::solid_angle_applies<T>(r)) continue;  // empty by definition in float
        REQUIRE_FALSE(apse_test::solid_angle_ellipse<T>(r).empty());
        const double err = apse_test::solid_angle_error<T>(r);
        INFO(r.category << " tan_alpha=" << r.tan_alpha << " tan_beta=" << r.tan_beta << " omega=" << double(r.omega));
        CHECK(err <= apse_test::solid_angle_budget<T>());
        worst = std::fmax(worst, err);
        if (r.omega < 1e-10L) worst_small = std::fmax(worst_small, err);
        ++n;
    }
    std::printf("solid_angle<%s>: %d ellipses, worst relative error %.3g (%.2f eps), below 1e-10 sr %.3g\n",
                sizeof(T) == 4 ? "float" : "double", n, worst, worst / double(apse::epsilon<T>()), worst_small);
}

TEMPLATE_TEST_CASE("solid angle: closed-form limits", "[spherical_ellipse][solid_angle]", float, double) {
    using T = TestType;
    const double tol = 8 * double(apse::epsilon<T>());
    // circle: 2 pi (1 - cos a) = 4 pi sin^2(a/2)
    for (double a : {1e-9, 1e-4, 0.1, 0.7, 1.2, 1.5, 1.5707}) {
        const T ta = T(std::tan(a));
        const double A = std::atan(double(ta));
        const auto e = canonical(ta, ta);
        CHECK(rel_err(e.solid_angle(), 4 * M_PI * std::pow(std::sin(A / 2), 2)) <= tol);
    }
    // far field: Omega -> pi tan a tan b
    const auto f = canonical(T(3e-9), T(1e-9));
    CHECK(rel_err(f.solid_angle(), M_PI * double(T(3e-9)) * double(T(1e-9))) <= tol);
    // lune limit: alpha -> pi/2 gives the lune of half-width beta, Omega = 4 beta
    for (double b : {1e-6, 0.1, 0.5, 1.0}) {
        const auto l = canonical(std::numeric_limits<T>::infinity(), T(std::tan(b)));
        CHECK(rel_err(l.solid_angle(), 4 * std::atan(double(T(std::tan(b))))) <= 4 * tol);
    }
    // monotone in both tangents, range (0, 2 pi)
    T prev = T(0);
    for (double t = 1e-12; t < 1e12; t *= 3.7) {
        const T w = canonical(T(t), T(t) * T(0.25)).solid_angle();
        CHECK(w >= prev * (T(1) - T(4) * apse::epsilon<T>()));  // monotone to rounding
        CHECK(w <= apse::two_pi_v<T>);
        prev = w;
    }
}

TEMPLATE_TEST_CASE("contains: the exact cone test", "[spherical_ellipse][contains]", float, double) {
    using T = TestType;
    const vec3<T> x(0, 0.6f, 0.8f), z(1, 0, 0);
    const vec3<T> y = glm::cross(z, x);
    for (double ta : {1e-6, 0.01, 0.5, 1.0, 5.0, 1e5}) {
        for (double ratio : {1.0, 0.5, 0.01}) {
            const auto e = apse::SphericalEllipse<T>::from_tangents(x, y, z, T(ta), T(ta * ratio));
            CHECK(e.contains(e.z));
            CHECK(e.contains(T(1e-30) * e.z));  // any length
            CHECK(e.contains(T(1e30) * e.z));
            CHECK_FALSE(e.contains(-e.z));
            CHECK_FALSE(e.contains(vec3<T>(0)));
            CHECK_FALSE(e.contains(vec3<T>(std::numeric_limits<T>::quiet_NaN())));
            CHECK_FALSE(e.contains(e.x));  // on the horizon
            // boundary points of the gnomonic ellipse, scaled in and out by 1e-3
            for (int k = 0; k < 32; ++k) {
                const T t = T(2 * M_PI * k / 32.0);
                const vec3<T> g(e.tan_alpha * std::cos(t), e.tan_beta * std::sin(t), T(1));
                const T in = T(1) - T(1e-3), out = T(1) + T(1e-3);
                CHECK(e.contains(e.to_world(vec3<T>(g.x * in, g.y * in, T(1)))));
                CHECK_FALSE(e.contains(e.to_world(vec3<T>(g.x * out, g.y * out, T(1)))));
            }
        }
    }
    CHECK_FALSE(apse::SphericalEllipse<T>::make_empty().contains(vec3<T>(0, 0, 1)));
}

TEMPLATE_TEST_CASE("to_local / to_world round trip", "[spherical_ellipse]", float, double) {
    using T = TestType;
    const vec3<T> z = glm::normalize(vec3<T>(1, 2, 3));
    const vec3<T> x = glm::normalize(glm::cross(z, vec3<T>(0, 0, 1)));
    const auto e = apse::SphericalEllipse<T>::from_tangents(x, glm::cross(z, x), z, T(0.4), T(0.2));
    const vec3<T> w(T(0.3), T(-1.7), T(2.5));
    const vec3<T> back = e.to_world(e.to_local(w));
    CHECK(glm::length(back - w) <= T(8) * apse::epsilon<T>() * glm::length(w));
    CHECK(glm::length(e.to_local(e.z) - vec3<T>(0, 0, 1)) <= T(4) * apse::epsilon<T>());
}
