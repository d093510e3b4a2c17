// apse — area-preserving parameterizations for spherical ellipses.
// SPDX-License-Identifier: MIT
#pragma once

/// @file detail/quadrant.hpp
/// The symmetry bookkeeping shared by the radial, LD-radial and parallel maps (docs/math.md §4–5):
/// every map solves its cumulative-area equation on one quadrant (radial) or one half (parallel)
/// of the ellipse and reaches the others by reflection. Written once here:
///
/// * `clamp_unit` — the input policy for points of the square (NaN is reported, finite values
///   are clamped into [0, 1]);
/// * `normalize_direction` — the input policy for directions given to invert() (any non-zero
///   finite length; zero, NaN or infinite is reported);
/// * `fold_quadrant` / `unfold_quadrant_fraction` — u1 in [0, 1] ↔ (quadrant q, fraction f of
///   that quadrant's area measured from the major axis), reflected in odd quadrants so the map
///   is continuous across quadrant boundaries;
/// * `quadrant_of` / `place_in_quadrant` — a local direction ↔ (quadrant, |x|, |y|);
/// * `fold_half` / `unfold_half_fraction` — u1 in [0, 1] ↔ (side ±1 of the major axis, fraction
///   of that half's area measured from the minor-axis end), the parallel map's symmetry.

#include <cmath>

#include "../config.hpp"
#include "math.hpp"
#include "glm.hpp"

namespace apse {
namespace detail {

/// x clamped to [0, 1]; `ok` is cleared when x is NaN (the caller then reports "no sample").
template <class T> APSE_HOT_INLINE T clamp_unit(T x, bool& ok) noexcept {
    const bool nan = is_nan(x);
    if (nan) ok = false;
    return nan ? T(0) : clamp_non_nan(x, T(0), T(1));
}

/// The point u of the square with both coordinates through clamp_unit (x first, then y).
template <class T> APSE_HOT_INLINE glm::vec<2, T> clamp_unit(const glm::vec<2, T>& u, bool& ok) noexcept {
    const T x = clamp_unit(u.x, ok);
    const T y = clamp_unit(u.y, ok);
    return glm::vec<2, T>(x, y);
}

/// v divided by its length; `ok` is cleared (and v returned unchanged) when the length is zero,
/// NaN or infinite (the caller then reports "no point").
template <class T> APSE_FUNC glm::vec<3, T> normalize_direction(const glm::vec<3, T>& v, bool& ok) noexcept {
    const T len = std::sqrt(v.x * v.x + v.y * v.y + v.z * v.z);
    if (!(len > T(0)) || !is_finite(len)) {
        ok = false;
        return v;
    }
    return v / len;
}

/// A point of [0, 1] folded onto one quadrant.
template <class T> struct QuadrantFold {
    T sign_x;      ///< ±1: the quadrant as the signs of its x and y (counter-clockwise from the +x
    T sign_y;      ///< (major) axis: q = 0 (+, +), 1 (−, +), 2 (−, −), 3 (+, −))
    T fraction;    ///< fraction of the quadrant's area, measured from the major axis, in [0, 1]
};

/// u1 in [0, 1] → quadrant q = floor(4 u1) (u1 = 1 belongs to quadrant 3) and the fraction
/// f = 4 u1 − q, reflected (1 − f) in the odd quadrants: f is then always measured from the major
/// axis, and azimuth = q pi/2 + phi0 (q even) or (q + 1) pi/2 − phi0 (q odd) is continuous in u1.
/// Without branches (a random u1's quadrant is unpredictable): f is the triangle wave
/// 1 − |1 − |4 u1 − 2|| (exact for u1 >= 1/4; below, within one rounding of 2, 2^-52 in double),
/// y < 0 in the lower half (u1 > 1/2) and x < 0 in the middle quadrants (|4 u1 − 2| < 1). On the
/// quadrants' boundaries (u1 = 1/4, 1/2, 3/4) the point is on an axis, where the sign that
/// differs from q's multiplies zero.
template <class T> APSE_HOT_INLINE QuadrantFold<T> fold_quadrant(T u1) noexcept {
    const T g = std::fabs(T(4) * clamp(u1, T(0), T(1)) - T(2));  // distance from the −x axis, [0, 2]
    const T f = T(1) - std::fabs(T(1) - g);
    return {std::copysign(T(1), g - T(1)), std::copysign(T(1), T(0.5) - u1), clamp_non_nan(f, T(0), T(1))};
}

/// Inverse of fold_quadrant: (q, f) → u1 = (q + f)/4 (q even) or (q + 1 − f)/4 (q odd).
template <class T> APSE_FUNC T unfold_quadrant_fraction(int q, T f) noexcept {
    return ((q & 1) ? (T(q + 1) - f) : (T(q) + f)) * T(0.25);
}

/// Inverse of fold_quadrant from the fold itself, without branches (for a random point): the
/// quadrant's base (0, 2, 2, 4 quarter turns for q = 0..3, from the signs) plus the fraction,
/// reflected in the odd quadrants (where sign_x sign_y = −1).
template <class T> APSE_FUNC T unfold_quadrant(const QuadrantFold<T>& fold) noexcept {
    const T base = fold.sign_y > T(0) ? T(1) - fold.sign_x : T(3) + fold.sign_x;
    return T(0.25) * (base + fold.sign_x * fold.sign_y * fold.fraction);
}

/// Maps a first-quadrant local (x >= 0, y >= 0) onto the quadrant of `fold` by the reflections
/// (x, y) → (±x, ±y): (sign_x x, sign_y y, z). Exact (and free of branches).
template <class T>
APSE_HOT_INLINE glm::vec<3, T> place_in_quadrant(const QuadrantFold<T>& fold, T x, T y, T z) noexcept {
    return glm::vec<3, T>(fold.sign_x * x, fold.sign_y * y, z);
}

/// Quadrant of a local direction (the inverse of place_in_quadrant): q such that the reflections
/// of quadrant q (fold_quadrant) take (|x|, |y|) back to (x, y). Points on the axes go to the quadrant
/// for which the fraction is 0 or 1 consistently with fold_quadrant (+x axis → q = 0 with f = 0,
/// +y → q = 0 with f = 1, −x → q = 1 with f = 0, −y → q = 2 with f = 1: the same u1
/// as the neighbouring quadrant would give).
template <class T> APSE_FUNC int quadrant_of(T x, T y) noexcept {
    if (y >= T(0)) return (x >= T(0)) ? 0 : 1;
    return (x > T(0)) ? 3 : 2;
}

/// A point of [0, 1] folded onto one half of the ellipse (sides of the major axis).
template <class T> struct HalfFold {
    T side;      ///< −1 (u1 < 1/2: y < 0) or +1
    T fraction;  ///< fraction of the half's area measured from the minor-axis end, in [0, 1]
};

/// u1 in [0, 1] → side and edge fraction g: u1 < 1/2 → (−1, 2 u1); else (+1, 2 − 2 u1). Exact
/// (both products and the difference, by Sterbenz, are exact): g = 0 at the ends of the minor
/// axis (u1 = 0, 1), g = 1 on the major axis (u1 = 1/2).
template <class T> APSE_FUNC HalfFold<T> fold_half(T u1) noexcept {
    if (u1 < T(0.5)) return {T(-1), clamp(T(2) * u1, T(0), T(1))};
    return {T(1), clamp(T(2) - T(2) * u1, T(0), T(1))};
}

/// Inverse of fold_half: (side, g) → u1 = g/2 (side < 0) or 1 − g/2.
template <class T> APSE_FUNC T unfold_half_fraction(T side, T g) noexcept {
    return side < T(0) ? T(0.5) * g : T(1) - T(0.5) * g;
}

}  // namespace detail
}  // namespace apse
