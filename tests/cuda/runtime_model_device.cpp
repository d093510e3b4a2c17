// The CPU model of the device side of runtime_test.cu: the same evaluation (runtime_cases.hpp)
// compiled into a shared library with a*b + c contracted into FMAs (-ffp-contract=fast, -mfma
// on x86), the device's main rounding difference from the host. Its symbols are hidden (its own
// copies of apse's inline functions, not the test program's), except the one entry point.
#include "runtime_cases.hpp"

#include <cstring>

namespace {

template <class T, class... K>
int run_kind(int kind, const void* configs, const void* cases, int n, void* out, const apse::TabulationView& view,
             apse_rt::KindList<K...>) {
    const auto* g = static_cast<const apse_rt::Config<T>*>(configs);
    const auto* k = static_cast<const apse_rt::Case<T>*>(cases);
    auto* o = static_cast<apse_rt::Output<T>*>(out);
    int index = 0, found = 0;
    auto one = [&](auto tag) {
        using Kind = decltype(tag);
        if (index++ != kind) return;
        found = 1;
        for (int i = 0; i < n; ++i) o[i] = Kind::template run<T>(g[k[i].config], k[i], view);
    };
    (one(K{}), ...);
    return found;
}

}  // namespace

/// Evaluates `n` cases of the kind with index `kind` in apse_rt::Kinds for T = float
/// (is_double 0) or double, reading the tabulation table from a copy of `table` (as the device
/// reads its own copy). Returns 0 for an unknown kind.
extern "C" __attribute__((visibility("default"))) int apse_rt_model_run(int kind, int is_double, const void* configs,
                                                                      const void* cases, int n, void* out,
                                                                      apse::TabulationView table) {
    const std::size_t count = std::size_t(table.alpha_nodes) * std::size_t(table.ratio_nodes) * std::size_t(table.bins + 1);
    std::vector<float> copy(table.cdf, table.cdf + count);
    const apse::TabulationView view{copy.data(), table.bins, table.alpha_nodes, table.ratio_nodes};
    return is_double ? run_kind<double>(kind, configs, cases, n, out, view, apse_rt::Kinds{})
                     : run_kind<float>(kind, configs, cases, n, out, view, apse_rt::Kinds{});
}
