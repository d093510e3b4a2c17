// apse — area-preserving parameterizations for spherical ellipses.
// SPDX-License-Identifier: MIT
#pragma once

/// @file projected_solid_angle.hpp
/// `ProjectedSolidAngleSampler<T>`: directions on a spherical ellipse drawn in proportion to a
/// receiver's clamped cosine max(0, n·ω) along each azimuth exactly, with the exact density
/// reported; no sample falls below the receiver's horizon (docs/cosine_weighted.md,
/// docs/math.md §13).
///
/// Polar coordinates (phi, theta) about the ellipse's centre (phi from the major axis): the
/// boundary is tan^2 theta_max(phi) = 1/(cos^2 phi / tan^2 alpha + sin^2 phi / tan^2 beta) and
/// dω = sin theta dtheta dphi. With n the unit normal in the ellipse's frame and
/// s(phi) = n_x cos phi + n_y sin phi, the cosine is n_z cos theta + s sin theta. Along one
/// azimuth the part above the horizon is one interval of theta (its ends in closed form); from
/// its lower end theta_0 the integrand c sin theta is sin d (a cos d + b sin d), d = theta −
/// theta_0, with (a, b) = (n_z, s) when the centre is above the horizon (theta_0 = 0) and
/// (−n_z, s) otherwise (theta_0 the horizon, c = sqrt(n_z^2 + s^2) sin d), so the conditional
/// CDF is F(d) = (a sin^2 d + b (d − sin d cos d))/2 in both cases, every term non-negative
/// where it matters (no cancellation), and d is found by safeguarded Halley steps
/// (find_root_bracketed). The azimuth is drawn from a piecewise-linear density m through the
/// exact marginal at Nodes azimuths (over the whole turn, or over the arc above the horizon
/// when the centre is below it); the density reported is exactly the one drawn from,
/// pdf(ω) = m(phi) / (M J(phi)) · c(ω) / F_phi, M = ∫m, whatever m is: m decides the variance only.
///
/// The azimuth is parameterised by an angle tau, (cos phi, sin phi) ∝ (cos tau, q sin tau) with
/// q = sin(beta/2)/sin(alpha/2) (the ratio of the Lambert equal-area images of the semi-axes: the
/// marginal in tau is nearly uniform for every ellipse, and smooth); u1 = tau/(2 pi) (folded
/// onto quadrants as the radial maps do), u2 the conditional CDF. Every sine and cosine of a
/// known range is a short polynomial (detail/math.hpp): no library call.

#include <cmath>

#include "config.hpp"
#include "detail/math.hpp"
#include "sample.hpp"
#include "spherical_ellipse.hpp"
#include "detail/glm.hpp"
#include "detail/linear_density.hpp"
#include "detail/polar.hpp"
#include "detail/vector.hpp"

namespace apse {
namespace detail {

/// E(x) k^2, E(x) = x − sin x cos x for x in [0, pi/2] with s = sin x, c = cos x, and a scale
/// k (1/sqrt(tan alpha tan beta), so that masses ~ theta^2 neither underflow nor overflow in float
/// for the tiniest and the thinnest ellipses): the
/// Taylor series of (y − sin y)/2, y = 2x, below x = 1/2 (the difference cancels there; the
/// series' first omitted term is below 1e-17 relative), the difference above (it loses at most a
/// factor 6 there).
template <class T> APSE_FUNC T angle_minus_sin_cos(T x, T s, T c, T k) noexcept {
    if (x < T(0.5)) {
        const T y2 = T(4) * x * x;
        T p = T(1) - y2 * T(1.0 / 342.0);
        p = T(1) - y2 * T(1.0 / 272.0) * p;
        p = T(1) - y2 * T(1.0 / 210.0) * p;
        p = T(1) - y2 * T(1.0 / 156.0) * p;
        p = T(1) - y2 * T(1.0 / 110.0) * p;
        p = T(1) - y2 * T(1.0 / 72.0) * p;
        p = T(1) - y2 * T(1.0 / 42.0) * p;
        p = T(1) - y2 * T(1.0 / 20.0) * p;
        const T xk = x * k;
        return T(2.0 / 3.0) * xk * xk * x * p;  // (2x)^3 / 12 (1 − ...) k^2
    }
    return (x - s * c) * k * k;
}

/// The part of one azimuth above the horizon, as the conditional density sin d (a cos d + b sin d)
/// of d = theta − theta_0 in [0, end] (file comment).
template <class T> struct PsaRay {
    T a, b;              ///< the conditional density's coefficients (a >= 0)
    T kc;                ///< > 0: the cosine is kc sin d (theta_0 is the horizon); 0: a cos d + b sin d
    T sin0, cos0;        ///< sin, cos of theta_0
    T sin_end, cos_end;  ///< sin, cos of the range's end
    T end;               ///< the range's end, radians (psa_finish)
    T mass;              ///< F(end) k^2, F(end) = ∫ c dω per unit azimuth (psa_finish); 0 if all below
    T k;                 ///< the scale of every F (k^2): 1/sqrt(tan alpha tan beta)
    bool valid;          ///< false: the whole azimuth is below the horizon
    bool at_rim;         ///< the range is [0, theta_max]: the centre to the rim
};

/// F(d) k^2, F(d) = (a sin^2 d + b (d − sin d cos d))/2.
template <class T> APSE_FUNC T psa_cdf(const PsaRay<T>& r, T d, T s, T c) noexcept {
    const T sk = s * r.k;
    return T(0.5) * (r.a * sk * sk + r.b * angle_minus_sin_cos(d, s, c, r.k));
}

/// (x, y)/h for finite (x, y) with h = hypot(x, y) > 0: a unit pair even when x and y are
/// subnormal (a normal whose components in the ellipse's frame are ~1e-320), which hold too few
/// digits for one; they are rescaled exactly by a power of two first.
template <class T> APSE_FUNC void psa_unit_pair(T x, T y, T h, T& ux, T& uy) noexcept {
    if (!(h >= safe_scale_min<T>())) {
        const Pow2Scale<T> sc = pow2_scale_for(h);
        x = sc(x);
        y = sc(y);
        h = hypot2(x, y);
    }
    ux = x / h;
    uy = y / h;
}

/// The ray of the unit horizontal direction (cp, sp) whose rim is at polar angle theta_max
/// (sin st, cos ct), for the unit normal n (ellipse frame): the range above the horizon and its
/// conditional density (end and mass: psa_finish); k: the scale of F (PsaRay::k).
template <class T> APSE_FUNC PsaRay<T> psa_ray(T cp, T sp, T st, T ct, const glm::vec<3, T>& n, T k) noexcept {
    PsaRay<T> r{};
    r.k = k;
    const T s = n.x * cp + n.y * sp;
    const T cm = n.z * ct + s * st;  // the cosine at the rim
    r.cos0 = T(1);
    r.valid = true;
    r.b = s;
    if (n.z > T(0)) {
        r.a = n.z;
        if (cm >= T(0)) {
            r.sin_end = st;
            r.cos_end = ct;
            r.at_rim = true;
        } else {  // the horizon cuts the azimuth at tan theta = n_z / (−s)
            psa_unit_pair(n.z, -s, hypot2(n.z, s), r.sin_end, r.cos_end);
        }
    } else if (s > T(0) && cm > T(0)) {
        const T h = hypot2(n.z, s);
        r.a = -n.z;
        r.kc = h;
        T c0, s0;  // (cos, sin) of theta_0 = atan(−n_z / s), where the horizon crosses the ray
        psa_unit_pair(s, -n.z, h, c0, s0);
        r.sin0 = s0;
        r.cos0 = c0;
        r.sin_end = st * c0 - ct * s0;  // sin(theta_max − theta_0): the rim's cosine / h
        r.cos_end = ct * c0 + st * s0;
    } else {
        r.valid = false;  // the whole azimuth is below the horizon
    }
    return r;
}

/// The end angle and mass of a valid ray, given E(end) k^2 (angle_minus_sin_cos).
template <class T> APSE_FUNC void psa_finish(PsaRay<T>& r, T end, T e) noexcept {
    r.end = end;
    const T sk = r.sin_end * r.k;
    r.mass = T(0.5) * (r.a * sk * sk + r.b * e);
}

/// sin and cos of the rim's polar angle theta_max at the unit horizontal direction (cp, sp):
/// 1/tan^2 theta_max = cp^2 / tan^2 alpha + sp^2 / tan^2 beta = d, sin = 1/sqrt(1 + d),
/// cos = sqrt(d) sin.
template <class T> APSE_FUNC void psa_rim(T cp, T sp, T inv_a2, T inv_b2, T& st, T& ct) noexcept {
    const T d = cp * cp * inv_a2 + sp * sp * inv_b2;
    st = T(1) / std::sqrt(T(1) + d);
    ct = std::sqrt(d) * st;
}

/// The azimuth parameter's point for the quadrant fraction f in [0, 1] (measured from the major
/// axis): (cos tau, sin tau), tau = f pi/2 (before the stretch q along the minor axis).
template <class T> APSE_FUNC void psa_azimuth_point(T f, T& x, T& y) noexcept {
    const SinCosValues<T> v = sin_cos_quarter_turn(f);
    x = v.c;
    y = v.s;
}
/// The inverse: the quadrant fraction of the unstretched point (x, y) (x, y >= 0, any length),
/// with that point's (cos tau, sin tau) in (sx, sy).
template <class T> APSE_FUNC T psa_azimuth_fraction(T x, T y, T& sx, T& sy) noexcept {
    const T len = hypot2(x, y);
    sx = x / len;
    sy = y / len;
    return detail::min_of(angle_of(sy, sx) * T(0.63661977236758134308), T(1));
}
/// dphi/dt = psa_turn_jacobian q / R^2 (t in turns): 4 quadrants × pi/2.
template <class T> APSE_FUNC constexpr T psa_turn_jacobian() noexcept { return detail::two_pi_v<T>; }


/// Exact projected-solid-angle sampling of a spherical ellipse for a receiver with normal n
/// (file comment; docs/cosine_weighted.md): the conditional along each azimuth is exactly
/// proportional to max(0, n·ω), the azimuth's density is piecewise linear through the marginal
/// at `Nodes` azimuths (a multiple of 4; the default is the measured trade-off between variance
/// and cost), and the reported pdf is the exact density of the samples. No sample lies below
/// the horizon. The input square: u1 the azimuth parameter (turns), u2 the conditional CDF
/// along it — continuous and monotone in each, so stratified points stay stratified. Set-up:
/// Nodes/4 − 1 rims off the axes (two square roots each), the node values from one quadrant by
/// symmetry where the horizon does not cut the ray; per sample one rim, one end angle and
/// 2–3 Halley steps (one polynomial sine and cosine each). Trivially copyable; no allocation.
template <class T, int Nodes = 8> class ProjectedSolidAngleSampler {
    static_assert(Nodes >= 4 && Nodes % 4 == 0, "the nodes fold onto the four quadrants");

public:
    using vec2 = glm::vec<2, T>;  ///< a point of the unit square
    using vec3 = glm::vec<3, T>;  ///< a 3-D vector (direction or normal)

    /// The empty sampler (every pdf 0).
    APSE_FUNC ProjectedSolidAngleSampler() noexcept : e_(SphericalEllipse<T>::make_empty()), empty_(true) {}

    /// The sampler of the ellipse `e` for a receiver with world-space normal `normal` (any
    /// non-zero finite length; the receiver's side is the one it points to). Empty (every pdf 0)
    /// for an empty ellipse, a zero, NaN or infinite normal, or a light entirely below the
    /// horizon (max n·ω <= 0 over the ellipse: an exact test).
    APSE_FUNC ProjectedSolidAngleSampler(const SphericalEllipse<T>& e, const vec3& normal) noexcept
        : e_(e), empty_(true) {
        if (e.empty()) return;
        const T scale = detail::max_abs3(normal);
        if (!(scale > T(0)) || !detail::is_finite(scale)) return;
        bool ok = true;
        n_ = e.to_local(detail::normalize_direction(normal / scale, ok));
        if (!ok) return;
        // Entirely below the horizon: -n lies in the dual cone of the ellipse's cone,
        // n_x^2 tan^2 alpha + n_y^2 tan^2 beta <= n_z^2 with n_z <= 0 (times cos^2 alpha cos^2 beta).
        const T ca2 = e.cos_alpha * e.cos_alpha, cb2 = e.cos_beta * e.cos_beta;
        const T lx = n_.x * e.sin_alpha * e.cos_beta, ly = n_.y * e.sin_beta * e.cos_alpha;
        if (!(n_.z > T(0)) && lx * lx + ly * ly <= n_.z * n_.z * ca2 * cb2) return;
        // every product after the divisions: tan^2 beta and tan alpha tan beta may be subnormal
        const T ia = T(1) / e.tan_alpha, ib = T(1) / e.tan_beta;
        inv_a2_ = ia * ia;
        inv_b2_ = ib * ib;
        k_ = std::sqrt(ia * ib);  // 1/sqrt(tan alpha tan beta)
        // the Lambert ratio sin(beta/2)/sin(alpha/2) = (sin beta/sin alpha) sqrt((1 + cos alpha)/(1 + cos beta))
        // (no product of small numbers; kept above sqrt(eps): any q > 0 is exact)
        q_ = detail::max_of(e.sin_beta / e.sin_alpha * std::sqrt((T(1) + e.cos_alpha) / (T(1) + e.cos_beta)), std::sqrt(detail::epsilon<T>()));
        T z[Nodes + 1];
        if (n_.z > T(0)) {
            full_nodes(z);
        } else if (!arc_nodes(lx, ly, z)) {
            return;
        }
        // the node values plus a floor (1e-3 of the largest), so that the marginal is positive
        // wherever a ray may be above the horizon; the ends of an arc are exactly where no ray is:
        // 0 there (the marginal vanishes like the distance to the end, or its square)
        T top = T(0);
        for (int k = 0; k <= Nodes; ++k) top = detail::max_of(top, z[k]);
        const T floor = top > T(0) && detail::is_finite(top) ? T(1e-3) * top : T(0);
        cdf_[0] = T(0);
        for (int k = 0; k <= Nodes; ++k) {
            const bool arc_end = width_ < T(1) && (k == 0 || k == Nodes);
            node_[k] = !(floor > T(0)) ? T(1) : (arc_end ? T(0) : detail::max_of(z[k], T(0)) + floor);  // no usable node: uniform
        }
        for (int k = 0; k < Nodes; ++k) cdf_[k + 1] = cdf_[k] + interval_mass(k, T(1)) / T(Nodes);
        inv_total_ = T(1) / cdf_[Nodes];
        empty_ = false;
    }

    /// True if the sampler cannot sample (empty ellipse, zero/NaN normal, light below the
    /// horizon): every sample and pdf is then 0.
    APSE_FUNC bool empty() const noexcept { return empty_; }

    /// The ellipse sampled.
    APSE_FUNC const SphericalEllipse<T>& ellipse() const noexcept { return e_; }

    /// Direction for the point u of the unit square (clamped into [0, 1]^2): a world-space unit
    /// vector inside the ellipse and above the receiver's horizon, with its exact density in
    /// solid angle. NaN u or empty(): pdf 0 and the ellipse's centre direction; u2 = 0 or 1
    /// where the range ends at the horizon: that horizon direction with pdf 0 (n·ω = 0); a
    /// density beyond T's range (float, lights of ~1e-36 sr grazing the horizon): pdf 0.
    APSE_FUNC DirectionSample<T> sample(const vec2& u) const noexcept {
        bool ok = !empty_;
        const vec2 uc = detail::clamp_unit(u, ok);
        if (!ok) return {e_.z, T(0)};
        // the azimuth: the piecewise-linear marginal's interval, then the root in it
        const T t = uc.x * cdf_[Nodes];
        int k = 0, hi = Nodes;  // bisection to cdf_[k] <= t < cdf_[k + 1]
        while (hi - k > 1) {
            const int mid = (k + hi) / 2;
            if (t < cdf_[mid]) hi = mid;
            else k = mid;
        }
        const T frac = interval_root(k, (t - cdf_[k]) * T(Nodes));
        const T m = interval_density(k, frac);
        Azimuth a = azimuth_at((T(k) + frac) / T(Nodes));
        const detail::PsaRay<T> r = ray(a);
        if (!r.valid || !(r.mass > T(0))) return {e_.z, T(0)};
        // along the azimuth: F(d) = u2 F(end) = target, from the root x = d/end of the cubic
        // A x^2 + B x^3 = target that matches F at d = 0 (to second order: F''(0) = a) and at
        // the end (A = a end^2/2, B = F(end) − A; two Newton steps from sqrt(u2))
        const T target = uc.y * r.mass;
        const T ek = r.end * r.k, ma = T(0.5) * r.a * ek * ek, mb = r.mass - ma;
        T x = std::sqrt(uc.y);
        for (int i = 0; i < 2; ++i) {
            const T slope = x * (T(2) * ma + T(3) * mb * x);
            if (slope > T(0)) x = detail::min_of(detail::max_of(x - (x * x * (ma + mb * x) - target) / slope, T(0)), T(1));
        }
        T sd = T(0), cd = T(1);
        // Halley's steps through the Newton root finder: with the derivative f' − f f''/(2 f')
        // its step is Halley's (cubic convergence), still safeguarded by the bracket
        auto eval = [&](T d, T& value, T& derivative) {
            const detail::SinCosValues<T> v = detail::sin_cos_quarter_turn(detail::min_of(d * T(0.63661977236758134308), T(1)));
            sd = v.s;
            cd = v.c;
            value = detail::psa_cdf(r, d, sd, cd) - target;
            const T f1 = sd * r.k * (r.a * cd + r.b * sd) * r.k;
            const T f2 = (r.a * (cd - sd) * (cd + sd) + T(2) * r.b * sd * cd) * r.k * r.k;
            derivative = f1 > T(0) ? f1 - value * f2 / (T(2) * f1) : f1;
        };
        detail::find_root_bracketed(eval, T(0), r.end, x * r.end, T(2) * detail::epsilon<T>() * r.mass, 60);
        // sd, cd: the last point evaluated, which find_root_bracketed returns
        const T st = sd * r.cos0 + cd * r.sin0, ct = cd * r.cos0 - sd * r.sin0;
        const T c = r.kc > T(0) ? r.kc * sd : r.a * cd + r.b * sd;
        const vec3 l(st * a.cp, st * a.sp, ct);
        return {e_.to_world(l), density(m, a, r, c)};
    }

    /// Density of sample() at the world-space direction `d` (any non-zero length), in solid
    /// angle: 0 outside the ellipse, below the horizon, for empty() or a zero/NaN direction.
    /// Equals the pdf sample() reports.
    APSE_FUNC T pdf(const vec3& d) const noexcept {
        vec3 l;
        if (!local(d, l) || !e_.contains(d)) return T(0);
        const T c = glm::dot(n_, l);
        if (!(c > T(0))) return T(0);
        const Azimuth a = azimuth_of(l.x, l.y);
        const detail::PsaRay<T> r = ray(a);
        if (!r.valid || !(r.mass > T(0))) return T(0);
        return density(marginal(a.x), a, r, c);
    }

    /// The point of the unit square whose sample has direction `d`: u1 the azimuth's CDF, u2
    /// the conditional CDF along it. Directions outside the ellipse or below the horizon: the
    /// same formulas, clamped into [0, 1]^2. Zero/NaN direction or empty(): (0, 0).
    APSE_FUNC vec2 invert(const vec3& d) const noexcept {
        vec3 l;
        if (!local(d, l)) return vec2(T(0));
        const Azimuth a = azimuth_of(l.x, l.y);
        int k;
        T frac;
        node_interval(a.x, k, frac);
        const T u1 = (cdf_[k] + interval_mass(k, frac) / T(Nodes)) * inv_total_;
        const detail::PsaRay<T> r = ray(a);
        if (!r.valid || !(r.mass > T(0))) return vec2(detail::clamp(u1, T(0), T(1)), T(0));
        const T rxy = detail::hypot2(l.x, l.y);
        // d = theta − theta_0 (sin, cos: the angle-difference formulas)
        const T sd = detail::max_of(rxy * r.cos0 - l.z * r.sin0, T(0)), cd = detail::max_of(l.z * r.cos0 + rxy * r.sin0, T(0));
        const T u2 = detail::psa_cdf(r, detail::angle_of(sd, cd), sd, cd) / r.mass;
        return vec2(detail::clamp(u1, T(0), T(1)), detail::clamp(u2, T(0), T(1)));
    }

private:
    /// An azimuth: its position x in [0, 1] along the nodes, unit horizontal direction (cp, sp)
    /// and dphi/dt (t: the parameter in turns).
    struct Azimuth {
        T x, cp, sp, jacobian;
    };

    /// The azimuth at position x along the nodes.
    APSE_FUNC Azimuth azimuth_at(T x) const noexcept {
        T t = t0_ + width_ * x;
        if (t >= T(1)) t -= T(1);
        const detail::QuadrantFold<T> f = detail::fold_quadrant(t);
        T sx, sy;
        detail::psa_azimuth_point(f.fraction, sx, sy);
        const T r2 = sx * sx + q_ * q_ * sy * sy, inv = T(1) / std::sqrt(r2);
        const vec3 h = detail::place_in_quadrant(f, sx * inv, q_ * sy * inv, T(0));
        return {x, h.x, h.y, detail::psa_turn_jacobian<T>() * q_ / r2};
    }

    /// The density in solid angle of the direction with cosine c on the ray r of azimuth a, where
    /// the azimuth's marginal is m: m / (M J) · c / F. 0 for c <= 0, and 0 where the density
    /// overflows T (beyond ~3e38 in float: only lights of ~1e-36 sr or less grazing the
    /// horizon), so that such a sample is declined rather than given an infinite pdf.
    APSE_FUNC T density(T m, const Azimuth& a, const detail::PsaRay<T>& r, T c) const noexcept {
        if (!(c > T(0))) return T(0);
        const T p = m * inv_total_ / (width_ * a.jacobian) * (c / r.mass * r.k) * r.k;
        return detail::is_finite(p) ? p : T(0);
    }

    /// The ray of an azimuth, its end angle to a few ulps (angle_of) and its mass.
    APSE_FUNC detail::PsaRay<T> ray(const Azimuth& a) const noexcept {
        T st, ct;
        detail::psa_rim(a.cp, a.sp, inv_a2_, inv_b2_, st, ct);
        detail::PsaRay<T> r = detail::psa_ray(a.cp, a.sp, st, ct, n_, k_);
        if (r.valid) {
            const T end = detail::angle_of(r.sin_end, r.cos_end);
            detail::psa_finish(r, end, detail::angle_minus_sin_cos(end, r.sin_end, r.cos_end, k_));
        }
        return r;
    }

    /// The marginal's value at a node of the ray r (its end angle within 2e-8, angle_approx: any
    /// positive node value is exact for the sampler); `rim_e`: E(theta_max), used if the range
    /// is the whole ray.
    static APSE_FUNC T node_mass(detail::PsaRay<T> r, T rim_e) noexcept {
        if (!r.valid) return T(0);
        if (r.at_rim) {
            detail::psa_finish(r, T(0), rim_e);
        } else {
            const T end = detail::angle_approx(r.sin_end, r.cos_end);
            detail::psa_finish(r, end, detail::angle_minus_sin_cos(end, r.sin_end, r.cos_end, r.k));
        }
        return r.mass;
    }

    /// The local unit direction l of the world-space direction d; false if the sampler is empty
    /// or d zero, NaN or infinite.
    APSE_FUNC bool local(const vec3& d, vec3& l) const noexcept {
        if (empty_) return false;
        bool ok = true;
        l = detail::normalize_direction(e_.to_local(d), ok);
        return ok;
    }

    /// The azimuth of the local horizontal direction (x, y) (any length; (0, 0): the major
    /// axis): the parameter t of its unstretched point (|cp|, |sp| / q), its position along the nodes
    /// (clamped into [0, 1]) and dphi/dt.
    APSE_FUNC Azimuth azimuth_of(T x, T y) const noexcept {
        const T rxy = detail::hypot2(x, y);
        const T cp = rxy > T(0) ? x / rxy : T(1), sp = rxy > T(0) ? y / rxy : T(0);
        T sx, sy;
        const T f = detail::psa_azimuth_fraction(std::fabs(cp), std::fabs(sp) / q_, sx, sy);
        T t = detail::unfold_quadrant_fraction(detail::quadrant_of(cp, sp), f) - t0_;
        if (t < T(0)) t += T(1);
        const T pos = width_ < T(1) ? t / width_ : t;
        return {detail::clamp(pos, T(0), T(1)), cp, sp, detail::psa_turn_jacobian<T>() * q_ / (sx * sx + q_ * q_ * sy * sy)};
    }

    /// The node interval k and the position in it of x in [0, 1].
    APSE_FUNC void node_interval(T x, int& k, T& frac) const noexcept {
        const T y = detail::clamp(x, T(0), T(1)) * T(Nodes);
        k = y > T(0) ? int(y) : 0;
        if (k > Nodes - 1) k = Nodes - 1;
        frac = detail::clamp(y - T(k), T(0), T(1));
    }

    /// The piecewise-linear marginal at x.
    APSE_FUNC T marginal(T x) const noexcept {
        int k;
        T frac;
        node_interval(x, k, frac);
        return interval_density(k, frac);
    }

    /// The marginal's density at the position y in [0, 1] of node interval k (linear).
    APSE_FUNC T interval_density(int k, T y) const noexcept { return node_[k] + y * (node_[k + 1] - node_[k]); }

    /// Its integral over [0, y].
    APSE_FUNC T interval_mass(int k, T y) const noexcept { return detail::linear_density_mass(node_[k], node_[k + 1], y); }

    /// The y in [0, 1] at which that integral is x.
    APSE_FUNC T interval_root(int k, T x) const noexcept { return detail::linear_density_root(node_[k], node_[k + 1], x); }

    /// Nodes over the whole turn (the centre above the horizon): one quadrant of rims, reflected.
    APSE_FUNC void full_nodes(T (&z)[Nodes + 1]) noexcept {
        t0_ = T(0);
        width_ = T(1);
        constexpr int m = Nodes / 4;
        T cp[m + 1], sp[m + 1], st[m + 1], ct[m + 1], e[m + 1], jac[m + 1], wa[m + 1], wb[m + 1];
        for (int j = 0; j <= m; ++j) {
            T sx, sy;
            detail::psa_azimuth_point(T(j) / T(m), sx, sy);
            const T r2 = sx * sx + q_ * q_ * sy * sy, inv = T(1) / std::sqrt(r2);
            cp[j] = sx * inv;
            sp[j] = q_ * sy * inv;
            jac[j] = detail::psa_turn_jacobian<T>() * q_ / r2;
            if (j == 0) {  // the major axis: theta_max = alpha
                st[j] = e_.sin_alpha;
                ct[j] = e_.cos_alpha;
            } else if (j == m) {  // the minor axis: beta
                st[j] = e_.sin_beta;
                ct[j] = e_.cos_beta;
            } else {
                detail::psa_rim(cp[j], sp[j], inv_a2_, inv_b2_, st[j], ct[j]);
            }
            e[j] = detail::angle_minus_sin_cos(detail::angle_approx(st[j], ct[j]), st[j], ct[j], k_);
            const T sk = st[j] * k_;
            wa[j] = T(0.5) * jac[j] * sk * sk;  // the node value is n_z wa + s wb when the
            wb[j] = T(0.5) * jac[j] * e[j];            // whole ray is above the horizon
        }
        for (int qd = 0; qd < 4; ++qd)
            for (int i = 0; i < m; ++i) {
                const int j = (qd & 1) ? m - i : i;  // odd quadrants are reflected (fold_quadrant)
                const T hx = (qd == 1 || qd == 2) ? -cp[j] : cp[j], hy = qd >= 2 ? -sp[j] : sp[j];
                const T sn = n_.x * hx + n_.y * hy;
                z[qd * m + i] = n_.z * ct[j] + sn * st[j] >= T(0)
                                    ? n_.z * wa[j] + sn * wb[j]
                                    : jac[j] * node_mass(detail::psa_ray(hx, hy, st[j], ct[j], n_, k_), e[j]);
            }
        z[Nodes] = z[0];
    }

    /// Nodes over the arc of azimuths above the horizon (the centre on or below it): its ends
    /// are where the horizon's line n_x x + n_y y = −n_z crosses the gnomonic boundary
    /// (tan alpha cos tau, tan beta sin tau): tau = tau_n ± gamma, cos gamma = −n_z / L. lx, ly:
    /// n_x tan alpha, n_y tan beta times cos alpha cos beta. False if the arc is empty.
    APSE_FUNC bool arc_nodes(T lx, T ly, T (&z)[Nodes + 1]) noexcept {
        const T len = detail::hypot2(lx, ly);
        const T cn = lx / len, sn = ly / len;  // tau_n
        const T cg = detail::clamp(-n_.z * e_.cos_alpha * e_.cos_beta / len, T(0), T(1)), sg = std::sqrt((T(1) - cg) * (T(1) + cg));
        // the two crossings' gnomonic directions (their scale does not matter)
        const T c_lo = cn * cg + sn * sg, s_lo = sn * cg - cn * sg;  // tau_n − gamma
        const T c_hi = cn * cg - sn * sg, s_hi = sn * cg + cn * sg;  // tau_n + gamma
        t0_ = T(0);
        width_ = T(1);
        const SphericalEllipse<T>& e = e_;
        const T lo = azimuth_of(e.sin_alpha * e.cos_beta * c_lo, e.sin_beta * e.cos_alpha * s_lo).x;
        const T hi = azimuth_of(e.sin_alpha * e.cos_beta * c_hi, e.sin_beta * e.cos_alpha * s_hi).x;
        T w = hi - lo;
        if (w < T(0)) w += T(1);
        if (w > T(0.75)) w = T(0);  // rounding wrapped a vanishing arc (the arc is at most half a turn)
        if (!(w > T(0))) return false;
        t0_ = lo;
        width_ = w;
        for (int k = 0; k <= Nodes; ++k) {
            const Azimuth az = azimuth_at(T(k) / T(Nodes));
            T st, ct;
            detail::psa_rim(az.cp, az.sp, inv_a2_, inv_b2_, st, ct);
            z[k] = w * az.jacobian * node_mass(detail::psa_ray(az.cp, az.sp, st, ct, n_, k_), T(0));
        }
        return true;
    }

    SphericalEllipse<T> e_;
    vec3 n_{};                ///< the unit normal in the ellipse's frame
    T inv_a2_{}, inv_b2_{};   ///< 1/tan^2 alpha, 1/tan^2 beta
    T q_{};                   ///< the azimuth parameter's stretch along the minor axis
    T k_{};                   ///< the scale of every F (PsaRay::k)
    T t0_{}, width_{};        ///< the arc of azimuths sampled: [t0, t0 + width] (turns, mod 1)
    T node_[Nodes + 1]{};     ///< the marginal at the nodes (> 0)
    T cdf_[Nodes + 1]{};      ///< its integral from 0 to node k (over x in [0, 1])
    T inv_total_{};           ///< 1 / cdf_[Nodes]
    bool empty_;
};

}  // namespace detail
}  // namespace apse
