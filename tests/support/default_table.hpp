// The default TabulationTable for the tests (apse::default_table(): built once per program,
// thread-safely). Shared by the tabulated-map tests, the shape statistics and the shapes fuzzer.
#pragma once

#include <apse/comparison.hpp>
#include <apse/maps/tabulated_ld_radial.hpp>

namespace apse_test {

inline const apse::TabulationTable& default_table() { return apse::default_table(); }

}  // namespace apse_test
