// apse — area-preserving parameterizations for spherical ellipses.
// SPDX-License-Identifier: MIT
#pragma once

// The accuracy of SphericalRectangle against independent references, measured once for
// tests/test_rectangle.cpp (which asserts each measure's budget) and tools/baselines_report.cpp
// (which prints the rectangle table of docs/baselines.md): the mpmath tables of
// tools/gen_rectangle_reference.py (solid angles and map points), long-double Gauss–Legendre
// quadrature of the solid angle of grid cells (chi-square) and finite differences (Jacobian).
// Errors are relative to kappa = 1 + (|corner − o| + |edges|) / (distance to the plane), the
// condition number of the problem with respect to the rounding of the inputs' differences.
// No Catch2: the loaders report a malformed table in `error`, the callers assert or stop.

#include <apse/math.hpp>
#include <apse/spherical_rectangle.hpp>

#include "support/statistics_core.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

namespace apse_test::rectangle {

/// One row of tests/data/rectangle/solid_angle.txt: o, corner s, edges ex, ey; S and kappa.
struct RectCase {
    std::string name;
    double o[3], s[3], ex[3], ey[3];
    double omega, kappa;
};

/// The rectangles of tests/data/rectangle/solid_angle.txt; `error` is empty if the table is sound.
struct RectCases {
    std::string error;
    std::vector<RectCase> cases;
};

inline const RectCases& rectangle_cases() {
    static const RectCases table = [] {
        RectCases out;
        const DataTable t = read_data_table("rectangle/solid_angle.txt");
        if (!t.opened) out.error = "cannot read " + t.path;
        for (const auto& row : t.rows) {
            if (row.size() != 15) {
                out.error = t.path + ": a row of " + std::to_string(row.size()) + " fields instead of 15";
                break;
            }
            RectCase c;
            c.name = row[0];
            for (int i = 0; i < 3; ++i) {
                c.o[i] = num(row[1 + i]);
                c.s[i] = num(row[4 + i]);
                c.ex[i] = num(row[7 + i]);
                c.ey[i] = num(row[10 + i]);
            }
            c.omega = num(row[13]);
            c.kappa = num(row[14]);
            out.cases.push_back(c);
        }
        return out;
    }();
    return table;
}

/// The rectangle named `name`, or nullptr.
inline const RectCase* find_rectangle_case(const std::string& name) {
    for (const auto& c : rectangle_cases().cases)
        if (c.name == name) return &c;
    return nullptr;
}

/// One row of tests/data/rectangle/map.txt: the rectangle, u (and its text) and the mpmath
/// direction and rectangle coordinates st of the map's point.
struct RectMapRow {
    const RectCase* c;
    std::string u_text[2];
    double u[2], direction[3], st[2];
};

struct RectMapRows {
    std::string error;
    std::vector<RectMapRow> rows;
};

inline const RectMapRows& rectangle_map_rows() {
    static const RectMapRows table = [] {
        RectMapRows out;
        const DataTable t = read_data_table("rectangle/map.txt");
        if (!t.opened) out.error = "cannot read " + t.path;
        for (const auto& row : t.rows) {
            if (row.size() != 8) {
                out.error = t.path + ": a row of " + std::to_string(row.size()) + " fields instead of 8";
                break;
            }
            RectMapRow r;
            r.c = find_rectangle_case(row[0]);
            if (!r.c) {
                out.error = t.path + ": no rectangle case " + row[0];
                break;
            }
            for (int i = 0; i < 2; ++i) {
                r.u_text[i] = row[1 + i];
                r.u[i] = num(row[1 + i]);
                r.st[i] = num(row[6 + i]);
            }
            for (int i = 0; i < 3; ++i) r.direction[i] = num(row[3 + i]);
            out.rows.push_back(r);
        }
        return out;
    }();
    return table;
}

template <class T> glm::vec<3, T> vec3_of(const double* p) { return glm::vec<3, T>(T(p[0]), T(p[1]), T(p[2])); }

/// The case's rectangle in T (its inputs are exact in float).
template <class T> apse::SphericalRectangle<T> make_rectangle(const RectCase& c) {
    return apse::SphericalRectangle<T>(vec3_of<T>(c.o), vec3_of<T>(c.s), vec3_of<T>(c.ex), vec3_of<T>(c.ey));
}

inline double norm3(const double* a) { return std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]); }

/// |corner − o| + |ex| + |ey|: the length scale of the inputs' rounding.
inline double length_scale(const RectCase& c) {
    const double r[3] = {c.s[0] - c.o[0], c.s[1] - c.o[1], c.s[2] - c.o[2]};
    return norm3(r) + norm3(c.ex) + norm3(c.ey);
}

/// Long-double local geometry of a case, computed independently of apse: the rectangle is
/// [0, w] x [0, h] in rectangle coordinates, o projects to (fx, fy), at distance d from the plane.
struct LocalGeometry {
    long double w, h, d, fx, fy;
    explicit LocalGeometry(const RectCase& c) {
        long double ex[3], ey[3], r[3];
        for (int i = 0; i < 3; ++i) {
            ex[i] = c.ex[i];
            ey[i] = c.ey[i];
            r[i] = (long double)c.o[i] - c.s[i];
        }
        auto dot = [](const long double* a, const long double* b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; };
        w = std::sqrt(dot(ex, ex));
        h = std::sqrt(dot(ey, ey));
        const long double n[3] = {ex[1] * ey[2] - ex[2] * ey[1], ex[2] * ey[0] - ex[0] * ey[2],
                                  ex[0] * ey[1] - ex[1] * ey[0]};
        d = std::fabs(dot(r, n)) / (w * h);
        fx = dot(r, ex) / w;
        fy = dot(r, ey) / h;
    }
    /// Solid-angle density per unit area at rectangle coordinates (x, y): d / dist³.
    long double density(long double x, long double y) const {
        const long double q = (x - fx) * (x - fx) + (y - fy) * (y - fy) + d * d;
        return d / (q * std::sqrt(q));
    }
    /// Solid angle of the cell [x0,x1] x [y0,y1] (rectangle coordinates) by n x n Gauss–Legendre.
    long double cell(const GaussLegendre& gl, long double x0, long double x1, long double y0, long double y1) const {
        return gl.integrate([&](long double x) { return gl.integrate([&](long double y) { return density(x, y); }, y0, y1); },
                            x0, x1);
    }
};

/// The published solid-angle formula S = g0 + g1 + g2 + g3 − 2 pi (docs/math.md §7), evaluated in T:
/// only used to document its cancellation for far rectangles.
template <class T> T published_solid_angle(const RectCase& c) {
    using V = glm::vec<3, T>;
    const V ex = vec3_of<T>(c.ex), ey = vec3_of<T>(c.ey);
    const T lx = glm::length(ex), ly = glm::length(ey);
    const V x = ex / lx, y = ey / ly;
    V z = glm::cross(x, y);
    const V dl = vec3_of<T>(c.s) - vec3_of<T>(c.o);
    const T x0 = glm::dot(dl, x), y0 = glm::dot(dl, y);
    T z0 = glm::dot(dl, z);
    if (z0 > 0) z0 = -z0;
    const T x1 = x0 + lx, y1 = y0 + ly;
    const V v00(x0, y0, z0), v01(x0, y1, z0), v10(x1, y0, z0), v11(x1, y1, z0);
    const V n0 = glm::normalize(glm::cross(v00, v10)), n1 = glm::normalize(glm::cross(v10, v11));
    const V n2 = glm::normalize(glm::cross(v11, v01)), n3 = glm::normalize(glm::cross(v01, v00));
    const T g0 = std::acos(std::clamp(-glm::dot(n0, n1), T(-1), T(1))), g1 = std::acos(std::clamp(-glm::dot(n1, n2), T(-1), T(1)));
    const T g2 = std::acos(std::clamp(-glm::dot(n2, n3), T(-1), T(1))), g3 = std::acos(std::clamp(-glm::dot(n3, n0), T(-1), T(1)));
    return g0 + g1 + g2 + g3 - apse::two_pi_v<T>;
}

/// Relative error of the published form's S against the table.
template <class T> double published_solid_angle_error(const RectCase& c) {
    return std::fabs(double(published_solid_angle<T>(c)) - c.omega) / c.omega;
}

/// Relative error of apse's S against the table.
template <class T> double solid_angle_error(const RectCase& c) {
    return std::fabs(double(make_rectangle<T>(c).solid_angle()) - c.omega) / c.omega;
}

/// The unit squares on the axis 1e2, 1e4, 1e6 and 1e8 sizes away: where the published form cancels.
constexpr const char* far_axis_cases[] = {"far_axis_100", "far_axis_10000", "far_axis_1e+06", "far_axis_1e+08"};

/// S of one rectangle in T: whether it is empty, S, and the relative errors of S from the
/// corner constructor and from the centred one (from_center: the centre rounded once more in
/// T) against the table (0 where the table's S is 0: o in the plane).
struct SolidAngleCheck {
    const RectCase* c;
    bool empty;
    double solid_angle, error, centred_error;
};

template <class T> std::vector<SolidAngleCheck> solid_angle_checks() {
    std::vector<SolidAngleCheck> out;
    for (const RectCase& c : rectangle_cases().cases) {
        const auto r = make_rectangle<T>(c);
        SolidAngleCheck k{&c, r.empty(), double(r.solid_angle()), 0.0, 0.0};
        if (c.omega != 0) {
            k.error = std::fabs(double(r.solid_angle()) - c.omega) / c.omega;
            const auto ctr = apse::SphericalRectangle<T>::from_center(
                vec3_of<T>(c.o), vec3_of<T>(c.s) + T(0.5) * vec3_of<T>(c.ex) + T(0.5) * vec3_of<T>(c.ey),
                T(0.5) * vec3_of<T>(c.ex), T(0.5) * vec3_of<T>(c.ey));
            k.centred_error = std::fabs(double(ctr.solid_angle()) - c.omega) / c.omega;
        }
        out.push_back(k);
    }
    return out;
}

/// The largest relative error of S over kappa (all rectangles with S > 0), and the largest
/// relative error of S among the far rectangles (names "far_*": 1e2..1e8 sizes away).
struct SolidAngleSummary {
    double worst_per_kappa = 0, worst_far = 0;
    const RectCase* worst = nullptr;
    const RectCase* worst_far_case = nullptr;
};

inline SolidAngleSummary summarize(const std::vector<SolidAngleCheck>& checks) {
    SolidAngleSummary s;
    for (const auto& k : checks) {
        if (k.c->omega == 0) continue;
        if (k.error / k.c->kappa > s.worst_per_kappa) {
            s.worst_per_kappa = k.error / k.c->kappa;
            s.worst = k.c;
        }
        if (k.c->name.rfind("far_", 0) == 0 && k.error > s.worst_far) {
            s.worst_far = k.error;
            s.worst_far_case = k.c;
        }
    }
    return s;
}

/// The map at one reference point in T: the max-norm error of st and the Euclidean error of the
/// direction against mpmath, and whether the reported pdf is exactly 1/S.
struct MapCheck {
    const RectMapRow* row;
    double st_error, direction_error;
    bool pdf_is_inverse_solid_angle;
};

template <class T> std::vector<MapCheck> map_checks() {
    std::vector<MapCheck> out;
    for (const RectMapRow& row : rectangle_map_rows().rows) {
        const auto r = make_rectangle<T>(*row.c);
        const auto p = r.sample_point(glm::vec<2, T>(T(row.u[0]), T(row.u[1])));
        const double dir_err = std::sqrt(std::pow(p.direction.x - row.direction[0], 2) + std::pow(p.direction.y - row.direction[1], 2) +
                                         std::pow(p.direction.z - row.direction[2], 2));
        const double st_err = std::max(std::fabs(p.st.x - row.st[0]), std::fabs(p.st.y - row.st[1]));
        out.push_back({&row, st_err, dir_err, p.pdf == T(1) / r.solid_angle()});
    }
    return out;
}

/// max st error / kappa and max direction error / kappa over the map's reference points.
struct MapSummary {
    double st_per_kappa = 0, direction_per_kappa = 0;
};

inline MapSummary summarize(const std::vector<MapCheck>& checks) {
    MapSummary s;
    for (const auto& k : checks) {
        s.st_per_kappa = std::max(s.st_per_kappa, k.st_error / k.row->c->kappa);
        s.direction_per_kappa = std::max(s.direction_per_kappa, k.direction_error / k.row->c->kappa);
    }
    return s;
}

/// The finite-difference step of the Jacobian check: 2^-12 in double, 2^-6 in float (float
/// points resolve only ~1e-7 of the rectangle).
template <class T> constexpr double jacobian_step() { return sizeof(T) == sizeof(float) ? 0x1p-6 : 0x1p-12; }

/// |Jacobian / S − 1| of the map at one u: |d st/du1 x d st/du2| w h (d / dist³), the
/// derivatives by fourth-order central differences with step jacobian_step<T>().
struct JacobianCheck {
    const RectCase* c;
    double u1, u2, error;
};

/// At 4 x 4 interior points of every rectangle with S > 0 and kappa <= 100 (grazing and very
/// close ones: the rounding over the step would dominate).
template <class T> std::vector<JacobianCheck> jacobian_checks() {
    const double delta = jacobian_step<T>();
    std::vector<JacobianCheck> out;
    for (const RectCase& c : rectangle_cases().cases) {
        if (c.omega == 0 || c.kappa > 100) continue;
        const auto r = make_rectangle<T>(c);
        const LocalGeometry g(c);
        for (int i = 1; i < 5; ++i)
            for (int j = 1; j < 5; ++j) {
                const double u1 = (i - 0.5) / 4.5, u2 = (j - 0.3) / 4.5;  // interior, irregular
                auto st = [&](double a, double b) {
                    const auto p = r.sample_point(glm::vec<2, T>(T(a), T(b))).st;
                    return glm::dvec2(p.x, p.y);
                };
                const glm::dvec2 du1 = (-st(u1 + 2 * delta, u2) + 8.0 * st(u1 + delta, u2) - 8.0 * st(u1 - delta, u2) +
                                        st(u1 - 2 * delta, u2)) / (12 * delta);
                const glm::dvec2 du2 = (-st(u1, u2 + 2 * delta) + 8.0 * st(u1, u2 + delta) - 8.0 * st(u1, u2 - delta) +
                                        st(u1, u2 - 2 * delta)) / (12 * delta);
                const auto p = st(u1, u2);
                const double jac = std::fabs(du1.x * du2.y - du1.y * du2.x) * double(g.w * g.h) *
                                   double(g.density(g.w * p.x, g.h * p.y));
                out.push_back({&c, u1, u2, std::fabs(jac / c.omega - 1)});
            }
    }
    return out;
}

/// The round trip's conditioning: invert() starts from a direction, whose rounding (eps) moves
/// the plane point by eps·dist relative to the edges: kappa·length_scale / min edge.
inline double round_trip_condition(const RectCase& c) {
    return c.kappa * length_scale(c) / std::min(norm3(c.ex), norm3(c.ey));
}

/// Calls f(c, r, i, j, u, p, error, kappa_rt) for the 9 x 9 points u = (i/8, j/8) of every
/// rectangle with S > 0: p = r.sample_point(u), error = max-norm |invert(p.direction) − u|.
template <class T, class F> void for_each_round_trip(F&& f) {
    for (const RectCase& c : rectangle_cases().cases) {
        if (c.omega == 0) continue;
        const auto r = make_rectangle<T>(c);
        const double kappa_rt = round_trip_condition(c);
        for (int i = 0; i <= 8; ++i)
            for (int j = 0; j <= 8; ++j) {
                const glm::vec<2, T> u(T(i / 8.0), T(j / 8.0));
                const auto p = r.sample_point(u);
                const auto back = r.invert(p.direction);
                const double err = std::max(std::fabs(double(back.x) - u.x), std::fabs(double(back.y) - u.y));
                f(c, r, i, j, u, p, err, kappa_rt);
            }
    }
}

/// The largest round-trip error / kappa_rt and its rectangle.
struct RoundTripSummary {
    double worst_per_kappa = 0;
    const RectCase* worst = nullptr;
};

template <class T> RoundTripSummary round_trip_summary() {
    RoundTripSummary s;
    for_each_round_trip<T>([&](const RectCase& c, const auto&, int, int, const auto&, const auto&, double err, double kappa_rt) {
        if (err / kappa_rt > s.worst_per_kappa) {
            s.worst_per_kappa = err / kappa_rt;
            s.worst = &c;
        }
    });
    return s;
}

/// The chi-square test's rectangles, its grid (cells per side), sample count and first seed.
constexpr const char* rectangle_chi2_cases[] = {"near02", "near05", "near08", "random03", "grazing04", "far_oblique_100"};
constexpr int rectangle_chi2_grid = 16;
constexpr long rectangle_chi2_samples = 1000000;
template <class T> constexpr std::uint64_t rectangle_chi2_seed() { return sizeof(T) == sizeof(float) ? 101 : 202; }

/// Chi-square of rectangle_chi2_samples samples of one rectangle (seeded) histogrammed over the
/// grid of its rectangle coordinates, against N Omega_cell / S, Omega_cell by 12 x 12-point
/// Gauss–Legendre quadrature in long double; quadrature_error = |sum of the cells / table's S − 1|.
struct RectangleChi2 {
    Chi2Result result;
    double quadrature_error;
};

template <class T> RectangleChi2 rectangle_chi2(const RectCase& c, std::uint64_t seed) {
    const int n = rectangle_chi2_grid;
    const long N = rectangle_chi2_samples;
    const GaussLegendre gl(12);
    const LocalGeometry g(c);
    std::vector<double> expected(n * n), observed(n * n, 0.0);
    long double total = 0;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            const long double e = g.cell(gl, g.w * i / n, g.w * (i + 1) / n, g.h * j / n, g.h * (j + 1) / n);
            expected[i * n + j] = double(e);
            total += e;
        }
    RectangleChi2 out;
    out.quadrature_error = std::fabs(double(total) / c.omega - 1);
    for (double& e : expected) e *= double(N / total);
    const auto r = make_rectangle<T>(c);
    Rng rng(seed);
    for (long k = 0; k < N; ++k) {
        const auto p = r.sample_point(glm::vec<2, T>(rng.uniform<T>(), rng.uniform<T>()));
        const int i = std::min(n - 1, int(p.st.x * n)), j = std::min(n - 1, int(p.st.y * n));
        observed[i * n + j] += 1;
    }
    out.result = chi2_test(observed, expected);
    return out;
}

}  // namespace apse_test::rectangle
