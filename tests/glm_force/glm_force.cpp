// apse under one of GLM's configuration macros (GLM_FORCE_*), given on the command line by
// tests/CMakeLists.txt (one executable per macro set): <apse/apse.hpp> compiles with the macros
// (warnings as errors), the samplers used here instantiate, and real results hold — every non-empty disk of the mpmath reference
// table (tests/data/projection/disks.csv, tools/gen_projection_reference.py) sampled by the
// LD-radial map and by DiskLight<RuntimeSampler> (the parallel map) with pdf = 1/Omega within the projection's budget, the inverse
// round trip, and a rectangle's solid angle against the closed form. Prints which macros were
// defined and GLM's vector sizes; exits non-zero on any failure.
#include <apse/apse.hpp>
#include <apse/math.hpp>
#include <apse/runtime_sampler.hpp>
#include <apse/spherical_rectangle.hpp>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <type_traits>
#include <vector>

namespace {

int failures = 0;

void expect(bool ok, const char* what, const std::string& detail) {
    if (ok) return;
    ++failures;
    if (failures <= 20) std::printf("FAILED: %s %s\n", what, detail.c_str());
}

/// The rows of disks.csv: (o, c, n, r, empty, omega, kappa_omega).
struct DiskRow {
    double o[3], c[3], n[3], r;
    bool empty;
    long double omega;
    double kappa_omega;
    std::string line;
};

std::vector<DiskRow> read_disks() {
    std::ifstream in(std::string(APSE_TEST_DATA_DIR) + "/projection/disks.csv");
    std::vector<DiskRow> rows;
    std::string line;
    bool header = false;
    while (std::getline(in, line)) {
        if (line.empty() || line[0] == '#') continue;
        if (!header) {  // case,o_x,o_y,o_z,c_x,c_y,c_z,n_x,n_y,n_z,r,empty,alpha,beta,omega,...,kappa_omega,kappa_frame
            header = true;
            continue;
        }
        std::vector<std::string> f;
        std::stringstream ss(line);
        std::string s;
        while (std::getline(ss, s, ',')) f.push_back(s);
        if (f.size() != 25) {
            expect(false, "disks.csv row with 25 fields:", line);
            continue;
        }
        DiskRow r;
        for (int i = 0; i < 3; ++i) {
            r.o[i] = std::strtod(f[std::size_t(1 + i)].c_str(), nullptr);
            r.c[i] = std::strtod(f[std::size_t(4 + i)].c_str(), nullptr);
            r.n[i] = std::strtod(f[std::size_t(7 + i)].c_str(), nullptr);
        }
        r.r = std::strtod(f[10].c_str(), nullptr);
        r.empty = f[11] == "1";
        r.omega = std::strtold(f[14].c_str(), nullptr);
        r.kappa_omega = std::strtod(f[23].c_str(), nullptr);
        r.line = line;
        rows.push_back(r);
    }
    return rows;
}

template <class T> glm::vec<3, T> v3(const double* p) { return glm::vec<3, T>(T(p[0]), T(p[1]), T(p[2])); }

/// The samplers stay plain data under every macro set (kernel arguments, memcpy to devices).
template <class T> constexpr bool plain_data() {
    return std::is_trivially_copyable<apse::LdRadialMap<T>>::value &&
           std::is_trivially_copyable<apse::TabulatedLdRadialMap<T>>::value &&
           std::is_trivially_copyable<apse::DiskLight<apse::RuntimeSampler<T>>>::value &&
           std::is_trivially_copyable<apse::DiskLight<apse::TabulatedLdRadialMap<T>>>::value &&
           std::is_trivially_copyable<apse::SphericalRectangle<T>>::value &&
           std::is_trivially_copyable<apse::PointSample<T>>::value;
}
static_assert(plain_data<float>() && plain_data<double>(), "apse's types are trivially copyable");

template <class T> void check_type(const std::vector<DiskRow>& rows) {
    const char* type = sizeof(T) == 4 ? "float" : "double";
    const double eps = double(apse::epsilon<T>());
    int checked = 0;
    for (const DiskRow& row : rows) {
        if (row.empty) continue;
        const glm::vec<3, T> o = v3<T>(row.o), c = v3<T>(row.c), n = v3<T>(row.n);
        const apse::LdRadialMap<T> map(apse::project_disk(o, c, n, T(row.r)));
        const apse::DiskLight<apse::RuntimeSampler<T>> light(o, c, n, T(row.r), apse::MapKind::parallel);
        const glm::vec<2, T> u(T(0.3), T(0.7));
        const apse::DirectionSample<T> s = map.sample(u);
        const auto ls = light.sample(u);
        // test_projection's budget for Omega, 8 eps (kappa + 64) (input rounding amplified by the
        // condition number, plus the implementation's own roundings); 1/Omega adds one rounding
        const double budget = 8 * eps * (row.kappa_omega + 64);
        const double err = std::fabs(double((long double)s.pdf * row.omega - 1));
        const double err_light = std::fabs(double((long double)ls.pdf * row.omega - 1));
        expect(err <= budget, "LdRadialMap pdf * Omega = 1:", std::string(type) + " " + row.line);
        expect(err_light <= budget, "DiskLight pdf * Omega = 1:", std::string(type) + " " + row.line);
        expect(map.pdf(s.direction) == s.pdf || !(map.pdf(s.direction) > T(0)), "pdf(sample) = 1/Omega:", row.line);
        ++checked;
    }
    expect(checked > 100, "rows checked > 100:", std::string(type) + " " + std::to_string(checked));

    // the LD-radial and tabulated inverses on a moderate light (the disk of radius 1 at (0.5, 0, −1)
    // seen from the origin): float 2e-3 / double 1e-8, the round-trip budget of test_tabulated
    static apse::TabulationTable table;
    table.build();
    const glm::vec<3, T> o(T(0)), c(T(0.5), T(0), T(-1)), n(T(0), T(0), T(1));
    const apse::SphericalEllipse<T> e = apse::project_disk(o, c, n, T(1));
    const apse::LdRadialMap<T> ld(e);
    const apse::TabulatedLdRadialMap<T> tab(e, table.view());
    const double rt = sizeof(T) == 4 ? 2e-3 : 1e-8;
    for (int i = 1; i < 8; ++i)
        for (int j = 1; j < 8; ++j) {
            const glm::vec<2, T> u(T(i / 8.0 + 0.01), T(j / 8.0 - 0.02));
            const glm::vec<2, T> a = ld.invert(ld.sample(u).direction), b = tab.invert(tab.sample(u).direction);
            expect(std::fabs(double(a.x - u.x)) <= rt && std::fabs(double(a.y - u.y)) <= rt, "LdRadialMap round trip", type);
            expect(std::fabs(double(b.x - u.x)) <= rt && std::fabs(double(b.y - u.y)) <= rt, "tabulated round trip", type);
        }

    // the square [−1, 1]² at distance 1 seen from its axis: Omega = 4 asin(1/2) = 2 pi/3;
    // the rectangle code's own budget, a few ulps: 16 eps
    const apse::SphericalRectangle<T> sq(glm::vec<3, T>(T(0)), glm::vec<3, T>(T(-1), T(-1), T(-1)),
                                         glm::vec<3, T>(T(2), T(0), T(0)), glm::vec<3, T>(T(0), T(2), T(0)));
    const double third = 2.0943951023931954923;  // 2 pi / 3
    expect(std::fabs(double(sq.solid_angle()) / third - 1) <= 16 * eps, "rectangle solid angle", type);
    const apse::RectanglePoint<T> p = sq.sample_point(glm::vec<2, T>(T(0.25), T(0.75)));
    expect(std::fabs(double(p.point.z) + 1) <= 16 * eps && std::fabs(double(p.distance) - double(glm::length(p.point))) <= 16 * eps,
           "rectangle point", type);
    std::printf("[%s] %d disks: pdf * Omega = 1; round trips; rectangle\n", type, checked);
}

}  // namespace

int main() {
    // APSE_GLM_FORCE_MACROS: the macro set, as tests/CMakeLists.txt defined it
    std::printf("GLM %d, sizeof(glm::vec3) = %zu, sizeof(glm::dvec3) = %zu; macros: %s\n", GLM_VERSION,
                sizeof(glm::vec3), sizeof(glm::dvec3), APSE_GLM_FORCE_MACROS);
    const std::vector<DiskRow> rows = read_disks();
    expect(rows.size() > 100, "disks.csv read", std::to_string(rows.size()));
    check_type<float>(rows);
    check_type<double>(rows);
    std::printf("%s\n", failures == 0 ? "ok" : "FAILED");
    return failures == 0 ? 0 : 1;
}
