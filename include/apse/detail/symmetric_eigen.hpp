// apse — area-preserving parameterizations for spherical ellipses.
// SPDX-License-Identifier: MIT
#pragma once

/// @file detail/symmetric_eigen.hpp
/// Eigen-decomposition of a real symmetric 3×3 matrix by the cyclic Jacobi method: a sequence
/// of plane rotations, each annihilating one off-diagonal entry (Golub & Van Loan, "Matrix
/// Computations", §8.5). Device-safe, allocation-free, a hard cap on the number of sweeps.
///
/// Why Jacobi: with the *relative* stopping test |a_pq| <= eps sqrt(|a_pp a_qq|) it computes every
/// eigenvalue to high relative accuracy when the matrix is a well-conditioned matrix scaled by a
/// diagonal (Demmel & Veselić 1992) — the shape of the cone matrices of projection.hpp for far
/// lights and for shading points near a light's plane, where the eigenvalues span many orders
/// of magnitude and a closed-form cubic would lose the small ones.

#include <cmath>

#include "../config.hpp"
#include "math.hpp"
#include "glm.hpp"

namespace apse {
namespace detail {

/// Eigenvalues `value[i]` (unsorted) and orthonormal eigenvectors `vector[i]` (columns of the
/// accumulated rotation), and the number of sweeps used.
template <class T> struct SymmetricEigen3 {
    T value[3];
    glm::vec<3, T> vector[3];
    int sweeps;
};

/// Hard cap on Jacobi sweeps (a 3×3 matrix converges quadratically, in 3–6 sweeps).
constexpr int jacobi_max_sweeps = 16;

/// Eigen-decomposition of the symmetric matrix [[a00, a01, a02], [a01, a11, a12], [a02, a12, a22]]
/// (finite entries expected; NaN entries give NaN results, never a hang).
template <class T>
APSE_FUNC SymmetricEigen3<T> symmetric_eigen3(T a00, T a01, T a02, T a11, T a12, T a22) noexcept {
    T a[3][3] = {{a00, a01, a02}, {a01, a11, a12}, {a02, a12, a22}};
    T v[3][3] = {{T(1), T(0), T(0)}, {T(0), T(1), T(0)}, {T(0), T(0), T(1)}};
    const T tol = epsilon<T>() * T(0.5);
    // Above this |theta| the rotation angle is t = 1/(2 theta) (theta^2 would overflow).
    const T theta_big = sizeof(T) == sizeof(float) ? T(1e15) : T(1e150);
    int sweep = 0;
    for (; sweep < jacobi_max_sweeps; ++sweep) {
        bool rotated = false;
        for (int k = 0; k < 3; ++k) {
            const int p = k == 2 ? 1 : 0, q = k == 0 ? 1 : 2;  // (0,1), (0,2), (1,2)
            const int r = 3 - p - q;
            const T apq = a[p][q];
            if (!(std::fabs(apq) > tol * std::sqrt(std::fabs(a[p][p])) * std::sqrt(std::fabs(a[q][q]))))
                continue;  // negligible (or NaN: leave it)
            rotated = true;
            const T theta = (a[q][q] - a[p][p]) / (T(2) * apq);
            T t;
            if (std::fabs(theta) > theta_big) {
                t = T(0.5) / theta;
            } else {
                t = T(1) / (std::fabs(theta) + std::sqrt(theta * theta + T(1)));
                if (theta < T(0)) t = -t;
            }
            const T c = T(1) / std::sqrt(t * t + T(1)), s = t * c, tau = s / (T(1) + c);
            a[p][p] -= t * apq;
            a[q][q] += t * apq;
            a[p][q] = a[q][p] = T(0);
            const T g = a[r][p], h = a[r][q];
            a[r][p] = a[p][r] = g - s * (h + g * tau);
            a[r][q] = a[q][r] = h + s * (g - h * tau);
            for (int i = 0; i < 3; ++i) {
                const T vp = v[i][p], vq = v[i][q];
                v[i][p] = vp - s * (vq + vp * tau);
                v[i][q] = vq + s * (vp - vq * tau);
            }
        }
        if (!rotated) break;
    }
    SymmetricEigen3<T> e;
    for (int i = 0; i < 3; ++i) {
        e.value[i] = a[i][i];
        e.vector[i] = glm::vec<3, T>(v[0][i], v[1][i], v[2][i]);
    }
    e.sweeps = sweep;
    return e;
}

}  // namespace detail
}  // namespace apse
