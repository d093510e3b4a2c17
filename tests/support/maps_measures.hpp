// apse — area-preserving parameterizations for spherical ellipses.
// SPDX-License-Identifier: MIT
#pragma once

// What the tests measure of the three area-preserving maps (radial, LD-radial, parallel), and the
// bounds they assert, shared by the tests (test_maps_reference.cpp, test_maps_properties.cpp,
// test_maps_statistics.cpp, test_stratification.cpp) and tools/maps_report.cpp (the "Measured"
// table of docs/maps.md). Each measure returns its largest error (or p-value range, variance
// ratio) and calls `on_point` / `on_result` with every value it measures, where the tests check
// it against the bound (with its context); the tool passes callbacks that do nothing. No test
// framework is used here.

#include <apse/baselines/gamito.hpp>
#include <apse/comparison.hpp>
#include <apse/maps/ld_radial.hpp>
#include <apse/maps/parallel.hpp>
#include <apse/maps/tabulated_ld_radial.hpp>
#include <apse/math.hpp>
#include <apse/projection.hpp>

#include "map_testing.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace apse_test {

// ---- the bounds the tests assert ---------------------------------------------------------------

/// Cumulative areas (Omega_r, I) against the 40-digit tables, relative to the area being
/// accumulated (Omega/4 radial, Omega/2 parallel): the closed forms are sums of non-negative terms
/// (R_J, atan2) each good to a few eps, plus the rounding of the arguments; 32 eps leaves room for
/// R_J's own budget (tests/test_elliptic).
template <class T> T area_tolerance() { return T(32) * apse::epsilon<T>(); }

/// Sampled directions against the tables: angular error relative to the ellipse's size sin(alpha)
/// (directions of tiny ellipses differ from the centre by ~alpha only). double: the inversion
/// stops within 4 eps of the area and the direction is built from the solution with a few more
/// roundings: 1e-13 (~450 eps). float: 1e-5 (~80 eps: the float R_J and the conditioning of the
/// azimuth of thin ellipses near their major axis).
template <class T> constexpr double direction_tolerance() { return sizeof(T) == 4 ? 1e-5 : 1e-13; }

/// The inversion's CDF error (relative to the area inverted), measured by long-double quadrature
/// at the state the solver returns (so it includes the rounding of that state: in float tau itself
/// is only known to ~6e-8): 1e-12 in double, 1e-5 in float.
template <class T> constexpr double cdf_tolerance() { return sizeof(T) == 4 ? 1e-5 : 1e-12; }
/// The solver's iterations over the reference ellipses: at most this many on average ...
constexpr double kMeanIterationsBound = 3.0;
/// ... and at most this many for any one sample.
constexpr int kMaxIterationsBound = 6;

/// Finite-difference Jacobian against Omega, relative. double: step 1e-4, truncation ~h^4 (the
/// differences are Richardson-extrapolated) and rounding ~eps/h = 2e-12: 1e-5. float: step 2^-7;
/// rounding ~eps/h = 1e-5 per derivative, amplified on the most eccentric shapes: 4e-3 (a bound
/// on the finite differences, not on the map).
template <class T> constexpr double jacobian_tolerance() { return sizeof(T) == 4 ? 4e-3 : 1e-5; }
template <class T> constexpr double jacobian_step() { return sizeof(T) == 4 ? 0x1p-7 : 1e-4; }

/// invert(sample(u)) − u on [0.01, 0.99]^2. double: 1e-9 (the inverse evaluates the same closed
/// form as the solver, so the error is the solver's 4 eps of area divided by the local density,
/// amplified near u2 = 0.01 by 1/sqrt(u2) in LD-radial). float: 2e-3, the same budget with float's
/// eps on the most eccentric shapes.
template <class T> constexpr double round_trip_tolerance() { return sizeof(T) == 4 ? 2e-3 : 1e-9; }
/// sample(invert(w)) against w, relative to sin(alpha), on top of the resolution of u in T.
template <class T> constexpr double round_trip_direction_tolerance() { return sizeof(T) == 4 ? 2e-3 : 1e-9; }

/// The disks of the statistical tests (the DiskCells frame: o = 0, plane z = d, centre (h, 0, d),
/// radius 1), as {d, h}: frontal, oblique, grazing.
inline constexpr double kStatisticsDisks[3][2] = {{1.0, 0.0}, {0.7, 1.3}, {0.25, 2.5}};
/// The chi-square tests: 3 maps × 2 types × 3 disks, at a family-wise level of 1 %.
constexpr int kChi2Tests = 3 * 2 * 3;
constexpr double kChi2FamilyLevel = 0.01;
/// Samples per chi-square test, into kChi2Rings equal-area rings × kChi2Sectors sectors of the disk.
constexpr int kChi2Samples = 100000;
constexpr int kChi2Rings = 10, kChi2Sectors = 16;
/// The per-test level: Šidák-corrected.
inline double chi2_level() { return sidak(kChi2FamilyLevel, kChi2Tests); }

/// Unbiasedness: the Monte Carlo estimate of 200 000 independent samples within 4.5 standard
/// errors of the quadrature (two-sided 7e-6 per test; 18 tests).
constexpr int kUnbiasedSamples = 200000;
constexpr double kUnbiasedSigmas = 4.5;

/// Stratification: the variance ratio independent / jittered (16 × 16 points) above this for the
/// maps, and below the second for rejection sampling (Gamito).
constexpr double kStratificationMapBound = 20.0;
constexpr double kStratificationRejectionBound = 15.0;
constexpr int kStratificationGrid = 16;
constexpr int kStratificationRepetitions = 300;

// ---- reference tables and long-double quadrature -----------------------------------------------

using TableRows = std::vector<std::vector<std::string>>;

/// A reference ellipse of tests/data/maps/ellipses.txt: tan alpha, tan beta and its solid angle.
struct RefEllipse {
    double ta, tb, omega;
};

/// The rows of tests/data/maps/ellipses.txt ("id tan_alpha tan_beta Omega").
inline std::vector<RefEllipse> reference_ellipses(const TableRows& rows) {
    std::vector<RefEllipse> out;
    for (const auto& row : rows) out.push_back({num(row[1]), num(row[2]), num(row[3])});
    return out;
}

/// The ellipse with tangents (ta, tb) about +z, major axis along +x.
template <class T> apse::SphericalEllipse<T> local_ellipse(double ta, double tb) {
    using V = glm::vec<3, T>;
    return apse::SphericalEllipse<T>::from_tangents(V(1, 0, 0), V(0, 1, 0), V(0, 0, 1), T(ta), T(tb));
}

/// pi in long double.
constexpr long double kPiL = 3.141592653589793238462643383279502884L;

/// Independent long-double quadrature of the cumulative areas (docs/math.md §4, §5 definitions).
struct Quadrature {
    using LD = long double;
    LD a, b, ta, tb;  // sin alpha, sin beta, tan alpha, tan beta
    GaussLegendre gl{24};
    Quadrature(double ta_, double tb_) : ta(ta_), tb(tb_) {
        a = ta / std::sqrt(1 + ta * ta);
        b = tb / std::sqrt(1 + tb * tb);
    }
    // 1 - cos theta_max(phi) = r^2/(1 + sqrt(1 - r^2)).
    LD wedge(LD phi) const {
        const LD s = std::sin(phi), c = std::cos(phi);
        const LD r2 = (a * b) * (a * b) / (a * a * s * s + b * b * c * c);
        return r2 / (1 + std::sqrt(1 - r2));
    }
    // Omega_r(phi): composite Gauss–Legendre split where the planar ellipse has k/32 of its area
    // (resolves the narrow peak of thin ellipses at phi = 0) ...
    LD radial(LD phi) const {
        // ... then doubling steps for the 1/phi^2 tail of thin ellipses.
        LD sum = 0, lo = 0;
        for (int k = 1; lo < phi; ++k) {
            LD hi = k < 32 ? std::atan2(tb * std::sin(k * kPiL / 64), ta * std::cos(k * kPiL / 64)) : 2 * lo;
            if (hi > phi) hi = phi;
            sum += gl.integrate([&](LD p) { return wedge(p); }, lo, hi);
            lo = hi;
        }
        return sum;
    }
    // I(psi) = int_0^psi 2 x_max, in the gnomonic angle theta (tan psi = tb sin theta), where the
    // integrand 2 ta tb cos^2/((1 + tb^2 s^2) sqrt(1 + ta^2 c^2 + tb^2 s^2)) has no endpoint
    // singularity (nearly hemispherical ellipses vary on 1/ta near pi/2 and on 1/tb near 0).
    LD parallel(LD psi) const {
        const LD th_end = std::asin(std::min<LD>(1, std::tan(psi) / tb));
        auto g = [&](LD th) {
            const LD s = std::sin(th), c = std::cos(th);
            return 2 * ta * tb * c * c / ((1 + tb * tb * s * s) * std::sqrt(1 + ta * ta * c * c + tb * tb * s * s));
        };
        // Pieces shrink geometrically towards both ends (wide ellipses vary on 1/tb near 0).
        std::vector<LD> pts;
        for (int k = 48; k >= 1; --k) pts.push_back(kPiL / 4 * std::pow(LD(0.6), LD(k)));
        pts.push_back(kPiL / 4);
        for (int k = 1; k <= 48; ++k) pts.push_back(kPiL / 2 - kPiL / 4 * std::pow(LD(0.6), LD(k)));
        pts.push_back(kPiL / 2);
        LD sum = 0, lo = 0;
        for (std::size_t k = 0; k < pts.size() && lo < th_end; ++k) {
            const LD hi = std::min(pts[k], th_end);
            sum += gl.integrate(g, lo, hi);
            lo = hi;
        }
        return sum;
    }
};

// ---- against the reference tables --------------------------------------------------------------

struct AreaErrors {
    double omega = 0;     ///< max |Omega − table| / Omega over the ellipses
    double radial = 0;    ///< max |Omega_r(phi) − table| / (Omega/4)
    double parallel = 0;  ///< max |I(psi) − table| / (Omega/2)
};

/// The cumulative areas Omega_r (radial_area.txt: "ellipse phi area") and I (parallel_area.txt:
/// "ellipse psi area") in T against the tables. on_row(variable, row, err) for every row of either
/// table, variable "phi" (Omega_r) or "psi" (I).
template <class T, class OnRow>
AreaErrors cumulative_area_errors(const std::vector<RefEllipse>& ells, const TableRows& radial_rows,
                                  const TableRows& parallel_rows, OnRow&& on_row) {
    AreaErrors worst;
    for (const RefEllipse& r : ells) {
        const T om = apse::RadialMap<T>(local_ellipse<T>(r.ta, r.tb)).solid_angle();
        worst.omega = std::max(worst.omega, std::fabs(double(om) - r.omega) / r.omega);
    }
    for (const auto& row : radial_rows) {
        const RefEllipse& r = ells[std::stoi(row[0])];
        const apse::RadialMap<T> map(local_ellipse<T>(r.ta, r.tb));
        const double err = std::fabs(double(map.quadrant_area(T(num(row[1])))) - num(row[2])) / (r.omega / 4);
        on_row("phi", row, err);
        worst.radial = std::max(worst.radial, err);
    }
    for (const auto& row : parallel_rows) {
        const RefEllipse& r = ells[std::stoi(row[0])];
        const apse::ParallelMap<T> map(local_ellipse<T>(r.ta, r.tb));
        const double err = std::fabs(double(map.half_area(T(num(row[1])))) - num(row[2])) / (r.omega / 2);
        on_row("psi", row, err);
        worst.parallel = std::max(worst.parallel, err);
    }
    return worst;
}

/// The directions sampled in T against samples.txt ("ellipse map u1 u2 x y z"): the angle between
/// them (|w × ref|: the z component of a direction near the centre is 1 to within ulp(1), which
/// would dominate a componentwise error for tiny ellipses) over sin(alpha). on_row(row, err) for
/// every row; returns the largest error of each map.
template <class T, class OnRow>
std::map<std::string, double> direction_errors(const std::vector<RefEllipse>& ells, const TableRows& rows, OnRow&& on_row) {
    std::map<std::string, double> worst;
    for (const auto& row : rows) {
        const RefEllipse& r = ells[std::stoi(row[0])];
        const auto e = local_ellipse<T>(r.ta, r.tb);
        const glm::vec<2, T> u(T(num(row[2])), T(num(row[3])));
        glm::vec<3, T> w;
        if (row[1] == "radial") w = apse::RadialMap<T>(e).sample(u).direction;
        else if (row[1] == "parallel") w = apse::ParallelMap<T>(e).sample(u).direction;
        else w = apse::LdRadialMap<T>(e).sample(u).direction;
        const double size = r.ta / std::sqrt(1 + r.ta * r.ta);
        const glm::dvec3 ref(num(row[4]), num(row[5]), num(row[6]));
        const double err = glm::length(glm::cross(glm::dvec3(w), ref)) / size;
        on_row(row, err);
        worst[row[1]] = std::max(worst[row[1]], err);
    }
    return worst;
}

struct InversionStats {
    double cdf_radial = 0, cdf_parallel = 0;      ///< largest CDF errors
    double mean_radial = 0, mean_parallel = 0;    ///< mean iterations
    int max_radial = 0, max_parallel = 0;         ///< most iterations
};

/// The radial and parallel solvers in T at the fractions f = (i + 1/2)/101 of the area of every
/// reference ellipse: the CDF error at their solution, by the long-double quadrature, and their
/// iterations (state evaluations after the first guess). on_point(ellipse, f, radial error,
/// parallel error) for every point.
template <class T, class OnPoint> InversionStats inversion_stats(const std::vector<RefEllipse>& ells, OnPoint&& on_point) {
    using LD = long double;
    const int n = 101;
    InversionStats s;
    long sum_r = 0, sum_p = 0, count = 0;
    for (const auto& r : ells) {
        const auto e = local_ellipse<T>(r.ta, r.tb);
        const apse::RadialMap<T> radial(e);
        const apse::ParallelMap<T> parallel(e);
        const Quadrature q(r.ta, r.tb);
        const LD quarter = q.radial(kPiL / 2), half = q.parallel(std::atan(LD(r.tb)));
        for (int i = 0; i < n; ++i) {
            const T f = T((i + 0.5) / n);
            int it = 0;
            const auto rp = radial.solve_quadrant(f, it);
            sum_r += it;
            s.max_radial = std::max(s.max_radial, it);
            // azimuth of the solution: tan phi = (b/a) tan tau
            const LD phi = std::atan2(q.b * LD(rp.st), q.a * LD(rp.ct));
            const double er = double(std::fabs(q.radial(phi) - LD(f) * quarter) / quarter);
            s.cdf_radial = std::max(s.cdf_radial, er);
            const auto pp = parallel.solve_half(f, it);
            sum_p += it;
            s.max_parallel = std::max(s.max_parallel, it);
            // slice of the solution psi = beta - e, e = 2 atan(t tan(beta/2)); edge area = half - I(psi)
            const LD psi = LD(e.beta()) - 2 * std::atan(LD(pp.t) * std::tan(LD(e.beta()) / 2));
            const double ep = double(std::fabs(half - q.parallel(psi) - LD(f) * half) / half);
            s.cdf_parallel = std::max(s.cdf_parallel, ep);
            ++count;
            on_point(r, f, er, ep);
        }
    }
    s.mean_radial = double(sum_r) / count;
    s.mean_parallel = double(sum_p) / count;
    return s;
}

// ---- geometric properties ----------------------------------------------------------------------

/// The shapes of the geometric tests: tiny (alpha = 1e-5) to nearly hemispherical
/// (alpha = pi/2 − 1e-4), round to very thin (beta/alpha = 1e-4), as (tan alpha, tan beta).
inline std::vector<std::pair<double, double>> map_shapes() {
    const double half_pi = 1.57079632679489661923;
    std::vector<std::pair<double, double>> s;
    for (double alpha : {1e-5, 0.05, 0.4, 1.0, 1.4, half_pi - 1e-4})
        for (double ratio : {1.0, 0.5, 0.05, 1e-4}) s.emplace_back(std::tan(alpha), std::tan(alpha * ratio));
    return s;
}

/// Calls f(name, map) for each of the three maps of ellipse e.
template <class T, class F> void for_each_map(const apse::SphericalEllipse<T>& e, F&& f) {
    f(std::string("radial"), apse::RadialMap<T>(e));
    f(std::string("ld_radial"), apse::LdRadialMap<T>(e));
    f(std::string("parallel"), apse::ParallelMap<T>(e));
}

/// Angle between two directions (any length), computed in double.
template <class T> double angle(const glm::vec<3, T>& a, const glm::vec<3, T>& b) {
    const glm::dvec3 x(a), y(b);
    return std::atan2(glm::length(glm::cross(x, y)), glm::dot(x, y));
}

/// Points where a map is not differentiable: the radial maps' quadrant folds (u1 = k/4 for the
/// radial map; the concentric map's diagonals for LD-radial), the parallel fold at u1 = 1/2 is
/// smooth. Finite differences must not straddle them.
inline bool near_kink(const std::string& name, double u1, double u2, double h) {
    if (name == "radial") return std::fabs(4 * u1 - std::round(4 * u1)) < 8 * h;
    if (name == "ld_radial") {
        const double a = 2 * u1 - 1, b = 2 * u2 - 1;
        return std::fabs(std::fabs(a) - std::fabs(b)) < 8 * h || std::fabs(a) < 8 * h || std::fabs(b) < 8 * h;
    }
    return false;
}

/// The Jacobian |dw/du1 × dw/du2| of every map in T against its solid angle, relative, at 24
/// random points of [0.05, 0.95]^2 (away from the folds) for every shape: by central differences
/// of the gnomonic coordinates (x/z, y/z) (accurate to relative rounding even when z rounds to 1),
/// Richardson-extrapolated (steps h and 2h: O(h^4)), times z^3 (the gnomonic area element).
/// on_point(name, shape, u1, u2, jacobian, omega, err) for every point; returns the largest error.
template <class T, class OnPoint> double jacobian_error(OnPoint&& on_point) {
    using Vec2 = glm::vec<2, T>;
    using Vec3 = glm::vec<3, T>;
    const double h = jacobian_step<T>();
    Rng rng(4);
    double worst = 0;
    for (const auto& s : map_shapes()) {
        const auto e = local_ellipse<T>(s.first, s.second);
        for_each_map(e, [&](const std::string& name, const auto& map) {
            const double omega = double(map.solid_angle());
            for (int i = 0; i < 24; ++i) {
                const double u1 = 0.05 + 0.9 * rng.uniform<double>(), u2 = 0.05 + 0.9 * rng.uniform<double>();
                if (near_kink(name, u1, u2, 2 * h)) continue;
                auto gnomonic = [&](double a, double b) {
                    const Vec3 w = map.sample(Vec2(T(a), T(b))).direction;
                    return glm::dvec2(double(w.x) / double(w.z), double(w.y) / double(w.z));
                };
                auto diff = [&](double du1, double du2) {
                    const glm::dvec2 a = (gnomonic(u1 + du1, u2 + du2) - gnomonic(u1 - du1, u2 - du2)) / (2 * h);
                    const glm::dvec2 b = (gnomonic(u1 + 2 * du1, u2 + 2 * du2) - gnomonic(u1 - 2 * du1, u2 - 2 * du2)) / (4 * h);
                    return (4.0 * a - b) / 3.0;
                };
                const glm::dvec2 d1 = diff(h, 0), d2 = diff(0, h);
                const Vec3 w = map.sample(Vec2(T(u1), T(u2))).direction;
                const double z = double(w.z) / glm::length(glm::dvec3(w));
                const double jac = std::fabs(d1.x * d2.y - d1.y * d2.x) * z * z * z;
                const double err = std::fabs(jac - omega) / omega;
                worst = std::max(worst, err);
                on_point(name, s, u1, u2, jac, omega, err);
            }
        });
    }
    return worst;
}

/// One point of the round trips: invert(sample(u)) against u, and sample(invert(w)) against a
/// direction w inside the ellipse.
template <class T> struct RoundTripPoint {
    glm::vec<2, T> u, back;  ///< u and invert(sample(u))
    double error_u;          ///< max |back − u| (componentwise)
    double angle_w;          ///< the angle between w and sample(invert(w))
    double size;             ///< sin(alpha)
    double resolution;       ///< how far sample(invert(w)) moves when invert(w) moves by 8 eps
};

struct RoundTripErrors {
    double u = 0;          ///< largest error in u
    double direction = 0;  ///< largest angle, relative to sin(alpha)
};

/// invert(sample(u)) = u on [0.01, 0.99]^2 (away from the documented seams: the radial map's
/// centre u2 = 0 and its +x seam u1 in {0, 1}, the parallel map's minor-axis ends u1 in {0, 1},
/// LD-radial's centre), and sample(invert(w)) = w for random directions inside, for every map in T
/// and every shape, 64 points each. on_point(name, shape, RoundTripPoint) for every point.
template <class T, class OnPoint> RoundTripErrors round_trip_errors(OnPoint&& on_point) {
    using Vec2 = glm::vec<2, T>;
    using Vec3 = glm::vec<3, T>;
    Rng rng(5);
    RoundTripErrors worst;
    for (const auto& s : map_shapes()) {
        const auto e = local_ellipse<T>(s.first, s.second);
        const double size = s.first / std::sqrt(1 + s.first * s.first);
        for_each_map(e, [&](const std::string& name, const auto& map) {
            for (int i = 0; i < 64; ++i) {
                RoundTripPoint<T> p;
                p.size = size;
                p.u = Vec2(T(0.01 + 0.98 * rng.uniform<double>()), T(0.01 + 0.98 * rng.uniform<double>()));
                const auto smp = map.sample(p.u);
                p.back = map.invert(smp.direction);
                p.error_u = std::max(std::fabs(double(p.back.x - p.u.x)), std::fabs(double(p.back.y - p.u.y)));
                worst.u = std::max(worst.u, p.error_u);
                // a direction inside: uniform in the gnomonic ellipse, shrunk by 0.999
                const double rho = 0.999 * std::sqrt(rng.uniform<double>()), t = double(kTwoPi) * rng.uniform<double>();
                const glm::dvec3 g(s.first * rho * std::cos(t), s.second * rho * std::sin(t), 1.0);
                const Vec3 w(glm::normalize(g));
                const Vec2 uw = map.invert(w);
                const Vec3 w2 = map.sample(uw).direction;
                // resolution of u in T: how far the image moves when u moves by 8 eps, the inverse's
                // accuracy in u (the solver stops within 4 eps of the area); directions near the
                // horizon of nearly hemispherical ellipses live within ~1e-5 of u1 = 1 in the
                // parallel map, where that moves the slice far
                auto nudge = [](T v) { const T d = T(8) * apse::epsilon<T>();
                                       return v + d <= T(1) ? v + d : v - d; };
                p.resolution = angle(w2, map.sample(Vec2(nudge(uw.x), uw.y)).direction) +
                               angle(w2, map.sample(Vec2(uw.x, nudge(uw.y))).direction);
                p.angle_w = angle(w, w2);
                worst.direction = std::max(worst.direction, p.angle_w / size);
                on_point(name, s, p);
            }
        });
    }
    return worst;
}

// ---- statistics --------------------------------------------------------------------------------

/// The spherical ellipse of the unit disk {d, h} of kStatisticsDisks seen from the origin.
template <class T> apse::SphericalEllipse<T> statistics_disk_ellipse(const double (&cfg)[2]) {
    using Vec3 = glm::vec<3, T>;
    return apse::project_disk(Vec3(0), Vec3(T(cfg[1]), T(0), T(cfg[0])), Vec3(0, 0, 1), T(1));
}

/// The p-values' range of a set of chi-square tests.
struct PRange {
    double min = 1, max = 0;
};

/// Chi-square uniformity of every map in T on every disk of kStatisticsDisks: kChi2Samples
/// samples into 10 equal-area rings × 16 sectors (625 expected per cell on average), expected
/// counts from DiskCells quadrature (independent of apse). on_disk(ellipse) before each disk,
/// on_result(name, disk, Chi2Result) after each test.
template <class T, class OnDisk, class OnResult> PRange chi2_p_values(OnDisk&& on_disk, OnResult&& on_result) {
    std::uint64_t seed = sizeof(T) == 4 ? 1000 : 2000;
    PRange range;
    for (const auto& cfg : kStatisticsDisks) {
        const DiskCells cells{cfg[0], cfg[1], 1.0, kChi2Rings, kChi2Sectors};
        const auto e = statistics_disk_ellipse<T>(cfg);
        on_disk(e);
        for_each_map(e, [&](const std::string& name, const auto& map) {
            const auto r = disk_chi2<T>(
                cells, [&](T u1, T u2) { return map.sample(glm::vec<2, T>(u1, u2)).direction; }, kChi2Samples, ++seed);
            range.min = std::min(range.min, r.p);
            range.max = std::max(range.max, r.p);
            on_result(name, cfg, r);
        });
    }
    return range;
}

/// int f(w) dw over the disk's solid angle, f a tilted cubic lobe, by quadrature on the disk
/// (DiskCells::integrals, independent of apse) against the mean of f/pdf over kUnbiasedSamples
/// independent samples of every map in T, on every disk of kStatisticsDisks.
/// on_result(name, disk, estimate, reference, standard error); returns the largest
/// |estimate − reference| in standard errors.
template <class T, class OnResult> double unbiased_sigmas(OnResult&& on_result) {
    double worst = 0;
    for (const auto& cfg : kStatisticsDisks) {
        const DiskCells cells{cfg[0], cfg[1], 1.0, 4, 16};
        const glm::dvec3 lobe = glm::normalize(glm::dvec3(0.3, -0.4, 1.0));
        auto f = [&](double x, double y, double z) { const double c = glm::dot(glm::dvec3(x, y, z), lobe); return 1.0 + 3.0 * c * c * c; };
        double ref = 0;
        for (double v : cells.integrals(16, f)) ref += v;
        const auto e = statistics_disk_ellipse<T>(cfg);
        for_each_map(e, [&](const std::string& name, const auto& map) {
            Rng rng(sizeof(T) * 100 + 7);
            const int n = kUnbiasedSamples;
            double sum = 0, sum2 = 0;
            for (int i = 0; i < n; ++i) {
                const auto s = map.sample(glm::vec<2, T>(rng.uniform<T>(), rng.uniform<T>()));
                const glm::dvec3 w = glm::normalize(glm::dvec3(s.direction));
                const double v = s.pdf > 0 ? f(w.x, w.y, w.z) / double(s.pdf) : 0.0;
                sum += v;
                sum2 += v * v;
            }
            const double mean = sum / n, se = std::sqrt((sum2 / n - mean * mean) / n);
            worst = std::max(worst, std::fabs(mean - ref) / se);
            on_result(name, cfg, mean, ref, se);
        });
    }
    return worst;
}

/// Calls f(name, sampler, is_rejection) for every sampler of the unit disk (h, 0, d) seen from
/// the origin, whose spherical ellipse is e: the three maps, the two tabulated maps (default
/// table) and Gamito's rejection samplers.
template <class T, class F> void for_each_disk_sampler(const apse::SphericalEllipse<T>& e, double d, double h, F&& f) {
    using Vec3 = glm::vec<3, T>;
    const Vec3 o(0), c(T(h), T(0), T(d)), n(0, 0, 1);
    f(std::string("radial"), apse::RadialMap<T>(e), false);
    f(std::string("ld_radial"), apse::LdRadialMap<T>(e), false);
    f(std::string("parallel"), apse::ParallelMap<T>(e), false);
    f(std::string("tabulated"), apse::TabulatedMap<T>(e, apse::default_table().view()), false);
    f(std::string("tabulated_ld_radial"), apse::TabulatedLdRadialMap<T>(e, apse::default_table().view()), false);
    f(std::string("gamito_single_shot"), apse::GamitoSingleShot<T>(o, c, n, T(1)), true);
    f(std::string("gamito_retry"), apse::GamitoRetry<T>(o, c, n, T(1)), true);
}

/// The variance ratios of one sampler over the disks.
struct RatioRange {
    std::string name;
    bool rejection = false;
    double min = std::numeric_limits<double>::infinity(), max = 0;
};

/// Stratification, for every sampler of for_each_disk_sampler in T on every disk of
/// kStatisticsDisks: the variance of a 16 × 16 jittered Monte Carlo estimate of a smooth cosine
/// lobe tilted off the centre (f = 1 + 3 cos^3) against that of 256 independent points, each over
/// 300 repetitions (each variance to ~±8 %, the ratio to ~±12 %). on_disk(ellipse) before each
/// disk, on_result(name, disk, rejection, variance jittered, variance independent) after each
/// sampler; returns each sampler's range of ratios, in the order of for_each_disk_sampler.
template <class T, class OnDisk, class OnResult>
std::vector<RatioRange> stratification_ratios(OnDisk&& on_disk, OnResult&& on_result) {
    using Vec3 = glm::vec<3, T>;
    std::vector<RatioRange> ranges;
    for (const auto& cfg : kStatisticsDisks) {
        const auto e = statistics_disk_ellipse<T>(cfg);
        on_disk(e);
        const glm::dvec3 lobe = glm::normalize(glm::dvec3(e.z) + 0.7 * glm::dvec3(e.x) + 0.4 * glm::dvec3(e.y));
        auto f = [&](const Vec3& w) {
            const double c = glm::dot(glm::dvec3(w), lobe);
            return 1.0 + 3.0 * c * c * c;
        };
        std::size_t k = 0;
        for_each_disk_sampler(e, cfg[0], cfg[1], [&](const std::string& name, const auto& sampler, bool rejection) {
            auto smp = [&](T u1, T u2) { return sampler.sample(glm::vec<2, T>(u1, u2)); };
            const double vj = estimator_variance<T>(smp, f, kStratificationGrid, kStratificationRepetitions, true, 77);
            const double vi = estimator_variance<T>(smp, f, kStratificationGrid, kStratificationRepetitions, false, 78);
            if (ranges.size() <= k) ranges.push_back({name, rejection});
            ranges[k].min = std::min(ranges[k].min, vi / vj);
            ranges[k].max = std::max(ranges[k].max, vi / vj);
            ++k;
            on_result(name, cfg, rejection, vj, vi);
        });
    }
    return ranges;
}

}  // namespace apse_test
