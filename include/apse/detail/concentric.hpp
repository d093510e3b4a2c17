// apse — area-preserving parameterizations for spherical ellipses.
// SPDX-License-Identifier: MIT
#pragma once

/// @file detail/concentric.hpp
/// Shirley–Chiu concentric map of the unit square onto the unit disk and its inverse, in polar
/// form (docs/math.md §4). It is area-preserving (up to the factor pi) and maps concentric squares
/// to concentric circles, so it keeps stratification. Used by uniform-by-area disk sampling
/// (signed form: point = radius (cos angle, sin angle), angle in [−pi/4, 3pi/4]) and by the LD-radial map (azimuthal area fraction
/// `turns` = angle / (2 pi), radial fraction radius^2).

#include <cmath>

#include "../config.hpp"
#include "math.hpp"
#include "glm.hpp"
#include "quadrant.hpp"

namespace apse {
namespace detail {

/// A point of the unit disk in polar form: `radius` in [0, 1], `turns` = angle / (2 pi) in
/// [0, 1) (computed directly, without rounding through pi).
template <class T> struct ConcentricPolar {
    T radius;  ///< in [0, 1]
    T turns;   ///< angle / (2 pi), in [0, 1)
    /// The polar angle in radians, in [0, 2 pi).
    APSE_FUNC T angle() const noexcept { return two_pi_v<T> * turns; }
};

/// Concentric map (docs/math.md §4): A = 2u1 − 1, B = 2u2 − 1; if |A| > |B|: radius |A|,
/// angle (pi/4)(B/A) (+pi if A < 0, +2pi if A > 0 > B); else radius |B|,
/// angle pi/2 − (pi/4)(A/B) (+pi if B < 0); the square's centre → (0, 0).
/// Domain [0, 1]^2; coordinates outside are clamped into it (NaN → 0).
template <class T> APSE_FUNC ConcentricPolar<T> concentric_to_disk(const glm::vec<2, T>& u) noexcept {
    const T a = T(2) * clamp(u.x, T(0), T(1)) - T(1);
    const T b = T(2) * clamp(u.y, T(0), T(1)) - T(1);
    if (a == T(0) && b == T(0)) return {T(0), T(0)};
    T radius, turns;
    if (std::fabs(a) > std::fabs(b)) {
        radius = std::fabs(a);
        turns = T(0.125) * (b / a);  // in (-1/8, 1/8)
        if (a < T(0)) turns += T(0.5);
        else if (turns < T(0)) turns += T(1);
    } else {
        radius = std::fabs(b);
        turns = T(0.25) - T(0.125) * (a / b);  // in [1/8, 3/8]
        if (b < T(0)) turns += T(0.5);
    }
    if (!(turns < T(1))) turns = T(0);  // 1 − tiny rounded up: the same point
    return {radius, turns};
}

/// The concentric map's point of u, folded as the LD-radial map reads it: the quadrant and the
/// fraction of its quarter turn that fold_quadrant(turns) gives, the radius and its square.
template <class T> struct ConcentricFold {
    QuadrantFold<T> fold;  ///< quadrant (signs of the disk point's x, y) and the fraction of the
                           ///< quarter turn measured from the x axis
    T radius;              ///< radius, in [0, 1]
    T radius2;             ///< radius^2
};

/// concentric_to_disk(u) folded onto the first quadrant, without branches: with A = 2u1 − 1 and
/// B = 2u2 − 1, the disk point's x has the sign of A and y that of B, the radius is
/// M = max(|A|, |B|), and the angle from the x axis is (pi/4)|B|/|A| (|A| > |B|) or
/// pi/2 − (pi/4)|A|/|B|: the fraction of the quarter turn is |B|/(2|A|) or 1 − |A|/(2|B|), both
/// 1/2 + (|B| − |A|)/(2M). The same point as fold_quadrant(concentric_to_disk(u).turns) up to
/// rounding (an absolute error of about one ulp of 1/2 in the fraction). u in [0, 1]^2, not
/// checked (the caller clamps: clamp_unit); the square's centre → radius 0.
template <class T> APSE_HOT_INLINE ConcentricFold<T> concentric_fold(const glm::vec<2, T>& u) noexcept {
    const T a = T(2) * u.x - T(1);
    const T b = T(2) * u.y - T(1);
    const T fa = std::fabs(a), fb = std::fabs(b);
    const T m = max_of(fa, fb);
    // (|B| − |A|)/(2M) with the centre (0/0) sent to 0: away from the centre M >= 2^-53 (a and b
    // are multiples of 2^-53), so the divisor is 2M itself there.
    const T fraction = T(0.5) + (fb - fa) / max_of(m + m, T(0x1p-64));
    return {{std::copysign(T(1), a), std::copysign(T(1), b), clamp_non_nan(fraction, T(0), T(1))}, m, m * m};
}

/// A point of the unit disk in signed polar form: radius (cos angle, sin angle) with `radius`
/// in [−1, 1] and `angle` in [−pi/4, 3pi/4] (the form a renderer writes: no angle wrapping).
template <class T> struct ConcentricSigned {
    T radius;  ///< in [−1, 1]
    T angle;   ///< radians, in [−pi/4, 3pi/4]
};

/// The concentric map's point of u (the same point as concentric_to_disk(u)), in signed polar
/// form: A = 2u1 − 1, B = 2u2 − 1; if |A| > |B|: (A, (pi/4)(B/A)), else (B, pi/2 − (pi/4)(A/B));
/// the square's centre → (0, 0). One division. Domain [0, 1]^2; coordinates outside are clamped
/// into it (NaN → 0).
template <class T> APSE_HOT_INLINE ConcentricSigned<T> concentric_to_disk_signed(const glm::vec<2, T>& u) noexcept {
    const T a = T(2) * clamp(u.x, T(0), T(1)) - T(1);
    const T b = T(2) * clamp(u.y, T(0), T(1)) - T(1);
    const T quarter_pi = T(0.25) * pi_v<T>;
    if (std::fabs(a) > std::fabs(b)) return {a, quarter_pi * (b / a)};
    if (b == T(0)) return {T(0), T(0)};
    return {b, half_pi_v<T> - quarter_pi * (a / b)};
}

/// Inverse of concentric_to_disk: the square point of the disk point (radius, turns) (radius in
/// [0, 1], turns = angle / (2 pi), any real: reduced modulo 1). Radii above 1 are clamped to 1.
template <class T> APSE_FUNC glm::vec<2, T> concentric_from_disk(T radius, T turns) noexcept {
    const T rho = clamp(radius, T(0), T(1));
    T t = turns - std::floor(turns);  // [0, 1]
    if (!(t >= T(0) && t < T(1))) t = T(0);
    const T s = T(8) * t;  // eighths of a turn, [0, 8)
    T a, b;
    if (s < T(1) || s >= T(7)) {  // right sector: A = rho, B/A = 8 turns (turns in [-1/8, 1/8))
        a = rho;
        b = rho * (s < T(1) ? s : s - T(8));
    } else if (s < T(3)) {  // top: B = rho, A/B = 2 − 8 turns
        b = rho;
        a = rho * (T(2) - s);
    } else if (s < T(5)) {  // left: A = −rho, B/A = 8 turns − 4
        a = -rho;
        b = -rho * (s - T(4));
    } else {  // bottom: B = −rho, A/B = 6 − 8 turns
        b = -rho;
        a = -rho * (T(6) - s);
    }
    return glm::vec<2, T>(T(0.5) * (a + T(1)), T(0.5) * (b + T(1)));
}

}  // namespace detail
}  // namespace apse
