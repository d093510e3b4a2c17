// apse — area-preserving parameterizations for spherical ellipses.
// SPDX-License-Identifier: MIT
#pragma once

/// @file detail/vector.hpp
/// Private geometric helpers shared by projection.hpp and baselines/area.hpp: exact power-of-two
/// rescaling, overflow-free hypot and normalisation, a deterministic perpendicular vector.

#include <cmath>

#include "../config.hpp"
#include "math.hpp"
#include "glm.hpp"

namespace apse {
namespace detail {

template <class T> APSE_FUNC T max_abs3(const glm::vec<3, T>& v) noexcept {
    return max_of(max_of(std::fabs(v.x), std::fabs(v.y)), std::fabs(v.z));
}

/// Exponent e with s in [2^(e-1), 2^e) for finite s > 0, so that ldexp(s, -e) is in [1/2, 1).
template <class T> APSE_FUNC int scale_exponent(T s) noexcept {
    int e = 0;
    (void)std::frexp(s, &e);
    return e;
}

/// The exact power-of-two rescaling v * 2^-e (computed with ldexp when 2^-e itself would
/// overflow or underflow).
template <class T> struct Pow2Scale {
    int e;
    T factor;  ///< 2^-e, or 0 when not representable
    APSE_FUNC T operator()(T v) const noexcept { return factor != T(0) ? v * factor : std::ldexp(v, -e); }
    APSE_FUNC glm::vec<3, T> operator()(const glm::vec<3, T>& v) const noexcept {
        return glm::vec<3, T>((*this)(v.x), (*this)(v.y), (*this)(v.z));
    }
};
template <class T> APSE_FUNC Pow2Scale<T> pow2_scale_for(T s) noexcept {
    const int e = scale_exponent(s);
    constexpr int limit = sizeof(T) == sizeof(float) ? 120 : 1000;
    return {e, (e > -limit && e < limit) ? std::ldexp(T(1), -e) : T(0)};
}

/// The range of scene scales (the largest length of a projection's input) in which no rescaling
/// is needed: every product of up to four lengths stays a normal number there, down to length
/// ratios of 2^-100 (double) / 2^-20 (float) (below those, tan(beta) < tan_min: empty anyway, or
/// the tiny-value fallbacks take over).
template <class T> APSE_FUNC constexpr T safe_scale_min() noexcept {
    return sizeof(T) == sizeof(float) ? T(0x1p-16) : T(0x1p-100);
}
template <class T> APSE_FUNC constexpr T safe_scale_max() noexcept {
    return sizeof(T) == sizeof(float) ? T(0x1p16) : T(0x1p100);
}

/// A sum of squares at least this large lost no precision to underflow (2^-100 in float,
/// 2^-960 in double: 2^24 / 2^62 times the smallest normal number).
template <class T> APSE_FUNC constexpr T square_safe_min() noexcept {
    return sizeof(T) == sizeof(float) ? T(0x1p-100) : T(0x1p-960);
}

/// sqrt(a^2 + b^2) without overflow or underflow of the squares.
template <class T> APSE_FUNC T hypot2(T a, T b) noexcept {
    a = std::fabs(a);
    b = std::fabs(b);
    const T big = max_of(a, b), small = min_of(a, b);
    if (!(big > T(0))) return big;
    const T q = small / big;
    return big * std::sqrt(T(1) + q * q);
}

/// A deterministic unit vector perpendicular to the unit vector z (continuous except where
/// |z.x| = |z.y|).
template <class T> APSE_FUNC glm::vec<3, T> any_perpendicular(const glm::vec<3, T>& z) noexcept {
    if (std::fabs(z.x) > std::fabs(z.y)) {
        const T inv = T(1) / std::sqrt(z.x * z.x + z.z * z.z);
        return glm::vec<3, T>(-z.z * inv, T(0), z.x * inv);
    }
    const T inv = T(1) / std::sqrt(z.y * z.y + z.z * z.z);
    return glm::vec<3, T>(T(0), z.z * inv, -z.y * inv);
}

/// v / |v| for a finite non-zero v of any magnitude (scaled by its largest component first);
/// the zero vector for a zero or non-finite v.
template <class T> APSE_FUNC glm::vec<3, T> robust_normalize(const glm::vec<3, T>& v) noexcept {
    const T mx = max_abs3(v);
    if (!(mx > T(0)) || !is_finite(mx)) return glm::vec<3, T>(T(0));
    const glm::vec<3, T> u = v / mx;
    return u / std::sqrt(glm::dot(u, u));
}

template <class T> APSE_FUNC bool finite3(const glm::vec<3, T>& v) noexcept {
    return is_finite(v.x) && is_finite(v.y) && is_finite(v.z);
}

}  // namespace detail
}  // namespace apse
