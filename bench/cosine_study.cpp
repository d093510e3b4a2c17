// apse — the variance study of cosine-weighted sampling (docs/cosine_weighted.md).
// SPDX-License-Identifier: MIT
//
// Irradiance E(p) = ∫ max(0, n·ω) dω over a disk light, estimated with 16 jittered samples (4×4
// strata, fresh random jitter per receiver and trial) by plain and cosine-weighted samplers, in
// double; printed: relMSE (mean over receivers of (I − R)²/(R² + 0.01 mean(R)²), as the demo) and
// its ratio to the plain LD-radial map, and the fraction of samples with n·ω <= 0.
//   1. the demo's plane scene: a disk of radius 1 at (0, 1.05, 0), normal ∝ (1, 0, 0.35), above a
//      25 × 25 grid of ground receivers in [−3, 3]² (normal +y; reference in closed form);
//   2. straddling: 400 seeded random receivers near a unit disk, each with a normal that puts the
//      light across its horizon (reference: 1000 × 1000 midpoint quadrature over the disk).
//   3. with `demo`: the demo's plane-scene pixels (the ground points its camera sees through the
//      pixel centres), jittered points against the demo's own scrambled Sobol' points, split by
//      the distance to the light — why the demo's gain differs from the receiver grid's.
// Usage: cosine_study [--into PAGE] [trials] [demo]   (default 8 trials per receiver; --into
// docs/cosine_weighted.md writes the tables there, between the page's cosine_study markers:
// sections receivers and straddling, or demo)

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <string>
#include <vector>

#include <apse/apse.hpp>
#include <apse/comparison.hpp>

#include "../examples/demo/points.hpp"  // the demo's per-pixel points
#include "../tools/doc_report.hpp"

namespace {

apse_tools::DocReport report("cosine_study");  // what the study prints

using dvec2 = glm::dvec2;
using dvec3 = glm::dvec3;
const double pi = 3.14159265358979323846;

struct Receiver {
    dvec3 p, n;
    double ref;
};
struct Light {
    dvec3 c, n;
    double r;
};

/// Closed-form irradiance vector of a disk (unit radiance), as examples/demo/scene.hpp.
dvec3 irradiance_vector(const dvec3& p, const Light& L) {
    const dvec3 v = p - L.c;
    const double vn = glm::dot(v, L.n), h = std::fabs(vn);
    const dvec3 q = v - vn * L.n;
    const double rho2 = glm::dot(q, q), r2 = L.r * L.r;
    const double S = h * h + rho2 + r2;
    const double Q = std::sqrt(std::max(S * S - 4.0 * rho2 * r2, 0.0));
    const double m = h * h + rho2 - r2;
    const double jn = m >= 0.0 ? 2.0 * pi * r2 * h * h / (Q * (Q + m)) : 0.5 * pi * (1.0 - m / Q);
    const double jr_over_rho = 2.0 * pi * h * r2 / (Q * (S + Q));
    return -(vn >= 0.0 ? 1.0 : -1.0) * jn * L.n - jr_over_rho * q;
}

/// ∫ max(0, n·ω) dω over the disk by an N × N midpoint rule in (r², angle).
double quadrature(const dvec3& p, const dvec3& n, const Light& L, int N) {
    const dvec3 e1 = glm::normalize(glm::cross(L.n, std::fabs(L.n.x) < 0.9 ? dvec3(1, 0, 0) : dvec3(0, 1, 0)));
    const dvec3 e2 = glm::cross(L.n, e1);
    double sum = 0.0;
    for (int i = 0; i < N; ++i)
        for (int j = 0; j < N; ++j) {
            const double rr = L.r * std::sqrt((i + 0.5) / N), ph = 2.0 * pi * (j + 0.5) / N;
            const dvec3 w = L.c + rr * std::cos(ph) * e1 + rr * std::sin(ph) * e2 - p;
            const double d2 = glm::dot(w, w), d = std::sqrt(d2);
            sum += std::max(glm::dot(w, n) / d, 0.0) * std::fabs(glm::dot(w, L.n)) / (d2 * d);
        }
    return sum * pi * L.r * L.r / (double(N) * N);
}

struct Result {
    double relmse, below, none;  // relMSE; fractions of samples with pdf > 0 and n·ω <= 0, with pdf 0
};

/// The ground points the demo's plane-scene camera sees through its pixel centres
/// (examples/demo/scene.hpp: eye (0.3, 3.2, 5.5), look-at (0, 0.2, 0), 50° vertical field of
/// view, 320 × 240 pixels), with the closed-form reference; `pixels` = all pixels (sky included:
/// the demo's relMSE averages over every pixel, sky pixels adding 0 error).
std::vector<Receiver> demo_pixels(const Light& L, int& pixels) {
    const int w = 320, h = 240;
    pixels = w * h;
    const dvec3 eye(0.3, 3.2, 5.5), at(0.0, 0.2, 0.0);
    const dvec3 fwd = glm::normalize(at - eye), right = glm::normalize(glm::cross(fwd, dvec3(0, 1, 0)));
    const dvec3 up = glm::cross(right, fwd);
    const double t = std::tan(0.5 * 50.0 * pi / 180.0);
    std::vector<Receiver> rs;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const double sx = (2.0 * (x + 0.5) / w - 1.0) * t * w / h, sy = (1.0 - 2.0 * (y + 0.5) / h) * t;
            const dvec3 d = glm::normalize(fwd + sx * right + sy * up);
            if (!(d.y < 0.0)) continue;
            const dvec3 p = eye + (-eye.y / d.y) * d;
            rs.push_back({dvec3(p.x, 0.0, p.z), dvec3(0, 1, 0), std::max(irradiance_vector(p, L).y, 0.0)});
        }
    return rs;
}

template <class Make>
Result run(const std::vector<Receiver>& rs, const Light& L, int trials, Make make) {
    double mean_ref = 0.0;
    for (const Receiver& r : rs) mean_ref += r.ref;
    mean_ref /= double(rs.size());
    std::mt19937_64 rng(20170619);
    std::uniform_real_distribution<double> U(0.0, 1.0);
    double err = 0.0, below = 0.0, none = 0.0, count = 0.0;
    for (const Receiver& r : rs) {
        const auto s = make(r, L);
        using T = decltype(s.sample(dvec2(0.0)).pdf);  // double, or float for a float sampler
        for (int t = 0; t < trials; ++t) {
            double sum = 0.0;
            for (int i = 0; i < 16; ++i) {
                const dvec2 u((i % 4 + U(rng)) / 4.0, (i / 4 + U(rng)) / 4.0);
                const auto ds = s.sample(glm::vec<2, T>(u));
                const apse::DirectionSample<double> d{dvec3(ds.direction), double(ds.pdf)};
                count += 1.0;
                if (!(d.pdf > 0.0)) {
                    none += 1.0;
                    continue;
                }
                const double c = glm::dot(r.n, d.direction);
                if (c <= 0.0) below += 1.0;
                else sum += c / d.pdf;
            }
            const double I = sum / 16.0;
            err += (I - r.ref) * (I - r.ref) / (r.ref * r.ref + 0.01 * mean_ref * mean_ref);
        }
    }
    return {err / (double(rs.size()) * trials), below / count, none / count};
}

/// Mean over `trials` of the squared error (I − R)² of each receiver, 16 samples: jittered
/// (4 × 4 strata) or, with `sobol`, the demo's points (Owen-scrambled Sobol', a fresh scramble
/// per receiver and trial).
template <class Make>
std::vector<double> squared_errors(const std::vector<Receiver>& rs, const Light& L, int trials, bool sobol, Make make) {
    std::mt19937_64 rng(20170619);
    std::uniform_real_distribution<double> U(0.0, 1.0);
    std::vector<double> out;
    for (std::size_t ri = 0; ri < rs.size(); ++ri) {
        const Receiver& r = rs[ri];
        const auto s = make(r, L);
        using T = typename decltype(s.ellipse().z)::value_type;
        double e = 0.0;
        for (int t = 0; t < trials; ++t) {
            const demo::PixelPoints pts(std::uint32_t(ri * 2654435761u + 12345u) ^ demo::hash32(std::uint32_t(t + 1)));
            double sum = 0.0;
            for (int i = 0; i < 16; ++i) {
                float u1, u2;
                pts.light(std::uint32_t(i), u1, u2);
                const glm::vec<2, T> u = sobol ? glm::vec<2, T>(u1, u2)
                                               : glm::vec<2, T>(T((i % 4 + U(rng)) / 4.0), T((i / 4 + U(rng)) / 4.0));
                const auto d = s.sample(u);
                const double c = glm::dot(r.n, dvec3(d.direction));
                if (d.pdf > T(0) && c > 0.0) sum += c / double(d.pdf);
            }
            e += (sum / 16.0 - r.ref) * (sum / 16.0 - r.ref);
        }
        out.push_back(e / trials);
    }
    return out;
}

const apse::TabulationView& table() {
    static apse::TabulationTable* t = [] {
        auto* p = new apse::TabulationTable;
        p->build();
        return p;
    }();
    static const apse::TabulationView v = t->view();
    return v;
}

template <class T = double> apse::SphericalEllipse<T> ellipse(const Receiver& r, const Light& L) {
    using v3 = glm::vec<3, T>;
    return apse::project_disk(v3(r.p), v3(L.c), v3(L.n), T(L.r));
}

template <class Map> struct Plain {
    Map operator()(const Receiver& r, const Light& L) const { return Map(ellipse(r, L)); }
};
template <class Map> struct PlainTab {
    Map operator()(const Receiver& r, const Light& L) const {
        return Map(ellipse<typename Map::vec3::value_type>(r, L), table());
    }
};
template <class Map, int Nodes> struct Cos {
    auto operator()(const Receiver& r, const Light& L) const {
        return apse::CosineWeighted<Map, Nodes>(Map(ellipse(r, L)), r.n);
    }
};
template <class Map, int Nodes> struct CosTab {
    auto operator()(const Receiver& r, const Light& L) const {
        using T = typename Map::vec3::value_type;
        return apse::CosineWeighted<Map, Nodes>(Map(ellipse<T>(r, L), table()), glm::vec<3, T>(r.n));
    }
};

template <class Make>
void row(const char* name, const std::vector<Receiver>& plane, const Light& Lp, const std::vector<Receiver>& strad,
         const Light& Ls, int trials, double base_plane, double base_strad, Make make) {
    const Result a = run(plane, Lp, trials, make), b = run(strad, Ls, trials, make);
    report.printf("| %s | %.3e | %.1f | %.3e | %.1f | %.2f %% | %.2f %% |\n", name, a.relmse, base_plane / a.relmse, b.relmse,
                base_strad / b.relmse, 100.0 * b.below, 100.0 * b.none);
}

/// Why the demo's plane scene gains less than the receiver grid (docs/cosine_weighted.md, "In the
/// demo"): the demo's relMSE over its pixels, split by the receiver's distance to the light.
template <class T> void demo_analysis(const Light& L, int trials, bool sobol) {
    std::printf("\n%s, %s points:\n", sizeof(T) == 4 ? "float" : "double", sobol ? "scrambled Sobol'" : "jittered");
    int pixels = 0;
    const std::vector<Receiver> rs = demo_pixels(L, pixels);
    const std::vector<double> a = squared_errors(rs, L, trials, sobol, PlainTab<apse::TabulatedLdRadialMap<T>>{});
    const std::vector<double> b = squared_errors(rs, L, trials, sobol, CosTab<apse::TabulatedLdRadialMap<T>, 8>{});
    double mean = 0.0;
    for (const Receiver& r : rs) mean += r.ref;
    mean /= pixels;  // the sky pixels (reference 0) count, as in the demo
    const double eps = 0.01 * mean * mean;
    // bins of the distance from the receiver to the disk's centre
    const double edges[] = {0.0, 1.0, 1.5, 2.0, 3.0, 5.0, 1e30};
    const int nb = 6;
    double ea[nb] = {}, eb[nb] = {}, pa[nb] = {}, pb[nb] = {}, cnt[nb] = {};
    double ta = 0.0, tb = 0.0, qa = 0.0, qb = 0.0;
    for (std::size_t i = 0; i < rs.size(); ++i) {
        const double dist = glm::length(rs[i].p - L.c);
        int k = 0;
        while (k < nb - 1 && dist >= edges[k + 1]) ++k;
        const double wa = a[i] / (rs[i].ref * rs[i].ref + eps), wb = b[i] / (rs[i].ref * rs[i].ref + eps);
        ea[k] += wa;
        eb[k] += wb;
        ta += wa;
        tb += wb;
        cnt[k] += 1.0;
        if (rs[i].ref > 0.0) {
            pa[k] += a[i] / (rs[i].ref * rs[i].ref);
            pb[k] += b[i] / (rs[i].ref * rs[i].ref);
            qa += a[i] / (rs[i].ref * rs[i].ref);
            qb += b[i] / (rs[i].ref * rs[i].ref);
        }
    }
    std::printf("demo plane pixels: %zu ground of %d; mean R (all pixels) %.4g; eps = 0.01 mean^2 = %.3g\n",
                rs.size(), pixels, mean, eps);
    std::printf("relMSE (demo metric, /all pixels): tabulated %.3e, cosine %.3e, ratio %.2f\n", ta / pixels,
                tb / pixels, ta / tb);
    std::printf("relMSE without the regulariser (ground pixels): tabulated %.3e, cosine %.3e, ratio %.2f\n",
                qa / double(rs.size()), qb / double(rs.size()), qa / qb);
    std::printf("| distance to the light's centre | pixels | share of tabulated error | share of cosine error | "
                "ratio (demo metric) | ratio (no regulariser) |\n|---|---:|---:|---:|---:|---:|\n");
    for (int k = 0; k < nb; ++k)
        std::printf("| [%.1f, %.1f) | %.0f | %.1f %% | %.1f %% | %.2f | %.2f |\n", edges[k], edges[k + 1] > 1e29 ? 99.0 : edges[k + 1],
                    cnt[k], 100.0 * ea[k] / ta, 100.0 * eb[k] / tb, ea[k] / eb[k], pa[k] / pb[k]);
}

/// The demo metric over the demo's pixels with both point sets.
template <class Make>
double demo_row(const std::vector<Receiver>& rs, int pixels, const Light& L, int trials, const char* name,
                double plain_sobol, Make make) {
    double mean = 0.0;
    for (const Receiver& r : rs) mean += r.ref;
    mean /= pixels;
    double e[2] = {0.0, 0.0};
    for (int k = 0; k < 2; ++k) {
        const std::vector<double> se = squared_errors(rs, L, trials, k == 1, make);
        for (std::size_t i = 0; i < rs.size(); ++i) e[k] += se[i] / (rs[i].ref * rs[i].ref + 0.01 * mean * mean);
    }
    const double sobol = e[1] / pixels;
    report.printf("| %s | %.3e | %.3e | %.1f |\n", name, e[0] / pixels, sobol,
                  plain_sobol > 0.0 ? plain_sobol / sobol : 1.0);
    return sobol;
}

}  // namespace

int main(int argc, char** argv) {
    const apse_tools::ToolArguments args = apse_tools::tool_arguments(argc, argv);
    const std::string& page = args.page;
    const int trials = !args.rest.empty() ? std::atoi(args.rest[0].c_str()) : 8;
    using namespace apse;
    const Light Lp{dvec3(0.0, 1.05, 0.0), glm::normalize(dvec3(1.0, 0.0, 0.35)), 1.0};
    std::vector<Receiver> plane;
    for (int i = 0; i < 25; ++i)
        for (int j = 0; j < 25; ++j) {
            const dvec3 p(-3.0 + 6.0 * i / 24.0, 0.0, -3.0 + 6.0 * j / 24.0);
            plane.push_back({p, dvec3(0, 1, 0), std::max(irradiance_vector(p, Lp).y, 0.0)});
        }
    const Light Ls{dvec3(0.0), dvec3(0, 0, 1), 1.0};
    std::vector<Receiver> strad;
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> U(-1.0, 1.0);
    while (strad.size() < 400) {
        const dvec3 p(2.0 * U(rng), 2.0 * U(rng), 0.05 + 1.5 * (U(rng) + 1.0));  // in front, near field
        dvec3 n(U(rng), U(rng), U(rng));
        if (glm::length(n) < 0.1) continue;
        n = glm::normalize(n);
        // keep receivers whose horizon cuts the disk: the disk's rim is on both sides
        double lo = 1e9, hi = -1e9;
        for (int k = 0; k < 64; ++k) {
            const double a = 2.0 * pi * k / 64.0;
            const double s = glm::dot(n, glm::normalize(dvec3(std::cos(a), std::sin(a), 0.0) - p));
            lo = std::min(lo, s);
            hi = std::max(hi, s);
        }
        if (!(lo < -0.05 && hi > 0.05)) continue;
        strad.push_back({p, n, quadrature(p, n, Ls, 1000)});
    }
    if (args.rest.size() > 1 && args.rest[1] == "demo") {
        demo_analysis<double>(Lp, trials, false);  // printed on the console
        demo_analysis<double>(Lp, trials, true);
        demo_analysis<float>(Lp, trials, true);
        int pixels = 0;
        const std::vector<Receiver> rs = demo_pixels(Lp, pixels);
        report.section("demo");
        report.printf("%d trials per pixel.\n\n", trials);
        report.printf("| demo pixels, relMSE (demo metric) | jittered 4 × 4 | scrambled Sobol' | plain / this (Sobol') |\n"
                      "|---|---:|---:|---:|\n");
        const double plain =
            demo_row(rs, pixels, Lp, trials, "TabulatedLdRadialMap", 0.0, PlainTab<TabulatedLdRadialMap<double>>{});
        demo_row(rs, pixels, Lp, trials, "CW<TabulatedLdRadial>, 8 nodes", plain, CosTab<TabulatedLdRadialMap<double>, 8>{});
        demo_row(rs, pixels, Lp, trials, "CW<TabulatedLdRadial>, 16 nodes", plain, CosTab<TabulatedLdRadialMap<double>, 16>{});
        demo_row(rs, pixels, Lp, trials, "CW<TabulatedLdRadial>, 32 nodes", plain, CosTab<TabulatedLdRadialMap<double>, 32>{});
        return report.finish(page);
    }
    report.section("receivers");
    report.printf("%d trials per receiver.\n", trials);
    int centre_above = 0;  // the straddling receivers whose horizon leaves the disk's centre above it
    for (const Receiver& r : strad) centre_above += glm::dot(r.n, Ls.c - r.p) > 0.0 ? 1 : 0;
    report.printf("straddling receivers with the light's centre above the horizon: %d of %zu\n\n", centre_above, strad.size());
    const Result bp = run(plane, Lp, trials, Plain<LdRadialMap<double>>{});
    const Result bs = run(strad, Ls, trials, Plain<LdRadialMap<double>>{});
    report.printf("| sampler | plane relMSE | plane: plain LD-radial / this | straddling relMSE | straddling: "
                "plain LD-radial / this | straddling: samples below the horizon | straddling: samples with pdf 0 "
                "|\n|---|---:|---:|---:|---:|---:|---:|\n");
    const double a = bp.relmse, b = bs.relmse;
    row("LdRadialMap", plane, Lp, strad, Ls, trials, a, b, Plain<LdRadialMap<double>>{});
    row("TabulatedLdRadialMap", plane, Lp, strad, Ls, trials, a, b, PlainTab<TabulatedLdRadialMap<double>>{});
    row("RadialMap", plane, Lp, strad, Ls, trials, a, b, Plain<RadialMap<double>>{});
    row("ParallelMap", plane, Lp, strad, Ls, trials, a, b, Plain<ParallelMap<double>>{});
    row("CW<LdRadial>, 4 nodes", plane, Lp, strad, Ls, trials, a, b, Cos<LdRadialMap<double>, 4>{});
    row("CW<LdRadial>, 8 nodes", plane, Lp, strad, Ls, trials, a, b, Cos<LdRadialMap<double>, 8>{});
    row("CW<LdRadial>, 12 nodes", plane, Lp, strad, Ls, trials, a, b, Cos<LdRadialMap<double>, 12>{});
    row("CW<LdRadial>, 16 nodes", plane, Lp, strad, Ls, trials, a, b, Cos<LdRadialMap<double>, 16>{});
    row("CW<LdRadial>, 32 nodes", plane, Lp, strad, Ls, trials, a, b, Cos<LdRadialMap<double>, 32>{});
    row("CW<TabulatedLdRadial>, 4 nodes", plane, Lp, strad, Ls, trials, a, b, CosTab<TabulatedLdRadialMap<double>, 4>{});
    row("CW<TabulatedLdRadial>, 8 nodes", plane, Lp, strad, Ls, trials, a, b, CosTab<TabulatedLdRadialMap<double>, 8>{});
    row("CW<TabulatedLdRadial>, 8 nodes, float", plane, Lp, strad, Ls, trials, a, b, CosTab<TabulatedLdRadialMap<float>, 8>{});
    row("CW<TabulatedLdRadial>, 12 nodes", plane, Lp, strad, Ls, trials, a, b, CosTab<TabulatedLdRadialMap<double>, 12>{});
    row("CW<TabulatedLdRadial>, 16 nodes", plane, Lp, strad, Ls, trials, a, b, CosTab<TabulatedLdRadialMap<double>, 16>{});
    row("CW<TabulatedLdRadial>, 32 nodes", plane, Lp, strad, Ls, trials, a, b, CosTab<TabulatedLdRadialMap<double>, 32>{});
    row("CW<Radial>, 8 nodes", plane, Lp, strad, Ls, trials, a, b, Cos<RadialMap<double>, 8>{});
    row("CW<Tabulated>, 8 nodes", plane, Lp, strad, Ls, trials, a, b, CosTab<TabulatedMap<double>, 8>{});
    row("CW<Parallel>, 8 nodes", plane, Lp, strad, Ls, trials, a, b, Cos<ParallelMap<double>, 8>{});
    // the straddling receivers split by the side of the horizon the light's centre is on (the
    // tabulated maps' warp serves the first, the exact sampler both)
    std::vector<Receiver> above, below;
    for (const Receiver& r : strad) (glm::dot(r.n, Ls.c - r.p) > 0.0 ? above : below).push_back(r);
    report.section("straddling");
    report.printf("| straddling receivers | plain LD-radial relMSE | CW<LdRadial> (exact sampler) | ratio | "
                "CW<TabulatedLdRadial> | ratio |\n|---|---:|---:|---:|---:|---:|\n");
    for (int k = 0; k < 2; ++k) {
        const std::vector<Receiver>& set = k == 0 ? above : below;
        const double p0 = run(set, Ls, trials, Plain<LdRadialMap<double>>{}).relmse;
        const double p1 = run(set, Ls, trials, Cos<LdRadialMap<double>, 8>{}).relmse;
        const double p2 = run(set, Ls, trials, CosTab<TabulatedLdRadialMap<double>, 8>{}).relmse;
        report.printf("| centre %s the horizon (%zu) | %.3e | %.3e | %.1f | %.3e | %.1f |\n", k == 0 ? "above" : "below", set.size(),
                    p0, p1, p0 / p1, p2, p0 / p2);
    }
    return report.finish(page);
}
