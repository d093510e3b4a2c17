// apse — area-preserving parameterizations for spherical ellipses.
// SPDX-License-Identifier: MIT
#pragma once

/// @file detail/map_access.hpp
/// `MapAccess`: the door through which apse's own code and its tests reach the maps' private
/// building blocks (the maps befriend it). A user samples through the public sampler concept
/// (sample / pdf / invert); these are the pieces under it.

#include "../config.hpp"

namespace apse {
namespace detail {

/// Static forwarders to the maps' private building blocks.
struct MapAccess {
    /// map.local_coordinates(l): (u1, u2) in [0, 1]^2 of the unit local direction `l`
    /// (RadialMap, TabulatedMap; the LD-radial maps' inverse goes through it).
    template <class Map, class V>
    static APSE_FUNC auto local_coordinates(const Map& map, const V& l) noexcept {
        return map.local_coordinates(l);
    }

    /// map.sample_folded(fold, u2, iterations): RadialMap's / TabulatedMap's sample at the
    /// quadrant and quadrant-area fraction `fold` and the radial fraction u2 (the LD-radial
    /// composition's entry, maps/ld_radial.hpp).
    template <class Map, class Fold, class T>
    static APSE_FUNC auto sample_folded(const Map& map, const Fold& fold, T u2, int& iterations) noexcept {
        return map.sample_folded(fold, u2, iterations);
    }

    /// TabulatedMap's pieces of one sample, for the cosine-weighted warp over it
    /// (detail/tabulated_cosine.hpp): the ray of a folded u1 (table walk included), the ray at a
    /// Lambert anomaly, the sample along a ray, the quadrant fraction of a Lambert anomaly and a
    /// local direction's coordinates, azimuth and density.
    template <class Map, class Fold>
    static APSE_FUNC auto ray_folded(const Map& map, const Fold& fold, int& steps) noexcept {
        return map.ray_folded(fold, steps);
    }
    template <class Map, class Fold, class T>
    static APSE_FUNC auto ray_at(const Map& map, const Fold& fold, T x, T df) noexcept {
        return map.ray_at(fold, x, df);
    }
    template <class Map, class Ray, class T>
    static APSE_FUNC auto ray_sample(const Map& map, const Ray& ray, T u2) noexcept {
        return map.ray_sample(ray, u2);
    }
    template <class Map, class T> static APSE_FUNC T lambda_fraction(const Map& map, T x) noexcept {
        return map.lambda_fraction(x);
    }
    template <class Map, class V> static APSE_FUNC auto local_point(const Map& map, const V& l) noexcept {
        return map.local_point(l);
    }
    /// map.solve_quadrant(f, iterations): RadialMap's boundary state at the fraction f of the
    /// quadrant's area, with the inversion iterations.
    template <class Map, class T>
    static APSE_FUNC auto solve_quadrant(const Map& map, T f, int& iterations) noexcept {
        return map.solve_quadrant(f, iterations);
    }

    /// map.quadrant_area(phi): RadialMap's cumulative area of the first quadrant up to the
    /// azimuth phi in [0, pi/2].
    template <class Map, class T> static APSE_FUNC T quadrant_area(const Map& map, T phi) noexcept {
        return map.quadrant_area(phi);
    }

    /// map.solve_half(g, iterations): ParallelMap's slice state at the edge fraction g of a half,
    /// with the inversion iterations.
    template <class Map, class T>
    static APSE_FUNC auto solve_half(const Map& map, T g, int& iterations) noexcept {
        return map.solve_half(g, iterations);
    }

    /// map.half_area(psi): ParallelMap's half-area I(psi) between the slices 0 and psi in [0, beta].
    template <class Map, class T> static APSE_FUNC T half_area(const Map& map, T psi) noexcept {
        return map.half_area(psi);
    }
};

}  // namespace detail
}  // namespace apse
