// APSE_NO_SIMD defined before including apse turns the SSE pair helpers off: the scalar path
// (the one CUDA device code and non-x86 hosts take) is then the one compiled. Checks that the
// switch is honoured and that the scalar pairs give the correctly rounded results the SSE ones
// give (IEEE square roots and quotients are correctly rounded either way). A plain executable: it
// needs no test framework.
#ifndef APSE_NO_SIMD  // (the fma-nosimd configuration defines it for every file)
#define APSE_NO_SIMD
#endif
#include <apse/detail/math.hpp>

#include <cmath>
#include <cstdio>
#include <limits>

#if APSE_PAIRS_SSE2
#error "APSE_NO_SIMD did not turn the SSE pairs off"
#endif

namespace {

int failures = 0;

template <class T> void check(T x, T y) {
    T sx, sy, qa, qc;
    apse::detail::sqrt2(x, y, sx, sy);
    apse::detail::div2(x, y, y, x, qa, qc);
    const volatile T vx = x, vy = y;  // keep the reference operations out of constant folding
    const T rx = std::sqrt(T(vx)), ry = std::sqrt(T(vy)), ra = T(vx) / T(vy), rc = T(vy) / T(vx);
    // Bit-identical (correctly rounded both ways), except under -ffast-math, whose reciprocal
    // approximations (x / y as x * (1 / y)) may be applied to one expression and not the other:
    // then within 2 ulps (two roundings of the reciprocal form).
#if defined(__FAST_MATH__) || defined(__RECIPROCAL_MATH__) || defined(__ASSOCIATIVE_MATH__)
    const T tol = T(2) * std::numeric_limits<T>::epsilon();
#else
    const T tol = T(0);
#endif
    auto same = [tol](T a, T b) { return a == b || std::fabs(a - b) <= tol * std::fabs(b); };
    if (!(same(sx, rx) && same(sy, ry) && same(qa, ra) && same(qc, rc))) {
        std::printf("mismatch for %.17g %.17g\n", double(x), double(y));
        ++failures;
    }
}

}  // namespace

int main() {
    const double values[] = {1.0, 2.0, 3.0, 0.1, 1e-300, 1e300, 7.25, 12345.678};
    for (double a : values)
        for (double b : values) {
            check<double>(a, b);
            check<float>(float(a < 1e30 && a > 1e-30 ? a : 1.5), float(b < 1e30 && b > 1e-30 ? b : 0.5));
        }
    std::printf("APSE_NO_SIMD: scalar pairs, %d mismatches\n", failures);
    return failures == 0 ? 0 : 1;
}
