// libFuzzer target: the eight elliptic functions at and around their domain edges (zeros, ±1 and a
// few ulps around it, n = -1/4, multiples of pi/2, denormals, huge values, infinities, NaN), float
// and double. Checks each function's documented contract: inside the domain a result that is not
// NaN and has the integral's sign (>= 0, or the sign of phi for F and Pi; +inf allowed where it
// overflows); outside the domain NaN. libFuzzer's -timeout catches a hang.
#include <apse/elliptic.hpp>

#include "fuzz_common.hpp"

#include <cstdint>

namespace {

double g_in[4];
int g_which = 0;

[[noreturn]] void fail(const char* what) {
    std::fprintf(stderr, "function %d\n", g_which);
    apse_fuzz::fail("fuzz_elliptic", what, g_in, 4);
}

template <class T> bool fin(T v) { return apse::detail::is_finite(v); }

/// The contract: in the domain, not NaN and sign-consistent (sign: +1, or -1 for a negative phi;
/// 0 means "any sign", e.g. for phi = 0); outside it, NaN.
template <class T> void expect(bool in_domain, T r, int sign) {
    if (!in_domain) {
        if (!apse::detail::is_nan(r)) fail("outside the domain, not NaN");
        return;
    }
    if (apse::detail::is_nan(r)) fail("inside the domain, NaN");
    if (sign > 0 && !(r >= T(0))) fail("negative result");
    if (sign < 0 && !(r <= T(0))) fail("positive result for negative phi");
}

template <class T> void check(int which) {
    const T a = T(g_in[0]), b = T(g_in[1]), c = T(g_in[2]), d = T(g_in[3]);
    const bool f3 = fin(a) && fin(b) && fin(c), f4 = f3 && fin(d);
    const int zeros3 = (a == T(0)) + (b == T(0)) + (c == T(0));
    switch (which) {
        case 0: expect(f3 && a >= T(0) && b >= T(0) && c >= T(0) && zeros3 <= 1, apse::carlson_rf(a, b, c), 1); break;
        case 1: expect(f3 && a >= T(0) && b >= T(0) && !(a == T(0) && b == T(0)) && c > T(0), apse::carlson_rd(a, b, c), 1); break;
        case 2: expect(f4 && a >= T(0) && b >= T(0) && c >= T(0) && zeros3 <= 1 && d > T(0), apse::carlson_rj(a, b, c, d), 1); break;
        case 3: expect(fin(a) && fin(b) && a >= T(0) && b > T(0), apse::carlson_rc(a, b), 1); break;
        case 4: expect(fin(a) && fin(b) && b < T(1), apse::ellint_f(a, b), a > T(0) ? 1 : (a < T(0) ? -1 : 0)); break;
        case 5: expect(f3 && a < T(1) && c < T(1), apse::ellint_pi(a, b, c), b > T(0) ? 1 : (b < T(0) ? -1 : 0)); break;
        case 6: expect(fin(a) && a < T(1), apse::comp_ellint_k(a), 1); break;
        default: expect(fin(a) && fin(b) && a < T(1) && b < T(1), apse::comp_ellint_pi(a, b), 1); break;
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    FuzzedDataProvider in(data, size);
    g_which = in.ConsumeIntegralInRange<int>(0, 7);
    for (double& v : g_in) v = apse_fuzz::value(in);
    if (in.ConsumeBool()) g_in[in.ConsumeIntegralInRange<int>(0, 3)] = -0.25;  // the ellint_pi switch
    check<float>(g_which);
    check<double>(g_which);
    return 0;
}
