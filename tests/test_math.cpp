// Tests of math.hpp (the public constants) and detail/math.hpp: the guarded scalar helpers and the
// bracketed Newton–bisection root finder.
#include <apse/math.hpp>

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

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
