// Calls the public API in a translation unit compiled with -fno-exceptions: proves no header
// throws, catches or needs exception support. Returns non-zero if a value is not finite.
#include <apse/apse.hpp>
#include <apse/baselines/area.hpp>
#include <apse/baselines/gamito.hpp>
#include <apse/elliptic.hpp>
#include <apse/spherical_rectangle.hpp>
#include <apse/diagnostics.hpp>
#include <apse/comparison.hpp>
#include <apse/runtime_sampler.hpp>

#include <cstdio>

template <class T>
static bool elliptic_ok() {
    const T values[] = {
        apse::carlson_rf(T(1), T(2), T(3)),   apse::carlson_rd(T(1), T(2), T(3)),
        apse::carlson_rj(T(1), T(2), T(3), T(4)), apse::carlson_rc(T(1), T(2)),
        apse::ellint_f(T(0.5), T(0.5)),       apse::ellint_pi(T(-2), T(0.5), T(0.5)),
        apse::comp_ellint_k(T(0.5)),          apse::comp_ellint_pi(T(-2), T(0.5)),
    };
    for (T v : values)
        if (!apse::detail::is_finite(v)) return false;
    return true;
}

template <class T>
static bool baselines_rectangle_gamito_ok() {
    using V = glm::vec<3, T>;
    const V o(T(0.3), T(0.2), T(1)), c(T(0), T(0), T(0)), ex(T(1), T(0), T(0)), ey(T(0), T(1), T(0)), n(T(0), T(0), T(1));
    const glm::vec<2, T> u(T(0.3), T(0.6));
    const apse::SphericalRectangle<T> r(o, c, ex, ey);
    const auto p = r.sample_point(u);
    const apse::GamitoSingleShot<T> g1(o, c, n, T(1));
    const apse::GamitoRetry<T> g8(o, c, n, T(1));
    const T values[] = {
        r.solid_angle(), r.sample(u).pdf, r.pdf(p.direction), r.invert(p.direction).x, r.locate(p.direction).distance,
        apse::SphericalRectangle<T>::from_center(o, c, ex, ey).solid_angle(),
        g1.sample(u).pdf, g1.pdf(p.direction), g8.sample(u).pdf, g8.pdf(p.direction), g8.solid_angle(),
        apse::point_on_plane(r.sample(u), o, c, n).distance,
    };
    for (T v : values)
        if (!apse::detail::is_finite(v) || !(v >= T(0))) return false;
    return !r.empty() && !g1.empty() && !g8.empty();
}

template <class T>
static bool maps_disk_light_ok() {
    using V = glm::vec<3, T>;
    const glm::vec<2, T> u(T(0.3), T(0.6));
    const auto e = apse::project_disk(V(0), V(T(0.5), T(0), T(-1)), V(0, 0, 1), T(1));
    const apse::RadialMap<T> radial(e);
    const apse::LdRadialMap<T> ld(e);
    const apse::ParallelMap<T> parallel(e);
    const apse::DiskLight<apse::RuntimeSampler<T>> light(V(0), V(T(0.5), T(0), T(-1)), V(0, 0, 1), T(1),
                                                         apse::MapKind::parallel);
    const auto s = light.sample(u);
    apse::SampleDiagnostics diag{0};
    const T values[] = {
        radial.sample(u).pdf, apse::sample_with_diagnostics(radial, u, diag).pdf, radial.pdf(s.direction), radial.invert(s.direction).x,
        radial.solid_angle(), radial.quadrant_area(T(0.5)), ld.sample(u).pdf, ld.pdf(s.direction),
        ld.invert(s.direction).y, parallel.sample(u).pdf, parallel.pdf(s.direction), parallel.invert(s.direction).x,
        parallel.half_area(T(0.1)), s.pdf, s.distance, light.pdf(s.direction), light.invert(s.direction).x,
        apse::DiskLight<apse::RuntimeSampler<T>>(V(0), V(T(0.5), T(0), T(-1)), V(0, 0, 1), T(1), apse::MapKind::radial)
            .sample(u)
            .pdf,
        apse::disk_light_pdf<apse::LdRadialMap<T>>(V(0), V(T(0.5), T(0), T(-1)), V(0, 0, 1), T(1), s.direction),
    };
    for (T v : values)
        if (!apse::detail::is_finite(v) || !(v >= T(0))) return false;
    return s.pdf > T(0) && !radial.empty() && !ld.empty() && !parallel.empty();
}

template <class T>
static bool projection_area_ok() {
    using V = glm::vec<3, T>;
    using E = apse::SphericalEllipse<T>;
    const V o(T(0.3), T(0.2), T(1)), c(T(0)), n(T(0), T(0), T(1)), u(T(1), T(0), T(0)), v(T(0), T(0.5), T(0));
    const E d = apse::project_disk(o, c, n, T(1));
    const E el = apse::project_ellipse(o, c, u, v);
    const E sp = apse::project_sphere(o, V(T(0), T(0), T(-2)), T(1));
    const E ed = apse::project_ellipsoid(o, V(T(0), T(0), T(-2)), u, v, V(T(0), T(0), T(0.25)));
    const E ft = E::from_tangents(d.x, d.y, d.z, T(0.5), T(0.25));
    const E fa = E::from_arcs(d.x, d.y, d.z, T(0.5), T(0.25));
    const apse::DiskAreaSampler<T> area(o, apse::DiskFrame<T>::make(c, n, T(1)));
    const glm::vec<2, T> uv(T(0.3), T(0.6));
    const auto smp = area.sample(uv);
    const auto pc = apse::detail::concentric_to_disk(uv);
    const T values[] = {
        d.solid_angle(), el.solid_angle(), sp.solid_angle(), ed.solid_angle(), ft.solid_angle(), fa.alpha(),
        d.to_local(-o).z, d.to_world(o).x + T(1), d.m, d.one_minus_m, smp.pdf, area.pdf(smp.direction),
        area.invert(smp.direction).x, pc.radius, pc.angle(), apse::detail::concentric_from_disk(pc.radius, pc.turns).y,
    };
    for (T val : values)
        if (!apse::detail::is_finite(val) || !(val >= T(0))) return false;
    return d.contains(-o) && apse::disk_faces(o, c, n) && apse::ellipse_faces(o, c, u, v) && !area.empty() &&
           E::make_empty().empty();
}

template <class T>
static bool tabulated_ok() {
    using V = glm::vec<3, T>;
    static apse::TabulationTable table;  // 77 KB: static storage
    table.build();
    const apse::TabulationTable& shared = apse::default_table();  // the built default table
    const glm::vec<2, T> u(T(0.3), T(0.6));
    const auto e = apse::project_disk(V(0), V(T(0.5), T(0), T(-1)), V(0, 0, 1), T(1));
    const apse::TabulatedMap<T> tab(e, table.view());
    const apse::TabulatedLdRadialMap<T> tld(e, table.view());
    const auto s = tab.sample(u);
    apse::SampleDiagnostics diag{0};
    const T with_steps = apse::sample_with_diagnostics(tab, u, diag).pdf + apse::sample_with_diagnostics(tld, u, diag).pdf;
    const T values[] = {s.pdf, tab.pdf(s.direction), tab.invert(s.direction).x, tld.sample(u).pdf,
                        tld.pdf(s.direction), tld.invert(s.direction).y, tld.radial().ellipse().alpha(),
                        T(apse::detail::tabulated_lambda_density(0.5, 0.5, 0.6, 0.9)), with_steps};
    for (T v : values)
        if (!apse::detail::is_finite(v) || !(v >= T(0))) return false;
    // cosine-weighted over the tabulated map, and DiskLight's cosine option
    const apse::CosineWeighted<apse::TabulatedLdRadialMap<T>> cw(tld, V(T(0.3), T(0.1), T(-1)));  // facing the light
    const auto c = cw.sample(u);
    const apse::DiskLight<apse::RuntimeSampler<T>> lit(V(0), V(T(0.5), T(0), T(-1)), V(0, 0, 1), T(1),
                                                       apse::MapKind::ld_radial, V(T(0.3), T(0.1), T(-1)));
    const auto ls = lit.sample(u);
    // DiskLight with a tabulated map and the stateless pdfs
    const apse::DiskLight<apse::RuntimeSampler<T>> tl(V(0), V(T(0.5), T(0), T(-1)), V(0, 0, 1), 1.0,
                                                      apse::MapKind::tabulated_ld_radial, shared.view());
    const auto ts = tl.sample(u);
    // DiskLight with the map's type chosen at compile time, plain and cosine-weighted
    const apse::DiskLight<apse::TabulatedLdRadialMap<T>> typed(V(0), V(T(0.5), T(0), T(-1)), V(0, 0, 1), T(1),
                                                               shared.view());
    const auto ys = typed.sample(u);
    const apse::DiskLight<apse::CosineWeighted<apse::TabulatedLdRadialMap<T>>> typed_lit(
        V(0), V(T(0.5), T(0), T(-1)), V(0, 0, 1), T(1), shared.view(), V(T(0.3), T(0.1), T(-1)));
    const auto yl = typed_lit.sample(u);
    // the projected-solid-angle sampler on its own
    const apse::detail::ProjectedSolidAngleSampler<T> psa(e, V(T(0.3), T(0.1), T(-1)));
    const auto p = psa.sample(u);
    const T more[] = {c.pdf, cw.pdf(c.direction), cw.invert(c.direction).x, ls.pdf, lit.pdf(ls.direction), ts.pdf,
                      tl.pdf(ts.direction),
                      apse::disk_light_pdf<apse::RuntimeSampler<T>>(V(0), V(T(0.5), T(0), T(-1)), V(0, 0, 1), 1,
                                                                    ts.direction, apse::MapKind::tabulated, shared.view()),
                      apse::disk_light_pdf<apse::RuntimeSampler<T>>(V(0), V(T(0.5), T(0), T(-1)), V(0, 0, 1), 1,
                                                                    ts.direction, apse::MapKind::tabulated, shared.view(),
                                                                    V(T(0.3), T(0.1), T(-1))),
                      apse::DiskLight<apse::RuntimeSampler<T>>(V(0), V(T(0.5), T(0), T(-1)), V(0, 0, 1), T(1),
                                                               apse::MapKind::tabulated, shared.view())
                          .sample(u)
                          .pdf,
                      ys.pdf, typed.pdf(ys.direction), typed.invert(ys.direction).x, yl.pdf,
                      typed_lit.pdf(yl.direction), typed_lit.solid_angle(),
                      p.pdf, psa.pdf(p.direction), psa.invert(p.direction).y, psa.ellipse().tan_alpha,
                      apse::detail::ProjectedSolidAngleSampler<T>().pdf(p.direction)};
    for (T v : more)
        if (!apse::detail::is_finite(v) || !(v >= T(0))) return false;
    return s.pdf > T(0) && !tab.empty() && !tld.empty() && c.pdf > T(0) && cw.weighted() && !cw.empty() &&
           lit.cosine_weighted() && ts.pdf > T(0) &&
           (tl.sampler().kind() == apse::MapKind::tabulated || tl.sampler().kind() == apse::MapKind::tabulated_ld_radial) &&
           ys.pdf > T(0) && yl.pdf > T(0) && typed_lit.cosine_weighted() && p.pdf > T(0) && !psa.empty();
}

int main() {
    const bool ok = maps_disk_light_ok<float>() && maps_disk_light_ok<double>() &&
                    projection_area_ok<float>() && projection_area_ok<double>() &&
                    baselines_rectangle_gamito_ok<float>() && baselines_rectangle_gamito_ok<double>() &&
                    elliptic_ok<float>() && elliptic_ok<double>() &&
                    tabulated_ok<float>() && tabulated_ok<double>();
    std::printf("no-exceptions build: %s\n", ok ? "ok" : "FAILED");
    return ok ? 0 : 1;
}
