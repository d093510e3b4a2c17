// Test utilities for the area-preserving maps (and any sampler with sample(u) -> {direction, pdf}):
// the disk-cell quadrature behind the chi-square test, the chi-square test itself (pooling +
// Šidák correction, from statistics_core.hpp), and through it the jittered-grid stratification
// estimator (estimator_variance, statistics_core.hpp).
// Reusable by the tabulated-map and Gamito tests. Independent of apse's own formulas: cell
// probabilities come from quadrature of the disk's solid-angle integrand, never from the code
// under test.
#pragma once

#include "statistics_core.hpp"

#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

namespace apse_test {

/// 2 pi (M_PI is not standard C++).
constexpr long double kTwoPi = 6.283185307179586476925286766559005768L;

/// A disk light seen from the origin, in its own frame: the disk {z = d, (x - h)^2 + y^2 <= r^2}
/// (o at the origin, normal +z, foot point at the origin, centre at (h, 0, d)). `cells` polar
/// cells of the disk, centred at the disk centre: `rings` equal-area rings × `sectors` sectors.
struct DiskCells {
    double d, h, r;
    int rings, sectors;

    int count() const { return rings * sectors; }

    /// Cell index of the disk point (px, py) (on the plane z = d); -1 if outside the disk
    /// (by more than `slack` relative to r).
    int cell_of(double px, double py, double slack = 1e-9) const {
        const double x = px - h, y = py;
        const double rho2 = (x * x + y * y) / (r * r);
        if (rho2 > 1 + slack) return -1;
        int ring = int(std::min(rho2, 1.0) * rings);  // equal-area rings: rho^2 uniform
        if (ring >= rings) ring = rings - 1;
        double ang = std::atan2(y, x);
        if (ang < 0) ang += double(kTwoPi);
        int sec = int(ang / double(kTwoPi) * sectors);
        if (sec >= sectors) sec = sectors - 1;
        return ring * sectors + sec;
    }

    /// Solid angle of every cell: int_cell cos(theta)/dist^2 dA = int d / (x^2 + y^2 + d^2)^{3/2} dA
    /// over the polar cell (rho, ang) of the disk, by a tensor Gauss–Legendre rule of n x n nodes
    /// per cell (the integrand is smooth on each cell unless the foot point is within a cell width
    /// of it; the tests keep d large enough or n high enough — see their comments).
    std::vector<double> solid_angles(int n) const {
        return integrals(n, [](double, double, double) { return 1.0; });
    }

    /// int_cell f(w) dw for every cell (w the unit direction from the origin to the disk point),
    /// with the same rule as solid_angles.
    template <class F> std::vector<double> integrals(int n, F&& f) const {
        GaussLegendre gl(n);
        std::vector<double> out(count());
        for (int i = 0; i < rings; ++i) {
            const long double r0 = r * std::sqrt((long double)i / rings), r1 = r * std::sqrt((long double)(i + 1) / rings);
            for (int j = 0; j < sectors; ++j) {
                const long double a0 = kTwoPi * j / sectors, a1 = kTwoPi * (j + 1) / sectors;
                const long double v = gl.integrate([&](long double rho) {
                    return gl.integrate([&](long double ang) {
                        const long double x = h + rho * std::cos(ang), y = rho * std::sin(ang);
                        const long double q = x * x + y * y + (long double)d * d, len = std::sqrt(q);
                        return rho * d / (q * len) * (long double)f(double(x / len), double(y / len), double(d / len));
                    }, a0, a1);
                }, r0, r1);
                out[i * sectors + j] = double(v);
            }
        }
        return out;
    }
};

/// Chi-square uniformity test of `n_samples` directions drawn by `sample(u) -> glm direction`
/// (pdf ignored) from a uniform generator, binned by the disk cell they hit, against the
/// expected counts from DiskCells::solid_angles (normalised by their own sum: independent of the
/// sampler's solid angle). Returns the chi-square result (pooling cells with expected < 5).
/// Directions must be given in the disk's frame (origin at o).
template <class T, class Sample>
Chi2Result disk_chi2(const DiskCells& cells, Sample&& sample, int n_samples, std::uint64_t seed, int quad_nodes = 8) {
    std::vector<double> expected = cells.solid_angles(quad_nodes);
    double total = 0;
    for (double v : expected) total += v;
    for (double& v : expected) v *= n_samples / total;
    std::vector<double> observed(cells.count(), 0.0);
    Rng rng(seed);
    int outside = 0;
    for (int i = 0; i < n_samples; ++i) {
        const T u1 = rng.uniform<T>(), u2 = rng.uniform<T>();
        const auto w = sample(u1, u2);
        const double t = cells.d / double(w.z);
        const int c = (w.z > 0) ? cells.cell_of(double(w.x) * t, double(w.y) * t, 1e-4) : -1;
        if (c < 0) { ++outside; continue; }
        observed[c] += 1;
    }
    Chi2Result res = chi2_test(observed, expected);
    if (outside > 0) res.p = 0;  // a sample off the disk is a failure
    return res;
}

}  // namespace apse_test
