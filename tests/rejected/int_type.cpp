// Compiled by expect_error.cmake: a sampler of int must stop at apse's static_assert.
#include <apse/apse.hpp>
#include <apse/comparison.hpp>

int main() {
    const apse::RadialMap<int> map(apse::SphericalEllipse<int>{});
    return map.empty() ? 0 : 1;
}
