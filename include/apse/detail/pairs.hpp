// apse — area-preserving parameterizations for spherical ellipses.
// SPDX-License-Identifier: MIT
#pragma once

/// @file detail/pairs.hpp
/// Two independent square roots or two independent divisions in one instruction, in double. On
/// x86-64 the square-root/divide unit is not fully pipelined (one sqrtsd per ~8 cycles, one divsd
/// per ~4-5 on Zen 3), and apse's set-up code and elliptic integrals are bound by it; SSE
/// `sqrtpd`/`divpd` compute two lanes for about the price of one (measured: R_F -12%, R_J -9%,
/// disk projection -6%). In float the scalar operations are faster (their throughput is higher,
/// and packing two floats into a vector adds latency: measured, float projection -7 %, tabulated
/// LD-radial set-up + 1 sample -6 % with the scalar form), so float takes them. The results are
/// bit-identical either way (IEEE square roots and quotients are correctly rounded). Also `swap_if_greater`, a pair
/// swapped on a comparison by a mask blend. Elsewhere (CUDA device code, non-x86 hosts, or with
/// `APSE_NO_SIMD` defined) they are the scalar operations.

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

/// (x, y) swapped when a > b (not swapped if a or b is NaN), without a branch: the swap's test is
/// unpredictable where it is used, and compilers turn a plain select, or its arithmetic form, into
/// a branch. SSE2, by mask blends (and/andnot/or): in double on the pair (y, x) and its shuffle,
/// with the mask from the comparison's flag; in float on broadcast operands, with the mask from a
/// vector compare (measured, per type, the faster of the two forms in the tabulated maps).
template <class T> APSE_FUNC void swap_if_greater(T a, T b, T& x, T& y) noexcept {
#if APSE_PAIRS_SSE2
    if constexpr (sizeof(T) == sizeof(double)) {
        const __m128d xy = _mm_set_pd(double(y), double(x)), yx = _mm_shuffle_pd(xy, xy, 1);
        const __m128d m = _mm_castsi128_pd(_mm_set1_epi64x(-static_cast<long long>(a > b)));
        const __m128d r = _mm_or_pd(_mm_andnot_pd(m, xy), _mm_and_pd(m, yx));
        x = T(_mm_cvtsd_f64(r));
        y = T(_mm_cvtsd_f64(_mm_unpackhi_pd(r, r)));
        return;
    } else {
        const __m128 m = _mm_cmpgt_ps(_mm_set1_ps(float(a)), _mm_set1_ps(float(b)));
        const __m128 vx = _mm_set1_ps(float(x)), vy = _mm_set1_ps(float(y));
        x = T(_mm_cvtss_f32(_mm_or_ps(_mm_andnot_ps(m, vx), _mm_and_ps(m, vy))));
        y = T(_mm_cvtss_f32(_mm_or_ps(_mm_andnot_ps(m, vy), _mm_and_ps(m, vx))));
        return;
    }
#endif
    const bool swap = a > b;
    const T x0 = x;
    x = swap ? y : x;
    y = swap ? x0 : y;
}

}  // namespace detail
}  // namespace apse
