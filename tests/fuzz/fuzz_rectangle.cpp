// libFuzzer target: the spherical-rectangle sampler (Ureña–Fajardo–King), corner and centre
// forms, with arbitrary geometry and points of the square, float and double. Checks: a solid
// angle in [0, 2 pi]; a finite unit direction and a finite pdf >= 0; for pdf > 0, a finite
// point at a finite positive distance with rectangle coordinates in [0, 1]² (rounding-aware), an
// inverse inside the square and finite pdf / locate values.
#include <apse/spherical_rectangle.hpp>
#include <apse/math.hpp>

#include "fuzz_common.hpp"

#include <cstdint>

namespace {

double g_in[14];

[[noreturn]] void fail(const char* what) { apse_fuzz::fail("fuzz_rectangle", what, g_in, 14); }

template <class T> void check(bool centred) {
    using V = glm::vec<3, T>;
    const V o{T(g_in[0]), T(g_in[1]), T(g_in[2])}, c{T(g_in[3]), T(g_in[4]), T(g_in[5])};
    const V ex{T(g_in[6]), T(g_in[7]), T(g_in[8])}, ey{T(g_in[9]), T(g_in[10]), T(g_in[11])};
    const apse::SphericalRectangle<T> rect =
        centred ? apse::SphericalRectangle<T>::from_center(o, c, ex, ey) : apse::SphericalRectangle<T>(o, c, ex, ey);
    const T omega = rect.solid_angle();
    if (!apse::detail::is_finite(omega) || !(omega >= T(0)) || omega > T(6.2832)) fail("solid angle out of [0, 2 pi]");
    const glm::vec<2, T> u{T(g_in[12]), T(g_in[13])};
    const auto p = rect.sample_point(u);
    if (!apse_fuzz::finite3(p.direction)) fail("non-finite direction");
    if (!apse::detail::is_finite(p.pdf) || !(p.pdf >= T(0))) fail("pdf not finite and >= 0");
    const auto s = rect.sample(u);
    if (!apse_fuzz::finite3(s.direction) || !apse::detail::is_finite(s.pdf) || !(s.pdf >= T(0))) fail("bad sample()");
    if (!(p.pdf > T(0))) return;
    if (std::fabs(glm::length(glm::dvec3(p.direction)) - 1) > 64 * double(apse::epsilon<T>())) fail("direction not unit");
    if (!apse_fuzz::finite3(p.point) || !apse::detail::is_finite(p.distance) || !(p.distance > T(0))) fail("bad point / distance");
    const T slack = T(1e-3);  // coordinates are ratios of rounded lengths: generous, still catches escapes
    if (!(p.st.x >= -slack && p.st.x <= 1 + slack && p.st.y >= -slack && p.st.y <= 1 + slack)) fail("point off the rectangle");
    const auto back = rect.invert(p.direction);
    if (!(back.x >= T(0) && back.x <= T(1) && back.y >= T(0) && back.y <= T(1))) fail("inverse outside the square");
    const T q = rect.pdf(p.direction);
    if (!apse::detail::is_finite(q) || !(q >= T(0))) fail("bad MIS pdf");
    const auto l = rect.locate(p.direction);
    if (!apse::detail::is_finite(l.pdf) || !(l.pdf >= T(0))) fail("bad locate pdf");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    FuzzedDataProvider in(data, size);
    const bool centred = in.ConsumeBool();
    for (int i = 0; i < 12; ++i) g_in[i] = apse_fuzz::value(in);
    if (in.ConsumeBool()) {  // often a true rectangle: edge_y made orthogonal to edge_x
        const glm::dvec3 ex(g_in[6], g_in[7], g_in[8]), ey(g_in[9], g_in[10], g_in[11]);
        const double xx = glm::dot(ex, ex);
        if (xx > 0 && apse::detail::is_finite(xx)) {
            const glm::dvec3 o = ey - ex * (glm::dot(ex, ey) / xx);
            for (int i = 0; i < 3; ++i) g_in[9 + i] = o[i];
        }
    }
    g_in[12] = apse_fuzz::unit(in);
    g_in[13] = apse_fuzz::unit(in);
    check<float>(centred);
    check<double>(centred);
    return 0;
}
