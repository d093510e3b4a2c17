// Test helpers shared by the sampler tests (rectangle, Gamito, maps, tabulated, area): everything
// of statistics_core.hpp (a seeded uniform generator, Gauss–Legendre quadrature, a Mitsuba-style
// chi-square test, the estimator variance) and the reading of the reference tables, asserted with
// Catch2. Everything here is independent of apse (no apse header is used), so it can serve as a
// reference.
#pragma once

#include "support/statistics_core.hpp"

#include "support/catch.hpp"

#include <string>
#include <vector>

namespace apse_test {

/// The whitespace-separated tokens of every non-comment line of tests/data/<relative_path>.
inline std::vector<std::vector<std::string>> read_table(const std::string& relative_path) {
    DataTable t = read_data_table(relative_path);
    INFO("reading " << t.path);
    REQUIRE(t.opened);
    return t.rows;
}

}  // namespace apse_test
