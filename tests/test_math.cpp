// Tests of math.hpp (the public constants) and detail/math.hpp: the guarded scalar helpers and the
// bracketed Newton–bisection root finder; the per-sample pieces written without branches
// (detail/polar.hpp fold_quadrant, detail/math.hpp).
#include <apse/math.hpp>
#include <apse/detail/math.hpp>
#include <apse/detail/polar.hpp>

#include "support/catch.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

TEMPLATE_TEST_CASE("constants and predicates", "[math]", float, double) {
    using T = TestType;
    CHECK(apse::epsilon<T>() == std::numeric_limits<T>::epsilon());
    CHECK(apse::pi_v<T> == T(std::acos(-1.0L)));
    CHECK(apse::two_pi_v<T> == T(2) * apse::pi_v<T>);
    CHECK(apse::detail::is_nan(apse::quiet_nan<T>()));
    CHECK_FALSE(apse::detail::is_nan(T(1)));
    CHECK(apse::detail::is_finite(T(1)));
    CHECK_FALSE(apse::detail::is_finite(std::numeric_limits<T>::infinity()));
    CHECK_FALSE(apse::detail::is_finite(-std::numeric_limits<T>::infinity()));
    CHECK_FALSE(apse::detail::is_finite(apse::quiet_nan<T>()));
    CHECK(apse::detail::is_finite(std::numeric_limits<T>::max()));
    CHECK(apse::detail::is_finite(std::numeric_limits<T>::denorm_min()));
}

TEMPLATE_TEST_CASE("NaN and infinity predicates read bits: they hold under -ffast-math", "[math][robust]", float, double) {
    using T = TestType;
    // Through volatile so the compiler cannot fold them: with -ffinite-math-only, `x != x` and
    // std::isnan(x) become false and std::isfinite(x) true whatever x holds at run time.
    const volatile T nan = std::numeric_limits<T>::quiet_NaN(), neg_nan = -std::numeric_limits<T>::quiet_NaN();
    const volatile T inf = std::numeric_limits<T>::infinity(), big = std::numeric_limits<T>::max();
    const volatile T tiny = std::numeric_limits<T>::denorm_min(), zero = T(0);
    CHECK(apse::detail::is_nan(T(nan)));
    CHECK(apse::detail::is_nan(T(neg_nan)));
    CHECK_FALSE(apse::detail::is_finite(T(nan)));
    CHECK_FALSE(apse::detail::is_nan(T(inf)));
    CHECK_FALSE(apse::detail::is_finite(T(inf)));
    CHECK_FALSE(apse::detail::is_finite(-T(inf)));
    CHECK(apse::detail::is_finite(T(big)));
    CHECK(apse::detail::is_finite(-T(big)));
    CHECK(apse::detail::is_finite(T(tiny)));
    CHECK(apse::detail::is_finite(T(zero)));
    CHECK_FALSE(apse::detail::is_nan(T(zero)));
    CHECK_FALSE(apse::detail::is_nan(-T(big)));
}

TEMPLATE_TEST_CASE("guarded functions stay in their domain", "[math]", float, double) {
    using T = TestType;
    CHECK(apse::detail::safe_sqrt(T(-1e-30)) == T(0));
    CHECK(apse::detail::safe_sqrt(T(4)) == T(2));
    CHECK(apse::detail::is_nan(apse::detail::safe_sqrt(apse::quiet_nan<T>())));
    CHECK(apse::detail::clamp(T(2), T(0), T(1)) == T(1));
    CHECK(apse::detail::clamp(T(-2), T(0), T(1)) == T(0));
    CHECK(apse::detail::clamp(apse::quiet_nan<T>(), T(0), T(1)) == T(0));
    CHECK(apse::detail::min_of(T(1), T(2)) == T(1));
    CHECK(apse::detail::max_of(T(1), T(2)) == T(2));
    CHECK(apse::detail::sqr(T(-3)) == T(9));
}

TEMPLATE_TEST_CASE("root finder converges, stays bracketed and terminates", "[math]", float, double) {
    using T = TestType;
    // sqrt(2) as the root of x^2 - 2 on [0, 2]: Newton converges quadratically.
    int calls = 0;
    auto square = [&calls](T x, T& value, T& derivative) {
        ++calls;
        value = x * x - T(2);
        derivative = T(2) * x;
    };
    const auto r = apse::detail::find_root_bracketed(square, T(0), T(2), T(1), T(4) * apse::epsilon<T>(), 50);
    CHECK(std::fabs(r.x - std::sqrt(T(2))) <= T(2) * apse::epsilon<T>());
    CHECK(r.iterations <= 6);
    CHECK(calls == r.iterations + 1);

    // Tolerance 0 cannot be met (x*x - 2 never rounds to 0 near sqrt(2)): the finder must stop
    // when the Newton step drops below an ulp instead of bisecting away from the root.
    const auto z = apse::detail::find_root_bracketed(square, T(0), T(2), T(1), T(0), 60);
    CHECK(std::fabs(z.x - std::sqrt(T(2))) <= T(2) * apse::epsilon<T>());
    CHECK(z.iterations <= 8);

    // A wrong derivative (0 here) must fall back to bisection and still converge.
    auto flat = [](T x, T& value, T& derivative) {
        value = x - T(0.3);
        derivative = T(0);
    };
    const auto b = apse::detail::find_root_bracketed(flat, T(0), T(1), T(0.9), T(0), 200);
    CHECK(std::fabs(b.x - T(0.3)) <= T(4) * apse::epsilon<T>());

    // NaN values: the result stays inside the bracket and the loop ends at the cap.
    auto broken = [](T, T& value, T& derivative) {
        value = apse::quiet_nan<T>();
        derivative = apse::quiet_nan<T>();
    };
    const auto n = apse::detail::find_root_bracketed(broken, T(0), T(1), T(0.5), T(1e-3), 10);
    CHECK(n.x >= T(0));
    CHECK(n.x <= T(1));

    // A function with no root in the bracket: bounded work (bisection towards the nearer end).
    int capped_calls = 0;
    auto positive = [&capped_calls](T x, T& value, T& derivative) {
        ++capped_calls;
        value = x + T(1);
        derivative = T(1);
    };
    const auto p = apse::detail::find_root_bracketed(positive, T(0), T(1), T(0.5), T(0), 20);
    CHECK(p.x >= T(0));
    CHECK(p.x <= T(1e-5));  // 20 halvings of 0.5
    CHECK(capped_calls <= 21);
}

TEMPLATE_TEST_CASE("fold_quadrant: quadrant signs and reflected fraction, without branches", "[math][quadrant]", float, double) {
    using T = TestType;
    const long double eps = apse::epsilon<T>();
    // u1 on a grid (with the quadrant boundaries and their neighbours): the reference in long
    // double from the definition, q = min(floor(4 u1), 3), f = 4 u1 − q, 1 − f in odd quadrants.
    std::vector<T> us;
    for (int i = 0; i <= 4096; ++i) us.push_back(T(i) / T(4096));
    for (T b : {T(0.25), T(0.5), T(0.75), T(1)}) {
        us.push_back(std::nextafter(b, T(0)));
        if (b < T(1)) us.push_back(std::nextafter(b, T(1)));
    }
    us.push_back(std::numeric_limits<T>::denorm_min());
    for (const T u : us) {
        const long double s = 4.0L * u;
        const int q = std::min(int(std::floor(s)), 3);
        const long double f_ref = (q & 1) ? 1.0L - (s - q) : s - q;
        const auto fold = apse::detail::fold_quadrant(u);
        // exact from u1 = 1/4 on (4 u1 − 2 and the reflections are exact there); below, one
        // rounding of 4 u1 − 2 (an ulp of 2 at most: 2 eps) carries into f
        const long double tol = u >= T(0.25) ? 0.0L : 2 * eps;
        CHECK(std::fabs(fold.fraction - f_ref) <= tol);
        if (f_ref > 0 && f_ref < 1) {  // off the axes, where the signs matter
            CHECK(fold.sign_x == ((q == 1 || q == 2) ? T(-1) : T(1)));
            CHECK(fold.sign_y == (q >= 2 ? T(-1) : T(1)));
        }
        // and back: unfold_quadrant_fraction of the quadrant of the signs
        const int q_back = fold.sign_y > 0 ? (fold.sign_x > 0 ? 0 : 1) : (fold.sign_x < 0 ? 2 : 3);
        if (f_ref > 0 && f_ref < 1) CHECK(std::fabs(apse::detail::unfold_quadrant_fraction(q_back, fold.fraction) - u) <= 2 * eps);
        // the same from the fold alone, without branches: one more rounding, of a sum below 4
        // (half an ulp of 4, 2 eps, quartered by the exact × 1/4) on top of the fraction's
        // error above: within 2 eps
        if (f_ref > 0 && f_ref < 1) CHECK(std::fabs(apse::detail::unfold_quadrant(fold) - u) <= 2 * eps);
    }
}

TEMPLATE_TEST_CASE("sin_cos_quarter_turn against the C library in long double", "[math][trig]", float, double) {
    using T = TestType;
    const long double eps = apse::epsilon<T>();
    // Two sine polynomials on the whole quarter turn (the cosine as the sine of 1 − q): measured
    // 1.9 eps (double) / 1.6 eps (float) absolute at most over 2e6 points (also with FMA
    // contraction and under clang); 2 eps allows for the reference's own rounding of q pi/2 in
    // long double (~1e-19). A polynomial one term short, or a wrong coefficient, is far beyond it.
    long double worst = 0;
    std::vector<T> qs;
    for (int i = 0; i <= 20000; ++i) qs.push_back(T(i) / T(20000));
    for (T b : {T(0.5), T(1)}) qs.push_back(std::nextafter(b, T(0)));
    qs.push_back(std::nextafter(T(0.5), T(1)));
    for (const T q : qs) {
        const auto sc = apse::detail::sin_cos_quarter_turn(q);
        const long double x = q * (std::acos(-1.0L) / 2);
        worst = std::max({worst, std::fabs(sc.s - std::sin(x)), std::fabs(sc.c - std::cos(x))});
        CHECK(sc.s >= T(0));
        CHECK(sc.c >= T(0));
    }
    CHECK(worst <= 2 * eps);
}

TEMPLATE_TEST_CASE("arc_ratio against atan2 in long double", "[math][trig]", float, double) {
    using T = TestType;
    // theta1 log-spaced from 1e-12 to pi/2, theta2 = rho theta1 for rho in [0, 1], the sines and
    // cosines rounded to T; the reference is atan2 of those rounded values in long double. The
    // bound: Hastings' atan is within 2e-8 absolute per angle, and its error relative to the
    // angle is smaller still for small angles, so the ratio stays within ~4e-8 in double; in float
    // the rounding of the quotient s/(1 + c) and of the polynomial (a few eps relative per angle)
    // dominates: 4 eps = 4.8e-7. The table coordinate it gives needs only ~1e-4 (docs/tabulated.md).
    const long double half_pi = std::acos(-1.0L) / 2;
    long double worst = 0;
    for (int i = 0; i <= 400; ++i) {
        const long double t1 = i == 400 ? half_pi : 1e-12L * std::pow(half_pi / 1e-12L, i / 400.0L);
        for (int j = 0; j <= 50; ++j) {
            const long double t2 = t1 * j / 50;
            const T s1 = T(std::sin(t1)), c1 = T(std::cos(t1)), s2 = T(std::sin(t2)), c2 = T(std::cos(t2));
            const long double ref = std::atan2((long double)s2, (long double)c2) / std::atan2((long double)s1, (long double)c1);
            const T got = apse::detail::arc_ratio(s1, c1, s2, c2);
            worst = std::max(worst, std::fabs(got - ref));
        }
    }
    INFO("max |arc_ratio - ratio| = " << double(worst));
    CHECK(worst <= (sizeof(T) == 4 ? 4 * apse::epsilon<float>() : 4e-8L));
    CHECK(apse::detail::arc_ratio(T(0), T(1), T(0), T(1)) == T(0));  // theta1 = 0
    WARN("arc_ratio: max error " << double(worst));
}


TEMPLATE_TEST_CASE("cube_root_approx against cbrt in long double", "[math]", float, double) {
    using T = TestType;
    // x log-spaced over the documented range [2^-100, 2^100] (and its ends). Bound: the bit
    // estimate is within 3.2e-2; one Halley step (float) leaves ~0.6 (3.2e-2)^3 = 2.1e-5 (measured
    // 2.09e-5; 2.2e-5 allows for FMA contraction and the float rounding of the step), two
    // (double) ~(2.1e-5)^3, below the rounding of the steps themselves: measured 6.1e-15, 1e-14
    // allows for FMA contraction. A wrong magic constant or a missing step is
    // orders of magnitude beyond either bound.
    long double worst = 0;
    for (int i = 0; i <= 200000; ++i) {
        const T x = T(std::ldexp(1.0L, -100) * std::pow(2.0L, 200.0L * i / 200000));
        const long double ref = std::cbrt((long double)x);
        worst = std::max(worst, std::fabs(apse::detail::cube_root_approx(x) / ref - 1));
    }
    INFO("max relative error " << double(worst));
    CHECK(worst <= (sizeof(T) == 4 ? 2.2e-5L : 1e-14L));
    CHECK(apse::detail::cube_root_approx(T(8)) == Approx(2).epsilon(sizeof(T) == 4 ? 2.2e-5 : 1e-14));
}
