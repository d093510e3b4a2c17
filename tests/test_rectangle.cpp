// Tests of spherical_rectangle.hpp (Ureña–Fajardo–King spherical rectangle sampling) against
// independent references: the mpmath tables of tools/gen_rectangle_reference.py (solid angles and
// map points), long-double Gauss–Legendre quadrature of the solid angle of grid cells (chi-square),
// and finite differences (Jacobian). Tolerances are in units of the type's epsilon times the
// condition number kappa = 1 + (|corner − o| + |edges|) / (distance to the plane): the inputs are
// float32-exact, but forming the plane's normal and the offset corner − o in T rounds them by
// O(eps) relative to those lengths, which moves the solid angle by O(eps·kappa).
#include <apse/spherical_rectangle.hpp>
#include <apse/math.hpp>

#include "support/statistics.hpp"

#include "support/catch.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace {

using apse_test::num;

/// One row of tests/data/rectangle/solid_angle.txt.
struct RectCase {
    std::string name;
    double o[3], s[3], ex[3], ey[3];
    double omega, kappa;
};

const std::vector<RectCase>& rect_cases() {
    static const std::vector<RectCase> cases = [] {
        std::vector<RectCase> out;
        for (const auto& row : apse_test::read_table("rectangle/solid_angle.txt")) {
            REQUIRE(row.size() == 15);
            RectCase c;
            c.name = row[0];
            for (int i = 0; i < 3; ++i) {
                c.o[i] = num(row[1 + i]);
                c.s[i] = num(row[4 + i]);
                c.ex[i] = num(row[7 + i]);
                c.ey[i] = num(row[10 + i]);
            }
            c.omega = num(row[13]);
            c.kappa = num(row[14]);
            out.push_back(c);
        }
        return out;
    }();
    return cases;
}

const RectCase& rect_case(const std::string& name) {
    for (const auto& c : rect_cases())
        if (c.name == name) return c;
    FAIL("no rectangle case " << name);
    return rect_cases().front();
}

template <class T> glm::vec<3, T> v3(const double* p) { return glm::vec<3, T>(T(p[0]), T(p[1]), T(p[2])); }

template <class T> apse::SphericalRectangle<T> make(const RectCase& c) {
    return apse::SphericalRectangle<T>(v3<T>(c.o), v3<T>(c.s), v3<T>(c.ex), v3<T>(c.ey));
}

double norm3(const double* a) { return std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]); }

/// |corner − o| + |ex| + |ey|: the length scale of the inputs' rounding.
double length_scale(const RectCase& c) {
    const double r[3] = {c.s[0] - c.o[0], c.s[1] - c.o[1], c.s[2] - c.o[2]};
    return norm3(r) + norm3(c.ex) + norm3(c.ey);
}

/// Long-double local geometry of a case, computed independently of apse: the rectangle is
/// [0, w] x [0, h] in rectangle coordinates, o projects to (fx, fy), at distance d from the plane.
struct LocalGeometry {
    long double w, h, d, fx, fy;
    explicit LocalGeometry(const RectCase& c) {
        long double ex[3], ey[3], r[3];
        for (int i = 0; i < 3; ++i) {
            ex[i] = c.ex[i];
            ey[i] = c.ey[i];
            r[i] = (long double)c.o[i] - c.s[i];
        }
        auto dot = [](const long double* a, const long double* b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; };
        w = std::sqrt(dot(ex, ex));
        h = std::sqrt(dot(ey, ey));
        const long double n[3] = {ex[1] * ey[2] - ex[2] * ey[1], ex[2] * ey[0] - ex[0] * ey[2],
                                  ex[0] * ey[1] - ex[1] * ey[0]};
        d = std::fabs(dot(r, n)) / (w * h);
        fx = dot(r, ex) / w;
        fy = dot(r, ey) / h;
    }
    /// Solid-angle density per unit area at rectangle coordinates (x, y): d / dist³.
    long double density(long double x, long double y) const {
        const long double q = (x - fx) * (x - fx) + (y - fy) * (y - fy) + d * d;
        return d / (q * std::sqrt(q));
    }
    /// Solid angle of the cell [x0,x1] x [y0,y1] (rectangle coordinates) by n x n Gauss–Legendre.
    long double cell(const apse_test::GaussLegendre& gl, long double x0, long double x1, long double y0,
                     long double y1) const {
        return gl.integrate([&](long double x) { return gl.integrate([&](long double y) { return density(x, y); }, y0, y1); },
                            x0, x1);
    }
};

template <class T> bool unit_and_finite(const glm::vec<3, T>& v) {
    const double len = std::sqrt(double(v.x) * v.x + double(v.y) * v.y + double(v.z) * v.z);
    return apse::detail::is_finite(v.x) && apse::detail::is_finite(v.y) && apse::detail::is_finite(v.z) &&
           std::fabs(len - 1.0) <= 8 * double(apse::epsilon<T>());
}

/// The published solid-angle formula S = g0 + g1 + g2 + g3 − 2 pi (docs/math.md §7), evaluated in T:
/// only used to document its cancellation for far rectangles.
template <class T> T published_solid_angle(const RectCase& c) {
    using V = glm::vec<3, T>;
    const V ex = v3<T>(c.ex), ey = v3<T>(c.ey);
    const T lx = glm::length(ex), ly = glm::length(ey);
    const V x = ex / lx, y = ey / ly;
    V z = glm::cross(x, y);
    const V dl = v3<T>(c.s) - v3<T>(c.o);
    const T x0 = glm::dot(dl, x), y0 = glm::dot(dl, y);
    T z0 = glm::dot(dl, z);
    if (z0 > 0) z0 = -z0;
    const T x1 = x0 + lx, y1 = y0 + ly;
    const V v00(x0, y0, z0), v01(x0, y1, z0), v10(x1, y0, z0), v11(x1, y1, z0);
    const V n0 = glm::normalize(glm::cross(v00, v10)), n1 = glm::normalize(glm::cross(v10, v11));
    const V n2 = glm::normalize(glm::cross(v11, v01)), n3 = glm::normalize(glm::cross(v01, v00));
    const T g0 = std::acos(std::clamp(-glm::dot(n0, n1), T(-1), T(1))), g1 = std::acos(std::clamp(-glm::dot(n1, n2), T(-1), T(1)));
    const T g2 = std::acos(std::clamp(-glm::dot(n2, n3), T(-1), T(1))), g3 = std::acos(std::clamp(-glm::dot(n3, n0), T(-1), T(1)));
    return g0 + g1 + g2 + g3 - apse::two_pi_v<T>;
}

}  // namespace

TEMPLATE_TEST_CASE("rectangle solid angle matches the mpmath table", "[rectangle]", float, double) {
    using T = TestType;
    const double eps = apse::epsilon<T>();
    double worst = 0, worst_far = 0;
    std::string worst_name;
    int checked = 0;
    for (const RectCase& c : rect_cases()) {
        INFO(c.name);
        const auto r = make<T>(c);
        if (c.omega == 0) {  // o in the plane: empty
            CHECK(r.empty());
            CHECK(r.solid_angle() == T(0));
            continue;
        }
        REQUIRE_FALSE(r.empty());
        const double err = std::fabs(double(r.solid_angle()) - c.omega) / c.omega;
        // Budget: 4 eps kappa (measured worst 1.3 eps kappa in float and double).
        CHECK(err <= 4 * eps * c.kappa);
        if (err / c.kappa > worst) {
            worst = err / c.kappa;
            worst_name = c.name;
        }
        if (c.name.rfind("far_", 0) == 0) worst_far = std::max(worst_far, err);
        // The centred constructor describes the same rectangle (centre rounded once more in T).
        const auto ctr = apse::SphericalRectangle<T>::from_center(
            v3<T>(c.o), v3<T>(c.s) + T(0.5) * v3<T>(c.ex) + T(0.5) * v3<T>(c.ey), T(0.5) * v3<T>(c.ex),
            T(0.5) * v3<T>(c.ey));
        CHECK(std::fabs(double(ctr.solid_angle()) - c.omega) / c.omega <= 8 * eps * c.kappa);
        ++checked;
    }
    CHECK(checked >= 100);
    WARN("max relative error / kappa: " << worst / eps << " eps (" << worst_name
                                        << "); far rectangles (1e2..1e8 sizes away): " << worst_far / eps << " eps");
}

TEMPLATE_TEST_CASE("the published g0+g1+g2+g3-2pi form cancels for far rectangles", "[rectangle]", float, double) {
    // Documents why apse does not use it: at 1e4 sizes away the published form has lost most of
    // its digits (double) or all of them (float); apse's form stays within a few ulps.
    using T = TestType;
    const RectCase& c = rect_case("far_axis_10000");
    const double published = std::fabs(double(published_solid_angle<T>(c)) - c.omega) / c.omega;
    const double ours = std::fabs(double(make<T>(c).solid_angle()) - c.omega) / c.omega;
    WARN("1e4 sizes away: published form relative error " << published << ", apse " << ours);
    CHECK(ours <= 8 * double(apse::epsilon<T>()));
    CHECK(published > 1e3 * ours);
}

TEMPLATE_TEST_CASE("rectangle map matches the mpmath reference points", "[rectangle]", float, double) {
    using T = TestType;
    const double eps = apse::epsilon<T>();
    double worst_st = 0, worst_dir = 0;
    int n = 0;
    for (const auto& row : apse_test::read_table("rectangle/map.txt")) {
        REQUIRE(row.size() == 8);
        const RectCase& c = rect_case(row[0]);
        INFO(c.name << " u = (" << row[1] << ", " << row[2] << ")");
        const auto r = make<T>(c);
        const auto p = r.sample_point(glm::vec<2, T>(T(num(row[1])), T(num(row[2]))));
        const double dir_err = std::sqrt(std::pow(p.direction.x - num(row[3]), 2) + std::pow(p.direction.y - num(row[4]), 2) +
                                         std::pow(p.direction.z - num(row[5]), 2));
        const double st_err = std::max(std::fabs(p.st.x - num(row[6])), std::fabs(p.st.y - num(row[7])));
        // Budget 4 eps kappa for both (measured worst 1.3 eps kappa); the direction's own
        // conditioning, |point − o| / distance-to-plane, is bounded by kappa.
        CHECK(st_err <= 4 * eps * c.kappa);
        CHECK(dir_err <= 4 * eps * c.kappa);
        CHECK(p.pdf == T(1) / r.solid_angle());
        worst_st = std::max(worst_st, st_err / (eps * c.kappa));
        worst_dir = std::max(worst_dir, dir_err / (eps * c.kappa));
        ++n;
    }
    CHECK(n >= 200);
    WARN("map vs mpmath: max st error " << worst_st << " eps kappa, direction " << worst_dir << " eps kappa");
}

TEMPLATE_TEST_CASE("rectangle map preserves area: Jacobian = S", "[rectangle]", float, double) {
    // |d st/du1 x d st/du2| w h (d / dist³) must equal the table's S everywhere. Fourth-order
    // central differences with step delta: truncation K delta^4 (K <= 7.2e3 measured over these
    // configurations at delta = 2^-6 and 2^-7 in double, where truncation dominates; budget 1e4)
    // plus rounding of the sampled points, 10 eps kappa / delta. delta = 2^-12 in double (budget
    // ~1e-11 kappa), 2^-6 in float (~4e-3: float points resolve only ~1e-7 of the rectangle).
    using T = TestType;
    const double eps = apse::epsilon<T>();
    const double delta = sizeof(T) == sizeof(float) ? 0x1p-6 : 0x1p-12;
    double worst = 0;
    std::string worst_name;
    int n = 0;
    for (const RectCase& c : rect_cases()) {
        if (c.omega == 0 || c.kappa > 100) continue;  // grazing/very close: rounding/delta too large
        const auto r = make<T>(c);
        const LocalGeometry g(c);
        for (int i = 1; i < 5; ++i)
            for (int j = 1; j < 5; ++j) {
                const double u1 = (i - 0.5) / 4.5, u2 = (j - 0.3) / 4.5;  // interior, irregular
                auto st = [&](double a, double b) {
                    const auto p = r.sample_point(glm::vec<2, T>(T(a), T(b))).st;
                    return glm::dvec2(p.x, p.y);
                };
                const glm::dvec2 du1 = (-st(u1 + 2 * delta, u2) + 8.0 * st(u1 + delta, u2) - 8.0 * st(u1 - delta, u2) +
                                        st(u1 - 2 * delta, u2)) / (12 * delta);
                const glm::dvec2 du2 = (-st(u1, u2 + 2 * delta) + 8.0 * st(u1, u2 + delta) - 8.0 * st(u1, u2 - delta) +
                                        st(u1, u2 - 2 * delta)) / (12 * delta);
                const auto p = st(u1, u2);
                const double jac = std::fabs(du1.x * du2.y - du1.y * du2.x) * double(g.w * g.h) *
                                   double(g.density(g.w * p.x, g.h * p.y));
                const double err = std::fabs(jac / c.omega - 1);
                INFO(c.name << " u = (" << u1 << ", " << u2 << ")");
                CHECK(err <= 10 * eps * c.kappa / delta + 1e4 * std::pow(delta, 4));
                if (err > worst) {
                    worst = err;
                    worst_name = c.name;
                }
                ++n;
            }
    }
    WARN("max |Jacobian / S - 1| = " << worst << " (" << worst_name << ") over " << n << " points");
}

TEMPLATE_TEST_CASE("rectangle inverse round trip, hits and boundaries", "[rectangle]", float, double) {
    using T = TestType;
    using V2 = glm::vec<2, T>;
    const double eps = apse::epsilon<T>();
    double worst = 0;
    std::string worst_name;
    for (const RectCase& c : rect_cases()) {
        if (c.omega == 0) continue;
        INFO(c.name);
        const auto r = make<T>(c);
        // invert() starts from a direction, whose rounding (eps) moves the plane point by
        // eps·dist relative to the edges: conditioning kappa·length_scale / min edge.
        const double kappa_rt = c.kappa * length_scale(c) / std::min(norm3(c.ex), norm3(c.ey));
        for (int i = 0; i <= 8; ++i)
            for (int j = 0; j <= 8; ++j) {
                const V2 u(T(i / 8.0), T(j / 8.0));
                const auto p = r.sample_point(u);
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
                const auto back = r.invert(p.direction);
                const double err = std::max(std::fabs(double(back.x) - u.x), std::fabs(double(back.y) - u.y));
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
                const double sx = (px * c.ex[0] + py * c.ex[1] + pz * c.ex[2]) / (norm3(c.ex) * norm3(c.ex));
                const double sy = (px * c.ey[0] + py * c.ey[1] + pz * c.ey[2]) / (norm3(c.ey) * norm3(c.ey));
                const double scale_st = length_scale(c) / std::min(norm3(c.ex), norm3(c.ey));
                CHECK(std::fabs(sx - p.st.x) <= 8 * eps * scale_st);
                CHECK(std::fabs(sy - p.st.y) <= 8 * eps * scale_st);
            }
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
    const int n = 16;
    const long N = 1000000;
    const double alpha = apse_test::sidak(0.01, 12);
    const apse_test::GaussLegendre gl(12);
    std::uint64_t seed = sizeof(T) == sizeof(float) ? 101 : 202;
    for (const char* name : {"near02", "near05", "near08", "random03", "grazing04", "far_oblique_100"}) {
        INFO(name);
        const RectCase& c = rect_case(name);
        const LocalGeometry g(c);
        std::vector<double> expected(n * n), observed(n * n, 0.0);
        long double total = 0;
        for (int i = 0; i < n; ++i)
            for (int j = 0; j < n; ++j) {
                const long double e = g.cell(gl, g.w * i / n, g.w * (i + 1) / n, g.h * j / n, g.h * (j + 1) / n);
                expected[i * n + j] = double(e);
                total += e;
            }
        REQUIRE(std::fabs(double(total) / c.omega - 1) < 1e-9);
        for (double& e : expected) e *= double(N / total);
        const auto r = make<T>(c);
        apse_test::Rng rng(seed++);
        for (long k = 0; k < N; ++k) {
            const auto p = r.sample_point(glm::vec<2, T>(rng.uniform<T>(), rng.uniform<T>()));
            const int i = std::min(n - 1, int(p.st.x * n)), j = std::min(n - 1, int(p.st.y * n));
            observed[i * n + j] += 1;
        }
        const auto res = apse_test::chi2_test(observed, expected);
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
