// apse — area-preserving parameterizations for spherical ellipses.
// SPDX-License-Identifier: MIT
#pragma once

/// @file projection.hpp
/// Shape → spherical ellipse seen from a shading point `o` (docs/math.md §2, §2b): disks (closed
/// form), oriented planar ellipses, spheres and ellipsoids (quadric tangent cone + a 3×3
/// symmetric eigen-problem).
///
/// Conventions shared by every function here:
/// * Geometry is **two-sided**: a disk or ellipse seen from behind gives the same ellipse as
///   from the front. One-sided emitters cull with `disk_faces` / `ellipse_faces`.
/// * The result is a `SphericalEllipse<T>`; degenerate or invalid input gives the empty ellipse
///   (`empty()`, solid angle 0) — never NaN, never UB: non-positive, NaN or infinite sizes,
///   zero-length, parallel or non-finite axis vectors or normals, NaN/Inf coordinates, `o` in
///   the plane of a disk or ellipse (the integrand cos(theta_l) vanishes there: Omega = 0, also
///   for `o` exactly on the disk), `o` inside or on a sphere or ellipsoid, and lights so small or
///   so grazing that tan(beta) < 1e-19 (float) / 1e-154 (double) (their solid angle is below
///   ~4 tan(beta)).
/// * Lengths are rescaled internally by a power of two (exact), so any scene scale works,
///   from 1e-30 to 1e30 in float.
/// * Accuracy (docs/projection.md has the measured table): in double, alpha, beta and Omega to
///   ~1e-15 relative whenever the input is well conditioned; the subtraction center − o is the
///   one unavoidable rounding, so a point at height d above the plane (and h from the axis) of a
///   disk of radius r loses about log10(max(|c − o|, r)/d) digits when o is near the rim (|h − r|
///   ~ d) — e.g. 1e-8 relative at d = 1e-8 r in double. float: ~1e-6 relative (same caveat).

#include <cmath>

#include "config.hpp"
#include "detail/glm.hpp"
#include "detail/pairs.hpp"
#include "detail/symmetric_eigen.hpp"
#include "detail/type_identity.hpp"
#include "detail/vector.hpp"
#include "math.hpp"
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
    if (!(l3 < T(0) && l2 > T(0) && is_finite(l1 - l3))) return E::make_empty();
    const T tan_alpha = std::sqrt(-l3 / l2), tan_beta = std::sqrt(-l3 / l1);
    vec3 z = vec[ineg];
    if (glm::dot(z, toward) < T(0)) z = -z;
    vec3 x = vec[i2];
    x = robust_normalize(x - glm::dot(x, z) * z);
    const vec3 y = glm::cross(z, x);
    const auto world = [&](const vec3& l) { return l.x * basis[0] + l.y * basis[1] + l.z * basis[2]; };
    return E::from_tangents(world(x), world(y), world(z), tan_alpha, min_of(tan_beta, tan_alpha));
}

}  // namespace detail

/// True if the shading point `o` is strictly on the side of the disk's (or any plane's) plane that
/// `normal` points to: (o − center)·normal > 0. A one-sided emitter that emits along +normal
/// lights `o` only then; the projections themselves are two-sided. `normal` need not be unit
/// length. False when o is in the plane and for NaN input.
template <class T>
APSE_FUNC bool disk_faces(const glm::vec<3, T>& o, const glm::vec<3, T>& center,
                          const glm::vec<3, T>& normal) noexcept {
    return glm::dot(o - center, normal) > T(0);
}

/// The spherical ellipse subtended at `o` by the disk {p : (p − center)·n = 0, |p − center| <= radius},
/// docs/math.md §2, in closed form: with d the height of o above the plane, h the distance from the
/// foot of o to the centre, T = d² + h² − r², Delta = sqrt(T² + 4d²r²), lambda = (T + Delta)/2:
/// tan alpha = r/sqrt(lambda), tan beta = r d/lambda (rewritten without cancellation when T < 0);
/// the major axis x is perpendicular to the plane through o, the centre and the normal, and the
/// centre direction z is the cone's axis; the sines, cosines and m come from lambda in closed form
/// too (no trigonometric call; docs/projection.md "Methods").
/// Domain: `normal` any finite non-zero vector (only its direction is used: it is normalised);
/// `radius` > 0; two-sided (use `disk_faces` to cull one-sided emitters).
/// On the disk's axis alpha = beta and the frame is a deterministic function of the normal.
/// Empty (Omega = 0) for: o in the disk's plane (including o on the disk or its rim: the
/// emitter's own surface), radius <= 0, zero or non-finite normal, NaN/Inf anywhere, lights with
/// tan(beta) below detail::tan_min<T>(). Measure: solid angle (two-sided, the disk's projected
/// area on the unit sphere). Accuracy: see the file comment. T is deduced from the vectors
/// alone: the radius may be any arithmetic type (converted to T), e.g. float vectors with a
/// double or int radius.
template <class T>
APSE_FUNC SphericalEllipse<T> project_disk(const glm::vec<3, T>& o, const glm::vec<3, T>& center,
                                           const glm::vec<3, T>& normal, detail::type_identity_t<T> radius) noexcept {
    using vec3 = glm::vec<3, T>;  ///< a 3-D vector (direction, point or normal)
    using E = SphericalEllipse<T>;
    const vec3 w0 = center - o;
    const T w_max = detail::max_abs3(w0);
    const T n2 = glm::dot(normal, normal);
    if (!(radius > T(0)) || !is_finite(radius + w_max + n2)) return E::make_empty();
    // The normal N and 1/|N|, 1/|N|^2 (directly when |N|^2 is a normal number, else rescaled).
    vec3 nv = normal;
    T nn2 = n2;
    if (!(n2 >= detail::tan_min<T>() && n2 <= T(1) / detail::tan_min<T>())) {
        nv = detail::robust_normalize(normal);
        nn2 = glm::dot(nv, nv);
        if (!(nn2 > T(0))) return E::make_empty();
    }
    const T inv_n2 = T(1) / nn2, inv_n = std::sqrt(nn2) * inv_n2;
    // Exact power-of-two rescaling (only when the scene's scale is extreme): max(|w|_inf, r) in
    // [1/2, 1) then, so no product of up to six lengths below can overflow or underflow.
    const T s_max = max_of(w_max, radius);
    vec3 w = w0;
    T r = radius;
    if (!(s_max >= detail::safe_scale_min<T>() && s_max <= detail::safe_scale_max<T>())) {
        const detail::Pow2Scale<T> sc = detail::pow2_scale_for(s_max);
        w = sc(w0);
        r = sc(radius);
    }
    // Height d of o above the plane and the in-plane offset v (foot of o -> centre), h = |v|;
    // d² and h² without square roots (they start the critical path to the tangents).
    const T wn = glm::dot(w, nv);
    const T d2 = wn * wn * inv_n2;  // may underflow to 0 for d ~ 1e-20 |w| (float): harmless
    const T d = std::fabs(wn) * inv_n;
    if (!(d > T(0))) return E::make_empty();
    vec3 v = w - (wn * inv_n2) * nv;
    T h2 = glm::dot(v, v);  // accurate to O(eps |w|)²: enough for alpha and beta
    // A second Gram–Schmidt pass makes v (the frame) exactly perpendicular to n when v is short
    // compared with w (off the critical path: only the frame uses it).
    const bool refine = h2 < T(0.0625) * glm::dot(w, w);
    if (refine) v -= (glm::dot(v, nv) * inv_n2) * nv;
    const vec3 n = nv * inv_n;
    const vec3 zd = wn > T(0) ? n : -n;  // from o towards the plane
    // An offset below the rounding noise of w (or so small that v / h would not be accurate) is
    // the axis: alpha − beta = O(h²) is far below an ulp there, and any frame is exact.
    const T h_min = max_of(T(8) * epsilon<T>() * detail::max_abs3(w), detail::tan_min<T>() * max_of(detail::max_abs3(w), r));
    const bool on_axis = !(h2 > h_min * h_min);
    if (on_axis) h2 = T(0);
    const T h = std::sqrt(h2);
    const T hv = refine ? std::sqrt(glm::dot(v, v)) : h;  // |v| (h² = |v|² unless refined or on the axis)
    // d² + h² − r², and Delta = sqrt(T² + 4 d² r²) (the discriminant of the cone's 2×2 block)
    // (h − r)(h + r) is exact when o is exactly above the rim (h == r), which h² − r² is not
    const T t = d2 + (h - r) * (h + r);
    const T two_dr = T(2) * d * r;
    const T delta2 = t * t + T(4) * d2 * (r * r);
    const T delta = delta2 >= detail::square_safe_min<T>() ? std::sqrt(delta2) : detail::hypot2(t, two_dr);
    // lambda = (T + Delta)/2, the cone's largest in-plane eigenvalue: tan alpha = r / sqrt(lambda),
    // tan beta = r d / lambda. For T < 0, D = Delta − T (a sum of positive terms) gives them
    // without cancellation: tan alpha = sqrt(D/2)/d, tan beta = D/(2 d r), lambda = d r / tan beta.
    // (sin_c, cos_c) ∝ (sin, cos) of the centre's polar angle theta_c from zd (the cone's axis):
    // (h lambda, d (lambda + r²)), for T < 0 the same times D/(d r²): (2 d h, 2 d² + D).
    T lambda, sl, tan_alpha, tan_beta, sin_c, cos_c;  // sl = sqrt(lambda)
    if (t >= T(0)) {
        lambda = T(0.5) * (t + delta);  // >= max(d², d r)
        sl = std::sqrt(lambda);
        // tan beta <= 1: a ratio, exact even for subnormal d r and lambda (1/lambda would overflow)
        detail::div2(r, sl, d * r, lambda, tan_alpha, tan_beta);
        sin_c = h * lambda;
        cos_c = d * (lambda + r * r);
    } else {
        const T big_d = delta - t;
        detail::div2(std::sqrt(T(0.5) * big_d), d, big_d, two_dr, tan_alpha, tan_beta);
        lambda = (d * r) / tan_beta;
        sl = std::sqrt(lambda);
        sin_c = T(2) * d * h;
        cos_c = T(2) * d * d + big_d;
    }
    tan_beta = min_of(tan_beta, tan_alpha);
    const vec3 yd = on_axis ? detail::any_perpendicular(zd) : v * (T(1) / hv);
    const vec3 xd = glm::cross(yd, zd);
    // Every other field in closed form from lambda, without going through the tangents (shorter
    // dependency chains, fewer square roots and divisions than from_tangents): with
    // A = sqrt(lambda + r²), B = sqrt(lambda Delta) (lambda Delta = lambda² + d² r²),
    //   cos alpha = sqrt(lambda)/A, sin alpha = r/A, 1 − cos alpha = r²/(A (A + sqrt lambda)),
    //   cos beta = lambda/B, sin beta = d r/B, 1 − cos beta = d² r²/(B (B + lambda)),
    //   1 − m = cos² alpha / cos² beta = Delta/A², and the centre's polar angle theta_c from zd,
    //   (sin, cos) = (h lambda, d (lambda + r²)) / (A B) (the cone's axis).
    // Beyond the tangent cap, below the tangent floor, or where lambda² would underflow (subnormal
    // heights in float), from_tangents builds the ellipse from the two tangents instead (capping,
    // emptying, rescaling: the rare path).
    if (tan_alpha <= detail::tan_cap<T>() && tan_beta >= detail::tan_min<T>() &&
        lambda * lambda >= detail::square_safe_min<T>()) {
        const T lr = lambda + r * r;
        T a_root, d_root;
        detail::sqrt2(lr, delta, a_root, d_root);
        const T b_root = sl * d_root, dr = d * r;
        T ra, rb;  // 1/(A (A + sqrt lambda)), 1/(B (B + lambda))
        detail::div2(T(1), a_root * (a_root + sl), T(1), b_root * (b_root + lambda), ra, rb);
        const T inv_a = (a_root + sl) * ra, inv_b = (b_root + lambda) * rb;
        const T inv_ab = inv_a * inv_b;
        sin_c = h * lambda * inv_ab;  // the same in both cases: lambda is accurate now
        cos_c = d * lr * inv_ab;
        E e;
        e.x = xd;
        e.y = cos_c * yd - sin_c * zd;
        e.z = sin_c * yd + cos_c * zd;
        e.tan_alpha = tan_alpha;
        e.tan_beta = tan_beta;
        e.sin_alpha = r * inv_a;
        e.cos_alpha = sl * inv_a;
        e.one_minus_cos_alpha = r * r * ra;
        e.sin_beta = dr * inv_b;
        e.cos_beta = lambda * inv_b;
        e.one_minus_cos_beta = dr * (dr * rb);  // (dr² alone may be subnormal in float)
        e.one_minus_m = delta * inv_a * inv_a;
        e.m = (tan_alpha - tan_beta) * (tan_alpha + tan_beta) * (e.cos_alpha * e.cos_alpha);
        return e;
    }
    // The centre's polar angle, normalised by rescaling (its norm² may underflow here).
    const T cs_max = max_of(sin_c, cos_c);
    sin_c /= cs_max;
    cos_c /= cs_max;
    const T inv_norm = T(1) / std::sqrt(sin_c * sin_c + cos_c * cos_c);
    sin_c *= inv_norm;
    cos_c *= inv_norm;
    // A NaN here (only for pathologically underflowing d r) makes from_tangents return empty.
    return E::from_tangents(xd, cos_c * yd - sin_c * zd, sin_c * yd + cos_c * zd, tan_alpha, tan_beta);
}

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
/// project_disk's ellipse (to rounding). Method: the cone matrix is built in the plane's frame
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
    const T s_max = max_of(detail::max_abs3(p0), max_of(detail::max_abs3(semi_axis_u), detail::max_abs3(semi_axis_v)));
    if (!(s_max > T(0))) return E::make_empty();
    const detail::Pow2Scale<T> sc = detail::pow2_scale_for(s_max);
    const vec3 p = sc(p0), u = sc(semi_axis_u), v = sc(semi_axis_v);
    // Parallel axes: u × v is then a rounding residual, which is not exactly 0 when the compiler
    // contracts a·b − c·d into an FMA (-march=x86-64-v3, AArch64, nvcc); below 8 eps |u| |v|
    // (per component) the axes are taken as parallel, so the ellipse is empty either way.
    const vec3 uxv = glm::cross(u, v);
    if (!(detail::max_abs3(uxv) > T(8) * epsilon<T>() * detail::max_abs3(u) * detail::max_abs3(v)))
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
        for (int j = 0; j < 3; ++j) b_max = max_of(b_max, std::fabs(b[i][j]));
    if (!(b_max > T(0)) || !is_finite(b_max)) return E::make_empty();
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

/// The spherical cap subtended at `o` by the sphere |p − center| <= radius (docs/math.md §2b):
/// alpha = beta = asin(radius / |center − o|), tan alpha = radius / sqrt((D − R)(D + R)),
/// z towards the centre, (x, y) a deterministic frame around it.
/// Empty for o inside or on the sphere (documented choice: a point inside sees the emitter in
/// every direction, which is not a spherical ellipse), radius <= 0, NaN/Inf anywhere.
/// Accuracy: tan alpha to a few ulps, except near the surface where D − R inherits the rounding
/// of center − o (relative error ~ eps D/(D − R)). T is deduced from the vectors alone (the
/// radius converts to it, as in project_disk).
template <class T>
APSE_FUNC SphericalEllipse<T> project_sphere(const glm::vec<3, T>& o, const glm::vec<3, T>& center,
                                             detail::type_identity_t<T> radius) noexcept {
    using vec3 = glm::vec<3, T>;  ///< a 3-D vector (direction, point or normal)
    using E = SphericalEllipse<T>;
    const vec3 p0 = center - o;
    const T p_max = detail::max_abs3(p0);
    if (!(radius > T(0)) || !is_finite(radius + p_max) || !detail::finite3(p0)) return E::make_empty();
    const detail::Pow2Scale<T> sc = detail::pow2_scale_for(max_of(p_max, radius));
    const vec3 p = sc(p0);
    const T r = sc(radius);
    const T dist = std::sqrt(glm::dot(p, p));
    if (!(dist > r)) return E::make_empty();
    const T tan_a = r / std::sqrt((dist - r) * (dist + r));
    const vec3 z = p / dist;
    const vec3 x = detail::any_perpendicular(z);
    return E::from_tangents(x, glm::cross(z, x), z, tan_a, tan_a);
}

/// The spherical ellipse subtended at `o` by the solid ellipsoid
/// {center + s1 A1 + s2 A2 + s3 A3 : s1² + s2² + s3² <= 1} (semi-axis vectors A1, A2, A3), docs/math.md §2b:
/// the tangent cone C = (qᵀAq − 1) A − (Aq)(Aq)ᵀ, q = o − center, is decomposed in the
/// ellipsoid's principal frame, without cancelling terms, together with its inverse (the dual
/// quadric diag(a_i²) − q qᵀ) and its exact determinant (detail::ellipse_of_cone): accurate for
/// far, near, pancake and needle ellipsoids alike. Cost: two 3×3 Jacobi solves (~1 µs).
/// A sphere (three equal orthogonal axes) gives project_sphere's cap.
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
    const T s_max = max_of(max_of(detail::max_abs3(q0), detail::max_abs3(axis1)),
                           max_of(detail::max_abs3(axis2), detail::max_abs3(axis3)));
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
    if (!(qn > T(1)) || !is_finite(qn)) return E::make_empty();
    const vec3 qh = qh1 / qn1;
    const T kappa = (qn - T(1)) * (qn + T(1)) / (qn * qn);  // 1 − 1/|q'|²
    // C ∝ G (kappa I − qh qhᵀ) G with G = diag(a_min / a_i): det C = −(g1 g2 g3 kappa / |q'|)².
    // Its inverse: (kappa I − qh qhᵀ)⁻¹ = (I − |q'|² qh qhᵀ) / kappa, so C⁻¹ = Cinv / (kappa rho) with
    // Cinv = diag(a_i / a_max)² − (q / a_max)(q / a_max)ᵀ (the dual cone), rho = (a_min / a_max)².
    const T a_min = min_of(a1, min_of(a2, a3)), a_max = max_of(a1, max_of(a2, a3));
    const vec3 qd(glm::dot(q, e1), glm::dot(q, e2), glm::dot(q, e3));
    if (!(a_max >= detail::tan_min<T>() * detail::max_abs3(qd))) return E::make_empty();  // tan beta < tan_min
    const vec3 g(a_min / a1, a_min / a2, a_min / a3);
    // kappa − qh_i² is written (sum of the other qh_j²) − 1/|q'|²: no cancellation of two terms
    // near 1 when o is far from the ellipsoid along one of its (thin) axes.
    const T inv_q2 = sqr(T(1) / qn);
    const vec3 qh2(qh.x * qh.x, qh.y * qh.y, qh.z * qh.z);
    const vec3 diag(qh2.y + qh2.z - inv_q2, qh2.x + qh2.z - inv_q2, qh2.x + qh2.y - inv_q2);
    const auto c = [&](int i, int j) { return g[i] * g[j] * (i == j ? diag[i] : -qh[i] * qh[j]); };
    const vec3 h(a1 / a_max, a2 / a_max, a3 / a_max);
    const vec3 qa = qd / a_max;
    const auto ci = [&](int i, int j) { return (i == j ? h[i] * h[i] : T(0)) - qa[i] * qa[j]; };
    const T rho = sqr(a_min / a_max);
    const T det_b = g.x * g.y * g.z * kappa / qn;
    const vec3 basis[3] = {e1, e2, e3};
    return detail::ellipse_of_cone(detail::Sym3<T>{c(0, 0), c(0, 1), c(0, 2), c(1, 1), c(1, 2), c(2, 2)},
                                   detail::Sym3<T>{ci(0, 0), ci(0, 1), ci(0, 2), ci(1, 1), ci(1, 2), ci(2, 2)},
                                   kappa * rho, det_b, basis, -qh);
}

}  // namespace apse
