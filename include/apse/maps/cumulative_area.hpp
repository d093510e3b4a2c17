// apse — area-preserving parameterizations for spherical ellipses.
// SPDX-License-Identifier: MIT
#pragma once

/// @file maps/cumulative_area.hpp
/// The cumulative areas the maps invert (docs/math.md §4–5), written without cancellation, with their
/// densities and the densities' slopes (for Halley steps and for the cheap Hermite increments of
/// detail/inversion.hpp).
///
/// **Radial** (§4). The boundary is parametrised by the *orthographic eccentric anomaly* tau:
/// the boundary point at tau is P(tau) = (a cos tau, b sin tau, C(tau)), a = sin alpha,
/// b = sin beta, C = cos theta_max = sqrt(cos^2 alpha cos^2 tau + cos^2 beta sin^2 tau); its
/// azimuth is tan phi = (b/a) tan tau. In tau the area density is smooth and bounded,
///     dOmega_r/dtau = (1 − cos theta_max) dphi/dtau = a b / (1 + C(tau))   in [ab/2, ab],
/// (*derived*; the paper works in phi, where the density varies by 1/(1 − cos beta)), and
/// the cancellation-free Omega_r of docs/math.md §4, rewritten in tau with the homogeneity of R_J (*derived*;
/// the gnomonic anomaly t has cos t = cos alpha cos tau / C, sin t = cos beta sin tau / C, and
/// w = sqrt(1 − m sin^2 t) = cos alpha / C), is
///     Omega_r(tau) = (a b cos^2 beta / (3 cos alpha)) sin^3 tau
///                      R_J(cos^2 tau, 1, C^2/cos^2 alpha, cos^2 tau + cos^2 beta sin^2 tau)
///                  + atan2((b/a) sin tau cos tau (tan^2 beta C^2 + m cos^2 tau) / (1 + C),
///                          cos^2 tau + (b/a)^2 C sin^2 tau),
/// a sum of two non-negative terms (checked against 30-digit quadrature to 1e-30 while deriving it;
/// in the tests against the tables of tools/gen_maps_reference.py).
///
/// **Parallel** (§5). The half-area between the slices 0 and psi (0 <= psi <= beta) is split into
/// the radial sector from the centre to the boundary point P where slice psi meets the ellipse,
/// plus the geodesic triangle (centre, P, M = (0, sin psi, cos psi)) (*derived*: the sector lies
/// between the slices because the ellipse is convex and the slice angle grows along its boundary):
///     I(psi) = 2 [Omega_r(tau_P) + E(triangle)],  E = 2 atan2(a sqrt(S) sin psi, N (1 + C + cos psi) + b cos alpha)
/// (Van Oosterom–Strackee), S = sin(beta − psi) sin(beta + psi), N^2 = b^2 cos^2 alpha + a^2 S,
/// P = (a sqrt(S), b cos alpha sin psi, b cos alpha cos psi)/N, so x_max(psi) = a sqrt(S)/N and
/// C = b cos alpha cos psi / N. Every term is non-negative: no cancellation, also where the
/// Legendre/Carlson form of docs/math.md §5 loses digits (nearly hemispherical ellipses). The parallel
/// map solves for t = tan(e/2)/tan(beta/2), e = beta − psi the distance to the end of the minor
/// axis, so sin(beta − psi) is exact near the end where the slice shrinks to a point, and sin e,
/// cos e are rational in t (no trigonometric call per iteration).

#include <cmath>

#include "../config.hpp"
#include "../detail/carlson.hpp"
#include "../spherical_ellipse.hpp"
#include "../detail/math.hpp"
#include "../detail/polar.hpp"


namespace apse {
namespace detail {

/// e.solid_angle() (one R_J), kept out of line in device code (see APSE_NOINLINE).
template <class T> APSE_NOINLINE APSE_FUNC T solid_angle_of(const SphericalEllipse<T>& e) noexcept {
    return e.solid_angle();
}

/// The radial map's state at one tau in [0, pi/2]: the boundary point and the area density.
template <class T> struct RadialPoint {
    T tau;      ///< orthographic eccentric anomaly
    T ct, st;   ///< cos tau, sin tau (both >= 0)
    T c_max;    ///< cos theta_max = C(tau)
    T density;  ///< dOmega_r/dtau = a b / (1 + C)
    T slope;    ///< d density / dtau
};

/// The parallel map's state at one slice position t = tan(e/2)/tan(beta/2) in [0, 1], e = beta −
/// psi the distance of the slice from the end of the minor axis (sin e and cos e are rational in
/// t: no trigonometric call).
template <class T> struct ParallelPoint {
    T t;                ///< tan(e/2)/tan(beta/2): 0 at the end of the minor axis, 1 on the major axis
    T sin_psi, cos_psi; ///< the slice angle psi = beta − e
    T x_max;            ///< half-width of the slice: sin of its half-arc, a sqrt(S)/N
    T cos_arc;          ///< cos of the slice's half-arc, b cos alpha / N = sqrt(1 − x_max^2)
    T ct, st, c_max;    ///< the boundary point P in tau form (for the radial sector)
    T density;          ///< d(edge area)/dt
    T slope;            ///< d density / dt
};

/// Per-ellipse constants of the cumulative areas (set-up: no transcendental call but the one R_J
/// of the solid angle, done by the caller).
template <class T> struct EllipseAreas : EllipseAxes<T> {
    using EllipseAxes<T>::a;
    using EllipseAxes<T>::b;
    using EllipseAxes<T>::ca;
    using EllipseAxes<T>::cb;
    using EllipseAxes<T>::ca2;
    using EllipseAxes<T>::cb2;
    using EllipseAxes<T>::c_max;
    T a2, b2, ab;    ///< a^2, b^2, a b
    T a2_minus_b2;   ///< a^2 − b^2 = cos^2 beta − cos^2 alpha, no cancellation
    T tb2;           ///< tan^2 beta
    T m;             ///< the elliptic parameter (tan^2 alpha − tan^2 beta)/(1 + tan^2 alpha)
    T k1;            ///< a b cos^2 beta / (3 cos alpha)
    T cb_over_ca2;   ///< (cos beta / cos alpha)^2
    T ba, ba2;       ///< b / a and its square

    static APSE_FUNC EllipseAreas make(const SphericalEllipse<T>& e) noexcept {
        EllipseAreas k;
        static_cast<EllipseAxes<T>&>(k) = EllipseAxes<T>::make(e);
        k.a2 = k.a * k.a;
        k.b2 = k.b * k.b;
        k.ab = k.a * k.b;
        k.a2_minus_b2 = (k.a - k.b) * (k.a + k.b);
        k.tb2 = e.tan_beta * e.tan_beta;
        k.m = e.m;
        if (e.is_cap()) {  // b = a, cos beta = cos alpha: the same constants without a division
            k.k1 = k.a2 * k.ca * T(1.0 / 3.0);
            k.cb_over_ca2 = k.ba = k.ba2 = T(1);
            return k;
        }
        k.k1 = k.ab * k.cb2 / (T(3) * k.ca);
        k.cb_over_ca2 = sqr(k.cb / k.ca);
        k.ba = k.a > T(0) ? k.b / k.a : T(0);
        k.ba2 = k.ba * k.ba;
        return k;
    }

    /// Omega_r at the boundary point (ct, st, C) = (cos tau, sin tau, C(tau)), tau in [0, pi/2]:
    /// the area of the part of the ellipse with azimuth in [0, phi(tau)] (file comment).
    /// Relative accuracy a few eps (R_J's and atan2's) for every ellipse.
    APSE_NOINLINE APSE_FUNC T radial_area(T ct, T st, T c) const noexcept {
        if (!(st > T(0))) return T(0);
        // R_J(ca² ct², ca², C², ca²(ct² + cb² st²)) = ca^-3 R_J(ct², 1, C²/ca², ct² + cb² st²)
        // (homogeneity; the scaled form neither underflows nor overflows for any ellipse).
        const T ct2 = ct * ct, st2 = st * st, c2 = c * c;
        const T rj = detail::rj_impl(ct2, T(1), ct2 + cb_over_ca2 * st2, ct2 + cb2 * st2);
        const T term1 = k1 * st * st2 * rj;
        // (both atan2 arguments divided by a^2, so that tiny ellipses do not underflow)
        const T term2 = std::atan2(ba * st * ct * (tb2 * c2 + m * ct2) / (T(1) + c), ct2 + ba2 * c * st2);
        return term1 + term2;
    }

    /// The radial state at tau with known cos tau, sin tau (>= 0).
    APSE_FUNC RadialPoint<T> radial_point(T tau, T ct, T st) const noexcept {
        RadialPoint<T> p;
        p.tau = tau;
        p.ct = ct;
        p.st = st;
        p.c_max = c_max(ct, st);
        const T one_plus_c = T(1) + p.c_max;
        p.density = ab / one_plus_c;
        // dC/dtau = (a^2 − b^2) sin tau cos tau / C; C >= cos alpha > 0 for a non-empty ellipse.
        const T dc = p.c_max > T(0) ? a2_minus_b2 * st * ct / p.c_max : T(0);
        p.slope = -p.density * dc / one_plus_c;
        return p;
    }

    /// The radial state at tau in [0, pi/2] (one polynomial sin/cos, both >= 0).
    APSE_FUNC RadialPoint<T> radial_point(T tau) const noexcept {
        const SinCosValues<T> sc = sin_cos_of_angle(tau);
        return radial_point(tau, sc.c, sc.s);
    }
};

/// EllipseAreas with the parallel map's constants and its slice states (file comment, §5).
template <class T> struct ParallelAreas : EllipseAreas<T> {
    using EllipseAreas<T>::a;
    using EllipseAreas<T>::b;
    using EllipseAreas<T>::ca;
    using EllipseAreas<T>::cb;
    using EllipseAreas<T>::ca2;
    using EllipseAreas<T>::radial_area;
    T k_e;    ///< 1/(1 + cos beta): sin e / b = 2 t q k_e
    T t_max;  ///< tan(beta/2) = b k_e: the slice position's scale
    T omc;    ///< 1 − cos alpha (a cap's sector area per radian of azimuth)
    bool cap; ///< the ellipse is a cap (SphericalEllipse::is_cap): sectors in closed form

    static APSE_FUNC ParallelAreas make(const SphericalEllipse<T>& e) noexcept {
        ParallelAreas k;
        static_cast<EllipseAreas<T>&>(k) = EllipseAreas<T>::make(e);
        k.k_e = T(1) / (T(1) + k.cb);
        k.t_max = k.b * k.k_e;
        k.omc = e.one_minus_cos_alpha;
        k.cap = e.is_cap();
        return k;
    }

    /// The parallel state at t = tan(e/2)/tan(beta/2) in [0, 1]. With q = 1/(1 + tan^2(e/2)):
    /// sin e = 2 t tan(beta/2) q and cos e = 1 − 2 tan^2(e/2) q; everything that scales with the
    /// ellipse is carried relative to b = sin beta (sin e / b, sin psi / b, S/b^2, N/b), so
    /// nothing underflows for tiny ellipses and no rescaling is needed (N/b = sqrt(cos^2 alpha +
    /// a^2 S/b^2), both terms at most 1).
    APSE_FUNC ParallelPoint<T> parallel_point(T t) const noexcept {
        ParallelPoint<T> p;
        p.t = t;
        const T th = t * t_max;                         // tan(e/2)
        const T q = T(1) / (T(1) + th * th);
        const T se_b = T(2) * t * q * k_e;              // sin e / b
        const T ce = T(1) - T(2) * th * th * q;         // cos e
        const T sp_b = max_of(ce - cb * se_b, T(0));    // sin psi / b = (b cos e − cos beta sin e)/b
        p.sin_psi = b * sp_b;
        p.cos_psi = cb * ce + b * b * se_b;             // cos(beta − e), positive terms
        const T sigma = max_of(se_b * (p.cos_psi + cb * sp_b), T(0));  // S/b^2, S = sin(beta − psi) sin(beta + psi)
        const T root_sigma = std::sqrt(sigma);
        const T d = std::sqrt(ca2 + a * a * sigma);     // N/b
        const T inv_d = T(1) / d;
        p.x_max = a * root_sigma * inv_d;
        p.cos_arc = ca * inv_d;
        p.ct = root_sigma * inv_d;
        p.st = ca * sp_b * inv_d;
        p.c_max = ca * p.cos_psi * inv_d;
        // In e: density 2 x_max, slope d(2 x_max)/de = 2 (a b cos alpha / N^2)^2 sin psi cos psi
        // / x_max = B/b with B = 2 a cos^2 alpha (sin psi / b) cos psi / ((N/b)^3 sqrt(S/b^2)).
        // de/dt = 2 q tan(beta/2): density_t = 2 q t_max density_e and
        // slope_t = 4 q^2 t_max (k_e B − t_max tan(e/2) density_e).
        const T density_e = T(2) * p.x_max;
        const T bb = sigma > T(0) ? T(2) * a * ca2 * sp_b * p.cos_psi / (d * d * d * root_sigma) : T(0);
        p.density = T(2) * q * t_max * density_e;
        p.slope = T(4) * q * q * t_max * (k_e * bb - t_max * th * density_e);
        return p;
    }

    /// Half-area I(psi) between the slices 0 and psi (file comment): the radial sector to the
    /// boundary point plus the geodesic triangle, doubled. Relative accuracy a few eps. On a cap
    /// the sector is (1 − cos alpha) phi_P, phi_P = atan2(sin tau, cos tau) the azimuth of the
    /// boundary point (docs/math.md §5, Caps): no elliptic integral.
    APSE_NOINLINE APSE_FUNC T parallel_half_area(const ParallelPoint<T>& p) const noexcept {
        const T sector = cap ? omc * std::atan2(p.st, p.ct) : radial_area(p.ct, p.st, p.c_max);
        // (both atan2 arguments divided by N: x_max sin psi and O(1) terms, no underflow for tiny ellipses)
        const T triangle = T(2) * std::atan2(p.x_max * p.sin_psi, (T(1) + p.c_max + p.cos_psi) + p.cos_arc);
        return T(2) * (sector + triangle);
    }
};

/// The radial quadrant area as a model for invert_area: variable tau in [0, pi/2]. The density
/// a b/(1 + C(tau)) is singular only where C = 0, at tau = ±i atanh(cos alpha / cos beta) (and
/// their images under tau → pi − tau), so rho(tau)^2 = tau^2 + atanh(.)^2, capped at 1.
template <class T> struct RadialAreaModel {
    using Point = RadialPoint<T>;
    const EllipseAreas<T>* k;
    T singular_im2;  ///< atanh(cos alpha / cos beta)^2, capped at 1
    APSE_FUNC Point point(T tau) const noexcept { return k->radial_point(tau); }
    APSE_FUNC T area(const Point& p) const noexcept { return k->radial_area(p.ct, p.st, p.c_max); }
    APSE_FUNC T variable(const Point& p) const noexcept { return p.tau; }
    APSE_FUNC T radius_sq(T tau) const noexcept { return min_of(T(1), tau * tau + singular_im2); }

    /// atanh(cos alpha / cos beta)^2 capped at 1 (the set-up's one logarithm, skipped when the
    /// ratio exceeds tanh(1), i.e. when the cap applies anyway).
    static APSE_FUNC T singular_distance_sq(const EllipseAreas<T>& k) noexcept {
        const T r = k.ca / k.cb;
        if (!(r < T(0.7615941559557649))) return T(1);
        const T at = T(0.5) * std::log((T(1) + r) / (T(1) - r));
        return min_of(T(1), at * at);
    }
};

/// The parallel map's edge area J = Omega/2 − I(psi) (the part of one half of the ellipse beyond
/// the slice psi = beta − e) as a model for invert_area: variable t = tan(e/2)/tan(beta/2) in
/// [0, 1], singular (square root) at t = 0, so rho(t) = t (the other singularities, tan(e/2) =
/// ±i and e = 2 beta, are farther from every t in the bracket).
template <class T> struct ParallelAreaModel {
    using Point = ParallelPoint<T>;
    const ParallelAreas<T>* k;
    T half;  ///< Omega / 2
    APSE_FUNC Point point(T t) const noexcept { return k->parallel_point(t); }
    APSE_FUNC T area(const Point& p) const noexcept { return half - k->parallel_half_area(p); }
    APSE_FUNC T variable(const Point& p) const noexcept { return p.t; }
    APSE_FUNC T radius_sq(T t) const noexcept { return t * t; }
};

}  // namespace detail
}  // namespace apse
