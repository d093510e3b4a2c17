// apse — area-preserving parameterizations for spherical ellipses.
// SPDX-License-Identifier: MIT
#pragma once

/// @file detail/glm.hpp
/// The one place apse includes GLM. Under nvcc, GLM 0.9.9 declares its defaulted constructors and
/// assignment operators `__host__ __device__`, which nvcc reports as warning #20012 ("annotation
/// is ignored on a ... function that is explicitly defaulted"). The warning is harmless —
/// defaulted functions are implicitly host and device — so it is silenced here, around GLM's
/// headers only, and consumers compiling with `-Werror all-warnings` are not broken by it.
///
/// GLM's configuration macros (`GLM_FORCE_*`) change the layout of its vectors, and so of every
/// apse type holding one: they must be the same in every translation unit that shares apse types.
/// apse works under each of them (tests/glm_force/) except `GLM_FORCE_CTOR_INIT`, which gives
/// GLM's vectors user-provided copy constructors: apse's samplers are plain data (trivially
/// copyable, passed to kernels by value), so that macro is rejected with a message.

#include <type_traits>

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

static_assert(std::is_trivially_copyable<glm::vec<3, float>>::value && std::is_trivially_copyable<glm::vec<2, double>>::value,
              "apse: GLM's vectors must be trivially copyable (apse's samplers are plain data): "
              "GLM_FORCE_CTOR_INIT is not supported");
