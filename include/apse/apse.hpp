// apse — area-preserving parameterizations for spherical ellipses.
// SPDX-License-Identifier: MIT
#pragma once

/// @file apse.hpp
/// The umbrella header: what a renderer needs to sample disk, sphere, ellipse and ellipsoid
/// lights — the spherical ellipse and the projections that make one, the recommended maps
/// (TabulatedLdRadialMap and its table, LdRadialMap, ParallelMap), CosineWeighted, DiskLight,
/// SphereLight and the sample types. `tools/public_names.py` counts what it brings into `apse::`
/// (a test keeps it at 25 or fewer).
///
/// Opt-in headers, not included here: runtime_sampler.hpp (the map chosen at run time),
/// comparison.hpp (RadialMap, TabulatedMap: the maps apse measures against), baselines/area.hpp
/// and baselines/gamito.hpp (the published baselines), spherical_rectangle.hpp (rectangle
/// lights), elliptic.hpp (the elliptic integrals), diagnostics.hpp (what a sample cost),
/// math.hpp (the scalar constants).

#include "config.hpp"
#include "sample.hpp"
#include "spherical_ellipse.hpp"
#include "disk_frame.hpp"
#include "projection.hpp"
#include "maps/ld_radial.hpp"
#include "maps/parallel.hpp"
#include "maps/tabulated_ld_radial.hpp"
#include "cosine_weighted.hpp"
#include "disk_light.hpp"
#include "sphere_light.hpp"
