// apse — area-preserving parameterizations for spherical ellipses.
// SPDX-License-Identifier: MIT
#pragma once

/// @file sphere_light.hpp
/// A sphere light in one call: the cap the sphere subtends at a shading point (project_sphere,
/// docs/math.md §2b), sampled with the sampler of your choice — any map, or CosineWeighted<map>
/// for directions ∝ the receiver's clamped cosine — with the direction, the point of the sphere
/// it reaches, its distance (the shadow ray) and the pdf in solid angle; plus the pdf of any
/// direction for MIS, from the light or statelessly (sphere_light_pdf).
///
///     // per shading point o, for each of n stratified points u:
///     apse::SphereLight<apse::LdRadialMap<float>> light(o, center, radius);
///     auto s = light.sample(u);              // s.pdf == 0: no sample (skip it)
///     if (s.pdf > 0 && visible(o, s.point)) L += Le * f(s.direction) / s.pdf;
///     float p_light = light.pdf(w);          // MIS: the density of a BSDF-sampled direction w
///     // cosine-weighted for the receiver normal n_r: exactly ∝ max(0, n_r·ω) on the cap
///     apse::SphereLight<apse::CosineWeighted<apse::LdRadialMap<float>>> lit(o, center, radius, n_r);
///     // tabulated maps take the table: SphereLight<TabulatedLdRadialMap<float>>(o, center, radius, table)
///
/// Every map samples a cap by closed forms (no elliptic integral, no table look-up), so the
/// choice of map only decides how the square is distorted; the cosine-weighted samplers draw
/// exactly ∝ max(0, n_r·ω) over the cap (ProjectedCapSampler).

#include <cmath>
#include <type_traits>
#include <utility>

#include "config.hpp"
#include "detail/math.hpp"
#include "projection.hpp"
#include "sample.hpp"
#include "spherical_ellipse.hpp"
#include "detail/glm.hpp"
#include "detail/type_identity.hpp"
#include "detail/vector.hpp"

namespace apse {

namespace detail {

/// Distance t > 0 along the unit direction w from o to the nearest point of the sphere of
/// radius r (inv_r = 1/r) whose centre is at p from o, |p| = dist > r (given), for a direction
/// inside the cap the sphere subtends: the root of t² − 2 b t + (dist − r)(dist + r) = 0
/// nearer to o (b = w·p), in the form t = (dist − r) ((dist + r) / (b + sqrt(disc))) that does
/// not cancel when o is close to the surface (t ≪ dist). The discriminant disc = r² − |q|², q =
/// p − b w the perpendicular offset, is taken as r sqrt((1 − s)(1 + s)), s = |q / r| (b² − |p|² + r²
/// would cancel for far spheres; q / r keeps the squares in range at any scale), and as 0 for
/// directions that rounding puts just outside the cap (the tangent point). Returns 0 when w
/// points away from the sphere (b <= 0) or the result is not finite.
template <class T>
APSE_HOT_INLINE T sphere_hit_distance(const glm::vec<3, T>& p, T r, T inv_r, T dist, const glm::vec<3, T>& w) noexcept {
    const T b = glm::dot(w, p);
    if (!(b > T(0))) return T(0);
    const glm::vec<3, T> q = (p - b * w) * inv_r;
    const T s = std::sqrt(glm::dot(q, q));
    const T root = s < T(1) ? r * std::sqrt((T(1) - s) * (T(1) + s)) : T(0);
    const T t = (dist - r) * ((dist + r) / (b + root));
    return t > T(0) && is_finite(t) ? t : T(0);
}

/// The distance t from a shading point to the nearest point of a sphere along a direction at
/// angle theta from the sphere's centre direction, for a direction inside the cap the sphere
/// subtends (half-angle alpha, |center − o| = dist): t = dist cos theta − dist sqrt(sin^2 alpha −
/// sin^2 theta), written t = dist cos^2 alpha / (cos theta + sqrt((cos theta − cos alpha)
/// (cos theta + cos alpha))) so that nothing cancels (near the centre direction, near the rim,
/// for far spheres and near ones): dist_cos2 = dist cos^2 alpha and rim_gap = cos theta −
/// cos alpha >= 0 are given without cancellation (CapMap::sample_polar). The rim gives
/// dist cos alpha (the tangent's length), the centre dist − radius.
template <class T> APSE_HOT_INLINE T sphere_distance_at_polar(T dist_cos2, T cos_alpha, T cos_theta, T rim_gap) noexcept {
    return dist_cos2 / (cos_theta + std::sqrt(rim_gap * (cos_theta + cos_alpha)));
}

/// True if the sampler S gives sample_polar(u) (CapMap: the radial maps on a cap).
template <class S, class = void> struct samples_polar : std::false_type {};
template <class S>
struct samples_polar<S, std::void_t<decltype(std::declval<const S&>().sample_polar(std::declval<const typename S::vec2&>()))>>
    : std::true_type {};

/// True if the sampler S places its samples on a sphere itself: S::sample_on_sphere(u, target)
/// (RuntimeSampler's cap sampler: the chosen sampler's way).
template <class S, class Target, class = void> struct samples_on_sphere : std::false_type {};
template <class S, class Target>
struct samples_on_sphere<S, Target,
                         std::void_t<decltype(std::declval<const S&>().sample_on_sphere(
                             std::declval<const typename S::vec2&>(), std::declval<const Target&>()))>>
    : std::true_type {};

/// The sphere of a SphereLight seen from its shading point o (outside it): places a sampler's
/// directions on it, with the nearest point along each and its distance (the shadow ray).
template <class T> struct SphereTarget {
    glm::vec<3, T> o;       ///< the shading point
    glm::vec<3, T> center;  ///< the sphere's centre
    T radius;               ///< its radius, > 0
    T dist;                 ///< |center − o| > radius
    T dist_cos2;            ///< dist cos^2 alpha (alpha the cap's half-angle)

    /// sampler.sample(u) (a sampler of the cap this sphere subtends at o) with the nearest point
    /// of the sphere along the direction and its distance: in closed form from the sample's polar
    /// angle for the samplers that give it (sample_polar, or sample_on_sphere where only some of
    /// their samples have it), from the direction for the others. pdf 0 ("no sample", point o,
    /// distance 0) where the sampler gives pdf 0 or the point overflows T.
    template <class S> APSE_HOT_INLINE PointSample<T> sample(const S& sampler, const glm::vec<2, T>& u) const noexcept {
        if constexpr (samples_on_sphere<S, SphereTarget>::value) return sampler.sample_on_sphere(u, *this);
        else if constexpr (samples_polar<S>::value) return place_polar(sampler.sample_polar(u), sampler.ellipse().cos_alpha);
        else return place_by_ray(sampler.sample(u));
    }

    /// The sample s of the sphere's cap (half-angle alpha) placed on the sphere from its polar
    /// angle: distance by sphere_distance_at_polar.
    APSE_HOT_INLINE PointSample<T> place_polar(const CapPolarSample<T>& s, T cos_alpha) const noexcept {
        return place(s.sample, sphere_distance_at_polar(dist_cos2, cos_alpha, s.cos_theta, s.rim_gap));
    }

    /// The sample s placed on the sphere by intersecting its ray (sphere_hit_distance).
    APSE_HOT_INLINE PointSample<T> place_by_ray(const DirectionSample<T>& s) const noexcept {
        return place(s, s.pdf > T(0) ? sphere_hit_distance(center - o, radius, T(1) / radius, dist, s.direction) : T(0));
    }

    /// The sample s placed at distance t along its direction (pdf 0 kept, and given for t <= 0 or
    /// a point that overflows T).
    APSE_HOT_INLINE PointSample<T> place(const DirectionSample<T>& s, T t) const noexcept {
        PointSample<T> r{{s.direction, T(0)}, o, T(0)};
        if (!(s.pdf > T(0))) return r;
        const glm::vec<3, T> p = o + t * s.direction;
        if (!(t > T(0)) || !is_finite(p.x + p.y + p.z)) return r;
        r.pdf = s.pdf;
        r.point = p;
        r.distance = t;
        return r;
    }
};

}  // namespace detail

/// A sphere light (centre, radius) seen from one shading point o, ready to sample with
/// `Sampler`: any map (LdRadialMap, TabulatedLdRadialMap, ParallelMap of T; the comparison maps
/// of comparison.hpp), CosineWeighted over one, or RuntimeSampler (runtime_sampler.hpp) when the
/// map is chosen at run time. The set-up — project_sphere and the sampler's own set-up —
/// is done once in the constructor; sample() as often as needed. The samples, pdf and invert
/// are exactly (bit for bit) those of Sampler built from project_sphere's cap, but the light
/// holds `Sampler::CapSampler`, what the sampler does on a cap and nothing else: the radial
/// maps' closed forms without their general-ellipse paths and tables (maps/cap.hpp), the
/// cosine-weighted ones as ProjectedCapSampler alone; ParallelMap as it is. Holds the shading
/// point, the centre, the radius, its distance D and D cos^2 alpha (the shadow ray's closed form)
/// and that sampler only; trivially copyable.
///
/// Defined behaviour on every input: a shading point inside or on the sphere (which sees the
/// emitter in every direction, not a cap), a zero, negative or NaN radius, NaN or infinite
/// coordinates give an empty light (every sample and pdf 0; never NaN). A zero or non-finite
/// receiver normal gives CosineWeighted's documented plain sampling (cosine_weighted() false).
template <class Sampler> class SphereLight {
public:
    using vec3 = typename Sampler::vec3;      ///< a 3-D vector (direction, point or normal)
    using vec2 = typename Sampler::vec2;      ///< a point of the unit square
    using T = typename vec3::value_type;      ///< float or double

    /// The light (center, radius) seen from o, sampled with `Sampler` built from the sphere's
    /// cap and `sampler_args`: nothing for the exact maps; the TabulationView for the tabulated
    /// maps; the receiver normal (after the table, for the tabulated maps) for CosineWeighted.
    template <class... SamplerArgs>
    APSE_HOT_INLINE SphereLight(const vec3& o, const vec3& center, detail::type_identity_t<T> radius,
                          const SamplerArgs&... sampler_args) noexcept
        : SphereLight(FromCap{}, detail::sphere_cap(o, center, T(radius)), o, center, radius, sampler_args...) {}

    /// The sampler's type: what `Sampler` does on a cap (the class comment).
    using CapSampler = typename Sampler::CapSampler;

    /// True if the light cannot be sampled (o inside or on the sphere, invalid input;
    /// cosine-weighted: also the cap entirely below the receiver's horizon): every sample and
    /// pdf is then 0.
    APSE_FUNC bool empty() const noexcept { return sampler_.empty(); }

    /// The cap the sphere subtends at o, as project_sphere gives it (empty for invalid input): a
    /// reference to the sampler's, or a copy where the sampler rebuilds it (the cosine-weighted
    /// samplers of caps).
    APSE_FUNC decltype(auto) ellipse() const noexcept { return sampler_.ellipse(); }

    /// Solid angle of the sphere seen from o: 2 pi (1 − cos alpha), sin alpha = radius / distance
    /// (steradians; 0 when empty), from the cap's stored 1 − cos alpha (no cancellation for far
    /// spheres).
    APSE_FUNC T solid_angle() const noexcept {
        const auto& e = ellipse();
        return e.empty() ? T(0) : e.cap_solid_angle();
    }

    /// True if the samples are cosine-weighted (Sampler is CosineWeighted, the receiver normal is
    /// usable and the cap not below its horizon): density exactly max(0, n·ω) / Omega_perp.
    /// False for the maps' uniform samples.
    APSE_FUNC bool cosine_weighted() const noexcept { return detail::weighted_of(sampler_, 0); }

    /// Sample for the point u of the unit square (clamped into [0, 1]^2; NaN → pdf 0): the
    /// direction, the nearest point of the sphere along it, its distance and the sampler's pdf
    /// (solid angle). The distance comes in closed form from the sample's polar angle for the
    /// radial maps (detail::sphere_distance_at_polar: accurate to a few ulps up to the rim), from
    /// the direction for the others (detail::sphere_hit_distance). pdf 0 ("no sample", point o,
    /// distance 0, the direction finite) for an empty light, a NaN u, or a hit point that
    /// overflows T.
    APSE_HOT_INLINE PointSample<T> sample(const vec2& u) const noexcept { return sphere_.sample(sampler_, u); }

    /// Density of sample() at the world-space direction `w` (any non-zero length), in solid
    /// angle: the sampler's pdf (0 outside the cap, i.e. for rays that miss the sphere).
    APSE_FUNC T pdf(const vec3& w) const noexcept { return sampler_.pdf(w); }

    /// The point of the unit square whose sample has direction `w` (the sampler's invert).
    APSE_FUNC vec2 invert(const vec3& w) const noexcept { return sampler_.invert(w); }

private:
    struct FromCap {};
    template <class... SamplerArgs>
    APSE_HOT_INLINE SphereLight(FromCap, const detail::SphereCap<T>& cap, const vec3& o, const vec3& center, T radius,
                                const SamplerArgs&... sampler_args) noexcept
        : sphere_{o, center, radius, cap.distance, cap.distance * (cap.cos_alpha * cap.cos_alpha)},
          sampler_(make_sampler(cap, sampler_args...)) {}

    /// The sampler of the cap: from the cap without its frame where it takes one (the
    /// cosine-weighted samplers, which read no frame), from project_sphere's ellipse otherwise.
    template <class... SamplerArgs>
    static APSE_HOT_INLINE CapSampler make_sampler(const detail::SphereCap<T>& cap, const SamplerArgs&... sampler_args) noexcept {
        if constexpr (std::is_constructible<CapSampler, const detail::SphereCap<T>&, const SamplerArgs&...>::value)
            return CapSampler(cap, sampler_args...);
        else
            return CapSampler(cap.ellipse(), sampler_args...);
    }

    detail::SphereTarget<T> sphere_;  ///< the shading point, the sphere and its distance
    CapSampler sampler_;
};

/// Density in solid angle with which SphereLight<Sampler>(o, center, radius, sampler_args...)
/// samples the direction w (any non-zero length) — exactly its pdf(w) — stateless, for the MIS
/// weight of a BSDF-sampled direction. Cost: project_sphere and the cap test; for directions
/// that hit the sphere, the sampler's set-up (closed forms for every map on a cap). 0 for rays
/// that miss the sphere and for invalid input.
///
///     float p = apse::sphere_light_pdf<apse::LdRadialMap<float>>(o, center, radius, w);
template <class Sampler, class... SamplerArgs>
APSE_FUNC typename Sampler::vec3::value_type
sphere_light_pdf(const typename Sampler::vec3& o, const typename Sampler::vec3& center,
                 detail::type_identity_t<typename Sampler::vec3::value_type> radius,
                 const typename Sampler::vec3& w, const SamplerArgs&... sampler_args) noexcept {
    using T = typename Sampler::vec3::value_type;
    const SphericalEllipse<T> cap = project_sphere(o, center, radius);
    if (!cap.contains(w)) return T(0);
    return typename Sampler::CapSampler(cap, sampler_args...).pdf(w);
}

}  // namespace apse
