// apse — area-preserving parameterizations for spherical ellipses.
// SPDX-License-Identifier: MIT
#pragma once

/// @file detail/math.hpp
/// Device-safe scalar helpers shared by every apse header (namespace apse::detail): constants,
/// NaN / finiteness tests on the bits, min/max/clamp, a guarded square root and a bracketed
/// Newton–bisection root finder. The public constants are re-exported by math.hpp.

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <type_traits>

#include "../config.hpp"

namespace apse {
namespace detail {

/// True for the two types apse computes in, float and double (every class template and function
/// template of apse rejects any other T with a static_assert naming it).
template <class T> APSE_FUNC constexpr bool is_real_type() noexcept {
    return std::is_same<T, float>::value || std::is_same<T, double>::value;
}

/// pi in type T (rounded to nearest).
template <class T> constexpr T pi_v = T(3.141592653589793238462643383279502884L);
/// pi / 2 in type T.
template <class T> constexpr T half_pi_v = T(1.570796326794896619231321691639751442L);
/// 2 pi in type T.
template <class T> constexpr T two_pi_v = T(6.283185307179586476925286766559005768L);

/// Quiet NaN of type T (the value apse functions return outside their domain).
/// (In device code without `--expt-relaxed-constexpr` std::numeric_limits is unavailable, hence
/// the CUDA intrinsics there.)
template <class T> APSE_FUNC T quiet_nan() noexcept {
#if defined(__CUDA_ARCH__)
    if constexpr (sizeof(T) == sizeof(float)) return T(__int_as_float(0x7fc00000));
    else return T(__longlong_as_double(0x7ff8000000000000LL));
#else
    return std::numeric_limits<T>::quiet_NaN();
#endif
}

/// Machine epsilon of type T (float or double), usable in host and device code.
template <class T> APSE_FUNC constexpr T epsilon() noexcept {
    static_assert(is_real_type<T>(), "apse: T must be float or double");
    return sizeof(T) == sizeof(float) ? T(0x1p-23) : T(0x1p-52);
}

/// The bits of x with the sign cleared: 32 bits for float, 64 for double. Reading the bits
/// keeps is_nan / is_finite true to IEEE 754 under -ffast-math / -ffinite-math-only, where
/// compilers fold `x != x`, `std::isnan(x)` and `std::isfinite(x)` to constants.
template <class T> APSE_FUNC auto magnitude_bits(T x) noexcept {
    static_assert(is_real_type<T>(), "apse: T must be float or double");
    if constexpr (sizeof(T) == sizeof(float)) {
#if defined(__CUDA_ARCH__)
        const std::uint32_t b = std::uint32_t(__float_as_uint(float(x)));
#else
        std::uint32_t b;
        std::memcpy(&b, &x, sizeof b);
#endif
        return std::uint32_t(b & 0x7fffffffu);
    } else {
#if defined(__CUDA_ARCH__)
        const std::uint64_t b = std::uint64_t(__double_as_longlong(double(x)));
#else
        std::uint64_t b;
        std::memcpy(&b, &x, sizeof b);
#endif
        return std::uint64_t(b & 0x7fffffffffffffffull);
    }
}

/// The exponent field of T with every bit set (the bits of +infinity).
template <class T> APSE_FUNC auto infinity_bits() noexcept {
    if constexpr (sizeof(T) == sizeof(float)) return std::uint32_t(0x7f800000u);
    else return std::uint64_t(0x7ff0000000000000ull);
}

/// True if x is NaN. Reads the bit pattern, so it holds under -ffast-math (where `x != x` and
/// std::isnan fold to false) and in device code.
template <class T> APSE_FUNC bool is_nan(T x) noexcept {
    return magnitude_bits(x) > infinity_bits<T>();
}

/// True if x is neither NaN nor +-infinity. Reads the bit pattern, so it holds under -ffast-math
/// (where std::isfinite folds to true) and in device code.
template <class T> APSE_FUNC bool is_finite(T x) noexcept {
    return magnitude_bits(x) < infinity_bits<T>();
}

/// x * x.
template <class T> APSE_FUNC constexpr T sqr(T x) noexcept { return x * x; }

/// x^(1/3) for x in [2^-100, 2^100] (not checked), relative error 2.1e-5 in float and 6.1e-15
/// in double (measured): the exponent divided by 3 on the bits (the initial estimate of fdlibm's
/// cbrt, within 3.2e-2), then Halley steps y (y^3 + 2x)/(2y^3 + x), each cubing the error (one
/// in float, two in double). For first guesses: no library call, no range reduction.
template <class T> APSE_FUNC T cube_root_approx(T x) noexcept {
    static_assert(is_real_type<T>(), "apse: T must be float or double");
    T y;
    if constexpr (sizeof(T) == sizeof(float)) {
#if defined(__CUDA_ARCH__)
        y = T(__uint_as_float(__float_as_uint(float(x)) / 3u + 0x2a5119f2u));
#else
        std::uint32_t b;
        std::memcpy(&b, &x, sizeof b);
        b = b / 3u + 0x2a5119f2u;
        std::memcpy(&y, &b, sizeof y);
#endif
    } else {
#if defined(__CUDA_ARCH__)
        y = T(__longlong_as_double(
            (long long)(std::uint64_t(__double_as_longlong(double(x))) / 3u + 0x2a9f789300000000ull)));
#else
        std::uint64_t b;
        std::memcpy(&b, &x, sizeof b);
        b = b / 3u + 0x2a9f789300000000ull;
        std::memcpy(&y, &b, sizeof y);
#endif
    }
    for (int step = 0; step < (sizeof(T) == sizeof(float) ? 1 : 2); ++step) {
        const T y3 = y * y * y;
        y *= (y3 + T(2) * x) / (T(2) * y3 + x);
    }
    return y;
}


/// The smaller of a and b (b if either is NaN).
template <class T> APSE_FUNC constexpr T min_of(T a, T b) noexcept { return a < b ? a : b; }

/// The larger of a and b (b if either is NaN).
template <class T> APSE_FUNC constexpr T max_of(T a, T b) noexcept { return a > b ? a : b; }

/// x clamped to [lo, hi]; NaN maps to lo (tested on the bits, so also under -ffast-math, where
/// the comparisons alone may let a NaN through).
template <class T> APSE_FUNC T clamp(T x, T lo, T hi) noexcept {
    return is_nan(x) ? lo : (x > lo ? (x < hi ? x : hi) : lo);
}

/// x clamped to [lo, hi] for an x that is not NaN (by construction, or tested before): a max and
/// a min (maxss/minss on x86), without clamp's test of the bits. The sampling paths' clamps
/// after their input has been checked.
template <class T> APSE_FUNC constexpr T clamp_non_nan(T x, T lo, T hi) noexcept { return min_of(max_of(x, lo), hi); }

/// sqrt(max(x, 0)): for quantities that are non-negative in exact arithmetic but may round
/// slightly below zero. NaN stays NaN.
template <class T> APSE_FUNC T safe_sqrt(T x) noexcept { return std::sqrt(x < T(0) ? T(0) : x); }

/// Result of find_root_bracketed: the root estimate and the number of Newton/bisection steps.
template <class T> struct RootResult {
    T x;             ///< the root estimate, always inside the initial bracket
    int iterations;  ///< the number of function evaluations after the initial guess
};

/// Solves f(x) = 0 for an increasing function on [lo, hi] with f(lo) <= 0 <= f(hi), by Newton
/// steps safeguarded with bisection. `eval(x, value, derivative)` writes f(x) and f'(x).
/// Starts from `guess` (clamped into the bracket); stops when |f(x)| <= tolerance, when the
/// bracket has collapsed to a few ulps, when a Newton step no longer moves x (it is below an
/// ulp), or after `max_iterations` evaluations (a hard cap: the
/// loop always terminates). Any Newton step leaving the current bracket is replaced by a
/// bisection step, so the result stays inside [lo, hi] even for NaN values of f or f'.
template <class T, class Eval>
APSE_FUNC RootResult<T> find_root_bracketed(Eval&& eval, T lo, T hi, T guess, T tolerance,
                                            int max_iterations) noexcept {
    T x = clamp(guess, lo, hi);
    int it = 0;
    for (;;) {
        T value = T(0), derivative = T(0);
        eval(x, value, derivative);
        if (!(std::fabs(value) > tolerance)) break;  // converged (or NaN: stop, x is in bracket)
        if (value < T(0)) lo = x; else hi = x;
        if (it >= max_iterations || !(hi - lo > T(4) * epsilon<T>() * max_of(std::fabs(lo), std::fabs(hi))))
            break;
        ++it;
        const T next = x - value / derivative;
        if (next == x) break;  // the Newton step is below an ulp of x: x is as good as it gets
        x = (next > lo && next < hi) ? next : T(0.5) * (lo + hi);
    }
    return {x, it};
}

}  // namespace detail
}  // namespace apse
