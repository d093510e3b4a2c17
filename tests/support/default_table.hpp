// The default TabulationTable, built once per test program (77 KB: static storage, not the
// stack). Shared by the tabulated-map tests, the shape statistics and the shapes fuzzer.
#pragma once

#include <apse/maps/tabulated.hpp>

namespace apse_test {

inline const apse::TabulationTable& default_table() {
    static const apse::TabulationTable* table = [] {
        static apse::TabulationTable t;
        t.build();
        return &t;
    }();
    return *table;
}

}  // namespace apse_test
