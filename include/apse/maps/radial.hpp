// apse — area-preserving parameterizations for spherical ellipses.
// SPDX-License-Identifier: MIT
#pragma once

/// @file maps/radial.hpp
/// `RadialMap<T>`: the paper's radial map (authors' code: `polar`), docs/math.md §4 — u1 picks the
/// azimuth by inverting the cumulative area, u2 the polar angle uniformly in solid angle along
/// the wedge. Area-preserving; continuous on the open square except that u1 = 0 and u1 = 1 meet
/// on the major axis (+x) and the whole edge u2 = 0 maps to the centre.
/// The polar step it shares with TabulatedMap: detail/polar.hpp; the cumulative area u1
/// inverts: cumulative_area.hpp.

#include <cmath>

#include "../config.hpp"
#include "../detail/math.hpp"
#include "../sample.hpp"
#include "../spherical_ellipse.hpp"
#include "../detail/glm.hpp"
#include "../detail/inversion.hpp"
#include "../detail/polar.hpp"
#include "cap.hpp"
#include "cumulative_area.hpp"

namespace apse {
namespace detail {

/// Radial area-preserving map of the unit square onto a spherical ellipse (docs/math.md §4).
///
/// Construction precomputes the solid angle (one R_J) and the constants of the cumulative area.
/// A spherical cap (SphericalEllipse::is_cap(), e.g. from project_sphere) is sampled in closed
/// form instead (docs/math.md §4, Caps): Omega = 2 pi (1 − cos alpha), azimuth linear in u1,
/// 1 − cos theta = u2 (1 − cos alpha); the same directions as the general path to rounding, no
/// iteration (0 iterations reported).
/// Each sample folds u1 onto a quadrant, solves Omega_r(tau) = f Omega/4 for the orthographic
/// eccentric anomaly tau (maps/cumulative_area.hpp) by bracketed Halley/Newton with the exact
/// density, from the Lambert-equal-area first guess tan tau = (cos(alpha/2)/cos(beta/2)) tan(f pi/2)
/// (exact for caps and for small ellipses), with one closed-form evaluation and cheap Hermite
/// increments after it (detail/inversion.hpp); relative stopping rule 4 eps of the quadrant area.
/// Accuracy (measured, docs/maps.md): cumulative-area error <= 1e-14 (double) / 1e-6 (float)
/// relative to Omega/4; directions to a few ulps.
/// Trivially copyable (pass it to kernels by value).
template <class T> class RadialMap {
    static_assert(detail::is_real_type<T>(), "apse: RadialMap<T>: T must be float or double");

public:
    using vec2 = glm::vec<2, T>;  ///< a point of the unit square
    using vec3 = glm::vec<3, T>;  ///< a 3-D vector (direction, point or normal)
    /// What SphereLight holds for this map: the same samples on a cap, without the
    /// general-ellipse path (maps/cap.hpp).
    using CapSampler = detail::CapMap<T, false, false>;

    /// Builds the map for `ellipse` (any SphericalEllipse, empty included: then every sample has
    /// pdf 0).
    APSE_HOT_INLINE explicit RadialMap(const SphericalEllipse<T>& ellipse) noexcept
        : ellipse_(ellipse), areas_(detail::EllipseAreas<T>::make(ellipse)), cap_(ellipse.is_cap()) {
        omega_ = cap_ ? ellipse.cap_solid_angle() : detail::solid_angle_of(ellipse);
        valid_ = !ellipse.empty() && omega_ > T(0) && detail::is_finite(omega_);
        inv_omega_ = valid_ ? T(1) / omega_ : T(0);
        quarter_ = T(0.25) * omega_;
        // Lambert guess: the equal-area image of a small ellipse has semi-axes 2 sin(alpha/2),
        // 2 sin(beta/2); in tau this is tan tau = kappa tan(f pi/2), kappa = cos(alpha/2)/cos(beta/2).
        // (a cap: kappa = 1 and no singularity near the bracket, without a division)
        kappa_ = cap_ ? T(1) : std::sqrt((T(1) + areas_.ca) / (T(1) + areas_.cb));
        singular_im2_ = cap_ ? T(1) : detail::RadialAreaModel<T>::singular_distance_sq(areas_);
    }

    /// The ellipse this map samples.
    APSE_FUNC const SphericalEllipse<T>& ellipse() const noexcept { return ellipse_; }

    /// Solid angle Omega of the ellipse (steradians); 0 when empty.
    APSE_FUNC T solid_angle() const noexcept { return valid_ ? omega_ : T(0); }

    /// True if the map cannot sample (empty ellipse, or a solid angle that is 0 or not finite in
    /// T): every sample and pdf is then 0.
    APSE_FUNC bool empty() const noexcept { return !valid_; }

    /// Direction for the point u of the unit square, docs/math.md §4: world-space unit vector inside
    /// the ellipse, pdf = 1/Omega (solid angle). u is clamped into [0, 1]^2 (u = 1 is the
    /// square's closed edge); a NaN coordinate or an empty map gives pdf 0 (and the centre
    /// direction). The inversion iterations: apse::sample_with_diagnostics.
    APSE_FUNC DirectionSample<T> sample(const vec2& u) const noexcept {
        int iterations = 0;
        return sample_counted(u, iterations);
    }

    /// The point of the unit square that sample() maps to the world-space direction `d` (any
    /// non-zero length). Exact inverse inside the ellipse (to ~1e-12 in double away from the
    /// centre and the +x seam, where u1 is ambiguous: 0 or 1). A direction outside the ellipse
    /// gives the point whose image is the boundary point at the same azimuth (u2 = 1); a zero,
    /// NaN or infinite direction, or an empty ellipse, gives (0, 0).
    APSE_FUNC vec2 invert(const vec3& d) const noexcept {
        if (!valid_) return vec2(T(0));
        bool ok = true;
        const vec3 l = detail::normalize_direction(ellipse_.to_local(d), ok);
        return ok ? local_coordinates(l) : vec2(T(0));
    }

    /// Density of sample() at the world-space direction `d`, in solid angle: 1/Omega inside the
    /// ellipse (boundary included), 0 outside, for an empty ellipse or a zero/NaN direction.
    APSE_FUNC T pdf(const vec3& d) const noexcept { return ellipse_.contains(d) ? inv_omega_ : T(0); }

    // The building blocks the LD-radial composition (maps/ld_radial.hpp), the cosine weighting
    // and the tests call.

    /// The world-space sample for the quadrant and quadrant-area fraction `fold` and the radial
    /// fraction u2 in [0, 1] (not checked; the map is valid), with the inversion iterations in
    /// `iterations`: sample() after fold_quadrant(u1), LdRadialMap's after the concentric map.
    APSE_HOT_INLINE DirectionSample<T> sample_folded(const detail::QuadrantFold<T>& fold, T u2,
                                               int& iterations) const noexcept {
        if (cap_) {
            iterations = 0;
            return {ellipse_.to_world(detail::cap_direction(fold, ellipse_.one_minus_cos_alpha, u2)), inv_omega_};
        }
        const detail::RadialPoint<T> p = solve_quadrant(fold.fraction, iterations);
        return {ellipse_.to_world(detail::radial_direction(areas_, fold, p.ct, p.st, p.c_max, u2)), inv_omega_};
    }

    /// (u1, u2) of the unit local direction `l` (clamped to [0, 1]^2): invert() and LdRadialMap's
    /// inverse (maps/ld_radial.hpp, ).
    APSE_FUNC vec2 local_coordinates(const vec3& l) const noexcept {
        if (cap_) return detail::cap_coordinates(l, ellipse_.one_minus_cos_alpha);
        const int q = detail::quadrant_of(l.x, l.y);
        const T x = std::fabs(l.x), y = std::fabs(l.y);
        // tan tau = (a/b) tan phi: (cos tau, sin tau) ∝ (b x, a y) ∝ ((b/a) x, y).
        const T bx = areas_.ba * x, ay = y;
        const T n = std::sqrt(bx * bx + ay * ay);
        const T ct = n > T(0) ? bx / n : T(1), st = n > T(0) ? ay / n : T(0);
        const T c = areas_.c_max(ct, st);
        const T f = detail::clamp(areas_.radial_area(ct, st, c) / quarter_, T(0), T(1));
        const T u1 = detail::unfold_quadrant_fraction(q, f);
        T u2 = T(1);
        if (l.z > T(0)) {
            const detail::RadialFraction<T> r = detail::radial_fraction(areas_, x, y, l.z, ct, st, c);
            u2 = detail::clamp(r.one_minus_cos / r.one_minus_c, T(0), T(1));
        }
        return vec2(detail::clamp(u1, T(0), T(1)), u2);
    }

    /// Solves the quadrant equation Omega_r(tau) = f Omega/4 (f in [0, 1]) for the boundary
    /// state at tau (maps/cumulative_area.hpp); `iterations` as in sample().
    APSE_FUNC detail::RadialPoint<T> solve_quadrant(T f, int& iterations) const noexcept {
        iterations = 0;
        if (!(f > T(0))) return areas_.radial_point(T(0), T(1), T(0));
        if (!(f < T(1))) return areas_.radial_point(detail::half_pi_v<T>, T(0), T(1));
        const detail::RadialPoint<T> start = guess_quadrant(f);
        const detail::RadialAreaModel<T> model{&areas_, singular_im2_};
        const auto r = detail::invert_area(model, f * quarter_, T(0), detail::half_pi_v<T>, start,
                                           detail::area_tolerance<T>() * quarter_);
        iterations = r.iterations;
        return r.point;
    }

    /// The first guess of solve_quadrant for the fraction f in [0, 1] of the quadrant's area:
    /// the Lambert-equal-area azimuth tan tau = kappa tan(f pi/2) (exact for caps and small
    /// ellipses; one polynomial sin/cos and one polynomial atan2). The inversion steps from tau,
    /// and the area it checks is that of (cos tau, sin tau): tau must match them to within the
    /// stopping rule. In double that takes angle_of (a few ulps; Hastings' 2e-8 alone would cost
    /// a second step); in float Hastings' atan alone is enough (2e-8 moves the area by ~3 % of
    /// the stopping rule's 4 eps for an average density) and much shorter.
    APSE_FUNC detail::RadialPoint<T> guess_quadrant(T f) const noexcept {
        const detail::SinCosValues<T> h = detail::sin_cos_quarter_turn(detail::clamp(f, T(0), T(1)));
        T ct, st;
        detail::lambert_tau(kappa_, h.c, h.s, ct, st);
        const T tau = sizeof(T) == sizeof(float) ? detail::angle_approx(st, ct) : detail::angle_of(st, ct);
        return areas_.radial_point(tau, ct, st);
    }

    /// Cumulative area of the first quadrant up to the azimuth phi in [0, pi/2] (docs/math.md §4
    /// Omega_r(phi), cancellation-free; for tests, ).
    APSE_FUNC T quadrant_area(T phi) const noexcept {
        const T c = std::cos(phi), s = std::sin(phi);
        const T bx = areas_.ba * detail::max_of(c, T(0)), ay = detail::max_of(s, T(0));
        const T n = std::sqrt(bx * bx + ay * ay);
        if (!(n > T(0))) return T(0);
        const T ct = bx / n, st = ay / n;
        return areas_.radial_area(ct, st, areas_.c_max(ct, st));
    }

    /// sample(u), counting the inversion iterations in `iterations` (0 for the exact first guess;
    /// detail/inversion.hpp).
    APSE_FUNC DirectionSample<T> sample_counted(const vec2& u, int& iterations) const noexcept {
        iterations = 0;
        bool ok = valid_;
        const vec2 uc = detail::clamp_unit(u, ok);
        if (!ok) return {ellipse_.z, T(0)};
        return sample_folded(detail::fold_quadrant(uc.x), uc.y, iterations);
    }

private:
    SphericalEllipse<T> ellipse_;
    detail::EllipseAreas<T> areas_;
    T omega_, inv_omega_, quarter_, kappa_, singular_im2_;
    bool cap_;  ///< the ellipse is a cap: sampled and inverted in closed form
    bool valid_;
};

}  // namespace detail
}  // namespace apse
