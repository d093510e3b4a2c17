// apse — area-preserving parameterizations for spherical ellipses.
// SPDX-License-Identifier: MIT
#pragma once

/// @file cosine_weighted.hpp
/// `CosineWeighted<Map>`: directions on a spherical ellipse drawn in proportion to the
/// receiver's clamped cosine max(0, n·ω) (no sample below the horizon), with the exact density
/// reported — the cosine-weighted option of every map (RadialMap, LdRadialMap, ParallelMap,
/// TabulatedMap, TabulatedLdRadialMap). docs/cosine_weighted.md has the derivation, the variants
/// measured and the numbers.
///
/// How, by map:
/// * every map, when its ellipse is a spherical cap (SphericalEllipse::is_cap()): the exact
///   sampler of caps (detail::ProjectedCapSampler, projected_cap.hpp), whatever the map —
///   closed form above the horizon, a continuous map of the square onto the visible part when
///   the horizon cuts the cap; the density is exactly max(0, n·ω) / Omega_perp;
/// * the tabulated maps, while the ellipse's centre is above the horizon: a warp of the map's own
///   square (maps/tabulated_cosine.hpp) that reuses the map's sample — a piecewise-linear
///   marginal over its azimuth coordinate and a model of the cosine along each ray whose root is
///   the horizon's exact crossing;
/// * the exact maps, and the tabulated maps with the centre on, below or within 1e-3 (of the
///   normal's largest component) above the horizon: the exact
///   projected-solid-angle sampler of the map's ellipse (ProjectedSolidAngleSampler,
///   projected_solid_angle.hpp), which needs only the ellipse.
/// For the LD-radial maps the Shirley–Chiu concentric map comes first (u → (turns, radius^2) →
/// the weighting), as in the maps themselves, so the point set's stratification is kept across
/// the square's seam. The map itself serves a zero or NaN normal (the plain map).

#include <cmath>
#include <new>
#include <type_traits>

#include "config.hpp"
#include "detail/math.hpp"
#include "projected_cap.hpp"
#include "projected_solid_angle.hpp"
#include "sample.hpp"
#include "spherical_ellipse.hpp"
#include "detail/polar.hpp"
#include "detail/glm.hpp"
#include "detail/vector.hpp"
#include "maps/ld_radial.hpp"
#include "maps/tabulated_cosine.hpp"

namespace apse {
namespace detail {

/// What CosineWeighted learns from a map's own members: the map that serves the plain case and
/// carries the weighting (`Base`: the inner radial map of an LD-radial map — a map with
/// `radial()` — else the map itself), whether the concentric map comes first (`ld`: the map has
/// `radial()`) and whether the base is tabulated (`tabulated`: it has the warp's building
/// blocks, `lambda_fraction`).
template <class Map, class = void> struct CosineTraits {
    using Base = Map;
    static constexpr bool ld = false;
    static APSE_FUNC const Base& base(const Map& m) noexcept { return m; }
};
template <class Map> struct CosineTraits<Map, std::void_t<decltype(std::declval<const Map&>().radial())>> {
    using Base = std::decay_t<decltype(std::declval<const Map&>().radial())>;
    static constexpr bool ld = true;
    static APSE_FUNC const Base& base(const Map& m) noexcept { return m.radial(); }
};
template <class Base, class = void> struct is_tabulated_base : std::false_type {};
template <class Base>
struct is_tabulated_base<Base, std::void_t<decltype(std::declval<const Base&>().lambda_fraction(
                                   std::declval<typename Base::vec3::value_type>()))>> : std::true_type {};

/// CosineWeighted<Map> on a spherical cap, holding only what it uses there (`Plain` is
/// Map::CapSampler): ProjectedCapSampler for a usable receiver normal, the map's cap sampler for
/// a zero, NaN or infinite one (plain samples), empty when the map cannot sample or the cap is
/// entirely below the horizon — the same samples, pdf and invert as CosineWeighted<Map> built
/// from the cap, without building the map when the normal is usable. Built from a cap
/// (project_sphere's result); any other ellipse gives an empty sampler. Trivially copyable.
template <class Plain> class CapCosine {
public:
    using vec2 = typename Plain::vec2;       ///< a point of the unit square
    using vec3 = typename Plain::vec3;       ///< a 3-D vector (direction, point or normal)
    using T = typename vec3::value_type;     ///< float or double

    /// The sampler of `cap` (a SphericalEllipse, or detail::SphereCap: a sphere's cap without its
    /// frame, built only if the map's samples are used) for the receiver normal `normal` (the
    /// exact maps and ParallelMap).
    template <class Cap, class P = Plain, std::enable_if_t<std::is_constructible<P, const SphericalEllipse<T>&>::value, int> = 0>
    APSE_HOT_INLINE CapCosine(const Cap& cap, const vec3& normal) noexcept {
        init(cap, nullptr, normal);
    }

    /// The same for the tabulated maps, with the table their map would be given.
    template <class Cap, class P = Plain,
              std::enable_if_t<std::is_constructible<P, const SphericalEllipse<T>&, const TabulationView&>::value, int> = 0>
    APSE_HOT_INLINE CapCosine(const Cap& cap, const TabulationView& table, const vec3& normal) noexcept {
        init(cap, &table, normal);
    }

    /// True if the sampler cannot sample: every sample and pdf is then 0.
    APSE_FUNC bool empty() const noexcept { return mode_ == Mode::empty; }

    /// True if the samples are cosine-weighted (ProjectedCapSampler's).
    APSE_FUNC bool weighted() const noexcept { return mode_ == Mode::cap; }

    /// The cap sampled.
    APSE_FUNC SphericalEllipse<T> ellipse() const noexcept {
        return mode_ == Mode::cap ? u_.cap.ellipse() : u_.plain.ellipse();
    }

    /// CosineWeighted::sample.
    APSE_HOT_INLINE DirectionSample<T> sample(const vec2& u) const noexcept {
        if (mode_ == Mode::cap) return u_.cap.sample(u);
        if (mode_ == Mode::plain) return u_.plain.sample(u);
        return {u_.plain.ellipse().z, T(0)};
    }

    /// sample(u) placed on a sphere by `target` (SphereLight: detail::SphereTarget) the way the
    /// sampler in use does it.
    template <class Target>
    APSE_HOT_INLINE PointSample<T> sample_on_sphere(const vec2& u, const Target& target) const noexcept {
        if (mode_ == Mode::cap) return target.sample(u_.cap, u);
        if (mode_ == Mode::plain) return target.sample(u_.plain, u);
        return target.place(sample(u), T(0));
    }

    /// CosineWeighted::pdf.
    APSE_FUNC T pdf(const vec3& d) const noexcept {
        if (mode_ == Mode::cap) return u_.cap.pdf(d);
        if (mode_ == Mode::empty) return T(0);
        const T p = u_.plain.pdf(d);
        return p > T(0) ? p : T(0);
    }

    /// CosineWeighted::invert.
    APSE_FUNC vec2 invert(const vec3& d) const noexcept {
        if (mode_ == Mode::plain) return u_.plain.invert(d);
        if (mode_ == Mode::empty) return vec2(T(0));
        return u_.cap.invert(d);
    }

private:
    /// The modes of CosineWeighted that a cap reaches.
    enum class Mode : int { empty, plain, cap };

    /// CosineWeighted's choice on a cap: `table` is null for the maps built without one.
    /// ProjectedCapSampler first: it checks the normal and the cap itself, and when it can
    /// sample, so can the map (its density 1/Omega is finite whenever ProjectedCapSampler's is,
    /// with its margin: Omega >= Omega_perp), so only a tabulated map's table is checked there.
    template <class Cap>
    APSE_HOT_INLINE void init(const Cap& cap, const TabulationView* table, const vec3& normal) noexcept {
        mode_ = Mode::empty;
        if (!table || table_usable(*table)) {
            new (&u_.cap) detail::ProjectedCapSampler<T>(cap, normal);  // built in place: no copy
            if (!u_.cap.empty()) {
                mode_ = Mode::cap;
                return;
            }
        }
        if constexpr (std::is_constructible<Plain, const SphericalEllipse<T>&, const TabulationView&>::value) {
            new (&u_.plain) Plain(ellipse_of(cap), *table);
        } else {
            new (&u_.plain) Plain(ellipse_of(cap));
        }
        const T scale = max_abs3(normal);
        const bool normal_ok = scale > T(0) && is_finite(scale) && finite3(normal);
        if (!normal_ok && !u_.plain.empty()) mode_ = Mode::plain;
    }

    Mode mode_;
    /// The sampler in use (mode_): the cap sampler, or the map's (also for an empty sampler, for
    /// its ellipse). A union: building one writes only the member it uses.
    union Samplers {
        APSE_FUNC Samplers() noexcept : none() {}
        char none;
        Plain plain;
        detail::ProjectedCapSampler<T> cap;
    } u_;
};

/// The member CosineWeighted holds in place of TabulatedCosineWarp for the exact maps.
struct NoCosineWarp {};

}  // namespace detail

// RuntimeSampler holds a CosineWeighted in a union next to the plain maps and picks the live
// member at run time; g++ cannot correlate the two and reports -Wmaybe-uninitialized on mode_ in
// the members' bodies when the union's other member is the live one (a false positive: the branch
// that reads it is not taken). Silenced for this class only.
#if defined(__GNUC__) && !defined(__clang__) && !defined(__CUDACC__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif

/// Cosine-weighted sampling of a spherical ellipse (file comment; docs/cosine_weighted.md):
/// `Map` is RadialMap<T>, LdRadialMap<T>, ParallelMap<T>, TabulatedMap<T> or
/// TabulatedLdRadialMap<T>; `Nodes` (a multiple of 4) is the number of azimuths at which the
/// azimuth's marginal is exact (the default is the measured trade-off between variance and
/// set-up cost; docs/cosine_weighted.md). Every sample lies above the receiver's horizon.
/// Measured: relMSE of irradiance far below the plain LD-radial map's at 16 jittered samples
/// (docs/cosine_weighted.md has the numbers and the cost). Trivially copyable (pass it to
/// kernels by value).
template <class Map, int Nodes = 8> class CosineWeighted {
    using Traits = detail::CosineTraits<Map>;
    using Base = typename Traits::Base;
    static constexpr bool tabulated = detail::is_tabulated_base<Base>::value;

public:
    using T = typename Map::vec3::value_type;  ///< float or double
    using vec2 = glm::vec<2, T>;  ///< a point of the unit square
    using vec3 = glm::vec<3, T>;  ///< a 3-D vector (direction, point or normal)
    /// What SphereLight holds for CosineWeighted<Map>: the same samples on a cap (a sphere's
    /// ellipse is always one), holding only the map's cap sampler or ProjectedCapSampler.
    using CapSampler = detail::CapCosine<typename Map::CapSampler>;

    /// Builds the sampler for the light `map` (any of the five maps, already built for the
    /// shading point) and the receiver's normal `normal` (world space, any non-zero finite length;
    /// the receiver's side is the one it points to). The light entirely below the receiver's
    /// horizon (max n·ω <= 0 over the ellipse, an exact test) or an empty map: empty(), every
    /// pdf 0. A zero, NaN or infinite normal: no weighting — the samples, pdf and invert of the
    /// plain map (`weighted()` is then false). A tabulated map uses the warp when the normal's
    /// component along the ellipse's axis exceeds 1e-3 of its largest component in the ellipse's
    /// frame (the centre above the horizon), the exact sampler otherwise. A spherical cap
    /// (`ellipse().is_cap()`), for every map: ProjectedCapSampler (empty() when the cap is
    /// entirely below the horizon).
    APSE_FUNC CosineWeighted(const Map& map, const vec3& normal) noexcept
        : mode_(Mode::empty), base_(Traits::base(map)) {
        if (base_.empty()) return;
        const T scale = detail::max_abs3(normal);
        if (!(scale > T(0)) || !detail::is_finite(scale) || !detail::finite3(normal)) {
            mode_ = Mode::plain;
            return;
        }
        if (base_.ellipse().is_cap()) {
            new (&w_.cap) detail::ProjectedCapSampler<T>(base_.ellipse(), normal);  // built in place: no copy of the sampler
            if (!w_.cap.empty()) mode_ = Mode::cap;
            return;
        }
        if constexpr (tabulated) {
            const vec3 nl = base_.ellipse().to_local(normal * (T(1) / scale));
            if (nl.z > T(1e-3) * detail::max_abs3(nl)) {
                w_.warp.build(base_, nl);
                mode_ = Mode::warped;
                return;
            }
        }
        w_.psa = detail::ProjectedSolidAngleSampler<T, Nodes>(base_.ellipse(), normal);
        if (!w_.psa.empty()) mode_ = Mode::exact;
    }

    /// CosineWeighted(Map(ellipse), normal): the sampler built from the light's ellipse directly,
    /// for the maps built from an ellipse alone (RadialMap, LdRadialMap, ParallelMap).
    template <class M = Map, std::enable_if_t<std::is_constructible<M, const SphericalEllipse<T>&>::value, int> = 0>
    APSE_FUNC CosineWeighted(const SphericalEllipse<T>& ellipse, const vec3& receiver_normal) noexcept
        : CosineWeighted(Map(ellipse), receiver_normal) {}

    /// CosineWeighted(Map(ellipse, table), normal): the same for the tabulated maps
    /// (TabulatedMap, TabulatedLdRadialMap), built from the ellipse and a table.
    template <class M = Map, std::enable_if_t<std::is_constructible<M, const SphericalEllipse<T>&, const TabulationView&>::value, int> = 0>
    APSE_FUNC CosineWeighted(const SphericalEllipse<T>& ellipse, const TabulationView& table, const vec3& receiver_normal) noexcept
        : CosineWeighted(Map(ellipse, table), receiver_normal) {}

    /// True if the sampler cannot sample (empty map or light entirely below the horizon): every
    /// sample and pdf is then 0.
    APSE_FUNC bool empty() const noexcept { return mode_ == Mode::empty; }

    /// True if the samples are cosine-weighted (false for an empty sampler or a zero/NaN normal).
    APSE_FUNC bool weighted() const noexcept { return mode_ == Mode::exact || mode_ == Mode::warped || mode_ == Mode::cap; }

    /// True if the samples come from ProjectedCapSampler (the ellipse is a cap and the normal
    /// usable): their density is exactly max(0, n·ω) / Omega_perp.
    APSE_FUNC bool exact_cap() const noexcept { return mode_ == Mode::cap; }

    /// The ellipse sampled.
    APSE_FUNC const SphericalEllipse<T>& ellipse() const noexcept { return base_.ellipse(); }

    /// Direction for the point u of the unit square (clamped into [0, 1]^2): a world-space unit
    /// vector inside the ellipse, above the receiver's horizon when weighted(), with its exact
    /// density in solid angle (the warp's or ProjectedSolidAngleSampler's sample, after the
    /// concentric map for the LD-radial maps; ProjectedCapSampler's for a cap, u as it is, for
    /// every map). NaN u or empty(): pdf 0 and the ellipse's centre direction.
    APSE_FUNC DirectionSample<T> sample(const vec2& u) const noexcept {
        if (mode_ == Mode::empty) return {base_.ellipse().z, T(0)};
        if (mode_ == Mode::plain) {  // the plain map's own sample
            if constexpr (Traits::ld) {
                int iterations = 0;
                return detail::ld_sample(base_, true, u, iterations);
            } else {
                return base_.sample(u);
            }
        }
        if (mode_ == Mode::cap) return w_.cap.sample(u);
        bool ok = true;
        const vec2 uc = detail::clamp_unit(u, ok);
        if (!ok) return {base_.ellipse().z, T(0)};
        if constexpr (tabulated) {
            if (mode_ == Mode::warped) {
                if constexpr (!Traits::ld) return w_.warp.sample(base_, uc.x, uc.y, std::sqrt(uc.y));
                // the concentric map's (turns, radius), without branches
                const detail::ConcentricFold<T> d = detail::concentric_fold(uc);
                return w_.warp.sample(base_, detail::unfold_quadrant(d.fold), d.radius2, d.radius);
            }
        }
        vec2 v = uc;
        if (Traits::ld) {
            const detail::ConcentricPolar<T> d = detail::concentric_to_disk(uc);
            v = vec2(d.turns, d.radius * d.radius);
        }
        return w_.psa.sample(v);
    }

    /// Density of sample() at the world-space direction `d` (any non-zero length), in solid
    /// angle: 0 outside the ellipse, below the horizon (when weighted()), for empty() or a
    /// zero/NaN direction. Equals the pdf sample() reports.
    APSE_FUNC T pdf(const vec3& d) const noexcept {
        if (mode_ == Mode::empty) return T(0);
        if (mode_ == Mode::exact) return w_.psa.pdf(d);
        if (mode_ == Mode::cap) return w_.cap.pdf(d);
        if constexpr (tabulated) {
            if (mode_ == Mode::warped) {
                vec3 l;
                return local(d, l) && base_.ellipse().contains(d) ? w_.warp.pdf(base_, l) : T(0);
            }
        }
        const T p = base_.pdf(d);
        return p > T(0) ? p : T(0);
    }

    /// The point of the unit square whose sample has direction `d` (the sampler's inverse, then
    /// the concentric map's for the LD-radial maps; ProjectedCapSampler's inverse for a cap).
    /// Outside the ellipse: clamped formulas.
    /// Zero/NaN direction or empty(): (0, 0).
    APSE_FUNC vec2 invert(const vec3& d) const noexcept {
        vec3 l;
        if (mode_ == Mode::empty || !local(d, l)) return vec2(T(0));
        if (mode_ == Mode::cap) return w_.cap.invert(d);
        vec2 v;
        if constexpr (tabulated) {
            if (mode_ == Mode::warped) v = w_.warp.invert(base_, l);
        }
        if (mode_ != Mode::warped) v = mode_ == Mode::exact ? w_.psa.invert(d) : base_.invert(d);
        if (Traits::ld) return detail::concentric_from_disk(std::sqrt(detail::clamp(v.y, T(0), T(1))), v.x);
        return v;
    }

private:
    /// The unit local direction l of the world-space direction d; false if d is zero, NaN or
    /// infinite.
    APSE_FUNC bool local(const vec3& d, vec3& l) const noexcept {
        bool ok = true;
        l = detail::normalize_direction(base_.ellipse().to_local(d), ok);
        return ok;
    }

    enum class Mode : int { empty, plain, exact, warped, cap };  // exact: ProjectedSolidAngleSampler; cap: ProjectedCapSampler
    using Warp = std::conditional_t<tabulated, detail::TabulatedCosineWarp<T, Nodes>, detail::NoCosineWarp>;
    Mode mode_;
    Base base_;
    /// The weighting in use (mode_): none, the exact sampler, the cap sampler or the warp. A union: building a
    /// CosineWeighted writes only the member it uses.
    union Weighting {
        APSE_FUNC Weighting() noexcept : none() {}
        detail::NoCosineWarp none;
        detail::ProjectedSolidAngleSampler<T, Nodes> psa;
        detail::ProjectedCapSampler<T> cap;
        Warp warp;
    } w_;
};

#if defined(__GNUC__) && !defined(__clang__) && !defined(__CUDACC__)
#pragma GCC diagnostic pop
#endif

}  // namespace apse
