// The program every consumer test builds: it includes the umbrella header and checks one value,
// so a broken include path, package file or target fails loudly.
#include <apse/apse.hpp>

#include <cmath>
#include <cstdio>

int main() {
    // R_F(1, 2, 0) = 1.3110287771461 (Carlson 1995, table 1).
    const double rf = apse::carlson_rf(1.0, 2.0, 0.0);
    const bool ok = std::fabs(rf - 1.3110287771461) < 1e-12;
    std::printf("apse %d.%d.%d: carlson_rf(1, 2, 0) = %.15g %s\n", APSE_VERSION_MAJOR,
                APSE_VERSION_MINOR, APSE_VERSION_PATCH, rf, ok ? "ok" : "WRONG");
    return ok ? 0 : 1;
}
