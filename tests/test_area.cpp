// Tests of detail/polar.hpp (Shirley–Chiu map, polar form) and baselines/area.hpp
// (uniform-by-area disk sampling with the solid-angle pdf).
#include <apse/baselines/area.hpp>
#include <apse/projection.hpp>
#include <apse/math.hpp>

#include "support/map_testing.hpp"

#include "support/catch.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <vector>

namespace {

template <class T> using vec2 = glm::vec<2, T>;
template <class T> using vec3 = glm::vec<3, T>;

template <class T> vec2<T> disk_point(const apse::detail::ConcentricPolar<T>& p) {
    return vec2<T>(p.radius * std::cos(p.angle()), p.radius * std::sin(p.angle()));
}

/// Omega of a disk by brute force: a fine polar grid about the disk's centre of
/// cos(theta_l) / dist^2 dA (midpoint rule in the radius and angle; independent of apse).
double disk_omega_grid(const vec3<double>& o, const vec3<double>& c, const vec3<double>& n, double r) {
    const vec3<double> nn = glm::normalize(n);
    const vec3<double> e1 = apse::detail::any_perpendicular(nn), e2 = glm::cross(nn, e1);
    const int nr = 600, na = 1200;
    double sum = 0;
    for (int i = 0; i < nr; ++i) {
        const double rho = r * (i + 0.5) / nr;
        for (int j = 0; j < na; ++j) {
            const double a = 2 * M_PI * (j + 0.5) / na;
            const vec3<double> p = c + rho * (std::cos(a) * e1 + std::sin(a) * e2);
            const vec3<double> d = p - o;
            const double dist2 = glm::dot(d, d);
            sum += std::fabs(glm::dot(d, nn)) / (dist2 * std::sqrt(dist2)) * rho;
        }
    }
    return sum * (r / nr) * (2 * M_PI / na);
}

}  // namespace

TEMPLATE_TEST_CASE("concentric map: ranges, centre, boundary, round trip", "[area][concentric]", float, double) {
    using T = TestType;
    const T tol = T(16) * apse::epsilon<T>();
    // centre and corners
    const auto c = apse::detail::concentric_to_disk(vec2<T>(T(0.5), T(0.5)));
    CHECK(c.radius == T(0));
    for (T x : {T(0), T(1)})
        for (T y : {T(0), T(1)}) CHECK(apse::detail::concentric_to_disk(vec2<T>(x, y)).radius == T(1));
    const int n = 64;
    for (int i = 0; i <= n; ++i) {
        for (int j = 0; j <= n; ++j) {
            const vec2<T> u(T(i) / T(n), T(j) / T(n));
            const auto p = apse::detail::concentric_to_disk(u);
            CHECK(p.radius >= T(0));
            CHECK(p.radius <= T(1));
            CHECK(p.turns >= T(0));
            CHECK(p.turns < T(1));
            // the square's boundary goes to the unit circle
            if (i == 0 || j == 0 || i == n || j == n) CHECK(p.radius == T(1));
            const vec2<T> back = apse::detail::concentric_from_disk(p.radius, p.turns);
            CHECK(std::fabs(back.x - u.x) <= tol);
            CHECK(std::fabs(back.y - u.y) <= tol);
        }
    }
    // out of the domain: clamped, NaN -> 0
    const auto q = apse::detail::concentric_to_disk(vec2<T>(T(2), std::numeric_limits<T>::quiet_NaN()));
    CHECK(apse::detail::is_finite(q.radius));
    CHECK(apse::detail::is_finite(q.turns));
    const vec2<T> r = apse::detail::concentric_from_disk(T(3), T(-0.25));  // clamped, reduced mod 1
    CHECK(r.x == T(0.5));
    CHECK(r.y == T(0));
}

TEMPLATE_TEST_CASE("concentric_fold: the concentric point's quadrant, quarter-turn fraction and radius", "[area][concentric]", float, double) {
    using T = TestType;
    const long double eps = apse::epsilon<T>();
    // Reference in long double from the Shirley–Chiu definition: A = 2u1 − 1, B = 2u2 − 1; the
    // angle from the x axis of the first-quadrant image is (pi/4)|B|/|A| (|A| > |B|) or
    // pi/2 − (pi/4)|A|/|B|, i.e. the fraction |B|/(2|A|) or 1 − |A|/(2|B|) of the quarter turn.
    std::vector<T> grid;
    const int n = 64;
    for (int i = 0; i <= n; ++i) grid.push_back(T(i) / T(n));
    for (T b : {T(0.5), T(0.25), T(0.75)}) {
        grid.push_back(std::nextafter(b, T(0)));
        grid.push_back(std::nextafter(b, T(1)));
    }
    for (const T x : grid) {
        for (const T y : grid) {
            const auto f = apse::detail::concentric_fold(vec2<T>(x, y));
            // A and B as the map's input step makes them in T (2u − 1 rounds for u < 1/4): the
            // fold is what is tested, from there on in long double
            const long double a = T(2) * x - T(1), b = T(2) * y - T(1), fa = std::fabs(a), fb = std::fabs(b);
            const long double m = std::max(fa, fb);
            CHECK(f.radius == T(m));                              // M exact
            CHECK(std::fabs(f.radius2 - m * m) <= eps * m * m);  // M^2 rounded once in T
            if (m == 0) {
                CHECK(f.fold.fraction == T(0.5));  // the centre: any angle, radius 0
                continue;
            }
            const long double ref = fa > fb ? fb / (2 * fa) : 1 - fa / (2 * fb);
            // three roundings (|B| − |A|, the quotient, the sum with 1/2), each at most half an
            // ulp of a value <= 1: 1.5 eps; 2 eps
            CHECK(std::fabs(f.fold.fraction - ref) <= 2 * eps);
            if (a != 0) CHECK(f.fold.sign_x == (a > 0 ? T(1) : T(-1)));
            if (b != 0) CHECK(f.fold.sign_y == (b > 0 ? T(1) : T(-1)));
            // the same point as the polar form folded by fold_quadrant (the LD-radial maps' old path)
            const auto p = apse::detail::concentric_to_disk(vec2<T>(x, y));
            const auto g = apse::detail::fold_quadrant(p.turns);
            CHECK(std::fabs(g.fraction - f.fold.fraction) <= 8 * eps);  // turns rounded through 1/8, +1, ×4
            if (ref > 8 * eps && ref < 1 - 8 * eps) {
                CHECK(g.sign_x == f.fold.sign_x);
                CHECK(g.sign_y == f.fold.sign_y);
            }
        }
    }
}

TEMPLATE_TEST_CASE("concentric map is area-preserving and continuous", "[area][concentric]", float, double) {
    using T = TestType;
    // Jacobian of u -> disk point by central differences: |det| = pi (area pi from area 1)
    std::mt19937_64 rng(1);
    std::uniform_real_distribution<double> u(0.02, 0.98);
    const double h = sizeof(T) == 8 ? 1e-6 : 1e-3;
    for (int k = 0; k < 1000; ++k) {
        const double x = u(rng), y = u(rng);
        if (std::fabs(std::fabs(x - 0.5) - std::fabs(y - 0.5)) < 2 * h) continue;  // sector seams
        const auto f = [](double a, double b) {
            return vec2<double>(disk_point(apse::detail::concentric_to_disk(vec2<T>(T(a), T(b)))));
        };
        const vec2<double> dx = (f(x + h, y) - f(x - h, y)) / (2 * h);
        const vec2<double> dy = (f(x, y + h) - f(x, y - h)) / (2 * h);
        CHECK(std::fabs(dx.x * dy.y - dx.y * dy.x) == Approx(M_PI).epsilon(sizeof(T) == 8 ? 1e-7 : 2e-2));
    }
    // continuity across the sector seams (the diagonals) and at turns = 0
    for (double t = 0.01; t < 1; t += 0.01) {
        for (double s : {-1.0, 1.0}) {
            const double x = 0.5 + 0.5 * t, y = 0.5 + s * 0.5 * t;
            const double e = 1e-4;
            const auto a = disk_point(apse::detail::concentric_to_disk(vec2<T>(T(x), T(y - e))));
            const auto b = disk_point(apse::detail::concentric_to_disk(vec2<T>(T(x), T(y + e))));
            CHECK(glm::length(vec2<double>(a - b)) < 1e-3);
        }
    }
}

TEMPLATE_TEST_CASE("concentric map, signed form: the same point, angle in [-pi/4, 3pi/4]", "[area][concentric]", float,
                   double) {
    using T = TestType;
    // Both forms compute the same ratio (B/A or A/B) with one rounding; the angles differ by a
    // multiple of pi/2 added in T, so the points agree to a few ulps of the unit radius (16 eps
    // allows for the cos/sin of an angle up to 2 pi rounded in T).
    const T tol = T(16) * apse::epsilon<T>();
    const int n = 64;
    for (int i = 0; i <= n; ++i) {
        for (int j = 0; j <= n; ++j) {
            const vec2<T> u(T(i) / T(n), T(j) / T(n));
            const auto p = apse::detail::concentric_to_disk(u);
            const auto q = apse::detail::concentric_to_disk_signed(u);
            CHECK(std::fabs(q.radius) == p.radius);  // the same |A| or |B|, exactly
            CHECK(q.angle >= -apse::pi_v<T> / T(4));
            CHECK(q.angle <= T(0.75) * apse::pi_v<T>);
            const vec2<T> a = disk_point(p), b(q.radius * std::cos(q.angle), q.radius * std::sin(q.angle));
            CHECK(std::fabs(a.x - b.x) <= tol);
            CHECK(std::fabs(a.y - b.y) <= tol);
        }
    }
    const auto c = apse::detail::concentric_to_disk_signed(vec2<T>(T(0.5), T(0.5)));
    CHECK(c.radius == T(0));
    const auto q = apse::detail::concentric_to_disk_signed(vec2<T>(T(-2), std::numeric_limits<T>::quiet_NaN()));
    CHECK(apse::detail::is_finite(q.radius));  // clamped, NaN -> 0
    CHECK(apse::detail::is_finite(q.angle));
}

TEMPLATE_TEST_CASE("DiskAreaSampler: a stored DiskFrame gives the same sampler as the per-point frame", "[area]", float,
                   double) {
    using T = TestType;
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> u(0, 1);
    for (int light = 0; light < 10; ++light) {
        const vec3<T> c(T(u(rng) * 2 - 1), T(u(rng) * 2 - 1), T(u(rng) * 2 - 1));
        const vec3<T> n = T(0.5 + 3 * u(rng)) * vec3<T>(T(u(rng) - 0.5), T(u(rng) - 0.5), T(u(rng) - 0.5));
        const T r = T(0.2 + u(rng));
        const apse::DiskFrame<T> frame = apse::DiskFrame<T>::make(c, n, r);
        REQUIRE(frame.valid());
        // an orthonormal right-handed frame around the unit normal (4 eps: a few roundings of
        // a normalisation and a cross product)
        const T tol = T(4) * apse::epsilon<T>();
        CHECK(std::fabs(glm::dot(frame.e1, frame.e1) - T(1)) <= tol);
        CHECK(std::fabs(glm::dot(frame.e2, frame.e2) - T(1)) <= tol);
        CHECK(std::fabs(glm::dot(frame.n, frame.n) - T(1)) <= tol);
        CHECK(std::fabs(glm::dot(frame.e1, frame.n)) <= tol);
        CHECK(std::fabs(glm::dot(frame.e2, frame.n)) <= tol);
        CHECK(std::fabs(glm::dot(frame.e1, frame.e2)) <= tol);
        CHECK(glm::dot(glm::cross(frame.e1, frame.e2), frame.n) > T(0.99));
        // one frame, many shading points: the same samples as building the frame at each point
        // (both constructors run the same code on the same values: bit-identical without FMA
        // contraction; with it — AArch64's default, -march=x86-64-v3 -ffp-contract=fast — the
        // two inlined copies may fuse different products, a few roundings: 8 eps in the direction;
        // the pdf, ~ 1/cos(theta_l), amplifies that by 1/cos(theta_l))
        const T same = T(8) * apse::epsilon<T>();
        auto close = [same](T a, T b, T cos_l) { return std::fabs(a - b) <= same / cos_l * std::fabs(b); };
        for (int point = 0; point < 20; ++point) {
            const vec3<T> o(T(u(rng) * 6 - 3), T(u(rng) * 6 - 3), T(u(rng) * 6 - 3));
            const apse::DiskAreaSampler<T> stored(o, frame), fresh(o, c, n, r);
            REQUIRE(stored.empty() == fresh.empty());
            for (int k = 0; k < 8; ++k) {
                const vec2<T> uu(T(u(rng)), T(u(rng)));
                const auto a = stored.sample(uu), b = fresh.sample(uu);
                const T cos_l = std::fabs(glm::dot(b.direction, frame.n));
                CHECK(close(a.pdf, b.pdf, cos_l));
                CHECK(glm::length(a.direction - b.direction) <= same);
                CHECK(close(stored.pdf(a.direction), fresh.pdf(a.direction), cos_l));
            }
        }
    }
    // invalid frames: every sampler built from them is empty
    const T nan = std::numeric_limits<T>::quiet_NaN(), inf = std::numeric_limits<T>::infinity();
    const vec3<T> c(0), n(0, 0, 1), o(T(0.2), T(0.1), T(1));
    const apse::DiskFrame<T> bad[] = {
        apse::DiskFrame<T>::make(c, n, T(0)),        apse::DiskFrame<T>::make(c, n, T(-1)),
        apse::DiskFrame<T>::make(c, n, nan),         apse::DiskFrame<T>::make(c, n, inf),
        apse::DiskFrame<T>::make(c, vec3<T>(0), T(1)), apse::DiskFrame<T>::make(vec3<T>(nan, 0, 0), n, T(1)),
        apse::DiskFrame<T>::make(c, n, std::numeric_limits<T>::denorm_min()),  // 1/r overflows
    };
    for (const auto& f : bad) {
        CHECK_FALSE(f.valid());
        const apse::DiskAreaSampler<T> s(o, f);
        CHECK(s.empty());
        CHECK(s.sample(vec2<T>(T(0.3), T(0.7))).pdf == T(0));
    }
}

TEMPLATE_TEST_CASE("DiskAreaSampler: grazing and far samples give pdf 0 or a finite pdf, never NaN", "[area][robustness]",
                   float, double) {
    using T = TestType;
    // o just off the disk's plane, far away (the samples graze the disk), and o at 1e12 radii
    // (len^3 / r^2 is large but finite in double; in float it overflows and is reported as 0)
    const vec3<T> c(0), n(0, 0, 1);
    const apse::DiskFrame<T> frame = apse::DiskFrame<T>::make(c, n, T(1));
    for (const vec3<T>& o : {vec3<T>(T(1e3), T(0), T(1e-30)), vec3<T>(T(1e12), T(1e12), T(1)),
                             vec3<T>(T(0.5), T(0.25), T(1e-30))}) {
        const apse::DiskAreaSampler<T> s(o, frame);
        REQUIRE_FALSE(s.empty());
        for (int i = 0; i <= 16; ++i) {
            const auto smp = s.sample(vec2<T>(T(i) / T(16), T(0.3)));
            CHECK(apse::detail::is_finite(smp.pdf));
            CHECK(smp.pdf >= T(0));
            CHECK(std::fabs(glm::length(smp.direction) - T(1)) <= T(8) * apse::epsilon<T>());
        }
    }
}

TEMPLATE_TEST_CASE("DiskAreaSampler: samples on the disk, pdf consistent, inverse", "[area]", float, double) {
    using T = TestType;
    std::mt19937_64 rng(2);
    std::uniform_real_distribution<double> u(0, 1);
    const double tol = sizeof(T) == 8 ? 1e-9 : 2e-3;
    for (int cfg = 0; cfg < 30; ++cfg) {
        const vec3<T> c(T(u(rng) * 2 - 1), T(u(rng) * 2 - 1), T(u(rng) * 2 - 1));
        const vec3<T> n = T(0.5 + 3 * u(rng)) * glm::normalize(vec3<T>(T(u(rng) - 0.5), T(u(rng) - 0.5), T(u(rng) - 0.5)));
        const T r = T(0.2 + u(rng));
        const vec3<T> o(T(u(rng) * 6 - 3), T(u(rng) * 6 - 3), T(u(rng) * 6 - 3));
        const apse::DiskAreaSampler<T> s(o, c, n, r);
        REQUIRE_FALSE(s.empty());
        const auto ellipse = apse::project_disk(o, c, n, r);
        for (int k = 0; k < 200; ++k) {
            const vec2<T> uu(T(0.02 + 0.96 * u(rng)), T(0.02 + 0.96 * u(rng)));
            const auto smp = s.sample(uu);
            CHECK(smp.pdf > T(0));
            CHECK(std::fabs(glm::length(smp.direction) - T(1)) <= T(8) * apse::epsilon<T>());
            // the direction hits the disk: pdf() agrees, and the spherical ellipse contains it
            const T p = s.pdf(smp.direction);
            CHECK(double(p) == Approx(double(smp.pdf)).epsilon(tol));
            const vec2<T> back = s.invert(smp.direction);
            CHECK(std::fabs(double(back.x - uu.x)) <= 1e3 * tol);
            CHECK(std::fabs(double(back.y - uu.y)) <= 1e3 * tol);
            if (k % 4 == 0) CHECK(ellipse.contains(smp.direction));
        }
        // directions that miss: pdf 0
        CHECK(s.pdf(-glm::normalize(c - o)) == T(0));
    }
}

TEMPLATE_TEST_CASE("DiskAreaSampler: E[1/pdf] = Omega and the pdf integrates to 1", "[area]", float, double) {
    using T = TestType;
    struct Cfg {
        vec3<double> o, c, n;
        double r;
    };
    const Cfg cfgs[] = {
        {{0.3, 0.2, 1.0}, {0, 0, 0}, {0, 0, 1}, 1.0},
        {{2.5, -1.0, 0.4}, {0, 0, 0}, {0, 0, 1}, 1.0},
        {{0.1, 3.0, 2.0}, {0.5, 0.5, -0.5}, {1, 2, -0.5}, 0.7},
        {{0.0, 0.0, -5.0}, {0.2, 0.1, 0.0}, {0, 0, 3}, 2.0},  // behind (two-sided)
    };
    const int n = 256;  // n x n stratified samples
    for (const Cfg& cf : cfgs) {
        const vec3<T> o(cf.o), c(cf.c), nn(cf.n);
        const apse::DiskAreaSampler<T> s(o, c, nn, T(cf.r));
        const double omega = disk_omega_grid(cf.o, cf.c, cf.n, cf.r);
        std::mt19937_64 rng(4);
        std::uniform_real_distribution<double> u(0, 1);
        double sum = 0, sum2 = 0;
        for (int i = 0; i < n; ++i) {
            for (int j = 0; j < n; ++j) {
                const vec2<T> uu(T((i + u(rng)) / n), T((j + u(rng)) / n));
                const auto smp = s.sample(uu);
                REQUIRE(smp.pdf > T(0));
                const double w = 1.0 / double(smp.pdf);
                sum += w;
                sum2 += w * w;
            }
        }
        const double mean = sum / (n * n);
        const double se = std::sqrt(std::fmax(sum2 / (n * n) - mean * mean, 0.0) / (n * n));
        INFO("omega " << omega << " estimate " << mean << " standard error (iid bound) " << se);
        CHECK(std::fabs(mean - omega) <= 5 * se + 1e-5 * omega);
        // int pdf d(omega) = 1: directions uniform in a cap around the ellipse's centre that
        // contains the whole ellipse, pdf() averaged times the cap's solid angle
        const auto e = apse::project_disk(o, c, nn, T(cf.r));
        const double cap = std::fmin(double(e.alpha()) * 1.2, M_PI / 2);
        const double cap_omega = 2 * M_PI * (1 - std::cos(cap));
        double acc = 0;
        const int m = 400;
        for (int i = 0; i < m; ++i) {
            for (int j = 0; j < m; ++j) {
                const double z = 1 - (1 - std::cos(cap)) * (i + u(rng)) / m, phi = 2 * M_PI * (j + u(rng)) / m;
                const double st = std::sqrt(1 - z * z);
                const vec3<double> l(st * std::cos(phi), st * std::sin(phi), z);
                const vec3<T> d = e.to_world(vec3<T>(l));
                acc += double(s.pdf(d));
            }
        }
        CHECK(acc / (m * m) * cap_omega == Approx(1.0).epsilon(0.02));
    }
}

TEMPLATE_TEST_CASE("DiskAreaSampler: chi-square against its own pdf integrated over disk cells", "[area][chi2]",
                   float, double) {
    using T = TestType;
    // 100 000 samples into 10 equal-area rings x 16 sectors; expected counts are the sampler's
    // reported solid-angle density dist^2/(cos theta pi r^2) = d^2/(pi r^2 w_z^3) integrated over
    // each cell by DiskCells' independent Gauss–Legendre quadrature (exact to far below the
    // chi-square's resolution). Family-wise level 1 % over 2 disks x 2 types, Šidák-corrected.
    const double level = apse_test::sidak(0.01, 4);
    const double disks[][2] = {{1.0, 0.0}, {0.3, 1.6}};  // (d, h): frontal; close and oblique
    for (const auto& cfg : disks) {
        const apse_test::DiskCells cells{cfg[0], cfg[1], 1.0, 10, 16};
        const double d = cfg[0];
        std::vector<double> expected = cells.integrals(8, [d](double, double, double wz) {
            return d * d / (3.14159265358979323846 * wz * wz * wz);
        });
        const apse::DiskAreaSampler<T> sampler(vec3<T>(0), vec3<T>(T(cfg[1]), T(0), T(d)), vec3<T>(0, 0, 1), T(1));
        const int n = 100000;
        for (double& v : expected) v *= n;
        std::vector<double> observed(cells.count(), 0.0);
        apse_test::Rng rng(sizeof(T) * 31 + 5);
        for (int i = 0; i < n; ++i) {
            const auto s = sampler.sample(vec2<T>(rng.uniform<T>(), rng.uniform<T>()));
            REQUIRE(s.pdf > T(0));
            const double t = d / double(s.direction.z);
            const int c = cells.cell_of(double(s.direction.x) * t, double(s.direction.y) * t, 1e-4);
            REQUIRE(c >= 0);
            observed[c] += 1;
        }
        const auto r = apse_test::chi2_test(observed, expected);
        INFO("d " << d << " h " << cfg[1] << " chi2 " << r.chi2 << " dof " << r.dof << " p " << r.p);
        CHECK(r.p > level);
    }
}

TEMPLATE_TEST_CASE("DiskAreaSampler: degenerate input gives an empty sampler", "[area][robustness]", float, double) {
    using T = TestType;
    const T nan = std::numeric_limits<T>::quiet_NaN(), inf = std::numeric_limits<T>::infinity();
    const vec3<T> o(T(0.2), T(0.1), T(1)), c(0, 0, 0), n(0, 0, 1);
    const apse::DiskAreaSampler<T> bad[] = {
        {vec3<T>(T(0.5), 0, 0), c, n, T(1)},  // o in the plane (on the disk)
        {vec3<T>(3, 0, 0), c, n, T(1)},       // in the plane, outside
        {o, c, n, T(0)},
        {o, c, n, T(-1)},
        {o, c, n, nan},
        {o, c, n, inf},
        {o, c, vec3<T>(0), T(1)},
        {o, c, vec3<T>(nan, 0, 1), T(1)},
        {vec3<T>(inf, 0, 1), c, n, T(1)},
        {o, vec3<T>(0, nan, 0), n, T(1)},
    };
    for (const auto& s : bad) {
        CHECK(s.empty());
        const auto smp = s.sample(vec2<T>(T(0.3), T(0.7)));
        CHECK(smp.pdf == T(0));
        CHECK(std::fabs(glm::length(smp.direction) - T(1)) <= T(4) * apse::epsilon<T>());
        CHECK(s.pdf(vec3<T>(0, 0, -1)) == T(0));
        const vec2<T> uu = s.invert(vec3<T>(0, 0, -1));
        CHECK(apse::detail::is_finite(uu.x + uu.y));
    }
    const apse::DiskAreaSampler<T> ok(o, c, T(1e-30f) * n, T(1));  // any normal length
    CHECK_FALSE(ok.empty());
    CHECK(ok.pdf(vec3<T>(nan)) == T(0));
    CHECK(ok.pdf(vec3<T>(0)) == T(0));
    CHECK(ok.pdf(vec3<T>(0, 0, 1)) == T(0));  // away from the disk
    CHECK(ok.pdf(-o) > T(0));                  // towards the centre
    const vec2<T> centre = ok.invert(c - o);
    CHECK(std::fabs(centre.x - T(0.5)) <= T(1e-5));
    CHECK(std::fabs(centre.y - T(0.5)) <= T(1e-5));
}
