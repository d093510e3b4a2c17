// Reader of the reference tables of tests/data/elliptic (tools/gen_elliptic_reference.py), shared
// by tests/test_elliptic.cpp and tools/accuracy_report.cpp: '#' comments, one header line, then
// rows "<inputs...>,value,category". Inputs are hexadecimal floating literals exact in float
// (std::strtod parses them exactly); the value has 30 digits (parsed to long double: 64-bit
// significand on x86).
#pragma once

#include <cstddef>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace apse_test {

/// One row of a reference table.
struct ReferenceRow {
    std::vector<double> in;  ///< the inputs, exact in float
    long double ref;         ///< the reference value (30 digits)
    std::string category;    ///< the row's category (last field)
    std::string line;        ///< the whole line, for messages
};

/// The rows of the table at `path` with `n_in` inputs each (a missing file gives no rows).
/// `check_row(field_count, line)` is called for every row before it is parsed (the caller
/// asserts field_count == n_in + 2 and stops if not); a row with another field count that
/// check_row returns from is skipped.
template <class CheckRow>
std::vector<ReferenceRow> read_reference_table(const std::string& path, std::size_t n_in, CheckRow&& check_row) {
    std::ifstream file(path);
    std::vector<ReferenceRow> rows;
    std::string line;
    bool header = false;
    while (std::getline(file, line)) {
        if (line.empty() || line[0] == '#') continue;
        if (!header) {
            header = true;
            continue;
        }
        std::vector<std::string> fields;
        std::stringstream ss(line);
        std::string field;
        while (std::getline(ss, field, ',')) fields.push_back(field);
        check_row(fields.size(), line);
        if (fields.size() != n_in + 2) continue;
        ReferenceRow r;
        for (std::size_t i = 0; i < n_in; ++i) r.in.push_back(std::strtod(fields[i].c_str(), nullptr));
        r.ref = std::strtold(fields[n_in].c_str(), nullptr);
        r.category = fields[n_in + 1];
        r.line = line;
        rows.push_back(r);
    }
    return rows;
}

}  // namespace apse_test
