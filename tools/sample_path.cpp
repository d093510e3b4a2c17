// One TabulatedLdRadialMap sample (double and float), with every apse function it enters recorded:
// built by tools/sample_path.py with -finstrument-functions, which reports each function entered,
// inlined ones included (GCC and Clang keep an addressable copy of every instrumented function).
// Prints the entered functions' addresses, one per line, for addr2line.
#include <apse/apse.hpp>

#include <cstdio>

namespace {

bool recording = false;
void* entered[4096];
int count = 0;

}  // namespace

extern "C" {
__attribute__((no_instrument_function)) void __cyg_profile_func_enter(void* fn, void*) {
    if (recording && count < 4096) entered[count++] = fn;
}
__attribute__((no_instrument_function)) void __cyg_profile_func_exit(void*, void*) {}
}

template <class T> __attribute__((no_instrument_function)) T one_sample(const apse::TabulationView& table) {
    const apse::SphericalEllipse<T> ellipse = apse::project_disk(glm::vec<3, T>(0), glm::vec<3, T>(0.3, 0.2, 2),
                                                                glm::vec<3, T>(0, 0.2, -1), T(0.7));
    const apse::TabulatedLdRadialMap<T> map(ellipse, table);
    T sum = 0;
    // one point of the square in each quadrant of the concentric disk (the signs of 2u − 1), each
    // in a different sector of the concentric map (right, top, left, bottom)
    const glm::vec<2, T> points[] = {{T(0.9), T(0.6)}, {T(0.4), T(0.9)}, {T(0.1), T(0.3)}, {T(0.6), T(0.05)}};
    for (const glm::vec<2, T>& u : points) {
        recording = true;
        const apse::DirectionSample<T> s = map.sample(u);
        recording = false;
        sum += s.pdf;
    }
    return sum;
}

__attribute__((no_instrument_function)) int main() {
    const apse::TabulationView table = apse::default_table().view();
    const double sum = one_sample<double>(table) + double(one_sample<float>(table));
    if (!(sum > 0)) return 1;
    for (int i = 0; i < count; ++i) std::printf("%p\n", entered[i]);
    return 0;
}
