// apse — area-preserving parameterizations for spherical ellipses.
// SPDX-License-Identifier: MIT
//
// A float sampler must not form subnormal numbers for ordinary lights: on x86 each subnormal
// result costs tens of cycles, and the set-up of the tabulated maps once formed several per
// shading point for every light farther than ~250 radii (the high powers of a short polynomial's
// argument in detail/math.hpp). The check is the floating-point environment's
// underflow flag (C99 <fenv.h>, raised for every tiny result), so the test fails wherever any
// operation of the set-up or of a sample underflows.

#include "support/catch.hpp"

#include <cfenv>
#include <cmath>

#include <apse/apse.hpp>
#include <apse/baselines/area.hpp>
#include <apse/comparison.hpp>

#include "support/default_table.hpp"

namespace {

using vec2 = glm::vec<2, float>;
using vec3 = glm::vec<3, float>;

/// A disk light and a shading point with its receiver normal.
struct Light {
    vec3 o, center, normal;
    float radius;
    vec3 receiver;  ///< the receiver's normal (for the cosine-weighted samplers)
};

/// Ordinary lights: distances from 0.1 to 1000 radii (log-spaced), the disk's normal tilted from
/// facing the shading point to nearly edge-on (cos of the tilt down to 1e-3), the shading point
/// off the disk's axis; receiver normals facing, tilted and straddling the light's horizon.
std::vector<Light> ordinary_lights() {
    std::vector<Light> lights;
    const float tilts[] = {0.0f, 0.5f, 1.0f, 1.4f, 1.5698f};
    const float offsets[] = {0.0f, 0.7f, 3.0f};
    for (int i = 0; i <= 16; ++i) {
        const float distance = 0.1f * std::pow(10.0f, 4.0f * float(i) / 16.0f);
        for (float tilt : tilts)
            for (float offset : offsets) {
                Light l;
                l.center = vec3(0.0f, 0.0f, 0.0f);
                l.radius = 1.0f;
                l.normal = vec3(std::sin(tilt), 0.0f, std::cos(tilt));
                l.o = vec3(offset * distance * 0.3f, 0.2f * distance, distance);
                const vec3 to_light = glm::normalize(l.center - l.o);
                const vec3 side = glm::normalize(glm::cross(to_light, vec3(0.0f, 1.0f, 0.0f)));
                l.receiver = glm::normalize(to_light + float(i % 3) * 0.6f * side);
                lights.push_back(l);
            }
    }
    return lights;
}

/// Runs `run(light)` for every ordinary light and returns how many raised FE_UNDERFLOW.
template <class Run> int lights_that_underflow(Run run) {
    int count = 0;
    for (const Light& l : ordinary_lights()) {
        std::feclearexcept(FE_ALL_EXCEPT);
        volatile float sink = run(l);
        (void)sink;
        if (std::fetestexcept(FE_UNDERFLOW)) ++count;
    }
    return count;
}

/// Set-up and 16 jittered samples of the sampler that `make(light)` builds; the sum of the
/// returned values keeps every result observable.
template <class Make> float setup_and_samples(const Light& l, Make make) {
    const auto s = make(l);
    float sum = 0.0f;
    for (int k = 0; k < 16; ++k) {
        const vec2 u((float(k % 4) + 0.37f) / 4.0f, (float(k / 4) + 0.61f) / 4.0f);
        const auto d = s.sample(u);
        sum += d.direction.x + d.direction.y + d.direction.z + d.pdf;
    }
    return sum;
}

}  // namespace

TEST_CASE("float samplers form no subnormal number for ordinary lights", "[robust]") {
#if defined(__FAST_MATH__)
    WARN("skipped under -ffast-math: subnormals are flushed there, and the compiler may reorder "
         "operations across the floating-point environment's calls");
#else
    const apse::TabulationView table = apse_test::default_table().view();
    auto ellipse = [](const Light& l) { return apse::project_disk(l.o, l.center, l.normal, l.radius); };
    CHECK(lights_that_underflow([&](const Light& l) {
              return setup_and_samples(l, [&](const Light& m) { return apse::DiskAreaSampler<float>(m.o, apse::DiskFrame<float>::make(m.center, m.normal, m.radius)); });
          }) == 0);
    CHECK(lights_that_underflow([&](const Light& l) {
              return setup_and_samples(l, [&](const Light& m) { return apse::RadialMap<float>(ellipse(m)); });
          }) == 0);
    CHECK(lights_that_underflow([&](const Light& l) {
              return setup_and_samples(l, [&](const Light& m) { return apse::LdRadialMap<float>(ellipse(m)); });
          }) == 0);
    CHECK(lights_that_underflow([&](const Light& l) {
              return setup_and_samples(l, [&](const Light& m) { return apse::ParallelMap<float>(ellipse(m)); });
          }) == 0);
    CHECK(lights_that_underflow([&](const Light& l) {
              return setup_and_samples(l, [&](const Light& m) { return apse::TabulatedMap<float>(ellipse(m), table); });
          }) == 0);
    CHECK(lights_that_underflow([&](const Light& l) {
              return setup_and_samples(l, [&](const Light& m) { return apse::TabulatedLdRadialMap<float>(ellipse(m), table); });
          }) == 0);
    CHECK(lights_that_underflow([&](const Light& l) {
              return setup_and_samples(l, [&](const Light& m) {
                  using Map = apse::TabulatedLdRadialMap<float>;
                  return apse::CosineWeighted<Map>(Map(ellipse(m), table), m.receiver);
              });
          }) == 0);
#endif
}
