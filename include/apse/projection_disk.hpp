// apse — area-preserving parameterizations for spherical ellipses.
// SPDX-License-Identifier: MIT
#pragma once

/// @file projection_disk.hpp
/// The spherical ellipse subtended by a disk, in closed form (docs/math.md §2), and the one-sided
/// emitter's side test. The conventions shared by every projection (two-sided geometry, the empty
/// ellipse for invalid input, scale invariance, accuracy) are in projection.hpp.

#include <cmath>

#include "config.hpp"
#include "detail/glm.hpp"
#include "detail/type_identity.hpp"
#include "detail/vector.hpp"
#include "disk_frame.hpp"
#include "detail/math.hpp"
#include "spherical_ellipse.hpp"

namespace apse {

/// True if the shading point `o` is strictly on the side of the disk's (or any plane's) plane that
/// `normal` points to: (o − center)·normal > 0. A one-sided emitter that emits along +normal
/// lights `o` only then; the projections themselves are two-sided. `normal` need not be unit
/// length. False when o is in the plane and for NaN input.
template <class T>
APSE_FUNC bool disk_faces(const glm::vec<3, T>& o, const glm::vec<3, T>& center,
                          const glm::vec<3, T>& normal) noexcept {
    return glm::dot(o - center, normal) > T(0);
}

namespace detail {

/// project_disk after its input checks: w0 = center − o (finite), w_max = max |w0_i|, nv the
/// disk's normal with inv_n2 = 1/|nv|² and inv_n = 1/|nv| (both 1 for a DiskFrame's unit normal),
/// radius > 0 and finite.
template <class T>
APSE_HOT_INLINE SphericalEllipse<T> project_disk_checked(const glm::vec<3, T>& w0, T w_max, const glm::vec<3, T>& nv,
                                                         T inv_n2, T inv_n, T radius) noexcept {
    using vec3 = glm::vec<3, T>;  ///< a 3-D vector (direction, point or normal)
    using E = SphericalEllipse<T>;
    // Exact power-of-two rescaling (only when the scene's scale is extreme): max(|w|_inf, r) in
    // [1/2, 1) then, so no product of up to six lengths below can overflow or underflow.
    const T s_max = detail::max_of(w_max, radius);
    vec3 w = w0;
    T r = radius;
    if (!(s_max >= detail::safe_scale_min<T>() && s_max <= detail::safe_scale_max<T>())) {
        const detail::Pow2Scale<T> sc = detail::pow2_scale_for(s_max);
        w = sc(w0);
        r = sc(radius);
    }
    // Height d of o above the plane and the in-plane offset v (foot of o -> centre), h = |v|;
    // d² and h² without square roots (they start the critical path to the tangents).
    const T wn = glm::dot(w, nv), wn_n2 = wn * inv_n2;
    // d² as (wn / |N|²) wn, not wn² / |N|²: wn² alone is subnormal in float for |N|² ~ 1e-17 and
    // d ~ 1e-14 |w| (and d² then off by percents); d² itself may underflow to 0 for d ~ 1e-20 |w|
    // (float): harmless
    const T d2 = wn_n2 * wn;
    const T d = std::fabs(wn) * inv_n;
    if (!(d > T(0))) return E::make_empty();
    vec3 v = w - wn_n2 * nv;
    T h2 = glm::dot(v, v);  // accurate to O(eps |w|)²: enough for alpha and beta
    // A second Gram–Schmidt pass makes v (the frame) exactly perpendicular to n when v is short
    // compared with w (off the critical path: only the frame uses it).
    const bool refine = h2 < T(0.0625) * glm::dot(w, w);
    if (refine) v -= (glm::dot(v, nv) * inv_n2) * nv;
    const vec3 n = nv * inv_n;
    const vec3 zd = n * std::copysign(T(1), wn);  // from o towards the plane (wn != 0 here; no branch)
    // An offset below the rounding noise of w (or so small that v / h would not be accurate) is
    // the axis: alpha − beta = O(h²) is far below an ulp there, and any frame is exact.
    const T h_min = detail::max_of(T(8) * detail::epsilon<T>() * detail::max_abs3(w), detail::tan_min<T>() * detail::max_of(detail::max_abs3(w), r));
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
    // On the axis (the offset below the rounding of w) the cone is circular: its tangents, <= 2
    // eps apart there (measured), are made exactly equal, so that the maps take their closed-form
    // cap path (docs/math.md §2b, Caps under rounding); the solid angle and the pdf move by at most
    // 2 eps relative. Off the axis the tangents are kept as computed (tangents that came out
    // exactly equal are a cap as they are and keep the closed form below).
    const bool circular = on_axis && tan_beta != tan_alpha;
    tan_beta = circular ? tan_alpha : detail::min_of(tan_beta, tan_alpha);
    const vec3 yd = on_axis ? detail::any_perpendicular(zd) : v * (T(1) / hv);
    const vec3 xd = glm::cross(yd, zd);
    // Every other field in closed form from lambda, without going through the tangents (shorter
    // dependency chains, fewer square roots and divisions than from_tangents): with
    // A = sqrt(lambda + r²), B = sqrt(lambda Delta) (lambda Delta = lambda² + d² r²),
    //   cos alpha = sqrt(lambda)/A, sin alpha = r/A, 1 − cos alpha = r²/(A (A + sqrt lambda)),
    //   cos beta = lambda/B, sin beta = d r/B, 1 − cos beta = d² r²/(B (B + lambda)),
    //   1 − m = cos² alpha / cos² beta = Delta/A², and the centre's polar angle theta_c from zd,
    //   (sin, cos) = (h lambda, d (lambda + r²)) / (A B) (the cone's axis).
    // Beyond the tangent cap, below the tangent floor, where lambda² would underflow (subnormal
    // heights in float), or for a circular cone (an exact cap, both tangents equal),
    // from_tangents builds the ellipse from the two tangents instead (capping, emptying,
    // rescaling, the cap's equal fields: the rare path, out of the general path's way).
    if (!circular && tan_alpha <= detail::tan_cap<T>() && tan_beta >= detail::tan_min<T>() &&
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
    const T cs_max = detail::max_of(sin_c, cos_c);
    sin_c /= cs_max;
    cos_c /= cs_max;
    const T inv_norm = T(1) / std::sqrt(sin_c * sin_c + cos_c * cos_c);
    sin_c *= inv_norm;
    cos_c *= inv_norm;
    // A NaN here (only for pathologically underflowing d r) makes from_tangents return empty.
    return E::from_tangents(xd, cos_c * yd - sin_c * zd, sin_c * yd + cos_c * zd, tan_alpha, tan_beta);
}

}  // namespace detail

/// The spherical ellipse subtended at `o` by the disk {p : (p − center)·n = 0, |p − center| <= radius},
/// docs/math.md §2, in closed form: with d the height of o above the plane, h the distance from the
/// foot of o to the centre, T = d² + h² − r², Delta = sqrt(T² + 4d²r²), lambda = (T + Delta)/2:
/// tan alpha = r/sqrt(lambda), tan beta = r d/lambda (rewritten without cancellation when T < 0);
/// the major axis x is perpendicular to the plane through o, the centre and the normal, and the
/// centre direction z is the cone's axis; the sines, cosines and m come from lambda in closed form
/// too (no trigonometric call; docs/projection.md "Methods").
/// Domain: `normal` any finite non-zero vector (only its direction is used: it is normalised);
/// `radius` > 0; two-sided (use `disk_faces` to cull one-sided emitters).
/// On the disk's axis (o − center along the normal to within its rounding) alpha = beta exactly
/// (SphericalEllipse::is_cap(): the tangents are made equal, docs/math.md §2b "Caps under
/// rounding", so the maps take their closed-form cap path; the solid angle moves by at most 2 eps
/// relative) and the frame is a deterministic function of the normal.
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
    if (!(radius > T(0)) || !detail::is_finite(radius + w_max + n2)) return E::make_empty();
    // The normal N and 1/|N|, 1/|N|^2 (directly when |N|^2 is a normal number, else rescaled).
    vec3 nv = normal;
    T nn2 = n2;
    if (!(n2 >= detail::tan_min<T>() && n2 <= T(1) / detail::tan_min<T>())) {
        nv = detail::robust_normalize(normal);
        nn2 = glm::dot(nv, nv);
        if (!(nn2 > T(0))) return E::make_empty();
    }
    const T inv_n2 = T(1) / nn2;
    return detail::project_disk_checked(w0, w_max, nv, inv_n2, std::sqrt(nn2) * inv_n2, T(radius));
}

/// project_disk for the light's stored frame (disk_frame.hpp: unit normal, radius): the same
/// ellipse as project_disk(o, frame.center, frame.n, frame.radius) up to rounding (the stored
/// normal is used as unit length: no normalisation per shading point). Empty for an invalid
/// frame and as above.
template <class T>
APSE_FUNC SphericalEllipse<T> project_disk(const glm::vec<3, T>& o, const DiskFrame<T>& frame) noexcept {
    const glm::vec<3, T> w0 = frame.center - o;
    const T w_max = detail::max_abs3(w0);
    if (!frame.valid() || !detail::is_finite(w_max)) return SphericalEllipse<T>::make_empty();
    return detail::project_disk_checked(w0, w_max, frame.n, T(1), T(1), frame.radius);
}

}  // namespace apse
