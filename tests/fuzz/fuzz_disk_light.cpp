// libFuzzer target: arbitrary geometry (shading point, disk centre, normal, radius), map choice
// (the five maps; the tabulated ones with the default table), an optional receiver normal (cosine-weighted sampling) and point of the square, in float and
// double, through disk_light.hpp (DiskLight<RuntimeSampler<T>>). Checks what the library
// promises for every input: a finite unit direction, a finite pdf >= 0, and for pdf > 0 a
// direction inside the disk's spherical ellipse (rounding-aware test), a finite point at a
// finite positive distance, an inverse inside the square, and finite MIS pdfs, the stateless one
// agreeing with the light's. Any violation
// aborts (libFuzzer reports it with the input).
//
// Build: clang++ -fsanitize=fuzzer,address,undefined (tests/CMakeLists.txt, APSE_BUILD_FUZZERS).
#include <apse/disk_light.hpp>
#include <apse/math.hpp>
#include <apse/runtime_sampler.hpp>

#include "fuzz_common.hpp"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>

namespace {

const double* g_input = nullptr;  // the geometry being checked (printed on failure)
double g_u[2];

[[noreturn]] void fail(const char* what) {
    std::fprintf(stderr, "fuzz_disk_light: %s\n", what);
    if (g_input)
        for (int i = 0; i < 13; ++i) std::fprintf(stderr, "  g[%d] = %.17g\n", i, g_input[i]);
    std::fprintf(stderr, "  u = %.17g %.17g\n", g_u[0], g_u[1]);
    std::abort();
}

using apse_fuzz::finite3;
using apse_fuzz::value;

template <class T> void check(const double* g, apse::MapKind map, bool cosine, T u1, T u2) {
    using V = glm::vec<3, T>;
    const V o{T(g[0]), T(g[1]), T(g[2])}, c{T(g[3]), T(g[4]), T(g[5])}, n{T(g[6]), T(g[7]), T(g[8])};
    const T r = T(g[9]);
    const V receiver{T(g[10]), T(g[11]), T(g[12])};
    const apse::TabulationView table = apse::default_table().view();
    using Light = apse::DiskLight<apse::RuntimeSampler<T>>;
    const Light light = cosine ? Light(o, c, n, r, map, table, receiver) : Light(o, c, n, r, map, table);
    const apse::PointSample<T> s = light.sample(glm::vec<2, T>(u1, u2));
    if (!finite3(s.direction)) fail("non-finite direction");
    if (!apse::detail::is_finite(s.pdf) || !(s.pdf >= T(0))) fail("pdf not finite and >= 0");
    const T omega = light.solid_angle();
    if (!apse::detail::is_finite(omega) || !(omega >= T(0)) || omega > T(6.2832)) fail("solid angle out of [0, 2 pi]");
    if (!(s.pdf > T(0))) return;
    const double len = glm::length(glm::dvec3(s.direction));
    if (std::fabs(len - 1) > 64 * double(apse::epsilon<T>())) fail("direction not unit");
    if (!finite3(s.point) || !apse::detail::is_finite(s.distance) || !(s.distance > T(0))) fail("bad point / distance");
    // inside the ellipse up to rounding: shrink |x|, |y| and grow z by d = 64 eps (the frame's and
    // the local direction's rounding, absolute for unit vectors)
    const apse::SphericalEllipse<T>& e = light.ellipse();
    const glm::dvec3 w(s.direction);
    const glm::dvec3 l(glm::dot(w, glm::dvec3(e.x)), glm::dot(w, glm::dvec3(e.y)), glm::dot(w, glm::dvec3(e.z)));
    const double d = 64 * double(apse::epsilon<T>());
    const double x = std::fmax(std::fabs(l.x) - d, 0) / double(e.tan_alpha);
    const double y = std::fmax(std::fabs(l.y) - d, 0) / double(e.tan_beta);
    const double z = l.z + d;
    if (!(z > 0) || x * x + y * y > z * z) fail("sample outside the ellipse");
    const glm::vec<2, T> back = light.invert(s.direction);
    if (!(back.x >= T(0) && back.x <= T(1) && back.y >= T(0) && back.y <= T(1))) fail("inverse outside the square");
    const T p1 = light.pdf(s.direction), p2 = apse::disk_light_pdf<apse::LdRadialMap<T>>(o, c, n, r, s.direction);
    if (!apse::detail::is_finite(p1) || !(p1 >= T(0)) || !apse::detail::is_finite(p2) || !(p2 >= T(0))) fail("bad MIS pdf");
    const T p3 = cosine ? apse::disk_light_pdf<apse::RuntimeSampler<T>>(o, c, n, r, s.direction, map, table, receiver)
                        : apse::disk_light_pdf<apse::RuntimeSampler<T>>(o, c, n, r, s.direction, map, table);
    // the same computation at another call site: equal, up to the rounding FMA contraction may
    // change (a tabulated bin edge: < 2 %)
    if (!apse::detail::is_finite(p3) || !(p3 >= T(0))) fail("bad stateless MIS pdf");
    if (p3 > T(0) && p1 > T(0) && std::fabs(double(p3) / double(p1) - 1) > 0.02) fail("stateless pdf differs from the light's");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    FuzzedDataProvider in(data, size);
    double g[13];
    for (double& v : g) v = value(in);
    const apse::MapKind maps[] = {apse::MapKind::radial, apse::MapKind::ld_radial, apse::MapKind::parallel,
                                  apse::MapKind::tabulated, apse::MapKind::tabulated_ld_radial};
    const apse::MapKind map = maps[in.ConsumeIntegralInRange<int>(0, 4)];
    const bool cosine = in.ConsumeBool();
    double u1 = in.ConsumeProbability<double>(), u2 = in.ConsumeProbability<double>();
    if (in.ConsumeBool()) u1 = value(in);  // sometimes out of [0, 1], NaN or infinite
    if (in.ConsumeBool()) u2 = value(in);
    g_input = g;
    g_u[0] = u1;
    g_u[1] = u2;
    check<float>(g, map, cosine, float(u1), float(u2));
    check<double>(g, map, cosine, u1, u2);
    return 0;
}
