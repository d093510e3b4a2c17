// concept_report: measures every sampler of the sampler concept as test_sampler_concept does — on
// its oblique, close disk (and the circumscribed square for SphericalRectangle), at its grid of
// interior points u — and prints the measured table of docs/reliability.md ("The sampler
// concept"): the largest |pdf(sample)/pdf − 1| and |invert(sample(u)) − u| over all samplers and
// the fewest points that gave a sample, in float and double, with the budgets the test asserts.
// --into writes it there (between the page's lines "<!-- concept_report: concept -->" and
// "<!-- /concept_report: concept -->").
//
//   concept_report [--into PAGE]
//
// The samplers, the light, the points, the measure and the budgets are the test's own
// (tests/support/concept_measures.hpp), so the table shows what the test checks. Exit status 1
// if a sampler exceeds a budget or gives too few samples.
#include "doc_report.hpp"
#include "support/concept_measures.hpp"

#include <algorithm>
#include <cstdio>
#include <string>

namespace {

namespace sc = apse_test::sampler_concept;

using apse_tools::sci;

/// The worst of every sampler's measure in one type.
struct Worst {
    int samplers = 0;
    int accepted = sc::kPoints;
    double pdf = 0, round_trip = 0;
    bool ok = true;  ///< every sampler within the budgets and with enough samples
};

template <class T> Worst measure_all() {
    Worst w;
    const sc::Scene<T> scene = sc::normal_scene<T>();
    sc::for_each_sampler([&](auto f) {
        using F = typename decltype(f)::type;
        const sc::Measure m = sc::measure<F, T>(F::make(scene), [](const auto&...) {});
        ++w.samplers;
        w.accepted = std::min(w.accepted, m.accepted);
        w.pdf = std::max(w.pdf, m.pdf);
        w.round_trip = std::max(w.round_trip, m.round_trip);
        if (!(m.pdf <= sc::Budget<T>::pdf && m.round_trip <= sc::Budget<T>::round_trip &&
              m.accepted >= sc::required_accepted<F>())) {
            std::fprintf(stderr, "concept_report: %s (%s): accepted %d, |pdf(sample)/pdf - 1| %.2e, round trip %.2e: "
                                 "over budget\n",
                         std::string(F::name).c_str(), sizeof(T) == 4 ? "float" : "double", m.accepted, m.pdf,
                         m.round_trip);
            w.ok = false;
        }
    });
    return w;
}

}  // namespace

int main(int argc, char** argv) {
    const apse_tools::ToolArguments args = apse_tools::tool_arguments(argc, argv);
    if (!args.rest.empty()) {
        std::fprintf(stderr, "usage: concept_report [--into PAGE]\n");
        return 2;
    }
    const Worst f = measure_all<float>();
    const Worst d = measure_all<double>();

    apse_tools::DocReport report("concept_report");
    report.section("concept");
    report.printf("| worst over the %d samplers | float | double | budget (float, double) |\n|---|---:|---:|---:|\n",
                  f.samplers);
    report.printf("| ∣pdf(sample)/pdf − 1∣ | %s | %s | %s, %s |\n", sci(f.pdf).c_str(), sci(d.pdf).c_str(),
                  sci(sc::Budget<float>::pdf, 0).c_str(), sci(sc::Budget<double>::pdf, 0).c_str());
    report.printf("| ∣invert(sample(u)) − u∣ | %s | %s | %s, %s |\n", sci(f.round_trip).c_str(),
                  sci(d.round_trip).c_str(), sci(sc::Budget<float>::round_trip, 0).c_str(),
                  sci(sc::Budget<double>::round_trip, 0).c_str());
    report.printf("| fewest points accepted (of %d each) | %d | %d | ≥ %d Gamito single shot, %d the others |\n",
                  sc::kPoints, f.accepted, d.accepted, sc::kGamitoSingleShotAccepted, sc::kPoints);
    const int written = report.finish(args.page);
    if (written != 0) return 2;
    return f.ok && d.ok ? 0 : 1;
}
