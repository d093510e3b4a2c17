// apse — area-preserving parameterizations for spherical ellipses.
// SPDX-License-Identifier: MIT
#pragma once

/// @file spherical_ellipse.hpp
/// `SphericalEllipse<T>`: the region of the unit sphere cut out by an elliptic cone with apex at
/// the shading point (docs/math.md §1) — what `projection.hpp` produces and every map samples.

#include <cmath>

#include "config.hpp"
#include "detail/glm.hpp"
#include "detail/carlson.hpp"
#include "detail/math.hpp"

namespace apse {
namespace detail {

/// Largest gnomonic semi-axis kept: tan(alpha), tan(beta) are capped here (2^26 in float, 2^55 in
/// double). The region changes only within 1/cap radians of the great circle z = 0, which moves
/// the solid angle by less than half an ulp (the relative change is below 1/cap < eps/4), and
/// keeps tan^2 and every product of two tangents far from overflow (a shading point 1e-30 above
/// a disk still gives a finite, exact-to-rounding ellipse).
template <class T> APSE_FUNC constexpr T tan_cap() noexcept {
    return sizeof(T) == sizeof(float) ? T(0x1p26) : T(0x1p55);
}

/// Smallest non-empty minor gnomonic semi-axis, sqrt(smallest normal number) (2^-63 in float,
/// 2^-511 in double): squares, products and ratios of the tangents then stay normal and finite
/// (contains() divides by tan_beta; maps take tan_alpha / tan_beta). Below it the ellipse is
/// empty: its solid angle is below 4 tan_min (4e-19 sr in float, 6e-154 sr in double).
template <class T> APSE_FUNC constexpr T tan_min() noexcept {
    return sizeof(T) == sizeof(float) ? T(0x1p-63) : T(0x1p-511);
}

/// sin, cos and 1 − cos of atan(t) for 0 <= t <= tan_cap (so t² cannot overflow), without
/// cancellation and without a branch: with q = 1 + t², R = 1 / (sqrt(q) (q + sqrt(q))),
/// cos = 1/sqrt(q) = (q + sqrt(q)) R, 1 − cos = t²/(q + sqrt(q)) = t² sqrt(q) R, sin = t cos.
/// Both tangents of an ellipse at once, their square roots and divisions paired (detail::sqrt2,
/// detail::div2; bit-identical to one at a time).
/// The cone test of SphericalEllipse::contains for a direction (x, y, z) in the ellipse's frame:
/// z > 0 and (x/(z ta))^2 + (y/(z tb))^2 <= 1 (gnomonic coordinates over the semi-axes; an
/// overflowing ratio means outside, a NaN one too).
template <class T> APSE_FUNC bool inside_cone(T x, T y, T z, T ta, T tb) noexcept {
    if (!(z > T(0))) return false;
    const T u = (x / z) / ta, v = (y / z) / tb;
    return u * u + v * v <= T(1);
}

template <class T> struct SinCos {
    T s, c, omc;
};
template <class T> APSE_FUNC void sin_cos_of_atan2(T ta, T tb, SinCos<T>& a, SinCos<T>& b) noexcept {
    const T ta2 = ta * ta, tb2 = tb * tb, qa = T(1) + ta2, qb = T(1) + tb2;
    T sqa, sqb;
    sqrt2(qa, qb, sqa, sqb);
    const T qsa = qa + sqa, qsb = qb + sqb;
    T ra, rb;
    div2(T(1), sqa * qsa, T(1), sqb * qsb, ra, rb);
    const T ca = qsa * ra, cb = qsb * rb;
    a = {ta * ca, ca, ta2 * sqa * ra};
    b = {tb * cb, cb, tb2 * sqb * rb};
}

}  // namespace detail

/// A spherical ellipse (docs/math.md §1): the directions `w` with `w.z > 0` and
/// `(w.x / (w.z tan alpha))^2 + (w.y / (w.z tan beta))^2 <= 1` in its own frame, i.e. the
/// intersection of the unit sphere with an elliptic cone whose axis is `z`.
///
/// * `x, y, z`: world-space, right-handed (`x × y = z`), orthonormal frame — `x` the major axis,
///   `y` the minor axis, `z` the centre direction.
/// * semi-arcs `pi/2 >= alpha >= beta >= 0` (radians, measured on the sphere from `z`), stored as
///   their tangents (the gnomonic semi-axes, the primary representation: accurate from 1e-150 to
///   the cap 2^55 in double, 2^26 in float) with sines, cosines and 1 − cos computed once, without
///   cancellation, from the two tangents. The arcs themselves are `alpha()` and `beta()` (one atan
///   per call: of the maps only the parallel one needs them, once, at set-up).
/// * `m`, `one_minus_m`: the parameter m = k^2 = (tan^2 alpha − tan^2 beta)/(1 + tan^2 alpha) of the
///   ellipse's elliptic integrals (docs/math.md §3) and its complement 1 − m = cos^2 alpha / cos^2 beta,
///   both computed without cancellation.
///
/// Build it with `from_tangents` (or a `project_*` function); it is trivially copyable and
/// cheap to pass by value to GPU kernels. The *empty* ellipse (solid angle 0; every field 0 except
/// `cos_alpha = cos_beta = one_minus_m = 1` and the identity frame) stands for degenerate or
/// invalid input; test it with `empty()` before sampling.
template <class T> struct SphericalEllipse {
    static_assert(detail::is_real_type<T>(), "apse: SphericalEllipse<T>: T must be float or double");
    using vec3 = glm::vec<3, T>;  ///< a 3-D vector (direction, point or normal)

    vec3 x;  ///< major-axis direction (world space, unit)
    vec3 y;  ///< minor-axis direction (world space, unit), y = z × x
    vec3 z;  ///< centre direction (world space, unit)
    T tan_alpha;            ///< tan(alpha): gnomonic major semi-axis, <= detail::tan_cap<T>()
    T tan_beta;             ///< tan(beta): gnomonic minor semi-axis, 0 iff empty
    T sin_alpha;            ///< sin(alpha): orthographic major semi-axis
    T sin_beta;             ///< sin(beta): orthographic minor semi-axis
    T cos_alpha;            ///< cos(alpha)
    T cos_beta;             ///< cos(beta)
    T one_minus_cos_alpha;  ///< 1 − cos(alpha) = sin^2/(1 + cos), no cancellation
    T one_minus_cos_beta;   ///< 1 − cos(beta), no cancellation
    T m;                    ///< (tan^2 alpha − tan^2 beta)/(1 + tan^2 alpha), in [0, 1] (it
                            ///< rounds to 1 for thin wide ellipses: use one_minus_m there)
    T one_minus_m;          ///< (1 + tan^2 beta)/(1 + tan^2 alpha) = 1 − m, in (0, 1]

    /// The empty ellipse (solid angle 0): identity frame, zero arcs.
    static APSE_FUNC SphericalEllipse make_empty() noexcept {
        SphericalEllipse e{};
        e.x = vec3(T(1), T(0), T(0));
        e.y = vec3(T(0), T(1), T(0));
        e.z = vec3(T(0), T(0), T(1));
        e.cos_alpha = e.cos_beta = e.one_minus_m = T(1);
        return e;
    }

    /// The ellipse with frame (x, y, z) and gnomonic semi-axes tan_alpha, tan_beta; fills every
    /// derived field from the two tangents (so they are mutually consistent).
    /// Domain: (x, y, z) a right-handed orthonormal frame (not checked beyond finiteness: the
    /// caller guarantees it), tan_alpha, tan_beta >= 0 (+inf allowed).
    /// * tan_beta > tan_alpha: the roles are swapped, with the frame rotated to (y, −x, z), so
    ///   the result keeps `x` on the major axis and stays right-handed.
    /// * tangents above detail::tan_cap<T>() (e.g. +inf: a semi-arc of exactly pi/2) are capped
    ///   there; the solid angle moves by less than half an ulp.
    /// * minor tangent below detail::tan_min<T>() (solid angle < ~1e-19 sr in float,
    ///   ~1e-153 sr in double), a NaN or negative tangent, a non-finite frame: the empty ellipse.
    static APSE_FUNC SphericalEllipse from_tangents(const vec3& x, const vec3& y, const vec3& z,
                                                   T tan_alpha, T tan_beta) noexcept {
        if (!(tan_alpha >= T(0) && tan_beta >= T(0))) return make_empty();
        const T frame_sum = (x.x + x.y + x.z) + (y.x + y.y + y.z) + (z.x + z.y + z.z);
        if (!detail::is_finite(frame_sum)) return make_empty();
        SphericalEllipse e;
        if (tan_beta > tan_alpha) {
            e.x = y;
            e.y = -x;
            const T t = tan_alpha;
            tan_alpha = tan_beta;
            tan_beta = t;
        } else {
            e.x = x;
            e.y = y;
        }
        e.z = z;
        const T cap = detail::tan_cap<T>();
        const T ta = detail::min_of(tan_alpha, cap), tb = detail::min_of(tan_beta, cap);
        if (!(tb >= detail::tan_min<T>())) return make_empty();
        e.tan_alpha = ta;
        e.tan_beta = tb;
        detail::SinCos<T> sa, sb;
        detail::sin_cos_of_atan2(ta, tb, sa, sb);
        e.sin_alpha = sa.s;
        e.cos_alpha = sa.c;
        e.sin_beta = sb.s;
        e.cos_beta = sb.c;
        e.one_minus_cos_alpha = sa.omc;
        e.one_minus_cos_beta = sb.omc;
        const T inv = T(1) / (T(1) + ta * ta);
        e.m = (ta - tb) * (ta + tb) * inv;
        e.one_minus_m = (T(1) + tb * tb) * inv;
        return e;
    }

    /// from_tangents(x, y, z, tan(alpha), tan(beta)) for semi-arcs given in radians; arcs in
    /// [pi/2, pi) or negative are out of the domain (empty ellipse), NaN → empty.
    static APSE_FUNC SphericalEllipse from_arcs(const vec3& x, const vec3& y, const vec3& z,
                                               T alpha, T beta) noexcept {
        const T h = detail::half_pi_v<T>;
        if (!(alpha >= T(0) && alpha <= h && beta >= T(0) && beta <= h)) return make_empty();
        // tan(float(pi/2)) is negative in float: use the cap (tan of pi/2 to rounding) there.
        const T ta = alpha >= h ? detail::tan_cap<T>() : std::tan(alpha);
        const T tb = beta >= h ? detail::tan_cap<T>() : std::tan(beta);
        return from_tangents(x, y, z, ta, tb);
    }

    /// Major semi-arc alpha = atan(tan_alpha) (radians), in [beta(), pi/2]; 0 for the empty
    /// ellipse. Computed on each call (one atan, accurate to ~1 ulp).
    APSE_FUNC T alpha() const noexcept { return std::atan(tan_alpha); }

    /// Minor semi-arc beta = atan(tan_beta) (radians), in [0, alpha()]; 0 for the empty ellipse.
    /// Computed on each call (one atan).
    APSE_FUNC T beta() const noexcept { return std::atan(tan_beta); }

    /// True for the empty ellipse (solid angle 0: degenerate or invalid input). Maps built on an
    /// empty ellipse return pdf 0 ("no sample").
    APSE_FUNC bool empty() const noexcept { return !(tan_beta > T(0)); }

    /// True for a spherical cap: a non-empty ellipse whose two semi-axes are exactly equal
    /// (tan_alpha == tan_beta), as project_sphere gives. The maps sample caps by closed forms.
    APSE_HOT_INLINE bool is_cap() const noexcept { return tan_beta == tan_alpha && !empty(); }

    /// Solid angle of a cap (is_cap(); steradians): 2 pi (1 − cos alpha) from the stored
    /// 1 − cos alpha (no cancellation, one product). For the smallest caps, whose 1 − cos alpha
    /// is subnormal (tan alpha below ~1e-19 in float, ~1e-154 in double) and flushed to 0 where
    /// denormals are (-ffast-math), (2 pi sin alpha) sin alpha / (1 + cos alpha) instead, which
    /// stays normal. Not meaningful for other ellipses (solid_angle() is).
    APSE_HOT_INLINE T cap_solid_angle() const noexcept {
        if (one_minus_cos_alpha > T(0)) return detail::two_pi_v<T> * one_minus_cos_alpha;
        return (detail::two_pi_v<T> * sin_alpha) * sin_alpha / (T(1) + cos_alpha);
    }

    /// Solid angle (steradians) of the ellipse, docs/math.md §3, by the cancellation-free form
    /// Omega = (4/3) tan(alpha) tan(beta) R_J(0, 1 + tan^2 beta, 1 + tan^2 alpha, 1)
    ///       = (4/3) sin(alpha) cos(alpha) sin(beta) cos(beta) sqrt(P) R_J(0, cos^2 alpha, cos^2 beta, P),
    /// P = cos^2 alpha cos^2 beta (homogeneity of R_J), evaluated from the stored sines and
    /// cosines by Bulirsch's transformation (detail::cel_core, which takes the square roots
    /// cos beta, cos alpha, sqrt(P) directly: no square root before its first step, every term
    /// positive, 4-5 steps for most ellipses). Range (0, 2 pi] (clamped to the rounded 2 pi); 0
    /// for the empty ellipse. Relative accuracy a few eps of T for every ellipse (measured
    /// <= 4.5 eps from 1e-27 sr to 2 pi; no cancellation down to 1e-300 sr in double;
    /// docs/projection.md). Computed on each call (~20-30 ns): maps cache it.
    APSE_FUNC T solid_angle() const noexcept {
        if (empty()) return T(0);
        const T ca = cos_alpha, cb = cos_beta;  // cb >= ca >= 2^-55 (double), 2^-26 (float)
        const T rj_q = detail::cel_core<T, false>(cb, ca, ca * cb).rj;
        return detail::min_of(T(4) / T(3) * (sin_alpha * ca) * (sin_beta * cb) * rj_q, detail::two_pi_v<T>);  // may round past 2 pi
    }

    /// World → ellipse frame: (dot(w, x), dot(w, y), dot(w, z)). Any vector, any length.
    APSE_HOT_INLINE vec3 to_local(const vec3& world) const noexcept {
        return vec3(glm::dot(world, x), glm::dot(world, y), glm::dot(world, z));
    }

    /// Ellipse frame → world: local.x x + local.y y + local.z z.
    APSE_HOT_INLINE vec3 to_world(const vec3& local) const noexcept {
        return local.x * x + local.y * y + local.z * z;
    }

    /// True if the world-space direction (any non-zero length: the test is homogeneous) lies
    /// inside the ellipse or on its boundary: the exact cone test in the ellipse frame,
    /// l.z > 0 and (l.x/(l.z tan alpha))^2 + (l.y/(l.z tan beta))^2 <= 1 with l = to_local(d).
    /// Never overflows into a wrong answer (an overflowing ratio means "outside"). False for the
    /// empty ellipse, a zero, NaN or infinite direction. Directions within a few ulps of the
    /// boundary may fall either way (rounding of to_local).
    APSE_FUNC bool contains(const vec3& world_direction) const noexcept {
        const vec3 l = to_local(world_direction);
        return !empty() && detail::inside_cone(l.x, l.y, l.z, tan_alpha, tan_beta);
    }
};

namespace detail {

/// (x, y) completing the unit vector z to a right-handed orthonormal basis: Duff et al.'s
/// branchless basis ("Building an Orthonormal Basis, Revisited", JCGT 2017), continuous except
/// where z.z changes sign; its divisor sign + z.z is at least 1 in magnitude (no cancellation).
template <class T>
APSE_HOT_INLINE void basis_around(const glm::vec<3, T>& z, glm::vec<3, T>& x, glm::vec<3, T>& y) noexcept {
    const T sign = std::copysign(T(1), z.z), a = T(-1) / (sign + z.z), b = z.x * z.y * a;
    x = glm::vec<3, T>(T(1) + sign * z.x * z.x * a, sign * b, -sign * z.x);
    y = glm::vec<3, T>(b, sign + z.y * z.y * a, -z.y);
}

/// The spherical cap a sphere subtends at a shading point, without a frame around its centre:
/// what project_sphere computes before it builds that frame, and what a sampler of caps that
/// needs no frame (ProjectedCapSampler) reads. `ellipse()` completes it into project_sphere's
/// SphericalEllipse, bit for bit. Fields as SphericalEllipse's for alpha = beta; `distance` =
/// |center − o| (for the shadow rays of SphereLight). Empty (tan_alpha 0) where project_sphere's
/// result is.
template <class T> struct SphereCap {
    glm::vec<3, T> z{T(0), T(0), T(1)};  ///< centre direction (unit)
    T tan_alpha = T(0);                    ///< tan(alpha); 0 iff empty
    T sin_alpha = T(0);                    ///< sin(alpha)
    T cos_alpha = T(1);                    ///< cos(alpha)
    T one_minus_cos_alpha = T(0);          ///< 1 − cos(alpha), no cancellation
    T distance = T(0);                     ///< |center − o| (0 when empty)

    /// True if the sphere subtends no cap (invalid input, o inside or on it, too small a cap).
    APSE_HOT_INLINE bool empty() const noexcept { return !(tan_alpha > T(0)); }

    /// The cap as a SphericalEllipse (project_sphere's result), (x, y) = basis_around(z).
    APSE_HOT_INLINE SphericalEllipse<T> ellipse() const noexcept {
        if (empty()) return SphericalEllipse<T>::make_empty();
        SphericalEllipse<T> e;
        basis_around(z, e.x, e.y);
        e.z = z;
        e.tan_alpha = e.tan_beta = tan_alpha;
        e.sin_alpha = e.sin_beta = sin_alpha;
        e.cos_alpha = e.cos_beta = cos_alpha;
        e.one_minus_cos_alpha = e.one_minus_cos_beta = one_minus_cos_alpha;
        e.m = T(0);
        e.one_minus_m = T(1);
        return e;
    }
};

/// The ellipse of a cap given as a SphericalEllipse (itself) or as a SphereCap (its ellipse()):
/// for the samplers that take either.
template <class T> APSE_HOT_INLINE const SphericalEllipse<T>& ellipse_of(const SphericalEllipse<T>& e) noexcept { return e; }
template <class T> APSE_HOT_INLINE SphericalEllipse<T> ellipse_of(const SphereCap<T>& c) noexcept { return c.ellipse(); }

}  // namespace detail

}  // namespace apse
