// apse — area-preserving parameterizations for spherical ellipses.
// SPDX-License-Identifier: MIT
#pragma once

/// @file maps/tabulated_ld_radial.hpp
/// `TabulatedLdRadialMap<T>`: the recommended map — the LD-radial composition (detail::LdComposition,
/// detail/polar.hpp) over the tabulated radial map `TabulatedMap<T>` (namespace detail here;
/// apse::TabulatedMap from comparison.hpp): no elliptic integral per shading point, the exact
/// density it draws from reported. Both are the paper's tabulated variants (authors' code:
/// `concentrictab` / `polartab`, docs/math.md §6), redone so that they are **unbiased**: the pdf
/// they report is exactly the density they draw from (the authors' version rejects samples outside
/// the ellipse, counts them as zero and reports 1/Omega: biased, docs/math.md §6, §11.4).
///
/// How it works (*derived*, see docs/tabulated.md). In one quadrant, parametrise the boundary by
/// the orthographic eccentric anomaly tau (tan phi = (b/a) tan tau, a = sin alpha, b = sin beta,
/// maps/cumulative_area.hpp), and tau by a "Lambert anomaly" lambda in [0, pi/2]:
/// tan tau = kappa tan lambda, kappa = cos(alpha/2)/cos(beta/2). The exact area density in lambda,
///     dOmega_r/dlambda = a b kappa / ((1 + C(tau)) (cos^2 lambda + kappa^2 sin^2 lambda)),
/// C(tau) = cos theta_max = sqrt(cos^2 alpha cos^2 tau + cos^2 beta sin^2 tau), is constant for
/// caps and for small ellipses and varies smoothly and by little otherwise. A table holds its
/// normalised CDF at N equally spaced lambda for a grid of shapes (1 − sqrt(cos alpha), beta/alpha); a map
/// blends the four rows around its own shape bilinearly (a convex combination of CDFs is a CDF
/// and its density is the same combination of densities), draws lambda from the resulting
/// piecewise-linear CDF (a walk from the uniform guess: O(1) expected, O(N) worst), and then
/// theta exactly as the radial map (cos theta uniform between cos theta_max(phi) and 1). Every
/// sample is inside the ellipse by construction; one point of the square gives one direction (no
/// rejection). The density drawn from, in solid angle, is
///     pdf(w) = p_lambda(lambda) / (4 (1 − cos theta_max) dphi/dlambda)
///            = p_lambda(lambda) (1 + C) kappa / (4 a b (kappa^2 cos^2 tau + sin^2 tau))
///            = p_lambda(lambda) (1 + C) |(cos lambda, kappa sin lambda)|^2 / (4 a b kappa),
/// with p_lambda = (Delta CDF of the bin)/(bin width): no solid angle, no elliptic integral and
/// no table accuracy enters the unbiasedness — the table's quality only sets how close pdf is to
/// 1/Omega (measured max |pdf Omega − 1| in docs/tabulated.md: 0.44 % for the default table).
/// The table itself (building it, viewing it, the shared default): maps/tabulation_table.hpp.

#include <cmath>

#include "../config.hpp"
#include "../sample.hpp"
#include "../spherical_ellipse.hpp"
#include "../detail/glm.hpp"
#include "../detail/math.hpp"
#include "../detail/polar.hpp"
#include "cap.hpp"
#include "tabulation_table.hpp"

namespace apse {
namespace detail {

/// Tabulated radial map (docs/math.md §4 + §6, unbiased; file comment): u1 picks the quadrant and the
/// Lambert anomaly from the blended table CDF, u2 the polar angle exactly as RadialMap. Not
/// area-preserving (nearly: pdf Omega within the table's error of 1), but the reported pdf is
/// exactly its density. Per shading point: no elliptic integral, no Omega, no library call (the
/// table coordinate beta/alpha by polynomials); per sample: a short table walk (rarely more than
/// the first guess) and a polynomial sin/cos. On a spherical cap (SphericalEllipse::is_cap())
/// the azimuthal CDF is exactly linear, so sample(), pdf() and invert() use RadialMap's closed
/// form instead of the table (docs/math.md §6, Caps): exactly uniform, pdf exactly
/// 1/(2 pi (1 − cos alpha)). Holds a pointer into the table
/// (the table must outlive the map). Trivially copyable.
template <class T> class TabulatedMap {
    static_assert(detail::is_real_type<T>(), "apse: TabulatedMap<T>: T must be float or double");

public:
    using vec2 = glm::vec<2, T>;  ///< a point of the unit square
    using vec3 = glm::vec<3, T>;  ///< a 3-D vector (direction, point or normal)
    /// What SphereLight holds for this map: the same samples on a cap, without the table walk
    /// (maps/cap.hpp).
    using CapSampler = detail::CapMap<T, false, true>;

    /// Builds the map for `ellipse` with the table `table` (set-up: the ellipse's semi-axis
    /// constants, kappa, the four blended rows and their weights; a paired square root and a few
    /// divisions).
    /// An empty ellipse or an invalid view gives an empty map (every sample has pdf 0).
    APSE_HOT_INLINE TabulatedMap(const SphericalEllipse<T>& ellipse, const TabulationView& table) noexcept
        : ellipse_(ellipse), axes_(detail::EllipseAxes<T>::make(ellipse)), bins_(table.bins) {
        for (int r = 0; r < 4; ++r) { rows_[r] = table.cdf; weights_[r] = T(0); }
        valid_ = !ellipse.empty() && detail::table_usable(table) && ellipse.tan_alpha > T(0);
        // a cap's azimuthal CDF is exactly linear: sample() draws it exactly, density 1/Omega
        cap_ = ellipse.is_cap();
        cap_inv_omega_ = cap_ ? detail::cap_density(ellipse) : T(0);
        if (cap_ && !(cap_inv_omega_ > T(0))) valid_ = false;  // no finite density
        // kappa^2 = (1 + cos alpha)/(1 + cos beta) and its inverse, paired (1 for a cap); then
        // kappa and sqrt(cos alpha), paired
        T inv_kappa2 = T(1), sqrt_ca;
        kappa2_ = T(1);
        if (!cap_) detail::div2(T(1) + axes_.ca, T(1) + axes_.cb, T(1) + axes_.cb, T(1) + axes_.ca, kappa2_, inv_kappa2);
        detail::sqrt2(kappa2_, axes_.ca, kappa_, sqrt_ca);
        const T nb = T(bins_ > 0 ? bins_ : 1);
        detail::div2(detail::half_pi_v<T>, nb, T(1), nb, bin_width_, inv_bins_);
        pdf_scale_ = T(0);
        ba_ = T(0);
        if (!valid_) return;
        // pdf = (dF N) (1 + C) n^2 / (2 pi a b kappa), n = |(cos lambda, kappa sin lambda)|
        // (density()): the constant part
        // 1/(2 pi a b kappa) = (1/(2 pi)) (1/a) (1/b) (kappa / kappa^2), multiplied in this order so
        // that it neither underflows nor overflows for the smallest ellipses (it is ~1/Omega; dF N
        // is ~1; 1/kappa is in [1, sqrt 2]). 1/a and 1/b do not wait for kappa.
        T inv_a, inv_b;
        detail::div2(T(1), axes_.a, T(1), axes_.b, inv_a, inv_b);
        pdf_scale_ = (((T(1) / detail::two_pi_v<T>) * inv_a) * inv_b) * (kappa_ * inv_kappa2);
        ba_ = axes_.b * inv_a;
        if (!detail::is_finite(pdf_scale_) || !(pdf_scale_ > T(0))) { valid_ = false; pdf_scale_ = T(0); return; }
        // Table coordinates: x = 1 − sqrt(cos alpha), y = beta/alpha (the latter by polynomials,
        // within 1e-7: it only chooses the rows blended, and any blend is exact for the sampler).
        // (a valid ellipse's values: no NaN, so a max and a min clamp them, without branches)
        const T fx = detail::clamp_non_nan(T(1) - sqrt_ca, T(0), T(1)) * T(table.alpha_nodes - 1);
        const T ratio = cap_ ? T(1) : detail::arc_ratio(axes_.a, axes_.ca, axes_.b, axes_.cb);
        const T fy = detail::clamp_non_nan(ratio, T(0), T(1)) * T(table.ratio_nodes - 1);
        int i = int(fx), j = int(fy);
        if (i > table.alpha_nodes - 2) i = table.alpha_nodes - 2;
        if (j > table.ratio_nodes - 2) j = table.ratio_nodes - 2;
        const T wx = detail::clamp_non_nan(fx - T(i), T(0), T(1)), wy = detail::clamp_non_nan(fy - T(j), T(0), T(1));
        const int stride = bins_ + 1;
        rows_[0] = table.cdf + (i * table.ratio_nodes + j) * stride;
        rows_[1] = rows_[0] + stride;                          // (i, j + 1)
        rows_[2] = rows_[0] + table.ratio_nodes * stride;      // (i + 1, j)
        rows_[3] = rows_[2] + stride;                          // (i + 1, j + 1)
        // The weights carry the factor N: the blended CDF runs from 0 to N, so a bin's mass is
        // already the density's factor N dF (density()); a separate factor N, multiplied into
        // the pdf's constant by -ffast-math's reassociation, would overflow for the smallest
        // ellipses (1/Omega is then within a factor N of the largest finite number).
        const T n = T(bins_);
        weights_[0] = (T(1) - wx) * (T(1) - wy) * n;
        weights_[1] = (T(1) - wx) * wy * n;
        weights_[2] = wx * (T(1) - wy) * n;
        weights_[3] = wx * wy * n;
    }

    /// The ellipse this map samples.
    APSE_FUNC const SphericalEllipse<T>& ellipse() const noexcept { return ellipse_; }

    /// True if the map cannot sample (empty ellipse or invalid table view): pdf 0 everywhere.
    APSE_FUNC bool empty() const noexcept { return !valid_; }

    /// Direction for the point u of the unit square (file comment): world-space unit vector
    /// inside the ellipse, with its exact density in solid angle (within the table's error of
    /// 1/Omega; never an estimate). u is clamped into [0, 1]^2; a NaN coordinate, an empty
    /// ellipse or an invalid table gives pdf 0 (and the centre direction). The table-walk steps:
    /// apse::sample_with_diagnostics.
    APSE_FUNC DirectionSample<T> sample(const vec2& u) const noexcept {
        int iterations = 0;
        return sample_counted(u, iterations);
    }

    /// The point of the unit square that sample() maps to the world-space direction `d` (any
    /// non-zero length): exact inverse inside the ellipse up to rounding (~1e-6 float, ~1e-14
    /// double; u1 is ambiguous on the +x seam (0 or 1) and undefined at the centre). A direction
    /// outside gives the point whose image is the boundary point at the same azimuth (u2 = 1);
    /// a zero/NaN/infinite direction or an empty map gives (0, 0).
    APSE_FUNC vec2 invert(const vec3& d) const noexcept {
        if (!valid_) return vec2(T(0));
        bool ok = true;
        const vec3 l = detail::normalize_direction(ellipse_.to_local(d), ok);
        return ok ? local_coordinates(l) : vec2(T(0));
    }

    /// Density of sample() at the world-space direction `d`, in solid angle (the same formula
    /// as sample() reports, from the direction's azimuth): > 0 inside the ellipse (boundary
    /// included), 0 outside, for an empty map, or a zero/NaN direction.
    APSE_FUNC T pdf(const vec3& d) const noexcept {
        if (!valid_ || !ellipse_.contains(d)) return T(0);
        if (cap_) return cap_inv_omega_;
        const vec3 l = ellipse_.to_local(d);
        const Azimuth az = azimuth_of(std::fabs(l.x), std::fabs(l.y));
        const T lo = cdf_at(az.bin), hi = cdf_at(az.bin + 1);
        const T c = axes_.c_max(az.ct, az.st);
        return density(hi - lo, (T(1) + c) * kappa2_ / (kappa2_ * az.ct * az.ct + az.st * az.st));
    }

    // The building blocks the LD-radial composition (maps/ld_radial.hpp), the cosine-weighted
    // warp (maps/tabulated_cosine.hpp) and the tests call.

    /// One azimuth of a sample (the quadrant, the Lambert point (px, py) = (cos lambda,
    /// kappa sin lambda), its length n, n C, g = 1/(n^2 (1 + C)), C = cos theta_max there) and
    /// the density's two factors (the bin's blended mass df and n^2 (1 + C)).
    struct Ray {
        detail::QuadrantFold<T> fold;
        T px, py, n, nc, g, c;
        T df, n2_1pc;
    };

    /// The ray at the Lambert anomaly lambda = x pi/2 (x in [0, 1]) of the quadrant `fold`, in a
    /// bin of blended mass df.
    APSE_HOT_INLINE Ray ray_at(const detail::QuadrantFold<T>& fold, T x, T df) const noexcept {
        const detail::SinCosValues<T> sc = detail::sin_cos_quarter_turn(x);
        // n = |(px, py)| and n C(tau) = sqrt(cos^2 alpha px^2 + cos^2 beta py^2): one paired square
        // root; then one division, g = 1/(n (n + n C)) = 1/(n^2 (1 + C)), gives C and everything
        // radial_direction needs; the density needs only n^2 (1 + C) (no division)
        Ray r;
        r.fold = fold;
        r.px = sc.c;
        r.py = kappa_ * sc.s;
        const T px2 = r.px * r.px, py2 = r.py * r.py;
        detail::sqrt2(px2 + py2, axes_.ca2 * px2 + axes_.cb2 * py2, r.n, r.nc);
        r.n2_1pc = r.n * (r.n + r.nc);
        r.g = T(1) / r.n2_1pc;
        r.c = r.nc * ((r.n + r.nc) * r.g);  // C = nc / n
        r.df = df;
        return r;
    }

    /// The ray of the quadrant and quadrant-area fraction `fold` (not checked; the map is valid),
    /// with the table-walk steps in `steps`.
    APSE_HOT_INLINE Ray ray_folded(const detail::QuadrantFold<T>& fold, int& steps) const noexcept {
        const T f = fold.fraction * T(bins_);  // the blended CDF runs from 0 to N
        // the bin k with F(k) <= f < F(k + 1) (F(0) = 0, F(N) = N up to rounding; f >= F(N) gives
        // the last bin): the blended CDF is within a few % of linear in lambda, so start at the
        // bin of the uniform CDF and walk (measured: <= 0.5 steps on average, at most 3; the
        // loops are bounded by N in any case).
        int lo = int(f);
        lo = lo < 0 ? 0 : (lo > bins_ - 1 ? bins_ - 1 : lo);
        T f0 = cdf_at(lo), f1 = cdf_at(lo + 1);
        steps = 0;
        while (lo > 0 && f0 > f) {
            --lo;
            ++steps;
            f1 = f0;
            f0 = cdf_at(lo);
        }
        while (lo < bins_ - 1 && !(f < f1)) {
            ++lo;
            ++steps;
            f0 = f1;
            f1 = cdf_at(lo + 1);
        }
        const T df = f1 - f0;
        const T s = df > T(0) ? detail::clamp_non_nan((f - f0) / df, T(0), T(1)) : T(0);
        // lambda = (lo + s) pi/(2N); tan tau = kappa tan lambda;
        // (cos tau, sin tau) = (cos lambda, kappa sin lambda)/n
        return ray_at(fold, detail::min_of((T(lo) + s) * inv_bins_, T(1)), df);
    }

    /// The world-space sample at the radial fraction u2 in [0, 1] of the ray r, with its density.
    APSE_HOT_INLINE DirectionSample<T> ray_sample(const Ray& r, T u2) const noexcept {
        return {ellipse_.to_world(detail::radial_direction(axes_, r.fold, r.px, r.py, r.c, r.g, u2)),  // as RadialMap
                density(r.df, r.n2_1pc)};
    }

    /// The world-space sample for the quadrant and quadrant-area fraction `fold` and the radial
    /// fraction u2 in [0, 1] (not checked; the map is valid), with the table-walk steps in
    /// `steps`: sample() after fold_quadrant(u1), TabulatedLdRadialMap's after the concentric map.
    APSE_HOT_INLINE DirectionSample<T> sample_folded(const detail::QuadrantFold<T>& fold, T u2, int& steps) const noexcept {
        if (cap_) {
            steps = 0;
            return {ellipse_.to_world(detail::cap_direction(fold, ellipse_.one_minus_cos_alpha, u2)), cap_inv_omega_};
        }
        return ray_sample(ray_folded(fold, steps), u2);
    }

    /// The quadrant-area fraction of the Lambert anomaly lambda = x pi/2 (x in [0, 1]): the
    /// blended CDF, linear within a bin.
    APSE_FUNC T lambda_fraction(T x) const noexcept {
        const T y = detail::clamp(x, T(0), T(1)) * T(bins_);
        int k = int(y);
        if (k > bins_ - 1) k = bins_ - 1;
        const T f0 = cdf_at(k), f1 = cdf_at(k + 1);
        return detail::clamp((f0 + (y - T(k)) * (f1 - f0)) * inv_bins_, T(0), T(1));
    }

    /// A local direction in the map's coordinates: (u1, u2), its azimuth's first-quadrant
    /// (cos tau, sin tau), C = cos theta_max there, and the map's density there.
    struct LocalPoint {
        vec2 u;
        T ct, st, c, pdf;
    };

    /// The LocalPoint of the unit local direction `l` ((u1, u2) clamped to [0, 1]^2).
    APSE_FUNC LocalPoint local_point(const vec3& l) const noexcept {
        const int q = detail::quadrant_of(l.x, l.y);
        const T x = std::fabs(l.x), y = std::fabs(l.y);
        const Azimuth az = azimuth_of(x, y);
        const T f0 = cdf_at(az.bin), f1 = cdf_at(az.bin + 1);
        const T s = detail::clamp(az.lambda / bin_width_ - T(az.bin), T(0), T(1));
        const T f = detail::clamp((f0 + s * (f1 - f0)) * inv_bins_, T(0), T(1));
        const T u1 = detail::unfold_quadrant_fraction(q, f);
        const T c = axes_.c_max(az.ct, az.st);
        T u2 = T(1);
        if (l.z > T(0)) {
            const detail::RadialFraction<T> r = detail::radial_fraction(axes_, x, y, l.z, az.ct, az.st, c);
            u2 = r.one_minus_c > T(0) ? detail::clamp(r.one_minus_cos / r.one_minus_c, T(0), T(1)) : T(0);
        }
        const T w = (T(1) + c) * kappa2_ / (kappa2_ * az.ct * az.ct + az.st * az.st);
        return {vec2(detail::clamp(u1, T(0), T(1)), u2), az.ct, az.st, c, density(f1 - f0, w)};
    }

    /// (u1, u2) of the unit local direction `l` (clamped to [0, 1]^2): invert() and
    /// TabulatedLdRadialMap's inverse (maps/ld_radial.hpp).
    APSE_FUNC vec2 local_coordinates(const vec3& l) const noexcept {
        return cap_ ? detail::cap_coordinates(l, ellipse_.one_minus_cos_alpha) : local_point(l).u;
    }

    /// sample(u), counting the table-walk steps in `iterations` (0 when the uniform guess was the
    /// bin).
    APSE_HOT_INLINE DirectionSample<T> sample_counted(const vec2& u, int& iterations) const noexcept {
        iterations = 0;
        bool ok = valid_;
        const vec2 uc = detail::clamp_unit(u, ok);
        if (!ok) return {ellipse_.z, T(0)};
        return sample_folded(detail::fold_quadrant(uc.x), uc.y, iterations);
    }

    struct Azimuth {
        T ct, st;  ///< cos tau, sin tau
        T lambda;  ///< Lambert anomaly in [0, pi/2]
        int bin;   ///< its bin, in [0, N − 1]
    };

    /// tau and lambda of the first-quadrant local direction (x, y) (x, y >= 0).
    APSE_FUNC Azimuth azimuth_of(T x, T y) const noexcept {
        // tan tau = (a/b) tan phi: (cos tau, sin tau) ∝ ((b/a) x, y)
        const T bx = ba_ * x;
        const T n = std::sqrt(bx * bx + y * y);
        Azimuth az;
        az.ct = n > T(0) ? bx / n : T(1);
        az.st = n > T(0) ? y / n : T(0);
        az.lambda = detail::clamp(std::atan2(az.st, kappa_ * az.ct), T(0), detail::half_pi_v<T>);
        int k = int(az.lambda / bin_width_);
        az.bin = k < 0 ? 0 : (k > bins_ - 1 ? bins_ - 1 : k);
        return az;
    }

    /// The blended CDF at node k (summed as a tree: it is on the sample's critical path).
    APSE_FUNC T cdf_at(int k) const noexcept {
        return (weights_[0] * T(rows_[0][k]) + weights_[1] * T(rows_[1][k])) +
               (weights_[2] * T(rows_[2][k]) + weights_[3] * T(rows_[3][k]));
    }

    /// Solid-angle density for a bin of blended mass df (N dF: the weights carry N) at an azimuth
    /// where w = (1 + C) |(cos lambda, kappa sin lambda)|^2
    /// = (1 + C) kappa^2 / (kappa^2 cos^2 tau + sin^2 tau), C = cos theta_max (file comment's
    /// pdf; a sample has w without a division).
    APSE_FUNC T density(T df, T w) const noexcept {
        const T p = (df * w) * pdf_scale_;  // df = N dF (the weights carry N)
        return detail::is_finite(p) ? detail::max_of(p, T(0)) : T(0);
    }

private:
    SphericalEllipse<T> ellipse_;
    detail::EllipseAxes<T> axes_;
    T ba_;  ///< b / a
    const float* rows_[4];
    T weights_[4];
    int bins_;
    T kappa_, kappa2_, bin_width_, inv_bins_, pdf_scale_;
    T cap_inv_omega_;  ///< 1/(2 pi (1 − cos alpha)) on a cap, else 0
    bool cap_;         ///< the ellipse is a cap: sample(), pdf() and invert() in closed form
    bool valid_;
};

}  // namespace detail

/// Tabulated LD-radial map (docs/math.md §4 + §6, unbiased): the Shirley–Chiu concentric map first,
/// then the tabulated radial map (comparison.hpp's TabulatedMap) with u1 = angle/(2 pi),
/// u2 = radius^2 (detail::LdComposition, as LdRadialMap over the radial map). Continuous on the
/// closed square; the same density, pdf, accuracy and table as the tabulated radial map: pdf is
/// exactly the density drawn from (within 0.44 % of 1/Omega for the default table). Holds a
/// pointer into the table (which must outlive the map). Trivially copyable.
template <class T> class TabulatedLdRadialMap : public detail::LdComposition<detail::TabulatedMap<T>> {
    static_assert(detail::is_real_type<T>(), "apse: TabulatedLdRadialMap<T>: T must be float or double");

public:
    /// What SphereLight holds for this map: the same samples on a cap, without the table walk
    /// (maps/cap.hpp).
    using CapSampler = detail::CapMap<T, true, true>;

    /// Builds the map for `ellipse` reading `table` (empty ellipse or invalid view: pdf 0
    /// everywhere).
    APSE_FUNC TabulatedLdRadialMap(const SphericalEllipse<T>& ellipse, const TabulationView& table) noexcept
        : detail::LdComposition<detail::TabulatedMap<T>>(ellipse, table) {}
};

}  // namespace apse
