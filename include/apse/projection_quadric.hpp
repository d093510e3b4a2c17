// apse — area-preserving parameterizations for spherical ellipses.
// SPDX-License-Identifier: MIT
#pragma once

/// @file projection_quadric.hpp
/// The spherical ellipses subtended by oriented planar ellipses, spheres and ellipsoids
/// (docs/math.md §2b): the quadric tangent cone and a 3×3 symmetric eigen-problem (the sphere's
/// cap in closed form). The conventions shared by every projection are in projection.hpp.

#include <cmath>

#include "config.hpp"
#include "detail/glm.hpp"
#include "detail/symmetric_eigen.hpp"
#include "detail/type_identity.hpp"
#include "detail/vector.hpp"
#include "detail/math.hpp"
#include "projection_disk.hpp"
#include "spherical_ellipse.hpp"

namespace apse {
namespace detail {

/// A symmetric 3×3 matrix by its upper triangle.
template <class T> struct Sym3 {
    T m00, m01, m02, m11, m12, m22;
};

/// Index of the entry of largest magnitude among v[0..2].
template <class T> APSE_FUNC int argmax_abs3(const T v[3]) noexcept {
    int i = std::fabs(v[1]) > std::fabs(v[0]) ? 1 : 0;
    return std::fabs(v[2]) > std::fabs(v[i]) ? 2 : i;
}

/// The spherical ellipse of the quadric cone {v : vᵀ C v <= 0} (docs/math.md §2b), the nappe
/// containing `toward`, all in a local orthonormal frame `basis[0..2]` (world-space unit vectors).
/// The eigenvalues l1 >= l2 > 0 > l3 of C give tan² alpha = −l3/l2, tan² beta = −l3/l1.
///
/// They may span many orders of magnitude (far lights: |l3| tiny; thin ellipses: l2, |l3| tiny;
/// points near a light's plane: l1, l2 tiny), and an eigen-solver applied to C alone finds only
/// the largest ones to high relative accuracy. So the caller also passes the inverse cone
/// Cinv ∝ C⁻¹ (known in closed form, e.g. M J Mᵀ for a planar ellipse with M = [U V p]): with
/// C⁻¹ = Cinv / k2, eigenvalue mu of Cinv is the eigenvalue k2/mu of C. The eigenpair of largest
/// |l| is taken from C, the one of smallest |l| from Cinv (its largest |mu|), both accurate to a
/// few ulps, and the middle one from the exact determinant det C = −det_b² (det_b = |det B| for
/// C = Bᵀ diag(1,1,−1) B) with its eigenvector the cross product of the other two. When all
/// three |l| are alike (the two choices coincide) C's own eigenvalues are already accurate.
/// A cone that is not elliptic in floating point (not exactly one negative eigenvalue) → empty.
template <class T>
APSE_FUNC SphericalEllipse<T> ellipse_of_cone(const Sym3<T>& c, const Sym3<T>& cinv, T k2, T det_b,
                                              const glm::vec<3, T> basis[3],
                                              const glm::vec<3, T>& toward) noexcept {
    using vec3 = glm::vec<3, T>;  ///< a 3-D vector (direction, point or normal)
    using E = SphericalEllipse<T>;
    const SymmetricEigen3<T> ec = symmetric_eigen3(c.m00, c.m01, c.m02, c.m11, c.m12, c.m22);
    const SymmetricEigen3<T> ei = symmetric_eigen3(cinv.m00, cinv.m01, cinv.m02, cinv.m11, cinv.m12, cinv.m22);
    T lam[3];
    vec3 vec[3];
    const int il = argmax_abs3(ec.value), is = argmax_abs3(ei.value);
    lam[0] = ec.value[il];
    vec[0] = ec.vector[il];
    lam[1] = k2 / ei.value[is];
    vec[1] = ei.vector[is];
    if (std::fabs(glm::dot(vec[0], vec[1])) < T(0.5)) {
        vec[1] = robust_normalize(vec[1] - glm::dot(vec[1], vec[0]) * vec[0]);
        vec[2] = glm::cross(vec[0], vec[1]);
        lam[2] = -(det_b / lam[0]) * (det_b / lam[1]);
    } else {  // all |eigenvalues| alike: C's own are accurate
        for (int i = 0; i < 3; ++i) {
            lam[i] = ec.value[i];
            vec[i] = ec.vector[i];
        }
    }
    int ineg = 0;
    if (lam[1] < lam[ineg]) ineg = 1;
    if (lam[2] < lam[ineg]) ineg = 2;
    const int ia = (ineg + 1) % 3, ib = (ineg + 2) % 3;
    const int i1 = lam[ia] >= lam[ib] ? ia : ib, i2 = i1 == ia ? ib : ia;
    const T l1 = lam[i1], l2 = lam[i2], l3 = lam[ineg];
    if (!(l3 < T(0) && l2 > T(0) && detail::is_finite(l1 - l3))) return E::make_empty();
    const T tan_alpha = std::sqrt(-l3 / l2);
    // A circular cone (a circle seen along its axis, a sphere) comes out of the eigen-solver
    // with tangents a few ulps apart (<= 5 eps, measured): within 8 eps they are made exactly
    // equal, an exact cap that the maps sample in closed form (docs/math.md §2b, Caps under
    // rounding). The shape moves by at most 8 eps, the solid angle and pdf by at most 8 eps
    // relative: below the eigen-solver's own error.
    const T tan_beta_raw = std::sqrt(-l3 / l1);
    const T tan_beta = tan_alpha - tan_beta_raw <= T(8) * detail::epsilon<T>() * tan_alpha ? tan_alpha : tan_beta_raw;
    vec3 z = vec[ineg];
    if (glm::dot(z, toward) < T(0)) z = -z;
    vec3 x = vec[i2];
    x = robust_normalize(x - glm::dot(x, z) * z);
    const vec3 y = glm::cross(z, x);
    const auto world = [&](const vec3& l) { return l.x * basis[0] + l.y * basis[1] + l.z * basis[2]; };
    return E::from_tangents(world(x), world(y), world(z), tan_alpha, detail::min_of(tan_beta, tan_alpha));
}

}  // namespace detail

/// True if `o` is strictly on the side of the ellipse's plane that semi_axis_u × semi_axis_v
/// points to (the emitting side of a one-sided ellipse light with that orientation); the same
/// test as disk_faces with normal = u × v.
template <class T>
APSE_FUNC bool ellipse_faces(const glm::vec<3, T>& o, const glm::vec<3, T>& center,
                             const glm::vec<3, T>& semi_axis_u, const glm::vec<3, T>& semi_axis_v) noexcept {
    return disk_faces(o, center, glm::cross(semi_axis_u, semi_axis_v));
}

/// The spherical ellipse subtended at `o` by the planar ellipse
/// {center + s U + t V : s² + t² <= 1} (U = semi_axis_u, V = semi_axis_v), docs/math.md §2b.
/// U and V need not be orthogonal: any two non-parallel vectors (conjugate semi-diameters)
/// define an ellipse; orthogonal ones are its semi-axes. A disk is U = r e1, V = r e2 and gives
/// project_disk's ellipse (to rounding); a circle seen along its axis gives an exact cap
/// (tangents within 8 eps of each other are made equal, docs/math.md §2b). Method: the cone matrix is built in the plane's frame
/// ([[d² S, −d S c], [−d cᵀS, cᵀS c − det²]]); its largest-|l| eigenpair comes from a Jacobi
/// iteration on it, the smallest from the inverse cone [U V p] J [U V p]ᵀ, the middle one from
/// the exact determinant (detail::ellipse_of_cone), so thin ellipses, far lights and points near
/// the plane all keep full relative accuracy. Cost: two 3×3 Jacobi solves (~1 µs).
/// Two-sided; empty for o in the plane, parallel/zero/non-finite axes, NaN/Inf anywhere (see
/// the file comment; axes within ~8 eps of parallel count as parallel). Accuracy: as
/// project_disk, a few times its rounding error (docs/projection.md).
template <class T>
APSE_FUNC SphericalEllipse<T> project_ellipse(const glm::vec<3, T>& o, const glm::vec<3, T>& center,
                                              const glm::vec<3, T>& semi_axis_u,
                                              const glm::vec<3, T>& semi_axis_v) noexcept {
    using vec3 = glm::vec<3, T>;  ///< a 3-D vector (direction, point or normal)
    using E = SphericalEllipse<T>;
    const vec3 p0 = center - o;
    if (!detail::finite3(p0) || !detail::finite3(semi_axis_u) || !detail::finite3(semi_axis_v))
        return E::make_empty();
    const T s_max = detail::max_of(detail::max_abs3(p0), detail::max_of(detail::max_abs3(semi_axis_u), detail::max_abs3(semi_axis_v)));
    if (!(s_max > T(0))) return E::make_empty();
    const detail::Pow2Scale<T> sc = detail::pow2_scale_for(s_max);
    const vec3 p = sc(p0), u = sc(semi_axis_u), v = sc(semi_axis_v);
    // Parallel axes: u × v is then a rounding residual, which is not exactly 0 when the compiler
    // contracts a·b − c·d into an FMA (-march=x86-64-v3, AArch64, nvcc); below 8 eps |u| |v|
    // (per component) the axes are taken as parallel, so the ellipse is empty either way.
    const vec3 uxv = glm::cross(u, v);
    if (!(detail::max_abs3(uxv) > T(8) * detail::epsilon<T>() * detail::max_abs3(u) * detail::max_abs3(v)))
        return E::make_empty();
    const vec3 n = detail::robust_normalize(uxv);
    if (!(glm::dot(n, n) > T(0))) return E::make_empty();
    const vec3 e1 = detail::robust_normalize(u - glm::dot(u, n) * n);
    if (!(glm::dot(e1, e1) > T(0))) return E::make_empty();
    const T sd = glm::dot(p, n);
    const T d = std::fabs(sd);
    if (!(d > T(0))) return E::make_empty();
    const vec3 zd = sd > T(0) ? n : -n;
    const vec3 e2 = glm::cross(zd, e1);
    // In-plane coordinates (e1, e2) about the foot of o: centre c, axes as the columns of M.
    const T c1 = glm::dot(p, e1), c2 = glm::dot(p, e2);
    const T m11 = glm::dot(u, e1), m12 = glm::dot(v, e1), m21 = glm::dot(u, e2), m22 = glm::dot(v, e2);
    const T det = m11 * m22 - m12 * m21;
    // B = [[d adj M, −adj M c], [0, 0, det]] with adj M = [[m22, −m12], [−m21, m11]]: the cone is
    // vᵀ Bᵀ diag(1, 1, −1) B v <= 0 and |det B| = d² det². Its inverse: B⁻¹ = P / (d det) with
    // P = [[M, c], [0, d]] = [U V p] in the plane's frame, so C⁻¹ = P J Pᵀ / (d det)².
    T b[3][3] = {{d * m22, -d * m12, -(m22 * c1 - m12 * c2)},
                 {-d * m21, d * m11, -(m11 * c2 - m21 * c1)},
                 {T(0), T(0), det}};
    T b_max = T(0);
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) b_max = detail::max_of(b_max, std::fabs(b[i][j]));
    if (!(b_max > T(0)) || !detail::is_finite(b_max)) return E::make_empty();
    const detail::Pow2Scale<T> bs = detail::pow2_scale_for(b_max);  // B -> 2^-e B (exact)
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) b[i][j] = bs(b[i][j]);
    const auto cb = [&](int i, int j) { return b[0][i] * b[0][j] + b[1][i] * b[1][j] - b[2][i] * b[2][j]; };
    const T pm[3][3] = {{m11, m12, c1}, {m21, m22, c2}, {T(0), T(0), d}};  // columns U, V, p
    const auto cp = [&](int i, int j) { return pm[i][0] * pm[j][0] + pm[i][1] * pm[j][1] - pm[i][2] * pm[j][2]; };
    const T det_b = std::fabs(b[0][0] * b[1][1] - b[0][1] * b[1][0]) * std::fabs(b[2][2]);
    const T k = d * bs(det);  // (2^-e B) P = k I
    const vec3 basis[3] = {e1, e2, zd};
    return detail::ellipse_of_cone(detail::Sym3<T>{cb(0, 0), cb(0, 1), cb(0, 2), cb(1, 1), cb(1, 2), cb(2, 2)},
                                   detail::Sym3<T>{cp(0, 0), cp(0, 1), cp(0, 2), cp(1, 1), cp(1, 2), cp(2, 2)},
                                   k * k, det_b, basis, vec3(T(0), T(0), T(1)));
}

namespace detail {

/// The cap the sphere |p − center| <= radius subtends at `o`, without its frame: project_sphere
/// (below) is this and SphereCap::ellipse().
template <class T>
APSE_HOT_INLINE SphereCap<T> sphere_cap(const glm::vec<3, T>& o, const glm::vec<3, T>& center, T radius) noexcept {
    using vec3 = glm::vec<3, T>;
    SphereCap<T> c;
    const vec3 p0 = center - o;
    const T p_max = max_abs3(p0);
    if (!(radius > T(0)) || !is_finite(radius + p_max) || !finite3(p0)) return c;
    const T s_max = max_of(p_max, radius);
    vec3 p = p0;
    T r = radius;
    const bool scaled = !(s_max >= safe_scale_min<T>() && s_max <= safe_scale_max<T>());
    Pow2Scale<T> sc{0, T(1)};
    if (scaled) {
        sc = pow2_scale_for(s_max);
        p = sc(p0);
        r = sc(radius);
    }
    // L = sqrt(D^2 − R^2) from D^2 itself, not from D (its square root beside D's, not after it):
    // the rounding of D^2 gives both forms the same relative error ~eps D/(D − R) near the surface
    const T dist2 = glm::dot(p, p);
    const T dist = std::sqrt(dist2);
    if (!(dist > r)) return c;
    const T l = std::sqrt(max_of(dist2 - r * r, T(0)));
    // tan alpha = R/L with 1 − cos alpha = R^2/(D (D + L)) (R q, not R^2 / ...: R^2 may be
    // subnormal); the divisions paired (detail::div2)
    T tan_a, q;
    div2(r, l, r, dist * (dist + l), tan_a, q);
    const T inv_d = T(1) / dist;
    if (!(tan_a >= tan_min<T>())) return c;  // as SphericalEllipse::from_tangents: empty
    c.z = p * inv_d;
    c.distance = scaled ? std::ldexp(dist, sc.e) : dist;
    if (!(tan_a <= tan_cap<T>())) {  // capped at tan_cap, as SphericalEllipse::from_tangents
        SinCos<T> sa, sb;
        sin_cos_of_atan2(tan_cap<T>(), tan_cap<T>(), sa, sb);
        c.tan_alpha = tan_cap<T>();
        c.sin_alpha = sa.s;
        c.cos_alpha = sa.c;
        c.one_minus_cos_alpha = sa.omc;
        return c;
    }
    c.tan_alpha = tan_a;
    c.sin_alpha = r * inv_d;
    c.cos_alpha = l * inv_d;
    c.one_minus_cos_alpha = r * q;
    return c;
}

}  // namespace detail

/// The spherical cap subtended at `o` by the sphere |p − center| <= radius (docs/math.md §2b):
/// alpha = beta = asin(radius / |center − o|), tan alpha = radius / sqrt((D − R)(D + R)),
/// z towards the centre, (x, y) a deterministic frame around it (Duff et al. 2017's branchless
/// orthonormal basis). The result is an exact cap (SphericalEllipse::is_cap(): tan_alpha ==
/// tan_beta), which every map samples in closed form. Every field comes from D, R and
/// L = sqrt(D^2 − R^2) directly: sin alpha = R/D, cos alpha = L/D, tan alpha = R/L,
/// 1 − cos alpha = R^2/(D (D + L)), no cancellation; the scene is rescaled by an exact power of
/// two only when its scale is extreme (outside [2^-100, 2^100] in double, [2^-16, 2^16] in
/// float), so D^2 neither overflows nor underflows.
/// Empty for o inside or on the sphere (documented choice: a point inside sees the emitter in
/// every direction, which is not a spherical ellipse), radius <= 0, NaN/Inf anywhere, and (as
/// SphericalEllipse::from_tangents) tan alpha below detail::tan_min; tan alpha above
/// detail::tan_cap (o within ~1e-16 radii of the surface in double) is capped there.
/// Accuracy: tan alpha and the other fields to a few ulps, except near the surface where D − R
/// inherits the rounding of center − o (relative error ~ eps D/(D − R)). T is deduced from the
/// vectors alone (the radius converts to it, as in project_disk).
template <class T>
APSE_HOT_INLINE SphericalEllipse<T> project_sphere(const glm::vec<3, T>& o, const glm::vec<3, T>& center,
                                                   detail::type_identity_t<T> radius) noexcept {
    return detail::sphere_cap(o, center, T(radius)).ellipse();
}

/// The spherical ellipse subtended at `o` by the solid ellipsoid
/// {center + s1 A1 + s2 A2 + s3 A3 : s1² + s2² + s3² <= 1} (semi-axis vectors A1, A2, A3), docs/math.md §2b:
/// the tangent cone C = (qᵀAq − 1) A − (Aq)(Aq)ᵀ, q = o − center, is decomposed in the
/// ellipsoid's principal frame, without cancelling terms, together with its inverse (the dual
/// quadric diag(a_i²) − q qᵀ) and its exact determinant (detail::ellipse_of_cone): accurate for
/// far, near, pancake and needle ellipsoids alike. Cost: two 3×3 Jacobi solves (~1 µs).
/// A sphere (three equal orthogonal axes) gives project_sphere's cap, an exact one
/// (SphericalEllipse::is_cap(): tangents within 8 eps of each other are made equal, docs/math.md
/// §2b "Caps under rounding"; as for a circle given to project_ellipse on its axis).
/// Measure: solid angle. Accuracy: docs/projection.md (double ~1e-15, float ~1e-6 when the
/// input is well conditioned).
/// Domain: the three axes mutually orthogonal (to within |cos| <= 1e-3; the frame is then
/// orthogonalised — A1's direction kept, A2 made orthogonal to it, A3 only supplies its length)
/// and non-zero. Empty for axes further from orthogonal, zero or non-finite axes, o inside or
/// on the ellipsoid (documented choice, as project_sphere), NaN/Inf anywhere.
template <class T>
APSE_FUNC SphericalEllipse<T> project_ellipsoid(const glm::vec<3, T>& o, const glm::vec<3, T>& center,
                                                const glm::vec<3, T>& axis1, const glm::vec<3, T>& axis2,
                                                const glm::vec<3, T>& axis3) noexcept {
    using vec3 = glm::vec<3, T>;  ///< a 3-D vector (direction, point or normal)
    using E = SphericalEllipse<T>;
    const vec3 q0 = o - center;
    if (!detail::finite3(q0) || !detail::finite3(axis1) || !detail::finite3(axis2) || !detail::finite3(axis3))
        return E::make_empty();
    const T s_max = detail::max_of(detail::max_of(detail::max_abs3(q0), detail::max_abs3(axis1)),
                           detail::max_of(detail::max_abs3(axis2), detail::max_abs3(axis3)));
    if (!(s_max > T(0))) return E::make_empty();
    const detail::Pow2Scale<T> sc = detail::pow2_scale_for(s_max);
    const vec3 q = sc(q0), A1 = sc(axis1), A2 = sc(axis2), A3 = sc(axis3);
    // The squared length of an axis ~1e-21 times the largest (scaled units) is a float denormal,
    // whose few bits left e1 = A1/a1 1e-4 off unit length, and the frame with it (found by
    // fuzz_shapes): e1 comes from the scale-free robust_normalize, and below the normal range a
    // length is A · (A/|A|) instead of sqrt(A · A).
    const auto length = [](const vec3& a) {
        const T d = glm::dot(a, a);
        return d >= detail::square_safe_min<T>() ? std::sqrt(d) : glm::dot(a, detail::robust_normalize(a));
    };
    const T a1 = length(A1), a2 = length(A2), a3 = length(A3);
    if (!(a1 > T(0) && a2 > T(0) && a3 > T(0))) return E::make_empty();
    const vec3 e1 = detail::robust_normalize(A1);
    const T tol = T(1e-3);
    if (!(std::fabs(glm::dot(e1, A2)) <= tol * a2 && std::fabs(glm::dot(e1, A3)) <= tol * a3 &&
          std::fabs(glm::dot(A2, A3)) <= tol * a2 * a3))
        return E::make_empty();
    const vec3 e2 = detail::robust_normalize(A2 - glm::dot(A2, e1) * e1);
    const vec3 e3 = glm::cross(e1, e2);
    // Unit-sphere coordinates of o: q'_i = (q . e_i) / a_i; outside iff |q'| > 1.
    const vec3 qs(glm::dot(q, e1) / a1, glm::dot(q, e2) / a2, glm::dot(q, e3) / a3);
    const T qs_max = detail::max_abs3(qs);
    const vec3 qh1 = qs / qs_max;
    const T qn1 = std::sqrt(glm::dot(qh1, qh1));
    const T qn = qs_max * qn1;  // |q'|
    if (!(qn > T(1)) || !detail::is_finite(qn)) return E::make_empty();
    const vec3 qh = qh1 / qn1;
    const T kappa = (qn - T(1)) * (qn + T(1)) / (qn * qn);  // 1 − 1/|q'|²
    // C ∝ G (kappa I − qh qhᵀ) G with G = diag(a_min / a_i): det C = −(g1 g2 g3 kappa / |q'|)².
    // Its inverse: (kappa I − qh qhᵀ)⁻¹ = (I − |q'|² qh qhᵀ) / kappa, so C⁻¹ = Cinv / (kappa rho) with
    // Cinv = diag(a_i / a_max)² − (q / a_max)(q / a_max)ᵀ (the dual cone), rho = (a_min / a_max)².
    const T a_min = detail::min_of(a1, detail::min_of(a2, a3)), a_max = detail::max_of(a1, detail::max_of(a2, a3));
    const vec3 qd(glm::dot(q, e1), glm::dot(q, e2), glm::dot(q, e3));
    if (!(a_max >= detail::tan_min<T>() * detail::max_abs3(qd))) return E::make_empty();  // tan beta < tan_min
    const vec3 g(a_min / a1, a_min / a2, a_min / a3);
    // kappa − qh_i² is written (sum of the other qh_j²) − 1/|q'|²: no cancellation of two terms
    // near 1 when o is far from the ellipsoid along one of its (thin) axes.
    const T inv_q2 = detail::sqr(T(1) / qn);
    const vec3 qh2(qh.x * qh.x, qh.y * qh.y, qh.z * qh.z);
    const vec3 diag(qh2.y + qh2.z - inv_q2, qh2.x + qh2.z - inv_q2, qh2.x + qh2.y - inv_q2);
    const auto c = [&](int i, int j) { return g[i] * g[j] * (i == j ? diag[i] : -qh[i] * qh[j]); };
    const vec3 h(a1 / a_max, a2 / a_max, a3 / a_max);
    const vec3 qa = qd / a_max;
    const auto ci = [&](int i, int j) { return (i == j ? h[i] * h[i] : T(0)) - qa[i] * qa[j]; };
    const T rho = detail::sqr(a_min / a_max);
    const T det_b = g.x * g.y * g.z * kappa / qn;
    const vec3 basis[3] = {e1, e2, e3};
    return detail::ellipse_of_cone(detail::Sym3<T>{c(0, 0), c(0, 1), c(0, 2), c(1, 1), c(1, 2), c(2, 2)},
                                   detail::Sym3<T>{ci(0, 0), ci(0, 1), ci(0, 2), ci(1, 1), ci(1, 2), ci(2, 2)},
                                   kappa * rho, det_b, basis, -qh);
}

}  // namespace apse
