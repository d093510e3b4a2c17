// apse — area-preserving parameterizations for spherical ellipses.
// SPDX-License-Identifier: MIT
#pragma once

/// @file disk_light.hpp
/// The one-call convenience a renderer wants for a disk light: project the disk seen from the
/// shading point to its spherical ellipse (projection.hpp, docs/math.md §2), sample it with one of the
/// area-preserving maps (maps/*.hpp, docs/math.md §4–5), and return the direction, the point on the
/// disk, its distance and the pdf in solid angle; plus the pdf of any direction (for MIS).
///
///     // per shading point o, for each of n stratified points u:
///     apse::DiskLight<float> light(o, center, normal, radius, apse::DiskMap::ld_radial);
///     auto s = light.sample(u);            // s.pdf == 0: no sample (skip it)
///     if (s.pdf > 0 && visible(o, s.point)) L += Le * f(s.direction) / s.pdf;
///     // MIS: the light's density of a BSDF-sampled direction w
///     float p_light = light.pdf(w);        // or apse::disk_light_pdf(o, center, normal, radius, w)
///     // cosine-weighted (CosineWeighted): directions ∝ max(0, n_r·ω) for the receiver normal n_r
///     apse::DiskLight<float> lit(o, center, normal, radius, apse::DiskMap::ld_radial, n_r);
///
/// The geometry is two-sided (the disk seen from behind gives the same ellipse); one-sided
/// emitters cull with `disk_faces(o, center, normal)` first.

#include <cmath>

#include "config.hpp"
#include "math.hpp"
#include "projection.hpp"
#include "sample.hpp"
#include "spherical_ellipse.hpp"
#include "detail/glm.hpp"
#include "maps/ld_radial.hpp"
#include "maps/parallel.hpp"
#include "maps/radial.hpp"
#include "cosine_weighted.hpp"
#include "detail/cumulative_area.hpp"

namespace apse {

/// Which area-preserving map a DiskLight uses (all three give the same, uniform, density; they
/// differ in how they distort the square and so in how well they keep stratification).
enum class DiskMap {
    radial,     ///< RadialMap (docs/math.md §4)
    ld_radial,  ///< LdRadialMap: continuous on the whole square; the default
    parallel,   ///< ParallelMap (docs/math.md §5)
};

/// One sample of a disk light.
template <class T> struct DiskLightSample {
    glm::vec<3, T> direction;  ///< world-space unit direction from o towards the disk
    glm::vec<3, T> point;      ///< the point of the disk hit along `direction`
    T distance;                ///< |point − o|
    T pdf;                     ///< density in solid angle (1/Omega); 0 marks "no sample"
};

/// A disk light seen from one shading point, ready to sample with one of the maps (the set-up
/// — projection, solid angle — is done once in the constructor; sample() as often as needed),
/// uniformly in solid angle or, given the receiver's normal, cosine-weighted (CosineWeighted).
/// Trivially copyable; holds only the chosen sampler (a union: 1176 bytes in double, 592 in float,
/// set by the cosine-weighted samplers; the plain maps alone would take 416 and 208).
template <class T> class DiskLight {
public:
    using vec2 = glm::vec<2, T>;  ///< a point of the unit square
    using vec3 = glm::vec<3, T>;  ///< a 3-D vector (direction, point or normal)

    /// Disk {p : (p − center)·normal = 0, |p − center| <= radius} seen from `o`; `normal` need
    /// not be unit. Degenerate or invalid input (see project_disk: o in the disk's plane,
    /// radius <= 0, NaN/Inf, lights subtending less than ~1e-19 sr in float / 1e-153 in double)
    /// gives a light whose samples all have pdf 0.
    APSE_FUNC DiskLight(const vec3& o, const vec3& center, const vec3& normal, T radius,
                        DiskMap map = DiskMap::ld_radial) noexcept
        : DiskLight(o, center, normal, map, project_disk(o, center, normal, radius)) {}

    /// The same disk, sampled in proportion to the receiver's clamped cosine max(0, n_r·ω)
    /// (CosineWeighted over the chosen map) for the receiver normal `receiver_normal` (any
    /// non-zero length): pdf is the exact density of the samples (not 1/Omega). The disk entirely
    /// below the receiver's horizon: every pdf 0. A zero/NaN receiver normal: the plain map.
    APSE_FUNC DiskLight(const vec3& o, const vec3& center, const vec3& normal, T radius, DiskMap map,
                        const vec3& receiver_normal) noexcept
        : DiskLight(o, center, normal, map, project_disk(o, center, normal, radius), receiver_normal) {}

    /// True if the samples are cosine-weighted (built with a valid receiver normal).
    APSE_FUNC bool cosine_weighted() const noexcept { return cosine_; }

    /// The disk's spherical ellipse.
    APSE_FUNC const SphericalEllipse<T>& ellipse() const noexcept {
        if (cosine_) return map_ == DiskMap::parallel ? maps_.cw_parallel.ellipse() : maps_.cw_radial.ellipse();
        return map_ == DiskMap::parallel ? maps_.parallel.ellipse() : maps_.ld.ellipse();
    }

    /// Solid angle of the disk seen from o (steradians, two-sided); 0 for degenerate input.
    APSE_FUNC T solid_angle() const noexcept {
        if (cosine_) return detail::solid_angle_of(ellipse());
        return map_ == DiskMap::parallel ? maps_.parallel.solid_angle() : maps_.ld.solid_angle();
    }

    /// Sample for the point u of the unit square (clamped into [0, 1]^2; NaN → pdf 0): the
    /// direction (uniform in solid angle over the disk, or cosine-weighted), the point of the disk
    /// along it, its distance and pdf (1/Omega, or the cosine-weighted density). pdf 0 ("no sample", finite direction and point = o) for a
    /// degenerate light, a NaN u, when rounding leaves the ray parallel to the disk's plane, or
    /// when the hit point overflows T.
    APSE_FUNC DiskLightSample<T> sample(const vec2& u) const noexcept {
        DirectionSample<T> s;
        if (cosine_) {
            if (map_ == DiskMap::parallel) s = maps_.cw_parallel.sample(u);
            else if (map_ == DiskMap::radial) s = maps_.cw_radial.sample(u);
            else s = maps_.cw_ld.sample(u);
        } else if (map_ == DiskMap::parallel) s = maps_.parallel.sample(u);
        else if (map_ == DiskMap::radial) s = maps_.ld.radial().sample(u);
        else s = maps_.ld.sample(u);
        DiskLightSample<T> r{s.direction, o_, T(0), T(0)};
        if (!(s.pdf > T(0))) return r;
        const T t = glm::dot(center_ - o_, normal_) / glm::dot(s.direction, normal_);
        if (!(t > T(0)) || !is_finite(t)) return r;
        const vec3 p = o_ + t * s.direction;
        if (!is_finite(p.x + p.y + p.z)) return r;  // beyond T's range
        r.point = p;
        r.distance = t;
        r.pdf = s.pdf;
        return r;
    }

    /// Density of sample() at the world-space direction `w` (any non-zero length), in solid
    /// angle: 1/Omega (or the cosine-weighted density) if the ray from o along w hits the disk
    /// (boundary included), else 0.
    APSE_FUNC T pdf(const vec3& w) const noexcept {
        if (cosine_) {
            if (map_ == DiskMap::parallel) return maps_.cw_parallel.pdf(w);
            return map_ == DiskMap::radial ? maps_.cw_radial.pdf(w) : maps_.cw_ld.pdf(w);
        }
        return map_ == DiskMap::parallel ? maps_.parallel.pdf(w) : maps_.ld.pdf(w);
    }

    /// The point of the unit square whose sample has direction `w` (the map's inverse; see
    /// RadialMap / LdRadialMap / ParallelMap::invert for the behaviour outside the disk).
    APSE_FUNC vec2 invert(const vec3& w) const noexcept {
        if (cosine_) {
            if (map_ == DiskMap::parallel) return maps_.cw_parallel.invert(w);
            return map_ == DiskMap::radial ? maps_.cw_radial.invert(w) : maps_.cw_ld.invert(w);
        }
        if (map_ == DiskMap::parallel) return maps_.parallel.invert(w);
        if (map_ == DiskMap::radial) return maps_.ld.radial().invert(w);
        return maps_.ld.invert(w);
    }

private:
    /// The chosen sampler only: plain (the LD-radial map, whose radial() serves
    /// DiskMap::radial, or the parallel one) or cosine-weighted (over the LD-radial, radial or
    /// parallel map), built in place; `map_` and `cosine_` say which member is alive. All are
    /// trivially copyable and destructible, so the union is too.
    struct ParallelTag {};
    struct CosineTag {};
    union Maps {
        LdRadialMap<T> ld;
        ParallelMap<T> parallel;
        CosineWeighted<LdRadialMap<T>> cw_ld;
        CosineWeighted<RadialMap<T>> cw_radial;
        CosineWeighted<ParallelMap<T>> cw_parallel;
        APSE_FUNC explicit Maps(const SphericalEllipse<T>& e) noexcept : ld(e) {}
        APSE_FUNC Maps(ParallelTag, const SphericalEllipse<T>& e) noexcept : parallel(e) {}
        APSE_FUNC Maps(CosineTag, const LdRadialMap<T>& m, const vec3& n) noexcept : cw_ld(m, n) {}
        APSE_FUNC Maps(CosineTag, const RadialMap<T>& m, const vec3& n) noexcept : cw_radial(m, n) {}
        APSE_FUNC Maps(CosineTag, const ParallelMap<T>& m, const vec3& n) noexcept : cw_parallel(m, n) {}
    };
    static APSE_FUNC Maps make_maps(DiskMap map, const SphericalEllipse<T>& e) noexcept {
        return map == DiskMap::parallel ? Maps(ParallelTag{}, e) : Maps(e);
    }
    static APSE_FUNC Maps make_cosine(DiskMap map, const SphericalEllipse<T>& e, const vec3& n) noexcept {
        if (map == DiskMap::parallel) return Maps(CosineTag{}, ParallelMap<T>(e), n);
        if (map == DiskMap::radial) return Maps(CosineTag{}, RadialMap<T>(e), n);
        return Maps(CosineTag{}, LdRadialMap<T>(e), n);
    }

    APSE_FUNC DiskLight(const vec3& o, const vec3& center, const vec3& normal, DiskMap map,
                        const SphericalEllipse<T>& e) noexcept
        : o_(o), center_(center), normal_(normal), map_(map), cosine_(false), maps_(make_maps(map, e)) {}

    APSE_FUNC DiskLight(const vec3& o, const vec3& center, const vec3& normal, DiskMap map,
                        const SphericalEllipse<T>& e, const vec3& receiver_normal) noexcept
        : o_(o), center_(center), normal_(normal), map_(map), cosine_(true),
          maps_(make_cosine(map, e, receiver_normal)) {}

    vec3 o_, center_, normal_;
    DiskMap map_;
    bool cosine_;
    Maps maps_;
};

/// One sample of the disk light (center, normal, radius) seen from o, with the chosen map, for
/// the point u of the unit square: DiskLight(o, center, normal, radius, map).sample(u).
template <class T>
APSE_FUNC DiskLightSample<T> sample_disk_light(const glm::vec<3, T>& o, const glm::vec<3, T>& center,
                                               const glm::vec<3, T>& normal, T radius, DiskMap map,
                                               const glm::vec<2, T>& u) noexcept {
    return DiskLight<T>(o, center, normal, radius, map).sample(u);
}

/// Density in solid angle with which every map samples the direction w from o: 1/Omega of the
/// disk's spherical ellipse if the ray o + t w (t > 0) hits the disk, else 0 (also for
/// degenerate input). One projection and one R_J: use it for MIS weights of BSDF samples.
template <class T>
APSE_FUNC T disk_light_pdf(const glm::vec<3, T>& o, const glm::vec<3, T>& center,
                           const glm::vec<3, T>& normal, T radius, const glm::vec<3, T>& w) noexcept {
    const SphericalEllipse<T> e = project_disk(o, center, normal, radius);
    if (!e.contains(w)) return T(0);
    const T omega = detail::solid_angle_of(e);
    return omega > T(0) ? T(1) / omega : T(0);
}

}  // namespace apse
