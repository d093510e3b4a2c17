// apse — area-preserving parameterizations for spherical ellipses.
// SPDX-License-Identifier: MIT
#pragma once

/// @file maps/parallel.hpp
/// `ParallelMap<T>`: the paper's parallel map (authors' code: `cylindrical`; Ureña's
/// construction), docs/math.md §5 — u1 picks a slice (a great circle through ±x, the major axis) by
/// inverting the cumulative area, u2 a point uniformly along the slice (Archimedes). Continuous
/// on the closed square; the edges u1 = 0 and u1 = 1 collapse to the two ends of the minor axis.

#include <cmath>

#include "../config.hpp"
#include "../detail/math.hpp"
#include "../sample.hpp"
#include "../spherical_ellipse.hpp"
#include "../detail/glm.hpp"
#include "../detail/inversion.hpp"
#include "../detail/polar.hpp"
#include "cumulative_area.hpp"

namespace apse {
namespace detail {

/// First guess for the parallel map's slice position t = tan(e/2)/tan(beta/2), e = beta − psi
/// the distance from the end of the minor axis, for the edge fraction g of a half. e is a blend,
/// weighted by the ellipse's shape w in [0, 1], of the planar-ellipse slice (the half-area of an
/// ellipse in the (psi, x) cylindrical equal-area plane, 1 − sin(theta) with (2 theta + sin 2
/// theta)/pi = 1 − g, by a fitted polynomial in s = (6 pi g)^(1/3), max error 1.1e-5; s by
/// cube_root_approx, with g kept above 2^-90) and the rectangle slice (e = g beta: the limit of
/// very wide ellipses whose slices keep their full width). Then t by the Pade approximant
/// tan h ~ h (15 − h^2)/(15 − 6 h^2) of both tangents, h = e/2 and beta/2 (`pade` = (15 − 6
/// (beta/2)^2)/(15 − (beta/2)^2), from the map's set-up): relative error below 3e-4 (beta =
/// pi/2), far less for smaller ellipses (6.4e-4 (beta/2)^6).
template <class T> APSE_FUNC T parallel_guess(T g, T beta, T w, T pade) noexcept {
    const T s = cube_root_approx(T(6) * detail::pi_v<T> * max_of(g, T(0x1p-90)));
    const T s2 = s * s;
    const T planar = s2 * (T(0.12503731796729795) +
                           s2 * (T(0.0014906081882330561) +
                                 s2 * (T(0.00010432809161716576) +
                                       s2 * (T(-7.249709538220279e-6) + s2 * T(1.1660217507228629e-6)))));
    const T f = detail::clamp(w * planar + (T(1) - w) * g, T(0), T(1));  // e / beta
    const T h = T(0.5) * beta * f, h2 = h * h;
    return min_of(f * pade * (T(15) - h2) / (T(15) - T(6) * h2), T(1));
}

}  // namespace detail

/// Parallel area-preserving map of the unit square onto a spherical ellipse (docs/math.md §5).
///
/// Construction precomputes the solid angle (one R_J). Each sample folds u1 onto one half of the
/// ellipse, solves the cumulative-area equation for the slice position t = tan(e/2)/tan(beta/2)
/// in [0, 1], e = beta − psi the distance of the slice from the end of the minor axis
/// (cancellation-free sector + triangle form, maps/cumulative_area.hpp; sin e and cos e rational
/// in t) by bracketed Halley/Newton with the exact density, from a shape-blended first guess,
/// one closed-form evaluation and cheap Hermite increments after it (detail/inversion.hpp);
/// relative stopping rule 4 eps of Omega/2. Accuracy (measured, docs/maps.md): cumulative-area
/// error <= 1e-14 (double) / 1e-6 (float) relative to Omega/2. On a spherical cap
/// (SphericalEllipse::is_cap()) the solid angle is 2 pi (1 − cos alpha) and the cumulative area
/// has no elliptic integral (docs/math.md §5, Caps); the inversion is the same bracketed one.
/// Trivially copyable.
template <class T> class ParallelMap {
    static_assert(detail::is_real_type<T>(), "apse: ParallelMap<T>: T must be float or double");

public:
    using vec2 = glm::vec<2, T>;  ///< a point of the unit square
    using vec3 = glm::vec<3, T>;  ///< a 3-D vector (direction, point or normal)
    /// What SphereLight holds for this map: the map itself (on a cap its cumulative area has no
    /// closed-form inverse: it keeps its bracketed steps).
    using CapSampler = ParallelMap;

    /// Builds the map for `ellipse` (empty allowed: every sample then has pdf 0).
    APSE_FUNC explicit ParallelMap(const SphericalEllipse<T>& ellipse) noexcept
        : ellipse_(ellipse), areas_(detail::ParallelAreas<T>::make(ellipse)), beta_(ellipse.beta()) {
        omega_ = areas_.cap ? ellipse.cap_solid_angle() : detail::solid_angle_of(ellipse);
        valid_ = !ellipse.empty() && omega_ > T(0) && detail::is_finite(omega_);
        inv_omega_ = valid_ ? T(1) / omega_ : T(0);
        half_ = T(0.5) * omega_;
        // Shape weight: the half-area relative to the (psi, x) rectangle 2 beta sin(alpha) is
        // pi/4 for a small ellipse (w = 1) and tends to 1 for wide nearly hemispherical ones (w = 0).
        const T rect = T(2) * beta_ * areas_.a;
        const T fill = rect > T(0) ? half_ / rect : T(1);
        blend_ = detail::clamp((T(1) - fill) / (T(1) - detail::pi_v<T> / T(4)), T(0), T(1));
        const T hb2 = T(0.25) * beta_ * beta_;
        pade_ = (T(15) - T(6) * hb2) / (T(15) - hb2);
    }

    /// The ellipse this map samples.
    APSE_FUNC const SphericalEllipse<T>& ellipse() const noexcept { return ellipse_; }

    /// Solid angle Omega of the ellipse (steradians); 0 when empty.
    APSE_FUNC T solid_angle() const noexcept { return valid_ ? omega_ : T(0); }

    /// True if the map cannot sample (empty ellipse, or a solid angle that is 0 or not finite in
    /// T): every sample and pdf is then 0.
    APSE_FUNC bool empty() const noexcept { return !valid_; }

    /// Direction for the point u of the unit square, docs/math.md §5: world-space unit vector inside
    /// the ellipse, pdf = 1/Omega (solid angle). u is clamped into [0, 1]^2; a NaN coordinate or
    /// an empty map gives pdf 0 (and the centre direction). The inversion iterations:
    /// apse::sample_with_diagnostics.
    APSE_FUNC DirectionSample<T> sample(const vec2& u) const noexcept {
        int iterations = 0;
        return sample_counted(u, iterations);
    }

    /// The point of the unit square that sample() maps to the world-space direction `d` (any
    /// non-zero length). Exact inverse inside the ellipse (to ~1e-12 in double away from the two
    /// ends of the minor axis, where a slice degenerates to a point and u2 is ambiguous). A
    /// direction outside the ellipse gives the nearest slice's point (clamped to [0, 1]^2); a
    /// zero, NaN or infinite direction, or an empty ellipse, gives (0, 0).
    APSE_FUNC vec2 invert(const vec3& d) const noexcept {
        if (!valid_) return vec2(T(0));
        bool ok = true;
        const vec3 l = detail::normalize_direction(ellipse_.to_local(d), ok);
        if (!ok) return vec2(T(0));
        const T side = l.y < T(0) ? T(-1) : T(1);
        // the slice angle psi of l, (sin psi, cos psi) = (|y|, z)/|(y, z)|, and the slice position
        // t = tan(e/2)/tan(beta/2) of e = beta − psi, tan(e/2) = sin e/(1 + cos e); 0 beyond the
        // end of the minor axis (psi > beta)
        const T ryz = std::sqrt(l.y * l.y + l.z * l.z);
        const T sp = ryz > T(0) ? std::fabs(l.y) / ryz : T(0), cp = ryz > T(0) ? l.z / ryz : T(1);
        const T se = areas_.b * cp - areas_.cb * sp, ce = areas_.cb * cp + areas_.b * sp;
        const T t = se > T(0) ? detail::min_of(se / ((T(1) + ce) * areas_.t_max), T(1)) : T(0);
        const detail::ParallelPoint<T> p = areas_.parallel_point(t);
        const T g = detail::clamp((half_ - areas_.parallel_half_area(p)) / half_, T(0), T(1));
        T u2 = T(0.5);
        if (p.x_max > T(0)) {
            const T ax = std::fabs(l.x);
            if (ax <= T(0.5)) {
                u2 = T(0.5) * (l.x / p.x_max + T(1));
            } else {
                // x_max − |x| = ((y^2 + z^2) − (1 − x_max^2)) / (x_max + |x|): accurate near x ~ 1
                const T gap = (l.y * l.y + l.z * l.z - p.cos_arc * p.cos_arc) / (p.x_max + ax);
                const T h = T(0.5) * gap / p.x_max;
                u2 = l.x > T(0) ? T(1) - h : h;
            }
            u2 = detail::clamp(u2, T(0), T(1));
        }
        return vec2(detail::clamp(detail::unfold_half_fraction(side, g), T(0), T(1)), u2);
    }

    /// Density of sample() at the world-space direction `d`, in solid angle: 1/Omega inside the
    /// ellipse (boundary included), 0 outside, for an empty ellipse or a zero/NaN direction.
    APSE_FUNC T pdf(const vec3& d) const noexcept { return ellipse_.contains(d) ? inv_omega_ : T(0); }

    // The building blocks sample_with_diagnostics (diagnostics.hpp) and the tests call.

    /// Solves the edge-area equation J(t) = g Omega/2 (g in [0, 1]: the fraction of a half
    /// beyond the slice) for the slice state, with the inversion iterations in `iterations`.
    APSE_FUNC detail::ParallelPoint<T> solve_half(T g, int& iterations) const noexcept {
        iterations = 0;
        if (!(g > T(0))) return areas_.parallel_point(T(0));
        if (!(g < T(1))) return areas_.parallel_point(T(1));
        const detail::ParallelAreaModel<T> model{&areas_, half_};
        const auto r = detail::invert_area(model, g * half_, T(0), T(1),
                                           guess_half(g),
                                           detail::area_tolerance<T>() * half_);
        iterations = r.iterations;
        return r.point;
    }

    /// The first guess of solve_half for the edge fraction g in [0, 1] (the shape-blended
    /// slice, detail parallel_guess).
    APSE_FUNC detail::ParallelPoint<T> guess_half(T g) const noexcept {
        return areas_.parallel_point(detail::parallel_guess(detail::clamp(g, T(0), T(1)), beta_, blend_, pade_));
    }

    /// Half-area I(psi) between the slices 0 and psi in [0, beta] (docs/math.md §5 I(psi),
    /// cancellation-free). Omega_p(psi) = Omega/2 ± I(|psi|).
    APSE_FUNC T half_area(T psi) const noexcept {
        const T e = detail::clamp(beta_ - psi, T(0), beta_);
        return areas_.parallel_half_area(areas_.parallel_point(detail::min_of(std::tan(T(0.5) * e) / areas_.t_max, T(1))));
    }

    /// sample(u), counting the inversion iterations in `iterations` (detail/inversion.hpp).
    APSE_HOT_INLINE DirectionSample<T> sample_counted(const vec2& u, int& iterations) const noexcept {
        iterations = 0;
        bool ok = valid_;
        const vec2 uc = detail::clamp_unit(u, ok);
        if (!ok) return {ellipse_.z, T(0)};
        const T u1 = uc.x, u2 = uc.y;
        const detail::HalfFold<T> fold = detail::fold_half(u1);
        const detail::ParallelPoint<T> p = solve_half(fold.fraction, iterations);
        const T x = (T(2) * u2 - T(1)) * p.x_max;
        // 1 − x^2 = (1 − x_max^2) + 4 u2 (1 − u2) x_max^2 with 1 − x_max^2 = (b cos alpha / N)^2: no
        // cancellation where the slice reaches the horizon (x_max ~ 1 in nearly hemispherical ellipses).
        const T rxy = std::sqrt(p.cos_arc * p.cos_arc + T(4) * u2 * (T(1) - u2) * p.x_max * p.x_max);
        const vec3 local(x, fold.side * rxy * p.sin_psi, rxy * p.cos_psi);
        return {ellipse_.to_world(local), inv_omega_};
    }

private:
    SphericalEllipse<T> ellipse_;
    detail::ParallelAreas<T> areas_;
    T beta_;  ///< the minor semi-arc (one atan, at set-up)
    T omega_, inv_omega_, half_, blend_;
    T pade_;  ///< (15 − 6 h^2)/(15 − h^2), h = beta/2: parallel_guess's 1/tan(beta/2), times h
    bool valid_;
};

}  // namespace apse
