// apse — area-preserving parameterizations for spherical ellipses.
// SPDX-License-Identifier: MIT
#pragma once

/// @file comparison.hpp
/// The maps apse measures its recommended ones against, for comparisons and tests (not included
/// by apse.hpp):
/// * `RadialMap<T>`: the paper's radial map (docs/math.md §4) — LdRadialMap without the concentric
///   map first, so discontinuous where u1 wraps (stratification suffers there);
/// * `TabulatedMap<T>`: the unbiased tabulated radial map (docs/math.md §6) — TabulatedLdRadialMap
///   without the concentric map.
/// Both are the building blocks of their LD-radial forms and satisfy the same sampler concept
/// (sample / pdf / invert / empty / ellipse; CosineWeighted, DiskLight and SphereLight take them).

#include "maps/radial.hpp"
#include "maps/tabulated_ld_radial.hpp"

namespace apse {

using detail::RadialMap;
using detail::TabulatedMap;

}  // namespace apse
