// apse — area-preserving parameterizations for spherical ellipses.
// SPDX-License-Identifier: MIT
#pragma once

/// @file elliptic.hpp
/// Elliptic integrals: Carlson's symmetric forms R_F, R_D, R_J, R_C and the Legendre forms
/// F(phi|m), Pi(n;phi|m), K(m), Pi(n|m) built on them (docs/math.md §1, DLMF chapter 19).
///
/// **Parameter m = k^2** everywhere (as DLMF and mpmath `ellipf(phi, m)`, `ellippi(n, phi, m)`,
/// `ellipk(m)`); Boost.Math and `std::ellint_1/3`, `std::comp_ellint_1/3` take the modulus k.
/// The characteristic n has the DLMF/mpmath sign: Pi(n;phi|m) = int_0^phi dt/((1 - n sin^2 t)
/// sqrt(1 - m sin^2 t)) (libstdc++'s `std::ellint_3(k, nu, phi)` uses the same sign, nu = n).
///
/// All functions are templates on T = float or double, `noexcept`, allocation- and
/// exception-free, callable from CUDA device code; outside their domain, and for NaN or infinite
/// arguments, they return NaN (every loop has a hard iteration cap: they never hang).
/// "Accuracy" below is the largest relative error measured against 30-digit mpmath reference
/// tables over the whole domain (`tests/data/elliptic`, `tools/accuracy_report`), in units of
/// T's machine epsilon (2^-23 for float, 2^-52 for double).

#include "config.hpp"
#include "detail/carlson.hpp"
#include "detail/math.hpp"

namespace apse {
namespace detail {

template <class T> APSE_FUNC T rf_impl(T x, T y, T z) noexcept {
    if (!carlson_args_ok(x, y, z)) return detail::quiet_nan<T>();
    return rf_core(x, y, z);
}

template <class T> APSE_FUNC T rd_impl(T x, T y, T z) noexcept {
    if (!(carlson_args_ok(x, y, z) && z > T(0))) return detail::quiet_nan<T>();
    return rd_core(x, y, z);
}

template <class T> APSE_FUNC T rc_impl(T x, T y) noexcept {
    if (!(x >= T(0) && y > T(0) && detail::is_finite(detail::max_of(x, y)))) return detail::quiet_nan<T>();
    return rc_core(std::fabs(x), y);  // fabs: -0 counts as 0 (d / -0 would be -inf)
}

/// sin and cos of phi reduced to [-pi/2, pi/2] by whole periods: phi = phi_r + j pi, returns
/// s = sin(phi_r), c = cos(phi_r) >= 0 and j. The reduction uses only the signs of sin(phi)
/// and cos(phi) (computed by the C library from phi itself), so it loses no accuracy near
/// +-pi/2 (float(pi/2) > pi/2, for instance, correctly gets j = 1).
template <class T> struct ReducedAmplitude {
    T s, c, j;
};
template <class T> APSE_FUNC ReducedAmplitude<T> reduce_amplitude(T phi) noexcept {
    T s = std::sin(phi), c = std::cos(phi), j = T(0);
    if (c >= T(0) && std::fabs(phi) < T(2)) return {s, c, j};  // the common case: |phi| <= pi/2
    j = std::nearbyint(phi / detail::pi_v<T>);
    if (std::fmod(j, T(2)) != T(0)) {
        s = -s;
        c = -c;
    }
    if (c < T(0)) {  // phi / pi rounded to the wrong side of a half-period
        j += s > T(0) ? T(1) : T(-1);
        s = -s;
        c = -c;
    }
    return {s, c, j};
}

template <class T> APSE_FUNC T k_impl(T m) noexcept {
    if (!(m < T(1)) || !detail::is_finite(m)) return detail::quiet_nan<T>();
    return rf_core(T(0), T(1) - m, T(1));
}

/// Below this |n| (n < 0), Pi uses F + (n/3) s^3 R_J directly: its cancellation amplifies
/// errors by at most 1 + |n|.
template <class T> APSE_FUNC constexpr T pi_direct_bound() noexcept { return T(0.25); }

/// True when the n < -1/4, m < 0 forms of Pi have an R_J argument q = c^2 + (1-m) s^2/(1-n) above
/// 2^400 (double) / 2^50 (float): that R_J may underflow where (1-m) R_J does not (a fuzz
/// finding, 1 - m near DBL_MAX), so it is computed on the arguments scaled by l = (1-n)/(1-m).
template <class T> APSE_FUNC bool huge_q(T q) noexcept {
    return q > (sizeof(T) == sizeof(float) ? T(0x1p50) : T(0x1p400));
}

template <class T> APSE_FUNC T comp_pi_valid(T n, T m) noexcept {
    const T mc = T(1) - m;
    if (n >= -pi_direct_bound<T>()) {  // K + (n/3) R_J(0, 1-m, 1, 1-n): no cancellation for n >= 0
        const RfRj<T> r = rj_core<T, true>(T(0), mc, T(1), T(1) - n);
        return r.rf + n * (T(1) / T(3)) * r.rj;
    }
    const T nn = -n;
    if (m >= T(0)) {
        // n < 0 <= m: pi/(2 sqrt((1-n) q)) + (m/(3|n|)) R_J(0, 1-m, 1, q), q = 1 + m/|n|
        // (DLMF 19.21.12 with (p-1)(q-1) = m; both terms positive).
        const T k = m / nn, q = T(1) + k;
        return detail::half_pi_v<T> / (std::sqrt(T(1) + nn) * std::sqrt(q)) +
               k * (T(1) / T(3)) * rj_core(T(0), mc, T(1), q).rj;
    }
    // n < 0, m < 0: (K + |n|(1-m)/(3(1-n)) R_J(0, 1-m, 1, q)) / (1-n), q = (1-m)/(1-n)
    // (DLMF 19.21.12 with (p-0)(q-0) = (1-m); all terms positive).
    const T np = T(1) + nn;
    if (!huge_q(mc / np)) {
        const RfRj<T> r = rj_core<T, true>(T(0), mc, T(1), mc / np);
        return (r.rf + nn * ((mc / np) * (T(1) / T(3)) * r.rj)) / np;
    }
    // q so large that R_J underflows where (1-m) R_J does not: homogeneity with l = (1-n)/(1-m),
    // R_F(v) = sqrt(l) R_F(l v), (1-m) R_J(v) = (1-n) sqrt(l) R_J(l v), l v = (0, 1-n, l, 1)
    const T l = np / mc;
    const RfRj<T> r = rj_core<T, true>(T(0), np, l, T(1));
    return (r.rf + nn * (T(1) / T(3)) * r.rj) * std::sqrt(l) / np;
}

template <class T> APSE_FUNC T comp_pi_impl(T n, T m) noexcept {
    if (!(m < T(1) && n < T(1)) || !detail::is_finite(m) || !detail::is_finite(n)) return detail::quiet_nan<T>();
    return comp_pi_valid(n, m);
}

template <class T> APSE_FUNC T f_impl(T phi, T m) noexcept {
    if (!(m < T(1)) || !detail::is_finite(m) || !detail::is_finite(phi)) return detail::quiet_nan<T>();
    const ReducedAmplitude<T> a = reduce_amplitude(phi);
    const T c2 = a.c * a.c, s2 = a.s * a.s;
    // 1 - m sin^2 = cos^2 + (1 - m) sin^2: a sum of non-negative terms, exact-ish for m -> 1.
    T f = a.s * rf_core(c2, c2 + (T(1) - m) * s2, T(1));
    if (a.j != T(0)) f += T(2) * a.j * rf_core(T(0), T(1) - m, T(1));
    return f;
}

template <class T> APSE_FUNC T pi_impl(T n, T phi, T m) noexcept {
    if (!(m < T(1) && n < T(1)) || !detail::is_finite(m) || !detail::is_finite(n) || !detail::is_finite(phi))
        return detail::quiet_nan<T>();
    const ReducedAmplitude<T> a = reduce_amplitude(phi);
    const T s = a.s, c = a.c, c2 = c * c, s2 = s * s, s3 = s * s2;
    const T y = c2 + (T(1) - m) * s2;  // 1 - m sin^2
    T v;
    if (n >= -pi_direct_bound<T>()) {
        // s R_F(c^2, y, 1) + (n/3) s^3 R_J(c^2, y, 1, 1 - n s^2): DLMF 19.25.14
        const RfRj<T> r = rj_core<T, true>(c2, y, T(1), c2 + (T(1) - n) * s2);
        v = s * r.rf + n * (T(1) / T(3)) * s3 * r.rj;
    } else if (m >= T(0)) {
        // n < 0 <= m: s R_C(c^2 y, p q) + (m/(3|n|)) s^3 R_J(c^2, y, 1, q), p = 1 - n s^2,
        // q = 1 + (m/|n|) s^2 (DLMF 19.21.12 with the 1 as the distinguished argument).
        // (R_C(c^2 y, p q) = R_C(c^2 y / p, q) / sqrt(p): p q may overflow for huge |n|.)
        const T nn = -n, k = m / nn, p = c2 + (T(1) + nn) * s2, q = T(1) + k * s2;
        v = s * rc_core(c2 * y / p, q) / std::sqrt(p) + k * (T(1) / T(3)) * s3 * rj_core(c2, y, T(1), q).rj;
    } else {
        // n < 0, m < 0: (s R_F + |n| s c R_C(y, p q) + |n|(1-m)/(3(1-n)) s^3 R_J(c^2, y, 1, q))/(1-n),
        // q = c^2 + (1-m) s^2/(1-n) (DLMF 19.21.12 with c^2 as the distinguished argument).
        const T nn = -n, np = T(1) + nn, mc = T(1) - m;
        const T p = c2 + np * s2, q = c2 + mc * s2 / np;
        if (!huge_q(q)) {
            const RfRj<T> r = rj_core<T, true>(c2, y, T(1), q);
            v = (s * r.rf + nn * (s * c * (rc_core(y / p, q) / std::sqrt(p))) +
                 nn * ((mc / np) * (T(1) / T(3)) * s3 * r.rj)) / np;
        } else {  // as in comp_pi_valid, l = (1-n)/(1-m): l v = (l c^2, l c^2 + (1-n) s^2, l, l c^2 + s^2)
            const T l = np / mc, lc2 = l * c2;
            const RfRj<T> r = rj_core<T, true>(lc2, lc2 + np * s2, l, lc2 + s2);
            v = ((s * r.rf + nn * (T(1) / T(3)) * s3 * r.rj) * std::sqrt(l) +
                 nn * (s * c * (rc_core(y / p, q) / std::sqrt(p)))) / np;
        }
    }
    if (a.j != T(0)) v += T(2) * a.j * comp_pi_valid(n, m);
    return v;
}

}  // namespace detail

/// Carlson's symmetric integral of the first kind
/// R_F(x, y, z) = 1/2 int_0^inf dt / sqrt((t+x)(t+y)(t+z)) (DLMF 19.16.1).
/// Domain: x, y, z >= 0 and finite, at most one of them zero; otherwise NaN.
/// Accuracy (measured, max over the reference table): 1.5 eps float, 1.7 eps double (budget 4).
/// Duplication with a degree-9 series; with a zero argument the arithmetic-geometric mean.
template <class T> APSE_FUNC T carlson_rf(T x, T y, T z) noexcept {
    static_assert(detail::is_real_type<T>(), "apse: T must be float or double");
    return detail::rf_impl<T>(x, y, z);
}

/// Carlson's symmetric integral of the second kind
/// R_D(x, y, z) = R_J(x, y, z, z) = 3/2 int_0^inf dt / ((t+z) sqrt((t+x)(t+y)(t+z))) (DLMF 19.16.5).
/// Domain: x, y >= 0, not both zero, z > 0, all finite; otherwise NaN.
/// Accuracy (measured): 2.4 eps float, 2.3 eps double (budget 8).
template <class T> APSE_FUNC T carlson_rd(T x, T y, T z) noexcept {
    static_assert(detail::is_real_type<T>(), "apse: T must be float or double");
    return detail::rd_impl<T>(x, y, z);
}

/// Carlson's symmetric integral of the third kind
/// R_J(x, y, z, p) = 3/2 int_0^inf dt / ((t+p) sqrt((t+x)(t+y)(t+z))) (DLMF 19.16.2), the
/// workhorse of the solid angle (docs/math.md §3: Omega = 4/3 tan a tan b R_J(0, 1+tan^2 b, 1+tan^2 a, 1)).
/// Domain: x, y, z >= 0 with at most one zero, p > 0, all finite. p <= 0 (the Cauchy principal
/// value) is not supported: NaN, as everywhere else outside the domain.
/// Accuracy (measured): 3.1 eps float, 2.8 eps double (budget 8). With a zero argument (the
/// solid angle's case) Bulirsch's Gauss transformation (quadratic convergence, no cancellation),
/// ~4x faster than duplication.
template <class T> APSE_FUNC T carlson_rj(T x, T y, T z, T p) noexcept {
    static_assert(detail::is_real_type<T>(), "apse: T must be float or double");
    return detail::rj_impl<T>(x, y, z, p);
}

/// Carlson's degenerate integral R_C(x, y) = R_F(x, y, y) = 1/2 int_0^inf dt / ((t+y) sqrt(t+x))
/// (DLMF 19.2.17): atan(sqrt((y-x)/x))/sqrt(y-x) for x < y, atanh(sqrt((x-y)/x))/sqrt(x-y) for
/// x > y, evaluated without cancellation.
/// Domain: x >= 0, y > 0, both finite (y < 0, the principal value, is not supported); else NaN.
/// Accuracy (measured): 1.5 eps float, 1.1 eps double (budget 4).
template <class T> APSE_FUNC T carlson_rc(T x, T y) noexcept {
    static_assert(detail::is_real_type<T>(), "apse: T must be float or double");
    return detail::rc_impl<T>(x, y);
}

/// Incomplete elliptic integral of the first kind, **parameter m = k^2**:
/// F(phi|m) = int_0^phi dt / sqrt(1 - m sin^2 t) = sin(phi) R_F(cos^2 phi, 1 - m sin^2 phi, 1)
/// (DLMF 19.25.5; docs/math.md §1). Same as mpmath `ellipf(phi, m)`, `std::ellint_1(sqrt(m), phi)`.
/// Domain: m < 1 (any negative m), phi finite; beyond |phi| = pi/2 the periodic extension
/// F(phi + j pi|m) = F(phi|m) + 2 j K(m) is used. m >= 1 (where F is only defined for
/// |sin phi| < 1/sqrt(m)) is not supported: NaN; so are NaN/infinite arguments.
/// Accuracy (measured): 2.5 eps float, 2.8 eps double (budget 8).
template <class T> APSE_FUNC T ellint_f(T phi, T m) noexcept {
    static_assert(detail::is_real_type<T>(), "apse: T must be float or double");
    return detail::f_impl<T>(phi, m);
}

/// Incomplete elliptic integral of the third kind, **parameter m = k^2**, characteristic n:
/// Pi(n;phi|m) = int_0^phi dt / ((1 - n sin^2 t) sqrt(1 - m sin^2 t)) (DLMF 19.2.7; docs/math.md §1),
/// as mpmath `ellippi(n, phi, m)`. For n >= -1/4: F + (n/3) sin^3 phi R_J(c^2, 1-m s^2, 1, 1-n s^2)
/// (DLMF 19.25.14); for n < -1/4 (where those two terms cancel: n = -tan^2 b in the parallel
/// map, |n| up to ~1e4) a form whose terms are all positive, obtained with DLMF 19.21.12.
/// Domain: n < 1, m < 1 (both may be large negative), phi finite, with the periodic extension
/// Pi(n; phi + j pi|m) = Pi(n;phi|m) + 2 j Pi(n|m). n >= 1 (the principal value for n > 1),
/// m >= 1, NaN or infinite arguments: NaN.
/// Accuracy (measured): 2.4 eps float, 3.5 eps double (budget 16).
template <class T> APSE_FUNC T ellint_pi(T n, T phi, T m) noexcept {
    static_assert(detail::is_real_type<T>(), "apse: T must be float or double");
    return detail::pi_impl<T>(n, phi, m);
}

/// Complete elliptic integral of the first kind, **parameter m = k^2**:
/// K(m) = F(pi/2|m) = R_F(0, 1 - m, 1) (DLMF 19.25.1), as mpmath `ellipk(m)`,
/// `std::comp_ellint_1(sqrt(m))`; e.g. K(0.5) = 1.8540746773013719.
/// Domain: m < 1 (any negative m); m >= 1 (K(1) = inf), NaN, -inf: NaN.
/// Accuracy (measured): 1.5 eps float, 1.7 eps double (budget 8). By the arithmetic-geometric mean.
template <class T> APSE_FUNC T comp_ellint_k(T m) noexcept {
    static_assert(detail::is_real_type<T>(), "apse: T must be float or double");
    return detail::k_impl<T>(m);
}

/// Complete elliptic integral of the third kind, **parameter m = k^2**:
/// Pi(n|m) = Pi(n; pi/2|m) = K(m) + (n/3) R_J(0, 1-m, 1, 1-n) (DLMF 19.25.2; for n < -1/4 a
/// cancellation-free form, see ellint_pi), as mpmath `ellippi(n, m)`.
/// Domain: n < 1, m < 1, finite; otherwise NaN.
/// Accuracy (measured): 3.2 eps float, 3.0 eps double (budget 16).
template <class T> APSE_FUNC T comp_ellint_pi(T n, T m) noexcept {
    static_assert(detail::is_real_type<T>(), "apse: T must be float or double");
    return detail::comp_pi_impl<T>(n, m);
}

}  // namespace apse
