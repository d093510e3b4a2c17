// libFuzzer target: the tabulated maps with odd table views — 0 to 6 bins, 0 to 4 nodes per
// axis, null pointers, rows that are valid CDFs but of arbitrary shape (flat bins included,
// unrelated to the shape they stand for) — on ellipses from arbitrary tangents, float and
// double. A view that keeps the documented layout (rows of bins + 1 increasing floats from 0 to
// 1) may give a poor density but never UB, a NaN or a non-unit direction, a negative pdf or an
// inverse outside the square.
#include <apse/comparison.hpp>
#include <apse/maps/tabulated_ld_radial.hpp>
#include <apse/math.hpp>

#include "fuzz_common.hpp"

#include <cstdint>
#include <vector>

namespace {

double g_in[4];

[[noreturn]] void fail(const char* what) { apse_fuzz::fail("fuzz_tabulated", what, g_in, 4); }

template <class T, class Map> void check_map(const Map& map, T u1, T u2) {
    const auto s = map.sample(glm::vec<2, T>(u1, u2));
    if (!apse_fuzz::finite3(s.direction)) fail("non-finite direction");
    if (!apse::detail::is_finite(s.pdf) || !(s.pdf >= T(0))) fail("pdf not finite and >= 0");
    if (!(s.pdf > T(0))) return;
    if (std::fabs(glm::length(glm::dvec3(s.direction)) - 1) > 64 * double(apse::epsilon<T>())) fail("direction not unit");
    const auto back = map.invert(s.direction);
    if (!(back.x >= T(0) && back.x <= T(1) && back.y >= T(0) && back.y <= T(1))) fail("inverse outside the square");
    const T p = map.pdf(s.direction);
    if (!apse::detail::is_finite(p) || !(p >= T(0))) fail("bad MIS pdf");
}

template <class T> void check(const apse::TabulationView& view, T u1, T u2) {
    const glm::vec<3, T> x(1, 0, 0), y(0, 1, 0), z(0, 0, 1);
    const auto e = apse::SphericalEllipse<T>::from_tangents(x, y, z, T(g_in[0]), T(g_in[1]));
    check_map<T>(apse::TabulatedMap<T>(e, view), u1, u2);
    check_map<T>(apse::TabulatedLdRadialMap<T>(e, view), u1, u2);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    FuzzedDataProvider in(data, size);
    apse::TabulationView view{nullptr, in.ConsumeIntegralInRange<int>(0, 6), in.ConsumeIntegralInRange<int>(0, 4),
                              in.ConsumeIntegralInRange<int>(0, 4)};
    const bool null_table = in.ConsumeIntegralInRange<int>(0, 15) == 0;
    const int bins = view.bins > 0 ? view.bins : 1;
    const int rows = (view.alpha_nodes > 0 ? view.alpha_nodes : 1) * (view.ratio_nodes > 0 ? view.ratio_nodes : 1);
    std::vector<float> cdf(std::size_t(rows) * std::size_t(bins + 1));
    for (int r = 0; r < rows; ++r) {
        // increments >= 0 (zero: a flat bin), at least one positive, normalised to end at 1
        std::vector<double> inc(bins);
        double total = 0;
        for (double& v : inc) { v = double(in.ConsumeIntegralInRange<int>(0, 3)) * in.ConsumeProbability<double>(); total += v; }
        if (!(total > 0)) { inc[0] = 1; total = 1; }
        float* row = cdf.data() + std::size_t(r) * (bins + 1);
        double run = 0;
        row[0] = 0.0f;
        for (int k = 0; k < bins; ++k) {
            run += inc[k];
            row[k + 1] = k + 1 == bins ? 1.0f : float(run / total);
        }
    }
    if (!null_table) view.cdf = cdf.data();
    for (double& v : g_in) v = apse_fuzz::value(in);
    g_in[2] = apse_fuzz::unit(in);
    g_in[3] = apse_fuzz::unit(in);
    check<float>(view, float(g_in[2]), float(g_in[3]));
    check<double>(view, g_in[2], g_in[3]);
    return 0;
}
