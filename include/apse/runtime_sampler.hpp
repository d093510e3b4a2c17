// apse — area-preserving parameterizations for spherical ellipses.
// SPDX-License-Identifier: MIT
#pragma once

/// @file runtime_sampler.hpp
/// `RuntimeSampler<T>`: the map chosen at run time (a scene file's string, a command-line flag),
/// plain or cosine-weighted, for any shape — it is built from a SphericalEllipse, so it serves
/// DiskLight, SphereLight and a projected ellipse or ellipsoid alike. Not included by apse.hpp: a
/// renderer that knows its map at compile time uses the map's type directly and pays for nothing
/// else; this one holds the largest of the samplers it can be.
///
///     const apse::TabulationView table = apse::default_table().view();
///     apse::MapKind kind = apse::MapKind::tabulated_ld_radial;    // e.g. parsed from the scene
///     apse::DiskLight<apse::RuntimeSampler<float>> light(o, center, normal, radius, kind, table);
///     apse::SphereLight<apse::RuntimeSampler<float>> ball(o, c, r, kind, table, n_r);  // cosine-weighted
///
/// Adding a map: its header, its test, and one entry in MapKind with its type in
/// detail::RuntimeMaps below.

#include <new>
#include <type_traits>

#include "config.hpp"
#include "cosine_weighted.hpp"
#include "sample.hpp"
#include "spherical_ellipse.hpp"
#include "detail/glm.hpp"
#include "detail/math.hpp"
#include "maps/ld_radial.hpp"
#include "maps/parallel.hpp"
#include "maps/radial.hpp"
#include "maps/tabulated_ld_radial.hpp"
#include "maps/tabulation_table.hpp"

namespace apse {

/// The maps a RuntimeSampler can be, in the order of detail::RuntimeMaps.
enum class MapKind : int {
    radial,               ///< RadialMap (comparison.hpp; docs/math.md §4)
    ld_radial,            ///< LdRadialMap: exact, continuous on the whole square
    parallel,             ///< ParallelMap (docs/math.md §5)
    tabulated,            ///< TabulatedMap (comparison.hpp; docs/math.md §6; needs a table)
    tabulated_ld_radial,  ///< TabulatedLdRadialMap (needs a table): the recommended map
};

namespace detail {

template <class... S> struct TypeList {
    static constexpr int size = int(sizeof...(S));
};

/// A union of the samplers S..., one of them alive (built in place); trivially copyable and
/// destructible when they all are. `visit(i, f)` calls f on the member i.
template <class... S> union OneOf;
template <> union OneOf<> {
    char none;
    APSE_FUNC OneOf() noexcept : none() {}
};
template <class S0, class... Rest> union OneOf<S0, Rest...> {
    S0 head;
    OneOf<Rest...> tail;
    APSE_FUNC OneOf() noexcept : tail() {}

    /// Builds the member i with `make(type_tag)` (make returns the member's value).
    template <class Make> APSE_FUNC void emplace(int i, const Make& make) noexcept {
        if (i == 0) {
            new (&head) S0(make(static_cast<S0*>(nullptr)));
            return;
        }
        if constexpr (sizeof...(Rest) > 0) tail.emplace(i - 1, make);
    }

    /// f(member i) (i out of range: the last member).
    template <class F> APSE_FUNC decltype(auto) visit(int i, F&& f) const noexcept {
        if constexpr (sizeof...(Rest) == 0) {
            return f(head);
        } else {
            if (i == 0) return f(head);
            return tail.visit(i - 1, f);
        }
    }
};

template <class Plain, class Cosine> struct OneOfBoth;
template <class... P, class... C> struct OneOfBoth<TypeList<P...>, TypeList<C...>> {
    using type = OneOf<P..., C...>;
    /// True if every sampler's ellipse() returns a reference (the cap samplers of CosineWeighted
    /// return a copy: they rebuild theirs).
    static constexpr bool ellipse_by_reference =
        (std::is_reference<decltype(std::declval<const P&>().ellipse())>::value && ...) &&
        (std::is_reference<decltype(std::declval<const C&>().ellipse())>::value && ...);
};

/// True if the map `Map` is built from (ellipse, table): the tabulated maps.
template <class Map>
constexpr bool reads_table =
    std::is_constructible<Map, const SphericalEllipse<typename Map::vec3::value_type>&, const TabulationView&>::value;

/// f(table) for the maps that read a table, f() for the others: the arguments after the
/// ellipse (or after a light's geometry) that build the map `Map`.
template <class Map, class F> APSE_HOT_INLINE decltype(auto) with_table_if_read(const TabulationView& table, F&& f) noexcept {
    if constexpr (reads_table<Map>) return f(table);
    else return f();
}

/// True if the sampler S takes a receiver normal after the ellipse (and the table): the
/// cosine-weighted samplers.
template <class S, class T>
constexpr bool takes_normal =
    std::is_constructible<S, const SphericalEllipse<T>&, const glm::vec<3, T>&>::value ||
    std::is_constructible<S, const SphericalEllipse<T>&, const TabulationView&, const glm::vec<3, T>&>::value;

/// The sampler S of the ellipse `e`: S(e[, table][, normal]), with the table where S reads one
/// and the receiver normal where S takes one (the cosine-weighted samplers).
template <class S, class T>
APSE_FUNC S make_sampler(const SphericalEllipse<T>& e, const TabulationView& table, const glm::vec<3, T>& normal) noexcept {
    if constexpr (std::is_constructible<S, const SphericalEllipse<T>&, const TabulationView&, const glm::vec<3, T>&>::value)
        return S(e, table, normal);
    else if constexpr (takes_normal<S, T>)
        return S(e, normal);
    else if constexpr (reads_table<S>)
        return S(e, table);
    else
        return S(e);
}

}  // namespace detail

// g++ cannot see that only the live union member is read (the visit's index says which) and
// reports -Wmaybe-uninitialized on the other members' fields; a false positive, silenced here.
#if defined(__GNUC__) && !defined(__clang__) && !defined(__CUDACC__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif

namespace detail {

/// The sampler chosen at run time among `Plain` (a TypeList of samplers built from an ellipse,
/// and a table if they read one, in MapKind's order) and `Cosine` (their cosine-weighted
/// counterparts, built with the receiver normal too): RuntimeSampler over the maps, and its
/// CapSampler over what they do on a cap. One sampler in a union (its size is the largest's);
/// trivially copyable. An out-of-range kind gives the empty sampler.
template <class T, class Plain, class Cosine> class RuntimeChoice {
public:
    using vec2 = glm::vec<2, T>;  ///< a point of the unit square
    using vec3 = glm::vec<3, T>;  ///< a 3-D vector (direction, point or normal)

    /// The map `kind` of `ellipse`, plain (the tabulated maps read `table`; without a valid
    /// table they are empty).
    APSE_NOINLINE APSE_FUNC RuntimeChoice(const SphericalEllipse<T>& ellipse, MapKind kind,
                                          const TabulationView& table = TabulationView{nullptr, 0, 0, 0}) noexcept
        : kind_(kind), cosine_(false) {
        build(ellipse, table, nullptr);
    }

    /// CosineWeighted over the map `kind` of `ellipse`, for the receiver normal
    /// `receiver_normal` (CosineWeighted's contract: a zero or non-finite normal gives the plain
    /// map's samples, weighted() false).
    APSE_NOINLINE APSE_FUNC RuntimeChoice(const SphericalEllipse<T>& ellipse, MapKind kind, const TabulationView& table,
                                          const vec3& receiver_normal) noexcept
        : kind_(kind), cosine_(true) {
        build(ellipse, table, &receiver_normal);
    }

    /// The same over an exact map, without a table (a tabulated kind gives the empty sampler).
    APSE_FUNC RuntimeChoice(const SphericalEllipse<T>& ellipse, MapKind kind, const vec3& receiver_normal) noexcept
        : RuntimeChoice(ellipse, kind, TabulationView{nullptr, 0, 0, 0}, receiver_normal) {}

    /// The map chosen.
    APSE_FUNC MapKind kind() const noexcept { return kind_; }

    /// True if built with a receiver normal (CosineWeighted over the map).
    APSE_FUNC bool cosine() const noexcept { return cosine_; }

    /// True if the samples are cosine-weighted (CosineWeighted::weighted()).
    APSE_FUNC bool weighted() const noexcept {
        return visit([](const auto& s) { return detail::weighted_of(s, 0); });
    }

    /// True if the sampler cannot sample: every sample and pdf is then 0.
    APSE_FUNC bool empty() const noexcept {
        return visit([](const auto& s) { return s.empty(); });
    }

    /// The ellipse sampled: a reference to the chosen sampler's, or a copy where the samplers
    /// return one (the cap samplers of a sphere light's CosineWeighted rebuild theirs).
    using EllipseResult = std::conditional_t<detail::OneOfBoth<Plain, Cosine>::ellipse_by_reference,
                                             const SphericalEllipse<T>&, SphericalEllipse<T>>;
    APSE_FUNC EllipseResult ellipse() const noexcept {
        return visit([](const auto& s) -> EllipseResult { return s.ellipse(); });
    }

    /// The chosen sampler's sample(u).
    APSE_NOINLINE APSE_FUNC DirectionSample<T> sample(const vec2& u) const noexcept {
        return visit([&u](const auto& s) { return s.sample(u); });
    }

    /// The chosen sampler's sample(u) placed on a sphere by `target.sample(sampler, u)`
    /// (SphereLight: detail::SphereTarget), the same as with the chosen sampler's own type.
    template <class Target>
    APSE_NOINLINE APSE_FUNC PointSample<T> sample_on_sphere(const vec2& u, const Target& target) const noexcept {
        return visit([&](const auto& s) { return target.sample(s, u); });
    }

    /// The chosen sampler's pdf(d).
    APSE_NOINLINE APSE_FUNC T pdf(const vec3& d) const noexcept {
        return visit([&d](const auto& s) { return s.pdf(d); });
    }

    /// The chosen sampler's invert(d).
    APSE_NOINLINE APSE_FUNC vec2 invert(const vec3& d) const noexcept {
        return visit([&d](const auto& s) { return s.invert(d); });
    }

private:
    static constexpr int map_count = Plain::size;
    static_assert(Plain::size == Cosine::size, "one cosine-weighted sampler per map");

    APSE_FUNC int index() const noexcept { return int(kind_) + (cosine_ ? map_count : 0); }

    template <class F> APSE_FUNC decltype(auto) visit(F&& f) const noexcept { return samplers_.visit(index(), f); }

    /// Builds the sampler of the index(); an out-of-range kind: the empty LD-radial map.
    APSE_FUNC void build(const SphericalEllipse<T>& e, const TabulationView& table, const vec3* n) noexcept {
        if (!(int(kind_) >= 0 && int(kind_) < map_count)) {
            kind_ = MapKind::ld_radial;
            build(SphericalEllipse<T>::make_empty(), table, n);
            return;
        }
        samplers_.emplace(index(), [&](auto* tag) {
            return detail::make_sampler<std::remove_pointer_t<decltype(tag)>>(e, table, n ? *n : vec3(T(0)));
        });
    }

    MapKind kind_;
    bool cosine_;
    typename detail::OneOfBoth<Plain, Cosine>::type samplers_;
};

}  // namespace detail

namespace detail {

/// The maps a RuntimeSampler can be, in MapKind's order.
template <class T>
using RuntimeMaps = TypeList<RadialMap<T>, LdRadialMap<T>, ParallelMap<T>, TabulatedMap<T>, TabulatedLdRadialMap<T>>;

/// CosineWeighted over each sampler of a TypeList.
template <class List> struct CosineOf;
template <class... S> struct CosineOf<TypeList<S...>> {
    using type = TypeList<CosineWeighted<S>...>;
};

/// The CapSampler of each sampler of a TypeList.
template <class List> struct CapSamplersOf;
template <class... S> struct CapSamplersOf<TypeList<S...>> {
    using type = TypeList<typename S::CapSampler...>;
};

/// RuntimeSampler's choice: the maps and CosineWeighted over each.
template <class T> using RuntimeMapChoice = RuntimeChoice<T, RuntimeMaps<T>, typename CosineOf<RuntimeMaps<T>>::type>;

}  // namespace detail

/// A sampler of a spherical ellipse whose map (MapKind) and cosine weighting are chosen at run
/// time: exactly the samples, pdf and invert of the map — or of CosineWeighted over it — built
/// from the same arguments (the constructors of detail::RuntimeChoice: ellipse, kind, then the
/// table, then the receiver normal). The sampler concept (sample / pdf / invert / empty /
/// ellipse), so it plugs into DiskLight and SphereLight; in SphereLight it holds what each map
/// does on a cap (CapSampler), as SphereLight<Map> does. Holds one sampler in a union (its size
/// is the largest's); trivially copyable. An out-of-range kind gives the empty sampler.
template <class T> class RuntimeSampler : public detail::RuntimeMapChoice<T> {
    static_assert(detail::is_real_type<T>(), "apse: RuntimeSampler<T>: T must be float or double");

public:
    /// The maps, in MapKind's order.
    using Maps = detail::RuntimeMaps<T>;
    /// What SphereLight holds: the same choice among the maps' cap samplers (maps/cap.hpp) and
    /// CosineWeighted's, built from the same arguments.
    using CapSampler = detail::RuntimeChoice<T, typename detail::CapSamplersOf<Maps>::type,
                                             typename detail::CapSamplersOf<typename detail::CosineOf<Maps>::type>::type>;

    using Base = detail::RuntimeMapChoice<T>;  ///< the constructors' class
    using Base::Base;
};

#if defined(__GNUC__) && !defined(__clang__) && !defined(__CUDACC__)
#pragma GCC diagnostic pop
#endif

}  // namespace apse
