// Tests of apse's elliptic integrals (include/apse/elliptic.hpp): the mpmath reference tables,
// Carlson's published values, identities, the m = k^2 convention, domain errors and
// pathological inputs. Every test runs for float and double.
#include <apse/elliptic.hpp>
#include <apse/math.hpp>

#include "support/catch.hpp"

#include "support/reference_table.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <string>
#include <type_traits>
#include <vector>

namespace {

// Template argument deduction from the arguments' type.
static_assert(std::is_same<decltype(apse::carlson_rf(1.0, 2.0, 0.0)), double>::value, "");
static_assert(std::is_same<decltype(apse::carlson_rf(1.f, 2.f, 3.f)), float>::value, "");
static_assert(std::is_same<decltype(apse::ellint_pi(-2.f, 0.5f, 0.5f)), float>::value, "");

template <class T> constexpr double eps() { return double(apse::epsilon<T>()); }

double rel_error(double v, double ref) {
    if (ref == 0) return v == 0 ? 0 : std::numeric_limits<double>::infinity();
    const double e = std::fabs(v - ref) / std::fabs(ref);
    return e == e ? e : std::numeric_limits<double>::infinity();  // NaN counts as infinite
}

// ---- reference tables (tools/gen_elliptic_reference.py) ---------------------------------------

using Row = apse_test::ReferenceRow;

// The table tests/data/elliptic/<name>.csv (support/reference_table.hpp): every row must have
// n_in inputs, the value and the category.
std::vector<Row> read_table(const std::string& name, std::size_t n_in) {
    const std::string path = std::string(APSE_TEST_DATA_DIR) + "/elliptic/" + name + ".csv";
    INFO("reference table " << path);
    return apse_test::read_reference_table(path, n_in, [&](std::size_t field_count, const std::string&) {
        REQUIRE(field_count == n_in + 2);
    });
}

// The largest relative error of f over a table must stay within budget * eps(T). The inputs
// are exact in float and the reference carries 30 digits (its own error is ~1e-30), so the
// budget is the whole tolerance: nothing is added for the reference or for input rounding.
template <class T, class F>
void check_table(const std::string& name, std::size_t n_in, double budget, F&& f) {
    const std::vector<Row> rows = read_table(name, n_in);
    REQUIRE(rows.size() >= 300);  // an empty or missing table fails
    double worst = 0;
    std::string worst_line;
    for (const Row& r : rows) {
        T a[4] = {};
        for (std::size_t i = 0; i < n_in; ++i) {
            a[i] = T(r.in[i]);
            REQUIRE(double(a[i]) == r.in[i]);  // exact in T
        }
        const double e = rel_error(double(f(a)), double(r.ref));
        if (e > worst || e != e) {
            worst = e;
            worst_line = r.line;
        }
    }
    INFO(name << ": worst row " << worst_line << " -> " << worst / eps<T>() << " eps");
    CHECK(worst <= budget * eps<T>());
}

}  // namespace

TEMPLATE_TEST_CASE("elliptic: reference tables", "[elliptic]", float, double) {
    using T = TestType;
    check_table<T>("carlson_rf", 3, 4, [](const T* a) { return apse::carlson_rf(a[0], a[1], a[2]); });
    check_table<T>("carlson_rd", 3, 8, [](const T* a) { return apse::carlson_rd(a[0], a[1], a[2]); });
    check_table<T>("carlson_rj", 4, 8,
                   [](const T* a) { return apse::carlson_rj(a[0], a[1], a[2], a[3]); });
    check_table<T>("carlson_rc", 2, 4, [](const T* a) { return apse::carlson_rc(a[0], a[1]); });
    check_table<T>("ellint_f", 2, 8, [](const T* a) { return apse::ellint_f(a[0], a[1]); });
    check_table<T>("ellint_pi", 3, 16, [](const T* a) { return apse::ellint_pi(a[0], a[1], a[2]); });
    check_table<T>("comp_ellint_k", 1, 8, [](const T* a) { return apse::comp_ellint_k(a[0]); });
    check_table<T>("comp_ellint_pi", 2, 16, [](const T* a) { return apse::comp_ellint_pi(a[0], a[1]); });
}

TEMPLATE_TEST_CASE("elliptic: Carlson 1995 test values", "[elliptic]", float, double) {
    using T = TestType;
    // Carlson, Numer. Algorithms 10 (1995), table of test values (14 digits; each re-checked
    // with mpmath). The tolerance is the printed precision, or the budget for float.
    const double tol4 = std::max(1e-13, 4 * eps<T>()), tol8 = std::max(1e-13, 8 * eps<T>());
    CHECK(rel_error(apse::carlson_rf(T(1), T(2), T(0)), 1.3110287771461) <= tol4);
    CHECK(rel_error(apse::carlson_rf(T(2), T(3), T(4)), 0.58408284167715) <= tol4);
    CHECK(rel_error(apse::carlson_rc(T(0), T(0.25)), 3.1415926535898) <= tol4);
    CHECK(rel_error(apse::carlson_rc(T(2.25), T(2)), 0.69314718055995) <= tol4);
    CHECK(rel_error(apse::carlson_rj(T(0), T(1), T(2), T(3)), 0.77688623778582) <= tol8);
    CHECK(rel_error(apse::carlson_rj(T(2), T(3), T(4), T(5)), 0.14297579667157) <= tol8);
    CHECK(rel_error(apse::carlson_rd(T(0), T(2), T(1)), 1.7972103521034) <= tol8);
    CHECK(rel_error(apse::carlson_rd(T(2), T(3), T(4)), 0.16510527294261) <= tol8);
}

TEMPLATE_TEST_CASE("elliptic: the parameter convention is m = k^2", "[elliptic]", float, double) {
    using T = TestType;
    // K(m = 0.5) = 1.8540746773013719; with the modulus k = 0.5 it would be 1.6857503548125961.
    CHECK(rel_error(apse::comp_ellint_k(T(0.5)), 1.8540746773013719) <= 8 * eps<T>());
    CHECK(rel_error(apse::comp_ellint_k(T(0.25)), 1.6857503548125961) <= 8 * eps<T>());
    // F(1|0.5) (mpmath ellipf(1, 0.5)) and Pi(0.25;1|0.5) (ellippi(0.25, 1, 0.5)): the sign of
    // n is DLMF's (Pi grows with n).
    CHECK(rel_error(apse::ellint_f(T(1), T(0.5)), 1.0832167728451688) <= 8 * eps<T>());
    CHECK(rel_error(apse::ellint_pi(T(0.25), T(1), T(0.5)), 1.1716354216186772) <= 16 * eps<T>());
}

TEMPLATE_TEST_CASE("elliptic: identities", "[elliptic]", float, double) {
    using T = TestType;
    const double e = eps<T>();
    const T vals[] = {T(0), T(1e-3), T(0.25), T(0.7), T(1), T(3.5), T(40), T(1e4)};
    for (T x : vals)
        for (T y : vals)
            for (T z : vals) {
                if ((x == 0) + (y == 0) + (z == 0) > 1) continue;
                INFO("x, y, z = " << x << ", " << y << ", " << z);
                const T rf = apse::carlson_rf(x, y, z);
                // symmetry
                CHECK(rel_error(apse::carlson_rf(y, z, x), rf) <= 8 * e);
                CHECK(rel_error(apse::carlson_rf(z, y, x), rf) <= 8 * e);
                // homogeneity with an exact scale (4^3 and 4^-2): R_F(l v) = l^(-1/2) R_F(v)
                CHECK(rel_error(apse::carlson_rf(T(64) * x, T(64) * y, T(64) * z), rf / 8) <= 8 * e);
                CHECK(rel_error(apse::carlson_rf(x / 16, y / 16, z / 16), rf * 4) <= 8 * e);
                if (z > 0) {
                    const T rd = apse::carlson_rd(x, y, z);
                    CHECK(rel_error(apse::carlson_rd(y, x, z), rd) <= 16 * e);
                    CHECK(rel_error(apse::carlson_rd(T(4) * x, T(4) * y, T(4) * z), rd / 8) <= 16 * e);
                    CHECK(rel_error(apse::carlson_rj(x, y, z, z), rd) <= 16 * e);
                }
                for (T p : {T(1e-3), T(0.6), T(2), T(300)}) {
                    const T rj = apse::carlson_rj(x, y, z, p);
                    CHECK(rel_error(apse::carlson_rj(z, x, y, p), rj) <= 16 * e);
                    CHECK(rel_error(apse::carlson_rj(y, z, x, p), rj) <= 16 * e);
                    CHECK(rel_error(apse::carlson_rj(x / 4, y / 4, z / 4, p / 4), rj * 8) <= 16 * e);
                }
            }
    for (T x : vals) {
        if (x == 0) continue;
        CHECK(rel_error(apse::carlson_rf(x, x, x), 1 / std::sqrt(double(x))) <= 4 * e);
        CHECK(rel_error(apse::carlson_rd(x, x, x), std::pow(double(x), -1.5)) <= 8 * e);
        CHECK(rel_error(apse::carlson_rj(x, x, x, x), std::pow(double(x), -1.5)) <= 8 * e);
        for (T y : vals) {
            CHECK(rel_error(apse::carlson_rc(y, x), apse::carlson_rf(y, x, x)) <= 8 * e);
        }
    }
    for (T m : {T(-1e4), T(-3), T(-0.5), T(0), T(0.3), T(0.9), T(0.999)}) {
        INFO("m = " << m);
        for (T phi : {T(1e-6), T(0.1), T(0.7), T(1.2), T(1.5)}) {
            const T f = apse::ellint_f(phi, m);
            CHECK(apse::ellint_f(-phi, m) == -f);  // odd in phi
            CHECK(rel_error(apse::ellint_pi(T(0), phi, m), f) <= 16 * e);
            for (T n : {T(-1e4), T(-2), T(-0.2), T(0.5)})
                CHECK(apse::ellint_pi(n, -phi, m) == -apse::ellint_pi(n, phi, m));
        }
        // K(m) = F(pi/2|m): T(pi/2) differs from pi/2 by < eps/2 relative, which moves F by at
        // most (eps pi/4)/sqrt(1 - m).
        const double slack = e * std::max(1.0, 1 / std::sqrt(1 - double(m)));
        const T k = apse::comp_ellint_k(m);
        CHECK(rel_error(apse::ellint_f(apse::half_pi_v<T>, m), k) <= 16 * e + slack);
        CHECK(rel_error(apse::comp_ellint_pi(T(0), m), k) <= 16 * e);
        for (T n : {T(-1e4), T(-2), T(-0.2), T(0.5)}) {
            const double slack_n = slack * std::max(1.0, 1 / (1 - double(n)));
            CHECK(rel_error(apse::ellint_pi(n, apse::half_pi_v<T>, m), apse::comp_ellint_pi(n, m)) <=
                  32 * e + 4 * slack_n);
        }
        // periodic extension: F(phi + pi) = F(phi) + 2K
        CHECK(rel_error(apse::ellint_f(T(0.5) + apse::pi_v<T>, m),
                        double(apse::ellint_f(T(0.5), m)) + 2 * double(k)) <= 8 * e + 8 * slack);
    }
}

TEMPLATE_TEST_CASE("elliptic: outside the domain the result is NaN", "[elliptic][robust]", float, double) {
    using T = TestType;
    const T nan = std::numeric_limits<T>::quiet_NaN(), inf = std::numeric_limits<T>::infinity();
    auto is_nan = [](T v) { return apse::detail::is_nan(v); };  // bit test: `v != v` folds to false under -ffast-math
    // negative arguments, two zeros, NaN and infinities
    CHECK(is_nan(apse::carlson_rf(T(-1), T(1), T(1))));
    CHECK(is_nan(apse::carlson_rf(T(0), T(0), T(1))));
    CHECK(is_nan(apse::carlson_rf(nan, T(1), T(1))));
    CHECK(is_nan(apse::carlson_rf(inf, T(1), T(1))));
    CHECK(is_nan(apse::carlson_rd(T(1), T(1), T(0))));
    CHECK(is_nan(apse::carlson_rd(T(0), T(0), T(1))));
    CHECK(is_nan(apse::carlson_rd(T(1), T(-1), T(1))));
    CHECK(is_nan(apse::carlson_rd(T(1), T(1), inf)));
    CHECK(is_nan(apse::carlson_rj(T(1), T(1), T(1), T(0))));   // p = 0
    CHECK(is_nan(apse::carlson_rj(T(1), T(1), T(1), T(-1))));  // p < 0: principal value, unsupported
    CHECK(is_nan(apse::carlson_rj(T(0), T(0), T(1), T(1))));
    CHECK(is_nan(apse::carlson_rj(T(1), T(-2), T(1), T(1))));
    CHECK(is_nan(apse::carlson_rj(T(1), T(1), T(1), nan)));
    CHECK(is_nan(apse::carlson_rj(T(1), T(1), inf, T(1))));
    CHECK(is_nan(apse::carlson_rc(T(1), T(0))));
    CHECK(is_nan(apse::carlson_rc(T(1), T(-1))));
    CHECK(is_nan(apse::carlson_rc(T(-1), T(1))));
    CHECK(is_nan(apse::carlson_rc(nan, T(1))));
    CHECK(is_nan(apse::carlson_rc(T(1), inf)));
    // Legendre: m >= 1 (also where F could be defined, |sin phi| < 1/sqrt m), n >= 1, NaN, inf
    CHECK(is_nan(apse::ellint_f(T(0.3), T(1))));
    CHECK(is_nan(apse::ellint_f(T(0.3), T(2))));
    CHECK(is_nan(apse::ellint_f(nan, T(0.5))));
    CHECK(is_nan(apse::ellint_f(inf, T(0.5))));
    CHECK(is_nan(apse::ellint_f(T(0.3), -inf)));
    CHECK(is_nan(apse::ellint_pi(T(1), T(0.3), T(0.5))));
    CHECK(is_nan(apse::ellint_pi(T(2), T(0.3), T(0.5))));
    CHECK(is_nan(apse::ellint_pi(T(0.5), T(0.3), T(1))));
    CHECK(is_nan(apse::ellint_pi(-inf, T(0.3), T(0.5))));
    CHECK(is_nan(apse::ellint_pi(T(0.5), nan, T(0.5))));
    CHECK(is_nan(apse::comp_ellint_k(T(1))));
    CHECK(is_nan(apse::comp_ellint_k(T(1.5))));
    CHECK(is_nan(apse::comp_ellint_k(nan)));
    CHECK(is_nan(apse::comp_ellint_k(-inf)));
    CHECK(is_nan(apse::comp_ellint_pi(T(1), T(0.5))));
    CHECK(is_nan(apse::comp_ellint_pi(T(0.5), T(1))));
    CHECK(is_nan(apse::comp_ellint_pi(nan, T(0.5))));
}

TEST_CASE("elliptic: widely spread arguments (up to the whole exponent range) stay accurate",
          "[elliptic][robust][extreme]") {
    // Arguments whose ratio exceeds ~4^16 once needed more duplication steps than the count made
    // from the smallest argument allowed (NaN), and huge |n|, |m| overflowed an intermediate
    // product in Pi (inf). References: mpmath 1.3 elliprf/elliprd/elliprj/ellipf/ellippi at 40
    // digits for these exact inputs. Budgets: those of the reference tables (4 eps R_F, 8 eps
    // R_D, R_J, F, 16 eps Pi). Tag [extreme]: not kept under -ffast-math, whose flush-to-zero and
    // reassociation lose the intermediates at the ends of the exponent range (inf measured).
    struct Row {
        double x, y, z, rf, rd, rj;  // rj = R_J(x, y, z, 1)
    };
    const Row rows[] = {
        {1, 1e200, 1, 2.3095165647996451719e-98, 1.5000000000000000227e-100, 1.5000000000000000227e-100},
        {0, 1e300, 1, 3.4677405831022673414e-148, 2.9999999999999999212e-150, 2.9999999999999999212e-150},
        {2, 3, 1e100, 1.1536933317604158507e-48, 3.4310799952812474977e-148, 9.2401385793744498426e-51},
    };
    const double e = eps<double>();
    for (const Row& r : rows) {
        INFO("x, y, z = " << r.x << ", " << r.y << ", " << r.z);
        CHECK(rel_error(apse::carlson_rf(r.x, r.y, r.z), r.rf) <= 4 * e);
        CHECK(rel_error(apse::carlson_rd(r.x, r.y, r.z), r.rd) <= 8 * e);
        CHECK(rel_error(apse::carlson_rj(r.x, r.y, r.z, 1.0), r.rj) <= 8 * e);
    }
    CHECK(rel_error(apse::carlson_rf(1e-300, 1.0, 1e300), 3.4677405831022673414e-148) <= 4 * e);
    CHECK(rel_error(apse::carlson_rj(1e-300, 1.0, 1e300, 1.0), 2.9999999999999999212e-150) <= 8 * e);
    CHECK(rel_error(apse::ellint_f(1.0, -1.7976931348623157e308), 2.6527309327542929806e-152) <= 8 * e);
    CHECK(rel_error(apse::ellint_pi(-1e200, 1.0, -1e200), 1.0000000000000000151e-100) <= 16 * e);
    CHECK(rel_error(apse::comp_ellint_pi(-1e200, -1e200), 1.0000000000000000151e-100) <= 16 * e);
    // The whole exponent range: scaling must not push the small arguments into the subnormals.
    const double big = std::numeric_limits<double>::max();
    CHECK(rel_error(apse::carlson_rj(0.0, big, 1.0, 1.0), 2.2375022193600621472e-154) <= 8 * e);
    CHECK(rel_error(apse::carlson_rd(big, 4.0, 1.7014118346046923e38), 1.3150856094050418967e-192) <= 8 * e);
    CHECK(rel_error(apse::comp_ellint_pi(-big, -big), 7.4583407312002071573e-155) <= 16 * e);
    CHECK(rel_error(apse::ellint_pi(-big, 1.0, -big), 7.4583407312002071573e-155) <= 16 * e);
    // n near -DBL_MAX with m < 0: |n| s c R_C(...) overflowed before its division (a fuzz finding).
    CHECK(rel_error(apse::ellint_pi(-1e308, 1.5, -1e-12), 1.5707963267948966106e-154) <= 16 * e);
    // |m| near DBL_MAX with n < -1/4: R_J(0, 1-m, 1, q) underflowed where (1-m) R_J does not (a
    // fuzz finding; mpmath, 60 digits).
    CHECK(rel_error(apse::comp_ellint_pi(-5080598558.875948, -1.7976931345577664e+308), 2.5687282962134502e-152) <= 16 * e);
    CHECK(rel_error(apse::ellint_pi(-5080598558.875948, -3.0, -1.7976931345577664e+308), -2.5687282962518808e-152) <=
          16 * e);
    // Every argument the smallest subnormal (fuzz findings: NaN, 1/mean overflowed; mpmath, 50
    // digits): R_F(d, d, d) = 1/sqrt(d), R_F(d, d, 2^1023) and R_F(2^-1070, 2^-1000, 2^1023) (the
    // 1/64 rescaling against overflow flushed the small ones), R_D beyond the range: inf.
    CHECK(rel_error(apse::carlson_rf(0x1p-1074, 0x1p-1074, 0x1p-1074), 4.4989137945431963828e+161) <= 4 * e);
    CHECK(rel_error(apse::carlson_rf(0x1p-1074, 0x1p-1074, 0x1p1023), 0x1.0131fa9e773b1p-502) <= 4 * e);
    CHECK(rel_error(apse::carlson_rf(0x1p-1070, 0x1p-1000, 0x1p1023), 0x1.f0beedadf9577p-503) <= 4 * e);
    CHECK(std::isinf(apse::carlson_rd(0x1p-1074, 0x1p-1074, 0x1p-1074)));
    CHECK(rel_error(apse::carlson_rd(0x1p1023, 0x1p-1074, 0x1p-1074), 0x1.0f876ccdf6cd9p+563) <= 8 * e);
    CHECK(rel_error(double(apse::carlson_rd(0x1p127f, 0x1p-149f, 0x1p-149f)), 0x1.0f876ccdf6cd9p+86) <= 8 * eps<float>());
    CHECK(rel_error(double(apse::carlson_rf(0x1p-149f, 0x1p-149f, 0x1p-149f)), 26713738906281537970891.923) <= 4 * eps<float>());
    CHECK(rel_error(double(apse::carlson_rf(0x1p-149f, 0x1p-149f, 1.7014118346046923e+38f)), 0x1.108302f53a277p-57) <=
          4 * eps<float>());
    // -0 is a valid zero argument: R_C(0, 2) = pi / (2 sqrt 2).
    CHECK(rel_error(apse::carlson_rc(-0.0, 2.0), 1.1107207345395915618) <= 4 * e);
    CHECK(rel_error(double(apse::carlson_rc(-0.0f, 2.0f)), 1.1107207345395915618) <= 4 * eps<float>());
    // float: the exact float inputs 1e38f = 9.9999996802856924651e37, 1e30f = 1.0000000150474662199e30,
    // -3e38f = -3.0000000054977557578e38, -1e30f
    const float ef = eps<float>();
    CHECK(rel_error(double(apse::carlson_rf(1.0f, 1e38f, 1.0f)), 4.4442264641902496615e-18) <= 4 * ef);
    CHECK(rel_error(double(apse::carlson_rd(1.0f, 1e38f, 1.0f)), 1.5000000239785736401e-19) <= 8 * ef);
    CHECK(rel_error(double(apse::carlson_rj(1.0f, 1e38f, 1.0f, 1.0f)), 1.5000000239785736401e-19) <= 8 * ef);
    CHECK(rel_error(double(apse::carlson_rd(1.0f, 1e30f, 1.0f)), 1.4999999887144004625e-15) <= 8 * ef);
    CHECK(rel_error(double(apse::ellint_f(1.0f, -3e38f)), 2.6027027953806862106e-18) <= 8 * ef);
    CHECK(rel_error(double(apse::ellint_pi(-1e30f, 1.0f, -1e30f)), 9.9999999247626697497e-16) <= 16 * ef);
}

TEST_CASE("elliptic: R_J with arguments spread over the whole exponent range", "[elliptic][robust][extreme]") {
    // tests/data/elliptic/carlson_rj_wide.csv (tools/gen_elliptic_reference.py): e.g.
    // R_J(1e300, 1e-300, 1e-300, 0.5), NaN before (a fuzz finding), one huge argument with the
    // others tiny in every position, p tiny or huge, two groups of arguments far apart; inputs
    // exact in double (wide_double) or float (wide_float), references normal numbers of that
    // type. Budget 8 eps, that of the R_J table: the reductions used there (rj_wide) err by
    // < 2^-98 relative, and their closed forms (R_C, R_F) stay within the table's errors. The
    // reference has 30 digits (nothing added for it).
    const std::vector<Row> rows = read_table("carlson_rj_wide", 4);
    REQUIRE(rows.size() >= 60);
    double worst_d = 0, worst_f = 0;
    std::size_t n_d = 0, n_f = 0;
    for (const Row& r : rows) {
        INFO(r.line);
        const double ref = double(r.ref);
        if (r.category == "wide_double") {
            const double e = rel_error(apse::carlson_rj(r.in[0], r.in[1], r.in[2], r.in[3]), ref) / eps<double>();
            CHECK(e <= 8);
            worst_d = std::max(worst_d, e);
            ++n_d;
        } else {
            REQUIRE(r.category == "wide_float");
            float a[4];
            for (int i = 0; i < 4; ++i) {
                a[i] = float(r.in[i]);
                REQUIRE(double(a[i]) == r.in[i]);  // exact in float
            }
            const double e = rel_error(double(apse::carlson_rj(a[0], a[1], a[2], a[3])), ref) / eps<float>();
            CHECK(e <= 8);
            worst_f = std::max(worst_f, e);
            ++n_f;
        }
    }
    CHECK(n_d >= 15);
    CHECK(n_f >= 40);
    std::printf("R_J wide table: %zu double rows, max %.2f eps; %zu float rows, max %.2f eps\n", n_d, worst_d, n_f,
                worst_f);
    // Beyond the type's range the result is inf (overflow) or 0 / subnormal (underflow), never
    // NaN (mpmath at 700 digits): R_J(1e300, 1e300, 1e300, 1e-300) = 2.1e-447,
    // R_J(1e-300, 1e-300, 2e-300, 1e-300) = 8.0e449; R_J(1e-300, 1e-300, 1e-300, 1e300) is normal.
    // float: R_J(1e36, 1e36, 1e36, 1e-36) ~ 2e-52, R_J(1e-30, 1e-30, 2e-30, 1e-30) ~ 8e44.
    CHECK(apse::carlson_rj(1e300, 1e300, 1e300, 1e-300) == 0.0);
    CHECK(std::isinf(apse::carlson_rj(1e-300, 1e-300, 2e-300, 1e-300)));
    CHECK(rel_error(apse::carlson_rj(1e-300, 1e-300, 1e-300, 1e300), 2.9999999999999998049e-150) <= 8 * eps<double>());
    CHECK(apse::carlson_rj(1e36f, 1e36f, 1e36f, 1e-36f) == 0.0f);
    // -0 is a valid zero argument on these paths too (a fuzz finding: R_C(-0, y) was NaN there;
    // mpmath at 800 digits): p >> x, y, z (the reduction of p), and the widest gap splitting.
    CHECK(rel_error(apse::carlson_rj(-0.0, 1e-300, 1e-300, 0.5), 9.4247779607693795973e+150) <= 8 * eps<double>());
    CHECK(rel_error(apse::carlson_rj(-0.0, 1e-300, 1e300, 1e-200), 3.4746720549078668556e+52) <= 8 * eps<double>());
    CHECK(std::isinf(apse::carlson_rj(1e-30f, 1e-30f, 2e-30f, 1e-30f)));
}

TEMPLATE_TEST_CASE("elliptic: pathological inputs return quickly, finite or NaN", "[elliptic][robust][denormals]",
                   float, double) {
    using T = TestType;
    using L = std::numeric_limits<T>;
    // Extremes of the exponent range mixed (incl. denormals and the largest finite value): every
    // call terminates (hard iteration caps) and returns a non-negative number, +inf where the
    // value overflows, or NaN — never a negative or garbage value, and never hangs.
    const T v[] = {T(0), L::denorm_min(), L::min(), T(1e-30), L::epsilon(), T(1), T(3),
                   T(1e30), L::max() / 4, L::max()};
    auto sane = [](T r) { return r != r || r >= T(0); };
    for (T x : v)
        for (T y : v)
            for (T z : v) {
                INFO("x, y, z = " << x << ", " << y << ", " << z);
                CHECK(sane(apse::carlson_rf(x, y, z)));
                CHECK(sane(apse::carlson_rd(x, y, z)));
                CHECK(sane(apse::carlson_rc(x, y)));
                for (T p : v) CHECK(sane(apse::carlson_rj(x, y, z, p)));
            }
    // Arguments near the largest finite value (whose sums overflow) are still valid.
    CHECK(rel_error(apse::carlson_rf(L::max(), L::max(), L::max()), 1 / std::sqrt(double(L::max()))) <=
          4 * eps<T>());
    CHECK(rel_error(apse::carlson_rc(L::max(), L::max()), 1 / std::sqrt(double(L::max()))) <= 4 * eps<T>());
    CHECK(rel_error(apse::carlson_rf(L::max(), L::max() / 2, T(0)),
                    double(apse::carlson_rf(T(4), T(2), T(0))) / std::sqrt(double(L::max()) / 4)) <=
          8 * eps<T>());
    // In the finite-result range the values are still accurate (homogeneity at the extremes).
    // (4^k scales, as extreme as the type allows while R_J ~ 8^-k stays a normal number.)
    const int ks[] = {-40, -20, -10, 10, 20, 40};
    for (int k0 : ks) {
        const int k = sizeof(T) == sizeof(float) ? k0 : 7 * k0;
        const T s = std::ldexp(T(1), 2 * k);
        const double ref_rf = 0.58408284167715170669, ref_rj = 0.14297579667156753833;
        CHECK(rel_error(double(apse::carlson_rf(2 * s, 3 * s, 4 * s)) * std::ldexp(1.0, k), ref_rf) <=
              4 * eps<T>());
        CHECK(rel_error(double(apse::carlson_rj(2 * s, 3 * s, 4 * s, 5 * s)) * std::ldexp(1.0, 3 * k),
                        ref_rj) <= 8 * eps<T>());
    }
    // p >> max(x, y, z) with tiny x, y, z (rj_core's reduction, whose intermediate R_J(x, y, z, q)
    // overflowed float before it was scaled: inf and NaN were returned for representable values).
    // References: mpmath elliprj at 30 digits for these exact float inputs.
    struct PLarge {
        float x, y, z, p;
        double ref;
    };
    const PLarge p_large[] = {
        {0x1.22c4c4p-103f, 0x1.eb36fp-89f, 0x1.3a609ap-93f, 0x1.9938aep-71f, 2.3742659522231772732e+35},
        {0x1.cp-146f, 0x1.5p-145f, 0x1.dp-145f, 0x1p+0f, 1.7575083916476261875e+22},  // subnormal x, y, z
        {0x1.4484cp-99f, 0x1.e6c72p-99f, 0x1.4484cp-98f, 0x1.2a05f2p+33f, 175224.85222531977592},
    };
    for (const PLarge& r : p_large) {
        INFO("R_J(" << r.x << ", " << r.y << ", " << r.z << ", " << r.p << ")");
        CHECK(rel_error(double(apse::carlson_rj(T(r.x), T(r.y), T(r.z), T(r.p))), r.ref) <= 8 * eps<T>());
    }
    // Legendre at the extremes of m, n and phi.
    const T big = T(1e30);
    for (T m : {-big, T(-1e4), T(0), T(1) - L::epsilon() / 2}) {
        for (T phi : {T(0), L::denorm_min(), T(1), T(1e4), big}) {
            const T f = apse::ellint_f(phi, m);
            CHECK((f != f || f >= T(0)));
            for (T n : {-big, T(-1e4), T(0), T(1) - L::epsilon() / 2}) {
                const T p = apse::ellint_pi(n, phi, m);
                CHECK((p != p || p >= T(0)));
                const T cp = apse::comp_ellint_pi(n, m);
                CHECK((cp != cp || cp >= T(0)));
            }
        }
    }
}
