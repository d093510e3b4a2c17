// Tests of spherical_rectangle.hpp (Ureña–Fajardo–King spherical rectangle sampling) against
// independent references: the mpmath tables of tools/gen_rectangle_reference.py (solid angles and
// map points), long-double Gauss–Legendre quadrature of the solid angle of grid cells (chi-square),
// and finite differences (Jacobian), measured by support/rectangle_accuracy.hpp (which
// tools/baselines_report also prints). Tolerances are in units of the type's epsilon times the
// condition number kappa = 1 + (|corner − o| + |edges|) / (distance to the plane): the inputs are
// float32-exact, but forming the plane's normal and the offset corner − o in T rounds them by
// O(eps) relative to those lengths, which moves the solid angle by O(eps·kappa).
#include <apse/spherical_rectangle.hpp>
#include <apse/math.hpp>

#include "support/rectangle_accuracy.hpp"

#include "support/catch.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace {

namespace measure = apse_test::rectangle;
using measure::RectCase;

const std::vector<RectCase>& rect_cases() {
    const auto& table = measure::rectangle_cases();
    INFO(table.error);
    REQUIRE(table.error.empty());
    return table.cases;
}

const RectCase& rect_case(const std::string& name) {
    rect_cases();
    const RectCase* c = measure::find_rectangle_case(name);
    if (!c) FAIL("no rectangle case " << name);
    return *c;
}

template <class T> bool unit_and_finite(const glm::vec<3, T>& v) {
    const double len = std::sqrt(double(v.x) * v.x + double(v.y) * v.y + double(v.z) * v.z);
    return apse::detail::is_finite(v.x) && apse::detail::is_finite(v.y) && apse::detail::is_finite(v.z) &&
           std::fabs(len - 1.0) <= 8 * double(apse::epsilon<T>());
}

}  // namespace

TEMPLATE_TEST_CASE("rectangle solid angle matches the mpmath table", "[rectangle]", float, double) {
    using T = TestType;
    const double eps = apse::epsilon<T>();
    rect_cases();
    const auto checks = measure::solid_angle_checks<T>();
    int checked = 0;
    for (const auto& k : checks) {
        const RectCase& c = *k.c;
        INFO(c.name);
        if (c.omega == 0) {  // o in the plane: empty
            CHECK(k.empty);
            CHECK(k.solid_angle == 0);
            continue;
        }
        REQUIRE_FALSE(k.empty);
        // Budget: 4 eps kappa (measured worst 1.3 eps kappa in float and double).
        CHECK(k.error <= 4 * eps * c.kappa);
        // The centred constructor describes the same rectangle (centre rounded once more in T).
        CHECK(k.centred_error <= 8 * eps * c.kappa);
        ++checked;
    }
    CHECK(checked >= 100);
    const auto s = measure::summarize(checks);
    WARN("max relative error / kappa: " << s.worst_per_kappa / eps << " eps (" << (s.worst ? s.worst->name : "")
                                        << "); far rectangles (1e2..1e8 sizes away): " << s.worst_far / eps << " eps");
}

TEMPLATE_TEST_CASE("the published g0+g1+g2+g3-2pi form cancels for far rectangles", "[rectangle]", float, double) {
    // Documents why apse does not use it: at 1e4 sizes away the published form has lost most of
    // its digits (double) or all of them (float); apse's form stays within a few ulps.
    using T = TestType;
    const RectCase& c = rect_case("far_axis_10000");
    const double published = measure::published_solid_angle_error<T>(c);
    const double ours = measure::solid_angle_error<T>(c);
    WARN("1e4 sizes away: published form relative error " << published << ", apse " << ours);
    CHECK(ours <= 8 * double(apse::epsilon<T>()));
    CHECK(published > 1e3 * ours);
}

TEMPLATE_TEST_CASE("rectangle map matches the mpmath reference points", "[rectangle]", float, double) {
    using T = TestType;
    const double eps = apse::epsilon<T>();
    rect_cases();
    {
        const auto& table = measure::rectangle_map_rows();
        INFO(table.error);
        REQUIRE(table.error.empty());
    }
    const auto checks = measure::map_checks<T>();
    for (const auto& k : checks) {
        const RectCase& c = *k.row->c;
        INFO(c.name << " u = (" << k.row->u_text[0] << ", " << k.row->u_text[1] << ")");
        // Budget 4 eps kappa for both (measured worst 1.3 eps kappa); the direction's own
        // conditioning, |point − o| / distance-to-plane, is bounded by kappa.
        CHECK(k.st_error <= 4 * eps * c.kappa);
        CHECK(k.direction_error <= 4 * eps * c.kappa);
        CHECK(k.pdf_is_inverse_solid_angle);
    }
    CHECK(checks.size() >= 200);
    const auto s = measure::summarize(checks);
    WARN("map vs mpmath: max st error " << s.st_per_kappa / eps << " eps kappa, direction " << s.direction_per_kappa / eps
                                        << " eps kappa");
}

TEMPLATE_TEST_CASE("rectangle map preserves area: Jacobian = S", "[rectangle]", float, double) {
    // |d st/du1 x d st/du2| w h (d / dist³) must equal the table's S everywhere. Fourth-order
    // central differences with step delta: truncation K delta^4 (K <= 7.2e3 measured over these
    // configurations at delta = 2^-6 and 2^-7 in double, where truncation dominates; budget 1e4)
    // plus rounding of the sampled points, 10 eps kappa / delta. delta = 2^-12 in double (budget
    // ~1e-11 kappa), 2^-6 in float (~4e-3: float points resolve only ~1e-7 of the rectangle).
    using T = TestType;
    const double eps = apse::epsilon<T>();
    const double delta = measure::jacobian_step<T>();
    rect_cases();
    double worst = 0;
    std::string worst_name;
    const auto checks = measure::jacobian_checks<T>();
    for (const auto& k : checks) {
        INFO(k.c->name << " u = (" << k.u1 << ", " << k.u2 << ")");
        CHECK(k.error <= 10 * eps * k.c->kappa / delta + 1e4 * std::pow(delta, 4));
        if (k.error > worst) {
            worst = k.error;
            worst_name = k.c->name;
        }
    }
    WARN("max |Jacobian / S - 1| = " << worst << " (" << worst_name << ") over " << checks.size() << " points");
}

TEMPLATE_TEST_CASE("rectangle inverse round trip, hits and boundaries", "[rectangle]", float, double) {
    using T = TestType;
    using V2 = glm::vec<2, T>;
    const double eps = apse::epsilon<T>();
    rect_cases();
    double worst = 0;
    std::string worst_name;
    // kappa_rt: invert() starts from a direction, whose rounding (eps) moves the plane point by
    // eps·dist relative to the edges (support/rectangle_accuracy.hpp, round_trip_condition).
    measure::for_each_round_trip<T>([&](const RectCase& c, const apse::SphericalRectangle<T>& r, int i, int j,
                                          const V2& /*u*/, const apse::RectanglePoint<T>& p, double err, double kappa_rt) {
        INFO(c.name);
        REQUIRE(unit_and_finite(p.direction));
        // the sample is on the rectangle and pdf() agrees
        CHECK(p.st.x >= T(0));
        CHECK(p.st.x <= T(1));
        CHECK(p.st.y >= T(0));
        CHECK(p.st.y <= T(1));
        // boundaries of the square go to the rectangle's edges
        if (i == 0) CHECK(p.st.x == T(0));
        if (i == 8) CHECK(p.st.x == T(1));
        if (j == 0) CHECK(p.st.y == T(0));
        if (j == 8) CHECK(p.st.y == T(1));
        // u -> direction -> invert() round trip
        CHECK(err <= 8 * eps * kappa_rt);
        if (err / kappa_rt > worst) {
            worst = err / kappa_rt;
            worst_name = c.name;
        }
        // Interior samples: the ray along the returned direction hits, pdf = 1/S — when
        // the direction's rounding moves the hit by less than the margin to the edges
        // (1/8); a float direction cannot resolve a rectangle 1e6 sizes away.
        if (i > 0 && i < 8 && j > 0 && j < 8 && 8 * eps * kappa_rt < 0.125) {
            CHECK(r.pdf(p.direction) == T(1) / r.solid_angle());
            const auto loc = r.locate(p.direction);
            CHECK(std::fabs(double(loc.st.x) - p.st.x) <= 8 * eps * kappa_rt);
            CHECK(std::fabs(double(loc.st.y) - p.st.y) <= 8 * eps * kappa_rt);
            CHECK(std::fabs(double(loc.distance) / p.distance - 1) <= 8 * eps * c.kappa);
        }
        // the point lies on the rectangle given by the inputs
        const double px = double(p.point.x) - c.s[0], py = double(p.point.y) - c.s[1], pz = double(p.point.z) - c.s[2];
        const double sx = (px * c.ex[0] + py * c.ex[1] + pz * c.ex[2]) / (measure::norm3(c.ex) * measure::norm3(c.ex));
        const double sy = (px * c.ey[0] + py * c.ey[1] + pz * c.ey[2]) / (measure::norm3(c.ey) * measure::norm3(c.ey));
        const double scale_st = measure::length_scale(c) / std::min(measure::norm3(c.ex), measure::norm3(c.ey));
        CHECK(std::fabs(sx - p.st.x) <= 8 * eps * scale_st);
        CHECK(std::fabs(sy - p.st.y) <= 8 * eps * scale_st);
    });
    for (const RectCase& c : rect_cases()) {
        if (c.omega == 0) continue;
        INFO(c.name);
        const auto r = measure::make_rectangle<T>(c);
        // monotone in each coordinate
        T last = T(-1);
        for (int i = 0; i <= 64; ++i) {
            const T x = r.sample_point(V2(T(i / 64.0), T(0.37))).st.x;
            CHECK(x >= last);
            last = x;
        }
    }
    WARN("max round-trip error / kappa_rt: " << worst / eps << " eps (" << worst_name << ")");
}

TEMPLATE_TEST_CASE("rectangle samples are uniform in solid angle (chi-square)", "[rectangle][chi2]", float, double) {
    // Histogram of 10^6 samples over a 16 x 16 grid of the rectangle against the expected counts
    // N Omega_cell / S, Omega_cell by 12 x 12-point Gauss–Legendre quadrature in long double (the
    // cells' quadrature sum must reproduce the table's S to 1e-9). 6 configurations x 2 types =
    // 12 tests at a family-wise level of 1% (Šidák).
    using T = TestType;
    const double alpha = apse_test::sidak(0.01, 12);
    std::uint64_t seed = measure::rectangle_chi2_seed<T>();
    for (const char* name : measure::rectangle_chi2_cases) {
        INFO(name);
        const RectCase& c = rect_case(name);
        const auto chi2 = measure::rectangle_chi2<T>(c, seed++);
        REQUIRE(chi2.quadrature_error < 1e-9);
        const auto& res = chi2.result;
        WARN(name << ": chi2 = " << res.chi2 << ", dof = " << res.dof << ", p = " << res.p);
        CHECK(res.p > alpha);
    }
}

TEMPLATE_TEST_CASE("rectangle: two-sided, and defined behaviour on degenerate input", "[rectangle][robust]", float, double) {
    using T = TestType;
    using V = glm::vec<3, T>;
    using V2 = glm::vec<2, T>;
    const T inf = std::numeric_limits<T>::infinity(), nan = apse::quiet_nan<T>();
    const V s(0, 0, 0), ex(1, 0, 0), ey(0, 1, 0);

    // A rectangle 1e37 times longer than o's distance to it (found by fuzz_rectangle): the world
    // point next to o is the difference of two coordinates ~1e37 and cancels to 0. Such a sample
    // has no usable direction and must say so with pdf 0, never a pdf > 0 at distance 0.
    {
        const V o(-3, -3, 0), c(-3, -3, -3), hx(-2, -3, 1);
        const V hy(T(-7.291765005448681e+37), T(6.0764708378739022e+37), T(3.6458825027243405e+37));
        const auto r = apse::SphericalRectangle<T>::from_center(o, c, hx, hy);
        for (const V2 u : {V2(T(0.80398256498197129), T(1.3823577699190182e-17)), V2(T(0.5), T(0.5)), V2(T(0.1), T(0.9))}) {
            const auto p = r.sample_point(u);
            CHECK(apse::detail::is_finite(p.pdf));
            if (p.pdf > T(0)) {
                CHECK(p.distance > T(0));
                CHECK(apse::detail::is_finite(p.distance));
            }
        }
    }

    // Coordinates near the type's maximum (also found by fuzz_rectangle): the point lies ~1.4
    // DBL_MAX from o, a distance double cannot hold. No sample then (pdf 0), never pdf > 0 with
    // an infinite distance. (In float the inputs overflow to inf: an empty rectangle.)
    {
        const T big = std::numeric_limits<T>::max();
        const T tiny = T(1e-300);  // 0 in float
        const apse::SphericalRectangle<T> r(V(0, big, 0), V(T(-3), tiny, big), V(0, 1, 1), V(tiny, 1, 1));
        for (const V2 u : {V2(T(1), T(0.043941662358302699)), V2(T(0.5), T(0.5)), V2(T(0.9), T(0.1))}) {
            const auto p = r.sample_point(u);
            CHECK(apse::detail::is_finite(p.pdf));
            if (p.pdf > T(0)) {
                CHECK(apse::detail::is_finite(p.distance));
                CHECK((apse::detail::is_finite(p.point.x) && apse::detail::is_finite(p.point.y) && apse::detail::is_finite(p.point.z)));
            }
        }
    }

    // o mirrored through the plane sees the same solid angle; samples are mirrored
    const apse::SphericalRectangle<T> above(V(0.3, 0.2, 0.5), s, ex, ey), below(V(0.3, 0.2, -0.5), s, ex, ey);
    CHECK(above.solid_angle() == below.solid_angle());
    const auto pa = above.sample_point(V2(0.3, 0.7)), pb = below.sample_point(V2(0.3, 0.7));
    CHECK(pa.st == pb.st);
    CHECK(pa.direction.z == -pb.direction.z);

    auto check_defined = [inf, nan](const apse::SphericalRectangle<T>& r, bool expect_empty) {
        CHECK(r.empty() == expect_empty);
        CHECK(apse::detail::is_finite(r.solid_angle()));
        for (const V2 u : {V2(0.5, 0.5), V2(0, 0), V2(1, 1), V2(-3, 7), V2(nan, nan), V2(inf, -inf)}) {
            INFO("u = (" << u.x << ", " << u.y << "), S = " << r.solid_angle());
            const auto p = r.sample_point(u);
            CHECK(unit_and_finite(p.direction));
            CHECK(apse::detail::is_finite(p.pdf));
            CHECK(p.pdf >= T(0));
            if (expect_empty) CHECK(p.pdf == T(0));
            CHECK(apse::detail::is_finite(p.distance));
            CHECK(apse::detail::is_finite(p.st.x));
            CHECK(apse::detail::is_finite(p.st.y));
            const auto q = r.sample(u);
            CHECK(unit_and_finite(q.direction));
        }
        for (const V d : {V(0, 0, -1), V(0, 0, 1), V(1, 0, 0), V(0, 0, 0), V(nan, 0, -1), V(inf, 0, -1), V(0.2, 0.3, -1e-30)}) {
            INFO("direction (" << d.x << ", " << d.y << ", " << d.z << "), S = " << r.solid_angle());
            const T p = r.pdf(d);
            CHECK(apse::detail::is_finite(p));
            CHECK(p >= T(0));
            const auto u = r.invert(d);
            CHECK(u.x >= T(0));
            CHECK(u.x <= T(1));
            CHECK(u.y >= T(0));
            CHECK(u.y <= T(1));
            const auto l = r.locate(d);
            CHECK(unit_and_finite(l.direction));
            CHECK(apse::detail::is_finite(l.pdf));
            CHECK(apse::detail::is_finite(l.st.x));
        }
    };
    check_defined(apse::SphericalRectangle<T>(), true);                                  // default
    check_defined(apse::SphericalRectangle<T>(V(0.5, 0.5, 0), s, ex, ey), true);         // o in the plane, on it
    check_defined(apse::SphericalRectangle<T>(V(3, 0.5, 0), s, ex, ey), true);           // o in the plane, outside
    check_defined(apse::SphericalRectangle<T>(V(0.5, 0.5, 1), s, V(0, 0, 0), ey), true); // zero edge
    check_defined(apse::SphericalRectangle<T>(V(0.5, 0.5, 1), s, ex, T(2) * ex), true);  // parallel edges
    check_defined(apse::SphericalRectangle<T>(V(nan, 0.5, 1), s, ex, ey), true);
    check_defined(apse::SphericalRectangle<T>(V(0.5, 0.5, 1), V(0, inf, 0), ex, ey), true);
    check_defined(apse::SphericalRectangle<T>(V(0.5, 0.5, 1), s, V(nan, 0, 0), ey), true);
    check_defined(apse::SphericalRectangle<T>(V(0.5, 0.5, 1), s, ex, V(0, inf, 0)), true);
    check_defined(apse::SphericalRectangle<T>(V(0.5, 0.5, 1), s, ex, ey), false);
    check_defined(apse::SphericalRectangle<T>(V(0.5, 0.5, T(1e-30)), s, ex, ey), false);   // touching
    check_defined(apse::SphericalRectangle<T>(V(0.5, 0.5, T(1e15)), s, ex, ey), false);    // S ~ 1e-30
    check_defined(apse::SphericalRectangle<T>(V(0.5, 0.5, T(1e30)), s, ex, ey), sizeof(T) == sizeof(float));  // S underflows
    if constexpr (sizeof(T) == sizeof(double))
        check_defined(apse::SphericalRectangle<T>(V(0.5, 0.5, T(1e200)), s, ex, ey), true);  // S underflows
    check_defined(apse::SphericalRectangle<T>(V(0.5, 0.5, 1), s, T(1e-25) * ex, T(1e-25) * ey), sizeof(T) == sizeof(float));
    check_defined(apse::SphericalRectangle<T>(V(T(1e18), 0, T(1e18)), V(T(1e18), 0, 0), T(1e17) * ex, T(1e17) * ey), false);
    check_defined(apse::SphericalRectangle<T>(V(2, 0.5, T(1e-20)), s, ex, ey), false);     // grazing
    // non-orthogonal edges: edge_y's component along edge_x is ignored
    const apse::SphericalRectangle<T> skew(V(0.3, 0.2, 0.5), s, ex, ey + T(0.5) * ex);
    CHECK(skew.solid_angle() == above.solid_angle());
}
