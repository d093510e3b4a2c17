// Statistical tests of the three maps, float and double: chi-square uniformity against cell
// probabilities integrated independently on the disk, and unbiasedness (stratification of every
// sampler: test_stratification.cpp).
#include "support/maps_measures.hpp"

#include "support/catch.hpp"

#include <cmath>
#include <cstdio>
#include <string>

// The disks (apse_test::kStatisticsDisks, in the frame of DiskCells: o = 0, plane z = d, centre
// (h, 0, d), r = 1): frontal, oblique, grazing. The integrand d/(x^2 + y^2 + d^2)^{3/2} is smooth
// on every cell (its peak, at the foot point, is at least d = 0.7 away when it lies on the disk);
// 8 x 8 Gauss–Legendre nodes per cell integrate it far below the chi-square's resolution
// (~1/sqrt(625) per cell).

TEMPLATE_TEST_CASE("chi-square: samples are uniform in solid angle", "[maps][chi2]", float, double) {
    using T = TestType;
    // 100 000 samples into 10 equal-area rings x 16 sectors of the disk (625 expected per cell on
    // average); expected counts from DiskCells quadrature (independent of apse). Family-wise level
    // 1% over all kChi2Tests tests (both types), Šidák-corrected per test.
    const double level = apse_test::chi2_level();
    apse_test::chi2_p_values<T>([](const apse::SphericalEllipse<T>& e) { REQUIRE_FALSE(e.empty()); },
                                [&](const std::string& name, const double (&cfg)[2], const apse_test::Chi2Result& r) {
        std::printf("[%s] chi2 %s d=%g h=%g: chi2 %.1f dof %d p %.3f\n", sizeof(T) == 4 ? "float" : "double",
                    name.c_str(), cfg[0], cfg[1], r.chi2, r.dof, r.p);
        INFO(name << " d " << cfg[0] << " h " << cfg[1] << " chi2 " << r.chi2 << " dof " << r.dof << " p " << r.p);
        CHECK(r.p > level);
    });
}

TEMPLATE_TEST_CASE("unbiased: Monte Carlo estimates of a known integral", "[maps][unbiased]", float, double) {
    using T = TestType;
    // int f(w) dw over the disk's solid angle, f a tilted cubic lobe, by quadrature on the disk
    // (DiskCells::integrals, independent of apse) against the estimate mean of f/pdf over 200 000
    // independent samples: within 4.5 standard errors (two-sided 7e-6 per test; 18 tests).
    apse_test::unbiased_sigmas<T>([&](const std::string& name, const double (&cfg)[2], double mean, double ref, double se) {
        std::printf("[%s] unbiased %s d=%g h=%g: estimate %.6f reference %.6f (%.2f standard errors)\n",
                    sizeof(T) == 4 ? "float" : "double", name.c_str(), cfg[0], cfg[1], mean, ref, (mean - ref) / se);
        INFO(name << " d " << cfg[0] << " h " << cfg[1] << " estimate " << mean << " reference " << ref << " se " << se);
        CHECK(std::fabs(mean - ref) <= apse_test::kUnbiasedSigmas * se);
    });
}
