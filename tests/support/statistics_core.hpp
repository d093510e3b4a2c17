// The statistics the sampler tests and the measuring tools share (tests/support/statistics.hpp
// adds Catch2's assertions to the table reading): reading the reference tables of tests/data, a
// seeded uniform generator, Gauss–Legendre quadrature, a Mitsuba-style chi-square test and the
// variance of a jittered or independent Monte Carlo estimator. No Catch2 and no apse header: the
// tools (tools/baselines_report.cpp) use it without a test framework, and nothing here depends
// on the code under test.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <numeric>
#include <sstream>
#include <string>
#include <vector>

namespace apse_test {

/// A table of tests/data: the whitespace-separated tokens of every non-comment line.
struct DataTable {
    std::string path;                            ///< the file read
    bool opened = false;                         ///< whether it could be opened
    std::vector<std::vector<std::string>> rows;  ///< its rows (none if not opened)
};

/// Reads tests/data/<relative_path> ('#' lines and empty lines skipped).
inline DataTable read_data_table(const std::string& relative_path) {
    DataTable t;
    t.path = std::string(APSE_TEST_DATA_DIR) + "/" + relative_path;
    std::ifstream in(t.path);
    t.opened = in.good();
    std::string line;
    while (std::getline(in, line)) {
        if (line.empty() || line[0] == '#') continue;
        std::istringstream is(line);
        std::vector<std::string> row;
        std::string tok;
        while (is >> tok) row.push_back(tok);
        t.rows.push_back(row);
    }
    return t;
}

/// A number from the tables: hex floats ("0x1.8p-3") or decimals, "inf" (correctly rounded).
inline double num(const std::string& s) { return std::strtod(s.c_str(), nullptr); }

/// splitmix64: a small, fast, well-mixed seeded generator (good enough for Monte Carlo tests).
struct Rng {
    std::uint64_t state;
    explicit Rng(std::uint64_t seed) : state(seed) {}
    std::uint64_t next() {
        std::uint64_t z = (state += 0x9e3779b97f4a7c15ULL);
        z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
        z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
        return z ^ (z >> 31);
    }
    /// Uniform in [0, 1) with the full precision of T (24 or 53 random bits).
    template <class T> T uniform() {
        if (sizeof(T) == sizeof(float)) return T(next() >> 40) * T(0x1p-24);
        return T(next() >> 11) * T(0x1p-53);
    }
};

/// Gauss–Legendre nodes and weights on [-1, 1] (Newton on P_n, long double).
struct GaussLegendre {
    std::vector<long double> x, w;
    explicit GaussLegendre(int n) : x(n), w(n) {
        const long double pi = 3.141592653589793238462643383279502884L;
        for (int i = 0; i < n; ++i) {
            long double z = std::cos(pi * (i + 0.75L) / (n + 0.5L)), dp = 0;
            for (int it = 0; it < 100; ++it) {
                long double p0 = 1, p1 = z;
                for (int k = 2; k <= n; ++k) {
                    const long double p2 = ((2 * k - 1) * z * p1 - (k - 1) * p0) / k;
                    p0 = p1;
                    p1 = p2;
                }
                dp = n * (z * p1 - p0) / (z * z - 1);
                const long double dz = p1 / dp;
                z -= dz;
                if (std::fabs(dz) < 1e-19L) break;
            }
            x[i] = z;
            w[i] = 2 / ((1 - z * z) * dp * dp);
        }
    }
    /// int_a^b f(t) dt.
    template <class F> long double integrate(F&& f, long double a, long double b) const {
        const long double h = (b - a) / 2, m = (a + b) / 2;
        long double s = 0;
        for (std::size_t i = 0; i < x.size(); ++i) s += w[i] * f(m + h * x[i]);
        return s * h;
    }
};

/// Regularized upper incomplete gamma Q(a, x) (series for x < a + 1, Lentz continued fraction
/// otherwise): the chi-square survival function is Q(dof / 2, chi2 / 2).
inline double gamma_q(double a, double x) {
    if (x <= 0) return 1.0;
    const double lg = std::lgamma(a);
    if (x < a + 1) {
        double sum = 1.0 / a, term = sum;
        for (int n = 1; n < 100000; ++n) {
            term *= x / (a + n);
            sum += term;
            if (std::fabs(term) < std::fabs(sum) * 1e-16) break;
        }
        return 1.0 - sum * std::exp(-x + a * std::log(x) - lg);
    }
    const double tiny = 1e-300;
    double b = x + 1 - a, c = 1 / tiny, d = 1 / b, h = d;
    for (int i = 1; i < 100000; ++i) {
        const double an = -i * (i - a);
        b += 2;
        d = an * d + b;
        if (std::fabs(d) < tiny) d = tiny;
        c = b + an / c;
        if (std::fabs(c) < tiny) c = tiny;
        d = 1 / d;
        const double delta = d * c;
        h *= delta;
        if (std::fabs(delta - 1) < 1e-16) break;
    }
    return std::exp(-x + a * std::log(x) - lg) * h;
}

struct Chi2Result {
    double chi2 = 0;
    int dof = 0;
    double p = 1;
};

/// Pearson's chi-square of observed counts against expected counts (same total), Mitsuba style:
/// cells are visited by increasing expectation and those with expected count < min_expected are
/// pooled together until the pool reaches min_expected; the pool is then one cell.
inline Chi2Result chi2_test(const std::vector<double>& observed, const std::vector<double>& expected,
                            double min_expected = 5.0) {
    std::vector<std::size_t> order(expected.size());
    std::iota(order.begin(), order.end(), std::size_t(0));
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return expected[a] < expected[b]; });
    Chi2Result r;
    double pool_obs = 0, pool_exp = 0;
    int cells = 0;
    for (std::size_t i : order) {
        if (expected[i] <= 0) {
            if (observed[i] > 0) return {1e300, 1, 0.0};  // sample where the density is 0
            continue;
        }
        if (expected[i] < min_expected) {
            pool_obs += observed[i];
            pool_exp += expected[i];
            if (pool_exp >= min_expected) {
                r.chi2 += (pool_obs - pool_exp) * (pool_obs - pool_exp) / pool_exp;
                ++cells;
                pool_obs = pool_exp = 0;
            }
            continue;
        }
        r.chi2 += (observed[i] - expected[i]) * (observed[i] - expected[i]) / expected[i];
        ++cells;
    }
    if (pool_exp > 0) {
        r.chi2 += (pool_obs - pool_exp) * (pool_obs - pool_exp) / pool_exp;
        ++cells;
    }
    r.dof = cells - 1;
    r.p = r.dof > 0 ? gamma_q(0.5 * r.dof, 0.5 * r.chi2) : 1.0;
    return r;
}

/// Per-test significance level that keeps the family-wise level at alpha over n tests (Šidák).
inline double sidak(double alpha, int n) { return 1.0 - std::pow(1.0 - alpha, 1.0 / n); }

/// Variance of the estimator (1/N) sum f(w_i)/pdf over `reps` repetitions with N = k x k points
/// per repetition, drawn either jittered (one uniform point per cell of the k x k grid) or
/// independent uniform. `sample(u1, u2)` returns {direction, pdf}.
template <class T, class Sample, class F>
double estimator_variance(Sample&& sample, F&& f, int k, int reps, bool jittered, std::uint64_t seed) {
    Rng rng(seed);
    double sum = 0, sum2 = 0;
    for (int rep = 0; rep < reps; ++rep) {
        double est = 0;
        for (int i = 0; i < k; ++i)
            for (int j = 0; j < k; ++j) {
                T u1, u2;
                if (jittered) {
                    u1 = T((i + rng.uniform<double>()) / k);
                    u2 = T((j + rng.uniform<double>()) / k);
                    if (!(u1 < T(1))) u1 = T(1) - std::numeric_limits<T>::epsilon();
                    if (!(u2 < T(1))) u2 = T(1) - std::numeric_limits<T>::epsilon();
                } else {
                    u1 = rng.uniform<T>();
                    u2 = rng.uniform<T>();
                }
                const auto s = sample(u1, u2);
                if (s.pdf > 0) est += double(f(s.direction)) / double(s.pdf);
            }
        est /= double(k) * k;
        sum += est;
        sum2 += est * est;
    }
    const double mean = sum / reps;
    return sum2 / reps - mean * mean;
}

}  // namespace apse_test
