// apse — area-preserving parameterizations for spherical ellipses.
// SPDX-License-Identifier: MIT
#pragma once

/// @file detail/carlson.hpp
/// Private kernels behind elliptic.hpp: Carlson's R_F, R_D, R_J (and a fused R_F + R_J of one
/// argument triple) and R_C. Callers have already checked the domain: these functions assume
/// valid, finite arguments.
///
/// Duplication (Carlson 1995, "Numerical computation of real or complex elliptic integrals",
/// Numer. Algorithms 10; DLMF 19.26.18, 19.36): a step maps every argument v to (v + lambda)/4,
/// lambda = sqrt(x y) + sqrt(y z) + sqrt(z x); it leaves R_F unchanged (R_D, R_J up to an
/// explicit term) and divides every difference between arguments by exactly 4. With A the
/// weighted mean of the arguments, the relative deviations X_i = (A - v_i)/A after n steps are
/// 4^-n (A_0 - v_i)/A_n; once they are below a tolerance, the rest is the Taylor series of R
/// about (A, A, A) in the elementary symmetric functions E2..E5 of the X_i (DLMF 19.36.1-2),
/// here to total degree 9 (Carlson stops at 5, DLMF lists 7). Its truncation error is below
/// eps/8 at the tolerances below (measured at 30 digits over all directions), which are 2.6x
/// (R_F) and 2.7x (R_J) larger than for degree 7: ~0.7 duplication steps fewer. (Degree 11 saves
/// another 0.4 step but measured no faster: 37 terms for R_J.)
///
/// Complete integrals (one argument zero) converge quadratically instead, with one square root
/// per step: the arithmetic-geometric mean for R_F (agm_rf), Bulirsch's Gauss transformation for
/// R_J (cel_rj).
///
/// Speed on x86-64 (see docs/elliptic.md) is bound by the square-root unit: a duplication step
/// needs three roots (four for R_J) whose latency chains into the next step, and the unit takes a
/// new double root only every ~8 cycles; sqrt2 (detail/math.hpp) pairs them in one SSE
/// instruction. Branches whose outcome depends on the chain (loop exits, rc1's cases) are kept
/// few: a mispredicted one discards the duplication steps already in flight behind it.

#include <cmath>

#include "../config.hpp"
#include "math.hpp"

namespace apse {
namespace detail {

/// Hard cap on duplication steps. Valid inputs need at most ~16 (double, arguments spanning
/// the whole exponent range); the cap only bounds the work for inputs that are not.
constexpr int carlson_max_steps = 64;
/// Steps run on one count before the count is made again (see duplicate_until_converged): more
/// than any argument ratio up to 4^16 needs, so such inputs count once.
constexpr int carlson_chunk_steps = 16;

/// Stopping tolerance on max |X_i| for R_F: (eps / (8 C))^(1/10), C = 0.0129 the largest
/// coefficient of the degree-10 truncation error (maximised numerically over all directions,
/// +10%). At exactly this tolerance the truncation error measures 0.10 eps (float and double).
template <class T> APSE_FUNC constexpr T rf_tolerance() noexcept {
    return sizeof(T) == sizeof(float) ? T(0.25) : T(0.034);
}
/// Stopping tolerance on max |X_i| for R_J and R_D: (eps / (8 C))^(1/10), C = 0.14 (measured
/// truncation error at the tolerance: 0.10 eps).
template <class T> APSE_FUNC constexpr T rj_tolerance() noexcept {
    return sizeof(T) == sizeof(float) ? T(0.2) : T(0.0268);
}

/// max |a - v| over four values (pass a value twice when there are three).
template <class T> APSE_FUNC T max_deviation(T a, T v0, T v1, T v2, T v3) noexcept {
    return max_of(max_of(std::fabs(a - v0), std::fabs(a - v1)),
                  max_of(std::fabs(a - v2), std::fabs(a - v3)));
}

/// Degree-9 Taylor series of sqrt(A) R_F in E2 = XY - Z^2, E3 = XYZ (X + Y + Z = 0): DLMF 19.36.1
/// to degree 7; the degree 8-9 terms were derived from the series of the integrand,
/// R_F(1-X, 1-Y, 1-Z) = sum_N T_N / (2N + 1), T_N = sum_{i+j+k=N} c_i c_j c_k X^i Y^j Z^k,
/// c_i = (1/2)_i / i!.
template <class T> APSE_FUNC T rf_series(T e2, T e3) noexcept {
    // grouped for a short dependency chain (Estrin-like), same terms
    const T e22 = e2 * e2;
    const T p0 = e2 * (T(-1) / T(10) + e2 * (T(1) / T(24))) +
                 e22 * e2 * (T(-5) / T(208) + e2 * (T(35) / T(2176)));
    const T p1 = (T(1) / T(14) + e2 * (T(-3) / T(44))) + e22 * (T(1) / T(16) + e2 * (T(-35) / T(608)));
    const T p2 = T(3) / T(104) + e2 * (T(-15) / T(272)) + e3 * (T(5) / T(304));
    return T(1) + (p0 + e3 * (p1 + e3 * p2));
}

/// Degree-9 Taylor series of A^(3/2) R_J in the elementary symmetric functions E2..E5 of
/// (X, Y, Z, P, P), X + Y + Z + 2P = 0: DLMF 19.36.2 to degree 7; the degree 8-9 terms derived
/// as for R_F (R_J(1-X, 1-Y, 1-Z, 1-P) = sum_N 3 T_N / (2N + 3), the P factor's c_i = 1).
template <class T> APSE_FUNC T rj_series(T e2, T e3, T e4, T e5) noexcept {
    const T c0 = e3 * (T(1) / T(6) + e3 * (T(3) / T(40) + e3 * (T(5) / T(112))) +
                       e4 * (T(-9) / T(68)) + e5 * (T(9) / T(76))) +
                 e4 * (T(-3) / T(22) + e4 * (T(9) / T(152)) + e5 * (T(-3) / T(28))) +
                 e5 * (T(3) / T(26));
    const T c1 = T(-3) / T(14) + e3 * (T(-9) / T(52) + e3 * (T(-45) / T(304)) + e4 * (T(15) / T(56))) +
                 e4 * (T(3) / T(20)) + e5 * (T(-9) / T(68));
    const T c2 = T(9) / T(88) + e3 * (T(45) / T(272)) + e4 * (T(-45) / T(304)) + e5 * (T(15) / T(112));
    const T c3 = T(-1) / T(16) + e3 * (T(-5) / T(32));
    const T c4 = T(105) / T(2432);
    const T e22 = e2 * e2;
    return T(1) + ((c0 + e2 * c1) + e22 * ((c2 + e2 * c3) + e22 * c4));
}

/// The series of R_J/R_D from the scaled deviations X, Y, Z, P.
template <class T> APSE_FUNC T rj_tail(T X, T Y, T Z, T P) noexcept {
    const T xyz = X * Y * Z, pp = P * P;
    const T e2 = X * Y + Z * (X + Y) - T(3) * pp;
    const T e3 = xyz + P * (T(2) * e2 + T(4) * pp);
    const T e4 = P * (T(2) * xyz + P * (e2 + T(3) * pp));
    const T e5 = xyz * pp;
    return rj_series(e2, e3, e4, e5);
}

/// |e| up to which R_C(1, 1 + e) is evaluated by the rational approximation rc1_rational.
template <class T> APSE_FUNC constexpr T rc1_rational_bound() noexcept { return T(0.25); }

/// R_C(1, 1 + e) = atan(sqrt e)/sqrt e = sum_k (-e)^k/(2k + 1) for |e| <= 1/4 by its Pade
/// approximant [7/7] in double, [4/4] in float (exact rational coefficients, derived from the
/// series): relative error below 1.1e-17 resp. 7.6e-11 there (measured at 50 digits). One
/// division instead of the 24 series terms the same range would need.
template <class T> APSE_FUNC T rc1_rational(T e) noexcept {
    if constexpr (sizeof(T) == sizeof(float)) {
        const T p = T(1) + e * (T(91) / T(51) + e * (T(83) / T(85) + e * (T(1289) / T(7735) +
                    e * (T(16384) / T(3828825)))));
        const T q = T(1) + e * (T(36) / T(17) + e * (T(126) / T(85) + e * (T(84) / T(221) +
                    e * (T(63) / T(2431)))));
        return p / q;
    } else {
        const T e2 = e * e, e4 = e2 * e2;
        const T p = (T(1) + e * (T(286) / T(87))) + e2 * (T(1837) / T(435) + e * (T(1628) / T(609))) +
                    e4 * ((T(15527) / T(18009) + e * (T(43322) / T(330165))) +
                          e2 * (T(1811401) / T(244652265) + e * (T(4194304) / T(62386327575))));
        const T q = (T(1) + e * (T(105) / T(29))) + e2 * (T(455) / T(87) + e * (T(1001) / T(261))) +
                    e4 * ((T(1001) / T(667) + e * (T(1001) / T(3335))) +
                          e2 * (T(1001) / T(38019) + e * (T(143) / T(215441))));
        return p / q;
    }
}

/// R_C(1, w) with e = w - 1 (both passed so that neither is computed by cancellation):
/// the rational approximation for |e| <= 1/4, atan(sqrt e)/sqrt e for e > 0, and for e < 0,
/// with u = sqrt(-e), atanh(u)/u = log((1 + u)/sqrt w)/u = log1p(u (1 + u/(1 + sqrt w))/sqrt w)/u
/// (using 1 - sqrt w = u^2/(1 + sqrt w): the log1p argument is a sum of positive terms, accurate
/// both for small u, where log would be ill-conditioned, and for w -> 0).
template <class T> APSE_FUNC T rc1(T e, T w) noexcept {
    if (std::fabs(e) <= rc1_rational_bound<T>()) return rc1_rational(e);
    if (e > T(0)) {
        const T r = std::sqrt(e);
        return std::atan(r) / r;
    }
    const T u = std::sqrt(-e), sw = std::sqrt(w);
    return std::log1p(u * (T(1) + u / (T(1) + sw)) / sw) / u;
}

/// R_C(x, y) for x >= 0, y > 0 (DLMF 19.2.17-19.2.18, written without cancellation).
template <class T> APSE_FUNC APSE_NOINLINE T rc_core(T x, T y) noexcept {
    if (x < y) {
        const T d = y - x;
        return std::atan(std::sqrt(d / x)) / std::sqrt(d);  // x = 0: atan(inf) = pi/2
    }
    if (x > y) {
        // log((sqrt x + sqrt(x - y))/sqrt y) / sqrt(x - y); the log argument minus one is a sum
        // of positive terms (sqrt x - sqrt y = d/(sqrt x + sqrt y)).
        const T d = x - y, sd = std::sqrt(d), sx = std::sqrt(x), sy = std::sqrt(y);
        const T r = (sd + d / (sx + sy)) / sy;
        if (is_finite(r)) return std::log1p(r) / sd;
        return (std::log(sx + sd) - std::log(sy)) / sd;  // the ratio overflows: y / x < eps^2
    }
    return T(1) / std::sqrt(x);
}

/// One duplication step on (x, y, z): replaces each argument v by (v + lambda)/4,
/// lambda = sqrt(x y) + sqrt(y z) + sqrt(z x); returns l = lambda/4 and the three square roots.
/// (Written as v/4 + l with l = (sx/4)(sy + sz) + (sy/4) sz — bit-identical, as the factors 1/4
/// are exact — which keeps the dependency chain sqrt -> lambda -> v one operation shorter.)
template <class T> struct DuplicationStep {
    T l, sx, sy, sz;  // l = lambda / 4
};
template <class T> APSE_FUNC DuplicationStep<T> duplicate(T& x, T& y, T& z, T sx, T sy, T sz) noexcept {
    const T l = (T(0.25) * sx) * (sy + sz) + (T(0.25) * sy) * sz;
    x = T(0.25) * x + l;
    y = T(0.25) * y + l;
    z = T(0.25) * z + l;
    return {l, sx, sy, sz};
}
template <class T> APSE_FUNC DuplicationStep<T> duplicate(T& x, T& y, T& z) noexcept {
    T sx, sy;
    sqrt2(x, y, sx, sy);
    return duplicate(x, y, z, sx, sy, std::sqrt(z));
}

/// Runs the duplication: `step(f)` performs one step (f = 4^-m before step m), `lower()` returns a
/// lower bound of every later mean A_n (the smallest current argument: the smallest argument
/// never decreases). q = max |A_0 - v_i| / tolerance. Returns 4^-n after the n steps.
///
/// The number of steps is fixed before the loop instead of testing 4^-n q <= A_n in it: two
/// steps, then the count from the smallest argument (n = 2 + ceil(log4(q / (16 min)))), so the
/// loop's exit does not wait for the chain of square roots. It costs ~0.1 step more on average
/// than the exact test; measured against an in-loop test, R_F is 6% faster, R_J 3% slower.
/// When even the step cap does not suffice (not reachable by valid arguments: see rj_core),
/// the result is NaN.
template <class T, class Step, class Lower>
APSE_FUNC T duplicate_until_converged(T q, T a0, Step&& step, Lower&& lower) noexcept {
    T f = T(1);
    if (!(q > a0)) return f;  // already within tolerance (e.g. equal arguments)
    step(f);
    f *= T(0.25);
    step(f);
    f *= T(0.25);
    T rest = q * f;
    int done = 2;
    for (;;) {
        // Steps needed if the smallest argument stayed at its current value; it only grows, so
        // for widely spread arguments (ratios beyond ~4^16) this overestimates: run at most
        // carlson_chunk_steps of them, then count again from the grown smallest argument.
        const T lo = lower();
        int n = 0;
        while (rest > lo && n < carlson_chunk_steps && done + n < carlson_max_steps) {
            rest *= T(0.25);
            ++n;
        }
        for (int i = 0; i < n; ++i) {
            step(f);
            f *= T(0.25);
        }
        done += n;
        if (!(rest > lo)) return f;
        if (done >= carlson_max_steps) break;
    }
    return rest > lower() ? quiet_nan<T>() : f;  // cannot converge within the cap: NaN, never garbage
}

/// R_F and R_J of one argument triple (the kernels that compute both share their work).
template <class T> struct RfRj {
    T rf, rj;
};

/// The complete integral R_F(0, y, z) (y, z > 0) by the arithmetic-geometric mean:
/// R_F(0, y, z) = pi / (2 M), M = lim a_n = lim g_n, a_0 = sqrt z, g_0 = sqrt y,
/// a_{n+1} = (a_n + g_n)/2, g_{n+1} = sqrt(a_n g_n) (DLMF 19.8.1, 19.20.1).
template <class T> APSE_FUNC APSE_NOINLINE T agm_rf(T y, T z) noexcept {
    constexpr T agm_tolerance = sizeof(T) == sizeof(float) ? T(3.4e-4) : T(1.49e-8);  // sqrt(eps)
    T a = std::sqrt(z), g = std::sqrt(y);
    // |a - g| <= sqrt(eps) a: the next mean is exact to eps/4 (a_{n+1} - M ~ (a - g)^2/(16 a)).
    for (int k = 0; k < 2 * carlson_max_steps && !(std::fabs(a - g) <= agm_tolerance * a); ++k) {
        const T ag = a * g;
        a = T(0.5) * (a + g);
        g = std::sqrt(ag);
    }
    return pi_v<T> / (a + g);
}

/// The complete integrals R_J(0, y, z, p) and R_F(0, y, z) (y, z, p > 0) by Bulirsch's Gauss
/// transformation of his generalised complete integral cel (R. Bulirsch, Numer. Math. 13 (1969)
/// 305-315), written homogeneously in (y, z, p). With A = sqrt z, G = sqrt y,
///   R_J(0, y, z, p) = 3 int_0^(pi/2) sin^2 t dt / ((A^2 cos^2 t + p sin^2 t) sqrt(A^2 cos^2 t + G^2 sin^2 t))
/// (from DLMF 19.25.2, Pi(n|m) - K(m) = (n/3) R_J(0, 1 - m, 1, 1 - n), and homogeneity), and one
/// Gauss transformation of the integration variable maps (A, G) to (A + G, 2 sqrt(A G)) and the
/// rest of the integrand, kept as (a cos^2 t + b sin^2 t)/(A^2 cos^2 t + q^2 sin^2 t)-like
/// coefficients a, b, q, to
///   a' = a + b/q,  b' = 2 (b + a A G / q),  q' = q + A G / q,
/// from a = 0, b = 1/sqrt p, q = sqrt p. Once A = G (to sqrt(eps), the truncation error is
/// below 0.12 (1 - G/A)^2 <= eps/8, measured at 60 digits) the integral is elementary:
///   R_J = (3 pi / 2) (b + a A') / (A' (A' + q')),  R_F = pi 2^n / (2 A')  (A' = A + G, n steps).
/// Every term is positive (no cancellation), and, unlike Carlson's AGM for R_J (DLMF 19.8.6-8),
/// whose third sequence p_n converges only after ~log2 of p/sqrt(y z) slow steps, the step count
/// is that of the AGM of sqrt y and sqrt z alone: 4-5 steps for y/z > 1e-6, 8 at y/z = 1e-24.
/// Measured error: <= 4.0 eps (double) and 3.5 eps (float) for y, z, p in [1e-12, 1e12].
///
/// cel_core takes the square roots big = sqrt(max(y, z)), small = sqrt(min(y, z)), q = sqrt p
/// and starts from b = 1 instead of 1/q: it returns sqrt(p) R_J(0, y, z, p) (and R_F).
/// Domain: cel_suits(y, z, p), y, z, p in the kernels' window (RjWindow).
template <class T, bool WithRf>
APSE_FUNC APSE_NOINLINE RfRj<T> cel_core(T big, T small, T q) noexcept {
    constexpr T tolerance = sizeof(T) == sizeof(float) ? T(3.4e-4) : T(1.49e-8);  // sqrt(eps)
    T e = big * small, b = T(1), a = T(0), two_n = T(1);
    for (int k = 0; k < 2 * carlson_max_steps; ++k) {
        const T inv_q = T(1) / q, a0 = a, g = e * inv_q;
        a += b * inv_q;
        b = T(2) * (b + a0 * g);
        q += g;
        const T big0 = big;
        big += small;
        if constexpr (WithRf) two_n *= T(2);
        if (std::fabs(big0 - small) <= tolerance * big0) break;  // big >= small: a meaningful test
        small = T(2) * std::sqrt(e);
        e = small * big;
    }
    RfRj<T> r{T(0), T(1.5) * pi_v<T> * (b + a * big) / (big * (big + q))};
    if constexpr (WithRf) r.rf = half_pi_v<T> * two_n / big;
    return r;
}

/// R_J(0, y, z, p) (and R_F(0, y, z)) by cel_core (y, z, p > 0, cel_suits).
template <class T, bool WithRf> APSE_FUNC RfRj<T> cel_rj(T y, T z, T p) noexcept {
    const T q = std::sqrt(p);
    RfRj<T> r = cel_core<T, WithRf>(std::sqrt(max_of(y, z)), std::sqrt(min_of(y, z)), q);
    r.rj /= q;
    return r;
}

/// True when cel_rj is accurate and free of overflow for R_J(0, y, z, p): p >= 2^-64 max(y, z)
/// (float), 2^-120 max(y, z) (double). Its largest coefficient, a ~ 2^n / p, then stays below
/// 2^105 (float) within the kernels' window (RjWindow); smaller p is left to duplication. Covers the solid
/// angle of every spherical ellipse (p / max = cos^2 alpha >= 2^-52 resp. 2^-110 at the tangent caps).
template <class T> APSE_FUNC bool cel_suits(T y, T z, T p) noexcept {
    constexpr T min_ratio = sizeof(T) == sizeof(float) ? T(0x1p-64) : T(0x1p-120);
    return p >= min_ratio * max_of(y, z);
}

/// R_F(x, y, z) by duplication, for valid finite arguments without a zero, finite sum.
template <class T> APSE_FUNC APSE_NOINLINE T rf_duplication(T x, T y, T z) noexcept {
    const T a0 = (x + y + z) * (T(1) / T(3));
    const T dx = a0 - x, dy = a0 - y;  // the deviations scale by exactly 4^-n
    T a = a0;
    const T f = duplicate_until_converged(
        max_deviation(a0, x, y, z, z) * (T(1) / rf_tolerance<T>()), a0,
        [&](T) { a = T(0.25) * a + duplicate(x, y, z).l; },
        [&] { return min_of(min_of(x, y), z); });
    const T s = f / a;
    const T X = dx * s, Y = dy * s, Z = -(X + Y);
    return rf_series(X * Y - Z * Z, X * Y * Z) / std::sqrt(a);
}

/// log 2.
template <class T> constexpr T ln2_v = T(0.693147180559945309417232121458176568L);

/// log(a / b) for positive finite a, b whose ratio may overflow or underflow.
template <class T> APSE_FUNC T log_ratio(T a, T b) noexcept {
    const T r = a / b;
    if (r >= T(0x1p-1000) && r <= T(0x1p1000)) return std::log(r);
    // |log(a/b)| > 693 here: the frexp split adds log(ma/mb) in (-0.7, 0.7) without cancellation
    int ea = 0, eb = 0;
    const T ma = std::frexp(a, &ea), mb = std::frexp(b, &eb);
    return std::log(ma / mb) + T(ea - eb) * ln2_v<T>;
}

template <class T> APSE_FUNC T rf_core(T x, T y, T z) noexcept;

/// R_F and R_D duplications need 1/mean finite: below this sum of the arguments they scale up by
/// 4^tiny_scale (exact: 2^-100 and 2^64 in float, 2^-900 and 2^200 in double).
template <class T> APSE_FUNC constexpr T tiny_sum() noexcept {
    return sizeof(T) == sizeof(float) ? T(0x1p-100) : T(0x1p-900);
}
template <class T> APSE_FUNC constexpr int tiny_scale() noexcept { return sizeof(T) == sizeof(float) ? 32 : 100; }

/// R_F(x, y, z) (no zero argument) when the sum of the arguments over the tolerance overflows.
/// R_F(v/64) = 8 R_F(v) scales exactly unless the smallest argument then loses bits in the
/// subnormals (it is below 2^-1016 in double, then 2^2030 below the largest; a fuzz finding,
/// R_F(1e-45, 1e-45, 1.7e38) in float, flushed two arguments to zero: NaN). Then the arguments
/// split at their wider gap G >= 2^1015: R_F(x, y, z) = R_F(0, y, z) (1 + O(G^-1/2)) for
/// x << y <= z, and R_F(x, y, z) = R_C(z, c) (1 + O(G^-1 log G)), c = ((sqrt x + sqrt y)/2)^2,
/// for x <= y << z (c makes int_0^inf (1/sqrt((t+x)(t+y)) - 1/(t+c)) dt vanish), where
/// R_C(z, c) = log(2 sqrt(z/c))/sqrt(z) to within c/z. float computes in double.
template <class T> APSE_FUNC APSE_COLD T rf_huge(T x, T y, T z) noexcept {
    if constexpr (sizeof(T) == sizeof(float)) {
        return T(rf_core(double(x), double(y), double(z)));
    } else {
        const T lo = min_of(min_of(x, y), z), hi = max_of(max_of(x, y), z);
        const T mid = max_of(min_of(x, y), min_of(max_of(x, y), z));
        if (lo >= T(0x1p-1016)) return T(0.125) * rf_duplication(x * T(0.015625), y * T(0.015625), z * T(0.015625));
        if (std::ilogb(mid) - std::ilogb(lo) >= std::ilogb(hi) - std::ilogb(mid)) return agm_rf(mid, hi);
        const T sc = T(0.5) * (std::sqrt(lo) + std::sqrt(mid)), sz = std::sqrt(hi);
        return (log_ratio(sz, sc) + ln2_v<T>) / sz;
    }
}

/// R_F(x, y, z) for valid finite arguments (at most one zero); the AGM when one is zero.
template <class T> APSE_FUNC T rf_core(T x, T y, T z) noexcept {
    if (x == T(0)) return agm_rf(y, z);
    if (y == T(0)) return agm_rf(x, z);
    if (z == T(0)) return agm_rf(x, y);
    // The mean, or the step count's q (<= the sum / tolerance, ~30x), would overflow: rescaled.
    if (!is_finite((x + y + z) * (T(1) / rf_tolerance<T>()))) return rf_huge(x, y, z);
    // So small that 1/mean would overflow (R_F(d, d, d) at the smallest subnormal d was NaN; a
    // fuzz finding): R_F(v) = 2^k R_F(4^k v), an exact scaling up.
    if (x + y + z < tiny_sum<T>()) return std::ldexp(rf_duplication(std::ldexp(x, 2 * tiny_scale<T>()),
        std::ldexp(y, 2 * tiny_scale<T>()), std::ldexp(z, 2 * tiny_scale<T>())), tiny_scale<T>());
    return rf_duplication(x, y, z);
}

/// R_F(x, y, z) and R_J(x, y, z, p) from one shared duplication (the R_F part only when WithRf).
///
/// R_J = 4^-n A_n^(-3/2) series + 6 sum_m 4^-m R_C(1, 1 + e_m) / d_m (Carlson 1995, eq. 2.39-2.40)
/// with d_m = prod (sqrt p_m + sqrt v_m), e_m = 4^-3m delta / d_m^2, delta = prod (p - v):
/// e_m = prod (sqrt p - sqrt v)/(sqrt p + sqrt v) lies in (-1, 1) and shrinks ~64x per step, so
/// after step 0 (often already there) R_C is rc1's rational approximation, without atan or log.
/// 1 + e_m = 2 sqrt(p)(p + lambda)/d_m exactly (the odd terms of prod(sqrt p +- sqrt v)
/// cancel), which rc1 needs near e = -1. (Carlson's 1979 form R_C(alpha_m, beta_m) saves the
/// root of p, but its e is unbounded and ~4x larger: for arguments log-uniform in [1e-2, 1e2],
/// |e_0| > 1/4 in 61% of the calls instead of 25%, |e_1| > 1/4 in 12% instead of 5%.)
template <class T, bool WithRf>
APSE_FUNC APSE_NOINLINE RfRj<T> rj_core_unscaled(T x, T y, T z, T p) noexcept {
    const T a0 = (x + y + z + T(2) * p) * T(0.2);
    const T dx = a0 - x, dy = a0 - y, dz = a0 - z;
    T q = max_deviation(a0, x, y, z, p) * (T(1) / rj_tolerance<T>());
    // R_F's mean follows the same recurrence; run until both series are accurate.
    T af = T(1), dfx = T(0), dfy = T(0);
    if constexpr (WithRf) {
        af = (x + y + z) * (T(1) / T(3));
        dfx = af - x;
        dfy = af - y;
        q = max_of(q, max_deviation(af, x, y, z, z) * (T(1) / rf_tolerance<T>()));
    }
    T delta = (p - x) * (p - y) * (p - z);  // 4^3m delta_m
    T a = a0, sum = T(0);
    const T f = duplicate_until_converged(
        q, min_of(a0, af),
        [&](T fm) {
            T sx, sy, sz, sp;
            sqrt2(x, y, sx, sy);
            sqrt2(z, p, sz, sp);
            const DuplicationStep<T> st = duplicate(x, y, z, sx, sy, sz);
            const T inv_d = T(1) / ((sp + sx) * (sp + sy) * (sp + sz));
            const T e = delta * inv_d * inv_d;
            const T w = T(2) * sp * (p + T(4) * st.l) * inv_d;  // 1 + e, without cancellation
            sum += fm * rc1(e, w) * inv_d;
            p = T(0.25) * p + st.l;
            a = T(0.25) * a + st.l;
            if constexpr (WithRf) af = T(0.25) * af + st.l;
            delta *= T(1) / T(64);
        },
        [&] { return min_of(min_of(x, y), min_of(z, p)); });
    const T s = f / a;
    const T X = dx * s, Y = dy * s, Z = dz * s, P = -(X + Y + Z) * T(0.5);
    RfRj<T> r{T(0), rj_tail(X, Y, Z, P) * (f / (a * std::sqrt(a))) + T(6) * sum};
    if constexpr (WithRf) {
        const T sf = f / af;
        const T Xf = dfx * sf, Yf = dfy * sf, Zf = -(Xf + Yf);
        r.rf = rf_series(Xf * Yf - Zf * Zf, Xf * Yf * Zf) / std::sqrt(af);
    }
    return r;
}

/// The kernels' window [2^lo, 2^hi] (double: [2^-300, 2^300], float: [2^-32, 2^40]):
/// duplication runs on the arguments as they are when all of them lie in it, Bulirsch's
/// transformation (one zero argument) when the largest one does. There
/// delta = prod (p - v) <= (2 max)^3, 1/d = 1/prod (sqrt p + sqrt v) <= min^(-3/2), the series'
/// A^(-3/2) and Bulirsch's coefficients (cel_suits) are all finite, and a delta small enough to
/// underflow belongs to an e_m = delta/d^2 below 2^-128 (d^2 >= min^3), which is negligible.
/// (With only the largest argument in the window, as before, a small one let 1/d overflow and
/// delta lose e_m: NaN or garbage, e.g. R_J(1e-90, 1e-135, 1e-135, 1e-118) in double.)
template <class T> struct RjWindow {
    static constexpr int lo = sizeof(T) == sizeof(float) ? -32 : -300;
    static constexpr int hi = sizeof(T) == sizeof(float) ? 40 : 300;
    /// Largest ratio of nonzero arguments that one power-of-4 scaling brings into the window
    /// (its width less a margin for the rounding of the scale's exponent).
    static constexpr int spread = hi - lo - 8;
};
template <class T> APSE_FUNC constexpr T rj_window_lo() noexcept {
    return sizeof(T) == sizeof(float) ? T(0x1p-32) : T(0x1p-300);
}
template <class T> APSE_FUNC constexpr T rj_window_hi() noexcept {
    return sizeof(T) == sizeof(float) ? T(0x1p40) : T(0x1p300);
}

/// The median of three values.
template <class T> APSE_FUNC T median_of(T x, T y, T z) noexcept {
    return max_of(min_of(x, y), min_of(max_of(x, y), z));
}

/// The smallest nonzero one of x, y, z (at most one of them is zero).
template <class T> APSE_FUNC T min_nonzero_of(T x, T y, T z) noexcept {
    const T lo = min_of(min_of(x, y), z);
    return lo > T(0) ? lo : median_of(x, y, z);
}

/// True when the nonzero values lo <= hi are within the factor 2^RjWindow::spread.
template <class T> APSE_FUNC bool rj_spread_ok(T lo, T hi) noexcept {
    constexpr T spread = sizeof(T) == sizeof(float) ? T(0x1p64) : T(0x1p592);
    static_assert(RjWindow<float>::spread == 64 && RjWindow<double>::spread == 592, "");
    return hi <= spread * lo;  // (an overflowing product means: within)
}

template <class T, bool WithRf, bool InWindow = false> APSE_FUNC RfRj<T> rj_dispatch(T x, T y, T z, T p) noexcept;

/// R_J (and optionally R_F) for arguments whose nonzero values are within rj_spread_ok (mx the
/// largest, mn the smallest nonzero one): scaled by the power of 4 that centres them in the
/// kernels' window (exact; homogeneity scales the results back: R_J(s v) = s^(-3/2) R_J(v),
/// R_F(s v) = s^(-1/2) R_F(v); the final ldexp rounds once where the result is subnormal).
template <class T, bool WithRf>
APSE_FUNC APSE_NOINLINE RfRj<T> rj_window(T x, T y, T z, T p, T mx, T mn) noexcept {
    int e_hi = 0, e_lo = 0;
    (void)std::frexp(mx, &e_hi);
    (void)std::frexp(mn, &e_lo);
    const int k = (e_hi + e_lo - RjWindow<T>::lo - RjWindow<T>::hi) / 4;  // scale by 4^-k
    constexpr int max_exponent = sizeof(T) == sizeof(float) ? 126 : 1022;
    RfRj<T> r;
    if (2 * k < max_exponent && -2 * k < max_exponent) {  // 4^-k representable: one product each
        const T s = std::ldexp(T(1), -2 * k);
        r = rj_dispatch<T, WithRf, true>(x * s, y * s, z * s, p * s);
    } else {
        r = rj_dispatch<T, WithRf, true>(std::ldexp(x, -2 * k), std::ldexp(y, -2 * k), std::ldexp(z, -2 * k),
                                         std::ldexp(p, -2 * k));
    }
    r.rj = std::ldexp(r.rj, -3 * k);
    if constexpr (WithRf) r.rf = std::ldexp(r.rf, -k);
    return r;
}

/// R_J (and optionally R_F) when p exceeds x, y, z by far (p > 2^16 max(x, y, z)) and x, y, z
/// are within rj_spread_ok.
///
/// Duplication would converge only linearly (p shrinks 4x per step while lambda, which does
/// not involve p, stays at the scale of x, y, z: ~log4(p / max) steps, beyond the step cap for
/// ratios above ~2^110). Instead DLMF 19.21.12, with y the middle argument and
/// (p - y)(q - y) = (x - y)(z - y), i.e. q = y - (y - x)(z - y)/(p - y) in [x, y]:
///   R_J(x,y,z,p) = (3 R_F(x,y,z) - 3 R_C(x z/y, p q/y) + (y - q) R_J(x,y,z,q)) / (p - y),
/// whose terms do not cancel (R_C ~ log(p)/sqrt(p) << R_F) and whose R_J has a moderate q.
///
/// The reduction runs on the arguments scaled by 4^-k so that the largest of x, y, z is in
/// [1/4, 4) (exact; homogeneity scales the results back), so that its intermediate R_J, which
/// does not involve p, cannot overflow where the result itself does not (e.g. arguments ~1e-28
/// in float: R_J(x, y, z, q) ~ 1e42, R_J(x, y, z, p) ~ 1e35). If p overflows in the scaled
/// units (p / max > ~2^126 in float), R_J = 3 R_F / p to within (max / p)^(1/2) log(p / max).
template <class T, bool WithRf>
APSE_FUNC APSE_COLD RfRj<T> rj_reduce_p(T x, T y, T z, T p) noexcept {
    x = std::fabs(x), y = std::fabs(y), z = std::fabs(z);  // -0 -> +0: R_C(-0, .) would be NaN
    T top = max_of(max_of(x, y), z);
    int ex = 0;
    (void)std::frexp(top, &ex);
    const int k = ex / 2;
    x = std::ldexp(x, -2 * k), y = std::ldexp(y, -2 * k), z = std::ldexp(z, -2 * k);  // exact
    top = std::ldexp(top, -2 * k);
    const T ps = std::ldexp(p, -2 * k);  // may overflow: see above
    const T lo = min_of(min_of(x, y), z), mid = median_of(x, y, z);
    if (!is_finite(ps)) {
        const T rf = std::ldexp(rf_core(x, y, z), -k);  // R_F(v) = 2^-k R_F(4^-k v)
        return {rf, T(3) * rf / p};
    }
    const T shift = (mid - lo) * ((top - mid) / (ps - mid));  // y - q >= 0
    const T q = mid - shift;
    const RfRj<T> r = rj_window<T, true>(x, y, z, q, top, min_of(min_nonzero_of(x, y, z), q));
    const T rc = rc_core(top * (lo / mid), ps * (q / mid));
    // R_F(v) = 2^-k R_F(4^-k v), R_J(v) = 8^-k R_J(4^-k v)
    return {std::ldexp(r.rf, -k), std::ldexp((T(3) * (r.rf - rc) + shift * r.rj) / (ps - mid), -3 * k)};
}

template <class T, bool WithRf = false> APSE_FUNC RfRj<T> rj_core(T x, T y, T z, T p) noexcept;

/// n / (d1 d2 d3) for positive finite d_i, without the intermediate overflow or underflow of
/// the product (the exponents are taken out by frexp; ldexp rounds once at the end).
template <class T> APSE_FUNC T quotient_scaled(T n, T d1, T d2, T d3 = T(1)) noexcept {
    int e1 = 0, e2 = 0, e3 = 0;
    const T m = std::frexp(d1, &e1) * std::frexp(d2, &e2) * std::frexp(d3, &e3);
    return std::ldexp(n / m, -(e1 + e2 + e3));
}

/// R_J (and optionally R_F) for arguments spread too widely for one power-of-4 scaling to bring
/// them into the kernels' window (nonzero arguments spanning more than 2^592 in double, 2^64
/// in float; e.g. R_J(1e300, 1e-300, 1e-300, 0.5)). float is computed in double, whose window
/// holds every float argument. In double, with the nonzero arguments sorted, the largest ratio
/// G between neighbours is then at least 2^196 (at most three ratios): the arguments split into
/// a large group L and a small group S that the integrand's scales separate, and R_J reduces to
/// simpler integrals (docs/elliptic.md derives each; relative errors measured at 60 digits):
///   L = {v}, S = {y, z, p}:  R_J = 3 R_C(a^2, b^2) / sqrt(v), a = p + sqrt(y z),
///                            b = sqrt(p) (sqrt y + sqrt z)          (error ~ G^-1 log G)
///   L = {p}, S = {x, y, z}:  R_J = 3 R_F(x, y, z) / p               (~ G^-1/2 log G)
///   L = {y, z}, S = {x, p}:  R_J = 3 R_C(x, p) / sqrt(y z)          (~ G^-1/2)
///   L = {z, p}, S = {x, y}:  R_J = R_J(z, c, c, p) = 3 (R_C(z, c) - R_C(z, p)) / (p - c),
///                            c = ((sqrt x + sqrt y)/2)^2, R_C(z, c) = log(2 sqrt(z/c))/sqrt(z)
///                                                                   (~ G^-1)
///   L = {y, z, p}, S = {x}:  R_J = R_J(0, y, z, p), then again      (~ G^-1/2)
///   L = {x, y, z}, S = {p}:  R_J = R_J(x, y, z, p') + 3 log(p'/p) / (2 sqrt(x y z)),
///                            p' = p 2^j at 2^-100 of min(x, y, z), then again (~ 2^-100)
/// (The first from int_0^inf dt/((t+p) sqrt((t+y)(t+z))) = 2 R_C(a^2, b^2), the fourth as
/// c makes int_0^inf (1/sqrt((t+x)(t+y)) - 1/(t+c)) dt vanish.) Every term is positive. After
/// at most two reductions (the last two rows, each once) the arguments are within the window's
/// spread or a closed form applies. The S values are scaled by a power of 4 before they are
/// combined, so that products of subnormal arguments keep their precision.
template <class T, bool WithRf>
APSE_FUNC APSE_COLD RfRj<T> rj_wide(T x, T y, T z, T p) noexcept {
    if constexpr (sizeof(T) == sizeof(float)) {
        const RfRj<double> r = rj_core<double, WithRf>(double(x), double(y), double(z), double(p));
        return {T(r.rf), T(r.rj)};
    } else {
        x = std::fabs(x), y = std::fabs(y), z = std::fabs(z);  // -0 -> +0: R_C(-0, .) would be NaN
        RfRj<T> r{T(0), T(0)};
        if constexpr (WithRf) r.rf = rf_core(x, y, z);
        T a0 = min_of(min_of(x, y), z), a1 = median_of(x, y, z), a2 = max_of(max_of(x, y), z);
        T add = T(0);  // R_J(x, y, z, p) = add + R_J(a0, a1, a2, p)
        for (int iteration = 0; iteration < 3; ++iteration) {
            const T lo = a0 > T(0) ? a0 : a1;
            if (p > T(0x1p16) * a2) {
                if (rj_spread_ok(lo, a2)) {
                    r.rj = add + rj_reduce_p<T, false>(a0, a1, a2, p).rj;
                    return r;
                }
            } else if (rj_spread_ok(min_of(lo, p), max_of(a2, p))) {
                r.rj = add + rj_window<T, false>(a0, a1, a2, p, max_of(a2, p), min_of(lo, p)).rj;
                return r;
            }
            // The nonzero values in increasing order, p at position ip; split after position
            // `split` (S = v[0..split] and the zero, L = the rest), the largest ratio.
            const int n = a0 > T(0) ? 4 : 3;
            const T as[3] = {a0, a1, a2};
            const T* a = a0 > T(0) ? as : as + 1;
            const int ip = int(p > a[0]) + int(p > a[1]) + (n == 4 ? int(p > a[2]) : 0);
            T v[4];
            for (int i = 0, j = 0; i < n; ++i) v[i] = i == ip ? p : a[j++];
            int split = 0, gap = -1;
            for (int i = 0; i + 1 < n; ++i) {
                const int g = std::ilogb(v[i + 1]) - std::ilogb(v[i]);
                if (g > gap) gap = g, split = i;
            }
            const int large = n - 1 - split;  // the size of L
            const bool p_large = ip > split;
            // S's values scaled by 4^m (exact) so that the largest is in [1, 4)
            const int m = -(std::ilogb(v[split]) / 2);
            const T s0 = std::ldexp(a0, 2 * m), s1 = std::ldexp(a1, 2 * m), sp = std::ldexp(p, 2 * m);
            if (large == 1 && !p_large) {  // L = {a2}, S = {a0, a1, p}
                const T ra0 = std::sqrt(s0), ra1 = std::sqrt(s1), rp = std::sqrt(sp);
                const T aa = sp + ra0 * ra1, bb = rp * (ra0 + ra1);  // 4^m a, 4^m b
                T rc, den;  // R_C(aa^2, bb^2) = rc / den
                if (bb <= aa) {
                    // R_C(1, u^2) = log(2/u) (1 + O(u^2 log u)) for small u
                    const T u = bb / aa;
                    rc = u < T(0x1p-30) ? std::log(T(2) / u) : rc_core(T(1), u * u);
                    den = aa;
                } else {
                    const T u = aa / bb;  // u^2 may underflow: R_C(0, 1) = pi/2 to within u
                    rc = rc_core(u * u, T(1));
                    den = bb;
                }
                r.rj = add + std::ldexp(quotient_scaled(T(3) * rc, den, std::sqrt(a2)), 2 * m);
                return r;
            }
            if (large == 1) {  // L = {p}, S = {a0, a1, a2}
                r.rj = add + T(3) * rf_core(a0, a1, a2) / p;
                return r;
            }
            if (large == 2 && !p_large) {  // L = {a1, a2}, S = {a0, p}: R_C(v) = 2^m R_C(4^m v)
                r.rj = add + std::ldexp(quotient_scaled(T(3) * rc_core(s0, sp), std::sqrt(a1), std::sqrt(a2)), m);
                return r;
            }
            if (large == 2) {  // L = {a2, p}, S = {a0, a1}: sqrt(4^m c) = (sqrt(s0) + sqrt(s1)) / 2
                const T sa2 = std::sqrt(a2), sc = T(0.5) * (std::sqrt(s0) + std::sqrt(s1));
                const T rc_c = (log_ratio(sa2, sc) + T(m + 1) * ln2_v<T>) / sa2;
                r.rj = add + T(3) * (rc_c - rc_core(a2, p)) / p;  // p - c = p (c < 2^-196 p)
                return r;
            }
            if (p_large) {  // L = {a1, a2, p}, S = {a0}
                a0 = T(0);
                continue;
            }
            // L = {a0, a1, a2}, S = {p}
            const int j = std::ilogb(a0) - std::ilogb(p) - 100;
            add += quotient_scaled(T(1.5) * T(j) * ln2_v<T>, std::sqrt(a0),
                                   std::sqrt(a1), std::sqrt(a2));
            p = std::ldexp(p, j);
        }
        r.rj = quiet_nan<T>();  // not reached: at most two reductions
        return r;
    }
}

/// R_J (and optionally R_F) outside the kernels' window: rescaled (rj_window), or rj_wide.
template <class T, bool WithRf>
APSE_FUNC APSE_COLD RfRj<T> rj_outside_window(T x, T y, T z, T p) noexcept {
    const T mx = max_of(max_of(x, y), max_of(z, p)), mn = min_of(min_nonzero_of(x, y, z), p);
    if (rj_spread_ok(mn, mx)) return rj_window<T, WithRf>(x, y, z, p, mx, mn);
    return rj_wide<T, WithRf>(x, y, z, p);
}

/// R_J (and optionally R_F) for valid finite arguments whose largest one is in the kernels'
/// window (RjWindow): the AGM when one of x, y, z is zero (complete integral; 2-3x faster;
/// accurate for any smaller nonzero argument), else duplication, if the smallest argument is in
/// the window too (always when InWindow), else rj_outside_window.
template <class T, bool WithRf, bool InWindow>
APSE_FUNC RfRj<T> rj_dispatch(T x, T y, T z, T p) noexcept {
    // (Three call sites: with one, on pairs chosen by selects, g++ lays out the duplication
    // path 13% slower; in device code cel_rj is not inlined, so the copies cost nothing.)
    if (x == T(0) && cel_suits(y, z, p)) return cel_rj<T, WithRf>(y, z, p);
    if (y == T(0) && cel_suits(x, z, p)) return cel_rj<T, WithRf>(x, z, p);
    if (z == T(0) && cel_suits(x, y, p)) return cel_rj<T, WithRf>(x, y, p);
    if constexpr (!InWindow) {
        if (!(min_of(min_of(x, y), min_of(z, p)) >= rj_window_lo<T>()))
            return rj_outside_window<T, WithRf>(x, y, z, p);
    }
    return rj_core_unscaled<T, WithRf>(x, y, z, p);
}

/// R_J (and optionally R_F) for valid finite arguments: the kernels in their window (the
/// common case), rj_reduce_p when p exceeds x, y, z by far, else rescaled or rj_wide.
template <class T, bool WithRf>
APSE_FUNC RfRj<T> rj_core(T x, T y, T z, T p) noexcept {
    const T top = max_of(max_of(x, y), z);
    if (!(p > T(0x1p16) * top)) {
        const T mx = max_of(top, p);
        if (mx <= rj_window_hi<T>() && mx >= rj_window_lo<T>()) return rj_dispatch<T, WithRf>(x, y, z, p);
        return rj_outside_window<T, WithRf>(x, y, z, p);
    }
    if (!rj_spread_ok(min_nonzero_of(x, y, z), top)) return rj_wide<T, WithRf>(x, y, z, p);
    return rj_reduce_p<T, WithRf>(x, y, z, p);
}

/// R_D(x, y, z) for valid finite arguments (z > 0, at most one of x, y zero):
/// R_D = 4^-n A_n^(-3/2) series + 3 sum_m 4^-m / (sqrt z_m (z_m + lambda_m)).
template <class T> APSE_FUNC APSE_NOINLINE T rd_core(T x, T y, T z) noexcept {
    // R_D(0, y, z) = R_J(0, y, z, z): complete, by the AGM (via rj_core, which scales).
    if (x == T(0) || y == T(0)) return rj_core(x, y, z, z).rj;
    T scale = T(1);
    // The sum, or q below (<= the sum / tolerance, up to ~37x), would overflow:
    // R_D(v/64) = 512 R_D(v).
    if (!is_finite((x + y + T(3) * z) * (T(1) / rj_tolerance<T>()))) {
        // R_D(v/64) = 512 R_D(v), unless a small argument would lose bits in the subnormals (a
        // fuzz finding, R_D(1.7e38, 1e-45, 1e-45) in float: NaN): then R_D = R_J(x, y, z, z),
        // whose scaling handles any spread
        if (!(min_of(x, y) * T(0.015625) >= (sizeof(T) == sizeof(float) ? T(0x1p-126) : T(0x1p-1022))))
            return rj_core(x, y, z, z).rj;
        x *= T(0.015625), y *= T(0.015625), z *= T(0.015625);
        scale = T(1) / T(512);
    } else if (x + y + T(3) * z < tiny_sum<T>()) {  // 1/mean would overflow: R_D(v) = 8^k R_D(4^k v)
        x = std::ldexp(x, 2 * tiny_scale<T>()), y = std::ldexp(y, 2 * tiny_scale<T>()), z = std::ldexp(z, 2 * tiny_scale<T>());
        const T r = rd_core(x, y, z);
        return std::ldexp(r, 3 * tiny_scale<T>());
    }
    const T a0 = (x + y + T(3) * z) * T(0.2);
    const T dx = a0 - x, dy = a0 - y;
    T a = a0, sum = T(0);
    const T f = duplicate_until_converged(
        max_deviation(a0, x, y, z, z) * (T(1) / rj_tolerance<T>()), a0,
        [&](T fm) {
            const T z0 = z;
            const DuplicationStep<T> st = duplicate(x, y, z);
            sum += fm / (st.sz * (z0 + T(4) * st.l));
            a = T(0.25) * a + st.l;
        },
        [&] { return min_of(min_of(x, y), z); });
    const T s = f / a;
    const T X = dx * s, Y = dy * s, Z = -(X + Y) * (T(1) / T(3));
    return scale * (rj_tail(X, Y, Z, Z) * (f / (a * std::sqrt(a))) + T(3) * sum);
}

/// Carlson domain: all >= 0 and finite, at most one of them zero.
template <class T> APSE_FUNC bool carlson_args_ok(T x, T y, T z) noexcept {
    // (the maximum, not the sum, is tested: the sum of large finite arguments may overflow)
    return x >= T(0) && y >= T(0) && z >= T(0) && detail::is_finite(detail::max_of(detail::max_of(x, y), z)) &&
           int(x == T(0)) + int(y == T(0)) + int(z == T(0)) <= 1;
}

/// R_J(x, y, z, p) with its domain checked (NaN outside): the kernel behind apse::carlson_rj, the
/// one the solid angle and the cumulative areas call.
template <class T> APSE_FUNC T rj_impl(T x, T y, T z, T p) noexcept {
    if (!(carlson_args_ok(x, y, z) && p > T(0) && detail::is_finite(p))) return detail::quiet_nan<T>();
    return rj_core(x, y, z, p).rj;
}

}  // namespace detail
}  // namespace apse
