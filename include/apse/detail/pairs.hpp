// apse — area-preserving parameterizations for spherical ellipses.
// SPDX-License-Identifier: MIT
#pragma once

/// @file detail/pairs.hpp
/// Two independent square roots or two independent divisions in one instruction, in double. On
/// x86-64 the square-root/divide unit is not fully pipelined (one sqrtsd per ~8 cycles, one divsd
/// per ~4-5 on Zen 3), and apse's set-up code and elliptic integrals are bound by it; SSE
/// `sqrtpd`/`divpd` compute two lanes for about the price of one (measured: R_F -12%, R_J -9%,
/// disk projection -6%). In float the scalar operations are faster (their throughput is higher,
/// and packing two floats into a vector adds latency: measured, float projection -7 to -9 %,
/// tabulated LD-radial set-up + 1 sample -5.5 to -6 % with the scalar form), so float takes them. The results are
/// bit-identical either way (IEEE square roots and quotients are correctly rounded). Elsewhere
/// (CUDA device code, non-x86 hosts, or with `APSE_NO_SIMD` defined) they are the scalar
/// operations.

#include <cmath>

#include "../config.hpp"

// SSE2: every x86-64 host compiler; never in CUDA device code, nor when the user defines
// APSE_NO_SIMD before including apse (the scalar path, the one device code takes).
#if (defined(__SSE2__) || defined(_M_X64)) && !defined(__CUDA_ARCH__) && !defined(APSE_NO_SIMD)
#include <emmintrin.h>
#define APSE_PAIRS_SSE2 1
#else
#define APSE_PAIRS_SSE2 0
#endif

namespace apse {
namespace detail {

/// sx = sqrt(x), sy = sqrt(y) (paired in double, see the file comment).
template <class T> APSE_FUNC void sqrt2(T x, T y, T& sx, T& sy) noexcept {
#if APSE_PAIRS_SSE2
    if constexpr (sizeof(T) == sizeof(double)) {
        const __m128d r = _mm_sqrt_pd(_mm_set_pd(double(y), double(x)));
        sx = T(_mm_cvtsd_f64(r));
        sy = T(_mm_cvtsd_f64(_mm_unpackhi_pd(r, r)));
        return;
    }
#endif
    sx = std::sqrt(x);
    sy = std::sqrt(y);
}

/// qa = a / b, qc = c / d (paired in double, see the file comment).
template <class T> APSE_FUNC void div2(T a, T b, T c, T d, T& qa, T& qc) noexcept {
#if APSE_PAIRS_SSE2
    if constexpr (sizeof(T) == sizeof(double)) {
        const __m128d r = _mm_div_pd(_mm_set_pd(double(c), double(a)), _mm_set_pd(double(d), double(b)));
        qa = T(_mm_cvtsd_f64(r));
        qc = T(_mm_cvtsd_f64(_mm_unpackhi_pd(r, r)));
        return;
    }
#endif
    qa = a / b;
    qc = c / d;
}

}  // namespace detail
}  // namespace apse
