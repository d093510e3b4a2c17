// apse — area-preserving parameterizations for spherical ellipses.
// SPDX-License-Identifier: MIT
#pragma once

/// @file config.hpp
/// Version macros and the function qualifiers every public apse function carries.
///
/// Macros a user may define before including apse:
/// * `APSE_NO_SIMD`: no SSE intrinsics on x86 hosts (detail/math.hpp computes its pairs of
///   square roots and quotients with scalar operations, as in device code; results identical).

// C++17 is required (if constexpr, inline variables, hex float literals). MSVC reports
// __cplusplus as 199711L unless /Zc:__cplusplus is given; _MSVC_LANG holds the real value.
#if (defined(_MSVC_LANG) && _MSVC_LANG < 201703L) || (!defined(_MSVC_LANG) && __cplusplus < 201703L)
#error "apse requires C++17 or later (compile with -std=c++17, or /std:c++17 for MSVC)"
#endif

/// Major version (the CMake package reads the three version macros from this file).
#define APSE_VERSION_MAJOR 0
/// Minor version: before 1.0 a new minor version may change the API.
#define APSE_VERSION_MINOR 2
/// Patch version.
#define APSE_VERSION_PATCH 0
/// Single integer version: major * 10000 + minor * 100 + patch.
#define APSE_VERSION (APSE_VERSION_MAJOR * 10000 + APSE_VERSION_MINOR * 100 + APSE_VERSION_PATCH)

/// `APSE_FUNC` marks every public function: `__host__ __device__ inline` when compiled by a CUDA
/// compiler (nvcc, or clang in CUDA mode), plain `inline` otherwise.
#if defined(__CUDACC__)
#define APSE_FUNC __host__ __device__ inline
#else
#define APSE_FUNC inline
#endif

/// `APSE_NOINLINE`: keeps a large internal function (a Carlson core, a closed-form cumulative
/// area) out of line in CUDA device code, so a kernel holds one copy of it however many apse
/// calls it makes — inlined everywhere, a kernel calling every sampler took ptxas minutes and
/// gigabytes. Empty on the host, where the compiler decides as usual.
#if defined(__CUDACC__)
#define APSE_NOINLINE __noinline__
#else
#define APSE_NOINLINE
#endif

/// `APSE_HOT_INLINE`: a small per-sample step inlined into its caller on the host (GCC and Clang
/// weigh inlining by size and otherwise keep the tabulated maps' sample step out of line, a call
/// per sample; measured ~20 % of the step's instructions), and the short per-shading-point set-ups
/// of a spherical cap (project_sphere, the radial maps' constructors: out of line, the ellipse is
/// stored and reloaded through memory, ~15 % of a cap's set-up and sample, measured), with the
/// steps of a cap's sample (the folds, the polar step, the frame, SphereLight's hit distance):
/// in a large translation unit GCC's inlining budget runs out and leaves them as calls, ~30 %
/// of a sphere light's set-up and sample (bench_samplers, measured). Plain `APSE_FUNC`
/// elsewhere.
#if !defined(__CUDACC__) && (defined(__GNUC__) || defined(__clang__))
#define APSE_HOT_INLINE __attribute__((always_inline)) inline
#else
#define APSE_HOT_INLINE APSE_FUNC
#endif

/// `APSE_COLD`: keeps a rarely taken internal path (e.g. the elliptic integrals' handling of
/// arguments at the ends of the exponent range) out of line everywhere, so that it does not
/// weigh on the inlining and code layout of the common path that calls it.
#if defined(__CUDACC__)
#define APSE_COLD __noinline__
#elif defined(__GNUC__) || defined(__clang__)
#define APSE_COLD __attribute__((noinline, cold))
#elif defined(_MSC_VER)
#define APSE_COLD __declspec(noinline)
#else
#define APSE_COLD
#endif
