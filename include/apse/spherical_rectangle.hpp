// apse — area-preserving parameterizations for spherical ellipses.
// SPDX-License-Identifier: MIT
#pragma once

/// @file spherical_rectangle.hpp
/// Uniform sampling of the solid angle subtended by a planar rectangle: the area-preserving map
/// of Ureña, Fajardo & King, "An Area-Preserving Parametrization for Spherical Rectangles"
/// (EGSR 2013), docs/math.md §7. A rectangle-light sampler in its own right, and the building block of
/// the Gamito baseline (baselines/gamito.hpp).
///
/// The map is the published one — u1 picks the column x of the rectangle whose left part
/// [x0, x] has solid angle u1·S, u2 is uniform in h = y / sqrt(x² + y² + d²) along that column —
/// but evaluated without the cancellations of the published formulas, which lose
/// log10(1/S) digits for far or small rectangles (S = g0+g1+g2+g3 − 2π):
///  * solid angles of the rectangle and of its left parts are sums of up to four positive pieces
///    cut by the lines through o's foot point, each in a cancellation-free closed form (corner
///    arctangent, rewritten difference of two, or Van Oosterom–Strackee triangles), added with
///    the tangent addition theorem (detail::rectangle_solid_angle);
///  * the column is Ureña's closed form (rewritten around the angle sum minus π) as a first
///    guess, polished by bracketed Newton steps on the cancellation-free left-part solid angle
///    (exact derivative: the column's solid-angle density);
///  * the position along the column and the hit point are computed as offsets from the corner,
///    with complementary quantities (1 ∓ h) carried separately, so the point is accurate
///    relative to the rectangle's size even when the shading point is 1e8 sizes away.
/// Everything is computed natively in T, after an exact power-of-two rescaling of the local
/// coordinates (no overflow or underflow for coordinates within T's range).

#include <cmath>

#include "config.hpp"
#include "detail/glm.hpp"
#include "detail/vector.hpp"
#include "detail/math.hpp"
#include "sample.hpp"

namespace apse {

/// A point of a rectangle light seen from the shading point o: what `SphericalRectangle::
/// sample_point` returns for a sample and `SphericalRectangle::locate` for a direction — a
/// PointSample (direction, pdf in **solid angle** (1/S; 0 = no sample / not on it), point,
/// distance) with the point's rectangle coordinates.
template <class T> struct RectanglePoint : PointSample<T> {
    glm::vec<2, T> st;  ///< rectangle coordinates: point = corner + st.x·edge_x + st.y·edge_y
};

namespace detail {

/// y1/sqrt(q2 + y1²) − y0/sqrt(q2 + y0²) for y0 <= y1, given l_i = sqrt(q2 + y_i²) and
/// dy = y1 − y0 (passed separately: it is often known more accurately than the difference).
/// Free of cancellation: when y0 and y1 have the same sign it is rewritten as
/// q2·dy·(y0 + y1) / (l0 l1 (y1 l0 + y0 l1)), all of whose factors are free of cancellation.
template <class T>
APSE_FUNC T sine_difference(T y0, T y1, T dy, T l0, T l1, T q2) noexcept {
    if (y0 < T(0) && y1 > T(0)) return y1 / l1 - y0 / l0;
    const T den = l0 * l1 * (y1 * l0 + y0 * l1);
    return den != T(0) ? q2 * dy * (y1 + y0) / den : T(0);
}

/// 1 − y/l and 1 + y/l (l = sqrt(q2 + y²)), each computed without cancellation.
template <class T>
APSE_FUNC void sine_complements(T y, T l, T q2, T& one_minus, T& one_plus) noexcept {
    if (y >= T(0)) {
        one_minus = q2 / (l * (l + y));
        one_plus = T(1) + y / l;
    } else {
        one_minus = T(1) - y / l;
        one_plus = q2 / (l * (l - y));
    }
}

/// An angle in [0, pi] kept as an unnormalised (sin, cos) pair: angle = atan2(y, x). Sums of
/// such angles are formed with the addition theorem, so a sum of pieces costs one arctangent.
template <class T> struct AnglePair {
    T y, x;
    /// this + other (valid while the sum stays within [0, pi]); no cancellation in y since
    /// both sines are >= 0 (x can cancel, but only where atan2 is insensitive to it).
    APSE_FUNC AnglePair plus(const AnglePair& o) const noexcept { return {y * o.x + o.y * x, x * o.x - y * o.y}; }
};

/// Solid angle of [x0, x1] x [y0, y1] (0 <= x0 < x1, 0 <= y0 < y1; xw = x1 − x0, yw = y1 − y0
/// passed exactly) in the plane z = −d seen from the origin — a rectangle in the first quadrant
/// of its plane about the foot point (0, 0), hence at most pi/2 — as an AnglePair. Exact forms
/// free of cancellation:
///  * x0 = y0 = 0: the corner term atan(x1 y1 / (d r11));
///  * y0 = 0 (or x0 = 0): a difference of two corner terms with the same y, written as one
///    angle with tangent (y1 d (x1/r11 − x0/r01)) / (d² + x0 x1 y1² / (r01 r11)) (sine_difference);
///  * x0, y0 > 0: two Van Oosterom–Strackee triangles, tan(Omega_i / 2) = N_i / D_i, where
///    N_i = d·xw·yw / (product of the corner distances) is exact and D_i = 1 + the three pairwise
///    cosines has no cancellation since every cosine is positive in this quadrant; the half
///    angles are added (N, D) = (N1 D2 + N2 D1, D1 D2 − N1 N2) and doubled, (2 N D, (D − N)(D + N))
///    (the half angle is below pi/4, so D > N).
template <class T>
APSE_FUNC AnglePair<T> quadrant_rectangle_angle(T x0, T xw, T y0, T yw, T d) noexcept {
    const T x1 = x0 + xw, y1 = y0 + yw, d2 = d * d;
    if (x0 == T(0) && y0 == T(0)) return {x1 * y1, d * std::sqrt(x1 * x1 + y1 * y1 + d2)};
    if (y0 == T(0) || x0 == T(0)) {
        // by symmetry, a difference along the axis whose lower bound is not 0
        const T a0 = y0 == T(0) ? x0 : y0, aw = y0 == T(0) ? xw : yw;
        const T b = y0 == T(0) ? y1 : x1, a1 = a0 + aw;
        const T q2 = b * b + d2;
        const T r0 = std::sqrt(q2 + a0 * a0), r1 = std::sqrt(q2 + a1 * a1);
        return {b * d * sine_difference(a0, a1, aw, r0, r1, q2), d2 + a0 * a1 * b * b / (r0 * r1)};
    }
    const T l00 = std::sqrt(x0 * x0 + y0 * y0 + d2), l10 = std::sqrt(x1 * x1 + y0 * y0 + d2);
    const T l11 = std::sqrt(x1 * x1 + y1 * y1 + d2), l01 = std::sqrt(x0 * x0 + y1 * y1 + d2);
    const T c00_10 = (x0 * x1 + y0 * y0 + d2) / (l00 * l10);
    const T c00_11 = (x0 * x1 + y0 * y1 + d2) / (l00 * l11);
    const T c10_11 = (x1 * x1 + y0 * y1 + d2) / (l10 * l11);
    const T c00_01 = (x0 * x0 + y0 * y1 + d2) / (l00 * l01);
    const T c11_01 = (x0 * x1 + y1 * y1 + d2) / (l11 * l01);
    const T vol = d * xw * yw;
    const T n1 = vol / (l00 * l10 * l11), n2 = vol / (l00 * l11 * l01);
    const T D1 = T(1) + c00_10 + c00_11 + c10_11, D2 = T(1) + c00_11 + c00_01 + c11_01;
    const T n = n1 * D2 + n2 * D1, dd = D1 * D2 - n1 * n2;
    return {T(2) * n * dd, (dd - n) * (dd + n)};
}

/// Splits [x0, x0 + w] at 0 into at most two pieces mirrored to [a, a + aw] with a >= 0.
template <class T>
APSE_FUNC int split_at_foot(T x0, T w, T* a, T* aw) noexcept {
    const T x1 = x0 + w;
    if (x0 >= T(0)) { a[0] = x0; aw[0] = w; return 1; }
    if (x1 <= T(0)) { a[0] = -x1; aw[0] = w; return 1; }
    a[0] = T(0); aw[0] = -x0;
    a[1] = T(0); aw[1] = x1;
    return 2;
}

/// Solid angle (steradians) of the rectangle [x0, x0 + w] x [y0, y0 + h] in the plane z = −d
/// (d > 0) seen from the origin. The rectangle is cut by the lines x = 0 and y = 0 through the
/// foot point into at most four pieces, each mirrored into the first quadrant and evaluated by
/// quadrant_rectangle_angle: a sum of positive terms, each free of cancellation, hence a
/// relative error of a few ulps for near, far, grazing, tiny and thin rectangles alike. Pieces
/// in the same half-plane (at most pi together) are added as AnglePairs: one or two arctangents.
template <class T>
APSE_FUNC T rectangle_solid_angle(T x0, T w, T y0, T h, T d) noexcept {
    T xa[2], xw[2], ya[2], yw[2];
    const int nx = split_at_foot(x0, w, xa, xw), ny = split_at_foot(y0, h, ya, yw);
    // pieces mirrored onto each other (a rectangle centred on the foot's line) are computed once
    const bool twin = nx == 2 && xw[0] == xw[1];
    T sum = T(0);
    for (int i = 0; i < (twin ? 1 : nx); ++i) {
        AnglePair<T> half{T(0), T(1)};
        for (int j = 0; j < ny; ++j)
            if (xw[i] > T(0) && yw[j] > T(0)) half = half.plus(quadrant_rectangle_angle(xa[i], xw[i], ya[j], yw[j], d));
        sum += std::atan2(half.y, half.x);
    }
    return twin ? T(2) * sum : sum;
}

}  // namespace detail

/// The spherical rectangle subtended by a planar rectangle light at a shading point `o`, with
/// the Ureña–Fajardo–King area-preserving map from the unit square (docs/math.md §7).
///
/// * Geometry is two-sided: o may be on either side of the plane (cull one-sided emitters
///   yourself). The rectangle is `corner + [0,1]·edge_x + [0,1]·edge_y`; the edges should be
///   orthogonal — the component of `edge_y` along `edge_x` is ignored (documented, not an error).
/// * Empty (solid angle 0, every pdf 0, `sample` returns "no sample"): o in the rectangle's plane,
///   a zero, NaN or infinite edge/coordinate, or a solid angle too small for 1/S to be finite in T.
/// * Accuracy (measured by tests/test_rectangle.cpp against mpmath): solid angle within a few
///   ulps times the condition number 1 + (|corner − o| + |edges|)/distance-to-plane, also for
///   rectangles 1e8 sizes away; map points within ~1 ulp·kappa of the mpmath map; inverse round
///   trip at the ulp level of the direction's resolution; Jacobian = S to the finite-difference
///   limit (2e-11 in double).
/// Trivially copyable, no heap: pass it to kernels by value.
template <class T> class SphericalRectangle {
    static_assert(detail::is_real_type<T>(), "apse: SphericalRectangle<T>: T must be float or double");

public:
    using vec2 = glm::vec<2, T>;  ///< a point of the unit square
    using vec3 = glm::vec<3, T>;  ///< a 3-D vector (direction, point or normal)

    /// An empty rectangle (solid angle 0; `sample` returns pdf 0).
    SphericalRectangle() = default;

    /// The rectangle `corner + [0,1]·edge_x + [0,1]·edge_y` seen from `o` (world space, any units).
    /// Set-up cost: about ten square roots and one or two arctangents.
    APSE_FUNC SphericalRectangle(const vec3& o, const vec3& corner, const vec3& edge_x,
                                 const vec3& edge_y) noexcept {
        init(o, corner, corner - o, edge_x, edge_y, false);
    }

    /// The rectangle `center ± half_edge_x ± half_edge_y` seen from `o`. Equivalent to the
    /// corner form, but the local coordinates are computed from `center − o`, so the rectangle
    /// stays exactly centred on `center` even when |center| ≫ |half edges| (what the Gamito
    /// baseline needs).
    APSE_FUNC static SphericalRectangle from_center(const vec3& o, const vec3& center,
                                                    const vec3& half_edge_x,
                                                    const vec3& half_edge_y) noexcept {
        SphericalRectangle r;
        r.init(o, center, center - o, half_edge_x, half_edge_y, true);
        return r;
    }

    /// True if the rectangle subtends no usable solid angle (see the class comment).
    APSE_FUNC bool empty() const noexcept { return !(inv_solid_angle_ > T(0)); }

    /// Solid angle S of the rectangle seen from o, in steradians (0 if empty). Two-sided.
    APSE_FUNC T solid_angle() const noexcept { return solid_angle_; }

    /// Maps u in [0,1]² (clamped; NaN -> 0) to a point of the rectangle, uniformly distributed
    /// in **solid angle** as seen from o: pdf = 1/S. u.x selects the position along `edge_x`,
    /// u.y along `edge_y`; the map is continuous, monotone in each coordinate and sends the
    /// square's edges to the rectangle's edges (u = (0,0) -> corner). Empty: pdf 0, direction
    /// (0,0,1), point o, st (0,0), distance 0.
    APSE_FUNC RectanglePoint<T> sample_point(const vec2& u) const noexcept {
        if (empty()) return none();
        const T u1 = detail::clamp(u.x, T(0), T(1)), u2 = detail::clamp(u.y, T(0), T(1));
        const T t = column(u1);
        // Position along the column x = x0 + t: uniform in h = y / sqrt(q2 + y²).
        const T x = x0_ + t, y1 = y0_ + h_;
        const T q2 = x * x + d_ * d_;
        const T l0 = std::sqrt(q2 + y0_ * y0_), l1 = std::sqrt(q2 + y1 * y1);
        const T h0 = y0_ / l0, h1 = y1 / l1;
        T m0, p0, m1, p1;
        detail::sine_complements(y0_, l0, q2, m0, p0);
        detail::sine_complements(y1, l1, q2, m1, p1);
        const T hv = (T(1) - u2) * h0 + u2 * h1;
        const T cv = std::sqrt(((T(1) - u2) * m0 + u2 * m1) * ((T(1) - u2) * p0 + u2 * p1));
        const T c0 = std::sqrt(m0 * p0);
        const T q = std::sqrt(q2);
        T s;  // offset from the corner's edge along edge_y (scaled units)
        if (!(cv > T(0))) {
            s = hv > T(0) ? h_ : T(0);
        } else if ((h0 >= T(0)) == (hv >= T(0))) {
            // y(hv) − y(h0) = q (hv − h0)(hv + h0) / (cv c0 (hv c0 + h0 cv)), hv − h0 = u2 (h1 − h0)
            const T den = cv * c0 * (hv * c0 + h0 * cv);
            const T dh = u2 * detail::sine_difference(y0_, y1, h_, l0, l1, q2);
            s = den != T(0) ? q * dh * (hv + h0) / den : T(0);
        } else {
            s = hv * q / cv - y0_;  // opposite signs: no cancellation
        }
        s = u2 < T(1) ? detail::clamp(s, T(0), h_) : h_;
        return make_point(t, s, inv_solid_angle_);
    }

    /// `sample_point(u)` reduced to the direction and its solid-angle pdf (1/S; 0 if empty).
    APSE_FUNC DirectionSample<T> sample(const vec2& u) const noexcept {
        const RectanglePoint<T> p = sample_point(u);
        return {p.direction, p.pdf};
    }

    /// Where the ray from o along `direction` (any length, need not be normalised) meets the
    /// rectangle: if it does (st in [0,1]², edges included), the point, its rectangle coordinates
    /// st, the distance and pdf = 1/S; otherwise pdf 0, point o, distance 0 and st the hit point's
    /// rectangle coordinates clamped to [−1, 2]² (only telling on which side the ray passed;
    /// (−1, −1) if the ray never reaches the plane). `direction` is returned normalised
    /// ((0,0,1) for a zero or non-finite input).
    APSE_FUNC RectanglePoint<T> locate(const vec3& direction) const noexcept {
        T t, s;
        const bool plane = hit_plane(direction, t, s);
        if (plane && t >= T(0) && t <= w_ && s >= T(0) && s <= h_)
            return make_point(t, s, inv_solid_angle_);
        RectanglePoint<T> r = none();
        const vec3 dir = detail::robust_normalize(direction);
        if (glm::dot(dir, dir) > T(0)) r.direction = dir;
        r.st = plane ? vec2(detail::clamp(t / w_, T(-1), T(2)), detail::clamp(s / h_, T(-1), T(2))) : vec2(T(-1), T(-1));
        return r;
    }

    /// Solid-angle density of `sample` at `direction`: 1/S if the ray from o hits the rectangle
    /// (edges included), 0 otherwise, for NaN and for an empty rectangle.
    APSE_FUNC T pdf(const vec3& direction) const noexcept {
        T t, s;
        if (!hit_plane(direction, t, s)) return T(0);
        return (t >= T(0) && t <= w_ && s >= T(0) && s <= h_) ? inv_solid_angle_ : T(0);
    }

    /// Inverse of the map: the point of [0,1]² that `sample` sends to `direction`. Directions
    /// whose ray meets the plane outside the rectangle give the square point of the nearest
    /// rectangle point along each edge (coordinates clamped); directions that never reach the
    /// plane, NaN, and an empty rectangle give (0,0).
    APSE_FUNC vec2 invert(const vec3& direction) const noexcept {
        T t, s;
        if (!hit_plane(direction, t, s)) return vec2(T(0), T(0));
        t = detail::clamp(t, T(0), w_);
        s = detail::clamp(s, T(0), h_);
        T lb, lc;
        const T u1 = detail::clamp(strip_solid_angle(t, lb, lc) * inv_solid_angle_, T(0), T(1));
        const T x = x0_ + t, y1 = y0_ + h_, y = y0_ + s;
        const T q2 = x * x + d_ * d_;
        const T l0 = std::sqrt(q2 + y0_ * y0_), l1 = std::sqrt(q2 + y1 * y1);
        const T ly = std::sqrt(q2 + y * y);
        const T num = detail::sine_difference(y0_, y, s, l0, ly, q2);
        const T den = detail::sine_difference(y0_, y1, h_, l0, l1, q2);
        const T u2 = den > T(0) ? detail::clamp(num / den, T(0), T(1)) : T(0);
        return vec2(u1, u2);
    }

    /// World-space corner of the sampled rectangle (st = (0,0)); (0,0,0) if empty.
    APSE_FUNC vec3 corner() const noexcept { return base_; }
    /// World-space edge vector along st.x (= the constructor's edge_x up to rounding); 0 if empty.
    APSE_FUNC vec3 edge_x() const noexcept { return xh_ * (w_ * unscale_); }
    /// World-space edge vector along st.y: edge_y orthogonalised against edge_x; 0 if empty.
    APSE_FUNC vec3 edge_y() const noexcept { return yh_ * (h_ * unscale_); }

private:
    // World frame: xh_, yh_ unit edge directions, zh_ unit normal pointing from the plane towards
    // o. Local coordinates about o, multiplied by 2^k (exact) so the largest is in [1/2, 1):
    // the rectangle is [x0_, x0_ + w_] x [y0_, y0_ + h_] in the plane z = -d_.
    vec3 o_{T(0), T(0), T(0)}, base_{T(0), T(0), T(0)}, delta_{T(0), T(0), T(0)};
    vec3 xh_{T(1), T(0), T(0)}, yh_{T(0), T(1), T(0)}, zh_{T(0), T(0), T(1)};
    T x0_ = T(0), y0_ = T(0), w_ = T(0), h_ = T(0), d_ = T(0);
    T unscale_ = T(0);              // scaled -> world length factor
    T b0_ = T(0), b1_ = T(0), sin_phi0_ = T(0), cos_phi0_ = T(1);  // Urena's closed form (first guess)
    T solid_angle_ = T(0), inv_solid_angle_ = T(0);

    // Shared set-up. `anchor` is the corner (centred == false) or the centre, `rel` = anchor - o,
    // `ex`, `ey` the full edges or the half edges.
    APSE_FUNC void init(const vec3& o, const vec3& anchor, const vec3& rel, const vec3& ex,
                        const vec3& ey, bool centred) noexcept {
        if (detail::finite3(o)) o_ = o;
        const T lx = glm::length(ex);
        const vec3 xh = ex / lx;
        const vec3 eyp = ey - glm::dot(ey, xh) * xh;
        const T ly = glm::length(eyp);
        const vec3 yh = eyp / ly;
        vec3 zh = glm::cross(xh, yh);
        T x0 = glm::dot(rel, xh), y0 = glm::dot(rel, yh), z0 = glm::dot(rel, zh);
        T w = lx, h = ly;
        vec3 base = anchor, delta = rel;
        if (centred) {  // centre form: corner = centre - half edges
            x0 -= lx;
            y0 -= ly;
            w = T(2) * lx;
            h = T(2) * ly;
            base = anchor - ex - eyp;
            delta = rel - ex - eyp;
        }
        if (z0 > T(0)) {
            zh = -zh;
            z0 = -z0;
        }
        const T d = -z0;
        const T big = detail::max_of(detail::max_of(std::fabs(x0) + w, std::fabs(y0) + h), d);
        if (!(w > T(0) && h > T(0) && d > T(0) && detail::is_finite(big) && detail::finite3(o) && detail::finite3(base)))
            return;  // stays empty
        const detail::Pow2Scale<T> scale = detail::pow2_scale_for(big);
        const T unscale = scale.factor != T(0) ? T(1) / scale.factor : std::ldexp(T(1), scale.e);
        x0_ = scale(x0);
        y0_ = scale(y0);
        w_ = scale(w);
        h_ = scale(h);
        d_ = scale(d);
        if (!(w_ > T(0) && h_ > T(0) && d_ > T(0)) || !detail::is_finite(unscale)) return;
        const T y1 = y0_ + h_, d2 = d_ * d_;
        const T S = detail::rectangle_solid_angle(x0_, w_, y0_, h_, d_);
        if (!(S > T(0)) || !detail::is_finite(T(1) / S)) return;
        base_ = base;
        delta_ = delta;
        xh_ = xh;
        yh_ = yh;
        zh_ = zh;
        unscale_ = unscale;
        solid_angle_ = S;
        inv_solid_angle_ = T(1) / S;
        // Urena's closed form in terms of phi = (sum of the two column angles) - pi:
        // phi(c) = asin(b0 c) + asin(b1 c), c = x / sqrt(x² + d²) the column's sine.
        b0_ = -y0_ / std::sqrt(d2 + y0_ * y0_);
        b1_ = y1 / std::sqrt(d2 + y1 * y1);
        // phi0 = phi(c0) at the left edge, kept as (sin, cos) by the addition theorem
        const T c0 = x0_ / std::sqrt(x0_ * x0_ + d2);
        const T k0 = detail::safe_sqrt(T(1) - detail::sqr(b0_ * c0)), k1 = detail::safe_sqrt(T(1) - detail::sqr(b1_ * c0));
        sin_phi0_ = c0 * (b0_ * k1 + b1_ * k0);
        cos_phi0_ = k0 * k1 - b0_ * b1_ * c0 * c0;
    }

    // Solid angle of the left part [x0, x0 + t] x [y0, y1] (scaled units); also writes the
    // lengths |(x0 + t, y0, -d)| and |(x0 + t, y1, -d)| (used by the column density).
    APSE_FUNC T strip_solid_angle(T t, T& lb, T& lc) const noexcept {
        const T x = x0_ + t, y1 = y0_ + h_, d2 = d_ * d_;
        lb = std::sqrt(x * x + y0_ * y0_ + d2);
        lc = std::sqrt(x * x + y1 * y1 + d2);
        return detail::rectangle_solid_angle(x0_, t, y0_, h_, d_);
    }

    // The column t in [0, w] whose left part has solid angle u1 S.
    APSE_FUNC T column(T u1) const noexcept {
        const T target = u1 * solid_angle_;
        if (!(target > T(0))) return T(0);
        if (!(target < solid_angle_)) return w_;
        // First guess: Urena's closed form. phi(c) = phi0 + target solved for c:
        // c = sin(phi) / sqrt(b0² + b1² + 2 b0 b1 cos(phi)), then x = c d / sqrt(1 - c²).
        const T st = std::sin(target), ct = std::cos(target);
        const T sin_phi = sin_phi0_ * ct + cos_phi0_ * st, cos_phi = cos_phi0_ * ct - sin_phi0_ * st;
        const T den2 = b0_ * b0_ + b1_ * b1_ + T(2) * b0_ * b1_ * cos_phi;
        const T c = den2 > T(0) ? detail::clamp(sin_phi / std::sqrt(den2), T(-1), T(1)) : T(0);
        const T guess = c * d_ / detail::safe_sqrt(T(1) - c * c) - x0_;  // inf/NaN: clamped by the solver
        // Polish: bracketed Newton on the cancellation-free left-part solid angle; its derivative
        // is the column's solid-angle density d (h1 - h0) / (x² + d²).
        const T y1 = y0_ + h_;
        auto eval = [this, target, y1](T t, T& value, T& derivative) {
            T lb, lc;
            value = strip_solid_angle(t, lb, lc) - target;
            const T x = x0_ + t, q2 = x * x + d_ * d_;
            derivative = d_ * detail::sine_difference(y0_, y1, h_, lb, lc, q2) / q2;
            // Converged when the Newton step is below one ulp of t: the residual cannot shrink
            // further (steep columns, o close to the plane). Reported as 0 so the solver stops
            // here instead of treating the non-moving step as a failed one.
            if (std::fabs(value) <= derivative * detail::epsilon<T>() * t) value = T(0);
        };
        const T tolerance = T(4) * detail::epsilon<T>() * solid_angle_;
        return detail::find_root_bracketed(eval, T(0), w_, guess, tolerance, 12).x;
    }

    // Ray from o along `direction` against the plane: offsets (t, s) of the hit point from the
    // corner along the edges (scaled units). False if the ray does not reach the plane.
    APSE_FUNC bool hit_plane(const vec3& direction, T& t, T& s) const noexcept {
        t = s = T(0);
        if (empty()) return false;
        const T dz = glm::dot(direction, zh_);
        if (!(dz < T(0))) return false;
        const T lam = d_ / -dz;
        t = lam * glm::dot(direction, xh_) - x0_;
        s = lam * glm::dot(direction, yh_) - y0_;
        return detail::is_finite(t) && detail::is_finite(s);
    }

    // The result for offsets (t, s) from the corner (scaled units).
    APSE_FUNC RectanglePoint<T> make_point(T t, T s, T pdf) const noexcept {
        const T tw = t * unscale_, sw = s * unscale_;
        const vec3 v = delta_ + tw * xh_ + sw * yh_;
        RectanglePoint<T> r;
        r.direction = detail::robust_normalize(v);
        r.distance = glm::dot(v, r.direction);  // |v|, without overflow
        r.point = base_ + tw * xh_ + sw * yh_;
        // No sample (pdf 0) when v = 0 after rounding (a point next to o on a rectangle ~1e16
        // (double) or ~1e7 (float) times larger than o's distance to it, where v cancels) or when
        // the point or its distance is beyond the type's range (coordinates near its maximum)
        const bool usable = r.distance > T(0) && detail::is_finite(r.distance) && detail::finite3(r.point);
        if (!(r.distance > T(0))) r.direction = vec3(T(0), T(0), T(1));
        r.pdf = usable ? pdf : T(0);
        r.st = vec2(t / w_, s / h_);
        return r;
    }

    APSE_FUNC RectanglePoint<T> none() const noexcept {
        RectanglePoint<T> r;
        r.direction = vec3(T(0), T(0), T(1));
        r.pdf = T(0);
        r.point = o_;
        r.st = vec2(T(0), T(0));
        r.distance = T(0);
        return r;
    }
};

}  // namespace apse
