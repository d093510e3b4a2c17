// apse — area-preserving parameterizations for spherical ellipses.
// SPDX-License-Identifier: MIT
#pragma once

/// @file maps/tabulated_ld_radial.hpp
/// `TabulatedLdRadialMap<T>`: the recommended map — the LD-radial composition (maps/ld_radial.hpp)
/// over the unbiased tabulated radial map (maps/tabulated.hpp, docs/math.md §6): no elliptic
/// integral per shading point, the exact density it draws from reported.

#include "../config.hpp"
#include "../sample.hpp"
#include "../spherical_ellipse.hpp"
#include "../detail/glm.hpp"
#include "../detail/math.hpp"
#include "cap.hpp"
#include "ld_radial.hpp"
#include "tabulated.hpp"
#include "tabulation_table.hpp"

namespace apse {

/// Tabulated LD-radial map (docs/math.md §4 + §6, unbiased): the Shirley–Chiu concentric map first,
/// then the tabulated radial map (comparison.hpp's TabulatedMap) with u1 = angle/(2 pi),
/// u2 = radius^2 (detail::LdComposition, as LdRadialMap over the radial map). Continuous on the
/// closed square; the same density, pdf, accuracy and table as the tabulated radial map: pdf is
/// exactly the density drawn from (within 0.44 % of 1/Omega for the default table). Holds a
/// pointer into the table (which must outlive the map). Trivially copyable.
template <class T> class TabulatedLdRadialMap : public detail::LdComposition<detail::TabulatedMap<T>> {
    static_assert(detail::is_real_type<T>(), "apse: TabulatedLdRadialMap<T>: T must be float or double");

public:
    /// What SphereLight holds for this map: the same samples on a cap, without the table walk
    /// (maps/cap.hpp).
    using CapSampler = detail::CapMap<T, true, true>;

    /// Builds the map for `ellipse` reading `table` (empty ellipse or invalid view: pdf 0
    /// everywhere).
    APSE_FUNC TabulatedLdRadialMap(const SphericalEllipse<T>& ellipse, const TabulationView& table) noexcept
        : detail::LdComposition<detail::TabulatedMap<T>>(ellipse, table) {}
};

}  // namespace apse
