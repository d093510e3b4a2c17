// maps_report: measures the three area-preserving maps (radial, LD-radial, parallel) in double
// and float as their tests do — against the mpmath reference tables of tests/data/maps, by
// long-double quadrature, finite differences, round trips, chi-square tests, jittered against
// independent estimates and Monte Carlo against quadrature — and prints the "Measured" table of
// docs/maps.md, with the bound each test asserts. --into writes it there (between the page's lines
// "<!-- maps_report: measured -->" and "<!-- /maps_report: measured -->").
//
//   maps_report [--into PAGE]
//
// The measures and the bounds are those of the tests (tests/support/maps_measures.hpp, used by
// test_maps_reference.cpp, test_maps_properties.cpp, test_maps_statistics.cpp and
// test_stratification.cpp): the same inputs, seeds and sample counts, so the table shows what the
// tests check.
#include <apse/math.hpp>

#include "doc_report.hpp"
#include "support/maps_measures.hpp"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#ifndef APSE_TEST_DATA_DIR
#define APSE_TEST_DATA_DIR "tests/data"
#endif

namespace {

using apse_test::TableRows;

/// tests/data/<relative_path>; a missing file is fatal.
TableRows table(const std::string& relative_path) {
    const apse_test::DataTable t = apse_test::read_data_table(relative_path);
    if (!t.opened || t.rows.empty()) {
        std::fprintf(stderr, "maps_report: cannot read %s\n", t.path.c_str());
        std::exit(2);
    }
    return t.rows;
}

using apse_tools::sci;

/// n with its thousands apart: 100 000.
std::string grouped(int n) {
    std::string s = std::to_string(n);
    for (int i = int(s.size()) - 3; i > 0; i -= 3) s.insert(std::size_t(i), " ");
    return s;
}

/// Ignores whatever a measure reports point by point (the tests check each point).
const auto ignore = [](auto&&...) {};

/// What is measured in one type.
struct Measured {
    apse_test::AreaErrors areas;
    apse_test::InversionStats inversion;
    double directions = 0;
    double jacobian = 0;
    apse_test::RoundTripErrors round_trip;
    apse_test::PRange chi2;
    std::vector<apse_test::RatioRange> stratification;
    double unbiased = 0;
};

template <class T>
Measured measure(const std::vector<apse_test::RefEllipse>& ells, const TableRows& radial_rows,
                 const TableRows& parallel_rows, const TableRows& sample_rows) {
    Measured m;
    m.areas = apse_test::cumulative_area_errors<T>(ells, radial_rows, parallel_rows, ignore);
    m.inversion = apse_test::inversion_stats<T>(ells, ignore);
    for (const auto& kv : apse_test::direction_errors<T>(ells, sample_rows, ignore))
        m.directions = std::max(m.directions, kv.second);
    m.jacobian = apse_test::jacobian_error<T>(ignore);
    m.round_trip = apse_test::round_trip_errors<T>(ignore);
    auto require_disk = [](const apse::SphericalEllipse<T>& e) {
        if (e.empty()) {
            std::fprintf(stderr, "maps_report: a disk of the statistical tests projects to no ellipse\n");
            std::exit(2);
        }
    };
    m.chi2 = apse_test::chi2_p_values<T>(require_disk, ignore);
    m.stratification = apse_test::stratification_ratios<T>(require_disk, ignore);
    m.unbiased = apse_test::unbiased_sigmas<T>(ignore);
    return m;
}

/// The display name of a sampler of apse_test::for_each_disk_sampler.
std::string sampler_name(const std::string& name) {
    if (name == "ld_radial") return "LD-radial";
    if (name == "tabulated_ld_radial") return "tabulated LD-radial";
    if (name == "gamito_single_shot") return "single shot";
    if (name == "gamito_retry") return "with retries";
    return name;
}

/// "radial 64–79, LD-radial 245–287, ..." for the maps (rejection false) or for Gamito's samplers.
std::string ratios(const std::vector<apse_test::RatioRange>& ranges, bool rejection) {
    std::string s;
    char buf[128];
    for (const auto& r : ranges) {
        if (r.rejection != rejection) continue;
        std::snprintf(buf, sizeof buf, "%s%s %.*f–%.*f", s.empty() ? "" : ", ", sampler_name(r.name).c_str(),
                      r.min < 10 ? 1 : 0, r.min, r.max < 10 ? 1 : 0, r.max);
        s += buf;
    }
    return s;
}

}  // namespace

int main(int argc, char** argv) {
    const apse_tools::ToolArguments args = apse_tools::tool_arguments(argc, argv);
    const std::string& page = args.page;
    if (!args.rest.empty()) {
        std::fprintf(stderr, "usage: maps_report [--into PAGE]\n");
        return 2;
    }
    const auto ells = apse_test::reference_ellipses(table("maps/ellipses.txt"));
    const TableRows radial_rows = table("maps/radial_area.txt"), parallel_rows = table("maps/parallel_area.txt"),
                    sample_rows = table("maps/samples.txt");
    const Measured d = measure<double>(ells, radial_rows, parallel_rows, sample_rows);
    const Measured f = measure<float>(ells, radial_rows, parallel_rows, sample_rows);

    apse_tools::DocReport report("maps_report");
    report.section("measured");
    report.printf("| quantity | double | float | asserted (double / float) |\n|---|---|---|---|\n");
    report.printf("| Omega_r, I(ψ) vs 40-digit tables (of Omega/4, Omega/2) | %s, %s | %s, %s | ≤ 32 eps: %s / %s |\n",
                  sci(d.areas.radial).c_str(), sci(d.areas.parallel).c_str(), sci(f.areas.radial).c_str(),
                  sci(f.areas.parallel).c_str(), sci(double(apse_test::area_tolerance<double>())).c_str(),
                  sci(double(apse_test::area_tolerance<float>())).c_str());
    report.printf("| CDF error at the solver's solution (vs long-double quadrature) radial / parallel | %s / %s | %s / %s "
                  "| ≤ %s / %s |\n",
                  sci(d.inversion.cdf_radial).c_str(), sci(d.inversion.cdf_parallel).c_str(),
                  sci(f.inversion.cdf_radial).c_str(), sci(f.inversion.cdf_parallel).c_str(),
                  sci(apse_test::cdf_tolerance<double>(), 0).c_str(), sci(apse_test::cdf_tolerance<float>(), 0).c_str());
    report.printf("| iterations radial: mean / max | %.2f / %d | %.2f / %d | mean ≤ %g, max ≤ %d |\n", d.inversion.mean_radial,
                  d.inversion.max_radial, f.inversion.mean_radial, f.inversion.max_radial,
                  apse_test::kMeanIterationsBound, apse_test::kMaxIterationsBound);
    report.printf("| iterations parallel: mean / max | %.2f / %d | %.2f / %d | mean ≤ %g, max ≤ %d |\n",
                  d.inversion.mean_parallel, d.inversion.max_parallel, f.inversion.mean_parallel,
                  f.inversion.max_parallel, apse_test::kMeanIterationsBound, apse_test::kMaxIterationsBound);
    report.printf("| sampled directions vs tables (angle / sin α) | ≤ %s | ≤ %s | ≤ %s / %s |\n",
                  sci(d.directions).c_str(), sci(f.directions).c_str(),
                  sci(apse_test::direction_tolerance<double>(), 0).c_str(),
                  sci(apse_test::direction_tolerance<float>(), 0).c_str());
    report.printf("| Jacobian ∣∂ω/∂u₁ × ∂ω/∂u₂∣ vs Omega (finite differences) | %s | %s (FD-limited) | ≤ %s / %s |\n",
                  sci(d.jacobian).c_str(), sci(f.jacobian).c_str(),
                  sci(apse_test::jacobian_tolerance<double>(), 0).c_str(),
                  sci(apse_test::jacobian_tolerance<float>(), 0).c_str());
    report.printf("| round trip invert(sample(u)) − u on [0.01, 0.99]² | %s | %s | ≤ %s / %s |\n",
                  sci(d.round_trip.u).c_str(), sci(f.round_trip.u).c_str(),
                  sci(apse_test::round_trip_tolerance<double>(), 0).c_str(),
                  sci(apse_test::round_trip_tolerance<float>(), 0).c_str());
    report.printf("| χ² p-values (%s samples, %d disk cells, 3 disks × 3 maps) | %.2f – %.2f | %.2f – %.2f "
                  "| > Šidák(%g %%, %d) = %s |\n",
                  grouped(apse_test::kChi2Samples).c_str(), apse_test::kChi2Rings * apse_test::kChi2Sectors, d.chi2.min, d.chi2.max, f.chi2.min, f.chi2.max,
                  100 * apse_test::kChi2FamilyLevel, apse_test::kChi2Tests, sci(apse_test::chi2_level()).c_str());
    report.printf("| variance ratio independent / jittered %d×%d, the maps | %s | %s | > %g |\n",
                  apse_test::kStratificationGrid, apse_test::kStratificationGrid, ratios(d.stratification, false).c_str(),
                  ratios(f.stratification, false).c_str(), apse_test::kStratificationMapBound);
    report.printf("| the same, Gamito's rejection sampling | %s | %s | < %g |\n", ratios(d.stratification, true).c_str(),
                  ratios(f.stratification, true).c_str(), apse_test::kStratificationRejectionBound);
    report.printf("| unbiasedness (MC vs quadrature, %s samples) | ≤ %.2f σ | ≤ %.2f σ | ≤ %g σ |\n",
                  grouped(apse_test::kUnbiasedSamples).c_str(), d.unbiased, f.unbiased, apse_test::kUnbiasedSigmas);
    return report.finish(page) != 0 ? 2 : 0;
}
