// apse — area-preserving parameterizations for spherical ellipses.
// SPDX-License-Identifier: MIT
#pragma once

/// @file maps/ld_radial.hpp
/// `LdRadialMap<T>`: the paper's LD-radial ("low-distortion radial") map (authors' code:
/// `concentric`), docs/math.md §4 — the Shirley–Chiu concentric map first, then the radial map with
/// u1 = angle/(2 pi) (azimuthal area fraction) and u2 = radius^2 (radial solid-angle fraction).
/// Both steps preserve area, so the composition does; it is continuous on the whole closed
/// square (centre → ellipse centre, boundary → ellipse boundary).
///
/// The composition itself (detail::LdComposition, detail/polar.hpp) is written once for
/// LdRadialMap (over RadialMap) and TabulatedLdRadialMap (over TabulatedMap).

#include <cmath>

#include "../config.hpp"
#include "../detail/math.hpp"
#include "../sample.hpp"
#include "../spherical_ellipse.hpp"
#include "../detail/glm.hpp"
#include "../detail/polar.hpp"
#include "cap.hpp"
#include "radial.hpp"

namespace apse {

/// LD-radial area-preserving map of the unit square onto a spherical ellipse (docs/math.md §4):
/// the radial map (comparison.hpp's RadialMap) composed with the concentric map
/// (detail::LdComposition; the same set-up, inversion and accuracy as the radial map),
/// continuous on the whole closed square; density 1/Omega. Trivially copyable.
template <class T> class LdRadialMap : public detail::LdComposition<detail::RadialMap<T>> {
    static_assert(detail::is_real_type<T>(), "apse: LdRadialMap<T>: T must be float or double");

public:
    /// What SphereLight holds for this map: the same samples on a cap, without the
    /// general-ellipse path (maps/cap.hpp).
    using CapSampler = detail::CapMap<T, true, false>;

    /// Builds the map for `ellipse` (empty allowed: every sample then has pdf 0).
    APSE_HOT_INLINE explicit LdRadialMap(const SphericalEllipse<T>& ellipse) noexcept
        : detail::LdComposition<detail::RadialMap<T>>(ellipse) {}

    /// Solid angle Omega of the ellipse (steradians); 0 when empty.
    APSE_FUNC T solid_angle() const noexcept { return this->radial_.solid_angle(); }
};

}  // namespace apse
