// Spherical caps (SphericalEllipse::is_cap(): alpha == beta exactly, as project_sphere gives):
// every map's closed-form cap path, float and double. Checked against closed forms evaluated here
// in long double, against the general algorithm of the same map on a near-cap (continuity), by
// finite differences (area preservation) and by chi-square against the integrated pdf.
#include <apse/maps/ld_radial.hpp>
#include <apse/maps/parallel.hpp>
#include <apse/comparison.hpp>
#include <apse/maps/tabulated_ld_radial.hpp>
#include <apse/projection.hpp>
#include <apse/diagnostics.hpp>

#include "support/default_table.hpp"
#include "support/map_testing.hpp"
#include "support/statistics.hpp"

#include "support/catch.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

namespace {

template <class T> using Vec2 = glm::vec<2, T>;
template <class T> using Vec3 = glm::vec<3, T>;
template <class T> const char* type_name() { return sizeof(T) == 4 ? "float" : "double"; }
template <class T> double eps() { return double(std::numeric_limits<T>::epsilon()); }

/// A tilted right-handed world frame (not the identity: the maps' to_world is exercised).
template <class T> struct Frame {
    Vec3<T> x, y, z;
};
template <class T> Frame<T> tilted_frame() {
    const glm::dvec3 z = glm::normalize(glm::dvec3(0.3, -0.5, 0.8));
    const glm::dvec3 x = glm::normalize(glm::cross(glm::dvec3(0.1, 1.0, 0.2), z));
    return {Vec3<T>(x), Vec3<T>(glm::cross(z, x)), Vec3<T>(z)};
}

/// The ellipse with semi-axis tangents ta >= tb in the tilted frame.
template <class T> apse::SphericalEllipse<T> ellipse(T ta, T tb) {
    const Frame<T> f = tilted_frame<T>();
    return apse::SphericalEllipse<T>::from_tangents(f.x, f.y, f.z, ta, tb);
}

/// Cap tangents: a small (1e-4 sr), a medium (~0.5 sr) and a large (~4.8 sr) cap.
const double kTangents[] = {5.64e-3, 0.4, 3.0};

/// The five maps on one ellipse, each passed to f(name, map).
template <class T, class F> void for_each_map(const apse::SphericalEllipse<T>& e, F&& f) {
    const apse::TabulationView view = apse_test::default_table().view();
    f(std::string("radial"), apse::RadialMap<T>(e));
    f(std::string("ld_radial"), apse::LdRadialMap<T>(e));
    f(std::string("parallel"), apse::ParallelMap<T>(e));
    f(std::string("tabulated"), apse::TabulatedMap<T>(e, view));
    f(std::string("tabulated_ld"), apse::TabulatedLdRadialMap<T>(e, view));
}

/// The ellipse's local coordinates of a world direction, in double (normalised).
template <class T> glm::dvec3 local_of(const apse::SphericalEllipse<T>& e, const Vec3<T>& d) {
    const glm::dvec3 w(d);
    return glm::normalize(glm::dvec3(glm::dot(w, glm::dvec3(e.x)), glm::dot(w, glm::dvec3(e.y)), glm::dot(w, glm::dvec3(e.z))));
}

/// 1 − cos theta of a unit local direction, without cancellation.
inline double one_minus_z(const glm::dvec3& l) { return (l.x * l.x + l.y * l.y) / (1 + l.z); }

/// 1 − cos(atan t) = t^2 / (sqrt(1 + t^2) (1 + sqrt(1 + t^2))) in long double.
inline long double omc_of_tangent(long double t) {
    const long double q = std::sqrt(1.0L + t * t);
    return t * t / (q * (1.0L + q));
}

}  // namespace

TEMPLATE_TEST_CASE("caps: solid angle in closed form", "[caps]", float, double) {
    using T = TestType;
    // Omega = 2 pi (1 − cos alpha) with 1 − cos alpha from the tangent in long double (independent
    // of the ellipse's stored fields), from 1e-30 sr to the hemisphere: within 4 eps (two
    // roundings of from_tangents' 1 − cos alpha, one of the product by 2 pi, the reference's).
    // And the general elliptic-integral solid angle of the same cap agrees (its own documented
    // accuracy: 4.5 eps).
    for (double t : {1e-15, 1e-8, 5.64e-3, 0.4, 1.0, 3.0, 1e4}) {
        if (t < double(apse::detail::tan_min<T>()) * 4) continue;
        const auto e = ellipse<T>(T(t), T(t));
        REQUIRE(e.is_cap());
        const long double ref = apse_test::kTwoPi * omc_of_tangent((long double)T(t));
        const auto check = [&](const std::string& name, double omega) {
            INFO(type_name<T>() << " " << name << " t " << t << " omega " << omega << " ref " << double(ref));
            CHECK(std::fabs(omega - double(ref)) <= 4 * eps<T>() * double(ref));
        };
        check("radial", double(apse::RadialMap<T>(e).solid_angle()));
        check("ld_radial", double(apse::LdRadialMap<T>(e).solid_angle()));
        check("parallel", double(apse::ParallelMap<T>(e).solid_angle()));
        check("tabulated 1/pdf", 1.0 / double(apse::TabulatedMap<T>(e, apse_test::default_table().view()).sample(Vec2<T>(T(0.3), T(0.2))).pdf));
        INFO("general solid angle " << double(e.solid_angle()));
        CHECK(std::fabs(double(e.solid_angle()) - double(ref)) <= 5 * eps<T>() * double(ref));
    }
}

TEMPLATE_TEST_CASE("caps: samples inside, exact pdf, invert round trip, rim", "[caps][properties]", float, double) {
    using T = TestType;
    for (double t : kTangents) {
        const auto e = ellipse<T>(T(t), T(t));
        const long double omc = omc_of_tangent((long double)T(t));
        const double inv_omega = double(1.0L / (apse_test::kTwoPi * omc));
        for_each_map(e, [&](const std::string& name, const auto& map) {
            INFO(type_name<T>() << " " << name << " tan alpha " << t);
            const bool ld = name == "ld_radial" || name == "tabulated_ld";
            const bool parallel = name == "parallel";
            double worst_out = 0, worst_pdf = 0, worst_u = 0, worst_rim = 0;
            const int n = 24;
            for (int i = 0; i <= n; ++i)
                for (int j = 0; j <= n; ++j) {
                    const Vec2<T> u(T((i + 0.37) / (n + 1)), T((j + 0.61) / (n + 1)));
                    apse::SampleDiagnostics diag{-1};
                    const auto s = apse::sample_with_diagnostics(map, u, diag);
                    // closed forms: no Newton step, no table step (the parallel map still inverts)
                    if (!parallel) CHECK(diag.iterations == 0);
                    const glm::dvec3 l = local_of(e, s.direction);
                    // inside: 1 − cos theta <= 1 − cos alpha up to the direction's rounding (a few
                    // eps absolute in the direction, i.e. a few eps sin alpha in 1 − cos theta)
                    worst_out = std::max(worst_out, (one_minus_z(l) - double(omc)) / std::sqrt(double(omc)));
                    // the pdf is 1/Omega (within the rounding of 1/Omega: 4 eps), and pdf() agrees
                    worst_pdf = std::max(worst_pdf, std::fabs(double(s.pdf) * (1 / inv_omega) - 1));
                    const T p = map.pdf(s.direction);
                    if (p > T(0)) CHECK(p == s.pdf);
                    const Vec2<T> back = map.invert(s.direction);
                    worst_u = std::max(worst_u, std::max(std::fabs(double(back.x - u.x)), std::fabs(double(back.y - u.y))));
                }
            // the square's boundary → the rim: u2 = 1 (radial), any edge (LD), u2 in {0, 1} (parallel)
            for (int i = 0; i <= n; ++i) {
                const T a = T((i + 0.5) / (n + 1));
                const Vec2<T> edges[] = {ld ? Vec2<T>(T(0), a) : Vec2<T>(a, T(1)), ld ? Vec2<T>(a, T(1)) : Vec2<T>(a, T(1)),
                                         parallel ? Vec2<T>(a, T(0)) : Vec2<T>(a, T(1))};
                for (const auto& u : edges) {
                    const glm::dvec3 l = local_of(e, map.sample(u).direction);
                    worst_rim = std::max(worst_rim, std::fabs(one_minus_z(l) / double(omc) - 1));
                }
            }
            std::printf("[%s] caps %s t=%g: outside %.2g, |pdf Omega - 1| %.2g, |invert - u| %.2g, rim %.2g\n",
                        type_name<T>(), name.c_str(), t, worst_out, worst_pdf, worst_u, worst_rim);
            CHECK(worst_out <= 8 * eps<T>());
            CHECK(worst_pdf <= 4 * eps<T>());
            // invert: azimuth and u2 from atan2 and (1 − z)/(1 − cos alpha), a few eps each, but
            // the direction itself carries an absolute rounding of a few eps, i.e. a relative
            // one of eps/sin alpha in x^2 + y^2 (2e-5 for the small cap in float); the parallel
            // map's invert goes through its cumulative area (the same order)
            CHECK(worst_u <= 64 * eps<T>() + 8 * eps<T>() / std::sqrt(double(omc) * 2));
            // the rim: 1 − cos theta = 1 − cos alpha up to the direction's rounding relative to
            // 1 − cos alpha (eps / sin alpha for the small cap)
            CHECK(worst_rim <= 16 * eps<T>() / std::sqrt(double(omc)));
        });
    }
}

TEMPLATE_TEST_CASE("caps: the closed form continues the general map (near-caps)", "[caps]", float, double) {
    using T = TestType;
    // The general algorithm of each map on a near-cap tan beta = tan alpha (1 − delta) against the
    // cap path for the same u: the ellipse differs from the cap by delta (relative), so directions
    // move by at most ~delta sin alpha (plus the general inversion's tolerance and rounding, a
    // few tens of eps), pdfs by ~delta relative, and inverses by ~delta plus the general invert's
    // accuracy (1e-12 double, ~1e-5 float). The tabulated maps' general path samples the table's
    // density, whose row for beta = alpha is the linear CDF up to its float storage (a cap's
    // density in the Lambert anomaly is constant): the same bounds plus 1e-6.
    const double delta = sizeof(T) == 4 ? 1e-5 : 1e-9;
    for (double t : kTangents) {
        const auto cap = ellipse<T>(T(t), T(t));
        const auto near = ellipse<T>(T(t), T(t * (1 - delta)));
        REQUIRE(cap.is_cap());
        REQUIRE_FALSE(near.is_cap());
        const double sin_a = double(cap.sin_alpha);
        std::vector<std::pair<std::string, std::vector<double>>> results;  // name → worst (dir, pdf, u)
        const auto compare = [&](const std::string& name, const auto& mc, const auto& mg) {
            const bool tab = name.rfind("tabulated", 0) == 0;
            double wd = 0, wp = 0, wu = 0;
            const int n = 20;
            for (int i = 0; i < n; ++i)
                for (int j = 0; j < n; ++j) {
                    const Vec2<T> u(T((i + 0.5) / n), T((j + 0.5) / n));
                    const auto sc = mc.sample(u), sg = mg.sample(u);
                    wd = std::max(wd, glm::length(glm::dvec3(sc.direction) - glm::dvec3(sg.direction)) / sin_a);
                    wp = std::max(wp, std::fabs(double(sg.pdf) / double(sc.pdf) - 1));
                    if (!tab) {
                        const Vec2<T> uc = mc.invert(sc.direction), ug = mg.invert(sc.direction);
                        // skip the radial maps' +x seam, where u1 is 0 or 1
                        if (std::fabs(double(uc.x - ug.x)) < 0.5)
                            wu = std::max(wu, std::max(std::fabs(double(uc.x - ug.x)), std::fabs(double(uc.y - ug.y))));
                    }
                }
            std::printf("[%s] near-cap %s t=%g delta=%g: |dir| / sin alpha %.2g, |pdf ratio - 1| %.2g, |u| %.2g\n",
                        type_name<T>(), name.c_str(), t, delta, wd, wp, wu);
            INFO(type_name<T>() << " " << name << " t " << t);
            // absolute rounding of unit directions; the table is stored in float (a CDF rounding
            // of 2^-23 moves the azimuth by ~1e-7 of a turn)
            const double rounding = 64 * eps<T>() / sin_a + (tab ? 1e-6 : 0.0);
            CHECK(wd <= 4 * delta + rounding);
            CHECK(wp <= 2 * delta + 16 * eps<T>() + (tab ? 1e-6 : 0.0));
            CHECK(wu <= 4 * delta + (sizeof(T) == 4 ? 1e-4 : 1e-11));
        };
        const apse::TabulationView view = apse_test::default_table().view();
        compare("radial", apse::RadialMap<T>(cap), apse::RadialMap<T>(near));
        compare("ld_radial", apse::LdRadialMap<T>(cap), apse::LdRadialMap<T>(near));
        compare("parallel", apse::ParallelMap<T>(cap), apse::ParallelMap<T>(near));
        compare("tabulated", apse::TabulatedMap<T>(cap, view), apse::TabulatedMap<T>(near, view));
        compare("tabulated_ld", apse::TabulatedLdRadialMap<T>(cap, view), apse::TabulatedLdRadialMap<T>(near, view));
    }
}

TEST_CASE("caps: area preservation by finite differences", "[caps]") {
    // |dw/du1 x dw/du2| = Omega for an area-preserving map: central differences with h = 1e-5
    // (truncation O(h^2) times the map's second derivatives, <= ~1e-8 here; rounding eps/h ~ 2e-11),
    // double only (float's eps/h would be 1e-2). Points stay 2h away from the LD maps' kinks (the
    // concentric map's diagonals) and the quadrant seams. Bound 1e-6.
    const double h = 1e-5;
    for (double t : kTangents) {
        const auto e = ellipse<double>(t, t);
        const double omega = double(apse_test::kTwoPi * omc_of_tangent(t));
        for_each_map(e, [&](const std::string& name, const auto& map) {
            double worst = 0;
            for (int i = 0; i < 12; ++i)
                for (int j = 0; j < 12; ++j) {
                    const glm::dvec2 u((i + 0.43) / 12, (j + 0.29) / 12);
                    const double a = 2 * u.x - 1, b = 2 * u.y - 1;
                    if (std::fabs(std::fabs(a) - std::fabs(b)) < 8 * h) continue;
                    if (std::fabs(4 * u.x - std::round(4 * u.x)) < 8 * h) continue;
                    const auto w = [&](double du1, double du2) { return map.sample(glm::dvec2(u.x + du1, u.y + du2)).direction; };
                    const glm::dvec3 d1 = (w(h, 0) - w(-h, 0)) / (2 * h), d2 = (w(0, h) - w(0, -h)) / (2 * h);
                    worst = std::max(worst, std::fabs(glm::length(glm::cross(d1, d2)) / omega - 1));
                }
            std::printf("[double] caps jacobian %s t=%g: max |J / Omega - 1| %.2g\n", name.c_str(), t, worst);
            INFO(name << " t " << t);
            CHECK(worst <= 1e-6);
        });
    }
}

TEMPLATE_TEST_CASE("caps: chi-square against the integrated pdf", "[caps][chi2]", float, double) {
    using T = TestType;
    // Caps from project_sphere: tiny (1e-8 sr), medium, and nearly a hemisphere (the shading
    // point 1e-4 radii above the surface). 50 000 samples into 8 rings of equal 1 − cos theta x 12
    // azimuthal sectors (521 expected per cell); a cell's expected count is its solid angle
    // (dphi/(2 pi)) (Delta(1 − cos theta)/(1 − cos alpha)) in closed form, the integral of the
    // uniform pdf 1/Omega every map reports. Binning in the cap's frame in double (1 − cos theta
    // from x, y: no cancellation even for the tiny cap in float). Family-wise level 1 % over
    // 3 caps x 5 maps x 2 types, Šidák-corrected.
    const double level = apse_test::sidak(0.01, 30);
    const int rings = 8, sectors = 12, n = 50000;
    // sphere radius 1 at distance D: sin alpha = 1/D
    const double distances[] = {1.0 / std::sqrt(1e-8 / double(apse_test::kTwoPi) * 2), 3.0, 1.0001};
    std::uint64_t seed = sizeof(T) == 4 ? 71000 : 72000;
    for (double dist : distances) {
        const Vec3<T> o(T(0.25), T(-0.5), T(2));
        const Vec3<T> dir(glm::normalize(glm::dvec3(0.6, 0.2, -0.77)));
        const auto e = apse::project_sphere(o, o + T(dist) * dir, T(1));
        REQUIRE(e.is_cap());
        const double omc = double(e.one_minus_cos_alpha);
        // inside up to the direction's rounding: a few eps absolute, relative eps/sin alpha in
        // 1 − cos theta (0.03 for the tiny cap in float: float directions cannot resolve it better)
        const double slack = 1 + 1e-9 + 16 * eps<T>() / std::sqrt(2 * omc);
        for_each_map(e, [&](const std::string& name, const auto& map) {
            std::vector<double> observed(rings * sectors, 0.0), expected(rings * sectors, double(n) / (rings * sectors));
            apse_test::Rng rng(++seed);
            int outside = 0;
            for (int i = 0; i < n; ++i) {
                const auto s = map.sample(Vec2<T>(rng.uniform<T>(), rng.uniform<T>()));
                const glm::dvec3 l = local_of(e, s.direction);
                const double f = one_minus_z(l) / omc;
                if (!(f <= slack) || !(s.pdf > T(0))) { ++outside; continue; }
                double ang = std::atan2(l.y, l.x);
                if (ang < 0) ang += double(apse_test::kTwoPi);
                const int ring = std::min(int(f * rings), rings - 1);
                const int sec = std::min(int(ang / double(apse_test::kTwoPi) * sectors), sectors - 1);
                observed[ring * sectors + sec] += 1;
            }
            const auto r = apse_test::chi2_test(observed, expected);
            std::printf("[%s] caps chi2 %s Omega=%.3g: chi2 %.1f dof %d p %.3f\n", type_name<T>(), name.c_str(),
                        double(apse_test::kTwoPi) * omc, r.chi2, r.dof, r.p);
            INFO(type_name<T>() << " " << name << " D " << dist << " p " << r.p);
            CHECK(outside == 0);
            CHECK(r.p > level);
        });
    }
}

TEMPLATE_TEST_CASE("caps: bad input as the general maps", "[caps][robust]", float, double) {
    using T = TestType;
    const T nan = std::numeric_limits<T>::quiet_NaN(), inf = std::numeric_limits<T>::infinity();
    const auto cap = ellipse<T>(T(0.4), T(0.4));
    for_each_map(cap, [&](const std::string& name, const auto& map) {
        INFO(type_name<T>() << " " << name);
        CHECK_FALSE(map.empty());
        for (const Vec2<T>& u : {Vec2<T>(nan, T(0.5)), Vec2<T>(T(0.5), nan)}) {
            const auto s = map.sample(u);
            CHECK(s.pdf == T(0));
            CHECK(s.direction == cap.z);
        }
        // outside the square: clamped (the same sample as the clamped point)
        CHECK(map.sample(Vec2<T>(T(-3), T(7))).direction == map.sample(Vec2<T>(T(0), T(1))).direction);
        CHECK(map.invert(Vec3<T>(T(0))) == Vec2<T>(T(0)));
        CHECK(map.invert(Vec3<T>(nan, T(0), T(1))) == Vec2<T>(T(0)));
        CHECK(map.invert(Vec3<T>(inf, T(0), T(1))) == Vec2<T>(T(0)));
        CHECK(map.pdf(Vec3<T>(nan, T(0), T(1))) == T(0));
        CHECK(map.pdf(-cap.z) == T(0));
        CHECK(map.pdf(cap.x) == T(0));
        // outside the cap: invert gives a point of [0, 1]^2 (the rim at that azimuth for the radial maps)
        const Vec2<T> u = map.invert(-cap.z + cap.x);
        CHECK((u.x >= T(0) && u.x <= T(1) && u.y >= T(0) && u.y <= T(1)));
    });
    // empty input stays empty
    for_each_map(apse::SphericalEllipse<T>::make_empty(), [&](const std::string& name, const auto& map) {
        INFO(name);
        CHECK(map.empty());
        CHECK(map.sample(Vec2<T>(T(0.3), T(0.3))).pdf == T(0));
    });
}

TEMPLATE_TEST_CASE("caps: project_sphere in closed form", "[caps][projection]", float, double) {
    using T = TestType;
    // Every field against long double closed forms of D and R (tan alpha = R/sqrt((D − R)(D + R)),
    // sin alpha = R/D, cos alpha = sqrt((D − R)(D + R))/D, 1 − cos alpha = R^2/(D (D + L))), with
    // the inputs rounded to T first: within 8 eps (a few roundings each) plus, for L, the rounding
    // of D amplified by D/(D − R) (documented; 2 eps D/(D − R) bounds it). Scene scales
    // from 2^-60 to 2^60 (float) / 2^-500 to 2^500 (double): the same tangent.
    const int emax = sizeof(T) == 4 ? 60 : 500;
    for (int k = -emax; k <= emax; k += emax / 5) {
        const T s = std::ldexp(T(1), k);
        for (double dist : {1.0001, 1.05, 2.0, 37.0, 1e6}) {
            const Vec3<T> o = s * Vec3<T>(T(0.5), T(0.25), T(-1)), dir(glm::normalize(glm::dvec3(-0.48, 0.6, 0.64)));
            const Vec3<T> c = o + (s * T(dist)) * dir;
            const T r = s * T(1);
            const auto e = apse::project_sphere(o, c, r);
            INFO(type_name<T>() << " scale 2^" << k << " D " << dist);
            REQUIRE(e.is_cap());
            const glm::dvec3 p = glm::dvec3(c) - glm::dvec3(o);  // exact in double for both types
            const long double d = std::sqrt((long double)glm::dot(p / double(s), p / double(s)));
            const long double l = std::sqrt((d - 1) * (d + 1));
            const auto rel = [](double v, long double ref) { return std::fabs(v - double(ref)) / double(ref); };
            const double tol = 8 * eps<T>(), tol_l = tol + 2 * eps<T>() * double(d / (d - 1));
            CHECK(rel(double(e.tan_alpha), 1 / l) <= tol_l);
            CHECK(rel(double(e.sin_alpha), 1 / d) <= tol);
            CHECK(rel(double(e.cos_alpha), l / d) <= tol_l);
            CHECK(rel(double(e.one_minus_cos_alpha), 1 / (d * (d + l))) <= tol_l);
            CHECK(e.m == T(0));
            CHECK(e.one_minus_m == T(1));
            // the frame: right-handed, orthonormal (to a few eps), z towards the centre
            const glm::dvec3 x(e.x), y(e.y), z(e.z);
            CHECK(std::fabs(glm::dot(x, x) - 1) <= 8 * eps<T>());
            CHECK(std::fabs(glm::dot(y, y) - 1) <= 8 * eps<T>());
            CHECK(std::fabs(glm::dot(x, y)) <= 8 * eps<T>());
            CHECK(glm::length(glm::cross(x, y) - z) <= 8 * eps<T>());
            CHECK(glm::length(z - glm::normalize(p / double(s))) <= 8 * eps<T>());
        }
    }
    // documented empties: inside or on the sphere, radius <= 0, NaN/Inf
    const T nan = std::numeric_limits<T>::quiet_NaN(), inf = std::numeric_limits<T>::infinity();
    const Vec3<T> o(T(0)), c(T(0), T(0), T(2));
    CHECK(apse::project_sphere(o, c, T(3)).empty());
    CHECK(apse::project_sphere(o, c, T(2)).empty());
    CHECK(apse::project_sphere(o, c, T(0)).empty());
    CHECK(apse::project_sphere(o, c, T(-1)).empty());
    CHECK(apse::project_sphere(o, c, nan).empty());
    CHECK(apse::project_sphere(o, c, inf).empty());
    CHECK(apse::project_sphere(Vec3<T>(nan, T(0), T(0)), c, T(1)).empty());
    CHECK(apse::project_sphere(o, Vec3<T>(T(0), inf, T(0)), T(1)).empty());
    // a sphere seen from just above its surface: tan alpha capped, still an exact cap
    const auto near = apse::project_sphere(o, Vec3<T>(T(0), T(0), T(1) + std::numeric_limits<T>::epsilon()), T(1));
    CHECK(near.is_cap());
    CHECK(near.tan_alpha <= apse::detail::tan_cap<T>());
    // so far that tan alpha < tan_min: empty
    CHECK(apse::project_sphere(o, c, apse::detail::tan_min<T>() / T(4)).empty());
}

TEMPLATE_TEST_CASE("caps: circles under rounding are exact caps", "[caps][projection]", float, double) {
    using T = TestType;
    // A disk seen along its axis, a circle (project_ellipse) on its axis, and a sphere given to
    // project_ellipsoid are circular cones; their tangents come out within a few eps of each
    // other and are made exactly equal (docs/math.md §2b, Caps under rounding). The effect on the
    // pdf is bounded by the snap threshold: 1/Omega within 8 eps (+ the projections' own
    // rounding, 8 eps) of the long double closed form 1/(2 pi (1 − cos atan(r/d))).
    apse_test::Rng rng(sizeof(T) * 977);
    double worst_circle = 0, worst_sphere = 0;
    for (int i = 0; i < 200; ++i) {
        const glm::dvec3 nd = glm::normalize(glm::dvec3(rng.uniform<double>() - 0.5, rng.uniform<double>() - 0.5, rng.uniform<double>() - 0.5));
        // the disk's centre at the origin: o = d n, so o − c lies on the axis to within its rounding
        // (with a centre far from the origin the rounding of o = c + d n moves o off the axis)
        const glm::dvec3 cd(0.0);
        const double r = std::exp(4 * rng.uniform<double>() - 2), d = r * std::exp(6 * rng.uniform<double>() - 3);
        const Vec3<T> n(nd), c(cd);
        const Vec3<T> o = c + T(d) * n;
        const glm::dvec3 a = glm::normalize(glm::cross(nd, glm::dvec3(0.3, 0.5, 0.7))), b = glm::cross(nd, a);
        const Vec3<T> oe = c + T(r + d) * n;
        const auto disk = apse::project_disk(o, c, n, T(r));
        const auto circle = apse::project_ellipse(o, c, Vec3<T>(a * r), Vec3<T>(b * r));
        const auto sphere = apse::project_ellipsoid(oe, c, Vec3<T>(a * r), Vec3<T>(b * r), Vec3<T>(nd * r));
        INFO(type_name<T>() << " r " << r << " d " << d);
        CHECK(disk.is_cap());
        CHECK(circle.is_cap());
        CHECK(sphere.is_cap());
        // the disk's reference, from the rounded inputs in long double: o − c is not exactly on
        // the axis after rounding; tan alpha ~ r/d to first order in the tiny offset
        const glm::dvec3 w = glm::dvec3(c) - glm::dvec3(o);
        const long double dd = std::sqrt((long double)glm::dot(w, w));
        const long double ref_disk = apse_test::kTwoPi * omc_of_tangent((long double)T(r) / dd);
        const double pd = double(apse::RadialMap<T>(disk).pdf(disk.z));
        CHECK(std::fabs(pd * double(ref_disk) - 1) <= 16 * eps<T>());
        // the eigen-solver's caps: the snap (8 eps) plus the eigen-decomposition's own error (a
        // few eps in well-conditioned cases, docs/projection.md), with the reference from the
        // rounded inputs (circle: as the disk; sphere: tan alpha = R / sqrt(D^2 − R^2))
        const double pc = double(apse::RadialMap<T>(circle).pdf(circle.z));
        worst_circle = std::max(worst_circle, std::fabs(pc * double(ref_disk) - 1) / eps<T>());
        const glm::dvec3 ws = glm::dvec3(c) - glm::dvec3(oe);
        const long double ds = std::sqrt((long double)glm::dot(ws, ws)), rs = (long double)T(r);
        const long double ref_sphere = apse_test::kTwoPi * omc_of_tangent(rs / std::sqrt((ds - rs) * (ds + rs)));
        const double ps = double(apse::RadialMap<T>(sphere).pdf(sphere.z));
        worst_sphere = std::max(worst_sphere, std::fabs(ps * double(ref_sphere) - 1) / eps<T>());
    }
    std::printf("[%s] caps under rounding: |pdf Omega - 1| circle %.1f eps, sphere %.1f eps\n", type_name<T>(), worst_circle,
                worst_sphere);
    CHECK(worst_circle <= 16);  // measured <= 7 eps
    CHECK(worst_sphere <= 16);  // measured <= 8 eps
}
