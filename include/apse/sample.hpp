// apse — area-preserving parameterizations for spherical ellipses.
// SPDX-License-Identifier: MIT
#pragma once

/// @file sample.hpp
/// The result type every apse sampler returns.

#include "detail/glm.hpp"

#include "config.hpp"

namespace apse {

/// One sampled direction: a world-space unit vector and its probability density **in solid
/// angle** (per steradian). `pdf == 0` means "no sample" (empty ellipse, out-of-domain input):
/// the caller must then skip the sample (its contribution is zero), which keeps estimators
/// unbiased; `direction` is still a finite unit vector in that case.
template <class T> struct DirectionSample {
    glm::vec<3, T> direction;  ///< world-space unit direction
    T pdf;                     ///< density in solid angle; 0 marks "no sample"
};

}  // namespace apse
