// apse — area-preserving parameterizations for spherical ellipses.
// SPDX-License-Identifier: MIT
#pragma once

/// @file sample.hpp
/// The results every apse sampler returns — one family: `DirectionSample` (direction and pdf),
/// extended by `PointSample` (plus the point on the light and its distance) — and point_on_plane,
/// which completes a direction into the point of a planar light. (What a sample cost:
/// diagnostics.hpp.)

#include "detail/glm.hpp"

#include "config.hpp"
#include "detail/math.hpp"

namespace apse {

/// One sampled direction: a world-space unit vector and its probability density **in solid
/// angle** (per steradian). `pdf == 0` means "no sample" (empty sampler, out-of-domain input):
/// the caller must then skip the sample (its contribution is zero), which keeps estimators
/// unbiased; `direction` is still a finite unit vector in that case.
template <class T> struct DirectionSample {
    static_assert(detail::is_real_type<T>(), "apse: DirectionSample<T>: T must be float or double");
    glm::vec<3, T> direction;  ///< world-space unit direction
    T pdf;                     ///< density in solid angle; 0 marks "no sample"
};

/// A DirectionSample completed with the point it reaches on the light (what a renderer needs for
/// the shadow ray): returned by the samplers that know the light's surface (DiskLight::sample,
/// SphericalRectangle::sample_point) and made from any DirectionSample of a planar light by
/// point_on_plane(). An aggregate: `PointSample<T>{{direction, pdf}, point, distance}`.
template <class T> struct PointSample : DirectionSample<T> {
    glm::vec<3, T> point;  ///< world-space point of the light along `direction` (o when pdf == 0)
    T distance;            ///< |point − o| in world units (0 when pdf == 0)
};

namespace detail {

/// A direction sampled on a spherical cap with its polar position (CapMap::sample_polar,
/// ProjectedCapSampler above the horizon): cos theta of its angle theta from the cap's centre
/// direction and the gap cos theta − cos alpha >= 0 to the rim, given without cancellation; a
/// sphere light finds the shadow ray's length from them in closed form (SphereLight).
template <class T> struct CapPolarSample {
    DirectionSample<T> sample;  ///< the direction and its pdf
    T cos_theta;                ///< cos theta
    T rim_gap;                  ///< cos theta − cos alpha
};

/// point_on_plane for the plane {p : (p − o)·plane_normal = height}: the shadow-ray data a light
/// stores per shading point (DiskLight), height = (plane_point − o)·plane_normal computed once.
template <class T>
APSE_FUNC PointSample<T> point_at_height(const DirectionSample<T>& sample, const glm::vec<3, T>& o,
                                         const glm::vec<3, T>& plane_normal, T height) noexcept {
    PointSample<T> r{{sample.direction, T(0)}, o, T(0)};
    if (!(sample.pdf > T(0))) return r;
    const T t = height / glm::dot(sample.direction, plane_normal);
    if (!(t > T(0)) || !detail::is_finite(t)) return r;
    const glm::vec<3, T> p = o + t * sample.direction;
    if (!detail::is_finite(p.x + p.y + p.z)) return r;  // beyond T's range
    r.point = p;
    r.distance = t;
    r.pdf = sample.pdf;
    return r;
}

}  // namespace detail

/// `sample` (drawn from the shading point `o`) completed with the point where the ray
/// o + t·direction, t > 0, meets the plane through `plane_point` with normal `plane_normal` (any
/// non-zero length; either orientation): point = o + t·direction, distance = t (the direction is
/// unit). "No sample" (pdf 0, point o, distance 0; the direction kept) when `sample` has pdf 0,
/// when the ray does not reach the plane (parallel to it after rounding, or pointing away), or
/// when the point overflows T.
template <class T>
APSE_FUNC PointSample<T> point_on_plane(const DirectionSample<T>& sample, const glm::vec<3, T>& o,
                                        const glm::vec<3, T>& plane_point,
                                        const glm::vec<3, T>& plane_normal) noexcept {
    return detail::point_at_height(sample, o, plane_normal, glm::dot(plane_point - o, plane_normal));
}

namespace detail {

/// Whether a light's sampler draws cosine-weighted samples: the samplers that can (CosineWeighted,
/// its cap sampler, RuntimeSampler) say so through weighted(); the maps, which have no such
/// member, never do.
template <class Sampler>
APSE_FUNC auto weighted_of(const Sampler& s, int) noexcept -> decltype(bool(s.weighted())) { return s.weighted(); }
template <class Sampler> APSE_FUNC bool weighted_of(const Sampler&, long) noexcept { return false; }

}  // namespace detail

}  // namespace apse
