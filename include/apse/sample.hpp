// apse — area-preserving parameterizations for spherical ellipses.
// SPDX-License-Identifier: MIT
#pragma once

/// @file sample.hpp
/// The results every apse sampler returns — one family: `DirectionSample` (direction and pdf),
/// extended by `PointSample` (plus the point on the light and its distance) — and the one way to
/// ask a sampler what a sample cost (`sample_with_diagnostics`).

#include <type_traits>
#include <utility>

#include "detail/glm.hpp"

#include "config.hpp"
#include "math.hpp"

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
    PointSample<T> r{{sample.direction, T(0)}, o, T(0)};
    if (!(sample.pdf > T(0))) return r;
    const T t = glm::dot(plane_point - o, plane_normal) / glm::dot(sample.direction, plane_normal);
    if (!(t > T(0)) || !detail::is_finite(t)) return r;
    const glm::vec<3, T> p = o + t * sample.direction;
    if (!detail::is_finite(p.x + p.y + p.z)) return r;  // beyond T's range
    r.point = p;
    r.distance = t;
    r.pdf = sample.pdf;
    return r;
}

/// What apse::sample_with_diagnostics reports about one sample.
struct SampleDiagnostics {
    /// Iterative steps the sample took: Newton/Halley iterations of the cumulative-area inversion
    /// (RadialMap, LdRadialMap, ParallelMap; 0 when the first guess was already exact) or
    /// table-walk steps (TabulatedMap, TabulatedLdRadialMap; 0 when the uniform guess was the
    /// bin). 0 for the samplers that do not count (`counts_iterations<S>` is false).
    int iterations;
};

namespace detail {

/// The door through which sample_with_diagnostics reaches a sampler's counting implementation, a
/// private member `sample_counted(u, int& iterations)` (samplers that count befriend this struct;
/// their public `sample(u)` calls the same implementation, the count optimised away).
struct DiagnosticsAccess {
    /// s.sample_counted(u, iterations).
    template <class S, class U>
    static APSE_FUNC auto sample(const S& s, const U& u, int& iterations) noexcept
        -> decltype(s.sample_counted(u, iterations)) {
        return s.sample_counted(u, iterations);
    }
};

/// True if S has the counting implementation DiagnosticsAccess reaches.
template <class S, class = void> struct has_sample_counted : std::false_type {};
template <class S>
struct has_sample_counted<S, std::void_t<decltype(DiagnosticsAccess::sample(
                                 std::declval<const S&>(), std::declval<const typename S::vec2&>(),
                                 std::declval<int&>()))>> : std::true_type {};

}  // namespace detail

/// True if the sampler type S reports its iterations through sample_with_diagnostics: the five
/// maps. False for the closed-form samplers (DiskAreaSampler) and those that do not count
/// (SphericalRectangle, the Gamito samplers, CosineWeighted, DiskLight): their
/// SampleDiagnostics::iterations is always 0.
template <class S> struct counts_iterations : detail::has_sample_counted<S> {};

/// counts_iterations<S>::value.
template <class S> constexpr bool counts_iterations_v = counts_iterations<S>::value;

/// `sampler.sample(u)` — the same result, bit for bit — with what the sample cost written to
/// `diagnostics` (SampleDiagnostics: iterations; 0 for samplers that do not count, see
/// counts_iterations). Works for every apse sampler; for benchmarks and tests (the samplers'
/// own `sample(u)` carries no diagnostics, so the rendering path pays nothing for them).
template <class Sampler, class T>
APSE_HOT_INLINE auto sample_with_diagnostics(const Sampler& sampler, const glm::vec<2, T>& u,
                                       SampleDiagnostics& diagnostics) noexcept {
    diagnostics.iterations = 0;
    if constexpr (counts_iterations<Sampler>::value)
        return detail::DiagnosticsAccess::sample(sampler, u, diagnostics.iterations);
    else
        return sampler.sample(u);
}

}  // namespace apse
