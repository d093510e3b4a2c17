// apse — area-preserving parameterizations for spherical ellipses.
// SPDX-License-Identifier: MIT
#pragma once

/// @file disk_light.hpp
/// A disk light in one call: the disk seen from the shading point projected to its spherical
/// ellipse (project_disk, docs/math.md §2), sampled with the sampler of your choice — a map, or
/// CosineWeighted<map> for directions ∝ the receiver's clamped cosine — with the direction, the
/// point of the disk it reaches, its distance (the shadow ray) and the pdf in solid angle; plus
/// the pdf of any direction for MIS, from the light or statelessly (disk_light_pdf).
///
///     // once: the table of the tabulated maps (thread-safe, built on first use)
///     const apse::TabulationView table = apse::default_table().view();
///     // per shading point o, for each of n stratified points u:
///     apse::DiskLight<apse::TabulatedLdRadialMap<float>> light(o, center, normal, radius, table);
///     auto s = light.sample(u);            // s.pdf == 0: no sample (skip it)
///     if (s.pdf > 0 && visible(o, s.point)) L += Le * f(s.direction) / s.pdf;
///     float p_light = light.pdf(w);        // MIS: the density of a BSDF-sampled direction w
///     // cosine-weighted for the receiver normal n_r: directions ∝ max(0, n_r·ω)
///     apse::DiskLight<apse::CosineWeighted<apse::TabulatedLdRadialMap<float>>> lit(o, center, normal, radius, table, n_r);
///
/// Every pdf is exactly the density its sampler draws from (1/Omega for the exact maps, the
/// tabulated map's own density — within 0.44 % of 1/Omega for the default table — or the
/// cosine-weighted density), so MIS weights computed with them sum to 1. The map chosen at run
/// time (a scene file's string): DiskLight<RuntimeSampler<T>> (runtime_sampler.hpp).
///
/// The geometry is two-sided (the disk seen from behind gives the same ellipse); one-sided
/// emitters cull with `disk_faces(o, center, normal)` first, in the light sample and in the pdf
/// query alike.

#include "config.hpp"
#include "disk_frame.hpp"
#include "projection_disk.hpp"
#include "sample.hpp"
#include "spherical_ellipse.hpp"
#include "detail/glm.hpp"
#include "detail/math.hpp"
#include "detail/type_identity.hpp"
#include "maps/cumulative_area.hpp"

namespace apse {

namespace detail {

/// The sampler's stored solid angle where it keeps one (the exact maps), else computed from the
/// ellipse (one R_J).
template <class Sampler>
APSE_FUNC auto solid_angle_stored(const Sampler& s, int) noexcept -> decltype(s.solid_angle()) {
    return s.solid_angle();
}
template <class Sampler>
APSE_FUNC typename Sampler::vec3::value_type solid_angle_stored(const Sampler& s, long) noexcept {
    return solid_angle_of(s.ellipse());
}

}  // namespace detail

/// A disk light (centre, normal, radius) seen from one shading point o, ready to sample with
/// `Sampler`: a map (LdRadialMap, TabulatedLdRadialMap, ParallelMap of T; the comparison maps of
/// comparison.hpp), CosineWeighted over one, or RuntimeSampler (runtime_sampler.hpp) when the
/// map is chosen at run time. The set-up — the projection and the sampler's own set-up — is
/// done once in the constructor; sample() as often as needed. Holds the shading point, the
/// disk's plane (normal and offset: for the shadow ray's point) and the sampler only: its size is
/// at most the sampler's plus three vectors. Trivially copyable when the sampler is (every apse sampler is;
/// the tabulated maps hold a pointer into the table, which must outlive the light).
///
/// Defined behaviour on every input: o in the disk's plane, a zero, negative or NaN radius, a
/// zero normal, NaN or infinite coordinates, lights subtending less than ~1e-19 sr in float /
/// 1e-153 in double (project_disk), a tabulated map with an invalid view give an empty light
/// (every sample and pdf 0; never NaN). A zero or non-finite receiver normal gives
/// CosineWeighted's documented plain sampling (cosine_weighted() false).
template <class Sampler> class DiskLight {
public:
    using vec3 = typename Sampler::vec3;  ///< a 3-D vector (direction, point or normal)
    using vec2 = typename Sampler::vec2;  ///< a point of the unit square
    using T = typename vec3::value_type;  ///< float or double

    /// The disk {p : (p − center)·normal = 0, |p − center| <= radius} (`normal` any non-zero
    /// length) seen from o, sampled with `Sampler` built from the disk's ellipse and
    /// `sampler_args`: nothing for the exact maps; the TabulationView for the tabulated maps;
    /// the receiver normal (after the table, for the tabulated maps) for CosineWeighted; the
    /// MapKind (then the table, then the receiver normal) for RuntimeSampler.
    template <class... SamplerArgs>
    APSE_FUNC DiskLight(const vec3& o, const vec3& center, const vec3& normal, detail::type_identity_t<T> radius,
                        const SamplerArgs&... sampler_args) noexcept
        : o_(o), normal_(normal), height_(glm::dot(center - o, normal)),
          sampler_(project_disk(o, center, normal, radius), sampler_args...) {}

    /// The disk of the light's stored frame (DiskFrame, built once per light) seen from o: the
    /// light above for (frame.center, frame.n, frame.radius), without normalising the normal per
    /// shading point. An invalid frame gives the empty light.
    template <class... SamplerArgs>
    APSE_FUNC DiskLight(const vec3& o, const DiskFrame<T>& frame, const SamplerArgs&... sampler_args) noexcept
        : o_(o), normal_(frame.n), height_(glm::dot(frame.center - o, frame.n)),
          sampler_(project_disk(o, frame), sampler_args...) {}

    /// True if the light cannot be sampled (invalid input; cosine-weighted: also the disk
    /// entirely below the receiver's horizon): every sample and pdf is then 0.
    APSE_FUNC bool empty() const noexcept { return sampler_.empty(); }

    /// True if the samples are cosine-weighted (the sampler is CosineWeighted — or a
    /// RuntimeSampler built with a receiver normal — and its weighted() is true): density
    /// ∝ max(0, n·ω). False for the maps' uniform samples.
    APSE_FUNC bool cosine_weighted() const noexcept { return detail::weighted_of(sampler_, 0); }

    /// The disk's spherical ellipse: the sampler's (a reference to it, or a copy where the
    /// sampler returns one: RuntimeSampler).
    APSE_FUNC decltype(auto) ellipse() const noexcept { return sampler_.ellipse(); }

    /// The sampler (what it reports: weighted(), the map's kind, ...).
    APSE_FUNC const Sampler& sampler() const noexcept { return sampler_; }

    /// Solid angle of the disk seen from o (steradians, two-sided); 0 for an empty ellipse.
    /// Stored by the exact maps; computed (one R_J) for the other samplers.
    APSE_FUNC T solid_angle() const noexcept { return detail::solid_angle_stored(sampler_, 0); }

    /// Sample for the point u of the unit square (clamped into [0, 1]^2; NaN → pdf 0): the
    /// direction, the point of the disk along it, its distance and the sampler's pdf (solid
    /// angle). pdf 0 ("no sample", point o, distance 0, the direction finite) for an empty
    /// light, a NaN u, when rounding leaves the ray parallel to the disk's plane, or when the
    /// hit point overflows T.
    APSE_FUNC PointSample<T> sample(const vec2& u) const noexcept {
        return detail::point_at_height(sampler_.sample(u), o_, normal_, height_);
    }

    /// Density of sample() at the world-space direction `w` (any non-zero length), in solid
    /// angle: the sampler's pdf (0 for rays that miss the disk). The same value as
    /// disk_light_pdf with the same arguments (the same computation; where the compiler
    /// contracts a·b + c into FMAs, the two call sites may round differently).
    APSE_FUNC T pdf(const vec3& w) const noexcept { return sampler_.pdf(w); }

    /// The point of the unit square whose sample has direction `w` (the sampler's invert).
    APSE_FUNC vec2 invert(const vec3& w) const noexcept { return sampler_.invert(w); }

private:
    vec3 o_, normal_;  ///< the shading point and the disk's normal (the shadow ray's plane)
    T height_;         ///< (center − o)·normal: the plane's offset from o along the normal
    Sampler sampler_;
};

/// Density in solid angle with which DiskLight<Sampler>(o, center, normal, radius,
/// sampler_args...) samples the direction w (any non-zero length) — exactly its pdf(w) —
/// stateless, for the MIS weight of a BSDF-sampled direction. 0 for rays that miss the disk and
/// for invalid input. Cost: the projection and the ellipse test; for directions that hit the
/// disk, the sampler's set-up (one R_J for the exact maps, none for the tabulated ones; the
/// cosine weighting's nodes for CosineWeighted — a renderer that queries many directions at one
/// shading point should keep the DiskLight instead).
///
///     float p = apse::disk_light_pdf<apse::TabulatedLdRadialMap<float>>(o, center, normal, radius, w, table);
template <class Sampler, class... SamplerArgs>
APSE_FUNC typename Sampler::vec3::value_type
disk_light_pdf(const typename Sampler::vec3& o, const typename Sampler::vec3& center,
               const typename Sampler::vec3& normal, detail::type_identity_t<typename Sampler::vec3::value_type> radius,
               const typename Sampler::vec3& w, const SamplerArgs&... sampler_args) noexcept {
    using T = typename Sampler::vec3::value_type;
    const SphericalEllipse<T> e = project_disk(o, center, normal, radius);
    if (!e.contains(w)) return T(0);
    return Sampler(e, sampler_args...).pdf(w);
}

}  // namespace apse
