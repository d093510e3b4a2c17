// apse — area-preserving parameterizations for spherical ellipses.
// SPDX-License-Identifier: MIT
#pragma once

/// @file apse.hpp
/// The umbrella header: every public sampler and its building blocks — a disk light's stored
/// frame, projection, the maps, the tabulated maps, cosine-weighted sampling, DiskLight,
/// SphereLight, the spherical-rectangle sampler and the elliptic integrals. The baselines apse is
/// measured against (uniform-by-area disk sampling, Gamito's rejection) are not included:
/// `#include <apse/baselines/area.hpp>` / `<apse/baselines/gamito.hpp>` for them.

#include "config.hpp"
#include "math.hpp"
#include "elliptic.hpp"
#include "sample.hpp"
#include "spherical_ellipse.hpp"
#include "disk_frame.hpp"
#include "projection.hpp"
#include "spherical_rectangle.hpp"
#include "maps/radial.hpp"
#include "maps/ld_radial.hpp"
#include "maps/parallel.hpp"
#include "maps/tabulated.hpp"
#include "projected_solid_angle.hpp"
#include "projected_cap.hpp"
#include "cosine_weighted.hpp"
#include "disk_light.hpp"
#include "sphere_light.hpp"
