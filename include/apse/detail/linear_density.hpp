// apse — area-preserving parameterizations for spherical ellipses.
// SPDX-License-Identifier: MIT
#pragma once

/// @file detail/linear_density.hpp
/// A linear density f0 + (f1 − f0) s on [0, 1] (f0, f1 >= 0): its integral up to s and the
/// inverse of that integral in closed form, without cancellation. The pieces of every
/// piecewise-linear marginal (projected_solid_angle.hpp).

#include <cmath>

#include "../config.hpp"
#include "math.hpp"

namespace apse {
namespace detail {

/// The s in [0, 1] at which the linear density f0 + (f1 − f0) s (f0, f1 >= 0, not both 0) has
/// integral x in [0, (f0 + f1)/2]: f0 s + (f1 − f0) s^2/2 = x, solved without cancellation as
/// s = 2 x / (f0 + sqrt(f0^2 + 2 (f1 − f0) x)).
template <class T> APSE_FUNC T linear_density_root(T f0, T f1, T x) noexcept {
    const T disc = max_of(f0 * f0 + T(2) * (f1 - f0) * x, T(0));
    const T den = f0 + std::sqrt(disc);
    return den > T(0) ? clamp(T(2) * x / den, T(0), T(1)) : T(0);
}

/// Integral over [0, s] of the linear density f0 + (f1 − f0) s.
template <class T> APSE_FUNC T linear_density_mass(T f0, T f1, T s) noexcept {
    return s * (f0 + T(0.5) * (f1 - f0) * s);
}

}  // namespace detail
}  // namespace apse
