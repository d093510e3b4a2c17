// apse — area-preserving parameterizations for spherical ellipses.
// SPDX-License-Identifier: MIT
#pragma once

/// @file math.hpp
/// The public scalar constants: pi, pi/2, 2 pi, machine epsilon and the quiet NaN apse returns
/// outside a function's domain. (The general helpers every apse header shares — NaN tests on the
/// bits, clamp, the bracketed root finder — live in detail/math.hpp, namespace apse::detail.)

#include "config.hpp"
#include "detail/math.hpp"

namespace apse {

/// pi in type T (rounded to nearest).
template <class T> constexpr T pi_v = detail::pi_v<T>;
/// pi / 2 in type T.
template <class T> constexpr T half_pi_v = detail::half_pi_v<T>;
/// 2 pi in type T.
template <class T> constexpr T two_pi_v = detail::two_pi_v<T>;

/// Quiet NaN of type T (the value apse functions return outside their domain).
template <class T> APSE_FUNC T quiet_nan() noexcept { return detail::quiet_nan<T>(); }

/// Machine epsilon of type T (float or double), usable in host and device code.
template <class T> APSE_FUNC constexpr T epsilon() noexcept { return detail::epsilon<T>(); }

}  // namespace apse
