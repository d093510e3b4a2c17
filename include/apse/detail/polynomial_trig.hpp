// apse — area-preserving parameterizations for spherical ellipses.
// SPDX-License-Identifier: MIT
#pragma once

/// @file detail/polynomial_trig.hpp
/// Trigonometry by short polynomials, for the per-sample and per-shading-point paths where the
/// argument's range is known (no library call, no range reduction, no branch on the argument's
/// size; the same code on the host and in CUDA device code):
///
/// * `sin_cos_quarter_turn(q)`: sin and cos of q pi/2 for q in [0, 1], within 2 eps (Taylor
///   polynomials of the sine on the whole quarter turn; the cosine as the sine of 1 − q), and
///   `sin_cos_of_angle(x)`, the same for an angle x in [0, pi/2] (`sin_cos_of_nonnegative_angle`
///   where x is known not to be negative or NaN);
/// * `arc_ratio(s1, c1, s2, c2)`: an approximation of the ratio of two angles in [0, pi/2] given
///   by their sines and cosines (Hastings' atan of the half angles' tangents; the ratio within
///   3e-8 in double, 3e-7 in float):
///   a table coordinate, never a result (TabulatedMap's blend of table rows: any value is exact
///   for the sampler, the approximation moves only which rows are blended, by less than 3e-6 of
///   a node);
/// * `angle_approx(s, c)`, `angle_of(s, c)`: atan2(s, c) for s, c >= 0 — Hastings' atan
///   (absolute error below 2e-8, relative error far smaller for small angles), and that refined
///   by one step with sin_cos_quarter_turn to within a few ulps (ProjectedSolidAngleSampler).

#include "../config.hpp"
#include "math.hpp"
#include "pairs.hpp"

namespace apse {
namespace detail {

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
