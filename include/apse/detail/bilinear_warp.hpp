// apse — area-preserving parameterizations for spherical ellipses.
// SPDX-License-Identifier: MIT
#pragma once

/// @file detail/bilinear_warp.hpp
/// A warp of the unit square whose density is clamped bilinear: h(v) = max(0, B(v)) + phi, B the
/// bilinear interpolant of signed values on a (Cols + 1) × (Rows + 1) grid of vertices (columns
/// at v1 = i/Cols, rows at increasing knots in v2), phi >= 0 a floor. Sampled by the
/// Knothe–Rosenblatt construction: v1 from a marginal m(v1) that is piecewise linear through
/// Z(v1) = ∫ h dv2 at Sub nodes per column, then v2 from the conditional h(v1, ·) / Z(v1), which
/// is piecewise linear (a row whose values change sign is split at its exact zero). Every
/// inversion is a quadratic solved in closed form; the inverse warp is the two CDFs. The warp is
/// continuous and monotone in each coordinate, so it keeps the stratification of its input
/// (docs/cosine_weighted.md).
///
/// Density on the square (normalised): p(v) = m(v1) h(v) / (Z(v1) total), total = ∫ m: the exact
/// density of sample(), for any values.

#include <cmath>

#include "../config.hpp"
#include "../math.hpp"
#include "glm.hpp"
#include "linear_density.hpp"

namespace apse {
namespace detail {

/// One piece of the clamped-linear conditional density: on [t0, t0 + len] the density is linear
/// from d0 to d1 (both >= 0).
template <class T> struct LinearPiece {
    T t0, len, d0, d1;
    APSE_FUNC T mass() const noexcept { return T(0.5) * len * (d0 + d1); }
};

/// Clamped-bilinear warp of the unit square (file comment). Fill `weight(i, j)` (column i in
/// [0, Cols], row j in [0, Rows]; finite, any sign: the signed cosine), call set_floor(phi) with
/// phi >= 0 (phi > 0 if any weight is <= 0), then finish(). Trivially copyable.
template <class T, int Cols, int Rows> struct BilinearWarp {
    static_assert(Cols >= 1 && Rows >= 1, "at least one cell");
    using vec2 = glm::vec<2, T>;

    T w[Cols + 1][Rows + 1];  ///< signed vertex values
    static constexpr int Sub = 4;     ///< marginal nodes per cell column
    static constexpr int N = Cols * Sub;  ///< marginal intervals
    T cdf[Cols + 1];          ///< cdf[k] = integral of the marginal over v1 in [0, k/Cols]
    T col[N + 1];             ///< Z_i: integral over v2 of the clamped density at v1 = i/N
    T knot[Rows + 1];         ///< the rows' v2 positions (0 = knot[0] < ... < knot[Rows] = 1)
    T phi;                    ///< the floor added to the clamped interpolant
    T inv_total;              ///< 1 / cdf[Cols]

    /// Vertex value at (v1, v2) = (i/Cols, j/Rows).
    APSE_FUNC T& weight(int i, int j) noexcept { return w[i][j]; }

    /// Row j's position v2 (increasing from 0 to 1; default j/Rows: set_uniform_knots()).
    APSE_FUNC T& row_knot(int j) noexcept { return knot[j]; }
    APSE_FUNC void set_uniform_knots() noexcept {
        for (int j = 0; j <= Rows; ++j) knot[j] = T(j) / T(Rows);
    }

    /// The floor phi >= 0 added to max(0, interpolant) everywhere.
    APSE_FUNC void set_floor(T f) noexcept { phi = f; }

    /// Computes the column integrals and the marginal CDF (call after filling the weights).
    APSE_FUNC void finish() noexcept {
        bool neg[Cols + 1];  // column k has a negative vertex value
        for (int k = 0; k <= Cols; ++k) {
            T lo = w[k][0];
            for (int j = 1; j <= Rows; ++j) lo = min_of(lo, w[k][j]);
            neg[k] = lo < T(0);
            if (neg[k]) {
                col[k * Sub] = mass(w[k]);
            } else {  // no clamping: the trapezoids
                T z = T(0);
                for (int j = 0; j < Rows; ++j) z += (knot[j + 1] - knot[j]) * (w[k][j] + w[k][j + 1]);
                col[k * Sub] = T(0.5) * z + phi;
            }
        }
        cdf[0] = T(0);
        for (int k = 0; k < Cols; ++k) {
            const T z0 = col[k * Sub], z1 = col[(k + 1) * Sub];
            T acc = T(0.5) * z0;
            for (int i = 1; i < Sub; ++i) {
                const T f = T(i) / T(Sub);
                if (!neg[k] && !neg[k + 1]) {  // no clamping in the cell column: Z is linear in v1
                    col[k * Sub + i] = z0 + f * (z1 - z0);
                } else {
                    T c[Rows + 1];
                    for (int j = 0; j <= Rows; ++j) c[j] = w[k][j] + f * (w[k + 1][j] - w[k][j]);
                    col[k * Sub + i] = mass(c);
                }
                acc += col[k * Sub + i];
            }
            cdf[k + 1] = cdf[k] + (acc + T(0.5) * z1) / T(N);  // trapezoids of the Sub intervals
        }
        inv_total = T(1) / cdf[Cols];
    }

    /// The point of the square for the input u in [0, 1]^2 (uniform → density p), and p there
    /// (normalised, in `density`).
    APSE_FUNC vec2 sample(const vec2& u, T& density) const noexcept {
        // cell column k: cdf[k] <= u1 total < cdf[k + 1]; then its marginal interval q
        T t = u.x * cdf[Cols];
        int k = 0;
        while (k < Cols - 1 && !(t < cdf[k + 1])) ++k;
        t = (t - cdf[k]) * T(N);
        int q = k * Sub;
        for (int i = 0; i < Sub - 1; ++i, ++q) {
            const T m = T(0.5) * (col[q] + col[q + 1]);
            if (t < m) break;
            t -= m;
        }
        const T sq = linear_density_root(col[q], col[q + 1], t);
        const T s = (T(q - k * Sub) + sq) / T(Sub);
        T c[Rows + 1];
        for (int j = 0; j <= Rows; ++j) c[j] = w[k][j] + s * (w[k + 1][j] - w[k][j]);
        LinearPiece<T> pieces[2 * Rows];
        int np;
        const T z = conditional(c, pieces, np);
        T t2 = u.y * z;
        int l = 0;
        while (l < np - 1 && !(t2 < pieces[l].mass())) t2 -= pieces[l++].mass();
        const LinearPiece<T>& p = pieces[l];
        const T s2 = p.len > T(0) ? linear_density_root(p.d0, p.d1, t2 / p.len) : T(0);
        const T m = col[q] + sq * (col[q + 1] - col[q]);  // the marginal at v1
        density = m * (p.d0 + s2 * (p.d1 - p.d0)) / z * inv_total;
        return vec2(clamp((T(q) + sq) / T(N), T(0), T(1)), clamp(p.t0 + s2 * p.len, T(0), T(1)));
    }

    /// Inverse of sample(): the input u whose image is v (v in [0, 1]^2, clamped).
    APSE_FUNC vec2 invert(const vec2& v) const noexcept {
        int q;
        T sq, c[Rows + 1];
        column_at(v.x, q, sq, c);
        const int k = q / Sub;
        T left = T(0);
        for (int i = k * Sub; i < q; ++i) left += T(0.5) * (col[i] + col[i + 1]);
        const T u1 = (cdf[k] + (left + linear_density_mass(col[q], col[q + 1], sq)) / T(N)) * inv_total;
        LinearPiece<T> pieces[2 * Rows];
        int np;
        const T z = conditional(c, pieces, np);
        const T v2 = clamp(v.y, T(0), T(1));
        T below = T(0);
        for (int l = 0; l < np; ++l) {
            const LinearPiece<T>& p = pieces[l];
            if (v2 >= p.t0 + p.len) below += p.mass();
            else if (v2 > p.t0) below += p.len * linear_density_mass(p.d0, p.d1, (v2 - p.t0) / p.len);
        }
        return vec2(clamp(u1, T(0), T(1)), clamp(below / z, T(0), T(1)));
    }

    /// Density of sample() at v in [0, 1]^2 (clamped), normalised.
    APSE_FUNC T density(const vec2& v) const noexcept {
        int q;
        T sq, c[Rows + 1];
        column_at(v.x, q, sq, c);
        const T z = mass(c);
        const T y = clamp(v.y, T(0), T(1));
        int l = 0;
        while (l < Rows - 1 && !(y < knot[l + 1])) ++l;
        const T s2 = clamp((y - knot[l]) / (knot[l + 1] - knot[l]), T(0), T(1));
        const T h = max_of(c[l] + s2 * (c[l + 1] - c[l]), T(0)) + phi;
        return (col[q] + sq * (col[q + 1] - col[q])) * h / z * inv_total;
    }

private:
    /// The marginal interval q of v1 (clamped), the position sq in it, and the column values
    /// interpolated at v1.
    APSE_FUNC void column_at(T v1, int& q, T& sq, T (&c)[Rows + 1]) const noexcept {
        locate(v1, N, q, sq);
        const int k = q / Sub;
        const T s = (T(q - k * Sub) + sq) / T(Sub);
        for (int j = 0; j <= Rows; ++j) c[j] = w[k][j] + s * (w[k + 1][j] - w[k][j]);
    }

    /// Integral over [0, 1] of the conditional density for the column values c (as conditional()).
    APSE_FUNC T mass(const T (&c)[Rows + 1]) const noexcept {
        T z = T(0);
        for (int j = 0; j < Rows; ++j) {
            const T a = c[j], b = c[j + 1], h = knot[j + 1] - knot[j];
            T m;
            if (a >= T(0) && b >= T(0)) m = T(0.5) * (a + b);
            else if (a <= T(0) && b <= T(0)) m = T(0);
            else m = T(0.5) * (a > T(0) ? a * a : b * b) / (a > T(0) ? a - b : b - a);  // the positive triangle
            z += h * (m + phi);
        }
        return z;
    }

    /// The conditional density in v2 for the column values c (signed): max(0, the linear
    /// interpolant of c) + phi, as linear pieces (a row whose interpolant changes sign is split
    /// at the exact zero) in `pieces[0..n)`; returns its integral over [0, 1].
    APSE_FUNC T conditional(const T (&c)[Rows + 1], LinearPiece<T> (&pieces)[2 * Rows], int& n) const noexcept {
        n = 0;
        T z = T(0);
        for (int j = 0; j < Rows; ++j) {
            const T a = c[j], b = c[j + 1], t0 = knot[j], h = knot[j + 1] - knot[j];
            if ((a > T(0) && b < T(0)) || (a < T(0) && b > T(0))) {
                const T tc = a / (a - b);  // the zero, in (0, 1)
                pieces[n++] = {t0, tc * h, max_of(a, T(0)) + phi, phi};
                pieces[n++] = {t0 + tc * h, (T(1) - tc) * h, phi, max_of(b, T(0)) + phi};
                z += pieces[n - 2].mass() + pieces[n - 1].mass();
            } else {
                pieces[n++] = {t0, h, max_of(a, T(0)) + phi, max_of(b, T(0)) + phi};
                z += pieces[n - 1].mass();
            }
        }
        return z;
    }

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
