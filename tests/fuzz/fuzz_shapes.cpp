// libFuzzer target: project_ellipse / project_sphere / project_ellipsoid with arbitrary inputs,
// each of the five maps (three exact, two tabulated with the default table) on the result, plain
// or cosine-weighted for an arbitrary receiver normal, an arbitrary point of the square, float and
// double. Checks what the library promises for every input: a solid angle in [0, 2 pi], a finite
// unit direction and a finite pdf >= 0, and for pdf > 0 a direction inside the ellipse
// (rounding-aware) and, cosine-weighted, not below the receiver's horizon, an inverse inside the
// square and a finite MIS pdf.
#include <apse/cosine_weighted.hpp>
#include <apse/maps/ld_radial.hpp>
#include <apse/maps/parallel.hpp>
#include <apse/comparison.hpp>
#include <apse/maps/tabulated_ld_radial.hpp>
#include <apse/projection.hpp>
#include <apse/math.hpp>

#include "../support/default_table.hpp"
#include "fuzz_common.hpp"

#include <cstdint>

namespace {

double g_in[19];  // 0-15 the shape, 16-18 the receiver's normal
int g_shape = 0, g_map = 0;  // printed on failure
bool g_cosine = false;

[[noreturn]] void fail(const char* what) {
    std::fprintf(stderr, "shape %d (ellipse, sphere, ellipsoid), map %d (radial, ld_radial, parallel, tabulated, "
                         "tabulated_ld_radial), cosine-weighted %d\n", g_shape, g_map, int(g_cosine));
    apse_fuzz::fail("fuzz_shapes", what, g_in, 19);
}


/// The checks on one sampler; `horizon`: the receiver's normal its samples must not fall below
/// (null: no such promise, e.g. a plain map, or a cosine-weighted one whose normal it treats as
/// zero — a subnormal one under fast-math's denormals-are-zero).
template <class T, class Map>
void check_sampler(const Map& map, const apse::SphericalEllipse<T>& e, T u1, T u2, const glm::vec<3, T>* horizon) {
    const auto s = map.sample(glm::vec<2, T>(u1, u2));
    if (!apse_fuzz::finite3(s.direction)) fail("non-finite direction");
    if (!apse::detail::is_finite(s.pdf) || !(s.pdf >= T(0))) fail("pdf not finite and >= 0");
    if (!(s.pdf > T(0))) return;
    const double len = glm::length(glm::dvec3(s.direction));
    if (std::fabs(len - 1) > 64 * double(apse::epsilon<T>())) fail("direction not unit");
    const glm::dvec3 w(s.direction);
    const glm::dvec3 l(glm::dot(w, glm::dvec3(e.x)), glm::dot(w, glm::dvec3(e.y)), glm::dot(w, glm::dvec3(e.z)));
    const double d = 64 * double(apse::epsilon<T>());  // the frame's and the direction's rounding
    const double x = std::fmax(std::fabs(l.x) - d, 0) / double(e.tan_alpha);
    const double y = std::fmax(std::fabs(l.y) - d, 0) / double(e.tan_beta);
    if (!(l.z + d > 0) || x * x + y * y > (l.z + d) * (l.z + d)) fail("sample outside the ellipse");
    if (horizon) {  // above the horizon, up to the direction's rounding (unit vectors: absolute)
        const glm::dvec3 n(*horizon);
        const double nl = glm::length(n);
        if (nl > 0 && std::isfinite(nl) && glm::dot(n / nl, w) < -d) fail("cosine-weighted sample below the horizon");
    }
    const auto back = map.invert(s.direction);
    if (!(back.x >= T(0) && back.x <= T(1) && back.y >= T(0) && back.y <= T(1))) fail("inverse outside the square");
    const T p = map.pdf(s.direction);
    if (!apse::detail::is_finite(p) || !(p >= T(0))) fail("bad MIS pdf");
}

/// The map itself, or cosine-weighted for the receiver's normal n (g_cosine).
template <class T, class Map>
void check_map(const Map& map, const apse::SphericalEllipse<T>& e, const glm::vec<3, T>& n, T u1, T u2) {
    if (g_cosine) {
        const apse::CosineWeighted<Map> cw(map, n);
        check_sampler<T>(cw, e, u1, u2, cw.weighted() ? &n : nullptr);
    } else {
        check_sampler<T>(map, e, u1, u2, nullptr);
    }
}

template <class T> void check(int shape, int map, T u1, T u2) {
    using V = glm::vec<3, T>;
    const V o{T(g_in[0]), T(g_in[1]), T(g_in[2])}, c{T(g_in[3]), T(g_in[4]), T(g_in[5])};
    const V a{T(g_in[6]), T(g_in[7]), T(g_in[8])}, b{T(g_in[9]), T(g_in[10]), T(g_in[11])};
    const V a3{T(g_in[12]), T(g_in[13]), T(g_in[14])};
    apse::SphericalEllipse<T> e;
    if (shape == 0) e = apse::project_ellipse(o, c, a, b);
    else if (shape == 1) e = apse::project_sphere(o, c, T(g_in[15]));
    else e = apse::project_ellipsoid(o, c, a, b, a3);
    const T omega = e.solid_angle();
    if (!apse::detail::is_finite(omega) || !(omega >= T(0)) || omega > T(6.2832)) fail("solid angle out of [0, 2 pi]");
    const V n{T(g_in[16]), T(g_in[17]), T(g_in[18])};
    const apse::TabulationView table = apse_test::default_table().view();
    switch (map) {
        case 0: check_map<T>(apse::RadialMap<T>(e), e, n, u1, u2); break;
        case 1: check_map<T>(apse::LdRadialMap<T>(e), e, n, u1, u2); break;
        case 2: check_map<T>(apse::ParallelMap<T>(e), e, n, u1, u2); break;
        case 3: check_map<T>(apse::TabulatedMap<T>(e, table), e, n, u1, u2); break;
        default: check_map<T>(apse::TabulatedLdRadialMap<T>(e, table), e, n, u1, u2); break;
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    FuzzedDataProvider in(data, size);
    const int shape = in.ConsumeIntegralInRange<int>(0, 2), map = in.ConsumeIntegralInRange<int>(0, 4);
    for (int i = 0; i < 16; ++i) g_in[i] = apse_fuzz::value(in);
    if (shape == 2 && in.ConsumeBool()) {
        // often make the ellipsoid's axes orthogonal (its domain), keeping the fuzzed lengths
        const glm::dvec3 a1(g_in[6], g_in[7], g_in[8]), t(g_in[9], g_in[10], g_in[11]);
        const glm::dvec3 a2 = glm::cross(a1, t), a3 = glm::cross(a1, a2);
        const double l2 = glm::length(t), l3 = std::fabs(g_in[12]);
        const glm::dvec3 n2 = glm::length(a2) > 0 ? a2 * (l2 / glm::length(a2)) : a2;
        const glm::dvec3 n3 = glm::length(a3) > 0 ? a3 * (l3 / glm::length(a3)) : a3;
        for (int i = 0; i < 3; ++i) { g_in[9 + i] = n2[i]; g_in[12 + i] = n3[i]; }
    }
    const double u1 = apse_fuzz::unit(in), u2 = apse_fuzz::unit(in);
    // read last, so that inputs written before the cosine-weighted case decode as they did
    g_cosine = in.ConsumeBool();
    for (int i = 16; i < 19; ++i) g_in[i] = g_cosine ? apse_fuzz::value(in) : 0.0;
    g_shape = shape;
    g_map = map;
    check<float>(shape, map, float(u1), float(u2));
    check<double>(shape, map, u1, u2);
    return 0;
}
