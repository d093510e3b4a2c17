// apse — area-preserving parameterizations for spherical ellipses.
// SPDX-License-Identifier: MIT
#pragma once

/// @file detail/glm.hpp
/// The one place apse includes GLM. Under nvcc, GLM 0.9.9 declares its defaulted constructors and
/// assignment operators `__host__ __device__`, which nvcc reports as warning #20012 ("annotation
/// is ignored on a ... function that is explicitly defaulted"). The warning is harmless —
/// defaulted functions are implicitly host and device — so it is silenced here, around GLM's
/// headers only, and consumers compiling with `-Werror all-warnings` are not broken by it.

#if defined(__NVCC__)
#pragma nv_diagnostic push
#pragma nv_diag_suppress 20012
#endif

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#if defined(__NVCC__)
#pragma nv_diagnostic pop
#endif
