// apse — area-preserving parameterizations for spherical ellipses.
// SPDX-License-Identifier: MIT
#pragma once

/// @file detail/math.hpp
/// Device-safe scalar helpers shared by every apse header (namespace apse::detail), apse's own
/// `<cmath>`: constants, NaN / finiteness tests on the bits, min/max/clamp, a guarded square
/// root, a bracketed Newton–bisection root finder, paired square roots and divisions, and
/// trigonometry by short polynomials. The public constants are re-exported by math.hpp.
///
/// **Paired square roots and divisions** (`sqrt2`, `div2`): two independent square roots or two
/// independent divisions in one instruction, in double. On x86-64 the square-root/divide unit is
/// not fully pipelined (one sqrtsd per ~8 cycles, one divsd per ~4-5 on Zen 3), and apse's
/// set-up code and elliptic integrals are bound by it; SSE `sqrtpd`/`divpd` compute two lanes
/// for about the price of one (measured: R_F -12%, R_J -9%, disk projection -6%). In float the
/// scalar operations are faster (their throughput is higher, and packing two floats into a
/// vector adds latency: measured, float projection -7 to -9 %, tabulated LD-radial set-up + 1
/// sample -5.5 to -6 % with the scalar form), so float takes them. The results are bit-identical
/// either way (IEEE square roots and quotients are correctly rounded). Elsewhere (CUDA device
/// code, non-x86 hosts, or with `APSE_NO_SIMD` defined) they are the scalar operations.
///
/// **Trigonometry by short polynomials**, for the per-sample and per-shading-point paths where
/// the argument's range is known (no library call, no range reduction, no branch on the
/// argument's size; the same code on the host and in CUDA device code):
///
/// * `sin_cos_quarter_turn(q)`: sin and cos of q pi/2 for q in [0, 1], within 2 eps (Taylor
///   polynomials of the sine on the whole quarter turn; the cosine as the sine of 1 − q), and
///   `sin_cos_of_angle(x)`, the same for an angle x in [0, pi/2] (`sin_cos_of_nonnegative_angle`
///   where x is known not to be negative or NaN);
/// * `arc_ratio(s1, c1, s2, c2)`: an approximation of the ratio of two angles in [0, pi/2] given
///   by their sines and cosines (Hastings' atan of the half angles' tangents; the ratio within
///   3e-8 in double, 3e-7 in float): a table coordinate, never a result (TabulatedMap's blend of
///   table rows: any value is exact for the sampler, the approximation moves only which rows are
///   blended, by less than 3e-6 of a node);
/// * `angle_approx(s, c)`, `angle_of(s, c)`: atan2(s, c) for s, c >= 0 — Hastings' atan
///   (absolute error below 2e-8, relative error far smaller for small angles), and that refined
///   by one step with sin_cos_quarter_turn to within a few ulps (ProjectedSolidAngleSampler).

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <type_traits>

#include "../config.hpp"

// SSE2 for sqrt2/div2: every x86-64 host compiler; never in CUDA device code, nor when the user
// defines APSE_NO_SIMD before including apse (the scalar path, the one device code takes).
#if (defined(__SSE2__) || defined(_M_X64)) && !defined(__CUDA_ARCH__) && !defined(APSE_NO_SIMD)
#include <emmintrin.h>
#define APSE_PAIRS_SSE2 1
#else
#define APSE_PAIRS_SSE2 0
#endif

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

// ---- Paired square roots and divisions (see the file comment) ----

/// sx = sqrt(x), sy = sqrt(y) (paired in double, see the file comment).
template <class T> APSE_FUNC void sqrt2(T x, T y, T& sx, T& sy) noexcept {
#if APSE_PAIRS_SSE2
    if constexpr (sizeof(T) == sizeof(double)) {
        const __m128d r = _mm_sqrt_pd(_mm_set_pd(double(y), double(x)));
        sx = T(_mm_cvtsd_f64(r));
        sy = T(_mm_cvtsd_f64(_mm_unpackhi_pd(r, r)));
        return;
    }
#endif
    sx = std::sqrt(x);
    sy = std::sqrt(y);
}

/// qa = a / b, qc = c / d (paired in double, see the file comment).
template <class T> APSE_FUNC void div2(T a, T b, T c, T d, T& qa, T& qc) noexcept {
#if APSE_PAIRS_SSE2
    if constexpr (sizeof(T) == sizeof(double)) {
        const __m128d r = _mm_div_pd(_mm_set_pd(double(c), double(a)), _mm_set_pd(double(d), double(b)));
        qa = T(_mm_cvtsd_f64(r));
        qc = T(_mm_cvtsd_f64(_mm_unpackhi_pd(r, r)));
        return;
    }
#endif
    qa = a / b;
    qc = c / d;
}

// ---- Trigonometry by short polynomials (see the file comment) ----

/// sin and cos of an angle.
template <class T> struct SinCosValues {
    T s;  ///< sine
    T c;  ///< cosine
};

/// c0 + c1 y + ... + c8 y^8 by Estrin's scheme (depth 5 multiply-adds instead of Horner's 8: the
/// polynomials below sit on the samplers' critical paths), for y in [0, 1], c0 = 1 and the other
/// coefficients below 1 in magnitude. In float the powers y^2, y^4, y^8 (and c8 y^8) would be
/// subnormal for y below 2^-15 (atan of a ratio below 0.004: the tangent of a far disk's angle),
/// and each subnormal result costs tens of cycles on x86: there the powers are formed from
/// max(y, 2^-14) instead (y itself stays exact in the terms c_i y), which moves the sum by at
/// most (|c2| + |c3|) 2^-28 + 2^-54: 1.3e-9 for atan_unit_approx's coefficients, 0.02 ulp of its
/// float result.
template <class T>
APSE_HOT_INLINE T estrin8(T y, T c0, T c1, T c2, T c3, T c4, T c5, T c6, T c7, T c8) noexcept {
    const T yp = sizeof(T) == sizeof(float) ? max_of(y, T(0x1p-14)) : y;
    const T y2 = yp * yp, y4 = y2 * y2, y8 = y4 * y4;
    const T p01 = c0 + c1 * y, p23 = c2 + c3 * y, p45 = c4 + c5 * y, p67 = c6 + c7 * y;
    const T p03 = p01 + p23 * y2, p47 = p45 + p67 * y2;
    return (p03 + p47 * y4) + c8 * y8;
}

/// sin(t pi/2) for t in [0, 1] (not checked): x P(x^2), x = t pi/2, with P the Taylor polynomial
/// of sin(x)/x to x^20 in double (the first term left out is below 1e-18 at x = pi/2) and to x^12
/// in float (below 7e-10), by Estrin's scheme; the powers of x^2 beyond the first are formed from
/// max(x^2, 2^-14) in float (no subnormals for small t; the sum moves by less than 2^-34).
template <class T> APSE_HOT_INLINE T sin_quarter_turn(T t) noexcept {
    const T x = t * half_pi_v<T>, y = x * x;
    if constexpr (sizeof(T) == sizeof(float)) {
        const T yp = max_of(y, T(0x1p-14)), y2 = yp * yp, y4 = y2 * y2;
        const T p01 = T(1) + T(-1.0 / 6) * y, p23 = T(1.0 / 120) + T(-1.0 / 5040) * y;
        const T p45 = T(1.0 / 362880) + T(-1.0 / 39916800) * y;
        return x * ((p01 + p23 * y2) + (p45 + T(1.0 / 6227020800.0) * y2) * y4);
    } else {
        const T y2 = y * y, y4 = y2 * y2, y8 = y4 * y4;
        const T p01 = T(1) + T(-1.0 / 6) * y, p23 = T(1.0 / 120) + T(-1.0 / 5040) * y;
        const T p45 = T(1.0 / 362880) + T(-1.0 / 39916800) * y;
        const T p67 = T(1.0 / 6227020800.0) + T(-1.0 / 1307674368000.0) * y;
        const T p89 = T(1.0 / 355687428096000.0) + T(-1.0 / 121645100408832000.0) * y;
        const T p07 = (p01 + p23 * y2) + (p45 + p67 * y2) * y4;
        return x * (p07 + (p89 + T(1.0 / 51090942171709440000.0) * y2) * y8);
    }
}

/// sin(q pi/2) and cos(q pi/2) = sin((1 − q) pi/2) for q in [0, 1] (not checked: the caller
/// clamps): two independent sine polynomials on the whole quarter turn, no reflection, no branch
/// and no select (q is a random sample's: a 50/50 branch is mispredicted half the time, and a
/// reflection's mask blends cost more than the longer polynomials). 1 − q is exact for
/// q >= 1/2 (Sterbenz) and within half an ulp of 1 below, where the cosine is flat. Measured
/// within 1.9 eps (double) / 1.6 eps (float) absolute of the true values, both in [0, 1].
template <class T> APSE_HOT_INLINE SinCosValues<T> sin_cos_quarter_turn(T q) noexcept {
    return {sin_quarter_turn(q), sin_quarter_turn(T(1) - q)};
}

/// 2/pi: quarter turns per radian.
template <class T> APSE_FUNC constexpr T quarter_turns_per_radian() noexcept { return T(0.63661977236758134308); }

/// sin and cos of the angle x in [0, pi/2] (clamped into it): sin_cos_quarter_turn(x 2/pi). Its
/// error is sin_cos_quarter_turn's (2 eps, tested) plus the rounding of x 2/pi (half an ulp of
/// the quarter-turn fraction, i.e. at most ~eps of the angle, times a derivative <= 1): within
/// ~3 eps absolute by that bound, and a few eps relative for small x (the sine is x (1 + O(x^2))).
template <class T> APSE_HOT_INLINE SinCosValues<T> sin_cos_of_angle(T x) noexcept {
    return sin_cos_quarter_turn(clamp(x * quarter_turns_per_radian<T>(), T(0), T(1)));
}

/// sin_cos_of_angle for an angle known to be >= 0 and not NaN (a root finder's bracketed iterate):
/// the same values there, without the clamp's NaN test (only x 2/pi rounding above 1 is capped).
template <class T> APSE_HOT_INLINE SinCosValues<T> sin_cos_of_nonnegative_angle(T x) noexcept {
    return sin_cos_quarter_turn(min_of(x * quarter_turns_per_radian<T>(), T(1)));
}

/// atan(z) for z in [0, 1], absolute error below 2e-8 (Hastings' degree-17 odd polynomial,
/// Abramowitz & Stegun 4.4.49); in float the rounding of T dominates.
template <class T> APSE_HOT_INLINE T atan_unit_approx(T z) noexcept {
    return z * estrin8(z * z, T(1), T(-0.3333314528), T(0.1999355085), T(-0.1420889944), T(0.1065626393),
                       T(-0.0752896400), T(0.0429096138), T(-0.0161657367), T(0.0028662257));
}

/// atan2(s, c) for s, c >= 0 (not both 0), absolute error below 2e-8 (atan_unit_approx of the
/// smaller of s/c and c/s; the angle's relative error is far smaller for small angles).
template <class T> APSE_FUNC T angle_approx(T s, T c) noexcept {
    return s > c ? half_pi_v<T> - atan_unit_approx(c / s) : atan_unit_approx(s / c);
}

/// atan2(s, c) for a unit (s, c) with s, c >= 0, to a few ulps: angle_approx's a, then
/// a + sin(theta − a) (sin(theta − a) = s cos a − c sin a by sin_cos_quarter_turn; the
/// correction's own error is below (2e-8)^3/6).
template <class T> APSE_FUNC T angle_of(T s, T c) noexcept {
    const T a = angle_approx(s, c);
    const SinCosValues<T> r = sin_cos_of_angle(a);
    return a + (s * r.c - c * r.s);
}

/// An approximation of theta2 / theta1 for angles theta_i = atan2(s_i, c_i) in [0, pi/2]
/// (s_i, c_i >= 0, not both 0; theta1 > 0): each angle is twice the atan of
/// tan(theta/2) = s/(1 + c), which is in [0, 1] (atan_unit_approx's range, no choice between atan
/// and pi/2 − atan; 1 + c >= 1: no cancellation), the two quotients paired; the factors 2
/// cancel. atan_unit_approx's absolute error is below 2e-8 per angle and its relative error far
/// smaller for small angles (the polynomial is z (1 + O(z^2))). Measured max absolute error of the
/// ratio over theta1 from 1e-12 to pi/2 (test_math): 2.9e-8 in double, 2.1e-7 in float (its
/// rounding). 0 if theta1 is 0.
template <class T> APSE_FUNC T arc_ratio(T s1, T c1, T s2, T c2) noexcept {
    T t1, t2;
    div2(s1, T(1) + c1, s2, T(1) + c2, t1, t2);
    const T a1 = atan_unit_approx(t1), a2 = atan_unit_approx(t2);
    return a1 > T(0) ? a2 / a1 : T(0);
}

}  // namespace detail
}  // namespace apse
