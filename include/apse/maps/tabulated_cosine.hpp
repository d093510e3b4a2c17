// apse — area-preserving parameterizations for spherical ellipses.
// SPDX-License-Identifier: MIT
#pragma once

/// @file maps/tabulated_cosine.hpp
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
/// Lambert anomaly) through M there (plus a floor of 1e-3 of the largest, build()). The
/// density reported is the map's density times the warp's,
///     pdf(ω) = pdf_map(ω) m(u1) / (∫ m) · c~(r) / M(u1),
/// exactly the density of the samples; the model decides the variance only.
///
/// The centre must be above the horizon (n_z > 0): every ray then starts above it (c~(0) = n_z),
/// and every azimuth has mass. CosineWeighted uses ProjectedSolidAngleSampler otherwise.

#include <cmath>

#include "../config.hpp"
#include "../sample.hpp"
#include "../spherical_ellipse.hpp"
#include "../detail/glm.hpp"
#include "../detail/math.hpp"
#include "../detail/polar.hpp"
#include "tabulated_ld_radial.hpp"

namespace apse {
namespace detail {

/// The cosine model along one ray whose centre is above the horizon (file comment), as a function
/// of r = sqrt(u2) on [0, end]: its value c~ and its mass G(r) = ∫ 2 r c~ dr from 0
/// = r^2 (g2 + r (g3 + g4 r)).
template <class T> struct CosineRay {
    T nz, b, h;    ///< the whole ray above the horizon: c~ = nz (1 − h r^2) + b r
    T beta, rh;    ///< cut at r_h: c~ = beta (rh − r)(1 + h rh r) (0 < rh <= 1)
    bool cut;      ///< whether the horizon cuts the ray
    T end;         ///< 1 or rh
    T g2, g3, g4;  ///< G's coefficients
    T mass;        ///< G(end) = ∫ c~ du2 over the part of the ray above the horizon

    /// c~ at r in [0, end] (> 0 there but at a cut ray's end).
    APSE_FUNC T value(T r) const noexcept {
        return cut ? beta * (rh - r) * (T(1) + h * rh * r) : nz + r * (b - nz * h * r);
    }

    /// G(r).
    APSE_FUNC T cdf(T r) const noexcept { return r * r * (g2 + r * (g3 + g4 * r)); }

    /// dG/dr and d2G/dr2 at r.
    APSE_FUNC T cdf_slope(T r) const noexcept { return r * (T(2) * g2 + r * (T(3) * g3 + T(4) * g4 * r)); }
    APSE_FUNC T cdf_curvature(T r) const noexcept { return T(2) * g2 + r * (T(6) * g3 + T(12) * g4 * r); }
};

/// The model of the ray whose cosine is nz (1 − h u2) + s sin theta (nz > 0), with b = s sin theta_max,
/// h = 1 − C and ipc = 1/(1 + C) (C = cos theta_max >= 0). The horizon cuts the ray where the
/// cosine at the rim, nz C + b, is negative, at tan theta_h = nz/(−s):
/// r_h^2 = (1 − cos theta_h)/h = nz^2 / (K (K + |b|) ipc), K = sqrt(nz^2 sin^2 theta_max + b^2),
/// written r_h = nz / beta with beta = sqrt(K (K + |b|) ipc) (no cancellation).
template <class T> APSE_HOT_INLINE CosineRay<T> cosine_ray(T nz, T b, T h, T c, T ipc) noexcept {
    CosineRay<T> r;
    r.nz = nz;
    r.b = b;
    r.h = h;
    r.g2 = nz;
    r.g4 = T(-0.5) * nz * h;
    r.cut = nz * c + b < T(0);
    if (r.cut) {
        const T k = std::sqrt(nz * nz * (h * (T(1) + c)) + b * b);
        r.beta = std::sqrt(k * (k - b) * ipc);  // b < 0
        r.rh = min_of(nz / r.beta, T(1));
        r.end = r.rh;
        r.g3 = T(2.0 / 3.0) * (nz * h * r.rh - r.beta);
    } else {
        r.beta = T(0);
        r.rh = T(1);
        r.end = T(1);
        r.g3 = T(2.0 / 3.0) * b;
    }
    r.mass = r.cdf(r.end);
    return r;
}

/// One of Halley's steps towards G(r) = target, with one division (Newton's where Halley's
/// denominator is not positive), kept inside [0, end].
template <class T> APSE_HOT_INLINE T cosine_ray_step(const CosineRay<T>& ray, T r, T f) noexcept {
    const T d1 = ray.cdf_slope(r), d2 = ray.cdf_curvature(r);
    const T den = T(2) * d1 * d1 - f * d2;
    const T next = den > T(0) ? r - T(2) * f * d1 / den : r - f / d1;
    return clamp_non_nan(next, T(0), ray.end);
}

/// The r in [0, ray.end] with G(r) = u mass (u in [0, 1]; root_u = sqrt(u)): two of Halley's
/// steps from end sqrt(u) (exact when G ∝ r^2), which land within the tolerance (2 eps of the
/// mass) for 76 % of the samples in double and 96 % in float (measured over the benchmark's
/// lights), then steps safeguarded by the bracket (at most 32) until they do.
template <class T> APSE_HOT_INLINE T cosine_ray_root(const CosineRay<T>& ray, T u, T root_u) noexcept {
    const T target = u * ray.mass, tolerance = T(2) * detail::epsilon<T>() * ray.mass;
    T r = ray.end * root_u;
    r = cosine_ray_step(ray, r, ray.cdf(r) - target);
    r = cosine_ray_step(ray, r, ray.cdf(r) - target);
    T f = ray.cdf(r) - target;
    if (!(std::fabs(f) > tolerance)) return r;
    T lo = T(0), hi = ray.end;
    for (int i = 0; i < 32; ++i) {
        if (f < T(0)) lo = r;
        else hi = r;
        const T next = cosine_ray_step(ray, r, f);
        const T mid = T(0.5) * (lo + hi);
        r = (next > lo && next < hi) ? next : mid;
        f = ray.cdf(r) - target;
        if (!(std::fabs(f) > tolerance) || !(hi - lo > T(4) * detail::epsilon<T>() * hi)) break;
    }
    return r;
}

/// The cosine-weighted warp of a TabulatedMap's square (file comment). Built for one map and one
/// normal (in the ellipse's frame, any positive length, n_z > 0); the map is passed to every
/// call (the warp holds only its own state). Trivially copyable.
template <class T, int Nodes> class TabulatedCosineWarp {
    static_assert(Nodes >= 4 && Nodes % 4 == 0, "the nodes fold onto the four quadrants");

public:
    using vec2 = glm::vec<2, T>;
    using vec3 = glm::vec<3, T>;

    /// Builds, in place, the warp of `map` (valid) for the local normal `nl` (finite, n_z > 0).
    /// (A member function rather than a constructor: CosineWeighted builds the warp inside its
    /// union, where a constructed temporary would be copied.)
    template <class Map> APSE_FUNC void build(const Map& map, const vec3& nl) noexcept {
        n_ = nl;
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
            const auto ray = map.ray_at(QuadrantFold<T>{T(1), T(1), T(0)}, T(j) / T(m), T(0));
            const T inv_n = (ray.n + ray.nc) * ray.g;
            ax[j] = a_ * ray.px * inv_n;
            by[j] = b_ * ray.py * inv_n;
            c[j] = ray.c;
            ipc[j] = ray.n * ray.n * ray.g;
            h[j] = (ax[j] * ax[j] + by[j] * by[j]) * ipc[j];
            frac[j] = map.lambda_fraction(T(j) / T(m));
        }
        // the intervals' widths in the first quadrant (the others mirror them), and their inverses
        T w[m], iw[m];
        for (int j = 0; j < m; ++j) {
            w[j] = T(0.25) * (frac[j + 1] - frac[j]);
            iw[j] = w[j] > T(0) ? T(1) / w[j] : T(0);
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
            const int i = k % m, j = ((k / m) & 1) ? m - 1 - i : i;  // the interval's first-quadrant twin
            node_[k + 1] += floor;
            slope_[k] = (node_[k + 1] - node_[k]) * iw[j];
            cdf_[k + 1] = cdf_[k] + w[j] * T(0.5) * (node_[k] + node_[k + 1]);
        }
        inv_total_ = T(1) / cdf_[Nodes];
    }

    /// The sample of (turns, u2) in [0, 1]^2 (the warp's input: u1 of TabulatedMap, or the
    /// concentric map's turns and radius^2), root_u2 = sqrt(u2).
    template <class Map>
    APSE_HOT_INLINE DirectionSample<T> sample(const Map& map, T turns, T u2, T root_u2) const noexcept {
        // the azimuth: the piecewise-linear marginal's interval, then the root in it:
        // d (node_k + slope_k d/2) = target − cdf_k, without cancellation
        const T target = turns * cdf_[Nodes];
        const int k = interval_of(cdf_, target);
        const T x = max_of(target - cdf_[k], T(0));
        const T den = node_[k] + std::sqrt(max_of(node_[k] * node_[k] + T(2) * slope_[k] * x, T(0)));
        const T d = den > T(0) ? T(2) * x / den : T(0);
        const T m = node_[k] + slope_[k] * d;
        int steps = 0;
        const auto ray = map.ray_folded(fold_quadrant(t_[k] + d), steps);
        // the cosine along it (ray_at: (a px, b py) (n + nc) g = sin theta_max (cos phi, sin phi))
        const T ax = ray.fold.sign_x * a_ * ray.px, by = ray.fold.sign_y * b_ * ray.py;
        const CosineRay<T> cr = cosine_ray(n_.z, (n_.x * ax + n_.y * by) * ((ray.n + ray.nc) * ray.g),
                                           (ax * ax + by * by) * ray.g, ray.c, ray.n * ray.n * ray.g);
        const T r = cosine_ray_root(cr, u2, root_u2);
        DirectionSample<T> s = map.ray_sample(ray, r * r);
        const T v = cr.value(r);
        const T p = s.pdf * (m * inv_total_) * v / cr.mass;
        s.pdf = v > T(0) && is_finite(p) ? p : T(0);
        return s;
    }

    /// The warp's density at the unit local direction l (inside the ellipse: the caller checks),
    /// times the map's: the pdf sample() reports there. 0 below the horizon.
    template <class Map> APSE_FUNC T pdf(const Map& map, const vec3& l) const noexcept {
        T m, r;
        CosineRay<T> cr;
        const auto lp = locate(map, l, m, r, cr);
        if (!(r <= cr.end)) return T(0);
        const T v = cr.value(r);
        const T p = lp.pdf * (m * inv_total_) * v / cr.mass;
        return v > T(0) && is_finite(p) ? p : T(0);
    }

    /// The (turns, u2) whose sample is the unit local direction l (clamped formulas outside).
    template <class Map> APSE_FUNC vec2 invert(const Map& map, const vec3& l) const noexcept {
        T m, r;
        CosineRay<T> cr;
        const auto lp = locate(map, l, m, r, cr);
        const int k = interval_of(t_, lp.u.x);
        const T d = clamp(lp.u.x - t_[k], T(0), t_[k + 1] - t_[k]);
        const T u1 = (cdf_[k] + d * (node_[k] + T(0.5) * slope_[k] * d)) * inv_total_;
        const T u2 = cr.cdf(min_of(r, cr.end)) / cr.mass;
        return vec2(clamp(u1, T(0), T(1)), clamp(u2, T(0), T(1)));
    }

private:
    /// The k in [0, Nodes − 1] with a[k] <= x < a[k + 1] (a increasing; x below a[1]: 0, at or
    /// above a[Nodes − 1]: Nodes − 1): a binary search without branches (x is random).
    static APSE_HOT_INLINE int interval_of(const T (&a)[Nodes + 1], T x) noexcept {
        int k = 0;
        for (int i = levels() - 1; i >= 0; --i) {
            const int next = k + (1 << i);
            k = (next < Nodes && a[next] <= x) ? next : k;
        }
        return k;
    }
    /// The binary search's steps: the least L with 2^L >= Nodes.
    static constexpr APSE_FUNC int levels() noexcept {
        int l = 0;
        while ((1 << l) < Nodes) ++l;
        return l;
    }

    /// The map's coordinates of l, the marginal m there, the ray's model and r = sqrt(u2).
    template <class Map> APSE_FUNC auto locate(const Map& map, const vec3& l, T& m, T& r, CosineRay<T>& cr) const noexcept {
        const auto lp = map.local_point(l);
        const int k = interval_of(t_, lp.u.x);
        m = node_[k] + slope_[k] * clamp(lp.u.x - t_[k], T(0), t_[k + 1] - t_[k]);
        const T ax = std::copysign(a_ * lp.ct, l.x), by = std::copysign(b_ * lp.st, l.y);
        const T ipc = T(1) / (T(1) + lp.c);
        cr = cosine_ray(n_.z, n_.x * ax + n_.y * by, (ax * ax + by * by) * ipc, lp.c, ipc);
        r = std::sqrt(lp.u.y);
        return lp;
    }

    vec3 n_;               ///< the normal in the ellipse's frame (n_z > 0)
    T a_, b_;              ///< sin alpha, sin beta
    T t_[Nodes + 1];       ///< the nodes' u1
    T node_[Nodes + 1];    ///< the marginal at the nodes (> 0)
    T slope_[Nodes];       ///< its slope in each interval
    T cdf_[Nodes + 1];     ///< its integral from 0 to node k
    T inv_total_;          ///< 1 / cdf_[Nodes]
};

}  // namespace detail
}  // namespace apse
