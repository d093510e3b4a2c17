// apse — area-preserving parameterizations for spherical ellipses.
// SPDX-License-Identifier: MIT
#pragma once

/// @file maps/cap.hpp
/// The radial maps on a spherical cap in closed form (docs/math.md §4, Caps): a cap's cumulative
/// area is linear in the azimuth, so u1 (or the concentric map's turns) is the azimuth's fraction
/// of the turn, and the polar angle has 1 − cos theta = u2 (1 − cos alpha); no inversion, no
/// table. These steps serve RadialMap and TabulatedMap (and their LD forms) when their ellipse is
/// a cap, and `CapMap`, the same samples in a sampler that holds only the cap: what SphereLight
/// uses for these maps (a sphere's ellipse is always a cap). CapMap carries no general-ellipse
/// path, so that its set-up and sample, inlined into a renderer's loop, stay a few dozen
/// instructions (the maps' general paths, compiled in the same function, cost a cap ~1.6x in
/// time: bench_samplers' sphere rows).

#include <cmath>
#include <type_traits>

#include "../config.hpp"
#include "../detail/math.hpp"
#include "../sample.hpp"
#include "../spherical_ellipse.hpp"
#include "../detail/polar.hpp"
#include "../detail/glm.hpp"
#include "tabulation_table.hpp"

namespace apse {
namespace detail {

/// cos theta and sin theta at the radial solid-angle fraction u2 in [0, 1] of a spherical cap
/// with 1 − cos alpha = omc (docs/math.md §4, Caps): 1 − cos theta = v = u2 omc and
/// sin theta = sqrt(v (2 − v)), both without cancellation (near the centre and near the horizon).
/// The polar step of every radial map on a cap (RadialMap, TabulatedMap and their LD forms).
template <class T> APSE_HOT_INLINE SinCosValues<T> cap_polar(T omc, T u2) noexcept {
    const T v = u2 * omc;
    return {std::sqrt(v * (T(2) - v)), T(1) - v};
}

/// The local direction of a cap (1 − cos alpha = omc) for the quadrant and quarter-turn fraction
/// `fold` and the radial fraction u2 in [0, 1]: azimuth phi = fraction pi/2 reflected into the
/// quadrant (a cap's cumulative area is linear in the azimuth, so this is the point the general
/// radial map gives), polar angle by cap_polar. No inversion, no table.
template <class T>
APSE_HOT_INLINE glm::vec<3, T> cap_direction(const QuadrantFold<T>& fold, T omc, T u2) noexcept {
    const SinCosValues<T> az = sin_cos_quarter_turn(fold.fraction);
    const SinCosValues<T> p = cap_polar(omc, u2);
    return place_in_quadrant(fold, p.s * az.c, p.s * az.s, p.c);
}

/// Inverse of cap_direction for the unit local direction `l`: u1 from the azimuth
/// (atan2(|y|, |x|) 2/pi, unfolded from its quadrant), u2 = (1 − cos theta)/omc with
/// 1 − cos theta = (x^2 + y^2)/(1 + z); clamped to [0, 1]^2 (a direction outside the cap, or
/// below its horizon, gives u2 = 1: the rim point at its azimuth).
template <class T> APSE_FUNC glm::vec<2, T> cap_coordinates(const glm::vec<3, T>& l, T omc) noexcept {
    const T x = std::fabs(l.x), y = std::fabs(l.y);
    const T f = clamp(std::atan2(y, x) * (T(2) / detail::pi_v<T>), T(0), T(1));
    const T u1 = clamp(unfold_quadrant_fraction(quadrant_of(l.x, l.y), f), T(0), T(1));
    const T u2 = l.z > T(0) ? clamp(((x * x + y * y) / (T(1) + l.z)) / omc, T(0), T(1)) : T(1);
    return glm::vec<2, T>(u1, u2);
}

/// 1/Omega of a cap (Omega = cap_solid_angle()) when it is finite and positive; 0 for an ellipse
/// that is not a cap (or empty) and for a density that overflows.
template <class T> APSE_HOT_INLINE T cap_density(const SphericalEllipse<T>& e) noexcept {
    if (!e.is_cap()) return T(0);
    const T inv = T(1) / e.cap_solid_angle();
    return is_finite(inv) && inv > T(0) ? inv : T(0);
}

/// The samples of RadialMap (Ld false) or LdRadialMap (Ld true) — and of TabulatedMap and
/// TabulatedLdRadialMap (Tabulated true: built with a TabulationView, which a cap does not read
/// but whose validity decides, as in those maps, whether the map can sample) — on a spherical
/// cap, bit for bit: the same steps (clamp, quadrant fold or concentric fold, cap_direction,
/// the cap's frame), the same density 1/Omega, Omega = 2 pi (1 − cos alpha), the same pdf and
/// invert. Built from any SphericalEllipse: one that is not a cap (or empty) gives an empty
/// sampler (every pdf 0), so give it project_sphere's result, which is always a cap or empty.
/// Trivially copyable.
template <class T, bool Ld, bool Tabulated> class CapMap {
public:
    using vec2 = glm::vec<2, T>;  ///< a point of the unit square
    using vec3 = glm::vec<3, T>;  ///< a 3-D vector (direction, point or normal)

    /// The sampler of `cap` (RadialMap, LdRadialMap).
    template <bool Tab = Tabulated, std::enable_if_t<!Tab, int> = 0>
    APSE_HOT_INLINE explicit CapMap(const SphericalEllipse<T>& cap) noexcept : cap_(cap) {
        inv_omega_ = cap_density(cap);
    }

    /// The sampler of `cap` with the table a tabulated map would be given (TabulatedMap,
    /// TabulatedLdRadialMap): empty, as the map, when the view is not a valid table.
    template <bool Tab = Tabulated, std::enable_if_t<Tab, int> = 0>
    APSE_HOT_INLINE CapMap(const SphericalEllipse<T>& cap, const TabulationView& table) noexcept : cap_(cap) {
        inv_omega_ = table_usable(table) ? cap_density(cap) : T(0);
    }

    /// The cap sampled (possibly empty).
    APSE_FUNC const SphericalEllipse<T>& ellipse() const noexcept { return cap_; }

    /// True if the sampler cannot sample (not a cap, or an invalid table): every pdf is then 0.
    APSE_FUNC bool empty() const noexcept { return !(inv_omega_ > T(0)); }

    /// Direction for the point u of the unit square (clamped into [0, 1]^2): the map's sample,
    /// pdf 1/Omega; a NaN coordinate or empty(): pdf 0 and the centre direction.
    APSE_HOT_INLINE DirectionSample<T> sample(const vec2& u) const noexcept { return sample_polar(u).sample; }

    /// sample(u) with the polar angle theta of its direction from the cap's centre direction:
    /// cos theta and cos theta − cos alpha = (1 − u2)(1 − cos alpha) >= 0 (u2 the radial
    /// fraction), the gap to the rim without cancellation. SphereLight places the sample on its
    /// sphere from them in closed form (detail::SphereTarget). For pdf 0: cos theta 1, gap 0.
    APSE_HOT_INLINE CapPolarSample<T> sample_polar(const vec2& u) const noexcept {
        bool ok = inv_omega_ > T(0);
        const vec2 uc = clamp_unit(u, ok);
        if (!ok) return {{cap_.z, T(0)}, T(1), T(0)};
        const T omc = cap_.one_minus_cos_alpha;
        if constexpr (Ld) {
            const ConcentricFold<T> disk = concentric_fold(uc);
            return {{cap_.to_world(cap_direction(disk.fold, omc, disk.radius2)), inv_omega_},
                    T(1) - disk.radius2 * omc, (T(1) - disk.radius2) * omc};
        } else {
            return {{cap_.to_world(cap_direction(fold_quadrant(uc.x), omc, uc.y)), inv_omega_}, T(1) - uc.y * omc,
                    (T(1) - uc.y) * omc};
        }
    }

    /// Density of sample() at the world-space direction `d` (any non-zero length), in solid
    /// angle: 1/Omega inside the cap (boundary included), 0 outside or for empty().
    APSE_FUNC T pdf(const vec3& d) const noexcept { return cap_.contains(d) ? inv_omega_ : T(0); }

    /// The point of the unit square that sample() maps to `d` (the map's invert: outside the
    /// cap, the rim point at the same azimuth; a zero, NaN or infinite direction or empty():
    /// (0, 0)).
    APSE_FUNC vec2 invert(const vec3& d) const noexcept {
        if (!(inv_omega_ > T(0))) return vec2(T(0));
        bool ok = true;
        const vec3 l = normalize_direction(cap_.to_local(d), ok);
        if (!ok) return vec2(T(0));
        const vec2 polar = cap_coordinates(l, cap_.one_minus_cos_alpha);
        if constexpr (Ld) return concentric_from_disk(std::sqrt(polar.y), polar.x);
        else return polar;
    }

private:
    SphericalEllipse<T> cap_;
    T inv_omega_;  ///< 1/Omega; 0 when empty
};

}  // namespace detail
}  // namespace apse
