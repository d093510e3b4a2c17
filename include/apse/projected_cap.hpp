// apse — area-preserving parameterizations for spherical ellipses.
// SPDX-License-Identifier: MIT
#pragma once

/// @file projected_cap.hpp
/// `ProjectedCapSampler<T>`: directions on a spherical cap drawn with density exactly
/// max(0, n·ω) / Omega_perp (Omega_perp the cap's projected solid angle, in closed form) for a
/// receiver with normal n; no sample falls below the receiver's horizon (docs/math.md §14).
///
/// Receiver frame: Z = n, X the unit tangent towards the cap's centre c = (sin g, 0, cos g)
/// (g the angle between n and c), Y = Z × X. The orthographic projection onto the tangent plane
/// turns density in area into density cos theta / area in solid angle (Nusselt), so a uniform
/// point of the cap's projection, lifted to the sphere, has the density wanted. The cap of
/// angular radius a projects to the ellipse centred at (x0, 0), x0 = cos a sin g, with signed
/// semi-axis a' = sin a cos g along X and b = sin a along Y.
/// * Above the horizon (g + a <= pi/2): the filled ellipse, area pi sin^2 a cos g; u goes
///   through the concentric map to the unit disk, scaled by (a', b) and lifted — closed form,
///   no iteration.
/// * Cut by the horizon: at each y the visible part is one interval [x_lo(y), x_hi(y)];
///   u1 → y by inverting the closed-form cumulative area in y (the substitution y = b sin theta,
///   bracketed Halley steps with a relative stopping rule and an iteration cap), then
///   x = x_lo + u2 (x_hi − x_lo). Continuous and area-preserving in u: stratified points stay
///   stratified.
/// Directions are assembled in the cap's own frame from differences computed without
/// cancellation, so that small caps keep their digits (samples stay inside the cap).

#include <cmath>

#include "config.hpp"
#include "detail/math.hpp"
#include "projected_solid_angle.hpp"
#include "sample.hpp"
#include "spherical_ellipse.hpp"
#include "detail/polar.hpp"
#include "detail/glm.hpp"
#include "detail/vector.hpp"

namespace apse {
namespace detail {

/// asin(y) − y for y in [0, 1] given w = sqrt(1 − y^2), without cancellation: y^3 times the
/// Maclaurin series of (asin y − y)/y^3 in z = y^2 below y = 1/4 (13 terms in double, 6 in float:
/// the first left out is below 2e-17, resp. 1e-8, relative), evaluated by Estrin's scheme (depth
/// 4 instead of 12: it sits on the cut-cap sampler's critical path; the powers of z formed from
/// max(z, 2^-120), resp. 2^-30, so that none is subnormal, which moves the sum by less than
/// 2^-120 relative), the difference above (at least y^3/6 there: it loses at most a factor 6 of
/// the arcsine's error) with the library's asin (`Precise`, to half an ulp) or atan2(y, w) by
/// polynomials (angle_of, to a few ulps: the sampling path).
template <bool Precise, class T> APSE_FUNC T asin_minus_identity(T y, T w) noexcept {
    if (y < T(0.25)) {
        const T z = y * y;
        const T zc = max_of(z, sizeof(T) == sizeof(float) ? T(0x1p-30) : T(0x1p-120));
        const T z2 = zc * zc, z4 = z2 * z2;
        const T a = (T(1.0 / 6.0) + z * T(3.0 / 40.0)) + z2 * (T(5.0 / 112.0) + z * T(35.0 / 1152.0));
        T p;
        if constexpr (sizeof(T) == sizeof(float)) {
            p = a + z4 * (T(63.0 / 2816.0) + z * T(231.0 / 13312.0));
        } else {
            const T b = (T(63.0 / 2816.0) + z * T(231.0 / 13312.0)) + z2 * (T(143.0 / 10240.0) + z * T(6435.0 / 557056.0));
            const T c = (T(12155.0 / 1245184.0) + z * T(46189.0 / 5505024.0)) + z2 * (T(88179.0 / 12058624.0) + z * T(676039.0 / 104857600.0));
            p = a + z4 * (b + z4 * (c + z4 * T(1300075.0 / 226492416.0)));
        }
        return y * z * p;
    }
    if constexpr (Precise) return std::asin(min_of(y, T(1))) - y;
    else return angle_of(y, w) - y;
}


/// Exact projected-solid-angle (cosine-weighted) sampling of a spherical cap for a receiver with
/// normal n (file comment; docs/math.md §14): density max(0, n·ω) / Omega_perp in solid angle,
/// exactly, for caps above the horizon, cut by it (centre above or below it) — no sample below
/// the horizon — and empty for caps entirely below it. The input square is mapped continuously
/// and area-preservingly (stratified and QMC points stay stratified). Set-up: two cross products, two square roots
/// and two divisions above the horizon; a few more square roots, an atan2 by polynomials and
/// one asin when the horizon cuts the cap.
/// Per sample: closed form above the horizon (the concentric map, two square roots); when cut,
/// a first guess from two Newton steps on a polynomial model of the area (its values and slopes
/// at both ends), then bracketed Halley steps (polynomial sine and cosine, one square root and
/// two divisions each; 2.1 evaluations per sample on average in double, 1.3 in float, measured
/// over random cut caps), stopped relative to the area inverted (never a fixed absolute
/// tolerance) with a hard cap of 40 steps. Measured cost against pbrt's cone sampling: docs/speed.md,
/// sphere lights (SphereLight<CosineWeighted<map>> builds this sampler alone); when cut, most of it
/// is the area's evaluations. The samples are continuous in u within each case; where the horizon starts
/// to cut the cap the map changes from the disk's to the strips' (Omega_perp and the density
/// are continuous there, the map of u is not). Every finite normal, however large or small its
/// components (subnormal, or cos g or sin g 0 or subnormal), gives finite unit directions and a
/// pdf that is 0 or the density. Trivially copyable; no allocation.
template <class T> class ProjectedCapSampler {
    static_assert(detail::is_real_type<T>(), "apse: ProjectedCapSampler<T>: T must be float or double");

public:
    using vec2 = glm::vec<2, T>;  ///< a point of the unit square
    using vec3 = glm::vec<3, T>;  ///< a 3-D vector (direction or normal)

    /// The empty sampler (every pdf 0).
    APSE_FUNC ProjectedCapSampler() noexcept {}

    /// The sampler of the cap `cap` for a receiver with world-space normal `receiver_normal` (any
    /// non-zero finite length; the receiver's side is the one it points to). Empty (every pdf 0)
    /// if `cap` is not a cap (`is_cap()` false: empty or a non-circular ellipse), for a zero, NaN
    /// or infinite normal, for a cap entirely below the horizon (cos(g − a) <= 0, g the angle
    /// from the normal to the centre, a the cap's angular radius), and for a projected solid
    /// angle so small (at most 2 / the largest T: a cap below ~1e-154 rad in double, ~1e-19 rad
    /// in float) that its reciprocal, the density's scale, overflows or comes within a factor 2
    /// of it. (That margin makes the cap's plain density 1/Omega finite too whenever this sampler
    /// is not empty, Omega >= Omega_perp: CapCosine relies on it.)
    APSE_HOT_INLINE ProjectedCapSampler(const SphericalEllipse<T>& cap, const vec3& receiver_normal) noexcept {
        if (cap.is_cap()) init(cap.z, cap.tan_alpha, cap.sin_alpha, cap.cos_alpha, cap.one_minus_cos_alpha, receiver_normal);
    }

    /// The same for the cap a sphere subtends (detail::sphere_cap: project_sphere without its
    /// frame, which this sampler does not read): the samples, pdf and invert of the sampler built
    /// from project_sphere's result, bit for bit.
    APSE_HOT_INLINE ProjectedCapSampler(const SphereCap<T>& cap, const vec3& receiver_normal) noexcept {
        if (!cap.empty()) init(cap.z, cap.tan_alpha, cap.sin_alpha, cap.cos_alpha, cap.one_minus_cos_alpha, receiver_normal);
    }

private:
    /// The set-up for the cap (centre c, tan, sin, cos and 1 − cos of its angular radius a)
    /// and the receiver normal (the constructors' contract). The receiver frame: g from
    /// n·c, e1 from n's part across c, e2 = c × e1. Out of line, as init_cut() and sample_cut():
    /// every caller runs the same code, so that the light built from a sphere and the sampler
    /// built from its cap agree under FMA contraction too.
    APSE_NOINLINE APSE_FUNC void init(const vec3& c, T ta, T sa, T ca, T omca, const vec3& receiver_normal) noexcept {
        const T scale = detail::max_abs3(receiver_normal);
        if (!(scale > T(0)) || !detail::is_finite(scale) || !detail::finite3(receiver_normal)) return;
        // |n| from n itself where neither its square nor the products below overflow or lose
        // digits to underflow; otherwise n divided by its largest component first (a division:
        // its reciprocal may be subnormal)
        const vec3 v = scale >= T(1) / normal_range() && scale <= normal_range() ? receiver_normal : receiver_normal / scale;
        const T vz = glm::dot(v, c);
        // v's part across c as (c × v) × c = v − (v·c) c: orthogonal to c to rounding relative to
        // the length of c × v (v − (v·c) c computed directly keeps ~eps |v| along c). Within
        // ~0.06 degrees of ±c (|across| below 2^-10 |v|) c × v is mostly the rounding of its
        // products, which may lie along c (it does under FMA contraction, where no second pass
        // of Gram–Schmidt can remove it): there the part across c comes from v's coordinates in
        // a basis around c instead, orthogonal to c by construction
        const vec3 cv = glm::cross(c, v);
        vec3 across = glm::cross(cv, c);
        T aa = glm::dot(across, across);
        if (aa < T(0x1p-20) * glm::dot(v, v)) {
            vec3 bx, by;
            detail::basis_around(c, bx, by);
            across = glm::dot(v, bx) * bx + glm::dot(v, by) * by;
            aa = glm::dot(across, across);
        }
        // |v| from its two parts, so that sin^2 g + cos^2 g = 1 to rounding (the sliver of a cap
        // whose centre is just below the horizon depends on both)
        const T len = std::sqrt(aa + vz * vz), sl = std::sqrt(aa);
        // sin g and e1 (the unit tangent at the centre pointing away from n, any one when n ∥ c;
        // e2 = c × e1): 1/|n| and 1/|n across c| from one division where the squares keep their
        // digits, from n's part across c divided by its largest component where they would be
        // subnormal (e1 stays unit)
        T inv_len, sg;
        vec3 e1, e2;
        if (sl >= tiny_square_root()) {
            const T r = T(1) / (len * sl);
            inv_len = sl * r;
            sg = sl * inv_len;
            e1 = across * (-(len * r));
        } else {
            inv_len = T(1) / len;
            sg = T(0);
            const T big = detail::max_abs3(across);
            if (big > T(0)) {
                const vec3 q = across / big;
                const T lq = std::sqrt(glm::dot(q, q));
                sg = big * lq * inv_len;
                e1 = q / (-lq);
            } else {
                detail::basis_around(c, e1, e2);
            }
        }
        e2 = glm::cross(c, e1);
        const T cg = vz * inv_len;
        const vec3 n = v * inv_len;
        const T cos_sum = cg * ca - sg * sa;   // cos(g + a): the rim's lowest point's height
        const T cos_diff = cg * ca + sg * sa;  // cos(g − a): its highest point's height
        if (!(cos_diff > T(0))) return;        // entirely below the horizon
        c_ = c;
        e1_ = e1;
        e2_ = e2;
        ta_ = ta;
        n_ = n;
        sg_ = sg;
        cg_ = cg;
        sa_ = sa;
        ca_ = ca;
        omca_ = omca;
        x0_ = ca * sg;
        ap_ = sa * cg;
        if (cos_sum >= T(0)) {  // above the horizon: the filled ellipse
            cut_ = false;
            area_ = detail::pi_v<T> * sa * sa * cg;
            half_ = T(0.5) * area_;
        } else {
            init_cut(sa, ca, sg, cg, cos_sum, cos_diff);
        }
        if (!(area_ > T(0)) || !detail::is_finite(area_)) return;
        inv_area_ = T(1) / area_;
        if (!(inv_area_ < density_limit())) return;  // too small an Omega_perp (constructor comment)
        empty_ = false;
    }

    /// The set-up where the horizon cuts the cap (init; the members up to omca_, x0_ and ap_ set):
    /// the areas of the visible region's two pieces and the first guess's slopes. Out of line, so
    /// that every caller runs the same code: the root finding of sample_cut() amplifies the
    /// last bits of these areas, which a compiler contracting a*b + c into FMAs could otherwise
    /// round differently where it inlines them into different callers.
    APSE_NOINLINE APSE_FUNC void init_cut(T sa, T ca, T sg, T cg, T cos_sum, T cos_diff) noexcept {
        cut_ = true;
        if (cg >= T(0)) {  // 1 − x0 = (1 − cos a) + cos a (1 − sin g), 1 − sin g = cos^2 g / (1 + sin g)
            one_minus_x0_ = omca_ + ca * (cg * cg / (T(1) + sg));
        } else {  // 1 − sin(g − a) = cos^2(g − a)/(1 + sin(g − a)): the visible width at y = 0
            d0_ = cos_diff * cos_diff / (T(1) + (sg * ca - cg * sa));
        }
        // the rim meets the horizon at y_t = sin a sin theta_t, with
        // sin theta_t = sqrt(−cos(g + a) cos(g − a)) / (sin a sin g), cos theta_t = |cos a cos g| / (sin a sin g)
        // (st^2 + ct^2 = (sin a sin g)^2: one reciprocal; sin a sin g > |cos a cos g| >= 0 when cut)
        const T st = std::sqrt(-cos_sum * cos_diff), ct = std::fabs(ca * cg);
        const T inv_len = T(1) / (sa * sg);
        st_ = detail::min_of(st * inv_len, T(1));
        ct_ = detail::min_of(ct * inv_len, T(1));
        theta_t_ = detail::angle_of(st_, ct_);
        const T wt = rim_w(ct_);  // sqrt(1 − y_t^2)
        inner_ = inner_area<true>(theta_t_, st_, ct_, wt, T(1) / (T(1) + wt));
        // beyond theta_t (centre above the horizon only): the ellipse's own band,
        // a' b (x − sin x cos x) from its top, x = pi/2 − theta
        outer_ = cg > T(0) ? ap_ * sa * detail::angle_minus_sin_cos(detail::half_pi_v<T> - theta_t_, ct_, st_, T(1)) : T(0);
        half_ = inner_ + outer_;
        area_ = T(2) * half_;
        // the slopes of H/inner in theta/theta_t at 0 and at theta_t (the first guess's model):
        // H'(0) = L(0) b, L(0) = 1 − x0 + a'; H'(theta_t) = 2 a' cos theta_t b cos theta_t
        // 1/inner, 0 where it is not finite (an empty or subnormal inner piece: the guess is then 0)
        const T ri = inner_ > T(0) ? T(1) / inner_ : T(0);
        inv_inner_ = detail::is_finite(ri) ? ri : T(0);
        const T k = sa * theta_t_ * inv_inner_;
        m0_ = (cg >= T(0) ? one_minus_x0_ + ap_ : d0_) * k;
        m1_ = cg > T(0) ? T(2) * ap_ * ct_ * ct_ * k : T(0);
    }

public:
    /// True if the sampler cannot sample (not a cap, zero/NaN normal, cap below the horizon):
    /// every sample and pdf is then 0.
    APSE_FUNC bool empty() const noexcept { return empty_; }

    /// The cap sampled, with the frame project_sphere gives it (detail::basis_around its centre):
    /// the same cap, whichever orthonormal (x, y) the cap given had. The empty ellipse for an
    /// empty sampler.
    APSE_FUNC SphericalEllipse<T> ellipse() const noexcept {
        if (empty_) return SphericalEllipse<T>::make_empty();
        return detail::SphereCap<T>{c_, ta_, sa_, ca_, omca_, T(0)}.ellipse();
    }

    /// True if the receiver's horizon cuts the cap (the sampler then inverts a cumulative area).
    APSE_FUNC bool cut() const noexcept { return cut_; }

    /// The cap's projected solid angle Omega_perp = ∫ max(0, n·ω) dω over the cap (steradians;
    /// 0 for empty()): pi sin^2 a cos g above the horizon, the closed form of docs/math.md §14
    /// when cut. Relative accuracy a few eps of T above the horizon and when the cap's centre is
    /// above it; with the centre below the horizon the closed form's terms cancel as the visible
    /// sliver vanishes (docs/math.md §14 has the measured accuracy).
    APSE_FUNC T projected_solid_angle() const noexcept { return empty_ ? T(0) : area_; }

    /// Direction for the point u of the unit square (clamped into [0, 1]^2): a world-space unit
    /// vector inside the cap and above the receiver's horizon, with its density
    /// max(0, n·ω) / Omega_perp in solid angle. NaN u or empty(): pdf 0 and the cap's centre.
    /// u2 = 1 where the visible range ends at the horizon: that horizon direction, pdf 0; a
    /// direction that rounding puts on or below the horizon: pdf 0 (declined). A direction that
    /// rounding puts outside the cap (by the few ulps of its components: up to ~1e-3 of a 1e-8 sr
    /// cap's radius in float) is moved towards the centre by as much, so that pdf() of every
    /// direction returned with pdf > 0 is that pdf to rounding (declined if that fails, e.g. for
    /// a cap narrower than the rounding of a direction).
    APSE_HOT_INLINE DirectionSample<T> sample(const vec2& u) const noexcept {
        bool ok = !empty_;
        const vec2 uc = detail::clamp_unit(u, ok);
        if (!ok) return {c_, T(0)};
        if (!cut_) {
            const Above a = sample_above(uc);
            return inside(a.w, a.pd, a.sure);
        }
        return sample_cut(uc);
    }

    /// sample(u) placed on a sphere by `target` (SphereLight's detail::SphereTarget): above the
    /// horizon, where the sample is surely inside the cap, from its polar angle in closed form
    /// (cos theta = s and cos theta − cos a = t cos g, a product: no cancellation at the rim);
    /// otherwise from the direction.
    template <class Target>
    APSE_HOT_INLINE PointSample<T> sample_on_sphere(const vec2& u, const Target& target) const noexcept {
        bool ok = !empty_;
        const vec2 uc = detail::clamp_unit(u, ok);
        if (ok && !cut_) {
            const Above a = sample_above(uc);
            if (a.sure) return target.place_polar({{a.w, a.pd}, a.cos_theta, a.rim_gap}, ca_);
            return target.place_by_ray(inside(a.w, a.pd, false));
        }
        return target.place_by_ray(ok ? sample_cut(uc) : DirectionSample<T>{c_, T(0)});
    }

    /// Density of sample() at the world-space direction `d` (any non-zero length), in solid
    /// angle: max(0, n·ω) / Omega_perp inside the cap (the test of SphericalEllipse::contains,
    /// in this sampler's frame), 0 outside,
    /// below the horizon, for empty() or a zero/NaN direction.
    APSE_FUNC T pdf(const vec3& d) const noexcept {
        if (empty_) return T(0);
        bool ok = true;
        const vec3 l = detail::normalize_direction(d, ok);
        if (!ok || !in_cap(l)) return T(0);
        const T c = glm::dot(n_, l);
        return c > T(0) ? c * inv_area_ : T(0);
    }

    /// The point of the unit square whose sample has direction `d` (any non-zero length): the
    /// inverse of sample(). Directions outside the cap or below the horizon: the same formulas,
    /// clamped into [0, 1]^2. Zero/NaN direction or empty(): (0, 0).
    APSE_FUNC vec2 invert(const vec3& d) const noexcept {
        if (empty_) return vec2(T(0));
        bool ok = true;
        const vec3 l = detail::normalize_direction(d, ok);
        if (!ok) return vec2(T(0));
        const T p = glm::dot(l, e1_), q = glm::dot(l, e2_), s = glm::dot(l, c_);
        // s − cos a = (1 − cos a) − (1 − s), 1 − s = (p^2 + q^2)/(1 + s)
        const T s_minus_ca = omca_ - (p * p + q * q) / (T(1) + detail::max_of(s, T(0)));
        if (!cut_) {
            // back along n to the flat disk: t = (s − cos a)/cos g, disk point ((p + t sin g), q)/sin a
            const T t = cg_ > T(0) ? s_minus_ca / cg_ : T(0);
            const T dx = (p + t * sg_) / sa_, dy = q / sa_;
            const T r = detail::hypot2(dx, dy);
            const T turns = r > T(0) ? std::atan2(dy, dx) * T(0.15915494309189533577) : T(0);
            return detail::concentric_from_disk(detail::min_of(r, T(1)), turns);
        }
        const T sth = detail::min_of(std::fabs(q) / sa_, T(1));
        const T cth = std::sqrt((T(1) - sth) * (T(1) + sth));
        const T th = std::atan2(sth, cth);
        T below, width;  // the area from y = 0 to |y|, the width at y
        // x − x_lo = cos g (p + sin a cos theta) + sin g (s − cos a)
        const T dxl = cg_ * (p + sa_ * cth) + sg_ * s_minus_ca;
        if (th > theta_t_ && outer_ > T(0)) {
            below = half_ - ap_ * sa_ * detail::angle_minus_sin_cos(detail::half_pi_v<T> - th, cth, sth, T(1));
            width = T(2) * ap_ * cth;
        } else {
            const T w = rim_w(cth);
            below = inner_area<false>(detail::min_of(th, theta_t_), sth, cth, w, T(1) / (T(1) + w));
            width = inner_width(cth, w);
        }
        const T u1 = T(0.5) + (q < T(0) ? T(-0.5) : T(0.5)) * (below / half_);
        const T u2 = width > T(0) ? dxl / width : T(0);
        return vec2(detail::clamp(u1, T(0), T(1)), detail::clamp(u2, T(0), T(1)));
    }

private:
    /// A sample above the horizon before inside(): the direction, its density, whether it is
    /// surely inside the cap (surely_inside), cos theta (theta its angle from the cap's centre)
    /// and cos theta − cos a.
    struct Above {
        vec3 w;
        T pd;
        bool sure;
        T cos_theta, rim_gap;
    };

    /// sample() above the horizon (uc clamped, the sampler not empty, not cut): the concentric
    /// map's disk point (dx, dy), its flat-disk point Q = cos a c + sin a (dx e1 + dy e2), lifted
    /// along n: w = Q + t n, t = sin^2 a (1 − r^2) / (Q_z + sqrt(Q_z^2 + sin^2 a (1 − r^2))).
    APSE_HOT_INLINE Above sample_above(const vec2& uc) const noexcept {
        // the concentric map folded into its quadrant (branch-free: the octant is a max, not a
        // test), the angle's sine and cosine in the quadrant by polynomials
        const detail::ConcentricFold<T> d = detail::concentric_fold(uc);
        const detail::SinCosValues<T> v = detail::sin_cos_quarter_turn(d.fold.fraction);
        const T r = d.radius;
        const T dx = d.fold.sign_x * (r * v.c), dy = d.fold.sign_y * (r * v.s);
        const T rest = sa_ * sa_ * ((T(1) - r) * (T(1) + r));
        const T qz = detail::max_of(ca_ * cg_ - sa_ * sg_ * dx, T(0));
        const T den = qz + std::sqrt(qz * qz + rest);
        const T t = den > T(0) ? rest / den : T(0);
        const T z = qz + t;
        const T p = sa_ * dx - t * sg_, q = sa_ * dy, s = ca_ + t * cg_;
        return {p * e1_ + q * e2_ + s * c_, z > T(0) ? z * inv_area_ : T(0), surely_inside(p, q, s, z), s, t * cg_};
    }

    /// sample() where the horizon cuts the cap (uc clamped, the sampler not empty): u1 → y by
    /// inverting the visible region's cumulative area, then x = x_lo + u2 L (file comment). Out
    /// of line from sample(): its root finding would otherwise be compiled into every caller.
    APSE_NOINLINE APSE_FUNC DirectionSample<T> sample_cut(const vec2& uc) const noexcept {
        const T v = T(2) * uc.x - T(1);
        const T side = v < T(0) ? T(-1) : T(1);
        const T f = std::fabs(v);
        const T rest = (T(1) - f) * half_;  // the area beyond y, towards the top
        T s_th, c_th, yy, w, width, gap, xlo, h;  // w = sqrt(1 − y^2), y = sin a sin theta
        if (rest < outer_) {
            // the ellipse's band: a' b E(x) = rest, x = pi/2 − theta, E(x) = x − sin x cos x
            const T target = rest / (ap_ * sa_);
            const T xmax = detail::half_pi_v<T> - theta_t_;
            const T guess = detail::min_of(cbrt_guess(T(1.5) * target), xmax);
            T sx = T(0), cx = T(1);
            auto eval = [&](T x, T& value, T& derivative) {
                const detail::SinCosValues<T> sc = detail::sin_cos_of_nonnegative_angle(x);
                sx = sc.s;
                cx = sc.c;
                value = detail::angle_minus_sin_cos(x, sx, cx, T(1)) - target;
                const T f1 = T(2) * sx * sx, f2 = T(4) * sx * cx;
                derivative = f1 > T(0) ? f1 - value * f2 / (T(2) * f1) : f1;
            };
            detail::find_root_bracketed(eval, T(0), xmax, guess, tolerance() * target, 40);
            s_th = cx;
            c_th = sx;
            width = T(2) * ap_ * c_th;
            xlo = x0_ - ap_ * c_th;
            const T hr = detail::max_of(ca_ * cg_ - sa_ * sg_ * c_th, T(0));  // the right rim point's height
            yy = rim_y(s_th);
            w = rim_w(c_th);
            gap = hr * hr / (w + x0_ + ap_ * c_th);
            h = ca_ * cg_ + sa_ * sg_ * c_th;
        } else {
            const T target = f * half_;
            const T guess = first_guess(detail::min_of(target * inv_inner_, T(1))) * theta_t_;
            solve_inner(target, guess, s_th, c_th);
            yy = rim_y(s_th);
            w = rim_w(c_th);
            width = inner_width(c_th, w);
            xlo = x0_ - ap_ * c_th;
            gap = T(0);
            h = ca_ * cg_ + sa_ * sg_ * c_th;
        }
        // x = x_lo + u2 L; the height z from w^2 − x^2 = (w − x)(w + x), w − x = gap + (1 − u2) L
        const T du = uc.y * width;
        const T x = xlo + du;
        const T z = std::sqrt(detail::max_of((gap + (T(1) - uc.y) * width) * (w + x), T(0)));
        h = detail::max_of(h, T(0));
        // the cap frame's components, from the rim point (x_lo, y, h) = −sin a cos theta e1 + y e2 + cos a c:
        // p − p_rim = cos g du − sin g (z − h), z − h = −du (x + x_lo)/(z + h)
        // (|z − h| <= z + h bounds the quotient: z + h may be subnormal, e.g. for cos g subnormal
        // at the top of the region, where du vanishes with it)
        const T zh = z + h;
        const T zmh = zh > T(0) ? detail::clamp(du * (x + xlo) / zh, -zh, zh) : T(0);
        const T p = -sa_ * c_th + du * cg_ + sg_ * zmh;
        const T q = side * yy;
        const T s = sg_ * x + cg_ * z;
        const vec3 dir = p * e1_ + q * e2_ + s * c_;
        const T pd = z * inv_area_;
        const T height = glm::dot(n_, dir);
        return inside(dir, pd > T(0) && height > T(0) ? pd : T(0), surely_inside(p, q, s, height));
    }

    /// True if the unit direction l lies in the cap (boundary included): SphericalEllipse::contains
    /// in the frame (e1, e2, c), l·c > 0 and (l·e1, l·e2)/(l·c) within tan a (an overflowing ratio
    /// means outside).
    APSE_FUNC bool in_cap(const vec3& l) const noexcept {
        return detail::inside_cone(glm::dot(l, e1_), glm::dot(l, e2_), glm::dot(l, c_), ta_, ta_);
    }

    /// True if pdf() certainly finds the direction w = p e1 + q e2 + s c (|w| = 1 to rounding, as
    /// sample() assembles it) inside the cap and above the horizon, w's height over it being
    /// `height` (n·w to rounding): the gnomonic radius |(p, q)| / s at most tan a by a margin
    /// larger than the rounding of w, of pdf()'s normalisation and of the cap's own cone test (each
    /// component of w and of its local coordinates within ~20 eps of T absolute, the test's ratio
    /// within a few eps relative: 64 eps absolute and 8 eps relative cover them), and the height
    /// above 32 eps. Saves sample() the pdf() check of inside() for all but the samples within
    /// that margin of the rim or the horizon.
    APSE_HOT_INLINE bool surely_inside(T p, T q, T s, T height) const noexcept {
        const T ta = ta_;
        const T lim = s * ta * (T(1) - T(8) * detail::epsilon<T>()) - T(64) * detail::epsilon<T>() * (T(1) + ta);
        return height > T(32) * detail::epsilon<T>() && lim > T(0) && p * p + q * q <= lim * lim;
    }

    /// The stopping rule of the inversions, relative to the area of the piece inverted: 16 eps of
    /// T, above the rounding of the area evaluated per step (a few eps; a tighter rule would only
    /// make the last steps chase rounding).
    static APSE_FUNC constexpr T tolerance() noexcept { return T(16) * detail::epsilon<T>(); }

    /// The sample (w, density pd) as sample() returns it: w as it is when pdf() places it inside
    /// the cap (or pd is 0); otherwise moved towards the centre along the great circle in steps of
    /// 4, 8, 16, 32 eps of T in angle (the rounding of w and of pdf()'s own test) until pdf() does, the
    /// density then pdf()'s; still outside: pdf 0 (declined).
    APSE_HOT_INLINE DirectionSample<T> inside(vec3 w, T pd, bool sure) const noexcept {
        if (sure || !(pd > T(0))) return {w, pd};
        return moved_inside(w, pd);
    }

    /// inside() for a sample not surely inside: pdf() decides.
    APSE_FUNC DirectionSample<T> moved_inside(vec3 w, T pd) const noexcept {
        if (pdf(w) > T(0)) return {w, pd};
        // w + k c turns w at the rim towards c by about k sin a: k = 4 eps / sin a for 4 eps
        T k = detail::min_of(T(4) * detail::epsilon<T>() / sa_, T(1));
        for (int i = 0; i < 4; ++i, k = detail::min_of(T(2) * k, T(1))) {
            const vec3 v = w + k * c_;
            w = v / std::sqrt(glm::dot(v, v));
            const T p = pdf(w);
            if (p > T(0)) return {w, p};
        }
        return {w, T(0)};
    }

    /// Half the largest finite T: the densities' scale 1/Omega_perp stays below it (constructor).
    static APSE_FUNC constexpr T density_limit() noexcept {
        return sizeof(T) == sizeof(float) ? T(0x1.fffffep126f) : T(0x1.fffffffffffffp1022);
    }

    /// A magnitude whose square is far enough above the subnormals (2^-960 in double, 2^-100 in
    /// float) that a sum of squares of numbers up to it loses nothing to their underflow.
    static APSE_FUNC constexpr T tiny_square_root() noexcept { return sizeof(T) == sizeof(float) ? T(0x1p-50) : T(0x1p-480); }

    /// The range [1/this, this] of a normal's largest component used as it is (2^240 in double,
    /// 2^25 in float): its length and the products of the set-up stay far from overflow and
    /// from the subnormals.
    static APSE_FUNC constexpr T normal_range() noexcept { return sizeof(T) == sizeof(float) ? T(0x1p25) : T(0x1p240); }

    /// y = sin a sin theta for the polynomial sine `sth` of theta, at most 1: near theta = pi/2
    /// that sine may exceed 1 by an ulp, and sin a rounds to 1 for a nearly hemispherical cap, so
    /// that 1 − y^2 (the square of the width's bound w) would be negative.
    APSE_FUNC T rim_y(T sth) const noexcept { return detail::min_of(sa_ * sth, T(1)); }

    /// w = sqrt(1 − y^2) at y = sin a sin theta, from cos theta `cth`, as the sum of squares
    /// sqrt(cos^2 a + sin^2 a cos^2 theta): no cancellation where 1 − y would lose its digits (sin a
    /// and sin theta both near 1: a nearly hemispherical cap near its top, where w is small and
    /// the samples' heights sqrt(w^2 − x^2) depend on it). At least cos a (to rounding).
    APSE_FUNC T rim_w(T cth) const noexcept {
        const T sc = sa_ * cth;
        return std::sqrt(ca_ * ca_ + sc * sc);
    }

    /// The Halley step (relative to the distance from theta to theta_t, where the region's width
    /// may vanish and with it H') below which the step is the last one, taken without evaluating
    /// its result: Halley's next error is then about the cube of this times that distance,
    /// 2^-54 in double (2^-18 here) and 2^-24 in float (2^-8), below eps/4.
    static APSE_FUNC constexpr T predicted_stop() noexcept { return sizeof(T) == sizeof(float) ? T(0x1p-8) : T(0x1p-18); }

    /// Solves H(theta) = target for theta in [0, theta_t] (sin and cos of the root in sth, cth)
    /// by bracketed Halley steps from `guess` (H' = L b cos theta, H'' from the width's slope):
    /// stops when |H − target| <= tolerance() of the piece, after a step below predicted_stop()
    /// of the distance to theta_t, when the bracket collapses to a few ulps, or after 40 steps; a step
    /// leaving the bracket is replaced by bisection, so the root stays in it.
    APSE_FUNC void solve_inner(T target, T guess, T& sth, T& cth) const noexcept {
        T lo = T(0), hi = theta_t_, th = detail::clamp(guess, lo, hi);
        const T tol = tolerance() * inner_;
        const detail::SinCosValues<T> sc0 = detail::sin_cos_of_nonnegative_angle(th);
        sth = sc0.s;
        cth = sc0.c;
        for (int it = 0;; ++it) {
            const T yy = rim_y(sth), w = rim_w(cth);
            // 1/w, 1/(1 + w) and 1/(w + x_lo) from one division (w >= cos a: no underflow)
            const T xlo = x0_ - ap_ * cth, h = ca_ * cg_ + sa_ * sg_ * cth;
            const bool by_height = xlo > T(0);  // the width as h^2/(w + x_lo) (inner_width)
            const T wx = by_height ? w + xlo : T(1), w1 = T(1) + w;
            const T r = T(1) / (w * w1 * wx);
            const T g = inner_area<false>(th, sth, cth, w, w * wx * r) - target;
            if (!(std::fabs(g) > tol)) break;
            if (g < T(0)) lo = th; else hi = th;
            if (it >= 40 || !(hi - lo > T(4) * detail::epsilon<T>() * hi)) break;
            const T lw = by_height ? h * h * (w * w1 * r) : w - xlo;
            const T f1 = lw * sa_ * cth;
            const T dl = -yy * sa_ * cth * (w1 * wx * r) - ap_ * sth;
            const T f2 = dl * sa_ * cth - lw * sa_ * sth;
            // Halley's step g/(f1 − g f2/(2 f1)) = 2 g f1/(2 f1^2 − g f2), one division (a step out
            // of the bracket, e.g. from a negative denominator, becomes a bisection below)
            const bool positive = f1 > T(0);
            T next = th - (positive ? T(2) * g * f1 : g) / (positive ? T(2) * f1 * f1 - g * f2 : f1);
            const bool inside = next > lo && next < hi;
            if (!inside) next = T(0.5) * (lo + hi);
            if (next == th) break;
            const T step = next - th;
            const bool last = inside && std::fabs(step) <= predicted_stop() * (theta_t_ - th);
            th = next;
            if (last) {
                // the last step: the sine and cosine turned by it, sin d = d − d^3/6 and
                // cos d = 1 − d^2/2 (|d| <= 2^-18 pi/2 in double, 2^-8 pi/2 in float: the next
                // terms are below eps/4), instead of the polynomials again
                const T d2 = step * step, sd = step - step * d2 * T(1.0 / 6.0), cd = T(1) - T(0.5) * d2;
                const T s1 = sth * cd + cth * sd, c1 = cth * cd - sth * sd;
                sth = detail::min_of(s1, T(1));
                cth = detail::max_of(c1, T(0));
                break;
            }
            const detail::SinCosValues<T> sc = detail::sin_cos_of_nonnegative_angle(th);
            sth = sc.s;
            cth = sc.c;
        }
    }

    /// The first guess of t = theta/theta_t where H = q inner (q in [0, 1]): two Newton steps on
    /// a model h(t) of H/inner with its values and slopes m0, m1 at both ends and h''(0) = 0 (H is
    /// odd in y): the quartic t (m0 + t^2 (a3 + a4 t)) where the region ends with a width
    /// (slope m1 above 0.05), else the tip 1 − (1 − t)^3 (1 + c1 t + c2 t^2) (the width vanishing
    /// like (theta_t − theta)^2), from 1 − (1 − q)^(1/3). Measured with it: 2.1 evaluations of H
    /// per sample in double, 1.3 in float (the linear guess: 2.85 and 2.1).
    APSE_FUNC T first_guess(T q) const noexcept {
        const bool tip = !(m1_ > T(0.05));
        T t = tip ? T(1) - cbrt_guess(T(1) - q) : q;
        const T a3 = T(4) - T(3) * m0_ - m1_, a4 = m1_ + T(2) * m0_ - T(3);
        const T c1 = T(3) - m0_, c2 = T(3) * c1 - T(3);
        for (int k = 0; k < 2; ++k) {
            T h, dh;
            if (tip) {
                const T r = T(1) - t, p = T(1) + t * (c1 + t * c2), dp = c1 + T(2) * c2 * t;
                h = T(1) - r * r * r * p;
                dh = r * r * (T(3) * p - r * dp);
            } else {
                const T t2 = t * t;
                h = t * (m0_ + t2 * (a3 + t * a4));
                dh = m0_ + t2 * (T(3) * a3 + T(4) * a4 * t);
            }
            if (dh > T(0)) t = detail::clamp(t - (h - q) / dh, T(0), T(1));
        }
        return t;
    }

    /// A first guess of x^(1/3) for x >= 0 (any finite value: the root finder refines it).
    static APSE_FUNC T cbrt_guess(T x) noexcept {
        return x > T(0x1p-100) ? detail::cube_root_approx(detail::min_of(x, T(0x1p100))) : T(0);
    }

    /// The visible width L at y = sin a sin theta, inside y_t (cos theta = ct, w = sqrt(1 − y^2)):
    /// w − x_lo, x_lo = x0 − a' cos theta, as h^2/(w + x_lo) when x_lo > 0
    /// (w^2 − x_lo^2 = h^2, h = cos a cos g + sin a sin g cos theta: no cancellation).
    APSE_FUNC T inner_width(T ct, T w) const noexcept {
        const T xlo = x0_ - ap_ * ct;
        if (xlo > T(0)) {
            const T h = ca_ * cg_ + sa_ * sg_ * ct;
            return h * h / (w + xlo);
        }
        return w - xlo;
    }

    /// The projected area between y = 0 and y = sin a sin theta for theta in [0, theta_t]
    /// (w = sqrt(1 − y^2), inv_1pw = 1/(1 + w)):
    /// (y w + asin y)/2 − x0 y + a' b (theta + sin theta cos theta)/2, written as
    /// y (1 − x0) + (asin y − y)/2 − y^3/(2 (1 + w)) + a' b (theta + sin theta cos theta)/2 (every
    /// term but the last positive; the last too when the centre is above the horizon).
    /// With the centre below the horizon (a' < 0) the last term is negative and, as the visible
    /// sliver vanishes, cancels the first; there the same area is evaluated as
    /// y (1 − sin(g − a)) + |a'| b (sin theta (1 − cos theta) − (theta − sin theta))/2
    ///   − (y^3/(2 (1 + w)) − (asin y − y)/2),
    /// whose terms are smaller by the sliver's width (docs/math.md §14).
    template <bool Precise> APSE_FUNC T inner_area(T th, T sth, T cth, T w, T inv_1pw) const noexcept {
        const T y = sa_ * sth;
        const T circle = T(0.5) * y * y * y * inv_1pw - T(0.5) * detail::asin_minus_identity<Precise>(y, w);  // ∫ (1 − w)
        if (cg_ < T(0)) {
            const T band = sth * (sth * sth / (T(1) + cth)) - angle_minus_sine(th, sth);
            return y * d0_ - T(0.5) * ap_ * sa_ * band - circle;
        }
        return y * one_minus_x0_ - circle + T(0.5) * ap_ * sa_ * (th + sth * cth);
    }

    /// theta − sin theta for theta in [0, pi/2] (s = sin theta) without cancellation: its Taylor
    /// series below 1/2 (8 terms in double, 4 in float: the first left out is below 1e-17, resp.
    /// 1e-9, relative), the difference above.
    static APSE_FUNC T angle_minus_sine(T th, T s) noexcept {
        if (th < T(0.5)) {
            const T t2 = th * th;
            T p = T(1);
            if constexpr (sizeof(T) != sizeof(float)) {
                p = T(1) - t2 * T(1.0 / 272.0);
                p = T(1) - t2 * T(1.0 / 210.0) * p;
                p = T(1) - t2 * T(1.0 / 156.0) * p;
                p = T(1) - t2 * T(1.0 / 110.0) * p;
            }
            p = T(1) - t2 * T(1.0 / 72.0) * p;
            p = T(1) - t2 * T(1.0 / 42.0) * p;
            p = T(1) - t2 * T(1.0 / 20.0) * p;
            return th * t2 * T(1.0 / 6.0) * p;
        }
        return th - s;
    }

    vec3 c_{T(0), T(0), T(1)};   ///< the cap's centre (world)
    vec3 e1_{T(1), T(0), T(0)};  ///< the tangent at the centre pointing away from the normal (world)
    vec3 e2_{T(0), T(1), T(0)};  ///< c × e1 (world): the receiver frame's Y
    vec3 n_{T(0), T(0), T(1)};   ///< the receiver's unit normal (world)
    T sg_{}, cg_{};              ///< sin g, cos g: g the angle from the normal to the centre
    T ta_{}, sa_{}, ca_{}, omca_{};  ///< tan a, sin a, cos a, 1 − cos a: a the cap's angular radius
    T x0_{}, ap_{}, one_minus_x0_{}, d0_{};  ///< the projected ellipse's centre x0 = cos a sin g, semi-axis a' = sin a cos g, 1 − x0, 1 − sin(g − a)
    T st_{}, ct_{}, theta_t_{};  ///< sin, cos of theta_t and theta_t (y_t = sin a sin theta_t)
    T inner_{}, outer_{};        ///< the areas of y in [0, y_t] and [y_t, b] (half the visible region each side)
    T half_{};                   ///< half the projected solid angle
    T m0_{}, m1_{};              ///< the slopes of H/inner in theta/theta_t at 0 and theta_t (first_guess)
    T inv_inner_{};              ///< 1 / inner_ (0 if inner_ is 0)
    T area_{};                   ///< the projected solid angle
    T inv_area_{};               ///< 1 / area_
    bool cut_ = false;           ///< the horizon cuts the cap
    bool empty_ = true;
};

}  // namespace detail
}  // namespace apse
