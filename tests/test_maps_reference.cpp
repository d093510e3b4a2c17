// The three area-preserving maps against independent references: the committed mpmath tables of
// tools/gen_maps_reference.py (cumulative areas by quadrature of their definitions, sampled
// directions solved from them at 40 digits), and long-double quadrature of the cumulative areas
// at the solver's solutions (CDF error), with the solver's iteration statistics.
#include "support/maps_measures.hpp"
#include "support/statistics.hpp"

#include "support/catch.hpp"

#include <cmath>
#include <cstdio>
#include <map>
#include <string>
#include <vector>

namespace {

using apse_test::num;
using apse_test::read_table;
using apse_test::RefEllipse;

std::vector<RefEllipse> reference_ellipses() {
    const auto out = apse_test::reference_ellipses(read_table("maps/ellipses.txt"));
    REQUIRE(out.size() >= 12);
    return out;
}

}  // namespace

TEST_CASE("reference quadrature reproduces the mpmath tables", "[maps][reference]") {
    // Validates the test's own long-double quadrature (used for the CDF errors below) against the
    // 40-digit tables: it must be far more accurate (1e-15 relative) than the 1e-12 it checks.
    const auto ells = reference_ellipses();
    for (const auto& row : read_table("maps/radial_area.txt")) {
        const RefEllipse& e = ells[std::stoi(row[0])];
        const apse_test::Quadrature q(e.ta, e.tb);
        INFO("ellipse " << row[0] << " phi " << row[1]);
        CHECK(std::fabs(double(q.radial(num(row[1]))) - num(row[2])) / (e.omega / 4) <= 1e-15);
    }
    for (const auto& row : read_table("maps/parallel_area.txt")) {
        const RefEllipse& e = ells[std::stoi(row[0])];
        const apse_test::Quadrature q(e.ta, e.tb);
        INFO("ellipse " << row[0] << " psi " << row[1]);
        CHECK(std::fabs(double(q.parallel(num(row[1]))) - num(row[2])) / (e.omega / 2) <= 1e-15);
    }
}

TEMPLATE_TEST_CASE("cumulative areas match the references", "[maps][reference]", float, double) {
    using T = TestType;
    // Budgets relative to the area being accumulated (Omega/4 radial, Omega/2 parallel): 32 eps
    // (apse_test::area_tolerance, which explains it).
    const T tol = apse_test::area_tolerance<T>();
    const auto ells = reference_ellipses();
    const auto worst = apse_test::cumulative_area_errors<T>(
        ells, read_table("maps/radial_area.txt"), read_table("maps/parallel_area.txt"),
        [&](const char* variable, const std::vector<std::string>& row, double err) {
            INFO("ellipse " << row[0] << " " << variable << " " << row[1] << " err " << err);
            CHECK(err <= tol);
        });
    std::printf("[%s] Omega max rel err %.2e; Omega_r max err %.2e (of Omega/4); I max err %.2e (of Omega/2)\n",
                sizeof(T) == 4 ? "float" : "double", worst.omega, worst.radial, worst.parallel);
}

TEMPLATE_TEST_CASE("sampled directions match the references", "[maps][reference]", float, double) {
    using T = TestType;
    // Angular error relative to the ellipse's size sin(alpha): 1e-13 in double, 1e-5 in float
    // (apse_test::direction_tolerance, which explains them). Measured values are printed below.
    const double tol = apse_test::direction_tolerance<T>();
    const auto worst = apse_test::direction_errors<T>(
        reference_ellipses(), read_table("maps/samples.txt"), [&](const std::vector<std::string>& row, double err) {
            INFO(row[1] << " ellipse " << row[0] << " u " << row[2] << " " << row[3] << " err " << err);
            CHECK(err <= tol);
        });
    for (const auto& kv : worst)
        std::printf("[%s] %s direction max err %.2e (of sin alpha)\n", sizeof(T) == 4 ? "float" : "double",
                    kv.first.c_str(), kv.second);
}

TEMPLATE_TEST_CASE("inversion: CDF error and iteration statistics", "[maps][reference]", float, double) {
    using T = TestType;
    // Goals: CDF error <= 1e-12 relative in double, <= 1e-5 in float (apse_test::cdf_tolerance);
    // mean <= 3 and max <= 6 iterations over the test configurations (the reference ellipses:
    // tiny, thin, large, nearly hemispherical). The error is measured by the long-double
    // quadrature (validated to 1e-15 above) at the state the solver returns.
    const double cdf_tol = apse_test::cdf_tolerance<T>();
    const auto s = apse_test::inversion_stats<T>(reference_ellipses(), [&](const RefEllipse& r, T f, double er, double ep) {
        INFO("ta " << r.ta << " tb " << r.tb << " f " << f << " radial err " << er << " parallel err " << ep);
        CHECK(er <= cdf_tol);
        CHECK(ep <= cdf_tol);
    });
    std::printf("[%s] radial: CDF err max %.2e, iterations mean %.2f max %d | parallel: CDF err max %.2e, "
                "iterations mean %.2f max %d\n",
                sizeof(T) == 4 ? "float" : "double", s.cdf_radial, s.mean_radial, s.max_radial, s.cdf_parallel,
                s.mean_parallel, s.max_parallel);
    CHECK(s.mean_radial <= apse_test::kMeanIterationsBound);
    CHECK(s.mean_parallel <= apse_test::kMeanIterationsBound);
    CHECK(s.max_radial <= apse_test::kMaxIterationsBound);
    CHECK(s.max_parallel <= apse_test::kMaxIterationsBound);
}
