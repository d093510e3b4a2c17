// Compiled by expect_error.cmake: apse computes in float or double only; long double must stop at
// apse's static_assert.
#include <apse/apse.hpp>

int main() {
    const apse::DirectionSample<long double> s{};
    return s.pdf > 0 ? 1 : 0;
}
