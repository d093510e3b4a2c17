// apse — area-preserving parameterizations for spherical ellipses.
// SPDX-License-Identifier: MIT
#pragma once

/// @file apse.hpp
/// The umbrella header: includes every public apse header.

#include "config.hpp"
#include "math.hpp"
#include "elliptic.hpp"
#include "sample.hpp"
