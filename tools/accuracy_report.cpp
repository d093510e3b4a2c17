// accuracy_report: measures apse's elliptic integrals against the mpmath reference tables in
// tests/data/elliptic and prints a markdown table of the largest and mean relative error, in
// units of the machine epsilon of the type, for every function and for
//   float (native)   — the computation in float,
//   float (promoted) — the computation in double, rounded to float,
//   double,
// plus the input with the largest error of the path the public float/double functions use.
// This is the accuracy table of docs/elliptic.md, which --into writes there (between the page's
// lines "<!-- accuracy_report: elliptic -->" and "<!-- /accuracy_report: elliptic -->").
// With `table_sizes` instead: the tabulated map's max |pdf Omega − 1| against the size of its
// table, the table of docs/tabulated.md (section "table_sizes").
//
//   accuracy_report [--into PAGE] [data_dir]      (default: the source tree's tests/data/elliptic)
//   accuracy_report [--into PAGE] table_sizes
//
// The reference values carry 30 digits and the inputs are exactly representable in float, so
// the measured error is the library's own error (the reference's is ~1e-30).
#include <apse/elliptic.hpp>
#include <apse/maps/tabulation_table.hpp>

#include "doc_report.hpp"
#include "support/reference_table.hpp"
#include "support/table_uniformity.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#ifndef APSE_TEST_DATA_DIR
#define APSE_TEST_DATA_DIR "tests/data"
#endif

namespace {

using Row = apse_test::ReferenceRow;

// The rows of the table at `path` (support/reference_table.hpp); a malformed row is fatal.
std::vector<Row> read_table(const std::string& path, std::size_t n_in) {
    return apse_test::read_reference_table(path, n_in, [&](std::size_t field_count, const std::string& line) {
        if (field_count != n_in + 2) {
            std::fprintf(stderr, "%s: bad row: %s\n", path.c_str(), line.c_str());
            std::exit(2);
        }
    });
}

// Relative error of v in units of eps; a NaN or a wrong zero counts as infinite.
long double rel_error(long double v, long double ref, long double eps) {
    if (ref == 0) return v == 0 ? 0 : INFINITY;
    const long double e = std::fabs(v - ref) / std::fabs(ref) / eps;
    return e == e ? e : INFINITY;
}

using Eval = std::function<long double(const std::vector<double>&)>;

struct Stats {
    long double max = 0, sum = 0;
    std::size_t count = 0, worst = 0;
};

Stats measure(const std::vector<Row>& rows, const Eval& f, long double eps) {
    Stats s;
    s.max = -1;
    for (std::size_t i = 0; i < rows.size(); ++i) {
        const long double e = rel_error(f(rows[i].in), rows[i].ref, eps);
        s.sum += e;
        ++s.count;
        if (e > s.max) {
            s.max = e;
            s.worst = i;
        }
    }
    return s;
}

// One function: its table, argument count, budget and the three evaluation paths.
struct Function {
    const char* name;
    std::size_t n_in;
    double budget;
    Eval native_float, promoted_float, as_double;
};

// f(W(a[0]), ..., W(a[N-1])) rounded to T.
template <class W, class T, std::size_t N, class F>
long double call(F&& f, const std::vector<double>& a) {
    if constexpr (N == 1) return static_cast<long double>(static_cast<T>(f(W(a[0]))));
    else if constexpr (N == 2) return static_cast<long double>(static_cast<T>(f(W(a[0]), W(a[1]))));
    else if constexpr (N == 3) return static_cast<long double>(static_cast<T>(f(W(a[0]), W(a[1]), W(a[2]))));
    else return static_cast<long double>(static_cast<T>(f(W(a[0]), W(a[1]), W(a[2]), W(a[3]))));
}

// The three evaluation paths of one detail::*_impl template with N arguments.
#define APSE_PATHS(impl, N)                                                                    \
    [](const std::vector<double>& a) {                                                         \
        return call<float, float, N>([](auto... v) { return apse::detail::impl<float>(v...); }, a); \
    },                                                                                         \
        [](const std::vector<double>& a) {                                                     \
            return call<double, float, N>([](auto... v) { return apse::detail::impl<double>(v...); }, a); \
        },                                                                                     \
        [](const std::vector<double>& a) {                                                     \
            return call<double, double, N>([](auto... v) { return apse::detail::impl<double>(v...); }, a); \
        }

std::string fmt_stats(const Stats& s, bool bold) {
    char buf[96];
    std::snprintf(buf, sizeof buf, "%s%.2Lf / %.2Lf%s", bold ? "**" : "", s.max, s.sum / s.count,
                  bold ? "**" : "");
    return buf;
}

std::string fmt_input(const std::vector<double>& in) {
    std::string s = "(";
    char buf[64];
    for (std::size_t i = 0; i < in.size(); ++i) {
        std::snprintf(buf, sizeof buf, "%s%.9g", i ? ", " : "", in[i]);
        s += buf;
    }
    return s + ")";
}

/// One row of the table-size table: max |pdf Omega − 1| with the table TabulationTableN<B, X, Y>.
template <int B, int X, int Y> void table_size_row(apse_tools::DocReport& report, bool is_default) {
    auto table = std::make_unique<apse::TabulationTableN<B, X, Y>>();  // up to 320 KB: not on the stack
    table->build();
    const double error = apse_test::table_uniformity_error(*table);
    const char* bold = is_default ? "**" : "";
    report.printf("| %s%d × %d × %d%s%s | %s%.0f KB%s | %s%#.2g %%%s |\n", bold, B, X, Y, is_default ? " (default)" : "",
                  bold, bold, double(sizeof(*table)) / 1024.0, bold, bold, 100.0 * error, bold);
}

/// The table-size table of docs/tabulated.md: max |pdf Omega − 1| of the tabulated radial map
/// over the shapes of support/table_uniformity.hpp, in double, for tables of several sizes.
int table_sizes(const std::string& page) {
    apse_tools::DocReport report("accuracy_report");
    report.section("table_sizes");
    report.printf("| bins × α nodes × ratio nodes | memory | max \\|pdf·Ω − 1\\| |\n|---|---|---|\n");
    table_size_row<16, 17, 9>(report, false);
    table_size_row<32, 17, 9>(report, false);
    table_size_row<64, 9, 5>(report, false);
    table_size_row<64, 17, 9>(report, false);
    table_size_row<128, 9, 5>(report, false);
    table_size_row<128, 17, 9>(report, true);
    table_size_row<128, 33, 17>(report, false);
    table_size_row<256, 17, 9>(report, false);
    table_size_row<512, 17, 9>(report, false);
    return report.finish(page) != 0 ? 2 : 0;
}

}  // namespace

int main(int argc, char** argv) {
    const apse_tools::ToolArguments args = apse_tools::tool_arguments(argc, argv);
    const std::string& page = args.page;
    if (!args.rest.empty() && args.rest[0] == "table_sizes") return table_sizes(page);
    const std::string dir = !args.rest.empty() ? args.rest[0] : std::string(APSE_TEST_DATA_DIR) + "/elliptic";
    // the data directory as the page names it: relative to the source tree where it is the default
    const std::string shown = !args.rest.empty() ? dir : std::string("tests/data/elliptic");
    apse_tools::DocReport report("accuracy_report");
    report.section("elliptic");
    const Function functions[] = {
        {"carlson_rf", 3, 4, APSE_PATHS(rf_impl, 3)},
        {"carlson_rd", 3, 8, APSE_PATHS(rd_impl, 3)},
        {"carlson_rj", 4, 8, APSE_PATHS(rj_impl, 4)},
        {"carlson_rc", 2, 4, APSE_PATHS(rc_impl, 2)},
        {"ellint_f", 2, 8, APSE_PATHS(f_impl, 2)},
        {"ellint_pi", 3, 16, APSE_PATHS(pi_impl, 3)},
        {"comp_ellint_k", 1, 8, APSE_PATHS(k_impl, 1)},
        {"comp_ellint_pi", 2, 16, APSE_PATHS(comp_pi_impl, 2)},
    };
    const long double eps_f = 0x1p-23L, eps_d = 0x1p-52L;
    report.printf("Relative error in units of eps (float: 2^-23, double: 2^-52), max / mean over the "
         "rows of %s/*.csv.\n\n", shown.c_str());
    report.printf("| function | rows | budget | float native | float promoted | double | "
         "worst float input | worst double input |\n");
    report.printf("|---|---:|---:|---:|---:|---:|---|---|\n");
    bool ok = true;
    for (const Function& f : functions) {
        const std::vector<Row> rows = read_table(dir + "/" + f.name + ".csv", f.n_in);
        if (rows.empty()) {
            report.printf("| %s | 0 | (missing table) |||||\n", f.name);
            ok = false;
            continue;
        }
        const Stats nf = measure(rows, f.native_float, eps_f);
        const Stats pf = measure(rows, f.promoted_float, eps_f);
        const Stats dd = measure(rows, f.as_double, eps_d);
        ok = ok && nf.max <= f.budget && dd.max <= f.budget;
        report.printf("| %s | %zu | %g | %s | %s | %s | %s %s | %s %s |\n", f.name, rows.size(), f.budget,
                  fmt_stats(nf, true).c_str(), fmt_stats(pf, false).c_str(), fmt_stats(dd, false).c_str(),
                  fmt_input(rows[nf.worst].in).c_str(), rows[nf.worst].category.c_str(),
                  fmt_input(rows[dd.worst].in).c_str(), rows[dd.worst].category.c_str());
    }
    report.printf("\n**bold**: the path the public float functions use. Budgets: R_F, R_C 4; R_D, R_J, F, K 8; Pi 16. "
                  "%s\n", ok ? "All within budget." : "SOME FUNCTION EXCEEDS ITS BUDGET.");
    if (report.finish(page) != 0) return 2;
    return ok ? 0 : 1;
}
