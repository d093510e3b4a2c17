// Tests of CosineWeighted<Map>, the detail::ProjectedSolidAngleSampler it uses for the exact maps and the
// warp it uses for the tabulated maps (maps/tabulated_cosine.hpp): the pdf it reports is
// the density it draws from (chi-square against the reported pdf integrated over cells of the
// light by quadrature; Monte Carlo of ∫ max(0, n·ω) dω against quadrature), pdf(sample) =
// reported pdf, invert(sample(u)) = u, no sample below the horizon, an MIS estimator converging
// to the reference, degenerate normals, lights below the horizon and extreme lights (tiny and far,
// grazing, the horizon through the centre), and stratification kept. Every expected value comes
// from quadrature over the light's area, never from the code under test.

#include "support/catch.hpp"

#include <apse/apse.hpp>
#include <apse/math.hpp>
#include <apse/comparison.hpp>
#include <apse/runtime_sampler.hpp>

#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <type_traits>
#include <vector>

#include "support/default_table.hpp"
#include "support/map_testing.hpp"
#include "support/statistics.hpp"

namespace {

const double kPi = 3.14159265358979323846;

/// An elliptical light {z = d, ((x − h)/ra)^2 + (y/rb)^2 <= 1} seen from the origin (a disk when
/// ra = rb), and a receiver normal at the origin.
struct Config {
    double d, h, ra, rb;
    glm::dvec3 normal;
    const char* name;
};

// Above the horizon, straddling it (the receiver's horizon cuts the light), disks and ellipses.
const Config kConfigs[] = {
    {1.0, 0.3, 1.0, 1.0, {0.0, 0.0, 1.0}, "disk, facing, near"},
    {0.6, 1.2, 1.0, 1.0, {0.3, -0.2, 1.0}, "disk, oblique, near"},
    {1.0, 0.5, 1.0, 1.0, {1.0, 0.2, 0.25}, "disk, straddling the horizon"},
    {0.4, 0.0, 1.0, 1.0, {0.0, 1.0, 0.05}, "disk, straddling, grazing, large"},
    {0.8, 0.6, 1.5, 0.5, {0.2, 0.1, 1.0}, "ellipse, above"},
    {0.7, -0.3, 1.2, 0.4, {-0.3, 1.0, 0.3}, "ellipse, straddling"},
    {1.0, 0.5, 1.0, 1.0, {1.0, 0.2, -0.6}, "disk, straddling, centre below the horizon"},
    // n ⟂ the centre direction (0.3, 0, 0.8): the horizon through the centre
    {0.8, 0.3, 1.2, 0.6, {0.8, 0.4, -0.3}, "ellipse, straddling, horizon through the centre"},
};
constexpr int kConfigCount = int(sizeof(kConfigs) / sizeof(kConfigs[0]));

template <class T> glm::vec<3, T> tv(const glm::dvec3& v) { return glm::vec<3, T>(T(v.x), T(v.y), T(v.z)); }

template <class T> apse::SphericalEllipse<T> light_ellipse(const Config& c) {
    const glm::vec<3, T> o(T(0)), centre(T(c.h), T(0), T(c.d));
    if (c.ra == c.rb) return apse::project_disk(o, centre, glm::vec<3, T>(T(0), T(0), T(1)), T(c.ra));
    return apse::project_ellipse(o, centre, glm::vec<3, T>(T(c.ra), T(0), T(0)), glm::vec<3, T>(T(0), T(c.rb), T(0)));
}

apse::TabulationView table_view() { return apse_test::default_table().view(); }

template <class Map> Map make_map(const apse::SphericalEllipse<typename Map::vec3::value_type>& e) {
    using T = typename Map::vec3::value_type;
    if constexpr (std::is_same<Map, apse::TabulatedMap<T>>::value || std::is_same<Map, apse::TabulatedLdRadialMap<T>>::value)
        return Map(e, table_view());
    else
        return Map(e);
}

template <class Map> apse::CosineWeighted<Map> make_sampler(const Config& c) {
    using T = typename Map::vec3::value_type;
    return apse::CosineWeighted<Map>(make_map<Map>(light_ellipse<T>(c)), tv<T>(c.normal));
}

/// Polar cells of the elliptical light: `rings` equal-area rings × `sectors` sectors in the
/// light's own (rho, angle) coordinates; int_cell f(ω) dω by an n × n Gauss–Legendre rule per cell.
struct LightCells {
    Config c;
    int rings, sectors;
    int count() const { return rings * sectors; }
    int cell_of(const glm::dvec3& w) const {
        if (!(w.z > 0)) return -1;
        const double t = c.d / w.z, x = (w.x * t - c.h) / c.ra, y = w.y * t / c.rb;
        const double rho2 = x * x + y * y;
        if (rho2 > 1 + 1e-4) return -1;
        int ring = int(std::min(rho2, 1.0) * rings);
        if (ring >= rings) ring = rings - 1;
        double ang = std::atan2(y, x);
        if (ang < 0) ang += 2 * kPi;
        int sec = int(ang / (2 * kPi) * sectors);
        if (sec >= sectors) sec = sectors - 1;
        return ring * sectors + sec;
    }
    /// The innermost ring is integrated over geometrically shrinking pieces of rho (1/4 each):
    /// where the horizon passes close to the light's centre the cosine-weighted density is
    /// concentrated in a thin sliver there (the range along each azimuth ends at the horizon), which
    /// one Gauss–Legendre rule over the whole ring would miss.
    /// `split`: each cell's other rings are integrated in that many pieces of rho (where the
    /// horizon meets the rim, the density rises steeply over a small part of the outer ring).
    template <class F> std::vector<double> integrals(int n, F&& f, int split = 1) const {
        // The rule's nodes and the sums over rho in long double, the integrand at each node in
        // double: its relative rounding (~1e-16) summed over ~3e5 nodes stays below 1e-10 of the
        // integral, far below what the tests resolve (1e-6), and it is the bulk of the work —
        // long double is emulated in software on AArch64 (the qemu runs).
        apse_test::GaussLegendre gl(n);
        std::vector<double> out(count());
        std::vector<double> cos_ang(n), sin_ang(n);
        for (int i = 0; i < rings; ++i) {
            const long double r0 = std::sqrt((long double)i / rings), r1 = std::sqrt((long double)(i + 1) / rings);
            for (int j = 0; j < sectors; ++j) {
                const long double a0 = 2 * kPi * j / sectors, a1 = 2 * kPi * (j + 1) / sectors;
                auto cell_piece = [&](long double lo, long double hi, long double b0, long double b1) {
                    // the inner rule over the angle (GaussLegendre::integrate's nodes and sum, in
                    // its order) with the nodes' cosines and sines computed once for every rho
                    const long double h = (b1 - b0) / 2, m = (b0 + b1) / 2;
                    for (int k = 0; k < n; ++k) {
                        const double ang = double(m + h * gl.x[std::size_t(k)]);
                        cos_ang[std::size_t(k)] = std::cos(ang);
                        sin_ang[std::size_t(k)] = std::sin(ang);
                    }
                    return gl.integrate([&](long double rho_l) {
                        const double rho = double(rho_l);
                        double sum = 0;
                        for (std::size_t k = 0; k < gl.x.size(); ++k) {
                            const double x = c.h + c.ra * rho * cos_ang[k], y = c.rb * rho * sin_ang[k];
                            const double q = x * x + y * y + c.d * c.d, len = std::sqrt(q);
                            const glm::dvec3 w(x / len, y / len, c.d / len);
                            sum += double(gl.w[k]) * (c.ra * c.rb * rho * c.d / (q * len) * f(w));
                        }
                        return (long double)sum * h;
                    }, lo, hi);
                };
                auto piece = [&](long double lo, long double hi) {
                    long double t = 0;
                    for (int k = 0; k < split; ++k) t += cell_piece(lo, hi, a0 + (a1 - a0) * k / split, a0 + (a1 - a0) * (k + 1) / split);
                    return t;
                };
                long double sum = 0;
                if (i == 0) {
                    long double hi = r1;
                    for (int k = 0; k < 6; ++k, hi /= 4) sum += piece(hi / 4, hi);
                    sum += piece(0, hi);
                } else {
                    for (int k = 0; k < split; ++k) sum += piece(r0 + (r1 - r0) * k / split, r0 + (r1 - r0) * (k + 1) / split);
                }
                out[i * sectors + j] = double(sum);
            }
        }
        return out;
    }
};

/// ∫ max(0, n·ω) dω over the light (reference by quadrature over its area, in rings × sectors
/// cells).
double projected_solid_angle(const Config& c, int rings = 32, int sectors = 128) {
    const glm::dvec3 n = glm::normalize(c.normal);
    const LightCells cells{c, rings, sectors};
    double s = 0;
    for (double v : cells.integrals(8, [&](const glm::dvec3& w) { return std::max(glm::dot(n, w), 0.0); })) s += v;
    return s;
}

template <class Map> void check_chi2(const Config& c, double level) {
    using T = typename Map::vec3::value_type;
    const auto s = make_sampler<Map>(c);
    REQUIRE(s.weighted());
    const LightCells cells{c, 8, 24};
    // expected counts: the reported pdf integrated over each cell (8 × 8 nodes per cell: the pdf
    // is continuous and piecewise smooth, the rule's error is far below the counts' noise)
    std::vector<double> expected = cells.integrals(8, [&](const glm::dvec3& w) { return double(s.pdf(tv<T>(w))); }, 3);
    double total = 0;
    for (double v : expected) total += v;
    // the reported pdf integrates to 1 over the light (quadrature error of the kinks of the
    // piecewise-linear marginal and of the density at the horizon: ~1e-4; float pdfs ~1e-6)
    CHECK(total == Approx(1.0).epsilon(2e-3));
    const int n = 200000;
    for (double& v : expected) v *= n / total;
    std::vector<double> observed(cells.count(), 0.0);
    apse_test::Rng rng(20260101);
    int off = 0;
    for (int i = 0; i < n; ++i) {
        const auto d = s.sample(glm::vec<2, T>(rng.uniform<T>(), rng.uniform<T>()));
        const int k = d.pdf > T(0) ? cells.cell_of(glm::dvec3(d.direction)) : -1;
        if (k < 0) ++off;
        else observed[k] += 1;
    }
    CHECK(off == 0);
    const apse_test::Chi2Result r = apse_test::chi2_test(observed, expected);
    INFO(c.name << ": chi2 " << r.chi2 << " dof " << r.dof << " p " << r.p);
    CHECK(r.p > level);
}

constexpr int kChi2Tests = kConfigCount * 5 * 2;  // configurations × maps × types

template <class T> void chi2_all_maps(const Config& c) {
    const double level = apse_test::sidak(0.01, kChi2Tests);  // 1 % family-wise
    check_chi2<apse::RadialMap<T>>(c, level);
    check_chi2<apse::LdRadialMap<T>>(c, level);
    check_chi2<apse::ParallelMap<T>>(c, level);
    check_chi2<apse::TabulatedMap<T>>(c, level);
    check_chi2<apse::TabulatedLdRadialMap<T>>(c, level);
}

template <class Map> void check_mc_mean(const Config& c, double reference) {
    using T = typename Map::vec3::value_type;
    const auto s = make_sampler<Map>(c);
    const glm::dvec3 n = glm::normalize(c.normal);
    apse_test::Rng rng(777);
    const int N = 100000;
    double sum = 0, sum2 = 0;
    for (int i = 0; i < N; ++i) {
        const auto d = s.sample(glm::vec<2, T>(rng.uniform<T>(), rng.uniform<T>()));
        const double f = d.pdf > T(0) ? std::max(glm::dot(n, glm::dvec3(d.direction)), 0.0) / double(d.pdf) : 0.0;
        sum += f;
        sum2 += f * f;
    }
    const double mean = sum / N, se = std::sqrt(std::max(sum2 / N - mean * mean, 0.0) / N);
    INFO(c.name << ": mean " << mean << " reference " << reference << " se " << se);
    // 5 standard errors (a false alarm once in ~1.7 million runs per check), plus the
    // quadrature reference's own error (1e-6 relative)
    CHECK(std::fabs(mean - reference) < 5 * se + 1e-6 * reference);
}

template <class T> void mc_all_maps(const Config& c) {
    const double ref = projected_solid_angle(c);
    check_mc_mean<apse::RadialMap<T>>(c, ref);
    check_mc_mean<apse::LdRadialMap<T>>(c, ref);
    check_mc_mean<apse::ParallelMap<T>>(c, ref);
    check_mc_mean<apse::TabulatedMap<T>>(c, ref);
    check_mc_mean<apse::TabulatedLdRadialMap<T>>(c, ref);
}

/// pdf(sample(u).direction) equals the reported pdf and invert(sample(u).direction) returns u.
template <class Map> void check_round_trip(const Config& c, double pdf_tol, double u_tol) {
    using T = typename Map::vec3::value_type;
    const auto s = make_sampler<Map>(c);
    const glm::dvec3 n = glm::normalize(c.normal);
    const double eps = std::numeric_limits<T>::epsilon();
    apse_test::Rng rng(99);
    double worst_pdf = 0, worst_u = 0;
    for (int i = 0; i < 2000; ++i) {
        const glm::vec<2, T> u(rng.uniform<T>(), rng.uniform<T>());
        const auto d = s.sample(u);
        REQUIRE(d.pdf > T(0));
        // sample() has the cosine of its own solve, pdf() recomputes n·ω from the rounded
        // direction: near the horizon that differs by a few eps of T over the cosine (16 eps/cos
        // allowed on top of the tolerance)
        const double cosv = glm::dot(n, glm::dvec3(d.direction));
        const double err = std::fabs(double(s.pdf(d.direction)) / double(d.pdf) - 1.0) - 16 * eps / cosv;
        worst_pdf = std::max(worst_pdf, err);
        const glm::vec<2, T> back = s.invert(d.direction);
        // u1 = 0 and 1 are the same direction for the radial maps (the +x seam)
        double du1 = std::fabs(double(back.x) - double(u.x));
        du1 = std::min(du1, 1.0 - du1);
        worst_u = std::max(worst_u, std::max(du1, std::fabs(double(back.y) - double(u.y))));
    }
    INFO(c.name << ": worst pdf ratio − 1 " << worst_pdf << ", worst |invert(sample(u)) − u| " << worst_u);
    CHECK(worst_pdf < pdf_tol);
    CHECK(worst_u < u_tol);
}

template <class T> void round_trip_all_maps(const Config& c) {
    // The sampler's solve is converged to a few eps of F and its inverse is closed form
    // (measured worst beyond the cosine's rounding: below 1e-13 in double, 4.0e-6 in float).
    // Tolerances ~10× the measured worst.
    const bool dbl = std::is_same<T, double>::value;
    const double pdf_tol = dbl ? 1e-12 : 1e-4, u_tol = dbl ? 1e-12 : 5e-5;
    check_round_trip<apse::RadialMap<T>>(c, pdf_tol, u_tol);
    check_round_trip<apse::LdRadialMap<T>>(c, pdf_tol, u_tol);
    check_round_trip<apse::ParallelMap<T>>(c, pdf_tol, u_tol);
    check_round_trip<apse::TabulatedMap<T>>(c, pdf_tol, u_tol);
    check_round_trip<apse::TabulatedLdRadialMap<T>>(c, pdf_tol, u_tol);
}

}  // namespace

TEST_CASE("cosine-weighted: chi-square against the reported pdf, double", "[cosine][chi2]") {
    for (const Config& c : kConfigs) chi2_all_maps<double>(c);
}

TEST_CASE("cosine-weighted: chi-square against the reported pdf, float", "[cosine][chi2]") {
    for (const Config& c : kConfigs) chi2_all_maps<float>(c);
}

TEST_CASE("cosine-weighted: Monte Carlo mean of the projected solid angle within 5 standard errors", "[cosine][mc]") {
    for (const Config& c : kConfigs) {
        mc_all_maps<double>(c);
        mc_all_maps<float>(c);
    }
}

TEST_CASE("cosine-weighted: pdf(sample) is the reported pdf and invert(sample(u)) = u", "[cosine]") {
    for (const Config& c : kConfigs) {
        round_trip_all_maps<double>(c);
        round_trip_all_maps<float>(c);
    }
}

/// No sample below the receiver's horizon (n·ω <= 0) for a light straddling it, and the reported
/// pdf 0 on the whole part of the light below the horizon (the range along each azimuth ends at the
/// horizon, in closed form).
template <class Map> void check_below_horizon(const Config& c) {
    using T = typename Map::vec3::value_type;
    const auto s = make_sampler<Map>(c);
    const glm::dvec3 n = glm::normalize(c.normal);
    const LightCells cells{c, 32, 128};
    double p = 0;
    for (double v : cells.integrals(4, [&](const glm::dvec3& w) {
             return glm::dot(n, w) <= 0.0 ? double(s.pdf(tv<T>(w))) : 0.0;
         }))
        p += v;
    const int N = 200000;
    apse_test::Rng rng(4242);
    int below = 0, none = 0;
    for (int i = 0; i < N; ++i) {
        const auto d = s.sample(glm::vec<2, T>(rng.uniform<T>(), rng.uniform<T>()));
        if (!(d.pdf > T(0))) ++none;
        else if (glm::dot(n, glm::dvec3(d.direction)) <= 0.0) ++below;
    }
    INFO(c.name << ": below the horizon " << below << ", pdf 0 " << none << " of " << N << "; pdf integrated below " << p);
    CHECK(below == 0);
    CHECK(none == 0);
    // 0 but for directions within rounding of the horizon (this test's n·ω and the sampler's
    // differ by ~1e-16 there, where the density itself is ∝ n·ω ~ 1e-16): measured 1.5e-20
    CHECK(p < 1e-15);
}

TEST_CASE("cosine-weighted: no sample below the horizon of straddling lights", "[cosine]") {
    for (const Config& c : kConfigs) {
        if (std::string(c.name).find("straddling") == std::string::npos) continue;
        check_below_horizon<apse::TabulatedLdRadialMap<double>>(c);
        check_below_horizon<apse::RadialMap<double>>(c);
        check_below_horizon<apse::ParallelMap<float>>(c);
        check_below_horizon<apse::LdRadialMap<float>>(c);
    }
}

TEST_CASE("cosine-weighted: MIS with a cosine-sampled BSDF converges to the reference", "[cosine][mc]") {
    // Irradiance ∫ max(0, n·ω) dω over the light by one light sample (this sampler) and one
    // cosine-sampled direction per iteration, balance heuristic: unbiased only if the light's
    // pdf(ω) is the density of its samples and 0 off the light.
    for (const Config& c : kConfigs) {
        const double ref = projected_solid_angle(c);
        const auto s = make_sampler<apse::LdRadialMap<double>>(c);
        const auto e = light_ellipse<double>(c);
        const glm::dvec3 n = glm::normalize(c.normal);
        const glm::dvec3 t = glm::normalize(glm::cross(n, std::fabs(n.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0)));
        const glm::dvec3 b = glm::cross(n, t);
        apse_test::Rng rng(4242);
        const int N = 200000;
        double sum = 0, sum2 = 0;
        for (int i = 0; i < N; ++i) {
            double f = 0;
            const auto l = s.sample(glm::dvec2(rng.uniform<double>(), rng.uniform<double>()));
            if (l.pdf > 0) {
                const double cosv = std::max(glm::dot(n, l.direction), 0.0), pb = cosv / kPi;
                f += cosv / l.pdf * (l.pdf / (l.pdf + pb));
            }
            // cosine-weighted hemisphere direction (Malley), pdf cos/pi
            const double r = std::sqrt(rng.uniform<double>()), phi = 2 * kPi * rng.uniform<double>();
            const glm::dvec3 w = r * std::cos(phi) * t + r * std::sin(phi) * b + std::sqrt(std::max(1 - r * r, 0.0)) * n;
            const double pb = glm::dot(n, w) / kPi;
            if (pb > 0 && e.contains(w)) {
                const double pl = s.pdf(w);
                f += glm::dot(n, w) / pb * (pb / (pl + pb));
            }
            sum += f;
            sum2 += f * f;
        }
        const double mean = sum / N, se = std::sqrt((sum2 / N - mean * mean) / N);
        INFO(c.name << ": MIS " << mean << " reference " << ref << " se " << se);
        CHECK(std::fabs(mean - ref) < 5 * se + 1e-6 * ref);  // 5 standard errors, as above
    }
}

TEMPLATE_TEST_CASE("cosine-weighted: degenerate normals, lights below the horizon, bad input", "[cosine]", float, double) {
    using T = TestType;
    using V3 = glm::vec<3, T>;
    const Config c = kConfigs[1];
    const apse::LdRadialMap<T> map(light_ellipse<T>(c));
    const T nan = std::numeric_limits<T>::quiet_NaN(), inf = std::numeric_limits<T>::infinity();
    // zero / NaN / infinite normal: the plain map, exactly
    for (const V3& n : {V3(T(0)), V3(nan, T(0), T(1)), V3(inf, T(0), T(0))}) {
        const apse::CosineWeighted<apse::LdRadialMap<T>> s(map, n);
        CHECK_FALSE(s.empty());
        CHECK_FALSE(s.weighted());
        for (int i = 0; i < 16; ++i) {
            const glm::vec<2, T> u(T((i % 4 + 0.5) / 4), T((i / 4 + 0.5) / 4));
            const auto a = s.sample(u), b = map.sample(u);
            CHECK(a.pdf == b.pdf);
            CHECK(a.direction == b.direction);
            CHECK(s.pdf(a.direction) == map.pdf(a.direction));
        }
    }
    // a huge or tiny normal is only a direction
    const apse::CosineWeighted<apse::LdRadialMap<T>> unit(map, tv<T>(glm::normalize(c.normal)));
    const apse::CosineWeighted<apse::LdRadialMap<T>> big(map, tv<T>(c.normal) * T(1e30));
    const apse::CosineWeighted<apse::LdRadialMap<T>> small(map, tv<T>(c.normal) * T(1e-30));
    const glm::vec<2, T> u(T(0.3), T(0.7));
    CHECK(big.sample(u).pdf == Approx(unit.sample(u).pdf).epsilon(1e-5));
    CHECK(small.sample(u).pdf == Approx(unit.sample(u).pdf).epsilon(1e-5));
    // light entirely below the horizon (the normal facing away from it): empty, pdf 0
    for (const V3& n : {V3(T(0), T(0), T(-1)), V3(T(0.2), T(0.1), T(-1))}) {
        const apse::CosineWeighted<apse::LdRadialMap<T>> s(map, n);
        CHECK(s.empty());
        const auto d = s.sample(u);
        CHECK(d.pdf == T(0));
        CHECK(std::isfinite(d.direction.x + d.direction.y + d.direction.z));
        CHECK(s.pdf(map.sample(u).direction) == T(0));
    }
    // the light just below the horizon: the disk {z = 1, |(x − 0.5, y)| <= 1} touches the plane
    // x = 1.5 z (normal (1, 0, −1.5)) at its rim point (1.5, 0, 1); tilting the normal a little
    // further, (1, 0, −1.51), leaves n·ω < 0 on the whole disk: empty (the exact cone test)
    {
        const Config t{1.0, 0.5, 1.0, 1.0, {1.0, 0.0, -1.51}, "just below"};
        const apse::CosineWeighted<apse::LdRadialMap<T>> s(apse::LdRadialMap<T>(light_ellipse<T>(t)), tv<T>(t.normal));
        CHECK(s.empty());
    }
    // empty map
    const apse::CosineWeighted<apse::LdRadialMap<T>> none(apse::LdRadialMap<T>(apse::SphericalEllipse<T>::make_empty()),
                                                         V3(T(0), T(0), T(1)));
    CHECK(none.empty());
    CHECK(none.sample(u).pdf == T(0));
    CHECK(none.pdf(V3(T(0), T(0), T(1))) == T(0));
    // NaN u, NaN direction: pdf 0, finite results
    const auto s = unit.sample(glm::vec<2, T>(nan, T(0.5)));
    CHECK(s.pdf == T(0));
    CHECK(unit.pdf(V3(nan, T(0), T(1))) == T(0));
    const glm::vec<2, T> back = unit.invert(V3(nan, T(0), T(1)));
    CHECK(std::isfinite(back.x + back.y));
    // every point of the square, including the edges, gives a finite sample with pdf > 0
    for (int i = 0; i <= 16; ++i)
        for (int j = 0; j <= 16; ++j) {
            const auto d = unit.sample(glm::vec<2, T>(T(i / 16.0), T(j / 16.0)));
            CHECK(d.pdf > T(0));
            CHECK(std::isfinite(d.pdf + d.direction.x + d.direction.y + d.direction.z));
        }
}

namespace {

/// The variance ratios of the stratification test below for CosineWeighted<Map>: independent /
/// jittered points, and the plain map's jittered points / the weighted sampler's.
template <class Map> void check_stratification(const Config& c, double min_gain) {
    const glm::dvec3 n = glm::normalize(c.normal);
    auto f = [&](const glm::dvec3& w) { return std::max(glm::dot(n, w), 0.0); };
    const auto s = make_sampler<Map>(c);
    auto sample = [&](double u1, double u2) { return s.sample(glm::dvec2(u1, u2)); };
    const double vj = apse_test::estimator_variance<double>(sample, f, 16, 400, true, 11);
    const double vi = apse_test::estimator_variance<double>(sample, f, 16, 400, false, 12);
    const Map plain = make_map<Map>(light_ellipse<double>(c));
    auto sample_plain = [&](double u1, double u2) { return plain.sample(glm::dvec2(u1, u2)); };
    const double vp = apse_test::estimator_variance<double>(sample_plain, f, 16, 400, true, 11);
    INFO(c.name << (std::is_same<Map, apse::LdRadialMap<double>>::value ? ", exact sampler" : ", the tabulated map's warp")
                << ": variance independent / jittered = " << vi / vj << ", plain jittered / jittered = " << vp / vj);
    CHECK(vi / vj > min_gain);
    CHECK(vp / vj > 10.0);
}

}  // namespace

TEST_CASE("cosine-weighted: stratification kept (jittered beats independent)", "[cosine][stratification]") {
    // Variance of the 16 × 16-point estimator of ∫ max(0, n·ω) dω with jittered vs independent
    // points. With the exact conditional along each azimuth (the exact sampler), f/pdf depends
    // on the azimuth alone (the marginal's ratio to its piecewise-linear fit, which varies at the
    // scale of the 8 nodes), so the 16 × 16 jittered points stratify it in 16 columns only: a
    // gain of at most ~16 for a function varying at that scale (measured: 14.7–23.6 here, 5.7
    // for the radial layout); a sampler that broke stratification would leave a ratio near 1,
    // hence > 8. The tabulated maps' warp leaves a smooth residual in both coordinates (its
    // model along each ray too), which jittered points stratify in both: measured
    // 14.7–40.1, hence > 8 as well. And jittered cosine-weighted points must beat jittered
    // points of the plain map (the variance the weighting removes; measured 27–528× for the exact
    // sampler, 27–445× for the warp).
    for (const Config& c : {kConfigs[0], kConfigs[1], kConfigs[4]}) {
        check_stratification<apse::LdRadialMap<double>>(c, 8.0);
        check_stratification<apse::TabulatedLdRadialMap<double>>(c, 8.0);
    }
}

TEMPLATE_TEST_CASE("cosine-weighted DiskLight: the wrapper's density, points on the disk, unbiased",
                   "[cosine][unbiased]", float, double) {
    using T = TestType;
    using V3 = glm::vec<3, T>;
    // the disk of kConfigs[2] (straddling the horizon), seen from the origin
    const Config c = kConfigs[2];
    const V3 o(T(0)), centre(T(c.h), T(0), T(c.d)), axis(T(0), T(0), T(1)), n = tv<T>(c.normal);
    const double omega_perp = projected_solid_angle(c);
    for (apse::MapKind m : {apse::MapKind::radial, apse::MapKind::ld_radial, apse::MapKind::parallel}) {
        const apse::DiskLight<apse::RuntimeSampler<T>> light(o, centre, axis, T(c.ra), m, n);
        CHECK(light.cosine_weighted());
        const glm::dvec3 nd = glm::normalize(c.normal);
        apse_test::Rng rng(5);
        const int N = 50000;
        double sum = 0, sum2 = 0;
        for (int i = 0; i < N; ++i) {
            const glm::vec<2, T> u(rng.uniform<T>(), rng.uniform<T>());
            const apse::PointSample<T> s = light.sample(u);
            REQUIRE(s.pdf > T(0));
            // the point is on the disk, along the direction (float: ~1e-6 relative)
            CHECK(std::fabs(double(s.point.z) - c.d) < (sizeof(T) == 4 ? 1e-5 : 1e-12));
            CHECK(glm::length(glm::dvec3(o + s.distance * s.direction - s.point)) < (sizeof(T) == 4 ? 1e-5 : 1e-12));
            // as the round-trip test: ~10× the worst measured there
            CHECK(double(light.pdf(s.direction)) == Approx(double(s.pdf)).epsilon(sizeof(T) == 4 ? 1e-4 : 1e-12));
            const double f = std::max(glm::dot(nd, glm::dvec3(s.direction)), 0.0) / double(s.pdf);
            sum += f;
            sum2 += f * f;
        }
        const double mean = sum / N, se = std::sqrt((sum2 / N - mean * mean) / N);
        INFO("MC " << mean << " reference " << omega_perp << " se " << se);
        CHECK(std::fabs(mean - omega_perp) < 5 * se + 1e-6 * omega_perp);  // 5 standard errors
    }
    // a zero receiver normal: the plain light
    const apse::DiskLight<apse::RuntimeSampler<T>> plain(o, centre, axis, T(c.ra), apse::MapKind::ld_radial, V3(T(0)));
    const apse::DiskLight<apse::LdRadialMap<T>> ref(o, centre, axis, T(c.ra));
    CHECK(plain.sample(glm::vec<2, T>(T(0.3), T(0.6))).pdf == ref.sample(glm::vec<2, T>(T(0.3), T(0.6))).pdf);
}

TEST_CASE("cosine-weighted: trivially copyable", "[cosine]") {
    STATIC_REQUIRE(std::is_trivially_copyable<apse::CosineWeighted<apse::LdRadialMap<float>>>::value);
    STATIC_REQUIRE(std::is_trivially_copyable<apse::CosineWeighted<apse::TabulatedLdRadialMap<double>>>::value);
    STATIC_REQUIRE(std::is_trivially_copyable<apse::CosineWeighted<apse::ParallelMap<double>>>::value);
}

namespace {

/// A light's projected solid angle by quadrature at two resolutions: the difference bounds the
/// finer one's error.
struct QuadratureReference {
    double fine, coarse;
    explicit QuadratureReference(const Config& c) : fine(projected_solid_angle(c)), coarse(projected_solid_angle(c, 16, 64)) {}
};

/// A cosine-weighted sampler `s` of the ellipse `e` (detail::ProjectedSolidAngleSampler on its own, or
/// CosineWeighted over a map), for a light at the edge of its domain: every sample finite, inside
/// the light and above the horizon with pdf > 0, pdf(sample) = the reported pdf,
/// invert(sample(u)) = u, and the Monte Carlo mean of ∫ max(0, n·ω) dω within 5 standard errors
/// of quadrature `q` (plus the quadrature's own error: the difference of two resolutions).
template <class T, class Sampler>
void check_extreme(const Config& c, const QuadratureReference& q, const apse::SphericalEllipse<T>& e, const Sampler& s,
                   const char* sampler, double float_bound = 3e-5) {
    INFO(c.name << ", " << sampler << (sizeof(T) == 4 ? ", float" : ", double"));
    REQUIRE_FALSE(s.empty());
    const glm::dvec3 n = glm::normalize(c.normal);
    const double eps = std::numeric_limits<T>::epsilon();
    const double ref = q.fine, ref_coarse = q.coarse;
    apse_test::Rng rng(31);
    const int N = 20000;
    double sum = 0, sum2 = 0, worst_pdf = 0, worst_u = 0;
    int bad = 0;
    for (int i = 0; i < N; ++i) {
        const glm::vec<2, T> u(rng.uniform<T>(), rng.uniform<T>());
        const auto d = s.sample(u);
        const glm::dvec3 w(d.direction);
        const double cosv = glm::dot(n, w);
        if (!(d.pdf > T(0)) || !std::isfinite(double(d.pdf)) || !(cosv > 0) || !(std::fabs(glm::length(w) - 1) < 1e-5) ||
            !e.contains(d.direction)) {
            ++bad;
            continue;
        }
        const double f = cosv / double(d.pdf);
        sum += f;
        sum2 += f * f;
        // as in the round trip above: a few eps of T over the cosine from the direction's rounding
        worst_pdf = std::max(worst_pdf, std::fabs(double(s.pdf(d.direction)) / double(d.pdf) - 1.0) - 16 * eps / cosv);
        const glm::vec<2, T> back = s.invert(d.direction);
        double du1 = std::fabs(double(back.x) - double(u.x));
        du1 = std::min(du1, 1.0 - du1);
        worst_u = std::max(worst_u, std::max(du1, std::fabs(double(back.y) - double(u.y))));
    }
    const double mean = sum / N, se = std::sqrt(std::max(sum2 / N - mean * mean, 0.0) / N);
    INFO("bad samples " << bad << "; MC " << mean << " reference " << ref << " (coarser: " << ref_coarse << ") se " << se
                        << "; worst pdf ratio − 1 " << worst_pdf << ", worst |invert(sample(u)) − u| " << worst_u);
    CHECK(bad == 0);
    CHECK(std::fabs(mean - ref) < 5 * se + std::fabs(ref - ref_coarse) + 1e-6 * ref);
    // as in the round trip above: ~10× the worst measured over these lights for the exact sampler
    // (float 2.9e-6, double below 1e-13); `float_bound` for the tabulated maps' warp (below)
    CHECK(worst_pdf < (sizeof(T) == 4 ? float_bound : 1e-12));
    CHECK(worst_u < (sizeof(T) == 4 ? 3e-5 : 1e-12));
}

const Config kExtremes[] = {
    {1e4, 0.0, 1.0, 1.0, {0.3, 0.2, 1.0}, "tiny far disk (theta_max 1e-4)"},
    {1e4, 0.0, 1.0, 1.0, {1.0, 0.3, 1e-5}, "tiny far disk, horizon 1e-5 from the centre"},
    {1e-3, 1.2, 1.0, 1.0, {0.0, 0.3, 1.0}, "grazing: 1e-3 above the disk's plane, 0.2 from its rim"},
    {1.0, 0.0, 1.0, 1.0, {1.0, 0.0, 0.0}, "normal perpendicular to the axis: the horizon through the centre"},
    {1.0, 0.0, 1.0, 1.0, {1.0, 0.0, 1e-7}, "the horizon 1e-7 from the centre"},
    {0.5, 0.2, 2.0, 0.02, {0.1, 1.0, 0.5}, "thin ellipse, straddling"},
};

}  // namespace

TEMPLATE_TEST_CASE("projected-solid-angle sampler: extreme lights", "[cosine]", float, double) {
    for (const Config& c : kExtremes) {
        const apse::SphericalEllipse<TestType> e = light_ellipse<TestType>(c);
        check_extreme(c, QuadratureReference(c), e, apse::detail::ProjectedSolidAngleSampler<TestType>(e, tv<TestType>(c.normal)),
                      "exact sampler");
    }
}

/// Whether CosineWeighted over a tabulated map uses its warp for this light and normal (the
/// ellipse's centre above the horizon by more than 1e-3 of the normal's largest local component;
/// cosine_weighted.hpp), rather than the exact sampler.
template <class T> bool uses_warp(const apse::SphericalEllipse<T>& e, const glm::vec<3, T>& n) {
    const glm::vec<3, T> l = e.to_local(n);
    return double(l.z) > 1e-3 * std::max({std::fabs(double(l.x)), std::fabs(double(l.y)), std::fabs(double(l.z))});
}

TEMPLATE_TEST_CASE("cosine-weighted: a zero, NaN or infinite direction inverts to (0, 0) in every mode", "[cosine]", float, double) {
    // As the plain maps' invert: the plain mode (a zero normal), the exact sampler and the warp,
    // over the LD-radial maps (whose concentric map would send the inner (0, 0) to the square's
    // centre) and the radial ones; a valid direction inverts as the plain map in the plain mode.
    using T = TestType;
    using V3 = glm::vec<3, T>;
    using V2 = glm::vec<2, T>;
    const T nan = std::numeric_limits<T>::quiet_NaN(), inf = std::numeric_limits<T>::infinity();
    const apse::SphericalEllipse<T> e = light_ellipse<T>(kConfigs[0]);
    const V3 n = tv<T>(kConfigs[0].normal);
    REQUIRE(uses_warp(e, n));
    const V3 bad[] = {V3(T(0)), V3(nan, T(0), T(1)), V3(inf, T(0), T(1))};
    auto check = [&](const auto& s, const auto& plain, bool weighted) {
        CHECK(s.weighted() == weighted);
        for (const V3& d : bad) {
            CHECK(s.invert(d) == V2(T(0)));
            CHECK(plain.invert(d) == V2(T(0)));
        }
        if (!weighted) {
            const V3 d = plain.sample(V2(T(0.3), T(0.7))).direction;
            CHECK(s.invert(d) == plain.invert(d));
        }
    };
    const apse::LdRadialMap<T> ld(e);
    const apse::RadialMap<T> radial(e);
    const apse::TabulatedLdRadialMap<T> tab_ld(e, table_view());
    const apse::TabulatedMap<T> tab(e, table_view());
    check(apse::CosineWeighted<apse::LdRadialMap<T>>(ld, V3(T(0))), ld, false);
    check(apse::CosineWeighted<apse::LdRadialMap<T>>(ld, n), ld, true);
    check(apse::CosineWeighted<apse::RadialMap<T>>(radial, n), radial, true);
    check(apse::CosineWeighted<apse::TabulatedLdRadialMap<T>>(tab_ld, V3(T(0))), tab_ld, false);
    check(apse::CosineWeighted<apse::TabulatedLdRadialMap<T>>(tab_ld, n), tab_ld, true);
    check(apse::CosineWeighted<apse::TabulatedMap<T>>(tab, n), tab, true);
}

TEMPLATE_TEST_CASE("cosine-weighted tabulated maps: extreme lights and every test light", "[cosine]", float, double) {
    // The warp the tabulated maps use while the centre is above the horizon (and the exact
    // sampler otherwise) through the same checks as the exact sampler above. The warp's pdf at a
    // direction is the tabulated map's, recomputed from the direction (lambda through atan2,
    // r = sqrt(u2) from 1 − cos theta: float rounding moves r by ~eps/(2 r (1 − C)) near the
    // centre), times the warp's density there: in float it matches the reported pdf to the
    // tabulated map's own precision (test_tabulated.cpp: 1e-3, 2 % within a few ulps of a bin
    // edge), measured here 1.3e-5 with g++, 4.5e-5 with clang ("disk, oblique, near") and 1.5e-3
    // with g++ -ffast-math (the thin ellipse, whose azimuth float resolves worst), hence the bound
    // 5e-3 in float (double: unchanged).
    using T = TestType;
    int warped = 0;
    auto check = [&](const Config& c) {
        const apse::SphericalEllipse<T> e = light_ellipse<T>(c);
        warped += uses_warp(e, tv<T>(c.normal)) ? 1 : 0;
        const QuadratureReference q(c);
        check_extreme(c, q, e, apse::CosineWeighted<apse::TabulatedMap<T>>(apse::TabulatedMap<T>(e, table_view()), tv<T>(c.normal)),
                      "CosineWeighted<TabulatedMap>", 5e-3);
        check_extreme(c, q, e,
                      apse::CosineWeighted<apse::TabulatedLdRadialMap<T>>(apse::TabulatedLdRadialMap<T>(e, table_view()), tv<T>(c.normal)),
                      "CosineWeighted<TabulatedLdRadialMap>", 5e-3);
    };
    for (const Config& c : kExtremes) check(c);
    for (const Config& c : kConfigs) check(c);
    CHECK(warped >= 8);  // the test lights with the centre above the horizon (counted: 9)
}

namespace {

/// The fuzz tests' random ellipse: tangents from 1e-20 to 1e20 (a twentieth of them 1e30, beyond
/// the cap), the minor's down to 1e-10 of the major's (returned in `tb`).
template <class T> apse::SphericalEllipse<T> fuzz_ellipse(apse_test::Rng& rng, double& tb) {
    using V3 = glm::vec<3, T>;
    double ta = std::pow(10.0, -20 + 40 * rng.uniform<double>());
    tb = ta * std::pow(10.0, -10 * rng.uniform<double>());
    if (rng.uniform<double>() < 0.05) ta = 1e30;
    return apse::SphericalEllipse<T>::from_tangents(V3(1, 0, 0), V3(0, 1, 0), V3(0, 0, 1), T(ta), T(tb));
}

/// The fuzz tests' random normal in the ellipse's frame: any direction; with probability
/// `zero_z` perpendicular to the axis, then with probability 0.1 its axial component uniform in
/// ±small_z/2, and a twentieth of them tiny (1e-30 of unit length).
template <class T> glm::vec<3, T> fuzz_normal(apse_test::Rng& rng, double zero_z, double small_z) {
    glm::vec<3, T> n(T(rng.uniform<double>() * 2 - 1), T(rng.uniform<double>() * 2 - 1), T(rng.uniform<double>() * 2 - 1));
    if (zero_z > 0 && rng.uniform<double>() < zero_z) n.z = T(0);
    if (rng.uniform<double>() < 0.1) n.z = T((rng.uniform<double>() - 0.5) * small_z);
    if (rng.uniform<double>() < 0.05) n *= T(1e-30);
    return n;
}

/// One fuzz sample and the pdf there.
template <class T> struct FuzzSample {
    apse::DirectionSample<T> sample;
    double cos_theta;  ///< with the receiver's unit normal
    T pdf;             ///< pdf(sample.direction)
};

/// The fuzz tests' k-th sample of `s` (k < 3: a random interior point of the square, counted in
/// `interior` and, if declined (pdf 0), in `declined`; k = 3: a random corner), with the checks
/// both make: sample, pdf and inverse finite, the pdf >= 0, a sample with pdf > 0 above the
/// horizon of the unit normal `nd` (to float's rounding of the direction).
template <class T, class Sampler>
FuzzSample<T> fuzz_sample(const Sampler& s, apse_test::Rng& rng, int k, const glm::dvec3& nd, int& interior, int& declined) {
    glm::vec<2, T> u(rng.uniform<T>(), rng.uniform<T>());
    if (k == 3) u = glm::vec<2, T>(T(rng.uniform<double>() < 0.5 ? 0 : 1), T(rng.uniform<double>() < 0.5 ? 0 : 1));
    const auto d = s.sample(u);
    const double w = double(d.direction.x) + double(d.direction.y) + double(d.direction.z);
    REQUIRE(std::isfinite(double(d.pdf)));
    REQUIRE(std::isfinite(w));
    REQUIRE(d.pdf >= T(0));
    const double cos_theta = glm::dot(nd, glm::dvec3(d.direction));
    if (d.pdf > T(0)) REQUIRE(cos_theta > -1e-6);  // float's rounding of the direction
    if (k < 3) ++interior, declined += d.pdf > T(0) ? 0 : 1;
    const T p = s.pdf(d.direction);
    REQUIRE(std::isfinite(double(p)));
    const glm::vec<2, T> b = s.invert(d.direction);
    REQUIRE(std::isfinite(double(b.x) + double(b.y)));
    return {d, cos_theta, p};
}

}  // namespace

TEMPLATE_TEST_CASE("cosine-weighted tabulated maps: random ellipses and normals, finite results", "[cosine]", float, double) {
    // As the exact sampler's fuzz test below, through CosineWeighted<TabulatedMap> (the warp where the
    // centre is above the horizon): every sample, pdf and inverse finite, every sample with pdf > 0
    // above the horizon (to the rounding of the direction), the pdf of a sample equal to the
    // reported one, few samples declined at interior points of the square.
    using T = TestType;
    apse_test::Rng rng(2027);
    int samplers = 0, warped = 0, declined = 0, interior = 0;
    double worst_pdf = 0;
    for (int i = 0; i < 20000; ++i) {
        double tb = 0;
        const apse::SphericalEllipse<T> e = fuzz_ellipse<T>(rng, tb);
        const glm::vec<3, T> n = fuzz_normal<T>(rng, 0.0, 1e-2);
        const apse::CosineWeighted<apse::TabulatedMap<T>> s(apse::TabulatedMap<T>(e, table_view()), n);
        if (s.empty()) continue;
        ++samplers;
        warped += uses_warp(e, n) ? 1 : 0;
        const glm::dvec3 nd = glm::normalize(glm::dvec3(n));
        for (int k = 0; k < 4; ++k) {
            const FuzzSample<T> f = fuzz_sample<T>(s, rng, k, nd, interior, declined);
            // the warp's pdf(sample) = reported, at interior points of the square away from the horizon
            // (where the cosine's rounding dominates; on the rim the direction may round outside), for
            // tan beta >= 1e-15 in float (below, the squares of the direction's components come near
            // float's subnormal range, flushed to zero under -ffast-math: the azimuth is lost)
            const bool resolved = sizeof(T) == 8 || tb >= 1e-15;
            if (uses_warp(e, n) && resolved && k < 3 && f.sample.pdf > T(0) && f.cos_theta > 1e-3)
                worst_pdf = std::max(worst_pdf, std::fabs(double(f.pdf) / double(f.sample.pdf) - 1.0));
        }
    }
    INFO(samplers << " samplers (" << warped << " warped), " << declined << " of " << interior
                  << " interior samples declined; worst |pdf(sample)/pdf − 1| " << worst_pdf);
    CHECK(samplers > 5000);
    CHECK(warped > 2000);
    CHECK(declined * 1000 < interior);
    // measured: 1.5e-5 in float (a large ellipse near its rim, the float direction's rounding;
    // 1.0e-5 under -ffast-math), below 1e-15 in double; the bounds ~7× and ~1000× that
    CHECK(worst_pdf < (sizeof(T) == 4 ? 1e-4 : 1e-12));
}

TEMPLATE_TEST_CASE("projected-solid-angle sampler: empty cases and outside directions", "[cosine]", float, double) {
    using T = TestType;
    using V3 = glm::vec<3, T>;
    const apse::SphericalEllipse<T> e = light_ellipse<T>(kConfigs[2]);
    const T nan = std::numeric_limits<T>::quiet_NaN();
    const glm::vec<2, T> u(T(0.3), T(0.6));
    // the default sampler, an empty ellipse, zero/NaN normals, the light below the horizon: empty
    const apse::detail::ProjectedSolidAngleSampler<T> none[] = {
        apse::detail::ProjectedSolidAngleSampler<T>(), apse::detail::ProjectedSolidAngleSampler<T>(apse::SphericalEllipse<T>::make_empty(), V3(0, 0, 1)),
        apse::detail::ProjectedSolidAngleSampler<T>(e, V3(T(0))), apse::detail::ProjectedSolidAngleSampler<T>(e, V3(nan, T(0), T(1))),
        apse::detail::ProjectedSolidAngleSampler<T>(e, -e.z)};
    for (const auto& s : none) {
        CHECK(s.empty());
        CHECK(s.sample(u).pdf == T(0));
        CHECK(s.pdf(e.z) == T(0));
        const glm::vec<2, T> b = s.invert(e.z);
        CHECK(std::isfinite(double(b.x + b.y)));
    }
    // straddling light: pdf 0 outside the ellipse and below the horizon, > 0 above inside
    const apse::detail::ProjectedSolidAngleSampler<T> s(e, tv<T>(kConfigs[2].normal));
    REQUIRE_FALSE(s.empty());
    const glm::dvec3 n = glm::normalize(kConfigs[2].normal);
    apse_test::Rng rng(7);
    int inside_above = 0, inside_below = 0;
    for (int i = 0; i < 4000; ++i) {
        const glm::dvec3 w = glm::normalize(glm::dvec3(rng.uniform<double>() * 2 - 1, rng.uniform<double>() * 2 - 1, rng.uniform<double>()));
        const V3 wt = tv<T>(w);
        const double p = double(s.pdf(wt));
        CHECK(std::isfinite(p));
        if (!e.contains(wt)) {
            CHECK(p == 0.0);
        } else if (glm::dot(n, w) <= 0.0) {
            ++inside_below;
            CHECK(p == 0.0);
        } else if (glm::dot(n, w) > 1e-3) {
            ++inside_above;
            CHECK(p > 0.0);
        }
        const glm::vec<2, T> b = s.invert(wt);
        CHECK((b.x >= T(0) && b.x <= T(1) && b.y >= T(0) && b.y <= T(1)));
    }
    CHECK(inside_above > 0);
    CHECK(inside_below > 0);
    STATIC_REQUIRE(std::is_trivially_copyable<apse::detail::ProjectedSolidAngleSampler<T>>::value);
}

TEMPLATE_TEST_CASE("projected-solid-angle sampler: random ellipses and normals, finite results", "[cosine]", float, double) {
    // Tangents from 1e-20 to beyond the cap and down to 1e-10 of each other, normals of every
    // direction (a fifth perpendicular to the axis, a tenth within 1e-6 of it, some tiny): every
    // sample, pdf and inverse is finite, every sample with pdf > 0 lies above the horizon (to the
    // rounding of the direction), and samples declined (pdf 0) at interior points of the square
    // are rare (measured: 16 of 430 000 in float, 4 of 490 000 in double, all on ellipses thinner
    // than 5e9 : 1 whose centre is below the horizon).
    using T = TestType;
    apse_test::Rng rng(2026);
    int samplers = 0, declined = 0, interior = 0;
    for (int i = 0; i < 20000; ++i) {
        double tb = 0;
        const apse::SphericalEllipse<T> e = fuzz_ellipse<T>(rng, tb);
        const glm::vec<3, T> n = fuzz_normal<T>(rng, 0.2, 1e-6);
        const apse::detail::ProjectedSolidAngleSampler<T> s(e, n);
        if (s.empty()) continue;
        ++samplers;
        const glm::dvec3 nd = glm::normalize(glm::dvec3(n));
        for (int k = 0; k < 4; ++k) fuzz_sample<T>(s, rng, k, nd, interior, declined);
    }
    INFO(samplers << " samplers, " << declined << " of " << interior << " interior samples declined");
    CHECK(samplers > 10000);
    CHECK(declined * 1000 < interior);  // < 0.1 % (measured ~3e-5)
}

TEST_CASE("projected-solid-angle sampler: a density beyond float's range is declined, never infinite", "[cosine]") {
    // A light of 2e-36 sr cut by the horizon near its centre: its projected solid angle is ~1e-55
    // (below float's range), and near the ends of the arc above the horizon the density exceeds
    // float's maximum (before, 128 of these 4096 samples reported an infinite pdf). Such samples
    // are declined (pdf 0), and only those: the same sampler in double reports a density above
    // 1e38 at every declined point (float's maximum is 3.4e38; the margin covers float's rounding
    // of the geometry).
    using V = glm::vec3;
    const auto e = apse::SphericalEllipse<float>::from_tangents(V(1, 0, 0), V(0, 1, 0), V(0, 0, 1), 1e-18f, 6.5e-19f);
    const auto ed = apse::SphericalEllipse<double>::from_tangents(glm::dvec3(1, 0, 0), glm::dvec3(0, 1, 0), glm::dvec3(0, 0, 1),
                                                                  double(1e-18f), double(6.5e-19f));
    const apse::detail::ProjectedSolidAngleSampler<float> s(e, V(1, 0.3f, 1e-22f));
    const apse::detail::ProjectedSolidAngleSampler<double> sd(ed, glm::dvec3(1, 0.3f, 1e-22f));
    REQUIRE_FALSE(s.empty());
    int declined = 0;
    for (int i = 0; i < 64; ++i)
        for (int j = 0; j < 64; ++j) {
            const glm::vec2 u((float(i) + 0.5f) / 64, (float(j) + 0.5f) / 64);
            const auto d = s.sample(u);
            REQUIRE(std::isfinite(d.pdf));
            REQUIRE(d.pdf >= 0.0f);
            REQUIRE(std::isfinite(s.pdf(d.direction)));
            if (d.pdf > 0.0f) continue;
            ++declined;
            CHECK(sd.sample(glm::dvec2(u)).pdf > 1e38);
        }
    INFO(declined << " of 4096 declined");
    CHECK(declined < 4096 / 10);  // measured 128: the ends of the arc only
}

TEMPLATE_TEST_CASE("a normal with subnormal components in the ellipse's frame still gives unit directions", "[cosine][robust]", float, double) {
    using T = TestType;
    using V3 = glm::vec<3, T>;
    // Found by fuzz_shapes: a huge normal (−DBL_MAX along z, −1e-12 along y) is, once
    // normalised and in the ellipse's frame, ~1e-320 in two components; the horizon's sine and
    // cosine from those subnormals were 0.04 % off a unit pair, and so were the directions near
    // the range's end (u2 = 1). Unit to rounding now (directions: 64 eps as everywhere).
    const auto e = apse::project_ellipse(V3(T(3), T(1e-30), T(3)), V3(T(3.14159265358979), T(3), T(3)),
                                         V3(T(2), T(-4), T(0)), V3(T(0), T(0), T(-1)));
    const V3 n(T(0), T(-1e-12), -std::numeric_limits<T>::max());
    const apse::CosineWeighted<apse::RadialMap<T>> s(apse::RadialMap<T>(e), n);
    REQUIRE(s.weighted());
    const T tiny = std::numeric_limits<T>::min();
    for (const T u1 : {tiny, T(1e-6), T(0.25), T(0.5), T(0.999)}) {
        for (const T u2 : {T(0), T(0.5), T(1)}) {
            const auto smp = s.sample(glm::vec<2, T>(u1, u2));
            CHECK(apse::detail::is_finite(smp.pdf));
            if (smp.pdf > T(0)) CHECK(std::fabs(glm::length(smp.direction) - T(1)) <= T(64) * apse::epsilon<T>());
        }
    }
}
