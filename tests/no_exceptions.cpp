// Calls the public API in a translation unit compiled with -fno-exceptions: proves no header
// throws, catches or needs exception support. Returns non-zero if a value is not finite.
#include <apse/apse.hpp>

#include <cstdio>

template <class T>
static bool elliptic_ok() {
    const T values[] = {
        apse::carlson_rf(T(1), T(2), T(3)),   apse::carlson_rd(T(1), T(2), T(3)),
        apse::carlson_rj(T(1), T(2), T(3), T(4)), apse::carlson_rc(T(1), T(2)),
        apse::ellint_f(T(0.5), T(0.5)),       apse::ellint_pi(T(-2), T(0.5), T(0.5)),
        apse::comp_ellint_k(T(0.5)),          apse::comp_ellint_pi(T(-2), T(0.5)),
    };
    for (T v : values)
        if (!apse::is_finite(v)) return false;
    return true;
}

int main() {
    const bool ok = elliptic_ok<float>() && elliptic_ok<double>();
    std::printf("no-exceptions build: %s\n", ok ? "ok" : "FAILED");
    return ok ? 0 : 1;
}
