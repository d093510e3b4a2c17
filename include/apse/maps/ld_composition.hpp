// apse — area-preserving parameterizations for spherical ellipses.
// SPDX-License-Identifier: MIT
#pragma once

/// @file maps/ld_composition.hpp
/// The LD-radial composition (docs/math.md §4), written once for LdRadialMap (over RadialMap) and
/// TabulatedLdRadialMap (over TabulatedMap): the Shirley–Chiu concentric map first
/// (detail/concentric.hpp), then the radial-type map with u1 = angle/(2 pi) (azimuthal area
/// fraction) and u2 = radius^2 (radial solid-angle fraction); the inverse goes back the same way.
/// The concentric map preserves area, so the composition has the radial map's density.
///
/// `Radial` is RadialMap<T> or TabulatedMap<T>: it provides `ellipse()`, the counting sample
/// (reached through DiagnosticsAccess, sample.hpp) and `local_coordinates(l)` (docs/math.md §4
/// inverse on the unit local direction l; reached through MapAccess, detail/map_access.hpp).

#include <cmath>

#include "../config.hpp"
#include "../sample.hpp"
#include "../detail/concentric.hpp"
#include "../detail/glm.hpp"
#include "../detail/map_access.hpp"
#include "../detail/math.hpp"
#include "../detail/quadrant.hpp"

namespace apse {
namespace detail {

/// sample() of the LD composition over `radial` (`valid`: the radial map can sample). u is
/// clamped into [0, 1]^2; a NaN coordinate or !valid gives pdf 0 and the centre direction, with
/// `iterations` = 0; otherwise the radial map's sample at (turns, radius^2) of the concentric
/// image of u (already in [0, 1]^2), its pdf and its `iterations`.
template <class T, class Radial>
APSE_FUNC DirectionSample<T> ld_sample(const Radial& radial, bool valid, const glm::vec<2, T>& u,
                                       int& iterations) noexcept {
    iterations = 0;
    bool ok = valid;
    const glm::vec<2, T> uc = clamp_unit(u, ok);
    if (!ok) return {radial.ellipse().z, T(0)};
    const ConcentricPolar<T> disk = concentric_to_disk(uc);
    return DiagnosticsAccess::sample(radial, glm::vec<2, T>(disk.turns, disk.radius * disk.radius), iterations);
}

/// invert() of the LD composition over `radial`: the radial map's (u1, u2) of the world-space
/// direction `d` (any non-zero length), then the inverse concentric map of (radius sqrt(u2),
/// turns u1). !valid or a zero/NaN/infinite direction gives (0, 0).
template <class T, class Radial>
APSE_FUNC glm::vec<2, T> ld_invert(const Radial& radial, bool valid, const glm::vec<3, T>& d) noexcept {
    if (!valid) return glm::vec<2, T>(T(0));
    bool ok = true;
    const glm::vec<3, T> l = normalize_direction(radial.ellipse().to_local(d), ok);
    if (!ok) return glm::vec<2, T>(T(0));
    const glm::vec<2, T> polar = MapAccess::local_coordinates(radial, l);
    return concentric_from_disk(std::sqrt(polar.y), polar.x);
}

}  // namespace detail
}  // namespace apse
