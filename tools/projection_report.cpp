// projection_report: measures apse's projections (project_disk, project_ellipse, project_sphere,
// project_ellipsoid) and the solid angle from two tangents (SphericalEllipse::from_tangents)
// against the mpmath tables in tests/data/projection, in float and double, and prints the
// accuracy table of docs/projection.md: per shape the largest relative error of alpha, beta and
// Omega, the largest error of the frame, the largest condition number kappa and the largest error
// in units of eps (kappa + 1). --into writes it there, between the page's lines
// "<!-- projection_report: accuracy -->" and "<!-- /projection_report: accuracy -->".
//
//   projection_report [--into PAGE] [data_dir]      (default: the source tree's tests/data/projection)
//
// The errors and their budget are those test_projection and test_spherical_ellipse check
// (tests/support/projection_reference.hpp). Exit status 1 if a row exceeds its budget or a light
// the table marks empty is not (or the reverse), 2 if a table or the page cannot be read.
#include "doc_report.hpp"
#include "support/projection_reference.hpp"

#include <cmath>
#include <cstdio>
#include <string>

#ifndef APSE_TEST_DATA_DIR
#define APSE_TEST_DATA_DIR "tests/data"
#endif

namespace {

using apse_test::Light;

const char* shape_name(Light light) {
    switch (light) {
    case Light::disk: return "disk";
    case Light::ellipse: return "planar ellipse";
    case Light::sphere: return "sphere";
    case Light::ellipsoid: return "ellipsoid";
    }
    return "";
}

using apse_tools::sci;

/// The largest errors of one shape's table in T; `ok` false if a row exceeds its budget or its
/// emptiness differs from the table's.
template <class T>
apse_test::ProjectionStats::Entry measure(Light light, const apse_test::ReferenceLights& table, bool& ok) {
    apse_test::ProjectionStats stats;
    for (const apse_test::ReferenceLight& r : table.rows) {
        const apse::SphericalEllipse<T> got = apse_test::project<T>(light, r);
        if (r.expected.empty || got.empty()) {
            if (r.expected.empty != got.empty()) {
                std::fprintf(stderr, "%s, %s row %zu: empty %d, the table says %d\n", shape_name(light),
                             sizeof(T) == 4 ? "float" : "double", r.row, int(got.empty()), int(r.expected.empty));
                ok = false;
            }
            if (r.expected.empty) stats.add_empty(r.category);
            continue;
        }
        const apse_test::ProjectionErrors e = apse_test::projection_errors(got, r.expected);
        if (!apse_test::within_budget<T>(e, r.expected)) {
            std::fprintf(stderr, "%s, %s row %zu (%s): over budget\n", shape_name(light), sizeof(T) == 4 ? "float" : "double",
                         r.row, r.category.c_str());
            ok = false;
        }
        stats.add(r.category, e);
    }
    return stats.all();
}

std::string errors_cell(const apse_test::ProjectionStats::Entry& e) {
    return sci(e.alpha) + " / " + sci(e.beta) + " / " + sci(e.omega) + " / " + sci(std::fmax(e.z, e.x));
}

/// The solid angle's largest relative error over the rows, that below 1e-10 sr, and the number of
/// rows that are ellipses in the type measured.
struct SolidAngleStats {
    double worst = 0, worst_small = 0;
    int n = 0;
};

template <class T> SolidAngleStats measure_solid_angle(const apse_test::SolidAngleReferences& table, bool& ok) {
    SolidAngleStats s;
    for (const apse_test::SolidAngleReference& r : table.rows) {
        if (!apse_test::solid_angle_applies<T>(r)) continue;
        const double err = apse_test::solid_angle_error<T>(r);
        if (!(err <= apse_test::solid_angle_budget<T>())) {
            std::fprintf(stderr, "solid angle, %s, %s (%.9g, %.9g): over budget\n", sizeof(T) == 4 ? "float" : "double",
                         r.category.c_str(), r.tan_alpha, r.tan_beta);
            ok = false;
        }
        s.worst = std::fmax(s.worst, err);
        if (r.omega < 1e-10L) s.worst_small = std::fmax(s.worst_small, err);
        ++s.n;
    }
    return s;
}

template <class T> std::string solid_angle_cell(const SolidAngleStats& s) {
    char buf[32];
    std::snprintf(buf, sizeof buf, " (%.1f eps)", s.worst / double(apse::epsilon<T>()));
    return "Ω " + sci(s.worst) + buf;
}

}  // namespace

int main(int argc, char** argv) {
    const apse_tools::ToolArguments args = apse_tools::tool_arguments(argc, argv);
    const std::string& page = args.page;
    const std::string dir = !args.rest.empty() ? args.rest[0] : std::string(APSE_TEST_DATA_DIR) + "/projection";
    apse_tools::DocReport report("projection_report");
    report.section("accuracy");
    report.printf("| shape | rows | double α / β / Ω / frame | float α / β / Ω / frame | max κ | "
                  "max err/(eps(κ+1)) d / f |\n");
    report.printf("|---|---:|---|---|---:|---|\n");
    bool ok = true;
    for (Light light : apse_test::all_lights) {
        const apse_test::ReferenceLights table = apse_test::read_reference_lights(dir, light);
        if (!table.error.empty()) {
            std::fprintf(stderr, "%s\n", table.error.c_str());
            return 2;
        }
        const auto d = measure<double>(light, table, ok);
        const auto f = measure<float>(light, table, ok);
        report.printf("| %s | %d (+%d empty) | %s | %s | %s | %.1f / %.1f |\n", shape_name(light), d.n, d.empty,
                      errors_cell(d).c_str(), errors_cell(f).c_str(), sci(d.kappa).c_str(), d.normalised, f.normalised);
    }
    const apse_test::SolidAngleReferences solid = apse_test::read_solid_angle_references(dir);
    if (!solid.error.empty()) {
        std::fprintf(stderr, "%s\n", solid.error.c_str());
        return 2;
    }
    const auto sd = measure_solid_angle<double>(solid, ok);
    const auto sf = measure_solid_angle<float>(solid, ok);
    std::string rows = std::to_string(sd.n);
    if (sf.n != sd.n) rows += " (float " + std::to_string(sf.n) + ")";
    report.printf("| solid angle alone (`from_tangents`) | %s | %s | %s | — | — |\n", rows.c_str(), solid_angle_cell<double>(sd).c_str(),
                  solid_angle_cell<float>(sf).c_str());
    report.printf("\nRows: the lights that project to an ellipse (those the table marks empty are checked to be "
                  "empty). Frame: the larger of the centre direction's error and the major axis' (up to sign, where "
                  "(α − β)/α > 1e-2), radians. Solid angles below 1e-10 sr: worst %s (double), %s (float). %s\n",
                  sci(sd.worst_small).c_str(), sci(sf.worst_small).c_str(),
                  ok ? "Every row within the tests' budgets (8 eps (κ + 64); the solid angle 8 eps)."
                     : "SOME ROW EXCEEDS ITS BUDGET.");
    if (report.finish(page) != 0) return 2;
    return ok ? 0 : 1;
}
