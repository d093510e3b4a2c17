// apse — area-preserving parameterizations for spherical ellipses.
// SPDX-License-Identifier: MIT
#pragma once

/// @file disk_light.hpp
/// The one-call convenience a renderer wants for a disk light: project the disk seen from the
/// shading point to its spherical ellipse (projection.hpp, docs/math.md §2), sample it with one of
/// the maps (maps/*.hpp, docs/math.md §4–6), and return the direction, the point on the disk, its
/// distance and the pdf in solid angle; plus the pdf of any direction (for MIS), from the light
/// object or statelessly (disk_light_pdf: from the shading point, the light and the direction).
///
///     // once: the table of the tabulated maps (thread-safe, built on first use)
///     const apse::TabulationView table = apse::default_table().view();
///     // per shading point o, for each of n stratified points u:
///     apse::DiskLight<float> light(o, center, normal, radius, apse::DiskMap::tabulated_ld_radial, table);
///     auto s = light.sample(u);            // s.pdf == 0: no sample (skip it)
///     if (s.pdf > 0 && visible(o, s.point)) L += Le * f(s.direction) / s.pdf;
///     // MIS: the light's density of a BSDF-sampled direction w, exactly the one sampled from
///     float p_light = light.pdf(w);        // or, stateless:
///     p_light = apse::disk_light_pdf(o, center, normal, radius, apse::DiskMap::tabulated_ld_radial, table, w);
///     // cosine-weighted (CosineWeighted): directions ∝ max(0, n_r·ω) for the receiver normal n_r
///     apse::DiskLight<float> lit(o, center, normal, radius, apse::DiskMap::tabulated_ld_radial, table, n_r);
///
/// Every pdf here is exactly the density its sampler draws from: 1/Omega for the exact maps
/// (radial, LD-radial, parallel), the tabulated maps' own density (within 0.44 % of 1/Omega for
/// the default table, not equal to it), the cosine-weighted density (CosineWeighted: the
/// tabulated maps' warp or ProjectedSolidAngleSampler) for the cosine-weighted samplers —
/// so MIS weights computed with them sum to 1.
///
/// The geometry is two-sided (the disk seen from behind gives the same ellipse); one-sided
/// emitters cull with `disk_faces(o, center, normal)` first, in the light sample and in the pdf
/// query alike. Scalars: T is deduced from the vectors; the radius may be any arithmetic type.

#include <cmath>

#include "config.hpp"
#include "math.hpp"
#include "projection_disk.hpp"
#include "sample.hpp"
#include "spherical_ellipse.hpp"
#include "detail/glm.hpp"
#include "detail/type_identity.hpp"
#include "maps/cumulative_area.hpp"
#include "maps/ld_radial.hpp"
#include "maps/parallel.hpp"
#include "maps/radial.hpp"
#include "maps/tabulated.hpp"
#include "cosine_weighted.hpp"

namespace apse {

/// Which map a DiskLight uses. The exact maps give the same, uniform, density 1/Omega and differ
/// in how they distort the square (and so in how well they keep stratification); the tabulated
/// ones need a TabulationView and draw from their own density (within the table's error of
/// 1/Omega: 0.44 % for the default table), which their pdf reports exactly.
enum class DiskMap {
    radial,               ///< RadialMap (docs/math.md §4)
    ld_radial,            ///< LdRadialMap: continuous on the whole square; the default
    parallel,             ///< ParallelMap (docs/math.md §5)
    tabulated,            ///< TabulatedMap (docs/math.md §6; needs a table)
    tabulated_ld_radial,  ///< TabulatedLdRadialMap (needs a table): the cheapest continuous map
};

/// True for the maps that read a tabulation table (DiskMap::tabulated, tabulated_ld_radial).
APSE_FUNC constexpr bool is_tabulated(DiskMap map) noexcept {
    return map == DiskMap::tabulated || map == DiskMap::tabulated_ld_radial;
}

/// One sample of a disk light: direction, pdf (solid angle; 0 marks "no sample"), the point of
/// the disk hit along the direction and its distance (the result family's PointSample).
template <class T> using DiskLightSample = PointSample<T>;

namespace detail {
struct DiskLightAccess;
}  // namespace detail

/// A disk light seen from one shading point, ready to sample with one of the maps (the set-up
/// — projection, map — is done once in the constructor; sample() as often as needed),
/// uniformly in solid angle (exact maps), with a tabulated map's density, or, given the
/// receiver's normal, cosine-weighted (CosineWeighted). Trivially copyable (the tabulated maps
/// hold a pointer into the table, which must outlive the light); holds only the chosen sampler
/// (a union: 824 bytes in double, 432 in float, set by the cosine-weighted samplers — in double
/// CosineWeighted<ParallelMap>, 744 bytes, in float the tabulated maps', 384; the plain maps
/// alone would take 432 and 232).
template <class T> class DiskLight {
    static_assert(detail::is_real_type<T>(), "apse: DiskLight<T>: T must be float or double");

public:
    using vec2 = glm::vec<2, T>;  ///< a point of the unit square
    using vec3 = glm::vec<3, T>;  ///< a 3-D vector (direction, point or normal)

    /// Disk {p : (p − center)·normal = 0, |p − center| <= radius} seen from `o`, sampled with
    /// `map` (tabulated maps read `table`, the other maps ignore it); `normal` need not be unit.
    /// Degenerate or invalid input (see project_disk: o in the disk's plane, radius <= 0,
    /// NaN/Inf, lights subtending less than ~1e-19 sr in float / 1e-153 in double) or a tabulated
    /// map with an invalid view gives a light whose samples all have pdf 0.
    APSE_FUNC DiskLight(const vec3& o, const vec3& center, const vec3& normal, detail::type_identity_t<T> radius,
                        DiskMap map, const TabulationView& table) noexcept
        : DiskLight(o, center, normal, map, project_disk(o, center, normal, radius), table) {}

    /// The same without a table: for the exact maps (a tabulated `map` here gives the empty
    /// light, every pdf 0 — pass a table).
    APSE_FUNC DiskLight(const vec3& o, const vec3& center, const vec3& normal, detail::type_identity_t<T> radius,
                        DiskMap map = DiskMap::ld_radial) noexcept
        : DiskLight(o, center, normal, radius, map, no_table()) {}

    /// The same disk, sampled in proportion to the receiver's clamped cosine max(0, n_r·ω)
    /// (CosineWeighted over the chosen map) for the receiver normal `receiver_normal` (any
    /// non-zero length): pdf is the exact density of the samples (not 1/Omega). The disk entirely
    /// below the receiver's horizon: every pdf 0. A zero/NaN receiver normal: the plain map.
    APSE_FUNC DiskLight(const vec3& o, const vec3& center, const vec3& normal, detail::type_identity_t<T> radius,
                        DiskMap map, const TabulationView& table, const vec3& receiver_normal) noexcept
        : DiskLight(o, center, normal, map, project_disk(o, center, normal, radius), table, receiver_normal) {}

    /// Cosine-weighted over an exact map (no table; a tabulated `map` gives the empty light).
    APSE_FUNC DiskLight(const vec3& o, const vec3& center, const vec3& normal, detail::type_identity_t<T> radius,
                        DiskMap map, const vec3& receiver_normal) noexcept
        : DiskLight(o, center, normal, radius, map, no_table(), receiver_normal) {}

    /// The disk of the light's stored frame (DiskFrame, built once per light) seen from `o`: the
    /// light of the constructors above for (frame.center, frame.n, frame.radius), without
    /// normalising the normal per shading point (project_disk(o, frame)). An invalid frame gives
    /// the empty light.
    APSE_FUNC DiskLight(const vec3& o, const DiskFrame<T>& frame, DiskMap map, const TabulationView& table) noexcept
        : DiskLight(o, frame.center, frame.n, map, project_disk(o, frame), table) {}

    /// The same without a table (exact maps; a tabulated `map` gives the empty light).
    APSE_FUNC explicit DiskLight(const vec3& o, const DiskFrame<T>& frame, DiskMap map = DiskMap::ld_radial) noexcept
        : DiskLight(o, frame, map, no_table()) {}

    /// The stored frame's disk, cosine-weighted for the receiver normal `receiver_normal` (as the
    /// constructor with a receiver normal above).
    APSE_FUNC DiskLight(const vec3& o, const DiskFrame<T>& frame, DiskMap map, const TabulationView& table,
                        const vec3& receiver_normal) noexcept
        : DiskLight(o, frame.center, frame.n, map, project_disk(o, frame), table, receiver_normal) {}

    /// The same over an exact map, without a table.
    APSE_FUNC DiskLight(const vec3& o, const DiskFrame<T>& frame, DiskMap map, const vec3& receiver_normal) noexcept
        : DiskLight(o, frame, map, no_table(), receiver_normal) {}

    /// The map used.
    APSE_FUNC DiskMap map() const noexcept { return map_; }

    /// True if the light cannot be sampled (degenerate input, o in the disk's plane; cosine-weighted:
    /// also the disk entirely below the receiver's horizon): every sample and pdf is then 0.
    APSE_FUNC bool empty() const noexcept {
        return visit([](const auto& m) { return m.empty(); });
    }

    /// True if the samples are cosine-weighted: built with a receiver normal that is non-zero and
    /// finite, and not empty() (CosineWeighted::weighted()).
    APSE_FUNC bool cosine_weighted() const noexcept {
        return cosine_ && visit([](const auto& m) { return weighted(m); });
    }

    /// The disk's spherical ellipse.
    APSE_FUNC const SphericalEllipse<T>& ellipse() const noexcept {
        return visit([](const auto& m) -> const SphericalEllipse<T>& { return m.ellipse(); });
    }

    /// Solid angle of the disk seen from o (steradians, two-sided); 0 for degenerate input.
    /// Stored by the plain exact maps; computed (one R_J) for the others.
    APSE_FUNC T solid_angle() const noexcept {
        if (!cosine_ && map_ == DiskMap::parallel) return maps_.parallel.solid_angle();
        if (!cosine_ && (map_ == DiskMap::radial || map_ == DiskMap::ld_radial)) return maps_.ld.solid_angle();
        return detail::solid_angle_of(ellipse());
    }

    /// Sample for the point u of the unit square (clamped into [0, 1]^2; NaN → pdf 0): the
    /// direction, the point of the disk along it, its distance and pdf (the sampler's exact
    /// density: 1/Omega, the tabulated map's or the cosine-weighted one). pdf 0 ("no sample",
    /// finite direction and point = o) for a degenerate light, a NaN u, when rounding leaves the
    /// ray parallel to the disk's plane, or when the hit point overflows T.
    APSE_NOINLINE APSE_FUNC DiskLightSample<T> sample(const vec2& u) const noexcept {
        const DirectionSample<T> s = visit([&u](const auto& m) { return m.sample(u); });
        return point_on_plane(s, o_, center_, normal_);
    }

    /// Density of sample() at the world-space direction `w` (any non-zero length), in solid
    /// angle: the sampler's density (1/Omega, the tabulated or the cosine-weighted one) if the
    /// ray from o along w hits the disk (boundary included), else 0. The same value as
    /// disk_light_pdf with the same arguments (the same computation; where the compiler contracts
    /// a·b + c into FMAs, the two call sites may round differently).
    APSE_NOINLINE APSE_FUNC T pdf(const vec3& w) const noexcept {
        return visit([&w](const auto& m) { return m.pdf(w); });
    }

    /// The point of the unit square whose sample has direction `w` (the map's inverse; see
    /// the maps' invert for the behaviour outside the disk).
    APSE_NOINLINE APSE_FUNC vec2 invert(const vec3& w) const noexcept {
        return visit([&w](const auto& m) { return m.invert(w); });
    }

private:
    friend struct detail::DiskLightAccess;

    /// The chosen sampler only: plain (the LD-radial map, whose radial() serves
    /// DiskMap::radial; the parallel one; the tabulated LD-radial map, whose radial() serves
    /// DiskMap::tabulated) or cosine-weighted over any of the five maps, built in place; `map_`
    /// and `cosine_` say which member is alive. All are trivially copyable and destructible, so
    /// the union is too.
    struct CosineTag {};
    union Maps {
        LdRadialMap<T> ld;
        ParallelMap<T> parallel;
        TabulatedLdRadialMap<T> tab;
        CosineWeighted<LdRadialMap<T>> cw_ld;
        CosineWeighted<RadialMap<T>> cw_radial;
        CosineWeighted<ParallelMap<T>> cw_parallel;
        CosineWeighted<TabulatedLdRadialMap<T>> cw_tab_ld;
        CosineWeighted<TabulatedMap<T>> cw_tab;
        APSE_FUNC explicit Maps(const LdRadialMap<T>& m) noexcept : ld(m) {}
        APSE_FUNC explicit Maps(const ParallelMap<T>& m) noexcept : parallel(m) {}
        APSE_FUNC explicit Maps(const TabulatedLdRadialMap<T>& m) noexcept : tab(m) {}
        APSE_FUNC Maps(CosineTag, const LdRadialMap<T>& m, const vec3& n) noexcept : cw_ld(m, n) {}
        APSE_FUNC Maps(CosineTag, const RadialMap<T>& m, const vec3& n) noexcept : cw_radial(m, n) {}
        APSE_FUNC Maps(CosineTag, const ParallelMap<T>& m, const vec3& n) noexcept : cw_parallel(m, n) {}
        APSE_FUNC Maps(CosineTag, const TabulatedLdRadialMap<T>& m, const vec3& n) noexcept : cw_tab_ld(m, n) {}
        APSE_FUNC Maps(CosineTag, const TabulatedMap<T>& m, const vec3& n) noexcept : cw_tab(m, n) {}
    };
    static APSE_FUNC TabulationView no_table() noexcept { return TabulationView{nullptr, 0, 0, 0}; }
    /// Whether a live sampler weights by the cosine: CosineWeighted's own answer, false for a plain map.
    template <class Map, int Nodes> static APSE_FUNC bool weighted(const CosineWeighted<Map, Nodes>& m) noexcept {
        return m.weighted();
    }
    template <class Map> static APSE_FUNC bool weighted(const Map&) noexcept { return false; }
    static APSE_NOINLINE APSE_FUNC Maps make_maps(DiskMap map, const SphericalEllipse<T>& e, const TabulationView& table) noexcept {
        if (map == DiskMap::parallel) return Maps(ParallelMap<T>(e));
        if (is_tabulated(map)) return Maps(TabulatedLdRadialMap<T>(e, table));
        return Maps(LdRadialMap<T>(e));
    }
    static APSE_NOINLINE APSE_FUNC Maps make_cosine(DiskMap map, const SphericalEllipse<T>& e, const TabulationView& table,
                                      const vec3& n) noexcept {
        switch (map) {
        case DiskMap::radial: return Maps(CosineTag{}, RadialMap<T>(e), n);
        case DiskMap::parallel: return Maps(CosineTag{}, ParallelMap<T>(e), n);
        case DiskMap::tabulated: return Maps(CosineTag{}, TabulatedMap<T>(e, table), n);
        case DiskMap::tabulated_ld_radial: return Maps(CosineTag{}, TabulatedLdRadialMap<T>(e, table), n);
        default: return Maps(CosineTag{}, LdRadialMap<T>(e), n);
        }
    }

    /// f(the live sampler): every sampler has sample, pdf, invert and ellipse. (sample, pdf,
    /// invert and the set-up are APSE_NOINLINE: in device code each holds every sampler's code
    /// once per kernel, however many calls the kernel makes.)
    template <class F> APSE_FUNC decltype(auto) visit(F&& f) const noexcept {
        if (cosine_) {
            switch (map_) {
            case DiskMap::radial: return f(maps_.cw_radial);
            case DiskMap::parallel: return f(maps_.cw_parallel);
            case DiskMap::tabulated: return f(maps_.cw_tab);
            case DiskMap::tabulated_ld_radial: return f(maps_.cw_tab_ld);
            default: return f(maps_.cw_ld);
            }
        }
        switch (map_) {
        case DiskMap::radial: return f(maps_.ld.radial());
        case DiskMap::parallel: return f(maps_.parallel);
        case DiskMap::tabulated: return f(maps_.tab.radial());
        case DiskMap::tabulated_ld_radial: return f(maps_.tab);
        default: return f(maps_.ld);
        }
    }

    APSE_FUNC DiskLight(const vec3& o, const vec3& center, const vec3& normal, DiskMap map,
                        const SphericalEllipse<T>& e, const TabulationView& table) noexcept
        : o_(o), center_(center), normal_(normal), map_(map), cosine_(false), maps_(make_maps(map, e, table)) {}

    APSE_FUNC DiskLight(const vec3& o, const vec3& center, const vec3& normal, DiskMap map,
                        const SphericalEllipse<T>& e, const TabulationView& table, const vec3& receiver_normal) noexcept
        : o_(o), center_(center), normal_(normal), map_(map), cosine_(true),
          maps_(make_cosine(map, e, table, receiver_normal)) {}

    vec3 o_, center_, normal_;
    DiskMap map_;
    bool cosine_;
    Maps maps_;
};

/// One sample of the disk light (center, normal, radius) seen from o, with the chosen exact map,
/// for the point u of the unit square: DiskLight(o, center, normal, radius, map).sample(u).
template <class T>
APSE_FUNC DiskLightSample<T> sample_disk_light(const glm::vec<3, T>& o, const glm::vec<3, T>& center,
                                               const glm::vec<3, T>& normal, detail::type_identity_t<T> radius,
                                               DiskMap map, const glm::vec<2, T>& u) noexcept {
    return DiskLight<T>(o, center, normal, radius, map).sample(u);
}

/// One sample with any map (the tabulated ones read `table`):
/// DiskLight(o, center, normal, radius, map, table).sample(u).
template <class T>
APSE_FUNC DiskLightSample<T> sample_disk_light(const glm::vec<3, T>& o, const glm::vec<3, T>& center,
                                               const glm::vec<3, T>& normal, detail::type_identity_t<T> radius,
                                               DiskMap map, const TabulationView& table,
                                               const glm::vec<2, T>& u) noexcept {
    return DiskLight<T>(o, center, normal, radius, map, table).sample(u);
}

/// One cosine-weighted sample for the receiver normal `receiver_normal`:
/// DiskLight(o, center, normal, radius, map, table, receiver_normal).sample(u).
template <class T>
APSE_FUNC DiskLightSample<T> sample_disk_light(const glm::vec<3, T>& o, const glm::vec<3, T>& center,
                                               const glm::vec<3, T>& normal, detail::type_identity_t<T> radius,
                                               DiskMap map, const TabulationView& table,
                                               const glm::vec<3, T>& receiver_normal,
                                               const glm::vec<2, T>& u) noexcept {
    return DiskLight<T>(o, center, normal, radius, map, table, receiver_normal).sample(u);
}

namespace detail {

/// DiskLight's constructor from the projected ellipse, for disk_light_pdf (which has projected
/// the disk already, to test the direction).
struct DiskLightAccess {
    template <class T>
    static APSE_FUNC DiskLight<T> cosine_light(const glm::vec<3, T>& o, const glm::vec<3, T>& center,
                                               const glm::vec<3, T>& normal, DiskMap map, const SphericalEllipse<T>& e,
                                               const TabulationView& table, const glm::vec<3, T>& receiver_normal) noexcept {
        return DiskLight<T>(o, center, normal, map, e, table, receiver_normal);
    }
};

}  // namespace detail

/// Density in solid angle with which the **exact** maps (DiskMap radial, ld_radial, parallel)
/// sample the direction w from o: 1/Omega of the disk's spherical ellipse if the ray o + t w
/// (t > 0) hits the disk, else 0 (also for degenerate input). One projection and one R_J. Not
/// the tabulated maps' density (use the overload with the map and the table) nor the
/// cosine-weighted one.
template <class T>
APSE_FUNC T disk_light_pdf(const glm::vec<3, T>& o, const glm::vec<3, T>& center, const glm::vec<3, T>& normal,
                           detail::type_identity_t<T> radius, const glm::vec<3, T>& w) noexcept {
    const SphericalEllipse<T> e = project_disk(o, center, normal, radius);
    if (!e.contains(w)) return T(0);
    const T omega = detail::solid_angle_of(e);
    return omega > T(0) ? T(1) / omega : T(0);
}

/// Density in solid angle with which DiskLight(o, center, normal, radius, map, table) samples
/// the direction w — exactly the pdf its sample() reports and its pdf(w) returns, for every map
/// — stateless, for the MIS weight of a BSDF-sampled direction: 1/Omega for the exact maps (as
/// the overload above), the tabulated maps' own density for DiskMap::tabulated and
/// tabulated_ld_radial (it differs from 1/Omega by up to the table's error, 0.44 % for the
/// default table: weights built from 1/Omega would not sum to 1). 0 if the ray misses the disk,
/// for degenerate input or an invalid table. Cost: the projection, then (hits only) one R_J
/// (exact maps) or the tabulated map's set-up and one table look-up (no elliptic integral).
template <class T>
APSE_FUNC T disk_light_pdf(const glm::vec<3, T>& o, const glm::vec<3, T>& center, const glm::vec<3, T>& normal,
                           detail::type_identity_t<T> radius, DiskMap map, const TabulationView& table,
                           const glm::vec<3, T>& w) noexcept {
    const SphericalEllipse<T> e = project_disk(o, center, normal, radius);
    if (!e.contains(w)) return T(0);
    if (is_tabulated(map)) return TabulatedMap<T>(e, table).pdf(w);
    const T omega = detail::solid_angle_of(e);
    return omega > T(0) ? T(1) / omega : T(0);
}

/// Density in solid angle with which the cosine-weighted
/// DiskLight(o, center, normal, radius, map, table, receiver_normal) samples w (exactly its
/// pdf(w)), stateless. Cost: the projection; for directions that hit the disk, the map's and
/// the cosine weighting's set-up (its marginal nodes) — a renderer that queries many
/// directions at one shading point should keep the DiskLight instead.
template <class T>
APSE_FUNC T disk_light_pdf(const glm::vec<3, T>& o, const glm::vec<3, T>& center, const glm::vec<3, T>& normal,
                           detail::type_identity_t<T> radius, DiskMap map, const TabulationView& table,
                           const glm::vec<3, T>& receiver_normal, const glm::vec<3, T>& w) noexcept {
    const SphericalEllipse<T> e = project_disk(o, center, normal, radius);
    if (!e.contains(w)) return T(0);
    return detail::DiskLightAccess::cosine_light(o, center, normal, map, e, table, receiver_normal).pdf(w);
}

}  // namespace apse
