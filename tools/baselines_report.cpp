// baselines_report: measures the baselines of docs/baselines.md as their tests do and prints the
// page's two "Measured accuracy" tables, in float and double:
//   rectangle — SphericalRectangle against the mpmath tables of tests/data/rectangle (solid
//               angles, map points), the published Σg − 2π form far away, the map's Jacobian by
//               finite differences, the u → direction → invert round trip and chi-square tests;
//   gamito    — Gamito's rejection samplers: Monte Carlo estimates against the mpmath disk
//               integrals (and the authors' biased bookkeeping), acceptance and success rates,
//               chi-square of the accepted directions, and how much stratification survives.
// --into writes them there (between the page's lines "<!-- baselines_report: rectangle -->" and
// "<!-- /baselines_report: rectangle -->", and likewise for gamito).
//
//   baselines_report [--into PAGE]
//
// The measures are the tests' own (tests/support/rectangle_accuracy.hpp for test_rectangle.cpp,
// tests/support/gamito_accuracy.hpp for test_gamito.cpp, tests/support/maps_measures.hpp for
// test_stratification.cpp): the same inputs, seeds and sample counts, so the tables show what
// the tests check.
#include <apse/math.hpp>

#include "doc_report.hpp"
#include "support/gamito_accuracy.hpp"
#include "support/maps_measures.hpp"
#include "support/rectangle_accuracy.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

#ifndef APSE_TEST_DATA_DIR
#define APSE_TEST_DATA_DIR "tests/data"
#endif

namespace {

namespace rect = apse_test::rectangle;
namespace gam = apse_test::gamito;

/// printf into a std::string.
template <class... Args> std::string format(const char* fmt, Args... args) {
    char buf[512];
    std::snprintf(buf, sizeof buf, fmt, args...);
    return buf;
}

/// A minimum and a maximum.
struct Range {
    double min = std::numeric_limits<double>::infinity(), max = -std::numeric_limits<double>::infinity();
    void add(double x) {
        min = std::min(min, x);
        max = std::max(max, x);
    }
};

/// n with its thousands apart: 200 000.
std::string grouped(long n) {
    std::string s = std::to_string(n);
    for (int i = int(s.size()) - 3; i > 0; i -= 3) s.insert(std::size_t(i), " ");
    return s;
}

/// 2^k of a power of two, as "2^k".
std::string power_of_two(double x) { return format("2^%d", std::ilogb(x)); }

/// What is measured of the rectangle in one type.
struct RectangleColumn {
    double eps = 0;
    rect::SolidAngleSummary solid_angle;
    double published[4] = {}, ours[4] = {};
    rect::MapSummary map;
    double jacobian = 0, jacobian_step = 0;
    std::size_t jacobian_points = 0;
    rect::RoundTripSummary round_trip;
    Range chi2_p;
};

template <class T> RectangleColumn measure_rectangle() {
    RectangleColumn m;
    m.eps = double(apse::epsilon<T>());
    m.solid_angle = rect::summarize(rect::solid_angle_checks<T>());
    for (int i = 0; i < 4; ++i) {
        const rect::RectCase* c = rect::find_rectangle_case(rect::far_axis_cases[i]);
        if (!c) {
            std::fprintf(stderr, "baselines_report: no rectangle case %s\n", rect::far_axis_cases[i]);
            std::exit(2);
        }
        m.published[i] = rect::published_solid_angle_error<T>(*c);
        m.ours[i] = rect::solid_angle_error<T>(*c);
    }
    m.map = rect::summarize(rect::map_checks<T>());
    const auto jac = rect::jacobian_checks<T>();
    for (const auto& k : jac) m.jacobian = std::max(m.jacobian, k.error);
    m.jacobian_points = jac.size();
    m.jacobian_step = rect::jacobian_step<T>();
    m.round_trip = rect::round_trip_summary<T>();
    std::uint64_t seed = rect::rectangle_chi2_seed<T>();
    for (const char* name : rect::rectangle_chi2_cases) {
        const rect::RectCase* c = rect::find_rectangle_case(name);
        if (!c) {
            std::fprintf(stderr, "baselines_report: no rectangle case %s\n", name);
            std::exit(2);
        }
        m.chi2_p.add(rect::rectangle_chi2<T>(*c, seed++).result.p);
    }
    return m;
}

void rectangle_section(apse_tools::DocReport& report) {
    for (const std::string& error : {rect::rectangle_cases().error, rect::rectangle_map_rows().error})
        if (!error.empty()) {
            std::fprintf(stderr, "baselines_report: %s\n", error.c_str());
            std::exit(2);
        }
    const RectangleColumn m[2] = {measure_rectangle<float>(), measure_rectangle<double>()};
    report.section("rectangle");
    report.printf("Errors in units of ε, the type's machine epsilon, over the %zu rectangles of "
                  "`tests/data/rectangle/solid_angle.txt` and the %zu reference points of `map.txt`.\n\n",
                  rect::rectangle_cases().cases.size(), rect::rectangle_map_rows().rows.size());
    report.printf("| quantity | float | double |\n|---|---|---|\n");
    auto row = [&](const std::string& label, auto&& cell) {
        report.printf("| %s | %s | %s |\n", label.c_str(), cell(m[0]).c_str(), cell(m[1]).c_str());
    };
    row("S vs mpmath, max relative error / κ", [](const RectangleColumn& c) {
        return format("%.2f ε (%s)", c.solid_angle.worst_per_kappa / c.eps, c.solid_angle.worst ? c.solid_angle.worst->name.c_str() : "");
    });
    row("S for the far rectangles (1e2–1e8 sizes away), max relative error", [](const RectangleColumn& c) {
        const rect::RectCase* w = c.solid_angle.worst_far_case;
        return format("%.2f ε = %.2g (%s, κ = %.3g)", c.solid_angle.worst_far / c.eps, c.solid_angle.worst_far,
                      w ? w->name.c_str() : "", w ? w->kappa : 0.0);
    });
    row("published `Σg − 2π` at 1e2 / 1e4 / 1e6 / 1e8 sizes (unit square on the axis), relative error",
        [](const RectangleColumn& c) {
            return format("%.2g / %.2g / %.2g / %.2g", c.published[0], c.published[1], c.published[2], c.published[3]);
        });
    row("apse at the same distances", [](const RectangleColumn& c) {
        return format("%.2g / %.2g / %.2g / %.2g", c.ours[0], c.ours[1], c.ours[2], c.ours[3]);
    });
    row("map points (st) vs mpmath, max error / κ", [](const RectangleColumn& c) { return format("%.2f ε", c.map.st_per_kappa / c.eps); });
    row("map directions vs mpmath, max error / κ",
        [](const RectangleColumn& c) { return format("%.2f ε", c.map.direction_per_kappa / c.eps); });
    row(format("Jacobian of the map / S − 1, max (4th-order finite differences, %zu points)", m[1].jacobian_points),
        [](const RectangleColumn& c) {
            return format("%.2g (step %s%s)", c.jacobian, power_of_two(c.jacobian_step).c_str(),
                          c.eps > 1e-10 ? ", limited by the rounding of float points" : "");
        });
    row("u → direction → invert round trip, max error / κ_rt (κ_rt = κ·length/min edge)", [](const RectangleColumn& c) {
        return format("%.2f ε (%s)", c.round_trip.worst_per_kappa / c.eps, c.round_trip.worst ? c.round_trip.worst->name.c_str() : "");
    });
    row(format("χ² (%d×%d cells, %s samples, %zu configurations), p-values", rect::rectangle_chi2_grid,
               rect::rectangle_chi2_grid, grouped(rect::rectangle_chi2_samples).c_str(), std::size(rect::rectangle_chi2_cases)),
        [](const RectangleColumn& c) { return format("%.2g–%.2g", c.chi2_p.min, c.chi2_p.max); });
}

/// What is measured of Gamito's samplers in one type.
struct GamitoColumn {
    double worst_unbiased = 0;          // single shot and retries, Omega and cos, standard errors
    Range authors_ratio, authors_sigma;  // estimate / truth and |deviation| where the bias is resolvable
    std::string authors_unresolved;      // the same where it is not (A near 1)
    double authors_zbias = 0;            // max |deviation from A·truth|
    double worst_acceptance = 0;         // max |z| of the single shot's acceptance rate
    const gam::DiskCase* low = nullptr;  // the lowest and highest measured acceptance rates
    const gam::DiskCase* high = nullptr;
    double low_rate = 2, high_rate = -1;
    double worst_success = 0;            // max |z| of the retries' success rates
    double min_success8 = 2;             // the lowest success rate with N = 8
    Range chi2_p;
    Range strat_single, strat_retry;
};

template <class T> GamitoColumn measure_gamito() {
    GamitoColumn m;
    for (const auto& u : gam::gamito_unbiasedness<T>()) {
        m.worst_unbiased = std::max({m.worst_unbiased, std::fabs(u.single.zo), std::fabs(u.single.zc)});
        for (const auto& v : u.retry) m.worst_unbiased = std::max({m.worst_unbiased, std::fabs(v.zo), std::fabs(v.zc)});
        if (u.bias_resolvable) {
            m.authors_ratio.add(u.authors_ratio);
            m.authors_sigma.add(std::fabs(u.authors.zo));
        } else {
            m.authors_unresolved += format("; %s (A = %.4g): %.4f × truth, %.3g σ off", u.c->name.c_str(), u.A,
                                           u.authors_ratio, std::fabs(u.authors.zo));
        }
        m.authors_zbias = std::max(m.authors_zbias, std::fabs(u.authors_zbias));
        m.worst_acceptance = std::max(m.worst_acceptance, std::fabs(u.single.za));
        const double rate = u.single.accepted.mean();
        if (rate < m.low_rate) {
            m.low_rate = rate;
            m.low = u.c;
        }
        if (rate > m.high_rate) {
            m.high_rate = rate;
            m.high = u.c;
        }
        for (int k = 0; k < 2; ++k) {
            m.worst_success = std::max(m.worst_success, std::fabs(u.retry[k].za));
            if (u.retry_attempts[k] == 8) m.min_success8 = std::min(m.min_success8, u.retry[k].accepted.mean());
        }
    }
    std::uint64_t seed = gam::gamito_chi2_seed<T>();
    for (const char* name : gam::gamito_chi2_cases) {
        const gam::DiskCase* c = gam::find_gamito_disk(name);
        if (!c) {
            std::fprintf(stderr, "baselines_report: no disk case %s\n", name);
            std::exit(2);
        }
        const auto cells = gam::gamito_chi2_cells(*c);
        for (int variant = 0; variant < 2; ++variant) m.chi2_p.add(gam::gamito_chi2<T>(*c, cells, variant, seed++).result.p);
    }
    const auto ignore = [](auto&&...) {};
    for (const auto& r : apse_test::stratification_ratios<T>(ignore, ignore)) {
        if (r.name == "gamito_single_shot") {
            m.strat_single.add(r.min);
            m.strat_single.add(r.max);
        } else if (r.name == "gamito_retry") {
            m.strat_retry.add(r.min);
            m.strat_retry.add(r.max);
        }
    }
    return m;
}

void gamito_section(apse_tools::DocReport& report) {
    if (!gam::gamito_disk_cases().error.empty()) {
        std::fprintf(stderr, "baselines_report: %s\n", gam::gamito_disk_cases().error.c_str());
        std::exit(2);
    }
    const GamitoColumn m[2] = {measure_gamito<float>(), measure_gamito<double>()};
    report.section("gamito");
    report.printf("Gamito: %s samples per configuration and variant, the %zu disks of "
                  "`tests/data/rectangle/gamito_disks.txt`; σ: standard errors.\n\n",
                  grouped(gam::gamito_unbiased_samples).c_str(), gam::gamito_disk_cases().cases.size());
    report.printf("| check | float | double |\n|---|---|---|\n");
    auto row = [&](const std::string& label, auto&& cell) {
        report.printf("| %s | %s | %s |\n", label.c_str(), cell(m[0]).c_str(), cell(m[1]).c_str());
    };
    row("single shot, retry N = 2, retry N = 8: estimates of Ω_disk and of ∫cos θ dω vs the mpmath truth",
        [](const GamitoColumn& c) { return format("all within %.2f σ", c.worst_unbiased); });
    row("authors' bookkeeping (single shot with pdf 1/Ω_disk): estimate / truth, and its deviation", [](const GamitoColumn& c) {
        return format("%.3f–%.3f × truth, %.0f–%.0f σ off%s; all within %.2f σ of A × truth", c.authors_ratio.min,
                      c.authors_ratio.max, c.authors_sigma.min, c.authors_sigma.max, c.authors_unresolved.c_str(),
                      c.authors_zbias);
    });
    row("single shot's acceptance rate vs exact A = Ω_disk/Ω_square", [](const GamitoColumn& c) {
        return format("within %.2f σ; %.4f (%s) … %.4f (%s)", c.worst_acceptance, c.low_rate, c.low ? c.low->name.c_str() : "",
                      c.high_rate, c.high ? c.high->name.c_str() : "");
    });
    row("retry success rate vs `1 − (1 − A)^N`", [](const GamitoColumn& c) {
        return format("within %.2f σ (N = 8: ≥ %.6g)", c.worst_success, c.min_success8);
    });
    row(format("χ² of accepted directions vs uniform over the disk (%d rings × %d sectors, %zu disks × 2 variants, %s samples)",
               gam::gamito_chi2_rings, gam::gamito_chi2_sectors, std::size(gam::gamito_chi2_cases),
               grouped(gam::gamito_chi2_samples).c_str()),
        [](const GamitoColumn& c) { return format("p = %.2g–%.2g", c.chi2_p.min, c.chi2_p.max); });
    row(format("stratification: variance ratio independent / jittered %d×%d, %zu disks (rejection breaks it; the maps: "
               "[maps.md](maps.md))",
               apse_test::kStratificationGrid, apse_test::kStratificationGrid, std::size(apse_test::kStatisticsDisks)),
        [](const GamitoColumn& c) {
            return format("single shot %.1f–%.1f, retry %.1f–%.1f", c.strat_single.min, c.strat_single.max, c.strat_retry.min,
                          c.strat_retry.max);
        });
}

}  // namespace

int main(int argc, char** argv) {
    const apse_tools::ToolArguments args = apse_tools::tool_arguments(argc, argv);
    const std::string& page = args.page;
    if (!args.rest.empty()) {
        std::fprintf(stderr, "usage: baselines_report [--into PAGE]\n");
        return 2;
    }
    apse_tools::DocReport report("baselines_report");
    rectangle_section(report);
    gamito_section(report);
    return report.finish(page) != 0 ? 2 : 0;
}
