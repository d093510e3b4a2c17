// apse — area-preserving parameterizations for spherical ellipses.
// SPDX-License-Identifier: MIT
#pragma once

// The projections against the committed mpmath tables of tests/data/projection (written by
// tools/gen_projection_reference.py): the tables' rows, the projection of each row's light, its
// errors against the reference and the budget they are held to. Shared by test_projection and
// test_spherical_ellipse (which check every row against its budget) and projection_report (the
// accuracy table of docs/projection.md), so that the page reports the error the tests check.
//
// Inputs are hexadecimal floating literals exact in float (std::strtod parses them exactly), so
// float and double read the same geometry; the reference values carry 30 digits (parsed to long
// double) and each row its condition numbers kappa with respect to the rounding of the inputs'
// difference (c − o, normals, axes).

#include <apse/math.hpp>
#include <apse/projection.hpp>
#include <apse/spherical_ellipse.hpp>

#include <cmath>
#include <cstddef>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace apse_test {

/// The light shapes of the projection tables, in the order of the accuracy table.
enum class Light { disk, ellipse, sphere, ellipsoid };

constexpr Light all_lights[] = {Light::disk, Light::ellipse, Light::sphere, Light::ellipsoid};

/// The table of a light shape, in tests/data/projection.
inline const char* table_file(Light light) {
    switch (light) {
    case Light::disk: return "disks.csv";
    case Light::ellipse: return "ellipses.csv";
    case Light::sphere: return "spheres.csv";
    case Light::ellipsoid: return "ellipsoids.csv";
    }
    return "";
}

/// The reference spherical ellipse of one row and its condition numbers.
struct ReferenceEllipse {
    bool empty = false;
    long double alpha = 0, beta = 0, omega = 0;
    glm::dvec3 ze{0}, xe{0};  ///< centre direction and major axis
    double k_alpha = 0, k_beta = 0, k_omega = 0, k_frame = 0;
};

/// One row: a light seen from o, and its reference ellipse.
struct ReferenceLight {
    std::string category;  ///< the row's case (far, near, rim, grazing, ...)
    std::size_t row = 0;   ///< its index in the table
    glm::dvec3 o{0}, c{0};  ///< shading point, centre
    /// disk: the normal; ellipse: the semi-diameters U, V; ellipsoid: the semi-axes A1, A2, A3
    glm::dvec3 axes[3] = {glm::dvec3(0), glm::dvec3(0), glm::dvec3(0)};
    double radius = 0;  ///< disk, sphere
    ReferenceEllipse expected;
};

/// The rows of one table, or why there are none.
struct ReferenceLights {
    std::vector<ReferenceLight> rows;
    std::string error;  ///< empty when the table was read
};

namespace detail_reference {

/// A CSV table: '#' comments, a header line naming the columns, then rows.
struct Csv {
    std::vector<std::string> columns;
    std::vector<std::vector<std::string>> rows;
    std::string error;
    int col(const std::string& name) const {
        for (std::size_t i = 0; i < columns.size(); ++i)
            if (columns[i] == name) return int(i);
        return -1;
    }
};

inline Csv read_csv(const std::string& path, const std::vector<std::string>& required) {
    Csv t;
    std::ifstream in(path);
    if (!in) {
        t.error = path + ": cannot read it";
        return t;
    }
    std::string line;
    while (std::getline(in, line)) {
        if (line.empty() || line[0] == '#') continue;
        std::vector<std::string> f;
        std::stringstream ss(line);
        std::string s;
        while (std::getline(ss, s, ',')) f.push_back(s);
        if (t.columns.empty()) {
            t.columns = f;
        } else if (f.size() != t.columns.size()) {
            t.error = path + ": bad row: " + line;
            return t;
        } else {
            t.rows.push_back(f);
        }
    }
    for (const std::string& c : required)
        if (t.col(c) < 0) t.error = path + ": no column " + c;
    return t;
}

/// The field `name` of row `f` (a column read_csv checked).
inline const std::string& field(const Csv& t, const std::vector<std::string>& f, const std::string& name) {
    return f[std::size_t(t.col(name))];
}
inline double num(const Csv& t, const std::vector<std::string>& f, const std::string& name) {
    return std::strtod(field(t, f, name).c_str(), nullptr);
}
inline long double dec(const Csv& t, const std::vector<std::string>& f, const std::string& name) {
    return std::strtold(field(t, f, name).c_str(), nullptr);
}
inline glm::dvec3 vec(const Csv& t, const std::vector<std::string>& f, const std::string& p) {
    return glm::dvec3(num(t, f, p + "_x"), num(t, f, p + "_y"), num(t, f, p + "_z"));
}
inline glm::dvec3 dec_vec(const Csv& t, const std::vector<std::string>& f, const std::string& p) {
    return glm::dvec3(double(dec(t, f, p + "_x")), double(dec(t, f, p + "_y")), double(dec(t, f, p + "_z")));
}

}  // namespace detail_reference

/// The rows of the table of `light` in `dir` (tests/data/projection).
inline ReferenceLights read_reference_lights(const std::string& dir, Light light) {
    namespace d = detail_reference;
    std::vector<std::string> axes, required = {"case", "empty", "alpha", "beta", "omega", "kappa_alpha", "kappa_beta",
                                               "kappa_omega", "kappa_frame"};
    switch (light) {
    case Light::disk: axes = {"n"}; required.push_back("r"); break;
    case Light::ellipse: axes = {"u", "v"}; break;
    case Light::sphere: required.push_back("radius"); break;
    case Light::ellipsoid: axes = {"a1", "a2", "a3"}; break;
    }
    std::vector<std::string> vectors = {"o", "c", "ze", "xe"};
    vectors.insert(vectors.end(), axes.begin(), axes.end());
    for (const std::string& v : vectors)
        for (const char* k : {"_x", "_y", "_z"}) required.push_back(v + k);
    const d::Csv t = d::read_csv(dir + "/" + table_file(light), required);
    ReferenceLights out;
    out.error = t.error;
    if (!t.error.empty()) return out;
    for (std::size_t i = 0; i < t.rows.size(); ++i) {
        const auto& f = t.rows[i];
        ReferenceLight r;
        r.category = d::field(t, f, "case");
        r.row = i;
        r.o = d::vec(t, f, "o");
        r.c = d::vec(t, f, "c");
        for (std::size_t k = 0; k < axes.size(); ++k) r.axes[k] = d::vec(t, f, axes[k]);
        if (light == Light::disk) r.radius = d::num(t, f, "r");
        if (light == Light::sphere) r.radius = d::num(t, f, "radius");
        ReferenceEllipse& e = r.expected;
        e.empty = d::field(t, f, "empty") == "1";
        if (!e.empty) {
            e.alpha = d::dec(t, f, "alpha");
            e.beta = d::dec(t, f, "beta");
            e.omega = d::dec(t, f, "omega");
            e.ze = d::dec_vec(t, f, "ze");
            e.xe = d::dec_vec(t, f, "xe");
            e.k_alpha = d::num(t, f, "kappa_alpha");
            e.k_beta = d::num(t, f, "kappa_beta");
            e.k_omega = d::num(t, f, "kappa_omega");
            e.k_frame = d::num(t, f, "kappa_frame");
        }
        out.rows.push_back(r);
    }
    return out;
}

/// The light of one row projected in T (its inputs are exact in float): project_disk(o, c, n, r),
/// project_ellipse(o, c, U, V), project_sphere(o, c, R) or project_ellipsoid(o, c, A1, A2, A3).
template <class T> apse::SphericalEllipse<T> project(Light light, const ReferenceLight& r) {
    using V = glm::vec<3, T>;
    const V o(r.o), c(r.c), a(r.axes[0]), b(r.axes[1]), d(r.axes[2]);
    switch (light) {
    case Light::disk: return apse::project_disk(o, c, a, T(r.radius));
    case Light::ellipse: return apse::project_ellipse(o, c, a, b);
    case Light::sphere: return apse::project_sphere(o, c, T(r.radius));
    case Light::ellipsoid: return apse::project_ellipsoid(o, c, a, b, d);
    }
    return apse::SphericalEllipse<T>::make_empty();
}

/// Relative error of x (|x| where the reference is 0).
inline double rel_err(long double x, long double ref) {
    return double(ref == 0 ? std::fabs(x) : std::fabs(x - ref) / std::fabs(ref));
}

/// Error budget: C eps (kappa + K): the rounding of the inputs' difference (kappa eps) plus the
/// implementation's own few dozen roundings.
template <class T> double budget(double kappa) {
    return 8.0 * double(apse::epsilon<T>()) * (kappa + 64.0);
}

/// The errors of a computed (non-empty) ellipse against its reference.
struct ProjectionErrors {
    double alpha = 0, beta = 0, omega = 0;  ///< relative errors of alpha, beta, Omega
    double z = 0;                           ///< |z − z_ref|, radians
    /// (alpha − beta)/alpha of the reference: the major axis is compared where it exceeds 1e-2
    double gap = 0;
    double x = 0;  ///< |x − x_ref| up to the axis' sign where compared, else 0
    /// max over alpha, beta, Omega and z of the error in units of eps (kappa + 1)
    double normalised = 0;
    double kappa = 0;  ///< max(kappa_alpha, kappa_beta, kappa_omega)
};

template <class T> ProjectionErrors projection_errors(const apse::SphericalEllipse<T>& got, const ReferenceEllipse& ex) {
    ProjectionErrors e;
    e.alpha = rel_err(got.alpha(), ex.alpha);
    e.beta = rel_err(got.beta(), ex.beta);
    e.omega = rel_err(got.solid_angle(), ex.omega);
    e.z = glm::length(glm::dvec3(got.z) - ex.ze);
    e.gap = double((ex.alpha - ex.beta) / ex.alpha);
    if (e.gap > 1e-2) {
        const glm::dvec3 gx(got.x);
        e.x = std::fmin(glm::length(gx - ex.xe), glm::length(gx + ex.xe));
    }
    const double eps = double(apse::epsilon<T>());
    e.normalised = std::fmax(std::fmax(e.alpha / (ex.k_alpha + 1), e.beta / (ex.k_beta + 1)),
                             std::fmax(e.omega / (ex.k_omega + 1), e.z / (ex.k_frame + 1))) / eps;
    e.kappa = std::fmax(ex.k_alpha, std::fmax(ex.k_beta, ex.k_omega));
    return e;
}

/// Whether every error is within its budget (the major axis' divided by the gap).
template <class T> bool within_budget(const ProjectionErrors& e, const ReferenceEllipse& ex) {
    return e.alpha <= budget<T>(ex.k_alpha) && e.beta <= budget<T>(ex.k_beta) && e.omega <= budget<T>(ex.k_omega) &&
           e.z <= budget<T>(ex.k_frame) && (e.gap <= 1e-2 || e.x <= budget<T>(ex.k_frame) / e.gap);
}

/// The largest errors over a table, per case and in all.
struct ProjectionStats {
    struct Entry {
        int n = 0;      ///< non-empty rows
        int empty = 0;  ///< empty rows
        double alpha = 0, beta = 0, omega = 0, z = 0, x = 0, normalised = 0, kappa = 0;
        void add(const Entry& o) {
            n += o.n;
            empty += o.empty;
            alpha = std::fmax(alpha, o.alpha);
            beta = std::fmax(beta, o.beta);
            omega = std::fmax(omega, o.omega);
            z = std::fmax(z, o.z);
            x = std::fmax(x, o.x);
            normalised = std::fmax(normalised, o.normalised);
            kappa = std::fmax(kappa, o.kappa);
        }
    };
    std::map<std::string, Entry> by_case;

    void add(const std::string& category, const ProjectionErrors& e) {
        Entry one;
        one.n = 1;
        one.alpha = e.alpha;
        one.beta = e.beta;
        one.omega = e.omega;
        one.z = e.z;
        one.x = e.x;
        one.normalised = e.normalised;
        one.kappa = e.kappa;
        by_case[category].add(one);
    }
    void add_empty(const std::string& category) { ++by_case[category].empty; }

    Entry all() const {
        Entry a;
        for (const auto& kv : by_case) a.add(kv.second);
        return a;
    }

    /// One line per case and the total: the largest errors (x_e: the major axis, where compared).
    void print(const char* what, const char* type) const {
        std::printf("%-10s %-6s | %-20s %4s | %9s %9s %9s %9s %9s | %9s | %s\n", what, type, "case", "n", "alpha", "beta",
                    "omega", "z_e", "x_e", "max kappa", "max err/(eps(kappa+1))");
        const auto line = [&](const std::string& name, const Entry& e) {
            std::printf("%-10s %-6s | %-20s %4d | %9.2e %9.2e %9.2e %9.2e %9.2e | %9.2e | %.1f\n", what, type, name.c_str(),
                        e.n, e.alpha, e.beta, e.omega, e.z, e.x, e.kappa, e.normalised);
        };
        for (const auto& kv : by_case) line(kv.first, kv.second);
        line("ALL", all());
    }
};

// ---------------------------------------------------------------------------------------------
// the solid angle from two tangents (solid_angle.csv)
// ---------------------------------------------------------------------------------------------

/// One row of solid_angle.csv: the ellipse of tangents tan_alpha >= tan_beta and its Omega.
struct SolidAngleReference {
    std::string category;
    double tan_alpha = 0, tan_beta = 0;  ///< exact in float
    long double omega = 0;
};

struct SolidAngleReferences {
    std::vector<SolidAngleReference> rows;
    std::string error;  ///< empty when the table was read
};

inline SolidAngleReferences read_solid_angle_references(const std::string& dir) {
    namespace d = detail_reference;
    const d::Csv t = d::read_csv(dir + "/solid_angle.csv", {"case", "tan_alpha", "tan_beta", "omega"});
    SolidAngleReferences out;
    out.error = t.error;
    if (!t.error.empty()) return out;
    for (const auto& f : t.rows)
        out.rows.push_back({d::field(t, f, "case"), d::num(t, f, "tan_alpha"), d::num(t, f, "tan_beta"),
                            d::dec(t, f, "omega")});
    return out;
}

/// Whether the row is an ellipse in T: below tan_min (float: rows down to 2^-45) it is empty by
/// definition.
template <class T> bool solid_angle_applies(const SolidAngleReference& r) {
    return T(r.tan_beta) >= apse::detail::tan_min<T>();
}

/// The row's ellipse in T (canonical frame, from_tangents).
template <class T> apse::SphericalEllipse<T> solid_angle_ellipse(const SolidAngleReference& r) {
    using V = glm::vec<3, T>;
    return apse::SphericalEllipse<T>::from_tangents(V(1, 0, 0), V(0, 1, 0), V(0, 0, 1), T(r.tan_alpha), T(r.tan_beta));
}

/// Relative error of the row's solid angle in T (a row solid_angle_applies to).
template <class T> double solid_angle_error(const SolidAngleReference& r) {
    return rel_err(solid_angle_ellipse<T>(r).solid_angle(), r.omega);
}

/// The solid-angle budget: 8 eps relative.
template <class T> double solid_angle_budget() { return 8.0 * double(apse::epsilon<T>()); }

}  // namespace apse_test
