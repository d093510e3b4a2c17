// apse — area-preserving parameterizations for spherical ellipses.
// SPDX-License-Identifier: MIT
#pragma once

/// @file detail/bilinear_warp.hpp
/// A warp of the unit square whose density is the bilinear interpolation of positive weights on
/// a regular (Cols + 1) × (Rows + 1) grid of vertices (piecewise bilinear over Cols × Rows
/// cells), sampled by the Knothe–Rosenblatt construction: v1 from the marginal (piecewise linear
/// in v1: each column's integral over v2 is linear between its two vertex columns), then v2 from
/// the conditional at v1 (piecewise linear in v2). Both inversions are quadratics solved in
/// closed form; the inverse warp is the two CDFs. The warp is continuous and monotone in each
/// coordinate, so it keeps the stratification of its input (docs/cosine_weighted.md).
///
/// Density on the square (normalised): p(v) = B(v) / total, B the bilinear interpolant and
/// total = ∫ B = sum over columns of (S_i + S_{i+1}) / (2 Cols), S_i = the trapezoid integral of
/// column i's vertex weights in v2. It is the exact density of sample(), for any weights.

#include <cmath>

#include "../config.hpp"
#include "../math.hpp"
#include "glm.hpp"

namespace apse {
namespace detail {

/// The s in [0, 1] at which the linear density f0 + (f1 − f0) s (f0, f1 >= 0, not both 0) has
/// integral x in [0, (f0 + f1)/2]: f0 s + (f1 − f0) s^2/2 = x, solved without cancellation as
/// s = 2 x / (f0 + sqrt(f0^2 + 2 (f1 − f0) x)).
template <class T> APSE_FUNC T linear_density_root(T f0, T f1, T x) noexcept {
    const T disc = max_of(f0 * f0 + T(2) * (f1 - f0) * x, T(0));
    const T den = f0 + std::sqrt(disc);
    return den > T(0) ? clamp(T(2) * x / den, T(0), T(1)) : T(0);
}

/// Integral over [0, s] of the linear density f0 + (f1 − f0) s.
template <class T> APSE_FUNC T linear_density_mass(T f0, T f1, T s) noexcept {
    return s * (f0 + T(0.5) * (f1 - f0) * s);
}

/// Piecewise-bilinear warp of the unit square (file comment). Fill `weight(i, j)` (column i in
/// [0, Cols], row j in [0, Rows]; finite and > 0) and call finish(). Trivially copyable.
template <class T, int Cols, int Rows> struct BilinearWarp {
    static_assert(Cols >= 1 && Rows >= 1, "at least one cell");
    using vec2 = glm::vec<2, T>;

    T w[Cols + 1][Rows + 1];  ///< vertex weights (> 0)
    T cdf[Cols + 1];          ///< cdf[i] = integral of B over v1 in [0, i/Cols]
    T col[Cols + 1];          ///< S_i: integral of column i's linear interpolant over v2
    T inv_total;              ///< 1 / cdf[Cols]

    /// Vertex weight at (v1, v2) = (i/Cols, j/Rows).
    APSE_FUNC T& weight(int i, int j) noexcept { return w[i][j]; }

    /// Computes the column integrals and the marginal CDF (call after filling the weights).
    APSE_FUNC void finish() noexcept {
        for (int i = 0; i <= Cols; ++i) {
            T s = T(0);
            for (int j = 0; j < Rows; ++j) s += w[i][j] + w[i][j + 1];
            col[i] = s * (T(0.5) / T(Rows));
        }
        cdf[0] = T(0);
        for (int i = 0; i < Cols; ++i) cdf[i + 1] = cdf[i] + (col[i] + col[i + 1]) * (T(0.5) / T(Cols));
        inv_total = T(1) / cdf[Cols];
    }

    /// The point of the square for the input u in [0, 1]^2 (uniform → density p), and p there
    /// (normalised, in `density`).
    APSE_FUNC vec2 sample(const vec2& u, T& density) const noexcept {
        // column k: cdf[k] <= u1 total < cdf[k + 1]
        const T t = u.x * cdf[Cols];
        int k = 0;
        while (k < Cols - 1 && !(t < cdf[k + 1])) ++k;
        const T s = linear_density_root(col[k], col[k + 1], (t - cdf[k]) * T(Cols));
        T c[Rows + 1], acc[Rows + 1];
        for (int j = 0; j <= Rows; ++j) c[j] = w[k][j] + s * (w[k + 1][j] - w[k][j]);
        acc[0] = T(0);
        for (int j = 0; j < Rows; ++j) acc[j + 1] = acc[j] + T(0.5) * (c[j] + c[j + 1]);
        const T t2 = u.y * acc[Rows];
        int l = 0;
        while (l < Rows - 1 && !(t2 < acc[l + 1])) ++l;
        const T s2 = linear_density_root(c[l], c[l + 1], t2 - acc[l]);
        density = (c[l] + s2 * (c[l + 1] - c[l])) * inv_total;
        return vec2((T(k) + s) / T(Cols), (T(l) + s2) / T(Rows));
    }

    /// Inverse of sample(): the input u whose image is v (v in [0, 1]^2, clamped).
    APSE_FUNC vec2 invert(const vec2& v) const noexcept {
        int k, l;
        T s, s2;
        locate(v.x, Cols, k, s);
        locate(v.y, Rows, l, s2);
        const T u1 = (cdf[k] + linear_density_mass(col[k], col[k + 1], s) / T(Cols)) * inv_total;
        T below = T(0), all = T(0);
        T prev = w[k][0] + s * (w[k + 1][0] - w[k][0]);
        for (int j = 0; j < Rows; ++j) {
            const T next = w[k][j + 1] + s * (w[k + 1][j + 1] - w[k][j + 1]);
            if (j < l) below += T(0.5) * (prev + next);
            else if (j == l) below += linear_density_mass(prev, next, s2);
            all += T(0.5) * (prev + next);
            prev = next;
        }
        return vec2(clamp(u1, T(0), T(1)), clamp(below / all, T(0), T(1)));
    }

    /// Density of sample() at v in [0, 1]^2 (clamped), normalised.
    APSE_FUNC T density(const vec2& v) const noexcept {
        int k, l;
        T s, s2;
        locate(v.x, Cols, k, s);
        locate(v.y, Rows, l, s2);
        const T c0 = w[k][l] + s * (w[k + 1][l] - w[k][l]);
        const T c1 = w[k][l + 1] + s * (w[k + 1][l + 1] - w[k][l + 1]);
        return (c0 + s2 * (c1 - c0)) * inv_total;
    }

private:
    /// Cell index in [0, n − 1] and position in it, for x in [0, 1] (clamped; NaN → 0).
    static APSE_FUNC void locate(T x, int n, int& cell, T& frac) noexcept {
        const T y = clamp(x, T(0), T(1)) * T(n);
        int c = y > T(0) ? int(y) : 0;
        if (c > n - 1) c = n - 1;
        cell = c;
        frac = clamp(y - T(c), T(0), T(1));
    }
};

}  // namespace detail
}  // namespace apse
