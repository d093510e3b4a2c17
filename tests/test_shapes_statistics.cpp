// Statistics of the maps fed by every light shape, float and double: the projections of oriented
// planar ellipses, spheres and ellipsoids (test_maps_statistics.cpp covers disks) give ellipses
// whose samples must be uniform in solid angle (chi-square against cell probabilities integrated
// independently over the light's cone, support/cone_cells.hpp) and whose reported pdf must give
// unbiased Monte Carlo estimates; and a multiple-importance-sampling estimator (light sampling +
// cosine-weighted BSDF sampling, balance heuristic, the light's pdf queried through map.pdf)
// converges to the quadrature reference.
#include <apse/maps/ld_radial.hpp>
#include <apse/maps/parallel.hpp>
#include <apse/comparison.hpp>
#include <apse/maps/tabulated_ld_radial.hpp>
#include <apse/projection.hpp>

#include "support/cone_cells.hpp"
#include "support/default_table.hpp"

#include "support/catch.hpp"

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace {

template <class T> using Vec2 = glm::vec<2, T>;
template <class T> using Vec3 = glm::vec<3, T>;

/// A light of one of the three shapes, given by exactly representable parameters (so float and
/// double see the same light; the cone is built in double from the same numbers).
struct Shape {
    std::string name;
    int kind;  // 0 planar ellipse (p1 = semi-axis u, p2 = semi-axis v), 1 sphere (radius r),
               // 2 ellipsoid (p1, p2, p3 orthogonal semi-axes)
    glm::dvec3 o, c, p1, p2, p3;
    double r;

    template <class T> apse::SphericalEllipse<T> project() const {
        const Vec3<T> to(o), tc(c);
        if (kind == 0) return apse::project_ellipse(to, tc, Vec3<T>(p1), Vec3<T>(p2));
        if (kind == 1) return apse::project_sphere(to, tc, T(r));
        return apse::project_ellipsoid(to, tc, Vec3<T>(p1), Vec3<T>(p2), Vec3<T>(p3));
    }

    apse_test::ConeCells cells(int rings, int sectors) const {
        apse_test::ConeMatrix cone;
        if (kind == 0) cone = apse_test::cone_of_ellipse(o, c, p1, p2);
        else if (kind == 1)
            cone = apse_test::cone_of_quadric(o, c, glm::dmat3(1.0 / (r * r)));
        else
            cone = apse_test::cone_of_quadric(o, c, apse_test::ellipsoid_matrix(p1, p2, p3));
        return apse_test::ConeCells(cone, c - o, rings, sectors);
    }
};

/// Two configurations per shape: moderate, and close / oblique (a large or thin ellipse on the
/// sphere of directions). Each cone contains c − o and is narrower than a half-space, so its
/// gnomonic section about c − o is a bounded ellipse (ConeCells checks this).
const std::vector<Shape>& shapes() {
    static const std::vector<Shape> s = {
        {"ellipse", 0, {0.25, -0.5, 0.125}, {0.5, 0.75, 2.0}, {1.0, 0.0, 0.5}, {0.0, 0.375, 0.0}, {}, 0},
        {"ellipse oblique", 0, {0.0, 0.0, 0.0}, {2.5, 0.25, 0.5}, {1.5, 0.0, 0.0}, {0.0, 0.5, 0.25}, {}, 0},
        {"sphere", 1, {0.125, 0.25, -0.375}, {1.0, 2.0, 3.0}, {}, {}, {}, 1.5},
        {"sphere close", 1, {0.0, 0.0, 0.0}, {0.75, -0.5, 0.625}, {}, {}, {}, 0.875},
        {"ellipsoid", 2, {0.0, 0.0, 0.0}, {0.5, 1.5, 2.5}, {0.75, 0.0, 0.0}, {0.0, 0.375, 0.5}, {0.0, -1.5, 1.125}, 0},
        {"ellipsoid needle", 2, {0.25, 0.0, -0.5}, {1.5, 0.5, 1.25}, {0.0, 0.0, 2.0}, {0.125, 0.0, 0.0}, {0.0, 0.0625, 0.0}, 0},
    };
    return s;
}


/// Calls f(name, map) for the three exact maps and, if `tabulated`, the two tabulated ones.
template <class T, class F> void for_each_map(const apse::SphericalEllipse<T>& e, bool tabulated, F&& f) {
    f(std::string("radial"), apse::RadialMap<T>(e));
    f(std::string("ld_radial"), apse::LdRadialMap<T>(e));
    f(std::string("parallel"), apse::ParallelMap<T>(e));
    if (tabulated) {
        f(std::string("tabulated"), apse::TabulatedMap<T>(e, apse_test::default_table().view()));
        f(std::string("tabulated_ld_radial"), apse::TabulatedLdRadialMap<T>(e, apse_test::default_table().view()));
    }
}

const char* type_name(std::size_t size) { return size == 4 ? "float" : "double"; }

}  // namespace

TEMPLATE_TEST_CASE("every shape: the cone cells cover the projected solid angle", "[shapes][statistics]", float, double) {
    using T = TestType;
    // The quadrature of the independent cone against the projection's solid angle: a check of
    // the test's own geometry (if the cones were wrong every chi-square below would be
    // meaningless). 8 × 8 nodes per cell of a smooth density: far below float's 1e-6.
    for (const Shape& s : shapes()) {
        const auto cells = s.cells(10, 16);
        REQUIRE(cells.valid);
        double omega = 0;
        for (double v : cells.solid_angles(8)) omega += v;
        const auto e = s.template project<T>();
        REQUIRE_FALSE(e.empty());
        INFO(s.name << " quadrature " << omega << " projection " << e.solid_angle());
        // float: the solid angle is within ~1e-6 relative of the exact value (docs/projection.md, Accuracy)
        CHECK(std::fabs(double(e.solid_angle()) - omega) <= (sizeof(T) == 4 ? 1e-5 : 1e-9) * omega);
    }
}

TEMPLATE_TEST_CASE("every shape: samples are uniform in solid angle (chi-square)", "[shapes][chi2]", float, double) {
    using T = TestType;
    // 100 000 samples into 10 equal-area rings × 16 sectors of the cone's gnomonic section (625
    // expected per cell on average), expected counts by quadrature of the independent cone.
    // Family-wise level 1 % over 6 shapes × 3 maps × 2 types = 36 tests, Šidák-corrected.
    const double level = apse_test::sidak(0.01, 36);
    std::uint64_t seed = sizeof(T) == 4 ? 3000 : 4000;
    for (const Shape& s : shapes()) {
        const auto cells = s.cells(10, 16);
        REQUIRE(cells.valid);
        std::vector<double> expected = cells.solid_angles(8);
        double total = 0;
        for (double v : expected) total += v;
        const int n = 100000;
        for (double& v : expected) v *= n / total;
        const auto e = s.template project<T>();
        REQUIRE_FALSE(e.empty());
        for_each_map(e, false, [&](const std::string& name, const auto& map) {
            apse_test::Rng rng(++seed);
            std::vector<double> observed(cells.count(), 0.0);
            int outside = 0;
            for (int i = 0; i < n; ++i) {
                const T u1 = rng.uniform<T>(), u2 = rng.uniform<T>();
                // slack 1e-4 in |y|²: float directions are rounded to ~1e-7, thin cones magnify it
                const int c = cells.cell_of(glm::dvec3(map.sample(Vec2<T>(u1, u2)).direction), 1e-4);
                if (c < 0) ++outside;
                else observed[c] += 1;
            }
            auto r = apse_test::chi2_test(observed, expected);
            std::printf("[%s] chi2 %s %s: chi2 %.1f dof %d p %.3f outside %d\n", type_name(sizeof(T)), s.name.c_str(),
                        name.c_str(), r.chi2, r.dof, r.p, outside);
            INFO(s.name << " " << name << " chi2 " << r.chi2 << " dof " << r.dof << " p " << r.p << " outside " << outside);
            CHECK(outside == 0);
            CHECK(r.p > level);
        });
    }
}

TEMPLATE_TEST_CASE("every shape: Monte Carlo estimates with the reported pdf are unbiased", "[shapes][unbiased]", float, double) {
    using T = TestType;
    // ∫ f dω over the light's cone, f a tilted cubic lobe, by quadrature of the independent cone
    // (10 × 16 cells × 12 × 12 nodes: relative error far below the estimates' 1e-3 standard
    // errors) against the mean of f/pdf over 200 000 independent samples, for the exact and the
    // tabulated maps: within 4.5 standard errors (two-sided 7e-6 per test; 60 tests).
    const glm::dvec3 lobe = glm::normalize(glm::dvec3(0.3, -0.4, 1.0));
    auto f = [&](const glm::dvec3& w) { const double c = glm::dot(w, lobe); return 1.0 + 3.0 * c * c * c; };
    for (const Shape& s : shapes()) {
        const auto cells = s.cells(10, 16);
        REQUIRE(cells.valid);
        double ref = 0;
        for (double v : cells.integrals(12, f)) ref += v;
        const auto e = s.template project<T>();
        for_each_map(e, true, [&](const std::string& name, const auto& map) {
            apse_test::Rng rng(sizeof(T) * 100 + 11);
            const int n = 200000;
            double sum = 0, sum2 = 0;
            for (int i = 0; i < n; ++i) {
                const auto smp = map.sample(Vec2<T>(rng.uniform<T>(), rng.uniform<T>()));
                const double v = smp.pdf > 0 ? f(glm::normalize(glm::dvec3(smp.direction))) / double(smp.pdf) : 0.0;
                sum += v;
                sum2 += v * v;
            }
            const double mean = sum / n, se = std::sqrt((sum2 / n - mean * mean) / n);
            std::printf("[%s] unbiased %s %s: estimate %.6g reference %.6g (%.2f standard errors)\n", type_name(sizeof(T)),
                        s.name.c_str(), name.c_str(), mean, ref, (mean - ref) / se);
            INFO(s.name << " " << name << " estimate " << mean << " reference " << ref << " se " << se);
            CHECK(std::fabs(mean - ref) <= 4.5 * se);
        });
    }
}

TEMPLATE_TEST_CASE("MIS: light + cosine BSDF sampling, balance heuristic, converges to the reference", "[shapes][mis][unbiased]", float, double) {
    using T = TestType;
    // Irradiance E = ∫ cos⁺θ dω over the light (unit radiance) at o, receiver normal nr tilted so
    // that part of the light is below the horizon for some shapes. Per pair of samples: one from
    // the map (pdf p_l), one cosine-weighted (p_b = cos θ / π), each weighted by the balance
    // heuristic f / (p_l + p_b); a BSDF direction hits the light when it is inside the
    // independent cone, and its p_l comes from map.pdf — a wrong MIS pdf biases the sum. Reference:
    // quadrature of cos⁺θ over the cone with 16 × 16 nodes per cell, required to agree with the
    // 8 × 8 rule to 1e-6 relative (cos⁺ has a kink where a light crosses the horizon: this checks
    // the rule has converged far below the ~1e-3 standard errors). 200 000 pairs, within 4.5 standard
    // errors; and the error of the first 12 500 pairs is also within 4.5 of its (4× larger)
    // standard errors, i.e. the estimate converges as 1/sqrt(N) to the same value.
    const glm::dvec3 nr = glm::normalize(glm::dvec3(0.4, 0.2, 0.9));
    auto cos_plus = [&](const glm::dvec3& w) { return std::fmax(0.0, glm::dot(w, nr)); };
    // orthonormal frame around nr for cosine sampling
    const glm::dvec3 t1 = glm::normalize(glm::cross(glm::dvec3(0, 1, 0), nr)), t2 = glm::cross(nr, t1);
    for (const Shape& s : shapes()) {
        const auto cells = s.cells(10, 16);
        REQUIRE(cells.valid);
        double ref = 0, ref8 = 0;
        for (double v : cells.integrals(16, cos_plus)) ref += v;
        for (double v : cells.integrals(8, cos_plus)) ref8 += v;
        INFO(s.name << " quadrature 16: " << ref << " 8: " << ref8);
        REQUIRE(std::fabs(ref - ref8) <= 1e-6 * ref);
        const auto e = s.template project<T>();
        for_each_map(e, true, [&](const std::string& name, const auto& map) {
            apse_test::Rng rng(sizeof(T) * 1000 + 17);
            const int n = 200000, n_early = 12500;
            double sum = 0, sum2 = 0, early_mean = 0, early_se = 0;
            for (int i = 0; i < n; ++i) {
                double v = 0;
                const auto ls = map.sample(Vec2<T>(rng.uniform<T>(), rng.uniform<T>()));
                if (ls.pdf > 0) {
                    const glm::dvec3 w = glm::normalize(glm::dvec3(ls.direction));
                    v += cos_plus(w) / (double(ls.pdf) + cos_plus(w) / double(apse_test::kTwoPi / 2));
                }
                // cosine-weighted hemisphere sample (Malley: uniform disk, lifted)
                const double r = std::sqrt(rng.uniform<double>()), phi = double(apse_test::kTwoPi) * rng.uniform<double>();
                const double x = r * std::cos(phi), y = r * std::sin(phi), z = std::sqrt(std::fmax(0.0, 1 - r * r));
                const glm::dvec3 wb = glm::normalize(x * t1 + y * t2 + z * nr);
                const double pb = z / double(apse_test::kTwoPi / 2);
                if (pb > 0 && cells.cell_of(wb, 0.0) >= 0) {
                    const double pl = double(map.pdf(Vec3<T>(wb)));
                    v += cos_plus(wb) / (pl + pb);
                }
                sum += v;
                sum2 += v * v;
                if (i + 1 == n_early) {
                    early_mean = sum / n_early;
                    early_se = std::sqrt((sum2 / n_early - early_mean * early_mean) / n_early);
                }
            }
            const double mean = sum / n, se = std::sqrt((sum2 / n - mean * mean) / n);
            std::printf("[%s] MIS %s %s: estimate %.6g reference %.6g (%.2f se; first %d: %.2f se)\n", type_name(sizeof(T)),
                        s.name.c_str(), name.c_str(), mean, ref, (mean - ref) / se, n_early, (early_mean - ref) / early_se);
            INFO(s.name << " " << name << " estimate " << mean << " reference " << ref << " se " << se);
            CHECK(std::fabs(mean - ref) <= 4.5 * se);
            CHECK(std::fabs(early_mean - ref) <= 4.5 * early_se);
        });
    }
}
