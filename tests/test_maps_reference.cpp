// The three area-preserving maps against independent references: the committed mpmath tables of
// tools/gen_maps_reference.py (cumulative areas by quadrature of their definitions, sampled
// directions solved from them at 40 digits), and long-double quadrature of the cumulative areas
// at the solver's solutions (CDF error), with the solver's iteration statistics.
#include <apse/maps/ld_radial.hpp>
#include <apse/maps/parallel.hpp>
#include <apse/comparison.hpp>
#include <apse/math.hpp>

#include "support/map_testing.hpp"

#include "support/catch.hpp"

#include <cmath>
#include <cstdio>
#include <map>
#include <string>
#include <vector>

namespace {

using apse_test::num;
using apse_test::read_table;

struct RefEllipse {
    double ta, tb, omega;
};

std::vector<RefEllipse> reference_ellipses() {
    std::vector<RefEllipse> out;
    for (const auto& row : read_table("maps/ellipses.txt")) out.push_back({num(row[1]), num(row[2]), num(row[3])});
    REQUIRE(out.size() >= 12);
    return out;
}

template <class T> apse::SphericalEllipse<T> make_ellipse(double ta, double tb) {
    using V = glm::vec<3, T>;
    return apse::SphericalEllipse<T>::from_tangents(V(1, 0, 0), V(0, 1, 0), V(0, 0, 1), T(ta), T(tb));
}

// ---- independent long-double quadrature of the cumulative areas (docs/math.md §4, §5 definitions) --
using LD = long double;
const LD kPi = 3.141592653589793238462643383279502884L;

struct Quadrature {
    LD a, b, ta, tb;  // sin alpha, sin beta, tan alpha, tan beta
    apse_test::GaussLegendre gl{24};
    Quadrature(double ta_, double tb_) : ta(ta_), tb(tb_) {
        a = ta / std::sqrt(1 + ta * ta);
        b = tb / std::sqrt(1 + tb * tb);
    }
    // 1 - cos theta_max(phi) = r^2/(1 + sqrt(1 - r^2)).
    LD wedge(LD phi) const {
        const LD s = std::sin(phi), c = std::cos(phi);
        const LD r2 = (a * b) * (a * b) / (a * a * s * s + b * b * c * c);
        return r2 / (1 + std::sqrt(1 - r2));
    }
    // Omega_r(phi): composite Gauss–Legendre split where the planar ellipse has k/32 of its area
    // (resolves the narrow peak of thin ellipses at phi = 0).
    LD radial(LD phi) const {
        // ... then doubling steps for the 1/phi^2 tail of thin ellipses.
        LD sum = 0, lo = 0;
        for (int k = 1; lo < phi; ++k) {
            LD hi = k < 32 ? std::atan2(tb * std::sin(k * kPi / 64), ta * std::cos(k * kPi / 64)) : 2 * lo;
            if (hi > phi) hi = phi;
            sum += gl.integrate([&](LD p) { return wedge(p); }, lo, hi);
            lo = hi;
        }
        return sum;
    }
    // I(psi) = int_0^psi 2 x_max, in the gnomonic angle theta (tan psi = tb sin theta), where the
    // integrand 2 ta tb cos^2/((1 + tb^2 s^2) sqrt(1 + ta^2 c^2 + tb^2 s^2)) has no endpoint
    // singularity (nearly hemispherical ellipses vary on 1/ta near pi/2 and on 1/tb near 0).
    LD parallel(LD psi) const {
        const LD th_end = std::asin(std::min<LD>(1, std::tan(psi) / tb));
        auto g = [&](LD th) {
            const LD s = std::sin(th), c = std::cos(th);
            return 2 * ta * tb * c * c / ((1 + tb * tb * s * s) * std::sqrt(1 + ta * ta * c * c + tb * tb * s * s));
        };
        // Pieces shrink geometrically towards both ends (wide ellipses vary on 1/tb near 0).
        std::vector<LD> pts;
        for (int k = 48; k >= 1; --k) pts.push_back(kPi / 4 * std::pow(LD(0.6), LD(k)));
        pts.push_back(kPi / 4);
        for (int k = 1; k <= 48; ++k) pts.push_back(kPi / 2 - kPi / 4 * std::pow(LD(0.6), LD(k)));
        pts.push_back(kPi / 2);
        LD sum = 0, lo = 0;
        for (std::size_t k = 0; k < pts.size() && lo < th_end; ++k) {
            const LD hi = std::min(pts[k], th_end);
            sum += gl.integrate(g, lo, hi);
            lo = hi;
        }
        return sum;
    }
};

}  // namespace

TEST_CASE("reference quadrature reproduces the mpmath tables", "[maps][reference]") {
    // Validates the test's own long-double quadrature (used for the CDF errors below) against the
    // 40-digit tables: it must be far more accurate (1e-15 relative) than the 1e-12 it checks.
    const auto ells = reference_ellipses();
    for (const auto& row : read_table("maps/radial_area.txt")) {
        const RefEllipse& e = ells[std::stoi(row[0])];
        const Quadrature q(e.ta, e.tb);
        INFO("ellipse " << row[0] << " phi " << row[1]);
        CHECK(std::fabs(double(q.radial(num(row[1]))) - num(row[2])) / (e.omega / 4) <= 1e-15);
    }
    for (const auto& row : read_table("maps/parallel_area.txt")) {
        const RefEllipse& e = ells[std::stoi(row[0])];
        const Quadrature q(e.ta, e.tb);
        INFO("ellipse " << row[0] << " psi " << row[1]);
        CHECK(std::fabs(double(q.parallel(num(row[1]))) - num(row[2])) / (e.omega / 2) <= 1e-15);
    }
}

TEMPLATE_TEST_CASE("cumulative areas match the references", "[maps][reference]", float, double) {
    using T = TestType;
    // Budgets relative to the area being accumulated (Omega/4 radial, Omega/2 parallel): the
    // closed forms are sums of non-negative terms (R_J, atan2) each good to a few eps, plus the
    // rounding of the arguments; 32 eps leaves room for R_J's own budget (tests/test_elliptic).
    const T tol = T(32) * apse::epsilon<T>();
    const auto ells = reference_ellipses();
    T worst_r = 0, worst_p = 0, worst_omega = 0;
    for (std::size_t i = 0; i < ells.size(); ++i) {
        const auto e = make_ellipse<T>(ells[i].ta, ells[i].tb);
        const T om = apse::RadialMap<T>(e).solid_angle();
        worst_omega = std::max(worst_omega, T(std::fabs(om - ells[i].omega) / ells[i].omega));
    }
    for (const auto& row : read_table("maps/radial_area.txt")) {
        const RefEllipse& r = ells[std::stoi(row[0])];
        const apse::RadialMap<T> map(make_ellipse<T>(r.ta, r.tb));
        const double err = std::fabs(double(map.quadrant_area(T(num(row[1])))) - num(row[2])) / (r.omega / 4);
        INFO("ellipse " << row[0] << " phi " << row[1] << " err " << err);
        CHECK(err <= tol);
        worst_r = std::max(worst_r, T(err));
    }
    for (const auto& row : read_table("maps/parallel_area.txt")) {
        const RefEllipse& r = ells[std::stoi(row[0])];
        const apse::ParallelMap<T> map(make_ellipse<T>(r.ta, r.tb));
        const double err = std::fabs(double(map.half_area(T(num(row[1])))) - num(row[2])) / (r.omega / 2);
        INFO("ellipse " << row[0] << " psi " << row[1] << " err " << err);
        CHECK(err <= tol);
        worst_p = std::max(worst_p, T(err));
    }
    std::printf("[%s] Omega max rel err %.2e; Omega_r max err %.2e (of Omega/4); I max err %.2e (of Omega/2)\n",
                sizeof(T) == 4 ? "float" : "double", double(worst_omega), double(worst_r), double(worst_p));
}

TEMPLATE_TEST_CASE("sampled directions match the references", "[maps][reference]", float, double) {
    using T = TestType;
    // Angular error relative to the ellipse's size sin(alpha) (directions of tiny ellipses differ
    // from the centre by ~alpha only). double: the inversion stops within 4 eps of the area and the
    // direction is built from the solution with a few more roundings: 1e-13 (~450 eps; measured
    // 1e-15). float: 1e-5 (~80 eps: the float R_J and the conditioning of the azimuth of thin
    // ellipses near their major axis; measured 8e-7). Measured values are printed below.
    const double tol = sizeof(T) == 4 ? 1e-5 : 1e-13;
    const auto ells = reference_ellipses();
    std::map<std::string, double> worst;
    for (const auto& row : read_table("maps/samples.txt")) {
        const RefEllipse& r = ells[std::stoi(row[0])];
        const auto e = make_ellipse<T>(r.ta, r.tb);
        const glm::vec<2, T> u(T(num(row[2])), T(num(row[3])));
        glm::vec<3, T> w;
        if (row[1] == "radial") w = apse::RadialMap<T>(e).sample(u).direction;
        else if (row[1] == "parallel") w = apse::ParallelMap<T>(e).sample(u).direction;
        else w = apse::LdRadialMap<T>(e).sample(u).direction;
        const double size = r.ta / std::sqrt(1 + r.ta * r.ta);
        // angle between the directions, |w x ref| (the z component of a direction near the centre
        // is 1 to within ulp(1), which would dominate a componentwise error for tiny ellipses)
        const glm::dvec3 ref(num(row[4]), num(row[5]), num(row[6]));
        const double err = glm::length(glm::cross(glm::dvec3(w), ref)) / size;
        INFO(row[1] << " ellipse " << row[0] << " u " << row[2] << " " << row[3] << " err " << err);
        CHECK(err <= tol);
        worst[row[1]] = std::max(worst[row[1]], err);
    }
    for (const auto& kv : worst)
        std::printf("[%s] %s direction max err %.2e (of sin alpha)\n", sizeof(T) == 4 ? "float" : "double",
                    kv.first.c_str(), kv.second);
}

TEMPLATE_TEST_CASE("inversion: CDF error and iteration statistics", "[maps][reference]", float, double) {
    using T = TestType;
    // Goals: CDF error <= 1e-12 relative in double, <= 1e-5 in float; mean <= 3 and
    // max <= 6 iterations over the test configurations (the reference ellipses: tiny, thin,
    // large, nearly hemispherical). The error is measured by the long-double quadrature above
    // (validated to 1e-15) at the state the solver returns, so it includes the rounding of that
    // state: in float tau itself is only known to ~6e-8.
    const double cdf_tol = sizeof(T) == 4 ? 1e-5 : 1e-12;
    const auto ells = reference_ellipses();
    const int n = 101;
    double worst_r = 0, worst_p = 0;
    long sum_r = 0, sum_p = 0, count = 0;
    int max_r = 0, max_p = 0;
    for (const auto& r : ells) {
        const auto e = make_ellipse<T>(r.ta, r.tb);
        const apse::RadialMap<T> radial(e);
        const apse::ParallelMap<T> parallel(e);
        const Quadrature q(r.ta, r.tb);
        const LD quarter = q.radial(kPi / 2), half = q.parallel(std::atan(LD(r.tb)));
        for (int i = 0; i < n; ++i) {
            const T f = T((i + 0.5) / n);
            int it = 0;
            const auto rp = radial.solve_quadrant(f, it);
            sum_r += it;
            max_r = std::max(max_r, it);
            // azimuth of the solution: tan phi = (b/a) tan tau
            const LD phi = std::atan2(q.b * LD(rp.st), q.a * LD(rp.ct));
            const double er = double(std::fabs(q.radial(phi) - LD(f) * quarter) / quarter);
            worst_r = std::max(worst_r, er);
            const auto pp = parallel.solve_half(f, it);
            sum_p += it;
            max_p = std::max(max_p, it);
            // slice of the solution psi = beta - e, e = 2 atan(t tan(beta/2)); edge area = half - I(psi)
            const LD psi = LD(e.beta()) - 2 * std::atan(LD(pp.t) * std::tan(LD(e.beta()) / 2));
            const double ep = double(std::fabs(half - q.parallel(psi) - LD(f) * half) / half);
            worst_p = std::max(worst_p, ep);
            ++count;
            INFO("ta " << r.ta << " tb " << r.tb << " f " << f << " radial err " << er << " parallel err " << ep);
            CHECK(er <= cdf_tol);
            CHECK(ep <= cdf_tol);
        }
    }
    const double mean_r = double(sum_r) / count, mean_p = double(sum_p) / count;
    std::printf("[%s] radial: CDF err max %.2e, iterations mean %.2f max %d | parallel: CDF err max %.2e, "
                "iterations mean %.2f max %d\n",
                sizeof(T) == 4 ? "float" : "double", worst_r, mean_r, max_r, worst_p, mean_p, max_p);
    CHECK(mean_r <= 3.0);
    CHECK(mean_p <= 3.0);
    CHECK(max_r <= 6);
    CHECK(max_p <= 6);
}
