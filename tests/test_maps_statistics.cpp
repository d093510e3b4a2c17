// Statistical tests of the three maps, float and double: chi-square uniformity against cell
// probabilities integrated independently on the disk, and unbiasedness (stratification of every
// sampler: test_stratification.cpp).
#include <apse/maps/ld_radial.hpp>
#include <apse/maps/parallel.hpp>
#include <apse/comparison.hpp>
#include <apse/projection.hpp>

#include "support/map_testing.hpp"

#include "support/catch.hpp"

#include <cmath>
#include <cstdio>
#include <string>

namespace {

template <class T> using Vec2 = glm::vec<2, T>;
template <class T> using Vec3 = glm::vec<3, T>;

/// Disk configurations (disk frame of DiskCells: o = 0, plane z = d, centre (h, 0, d), r = 1):
/// frontal, oblique, grazing and farther. The integrand d/(x^2 + y^2 + d^2)^{3/2} is smooth on
/// every cell (its peak, at the foot point, is at least d = 0.7 away when it lies on the disk);
/// 8 x 8 Gauss–Legendre nodes per cell integrate it far below the chi-square's resolution
/// (~1/sqrt(625) per cell).
const double kDisks[][2] = {{1.0, 0.0}, {0.7, 1.3}, {0.25, 2.5}};
constexpr int kMaps = 3, kTypes = 2, kDiskCount = 3;
constexpr int kChi2Tests = kMaps * kTypes * kDiskCount;

template <class T, class F> void for_each_map(const apse::SphericalEllipse<T>& e, F&& f) {
    f(std::string("radial"), apse::RadialMap<T>(e));
    f(std::string("ld_radial"), apse::LdRadialMap<T>(e));
    f(std::string("parallel"), apse::ParallelMap<T>(e));
}

}  // namespace

TEMPLATE_TEST_CASE("chi-square: samples are uniform in solid angle", "[maps][chi2]", float, double) {
    using T = TestType;
    // 100 000 samples into 10 equal-area rings x 16 sectors of the disk (625 expected per cell on
    // average); expected counts from DiskCells quadrature (independent of apse). Family-wise level
    // 1% over all kChi2Tests tests (both types), Šidák-corrected per test.
    const double level = apse_test::sidak(0.01, kChi2Tests);
    std::uint64_t seed = sizeof(T) == 4 ? 1000 : 2000;
    for (const auto& cfg : kDisks) {
        const apse_test::DiskCells cells{cfg[0], cfg[1], 1.0, 10, 16};
        const auto e = apse::project_disk(Vec3<T>(0), Vec3<T>(T(cfg[1]), T(0), T(cfg[0])), Vec3<T>(0, 0, 1), T(1));
        REQUIRE_FALSE(e.empty());
        for_each_map(e, [&](const std::string& name, const auto& map) {
            const auto r = apse_test::disk_chi2<T>(
                cells, [&](T u1, T u2) { return map.sample(Vec2<T>(u1, u2)).direction; }, 100000, ++seed);
            std::printf("[%s] chi2 %s d=%g h=%g: chi2 %.1f dof %d p %.3f\n", sizeof(T) == 4 ? "float" : "double",
                        name.c_str(), cfg[0], cfg[1], r.chi2, r.dof, r.p);
            INFO(name << " d " << cfg[0] << " h " << cfg[1] << " chi2 " << r.chi2 << " dof " << r.dof << " p " << r.p);
            CHECK(r.p > level);
        });
    }
}

TEMPLATE_TEST_CASE("unbiased: Monte Carlo estimates of a known integral", "[maps][unbiased]", float, double) {
    using T = TestType;
    // int f(w) dw over the disk's solid angle, f a tilted cubic lobe, by quadrature on the disk
    // (DiskCells::integrals, independent of apse) against the estimate mean of f/pdf over 200 000
    // independent samples: within 4.5 standard errors (two-sided 7e-6 per test; 18 tests).
    for (const auto& cfg : kDisks) {
        const apse_test::DiskCells cells{cfg[0], cfg[1], 1.0, 4, 16};
        const glm::dvec3 lobe = glm::normalize(glm::dvec3(0.3, -0.4, 1.0));
        auto f = [&](double x, double y, double z) { const double c = glm::dot(glm::dvec3(x, y, z), lobe); return 1.0 + 3.0 * c * c * c; };
        double ref = 0;
        for (double v : cells.integrals(16, f)) ref += v;
        const auto e = apse::project_disk(Vec3<T>(0), Vec3<T>(T(cfg[1]), T(0), T(cfg[0])), Vec3<T>(0, 0, 1), T(1));
        for_each_map(e, [&](const std::string& name, const auto& map) {
            apse_test::Rng rng(sizeof(T) * 100 + 7);
            const int n = 200000;
            double sum = 0, sum2 = 0;
            for (int i = 0; i < n; ++i) {
                const auto s = map.sample(Vec2<T>(rng.uniform<T>(), rng.uniform<T>()));
                const glm::dvec3 w = glm::normalize(glm::dvec3(s.direction));
                const double v = s.pdf > 0 ? f(w.x, w.y, w.z) / double(s.pdf) : 0.0;
                sum += v;
                sum2 += v * v;
            }
            const double mean = sum / n, se = std::sqrt((sum2 / n - mean * mean) / n);
            std::printf("[%s] unbiased %s d=%g h=%g: estimate %.6f reference %.6f (%.2f standard errors)\n",
                        sizeof(T) == 4 ? "float" : "double", name.c_str(), cfg[0], cfg[1], mean, ref, (mean - ref) / se);
            INFO(name << " d " << cfg[0] << " h " << cfg[1] << " estimate " << mean << " reference " << ref << " se " << se);
            CHECK(std::fabs(mean - ref) <= 4.5 * se);
        });
    }
}
