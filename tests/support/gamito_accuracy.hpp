// apse — area-preserving parameterizations for spherical ellipses.
// SPDX-License-Identifier: MIT
#pragma once

// The statistics of Gamito's rejection samplers (baselines/gamito.hpp), measured once for
// tests/test_gamito.cpp (which asserts them) and tools/baselines_report.cpp (which prints the
// Gamito table of docs/baselines.md): Monte Carlo estimates of the disk's solid angle and of
// ∫cos θ dω by both variants and by the authors' bookkeeping against the mpmath disk integrals
// of tools/gen_rectangle_reference.py, acceptance and success rates against the exact ratio,
// and a chi-square test of the accepted directions against the uniform distribution over the
// disk's solid angle (cells integrated by long-double quadrature, independent of apse).
// No Catch2: the loader reports a malformed table in `error`, the callers assert or stop.

#include <apse/baselines/gamito.hpp>
#include <apse/math.hpp>

#include "support/statistics_core.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

namespace apse_test::gamito {

/// One row of tests/data/rectangle/gamito_disks.txt: o, centre c, normal n, radius r; the disk's
/// solid angle, ∫cos θ dω (cos = omega . z_d) and its bounding square's solid angle.
struct DiskCase {
    std::string name;
    double o[3], c[3], n[3], r;
    double omega, cos_integral, omega_square;
};

/// The disks of tests/data/rectangle/gamito_disks.txt; `error` is empty if the table is sound.
struct DiskCases {
    std::string error;
    std::vector<DiskCase> cases;
};

inline const DiskCases& gamito_disk_cases() {
    static const DiskCases table = [] {
        DiskCases out;
        const DataTable t = read_data_table("rectangle/gamito_disks.txt");
        if (!t.opened) out.error = "cannot read " + t.path;
        for (const auto& row : t.rows) {
            if (row.size() != 14) {
                out.error = t.path + ": a row of " + std::to_string(row.size()) + " fields instead of 14";
                break;
            }
            DiskCase d;
            d.name = row[0];
            for (int i = 0; i < 3; ++i) {
                d.o[i] = num(row[1 + i]);
                d.c[i] = num(row[4 + i]);
                d.n[i] = num(row[7 + i]);
            }
            d.r = num(row[10]);
            d.omega = num(row[11]);
            d.cos_integral = num(row[12]);
            d.omega_square = num(row[13]);
            out.cases.push_back(d);
        }
        return out;
    }();
    return table;
}

/// The disk named `name`, or nullptr.
inline const DiskCase* find_gamito_disk(const std::string& name) {
    for (const auto& c : gamito_disk_cases().cases)
        if (c.name == name) return &c;
    return nullptr;
}

template <class T> glm::vec<3, T> disk_vec3(const double* p) { return glm::vec<3, T>(T(p[0]), T(p[1]), T(p[2])); }

/// Long-double disk geometry, independent of apse: unit normal, in-plane frame (e1, e2), the
/// foot point of o in that frame (fx, fy) and the height d; z_d points from o to the plane.
struct DiskGeometry {
    long double n[3], e1[3], e2[3], zd[3], fx, fy, d, r;
    explicit DiskGeometry(const DiskCase& c) : r(c.r) {
        const long double ln = std::sqrt((long double)c.n[0] * c.n[0] + (long double)c.n[1] * c.n[1] + (long double)c.n[2] * c.n[2]);
        for (int i = 0; i < 3; ++i) n[i] = c.n[i] / ln;
        const long double a[3] = {std::fabs(n[0]) < 0.9L ? 1.0L : 0.0L, std::fabs(n[0]) < 0.9L ? 0.0L : 1.0L, 0.0L};
        e1[0] = n[1] * a[2] - n[2] * a[1];
        e1[1] = n[2] * a[0] - n[0] * a[2];
        e1[2] = n[0] * a[1] - n[1] * a[0];
        const long double l1 = std::sqrt(e1[0] * e1[0] + e1[1] * e1[1] + e1[2] * e1[2]);
        for (long double& x : e1) x /= l1;
        e2[0] = n[1] * e1[2] - n[2] * e1[1];
        e2[1] = n[2] * e1[0] - n[0] * e1[2];
        e2[2] = n[0] * e1[1] - n[1] * e1[0];
        long double w[3];
        for (int i = 0; i < 3; ++i) w[i] = (long double)c.o[i] - c.c[i];
        const long double sd = w[0] * n[0] + w[1] * n[1] + w[2] * n[2];
        d = std::fabs(sd);
        for (int i = 0; i < 3; ++i) zd[i] = sd > 0 ? -n[i] : n[i];
        fx = w[0] * e1[0] + w[1] * e1[1] + w[2] * e1[2];
        fy = w[0] * e2[0] + w[1] * e2[1] + w[2] * e2[2];
    }
    /// Solid angle of the polar cell rho in [ra, rb] (units of r), psi in [pa, pb] (GL n x n).
    long double cell(const GaussLegendre& gl, long double ra, long double rb, long double pa, long double pb) const {
        return gl.integrate(
            [&](long double rho) {
                return gl.integrate(
                    [&](long double psi) {
                        const long double x = r * rho * std::cos(psi) - fx, y = r * rho * std::sin(psi) - fy;
                        const long double q = x * x + y * y + d * d;
                        return d * r * r * rho / (q * std::sqrt(q));
                    },
                    pa, pb);
            },
            ra, rb);
    }
    /// Polar coordinates (rho in units of r, psi in (-pi, pi]) of a world point of the plane.
    void polar(double px, double py, double pz, const DiskCase& c, double& rho, double& psi) const {
        const long double q[3] = {px - c.c[0], py - c.c[1], pz - c.c[2]};
        const long double x = q[0] * e1[0] + q[1] * e1[1] + q[2] * e1[2];
        const long double y = q[0] * e2[0] + q[1] * e2[1] + q[2] * e2[2];
        rho = double(std::sqrt(x * x + y * y) / r);
        psi = double(std::atan2(y, x));
    }
};

/// 1 + (|c − o| + 4r)/d: the disk's condition number, as kappa of the rectangle.
inline double disk_condition(const DiskCase& c) {
    const DiskGeometry g(c);
    const double dist = std::sqrt(std::pow(c.c[0] - c.o[0], 2) + std::pow(c.c[1] - c.o[1], 2) + std::pow(c.c[2] - c.o[2], 2));
    return 1 + (dist + 4 * c.r) / double(g.d);
}

/// Mean and standard error of a Monte Carlo estimator.
struct Estimate {
    double sum = 0, sum2 = 0;
    long n = 0;
    void add(double x) {
        sum += x;
        sum2 += x * x;
        ++n;
    }
    double mean() const { return sum / n; }
    double stderr_() const { return std::sqrt(std::max(0.0, sum2 / n - mean() * mean()) / (n - 1)); }
};

/// E[1/pdf], E[cos/pdf] over M samples ("no sample" contributes 0), and the acceptance rate.
template <class T, class Sampler>
void estimate(const Sampler& s, const DiskCase& c, long M, std::uint64_t seed, Estimate& omega, Estimate& cosine,
              Estimate& accepted, bool authors_bookkeeping = false) {
    const DiskGeometry g(c);
    Rng rng(seed);
    for (long k = 0; k < M; ++k) {
        const auto smp = s.sample(glm::vec<2, T>(rng.uniform<T>(), rng.uniform<T>()));
        double inv = 0;
        if (smp.pdf > T(0)) inv = authors_bookkeeping ? c.omega : 1.0 / double(smp.pdf);
        const double cs = double(smp.direction.x * g.zd[0] + smp.direction.y * g.zd[1] + smp.direction.z * g.zd[2]);
        omega.add(inv);
        cosine.add(inv * cs);
        accepted.add(smp.pdf > T(0) ? 1.0 : 0.0);
    }
}

/// Samples per configuration and variant of the unbiasedness check.
constexpr long gamito_unbiased_samples = 200000;

/// One variant's estimates on one disk, with their deviations from the truth in standard
/// errors: zo (Omega_disk), zc (∫cos θ dω), za (the acceptance or success rate against
/// `expected_rate`).
struct VariantEstimate {
    Estimate omega, cosine, accepted;
    double zo = 0, zc = 0, za = 0, expected_rate = 0;
};

/// The unbiasedness check on one disk: single shot (pdf 1/Omega_square), GamitoRetry with N = 2
/// and 8 (pdf (1 − (1 − A)^N)/Omega_disk), and the authors' bookkeeping (single shot reporting
/// pdf 1/Omega_disk, whose expectation is A Omega_disk). A = Omega_disk/Omega_square from the table.
struct GamitoUnbiasedness {
    const DiskCase* c;
    double A;
    VariantEstimate single, retry[2], authors;
    int retry_attempts[2] = {2, 8};
    double authors_ratio = 0;  ///< the authors' estimate of Omega_disk / the truth
    double authors_zbias = 0;  ///< its deviation from A·truth, in standard errors
    bool bias_resolvable = false;  ///< (1 − A)·∫cos θ dω > 20 standard errors: the bias is visible
};

/// The unbiasedness check over every disk (gamito_unbiased_samples samples per configuration
/// and variant, seeded 1000, 1001, ... in float, 2000, ... in double). For the 0/1-valued 1/pdf
/// estimator of GamitoRetry failures are rare (~(1-A)^8 M ~ 1..50), so its standard error is the
/// exact one, Omega sqrt((1 - s)/s)/sqrt(M), s = 1 - (1 - A)^N from the table; (1 - s) can be
/// ~1e-23 (A = 0.9987): then 1/pdf is deterministic up to the rounding of the pdf, which gets a
/// budget of 64 eps kappa (as Omega_disk in test_gamito's solid-angle check).
template <class T> std::vector<GamitoUnbiasedness> gamito_unbiasedness() {
    const long M = gamito_unbiased_samples;
    std::uint64_t seed = sizeof(T) == sizeof(float) ? 1000 : 2000;
    std::vector<GamitoUnbiasedness> out;
    for (const DiskCase& c : gamito_disk_cases().cases) {
        GamitoUnbiasedness u;
        u.c = &c;
        const T r = T(c.r);
        const auto o = disk_vec3<T>(c.o), ctr = disk_vec3<T>(c.c), n = disk_vec3<T>(c.n);
        const double A = c.omega / c.omega_square;
        u.A = A;
        {  // single shot: pdf 1/Omega_square
            VariantEstimate& v = u.single;
            estimate<T>(apse::GamitoSingleShot<T>(o, ctr, n, r), c, M, seed++, v.omega, v.cosine, v.accepted);
            v.zo = (v.omega.mean() - c.omega) / v.omega.stderr_();
            v.zc = (v.cosine.mean() - c.cos_integral) / v.cosine.stderr_();
            v.za = (v.accepted.mean() - A) / std::sqrt(A * (1 - A) / M);
            v.expected_rate = A;
        }
        for (int k = 0; k < 2; ++k) {  // bounded retries: pdf (1 - (1-A)^N)/Omega_disk
            const int N = u.retry_attempts[k];
            VariantEstimate& v = u.retry[k];
            estimate<T>(apse::GamitoRetry<T>(o, ctr, n, r, N), c, M, seed++, v.omega, v.cosine, v.accepted);
            const double s = 1 - std::pow(1 - A, N);
            const double rounding = 64 * double(apse::epsilon<T>()) * disk_condition(c);
            v.zo = (v.omega.mean() - c.omega) / (c.omega * (std::sqrt((1 - s) / s / M) + rounding / 5));
            v.zc = (v.cosine.mean() - c.cos_integral) / v.cosine.stderr_();
            v.za = (v.accepted.mean() - s) / (std::sqrt(s * (1 - s) / M) + 0.2 / M);
            v.expected_rate = s;
        }
        {  // the authors' bookkeeping: single shot reporting pdf 1/Omega_disk. Expectation A Omega.
            VariantEstimate& v = u.authors;
            estimate<T>(apse::GamitoSingleShot<T>(o, ctr, n, r), c, M, seed++, v.omega, v.cosine, v.accepted, true);
            v.zo = (v.omega.mean() - c.omega) / v.omega.stderr_();
            v.zc = (v.cosine.mean() - c.cos_integral) / v.cosine.stderr_();
            v.expected_rate = A;
            u.authors_ratio = v.omega.mean() / c.omega;
            u.authors_zbias = (v.omega.mean() - A * c.omega) / v.omega.stderr_();
            u.bias_resolvable = (1 - A) * c.cos_integral > 20 * v.cosine.stderr_();
        }
        out.push_back(u);
    }
    return out;
}

/// The chi-square test's disks, its grid (equal-area rings x sectors), sample count and first seed.
constexpr const char* gamito_chi2_cases[] = {"typical", "near_above", "grazing", "random1"};
constexpr int gamito_chi2_rings = 8, gamito_chi2_sectors = 16;
constexpr long gamito_chi2_samples = 400000;
template <class T> constexpr std::uint64_t gamito_chi2_seed() { return sizeof(T) == sizeof(float) ? 3000 : 4000; }

/// The solid angles of the chi-square cells of one disk (12 x 12 Gauss–Legendre in long double),
/// and |their sum / the table's Omega_disk − 1|.
struct DiskChi2Cells {
    std::vector<double> cell;
    long double total = 0;
    double quadrature_error = 0;
};

inline DiskChi2Cells gamito_chi2_cells(const DiskCase& c) {
    const int rings = gamito_chi2_rings, sectors = gamito_chi2_sectors;
    const GaussLegendre gl(12);
    const double pi = 3.14159265358979323846;
    const DiskGeometry g(c);
    DiskChi2Cells out;
    out.cell.resize(rings * sectors);
    for (int i = 0; i < rings; ++i)
        for (int j = 0; j < sectors; ++j) {
            const long double e = g.cell(gl, std::sqrt((long double)i / rings), std::sqrt((long double)(i + 1) / rings),
                                         -pi + 2 * pi * j / sectors, -pi + 2 * pi * (j + 1) / sectors);
            out.cell[i * sectors + j] = double(e);
            out.total += e;
        }
    out.quadrature_error = std::fabs(double(out.total) / c.omega - 1);
    return out;
}

/// Chi-square of the accepted points of gamito_chi2_samples samples (seeded) of one variant
/// (0: single shot, 1: retry), histogrammed over the cells, against N_accepted Omega_cell /
/// Omega_disk; pdf_mismatch counts the accepted samples whose pdf(direction) differs from the
/// pdf they were returned with.
struct GamitoChi2 {
    Chi2Result result;
    int pdf_mismatch = 0;
};

template <class T> GamitoChi2 gamito_chi2(const DiskCase& c, const DiskChi2Cells& cells, int variant, std::uint64_t seed) {
    const int rings = gamito_chi2_rings, sectors = gamito_chi2_sectors;
    const double pi = 3.14159265358979323846;
    const DiskGeometry g(c);
    const auto o = disk_vec3<T>(c.o), ctr = disk_vec3<T>(c.c), n = disk_vec3<T>(c.n);
    const apse::GamitoSingleShot<T> single(o, ctr, n, T(c.r));
    const apse::GamitoRetry<T> retry(o, ctr, n, T(c.r));
    std::vector<double> observed(rings * sectors, 0.0);
    double accepted = 0;
    GamitoChi2 out;
    Rng rng(seed);
    for (long k = 0; k < gamito_chi2_samples; ++k) {
        const glm::vec<2, T> u(rng.uniform<T>(), rng.uniform<T>());
        const auto p = variant == 0 ? single.sample_point(u) : retry.sample_point(u);
        if (!(p.pdf > T(0))) continue;
        const T back = variant == 0 ? single.pdf(p.direction) : retry.pdf(p.direction);
        if (back != p.pdf) ++out.pdf_mismatch;
        double rho, psi;
        g.polar(p.point.x, p.point.y, p.point.z, c, rho, psi);
        const int i = std::min(rings - 1, int(rho * rho * rings));
        const int j = std::min(sectors - 1, std::max(0, int((psi + pi) / (2 * pi) * sectors)));
        observed[i * sectors + j] += 1;
        accepted += 1;
    }
    std::vector<double> expected(cells.cell.size());
    for (std::size_t k = 0; k < cells.cell.size(); ++k) expected[k] = cells.cell[k] * accepted / double(cells.total);
    out.result = chi2_test(observed, expected);
    return out;
}

}  // namespace apse_test::gamito
