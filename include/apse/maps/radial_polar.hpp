// apse — area-preserving parameterizations for spherical ellipses.
// SPDX-License-Identifier: MIT
#pragma once

/// @file maps/radial_polar.hpp
/// The polar step of the radial maps (docs/math.md §4), written once for RadialMap and TabulatedMap
/// (and through them LdRadialMap and TabulatedLdRadialMap): once u1 has fixed the azimuth, i.e.
/// the boundary point of the ellipse at that azimuth, u2 picks the polar angle uniformly in solid
/// angle along the wedge from the centre to that boundary point; and the inverse, u2 of a
/// direction.

#include <cmath>

#include "../config.hpp"
#include "../detail/glm.hpp"
#include "../detail/math.hpp"
#include "../detail/quadrant.hpp"
#include "cumulative_area.hpp"

namespace apse {
namespace detail {

/// The local direction (x along the major axis, z the centre) at the solid-angle fraction u2 in
/// [0, 1] of the wedge towards the first-quadrant boundary point with orthographic eccentric
/// anomaly (cos tau, sin tau) = (ct, st) and cos theta_max = c there (k.c_max(ct, st)), reflected
/// into quadrant q (place_in_quadrant). sin theta_max = r = |(a cos tau, b sin tau)|;
/// 1 − cos theta = u2 (1 − C), 1 − C = r^2/(1 + C); cos theta = (1 − u2) + u2 C (no cancellation
/// near the horizon of large ellipses); the in-plane part (ax, by) sin theta / r with
/// sin theta / r = sqrt(u2 (2 − v)/(1 + C)), v = 1 − cos theta. u2 = 0 gives the centre, u2 = 1
/// the boundary point. `inv_1pc` = 1/(1 + C) (the caller may have it from a paired division).
template <class T>
APSE_FUNC glm::vec<3, T> radial_direction(const EllipseAreas<T>& k, int q, T ct, T st, T c, T inv_1pc,
                                          T u2) noexcept {
    const T ax = k.a * ct, by = k.b * st;
    const T r2 = ax * ax + by * by;
    // v = 1 − cos theta = u2 r^2/(1 + C); sin theta / r = sqrt(v (2 − v))/r = sqrt(u2 (2 − v)/(1 + C)):
    // no division here and one square root (r itself is never needed).
    const T v = u2 * (r2 * inv_1pc);
    const T scale = std::sqrt(u2 * (T(2) - v) * inv_1pc);
    return place_in_quadrant(q, ax * scale, by * scale, (T(1) - u2) + u2 * c);
}

/// radial_direction with 1/(1 + C) computed here (one division).
template <class T>
APSE_FUNC glm::vec<3, T> radial_direction(const EllipseAreas<T>& k, int q, T ct, T st, T c, T u2) noexcept {
    return radial_direction(k, q, ct, st, c, T(1) / (T(1) + c), u2);
}

/// The orthographic eccentric anomaly (cos tau, sin tau) of the Lambert anomaly lambda given as
/// (cl, sl) = (cos lambda, sin lambda) >= 0: tan tau = kappa tan lambda, kappa =
/// cos(alpha/2)/cos(beta/2) (the equal-area image of a small ellipse, exact for caps; the radial
/// map's first guess and the tabulated map's variable). Writes (ct, st), both >= 0.
template <class T> APSE_FUNC void lambert_tau(T kappa, T cl, T sl, T& ct, T& st) noexcept {
    const T px = cl, py = kappa * sl, n = std::sqrt(px * px + py * py);
    ct = n > T(0) ? px / n : T(1);
    st = n > T(0) ? py / n : T(0);
}

/// The two terms of the inverse of radial_direction's u2: u2 = one_minus_cos / one_minus_c.
template <class T> struct RadialFraction {
    T one_minus_cos;  ///< 1 − cos theta of the direction
    T one_minus_c;    ///< 1 − C of the boundary point at its azimuth
};

/// The terms of u2 for the unit local direction (x, y, z), z > 0 (x, y of either sign), whose
/// azimuth has the first-quadrant boundary point (ct, st) with cos theta_max = c there:
/// 1 − z = (x^2 + y^2)/(1 + z) and 1 − C = r^2/(1 + C) (both without cancellation). The caller
/// divides and clamps (and chooses what a zero 1 − C gives).
template <class T>
APSE_FUNC RadialFraction<T> radial_fraction(const EllipseAreas<T>& k, T x, T y, T z, T ct, T st, T c) noexcept {
    const T ax = k.a * ct, by = k.b * st;
    const T one_minus_z = (x * x + y * y) / (T(1) + z);
    const T one_minus_c = (ax * ax + by * by) / (T(1) + c);
    return {one_minus_z, one_minus_c};
}

}  // namespace detail
}  // namespace apse
