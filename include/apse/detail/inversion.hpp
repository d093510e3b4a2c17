// apse — area-preserving parameterizations for spherical ellipses.
// SPDX-License-Identifier: MIT
#pragma once

/// @file detail/inversion.hpp
/// Inversion of a cumulative area A(x) = target (docs/math.md §6, §11–12), shared by every map: a
/// bracketed Halley/Newton iteration with the exact density A'(x) and its slope A''(x), in which
/// only the first value of A comes from the closed form (one R_J): each later A(x_{k+1}) is the
/// previous value plus the increment over [x_k, x_{k+1}] by the two-point Hermite (corrected
/// trapezoid) rule
///     A(x_{k+1}) − A(x_k) = d/2 (A'_k + A'_{k+1}) + d^2/12 (A''_k − A''_{k+1}) + O(d^5 A^(5)),
/// which reuses the densities the iteration needs anyway, whenever the step d is short compared
/// with the distance rho(x) from x to the nearest complex singularity of the density
/// (|d| <= c rho, c = 0.003 in double, 0.05 in float: the rule's error, about (d/rho)^4 d A'/30,
/// is then below eps; the CDF errors at the solutions are checked against quadrature in
/// tests/test_maps_reference.cpp). Longer
/// steps re-evaluate the closed form.
///
/// The model passed in supplies `point(x)` (the state at x, with fields `density` and `slope`),
/// `area(point)` (closed form), `variable(point)` (x) and `radius_sq(x)` (rho(x)^2).

#include <cmath>

#include "../config.hpp"
#include "math.hpp"

namespace apse {
namespace detail {

/// Hard cap on the iterations of invert_area (evaluations after the first). The test
/// configurations need at most a handful; the cap only bounds the work for pathological input.
constexpr int max_area_iterations = 24;

/// The stopping rule of invert_area, relative to the area of the piece being inverted:
/// |A(x) − target| <= area_tolerance * piece_area, a few eps of T (the closed form's own
/// rounding error is about that).
template <class T> APSE_FUNC constexpr T area_tolerance() noexcept { return T(4) * epsilon<T>(); }

/// Longest step (relative to the singularity distance rho) taken with the Hermite increment.
template <class T> APSE_FUNC constexpr T hermite_step_limit() noexcept {
    return sizeof(T) == sizeof(float) ? T(0.05) : T(0.003);
}

/// Result of invert_area: the state at the solution and the number of iterations (state
/// evaluations after the first guess; closed-form re-evaluations included).
template <class Point> struct AreaInversion {
    Point point;
    int iterations;
};

/// Solves model.area(x) = target for x in [lo, hi] (area increasing, area(lo) <= target <=
/// area(hi) up to rounding), starting from the state `start` (inside the bracket). Stops when
/// |A − target| <= tolerance, when the bracket has collapsed to a few ulps, or after
/// max_area_iterations; the result always lies in [lo, hi], also for NaN values (which turn
/// every step into a bisection).
template <class T, class Model>
APSE_FUNC AreaInversion<typename Model::Point> invert_area(const Model& model, T target, T lo, T hi,
                                                           const typename Model::Point& start,
                                                           T tolerance) noexcept {
    using Point = typename Model::Point;
    Point p = start;
    T x = model.variable(p);
    T area = T(0);
    bool closed_form = true;  // evaluate the closed form at the top of the loop (one call site)
    const T limit2 = sqr(hermite_step_limit<T>());
    // 1/A' at the start (computed while the closed form is evaluated): the Halley step's unit
    T scale = T(1) / p.density;
    if (!(scale > T(0) && is_finite(scale))) scale = T(1);
    int it = 0;
    for (;;) {
        if (closed_form) area = model.area(p);
        const T g = area - target;
        if (!(std::fabs(g) > tolerance)) break;
        if (g < T(0)) lo = x; else hi = x;
        if (it >= max_area_iterations || !(hi - lo > T(4) * epsilon<T>() * max_of(std::fabs(lo), std::fabs(hi))))
            break;
        // Halley step (cubic convergence) n/(1 + r), n = −g/A', r = n A''/(2A'), written with one
        // division, −2 g A'/(2 A'^2 − g A''), and Newton's −g/A' when |r| >= 1/2 (|g A''| >= A'^2);
        // g, A' and A'' in units of the first density, so that no product underflows.
        const T gs = g * scale, ds = p.density * scale, gss = gs * (p.slope * scale), d2 = ds * ds;
        const bool halley = std::fabs(gss) < d2;
        T next = x - (halley ? T(2) * gs * ds : gs) / (halley ? T(2) * d2 - gss : ds);
        if (!(next > lo && next < hi)) next = T(0.5) * (lo + hi);
        const Point q = model.point(next);
        const T d = next - x;
        closed_form = !(d * d <= limit2 * min_of(model.radius_sq(x), model.radius_sq(next)));
        if (!closed_form) area += T(0.5) * d * (p.density + q.density) + d * d / T(12) * (p.slope - q.slope);
        p = q;
        x = next;
        ++it;
    }
    return {p, it};
}

}  // namespace detail
}  // namespace apse
