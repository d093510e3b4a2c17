// The program every consumer test builds: it includes the umbrella header and checks one value,
// so a broken include path, package file or target fails loudly.
#include <apse/apse.hpp>
#include <apse/elliptic.hpp>

#include <cmath>
#include <cstdio>

#if defined(APSE_PACKAGE_VERSION_MAJOR)  // set by the find_package consumer from the package
static_assert(APSE_VERSION_MAJOR == APSE_PACKAGE_VERSION_MAJOR &&
                  APSE_VERSION_MINOR == APSE_PACKAGE_VERSION_MINOR &&
                  APSE_VERSION_PATCH == APSE_PACKAGE_VERSION_PATCH,
              "the installed package's version differs from the headers' APSE_VERSION_*");
#endif

int main() {
    // R_F(1, 2, 0) = 1.3110287771461 (Carlson 1995, table 1).
    const double rf = apse::carlson_rf(1.0, 2.0, 0.0);
    const bool ok = std::fabs(rf - 1.3110287771461) < 1e-12;
    std::printf("apse %d.%d.%d: carlson_rf(1, 2, 0) = %.15g %s\n", APSE_VERSION_MAJOR,
                APSE_VERSION_MINOR, APSE_VERSION_PATCH, rf, ok ? "ok" : "WRONG");
    return ok ? 0 : 1;
}
