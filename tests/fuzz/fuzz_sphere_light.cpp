// libFuzzer target: SphereLight with arbitrary shading points, centres, radii and receiver normals,
// over each of the five maps (the tabulated ones with the default table), plain or
// cosine-weighted, at an arbitrary point of the square, float and double. Checks what the library
// promises for every input: a finite unit direction and a finite pdf >= 0; for pdf > 0 a point on
// the sphere's side facing o (rounding-aware), a finite distance > 0 with point = o + distance ·
// direction, cosine-weighted samples not below the receiver's horizon, an inverse inside the
// square, and finite pdfs of the direction from the light and from sphere_light_pdf.
#include <apse/cosine_weighted.hpp>
#include <apse/maps/ld_radial.hpp>
#include <apse/maps/parallel.hpp>
#include <apse/comparison.hpp>
#include <apse/maps/tabulated_ld_radial.hpp>
#include <apse/sphere_light.hpp>
#include <apse/math.hpp>

#include "../support/default_table.hpp"
#include "fuzz_common.hpp"

#include <cstdint>
#include <limits>

namespace {

double g_in[12];  // o, centre, radius, receiver normal, u
int g_map = 0;    // printed on failure
bool g_cosine = false;

[[noreturn]] void fail(const char* what) {
    std::fprintf(stderr, "map %d (radial, ld_radial, parallel, tabulated, tabulated_ld_radial), cosine-weighted %d\n",
                 g_map, int(g_cosine));
    apse_fuzz::fail("fuzz_sphere_light", what, g_in, 12);
}

/// The checks on one light; `horizon`: the receiver's normal its samples must not fall below
/// (null for a plain map, or a cosine-weighted one that does not weight: a zero normal, say).
template <class T, class Sampler, class... Args>
void check_light(const glm::vec<3, T>& o, const glm::vec<3, T>& c, T r, const glm::vec<2, T>& u,
                 const glm::vec<3, T>* horizon, const Args&... args) {
    const apse::SphereLight<Sampler> light(o, c, r, args...);
    const auto s = light.sample(u);
    if (!apse_fuzz::finite3(s.direction)) fail("non-finite direction");
    if (!apse::detail::is_finite(s.pdf) || !(s.pdf >= T(0))) fail("pdf not finite and >= 0");
    if (!(s.pdf > T(0))) {
        if (s.distance != T(0)) fail("no sample with a distance");
        return;
    }
    // the checks in long double: its range holds the squares of any double (1e-300 coordinates
    // square to 1e-600), so lengths neither underflow nor overflow
    using L = long double;
    using LV = glm::vec<3, L>;
    const L eps = L(apse::epsilon<T>());
    const LV w(s.direction), od(o), cd(c), p(s.point);
    if (std::fabs(glm::length(w) - 1) > 64 * eps) fail("direction not unit");
    if (!(s.distance > T(0)) || !apse::detail::is_finite(s.distance) || !apse_fuzz::finite3(s.point))
        fail("bad point or distance");
    // every coordinate's scale: the rounding of o, c and the point is relative to it, and at
    // least T's subnormal spacing: a sphere whose coordinates, radius or distance are subnormal
    // (or round to the subnormals in a product) gets its point and distance on that grid, each
    // operation within half a spacing (`floor`: 16 spacings cover the few operations of the point,
    // of the distance and of the check)
    const L scale = std::fmax(glm::length(od), glm::length(cd)) + L(r) + L(s.distance);
    const L floor = 16 * L(std::numeric_limits<T>::denorm_min());
    if (glm::length(p - (od + L(s.distance) * w)) > 64 * eps * scale + floor) fail("point is not o + distance * direction");
    // on the sphere, up to the rounding of the direction (its angular error times the distance)
    // and of the cap itself: the light computes |c − o| = D to within ~2 eps D (the rounding of
    // c − o is relative to the difference, then a dot product and a square root), allowed as
    // dD = 4 eps D. That moves the cap's rim (sin alpha = r/D) by d alpha = r dD / (D L), L the
    // tangent length, and a direction that far outside the exact rim reaches the tangent point
    // with (p − c)·w = 2 r d alpha = 8 eps r² / L (measured 4.7e-10 for a shading point 3.6e-12
    // above a sphere of radius 2 in double, where 8 eps r² / L = 9.3e-10), with L taken at D − dD.
    // A shading point within dD of the surface is on no side of it that its coordinates decide
    // (the light may see a nearly hemispherical cap from what is, exactly, inside the sphere):
    // there the side the point faces is not checked.
    const L dc = glm::length(cd - od), rl = L(r), dd = 4 * eps * dc;
    const bool side_known = dc - dd > rl;
    const L tangent = side_known ? std::sqrt((dc - dd - rl) * (dc - dd + rl)) : L(0);
    const L tol = 256 * eps * scale + floor;
    if (std::fabs(glm::length(p - cd) - rl) > tol) fail("point not on the sphere");
    if (side_known && glm::dot(p - cd, w) > tol + 8 * eps * rl * rl / tangent) fail("point on the far side of the sphere");
    if (horizon) {
        const LV n(*horizon);
        const L nl = glm::length(n);
        if (nl > 0 && std::isfinite(nl) && glm::dot(n / nl, w) < -64 * eps) fail("cosine-weighted sample below the horizon");
    }
    const auto back = light.invert(s.direction);
    if (!(back.x >= T(0) && back.x <= T(1) && back.y >= T(0) && back.y <= T(1))) fail("inverse outside the square");
    const T pl = light.pdf(s.direction), ps = apse::sphere_light_pdf<Sampler>(o, c, r, s.direction, args...);
    if (!apse::detail::is_finite(pl) || !(pl >= T(0)) || !apse::detail::is_finite(ps) || !(ps >= T(0)))
        fail("bad MIS pdf");
}

template <class T, class Map, class... Args>
void check_map(const glm::vec<3, T>& o, const glm::vec<3, T>& c, T r, const glm::vec<3, T>& n,
               const glm::vec<2, T>& u, const Args&... args) {
    if (g_cosine) {
        const apse::SphereLight<apse::CosineWeighted<Map>> light(o, c, r, args..., n);
        check_light<T, apse::CosineWeighted<Map>>(o, c, r, u, light.cosine_weighted() ? &n : nullptr, args..., n);
    } else {
        check_light<T, Map>(o, c, r, u, nullptr, args...);
    }
}

template <class T> void check(int map) {
    using V = glm::vec<3, T>;
    const V o{T(g_in[0]), T(g_in[1]), T(g_in[2])}, c{T(g_in[3]), T(g_in[4]), T(g_in[5])};
    const T r = T(g_in[6]);
    const V n{T(g_in[7]), T(g_in[8]), T(g_in[9])};
    const glm::vec<2, T> u{T(g_in[10]), T(g_in[11])};
    const apse::TabulationView table = apse_test::default_table().view();
    switch (map) {
        case 0: check_map<T, apse::RadialMap<T>>(o, c, r, n, u); break;
        case 1: check_map<T, apse::LdRadialMap<T>>(o, c, r, n, u); break;
        case 2: check_map<T, apse::ParallelMap<T>>(o, c, r, n, u); break;
        case 3: check_map<T, apse::TabulatedMap<T>>(o, c, r, n, u, table); break;
        default: check_map<T, apse::TabulatedLdRadialMap<T>>(o, c, r, n, u, table); break;
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    FuzzedDataProvider in(data, size);
    g_map = in.ConsumeIntegralInRange<int>(0, 4);
    g_cosine = in.ConsumeBool();
    for (int i = 0; i < 10; ++i) g_in[i] = apse_fuzz::value(in);
    if (in.ConsumeBool()) {  // often a shading point just outside the sphere, near its surface
        const glm::dvec3 c(g_in[3], g_in[4], g_in[5]), d(g_in[0], g_in[1], g_in[2]);
        const double len = glm::length(d), k = 1 + std::ldexp(1.0, -in.ConsumeIntegralInRange<int>(1, 40));
        if (len > 0 && std::isfinite(len) && std::isfinite(g_in[6]))
            for (int i = 0; i < 3; ++i) g_in[i] = c[i] + d[i] / len * std::fabs(g_in[6]) * k;
    }
    g_in[10] = apse_fuzz::unit(in);
    g_in[11] = apse_fuzz::unit(in);
    check<float>(g_map);
    check<double>(g_map);
    return 0;
}
