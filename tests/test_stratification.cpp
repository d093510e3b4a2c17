// Stratification, for every sampler of a disk light, float and double: the variance of a
// 16 x 16 jittered Monte Carlo estimate against that of 256 independent points. A continuous
// area-preserving map keeps the jittered estimator's variance at O(N^-2) against O(N^-1); a
// rejection sampler (Gamito) loses most of that benefit — this file shows both.
#include "support/maps_measures.hpp"

#include "support/catch.hpp"

#include <cstdio>
#include <string>

TEMPLATE_TEST_CASE("stratification survives the maps, not rejection", "[stratification]", float, double) {
    using T = TestType;
    // Every sampler of apse_test::for_each_disk_sampler on unit disks in the plane z = d with
    // centre (h, 0, d), seen from the origin: frontal, oblique, grazing. Integrand: a smooth cosine
    // lobe tilted off the centre, f = 1 + 3 cos^3. 300 repetitions of each estimator give each
    // variance to ~+-8 % (chi-square, 299 dof), the ratio to ~+-12 %. The maps and the tabulated
    // maps keep most of the jittered grid's gain (the radial map least: its centre seam); Gamito's
    // rejected points leave holes in the jittered pattern and its retries are not stratified. The
    // bounds — maps > 20, rejection < 15 — sit far outside the noise on either side, so the test
    // shows the gap, not a value (tools/maps_report prints the measured ratios).
    apse_test::stratification_ratios<T>(
        [](const apse::SphericalEllipse<T>& e) { REQUIRE_FALSE(e.empty()); },
        [&](const std::string& name, const double (&cfg)[2], bool rejection, double vj, double vi) {
            std::printf("[%s] stratification %s d=%g h=%g: variance independent/jittered = %.1f\n",
                        sizeof(T) == 4 ? "float" : "double", name.c_str(), cfg[0], cfg[1], vi / vj);
            INFO(name << " d " << cfg[0] << " h " << cfg[1] << " var jittered " << vj << " independent " << vi);
            if (rejection)
                CHECK(vi / vj < apse_test::kStratificationRejectionBound);
            else
                CHECK(vi / vj > apse_test::kStratificationMapBound);
        });
}
