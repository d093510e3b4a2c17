// Shared by apse's libFuzzer targets: input decoding biased towards the edges (raw bits, NaN,
// infinities, zeros, denormals, ±1 and a few ulps around it, plausible magnitudes) and a failure
// report. The targets also build without libFuzzer, with fuzz_replay.cpp as main, to replay the
// committed corpora (tests/fuzz/corpus/<target>/) in every configuration.
#pragma once

#include <apse/math.hpp>

#include <fuzzer/FuzzedDataProvider.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>

namespace apse_fuzz {

/// A double: raw bits (any value, NaN/Inf/denormal included), an edge value, or a plausible one
/// (mantissa in [-1, 1] times 10^[-12, 12]).
inline double value(FuzzedDataProvider& in) {
    switch (in.ConsumeIntegralInRange<int>(0, 5)) {
        case 0: return in.ConsumeFloatingPoint<double>();
        case 1: return double(in.ConsumeIntegralInRange<int>(-4, 4));
        case 2: {
            const double edges[] = {0.0, -0.0, 1.0, -1.0, 0.5, -0.25, 1.5707963267948966, 3.141592653589793,
                                    std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity(),
                                    std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::denorm_min(),
                                    std::numeric_limits<double>::min(), std::numeric_limits<double>::max(),
                                    1e-300, 1e300, 0x1p-149, 0x1p127};
            return edges[in.ConsumeIntegralInRange<int>(0, int(sizeof edges / sizeof edges[0]) - 1)];
        }
        case 3: {  // a few ulps (of double or of float) around ±1 or 0.5
            const double base = in.ConsumeBool() ? 1.0 : 0.5;
            const double ulp = in.ConsumeBool() ? 0x1p-52 : 0x1p-23;
            return (in.ConsumeBool() ? -1 : 1) * (base + ulp * in.ConsumeIntegralInRange<int>(-8, 8));
        }
        default: {
            const double m = in.ConsumeFloatingPointInRange<double>(-1.0, 1.0);
            return m * std::pow(10.0, in.ConsumeIntegralInRange<int>(-12, 12));
        }
    }
}

/// A point of the square: usually in [0, 1), sometimes any value().
inline double unit(FuzzedDataProvider& in) {
    return in.ConsumeBool() ? in.ConsumeProbability<double>() : value(in);
}

/// Reports the violated promise with the inputs (up to 16 numbers) and aborts (libFuzzer then
/// saves the input).
[[noreturn]] inline void fail(const char* target, const char* what, const double* inputs, int count) {
    std::fprintf(stderr, "%s: %s\n", target, what);
    for (int i = 0; i < count; ++i) std::fprintf(stderr, "  in[%d] = %.17g\n", i, inputs[i]);
    std::abort();
}

template <class V> bool finite3(const V& v) {
    return apse::detail::is_finite(v.x) && apse::detail::is_finite(v.y) && apse::detail::is_finite(v.z);
}

}  // namespace apse_fuzz
