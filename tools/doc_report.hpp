// apse — area-preserving parameterizations for spherical ellipses.
// SPDX-License-Identifier: MIT
#pragma once

// A measuring tool's report, printed or written into a docs page: each named section replaces the
// text between the page's lines "<!-- TOOL: NAME -->" and "<!-- /TOOL: NAME -->", so that a
// measured table lives in one place, written by the tool that measures it (accuracy_report,
// cosine_study; tools/bench_table.py does the same for the benchmarks).
//
//     apse_tools::DocReport report("cosine_study");
//     report.section("receivers");
//     report.printf("| ... |\n", ...);
//     return report.finish(page);   // page "": print everything

#include <algorithm>
#include <cstdarg>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace apse_tools {

/// x in scientific notation with `digits` digits after the point and a plain exponent (no '+',
/// no leading zeros): 6.6e-7, 1.3e8; "0" for 0.
inline std::string sci(double x, int digits = 1) {
    if (x == 0) return "0";
    char buf[48];
    std::snprintf(buf, sizeof buf, "%.*e", digits, x);
    const std::string s = buf;
    const std::size_t e = s.find('e');
    std::string exponent = s.substr(e + 1);
    const bool negative = exponent[0] == '-';
    exponent = exponent.substr(1);
    exponent.erase(0, std::min(exponent.find_first_not_of('0'), exponent.size() - 1));
    return s.substr(0, e) + "e" + (negative ? "-" : "") + exponent;
}

/// A measuring tool's command line: a leading `--into PAGE` (`page` empty without one) and the
/// arguments after it.
struct ToolArguments {
    std::string page;
    std::vector<std::string> rest;
};
inline ToolArguments tool_arguments(int argc, char** argv) {
    ToolArguments a;
    int i = 1;
    if (argc > 2 && std::string(argv[1]) == "--into") {
        a.page = argv[2];
        i = 3;
    }
    for (; i < argc; ++i) a.rest.emplace_back(argv[i]);
    return a;
}

class DocReport {
public:
    explicit DocReport(std::string tool) : tool_(std::move(tool)) {}

    /// What is printed from now on goes to the section `name`.
    void section(const std::string& name) { sections_.emplace_back(name, std::string()); }

    /// printf into the current section (a section "" if none was opened).
    void printf(const char* format, ...) {
        if (sections_.empty()) section("");
        char buf[2048];
        va_list args;
        va_start(args, format);
        std::vsnprintf(buf, sizeof buf, format, args);
        va_end(args);
        sections_.back().second += buf;
    }

    /// Prints every section (page empty), or writes each into `page` between its markers.
    /// Returns 0, or 2 (with a message) if the page cannot be read or written or lacks markers.
    int finish(const std::string& page) const {
        if (page.empty()) {
            for (const auto& s : sections_) std::fputs((s.second + "\n").c_str(), stdout);
            return 0;
        }
        std::ifstream in(page);
        std::stringstream buffer;
        buffer << in.rdbuf();
        std::string text = buffer.str();
        if (!in) return fail(page, "cannot read it");
        for (const auto& s : sections_) {
            const std::string begin = "<!-- " + tool_ + ": " + s.first + " -->\n";
            const std::string end = "<!-- /" + tool_ + ": " + s.first + " -->";
            const std::size_t i = text.find(begin), j = text.find(end);
            if (i == std::string::npos || j == std::string::npos || j < i) return fail(page, "no markers " + begin);
            text = text.substr(0, i + begin.size()) + "\n" + s.second + "\n" + text.substr(j);
            std::fprintf(stderr, "%s: section %s written\n", page.c_str(), s.first.c_str());
        }
        std::ofstream out(page);
        out << text;
        return out ? 0 : fail(page, "cannot write it");
    }

private:
    static int fail(const std::string& page, const std::string& why) {
        std::fprintf(stderr, "%s: %s\n", page.c_str(), why.c_str());
        return 2;
    }

    std::string tool_;
    std::vector<std::pair<std::string, std::string>> sections_;
};

}  // namespace apse_tools
