// apse — area-preserving parameterizations for spherical ellipses.
// SPDX-License-Identifier: MIT
#pragma once

/// @file detail/tabulated_cosine.hpp
/// `TabulatedCosineWarp<T, Nodes>`: the cosine-weighted option of the tabulated maps when the
/// ellipse's centre is above the receiver's horizon (CosineWeighted, docs/cosine_weighted.md).
/// A warp of TabulatedMap's own square (u1 the azimuth's area fraction, u2 the radial fraction)
/// whose density follows the receiver's cosine, so that it reuses the map's sample — its table
/// walk, rim and direction — and adds no trigonometry.
///
/// Along the ray of one azimuth the map's radial fraction u2 gives cos theta = 1 − h u2
/// (h = 1 − C, C = cos theta_max there), so with r = sqrt(u2) the receiver's cosine is exactly
///     c(r) = n_z (1 − h r^2) + s sin theta(r),   sin theta(r) = r sqrt(h (2 − h r^2)),
/// (s: the normal's component along the azimuth, n_z along the ellipse's axis). The warp draws r
/// from the model
///     c~(r) = n_z (1 − h r^2) + B r,
/// exact at the centre and, with B = s sin theta_max, at the rim; where the horizon crosses the
/// ray (at r_h, in closed form), B is the value that puts c~'s root there too, and c~ factors as
/// beta (r_h − r)(1 + h r_h r), beta = n_z / r_h: c~ > 0 exactly on the part of the ray above the
/// horizon, so no sample falls below it. The conditional density of u2 is c~ / M (M = ∫ c~ du2,
/// a polynomial in r), drawn by Halley's steps on that quartic polynomial. The azimuth is
/// drawn from a density in u1 that is linear between Nodes azimuths (at equal steps of the map's
/// Lambert anomaly) through M there. The density reported is the map's density times the warp's,
///     pdf(ω) = pdf_map(ω) m(u1) / (∫ m) · c~(r) / M(u1),
/// exactly the density of the samples; the model decides the variance only.
///
/// The centre must be above the horizon (n_z > 0): every ray then starts above it (c~(0) = n_z),
/// and every azimuth has mass. CosineWeighted uses ProjectedSolidAngleSampler otherwise.

#include <cmath>

#include "../config.hpp"
#include "../sample.hpp"
#include "glm.hpp"
#include "linear_density.hpp"
#include "map_access.hpp"
#include "math.hpp"
#include "pairs.hpp"
#include "quadrant.hpp"

namespace apse {
namespace detail {

/// The cosine model along one ray (file comment), in y = r − lo on [0, end]: its value c~ and its
/// mass G(y) = ∫ 2 r c~ dr from lo = y^2 (g2 + y (g3 + g4 y)), every coefficient free of
/// cancellation where it matters.
template <class T> struct CosineRay {
    enum Kind : int { below, whole, to_horizon, from_horizon };
    Kind kind;
    T nz, b, h;    ///< whole: c~ = nz (1 − h y^2) + b y
    T beta, rh;    ///< to_horizon: c~ = beta (rh − y)(1 + h rh y); from_horizon: beta y (p + q y)
    T p, q;        ///< from_horizon: 1 + h rh^2, h rh
    T lo, end;     ///< the range of r above the horizon: [lo, lo + end]
    T g2, g3, g4;  ///< G's coefficients
    T mass;        ///< G(end) = ∫ c~ du2 over the ray

    /// c~ at y (>= 0 inside [0, end]).
    APSE_FUNC T value(T y) const noexcept {
        if (kind == whole) return nz + y * (b - nz * h * y);
        if (kind == to_horizon) return beta * (rh - y) * (T(1) + h * rh * y);
        return beta * y * (p + q * y);
    }

    /// G(y).
    APSE_FUNC T cdf(T y) const noexcept { return y * y * (g2 + y * (g3 + g4 * y)); }
};

/// The model of the ray whose cosine is nz (1 − h u2) + s sin theta, with b = s sin theta_max,
/// h = 1 − C and ipc = 1/(1 + C) (C = cos theta_max >= 0): the horizon's crossing, if any, from
/// tan theta_h = −nz/s, as r_h^2 = (1 − cos theta_h)/h = nz^2 / (K (K + |b|) ipc)... written as
/// r_h = |nz| / beta with beta = sqrt(K (K + |b|) ipc), K = sqrt(nz^2 sin^2 theta_max + b^2).
template <class T> APSE_HOT_INLINE CosineRay<T> cosine_ray(T nz, T b, T h, T c, T ipc) noexcept {
    CosineRay<T> r{};
    r.nz = nz;
    r.b = b;
    r.h = h;
    const T rim = nz * c + b;  // the cosine at the rim
    if (nz > T(0) && rim >= T(0)) {
        r.kind = CosineRay<T>::whole;
        r.end = T(1);
        r.g2 = nz;
        r.g3 = T(2.0 / 3.0) * b;
        r.g4 = T(-0.5) * nz * h;
    } else if (nz > T(0) || rim > T(0)) {
        const T k = std::sqrt(nz * nz * (h * (T(1) + c)) + b * b);
        r.beta = std::sqrt(k * (k + std::fabs(b)) * ipc);
        r.rh = clamp(std::fabs(nz) / r.beta, T(0), T(1));
        if (nz > T(0)) {
            r.kind = CosineRay<T>::to_horizon;
            r.end = r.rh;
            r.g2 = nz;
            r.g3 = T(2.0 / 3.0) * (nz * h * r.rh - r.beta);
            r.g4 = T(-0.5) * nz * h;
        } else {
            r.kind = CosineRay<T>::from_horizon;
            r.lo = r.rh;
            r.end = T(1) - r.rh;
            r.p = T(1) + h * r.rh * r.rh;
            r.q = h * r.rh;
            r.g2 = r.beta * r.rh * r.p;
            r.g3 = T(2.0 / 3.0) * r.beta * (r.p + r.rh * r.q);
            r.g4 = T(0.5) * r.beta * r.q;
        }
    } else {
        r.kind = CosineRay<T>::below;
        return r;
    }
    r.mass = r.cdf(r.end);
    return r;
}

/// The y in [0, ray.end] with G(y) = u mass (u in [0, 1]): Halley's steps with one division,
/// safeguarded by the bracket, from end sqrt(u) (exact when G ∝ y^2); measured over the
/// benchmark's lights: 2.2 steps per sample in double.
template <class T> APSE_HOT_INLINE T cosine_ray_root(const CosineRay<T>& ray, T u) noexcept {
    const T target = u * ray.mass, tolerance = T(2) * epsilon<T>() * ray.mass;
    T lo = T(0), hi = ray.end;
    T y = ray.end * std::sqrt(u);
    for (int i = 0; i < 16; ++i) {
        const T f = ray.cdf(y) - target;
        if (!(std::fabs(f) > tolerance)) break;
        if (f < T(0)) lo = y;
        else hi = y;
        const T d1 = y * (T(2) * ray.g2 + y * (T(3) * ray.g3 + T(4) * ray.g4 * y));
        const T d2 = T(2) * ray.g2 + y * (T(6) * ray.g3 + T(12) * ray.g4 * y);
        const T den = T(2) * d1 * d1 - f * d2;
        const T next = den > T(0) ? y - T(2) * f * d1 / den : y - f / d1;
        if (next == y || !(hi - lo > T(4) * epsilon<T>() * hi)) break;
        y = (next > lo && next < hi) ? next : T(0.5) * (lo + hi);
    }
    return y;
}

/// The cosine-weighted warp of a TabulatedMap's square (file comment). Built for one map and one
/// normal (in the ellipse's frame, any positive length, n_z > 0); the map is passed to every
/// call (the warp holds only its own state). Trivially copyable.
template <class T, int Nodes> class TabulatedCosineWarp {
    static_assert(Nodes >= 4 && Nodes % 4 == 0, "the nodes fold onto the four quadrants");

public:
    using vec2 = glm::vec<2, T>;
    using vec3 = glm::vec<3, T>;

    TabulatedCosineWarp() = default;

    /// The warp of `map` (valid) for the local normal `nl` (finite, n_z > 0).
    template <class Map> APSE_FUNC TabulatedCosineWarp(const Map& map, const vec3& nl) noexcept : n_(nl) {
        const SphericalEllipse<T>& e = map.ellipse();
        a_ = e.sin_alpha;
        b_ = e.sin_beta;
        constexpr int m = Nodes / 4;
        // one quadrant of node rays, at the Lambert anomalies j/m of a quarter turn:
        // sin theta_max (cos phi, sin phi) = (ax, by), C = cos theta_max, ipc = 1/(1 + C), h = 1 − C,
        // and the ray's quadrant-area fraction; the axes (j = 0: alpha, j = m: beta) in closed form
        T ax[m + 1], by[m + 1], h[m + 1], c[m + 1], ipc[m + 1], frac[m + 1];
        ax[0] = a_;
        by[0] = T(0);
        c[0] = e.cos_alpha;
        frac[0] = T(0);
        ax[m] = T(0);
        by[m] = b_;
        c[m] = e.cos_beta;
        frac[m] = T(1);
        div2(T(1), T(1) + c[0], T(1), T(1) + c[m], ipc[0], ipc[m]);
        h[0] = a_ * a_ * ipc[0];
        h[m] = b_ * b_ * ipc[m];
        for (int j = 1; j < m; ++j) {
            const auto ray = MapAccess::ray_at(map, QuadrantFold<T>{T(1), T(1), T(0)}, T(j) / T(m), T(0));
            const T inv_n = (ray.n + ray.nc) * ray.g;
            ax[j] = a_ * ray.px * inv_n;
            by[j] = b_ * ray.py * inv_n;
            c[j] = ray.c;
            ipc[j] = ray.n * ray.n * ray.g;
            h[j] = (ax[j] * ax[j] + by[j] * by[j]) * ipc[j];
            frac[j] = MapAccess::lambda_fraction(map, T(j) / T(m));
        }
        // the nodes over the turn: the first quadrant's ray j reflected by the signs of (x, y) =
        // (+, +), (−, +), (−, −), (+, −) in the quadrants 0 to 3, the odd ones in reverse order
        // (fold_quadrant): nodes j, 2m − j, 2m + j, 4m − j
        T top = T(0);
        for (int j = 0; j <= m; ++j) {
            const T px = n_.x * ax[j], py = n_.y * by[j];
            if (j < m) {
                t_[j] = T(0.25) * frac[j];
                t_[2 * m + j] = T(0.25) * (T(2) + frac[j]);
                node_[j] = cosine_ray(n_.z, px + py, h[j], c[j], ipc[j]).mass;
                node_[2 * m + j] = cosine_ray(n_.z, -px - py, h[j], c[j], ipc[j]).mass;
                top = max_of(top, max_of(node_[j], node_[2 * m + j]));
            }
            if (j > 0) {
                t_[2 * m - j] = T(0.25) * (T(2) - frac[j]);
                t_[4 * m - j] = T(0.25) * (T(4) - frac[j]);
                node_[2 * m - j] = cosine_ray(n_.z, py - px, h[j], c[j], ipc[j]).mass;
                node_[4 * m - j] = cosine_ray(n_.z, px - py, h[j], c[j], ipc[j]).mass;
                top = max_of(top, max_of(node_[2 * m - j], node_[4 * m - j]));
            }
        }
        t_[Nodes] = T(1);
        node_[Nodes] = node_[0];
        // every node's mass is > 0 (n_z > 0); a floor of 1e-3 of the largest keeps a mass that
        // underflowed (a horizon within ~1e-13 of the centre, in float) positive
        const T floor = T(1e-3) * top;
        node_[0] += floor;
        cdf_[0] = T(0);
        for (int k = 0; k < Nodes; ++k) {
            node_[k + 1] += floor;
            width_[k] = t_[k + 1] - t_[k];
            cdf_[k + 1] = cdf_[k] + width_[k] * T(0.5) * (node_[k] + node_[k + 1]);
        }
        inv_total_ = T(1) / cdf_[Nodes];
    }

    /// The sample of (turns, u2) in [0, 1]^2 (the warp's input: u1 of TabulatedMap, or the
    /// concentric map's turns and radius^2).
    template <class Map> APSE_HOT_INLINE DirectionSample<T> sample(const Map& map, T turns, T u2) const noexcept {
        // the azimuth: the piecewise-linear marginal's interval, then the root in it
        const T target = turns * cdf_[Nodes];
        const int k = count_below(cdf_, target);
        const T x = width_[k] > T(0) ? (target - cdf_[k]) / width_[k] : T(0);
        const T frac = linear_density_root(node_[k], node_[k + 1], x);
        const T m = node_[k] + frac * (node_[k + 1] - node_[k]);
        int steps = 0;
        const auto ray = MapAccess::ray_folded(map, fold_quadrant(t_[k] + width_[k] * frac), steps);
        // the cosine along it (ray_at: (a px, b py) (n + nc) g = sin theta_max (cos phi, sin phi))
        const T ax = ray.fold.sign_x * a_ * ray.px, by = ray.fold.sign_y * b_ * ray.py;
        const T ipc = ray.n * ray.n * ray.g;
        const CosineRay<T> cr = cosine_ray(n_.z, (n_.x * ax + n_.y * by) * ((ray.n + ray.nc) * ray.g),
                                           (ax * ax + by * by) * ray.g, ray.c, ipc);
        const T y = cosine_ray_root(cr, u2);
        const T r = cr.lo + y;
        DirectionSample<T> s = MapAccess::ray_sample(map, ray, r * r);
        const T v = cr.value(y);
        const T p = s.pdf * (m * inv_total_) * (v / cr.mass);
        s.pdf = v > T(0) && is_finite(p) ? p : T(0);
        return s;
    }

    /// The warp's density at the unit local direction l (inside the ellipse: the caller checks),
    /// times the map's: the pdf sample() reports there. 0 below the horizon.
    template <class Map> APSE_FUNC T pdf(const Map& map, const vec3& l) const noexcept {
        T m, y;
        CosineRay<T> cr;
        const auto lp = locate(map, l, m, y, cr);
        if (cr.kind == CosineRay<T>::below || !(y >= T(0)) || !(y <= cr.end)) return T(0);
        const T v = cr.value(y);
        const T p = lp.pdf * (m * inv_total_) * (v / cr.mass);
        return v > T(0) && is_finite(p) ? p : T(0);
    }

    /// The (turns, u2) whose sample is the unit local direction l (clamped formulas outside).
    template <class Map> APSE_FUNC vec2 invert(const Map& map, const vec3& l) const noexcept {
        T m, y;
        CosineRay<T> cr;
        const auto lp = locate(map, l, m, y, cr);
        int k;
        T frac;
        interval(lp.u.x, k, frac);
        const T u1 = (cdf_[k] + width_[k] * linear_density_mass(node_[k], node_[k + 1], frac)) * inv_total_;
        const T u2 = cr.kind == CosineRay<T>::below ? T(0) : cr.cdf(clamp(y, T(0), cr.end)) / cr.mass;
        return vec2(clamp(u1, T(0), T(1)), clamp(u2, T(0), T(1)));
    }

private:
    /// The number of a[1 .. Nodes − 1] at or below x: the interval of x among the nodes
    /// (counted without branches: x is random).
    static APSE_HOT_INLINE int count_below(const T (&a)[Nodes + 1], T x) noexcept {
        int k = 0;
        for (int i = 1; i < Nodes; ++i) k += a[i] <= x ? 1 : 0;
        return k;
    }

    /// The node interval k of u1 and the position in it.
    APSE_FUNC void interval(T u1, int& k, T& frac) const noexcept {
        k = count_below(t_, u1);
        frac = width_[k] > T(0) ? clamp((u1 - t_[k]) / width_[k], T(0), T(1)) : T(0);
    }

    /// The map's coordinates of l, the marginal m there, the ray's model and y = r − lo.
    template <class Map> APSE_FUNC auto locate(const Map& map, const vec3& l, T& m, T& y, CosineRay<T>& cr) const noexcept {
        const auto lp = MapAccess::local_point(map, l);
        int k;
        T frac;
        interval(lp.u.x, k, frac);
        m = node_[k] + frac * (node_[k + 1] - node_[k]);
        const T ax = std::copysign(a_ * lp.ct, l.x), by = std::copysign(b_ * lp.st, l.y);
        const T ipc = T(1) / (T(1) + lp.c);
        cr = cosine_ray(n_.z, n_.x * ax + n_.y * by, (ax * ax + by * by) * ipc, lp.c, ipc);
        y = std::sqrt(lp.u.y) - cr.lo;
        return lp;
    }

    vec3 n_{};               ///< the normal in the ellipse's frame (n_z > 0)
    T a_{}, b_{};            ///< sin alpha, sin beta
    T t_[Nodes + 1]{};       ///< the nodes' u1
    T width_[Nodes]{};       ///< the intervals' widths
    T node_[Nodes + 1]{};    ///< the marginal at the nodes (> 0)
    T cdf_[Nodes + 1]{};     ///< its integral from 0 to node k
    T inv_total_{};          ///< 1 / cdf_[Nodes]
};

}  // namespace detail
}  // namespace apse
