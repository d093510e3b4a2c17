// CPU model of runtime_test.cu: the same cases and the same comparison (runtime_cases.hpp), with
// the "device" a shared library of the same evaluation compiled with FMA contraction
// (runtime_model_device.cpp) and this program compiled without it. It checks the comparison
// logic and its tolerances on a machine without a GPU: FMA contraction is one of the two ways
// in which a GPU's results differ from the host's (the other, the device's transcendental
// functions, cannot be modelled here). Exit code 77 (skipped) on an x86 CPU without FMA.
#include "runtime_cases.hpp"

#include <cstdio>

extern "C" int apse_rt_model_run(int kind, int is_double, const void* configs, const void* cases, int n, void* out,
                                 apse::TabulationView table);

namespace {

template <class Kind, class... K> constexpr int index_of(apse_rt::KindList<K...>) {
    int i = 0, found = -1;
    ((std::is_same<Kind, K>::value ? (found = i, ++i) : ++i), ...);
    return found;
}

struct ModelDevice {
    apse::TabulationView table;
    template <class Kind, class T>
    std::vector<apse_rt::Output<T>> run(const std::vector<apse_rt::Config<T>>& configs,
                                        const std::vector<apse_rt::Case<T>>& cases) const {
        std::vector<apse_rt::Output<T>> out(cases.size());
        if (!apse_rt_model_run(index_of<Kind>(apse_rt::Kinds{}), sizeof(T) == 8, configs.data(), cases.data(),
                               int(cases.size()), out.data(), table))
            out.clear();
        return out;
    }
};

}  // namespace

int main() {
#if defined(__x86_64__) || defined(__i386__)
    if (!__builtin_cpu_supports("fma")) {
        std::printf("skipped: this CPU has no FMA instructions\n");
        return 77;
    }
#endif
    const apse::TabulationView view = apse::default_table().view();
    ModelDevice device{view};
    int passed = 0, failed = 0;
    apse_rt::print_header();
    apse_rt::run_all<float>(device, apse_rt::Kinds{}, view, passed, failed);
    apse_rt::run_all<double>(device, apse_rt::Kinds{}, view, passed, failed);
    std::printf("\n%d passed, %d failed\n", passed, failed);
    return failed == 0 ? 0 : 1;
}
