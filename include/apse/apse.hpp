// apse — area-preserving parameterizations for spherical ellipses.
// SPDX-License-Identifier: MIT
#pragma once

/// @file apse.hpp
/// The umbrella header: includes every public apse header.

#include "config.hpp"
#include "math.hpp"
#include "elliptic.hpp"
#include "sample.hpp"
#include "spherical_ellipse.hpp"
#include "projection.hpp"
#include "baselines/area.hpp"
#include "baselines/rectangle.hpp"
#include "baselines/gamito.hpp"
#include "maps/radial.hpp"
#include "maps/ld_radial.hpp"
#include "maps/parallel.hpp"
#include "maps/tabulated.hpp"
#include "projected_solid_angle.hpp"
#include "cosine_weighted.hpp"
#include "disk_light.hpp"
