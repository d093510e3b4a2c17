// The device-versus-host comparison behind tests/cuda/runtime_test.cu (and its CPU model,
// runtime_model.cpp): the samplers, the configurations, the evaluation both sides run (the same
// source, __host__ __device__), and the host's comparison of the two.
//
// What is compared, per sampler, configuration and point u of the square: the sample's direction,
// pdf and distance (point samplers), and pdf(w), invert(w) at one direction w given to both sides
// (the host's own sample direction; every fifth case its opposite, a miss). Both sides read the
// same inputs; they differ only in rounding: the device contracts a*b + c into FMAs where the
// host does not, and its sin/cos/atan2/asin/log/exp differ from glibc's by up to 2 ulps (CUDA
// Programming Guide, "Mathematical Functions": 2 ulps for sinf/cosf/asinf/acosf, 3 for atan2f,
// 2 for the double ones; sqrt and division are correctly rounded without --use_fast_math).
//
// The acceptance rule, per output (a case passes when every output passes):
// 1. direct: |device - host| <= kDirect eps (absolute for the direction and invert, unit
//    scale; relative to the larger of the two for pdf and distance; invert's u1 modulo 1, an
//    azimuth for the radial maps). kDirect = 64: the outputs pass through ~100 operations
//    (projection, an R_J, a Newton inversion, the frame change), each of which may round
//    differently by 1 ulp (FMA) or 2 ulps (device transcendentals); for well-conditioned outputs
//    these add, so 64 eps is a few times the worst such sum.
// 2. neighbourhood, for the outputs that are ill-conditioned or discontinuous in their inputs (a
//    grazing disk's pdf loses digits with the distance to its plane; a tabulated map's pdf jumps
//    at its bins' edges; the rim test of pdf(w); a rejection sampler's acceptance; a far light
//    spans only a few ulps of direction, so w's place in it is set by rounding): the device's
//    output must lie within the range of the host's outputs when the inputs move by up to
//    kNeighbour eps (the shading point by that many eps of |c - o|, the normals, radius and w by
//    that many eps of their size, u by that many eps), widened by kDirect eps. The range is
//    sampled: all inputs at once with random signs, w and u alone the same way, at 4, 2, 1, 1/2
//    and 1/4 eps, and each input coordinate alone by +-4 and +-1 eps. kNeighbour = 4: a rounding
//    difference of an ulp or two in an intermediate value acts like a relative perturbation of
//    about that size of the inputs it was computed from.
// 3. round trip, for invert(w) with w in the light or on its rim: the host's sample of the
//    device's point must be as close to w as the host's sample of its own point (within a
//    factor 2, plus kDirect eps): invert is judged by how well it reproduces w, which stays
//    well-conditioned where the point of the square does not (thin and far lights).
// 4. singular points (near_singular_point): at the centre of the light's ellipse and at the ends
//    of its minor axis invert(w) is arbitrary in one coordinate and the tabulated density is a
//    limit computed in a branch of its own; pdf(w) and invert(w) are not compared there, and the
//    cases are counted.
// 5. point on the light, for the distance of DiskLight and SphereLight: the device's point
//    o + dist·dir lies on the disk's plane or the sphere to within kDirect eps of |o| + dist
//    (near-grazing rays make the distance ill-conditioned in the direction's last bits).
// An output that differs by more than this is a real difference (a wrong table, another branch
// of the code). ctest cuda_runtime_model runs this comparison against an FMA-contracted CPU build
// of the same evaluation (the device's other difference, its transcendentals, is not modelled).
// Every output of both sides must be finite (pdf 0 marks "no sample"; directions stay unit).
#pragma once

#include <apse/apse.hpp>
#include <apse/baselines/area.hpp>
#include <apse/baselines/gamito.hpp>
#include <apse/comparison.hpp>
#include <apse/runtime_sampler.hpp>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <type_traits>
#include <vector>

namespace apse_rt {

template <class T> using V2 = glm::vec<2, T>;
template <class T> using V3 = glm::vec<3, T>;

/// One geometry: shading point o; a disk (centre c, normal n, radius r) — the sphere samplers use
/// the sphere (c, r); rn the receiver normal of the cosine-weighted samplers.
template <class T> struct Config {
    V3<T> o, c, n, rn;
    T r;
};

/// One evaluation: configuration index, sampler variant (DiskLight's map), point u, direction w.
template <class T> struct Case {
    int config;
    int variant;
    V2<T> u;
    V3<T> w;
};

/// What both sides compute for a Case.
template <class T> struct Output {
    V3<T> dir;   ///< sample(u).direction
    T pdf;       ///< sample(u).pdf
    T dist;      ///< sample(u).distance (point samplers; 0 otherwise)
    T pdf_w;     ///< pdf(w)
    V2<T> inv;   ///< invert(w) ((0, 0) for the samplers without an inverse)
};

template <class S, class = void> struct has_invert : std::false_type {};
template <class S>
struct has_invert<S, std::void_t<decltype(std::declval<const S&>().invert(std::declval<const typename S::vec3&>()))>>
    : std::true_type {};

template <class S, class = void> struct has_distance : std::false_type {};
template <class S>
struct has_distance<S, std::void_t<decltype(std::declval<const S&>().sample(std::declval<const typename S::vec2&>()).distance)>>
    : std::true_type {};

template <class S, class T> APSE_FUNC Output<T> outputs(const S& s, const Case<T>& k) noexcept {
    const auto smp = s.sample(k.u);
    Output<T> r{smp.direction, smp.pdf, T(0), s.pdf(k.w), V2<T>(T(0))};
    if constexpr (has_distance<S>::value) r.dist = smp.distance;
    if constexpr (has_invert<S>::value) r.inv = s.invert(k.w);
    return r;
}

template <class T> APSE_FUNC apse::SphericalEllipse<T> disk_ellipse(const Config<T>& g) noexcept {
    return apse::project_disk(g.o, g.c, g.n, g.r);
}

// The samplers: one kernel each (per T). `variants` > 1: the variant picks DiskLight's map.
#define APSE_RT_KIND(Kind, Label, Invertible, Expr)                                                  \
    struct Kind {                                                                                   \
        static constexpr const char* name = Label;                                                  \
        static constexpr int variants = 1;                                                          \
        static constexpr bool invertible = Invertible;                                              \
        template <class T>                                                                          \
        static APSE_FUNC Output<T> run(const Config<T>& g, const Case<T>& k, const apse::TabulationView& view) noexcept { \
            (void)view;                                                                             \
            return outputs(Expr, k);                                                                \
        }                                                                                           \
    };

APSE_RT_KIND(KRadial, "RadialMap", true, apse::RadialMap<T>(disk_ellipse(g)))
APSE_RT_KIND(KLdRadial, "LdRadialMap", true, apse::LdRadialMap<T>(disk_ellipse(g)))
APSE_RT_KIND(KParallel, "ParallelMap", true, apse::ParallelMap<T>(disk_ellipse(g)))
APSE_RT_KIND(KTabulated, "TabulatedMap", true, apse::TabulatedMap<T>(disk_ellipse(g), view))
APSE_RT_KIND(KTabulatedLd, "TabulatedLdRadialMap", true, apse::TabulatedLdRadialMap<T>(disk_ellipse(g), view))
APSE_RT_KIND(KCosRadial, "CosineWeighted<RadialMap>", true, apse::CosineWeighted<apse::RadialMap<T>>(disk_ellipse(g), g.rn))
APSE_RT_KIND(KCosLdRadial, "CosineWeighted<LdRadialMap>", true, apse::CosineWeighted<apse::LdRadialMap<T>>(disk_ellipse(g), g.rn))
APSE_RT_KIND(KCosParallel, "CosineWeighted<ParallelMap>", true, apse::CosineWeighted<apse::ParallelMap<T>>(disk_ellipse(g), g.rn))
APSE_RT_KIND(KCosTabulated, "CosineWeighted<TabulatedMap>", true,
                 apse::CosineWeighted<apse::TabulatedMap<T>>(disk_ellipse(g), view, g.rn))
APSE_RT_KIND(KCosTabulatedLd, "CosineWeighted<TabulatedLdRadialMap>", true,
                 apse::CosineWeighted<apse::TabulatedLdRadialMap<T>>(disk_ellipse(g), view, g.rn))
APSE_RT_KIND(KSphereLd, "SphereLight<LdRadialMap>", true, apse::SphereLight<apse::LdRadialMap<T>>(g.o, g.c, g.r))
APSE_RT_KIND(KSphereCosLd, "SphereLight<CosineWeighted<LdRadialMap>>", true,
                 apse::SphereLight<apse::CosineWeighted<apse::LdRadialMap<T>>>(g.o, g.c, g.r, g.rn))
APSE_RT_KIND(KProjectedCap, "ProjectedCapSampler", true, apse::detail::ProjectedCapSampler<T>(apse::project_sphere(g.o, g.c, g.r), g.rn))
APSE_RT_KIND(KArea, "DiskAreaSampler", true, apse::DiskAreaSampler<T>(g.o, apse::DiskFrame<T>::make(g.c, g.n, g.r)))
APSE_RT_KIND(KGamitoSingle, "GamitoSingleShot", false, apse::GamitoSingleShot<T>(g.o, g.c, g.n, g.r))
APSE_RT_KIND(KGamitoRetry, "GamitoRetry(8)", false, apse::GamitoRetry<T>(g.o, g.c, g.n, g.r, 8))
#undef APSE_RT_KIND

/// DiskLight<RuntimeSampler> with each of the five maps (the variant, a MapKind), plain (Cosine
/// false) or cosine-weighted.
template <bool Cosine> struct KDiskLightT {
    static constexpr const char* name = Cosine ? "DiskLight cosine-weighted" : "DiskLight";
    static constexpr int variants = 5;
    static constexpr bool invertible = true;
    template <class T>
    static APSE_FUNC Output<T> run(const Config<T>& g, const Case<T>& k, const apse::TabulationView& view) noexcept {
        const auto map = static_cast<apse::MapKind>(k.variant);
        using Light = apse::DiskLight<apse::RuntimeSampler<T>>;
        if constexpr (Cosine) return outputs(Light(g.o, g.c, g.n, g.r, map, view, g.rn), k);
        else return outputs(Light(g.o, g.c, g.n, g.r, map, view), k);
    }
};
using KDiskLight = KDiskLightT<false>;
using KDiskLightCos = KDiskLightT<true>;

/// The light's surface a kind's distance reaches (rule 5): 0 none, 1 the disk's plane, 2 the sphere.
template <class Kind> struct surface_of : std::integral_constant<int, 0> {};
template <bool Cosine> struct surface_of<KDiskLightT<Cosine>> : std::integral_constant<int, 1> {};
template <> struct surface_of<KSphereLd> : std::integral_constant<int, 2> {};
template <> struct surface_of<KSphereCosLd> : std::integral_constant<int, 2> {};

inline const char* variant_name(int v) {
    static const char* const names[] = {"radial", "ld_radial", "parallel", "tabulated", "tabulated_ld_radial"};
    return v >= 0 && v < 5 ? names[v] : "?";
}

template <class... K> struct KindList {};

/// Every sampler, in the order of the report. APSE_RT_GROUP (0 to kGroups − 1) selects one
/// group: tools/gpu_check.sh compiles the groups as separate programs, in parallel (grouped so
/// that each takes ptxas a similar time).
constexpr int kGroups = 8;
#if !defined(APSE_RT_GROUP)
using Kinds = KindList<KRadial, KLdRadial, KParallel, KTabulated, KTabulatedLd, KCosRadial, KCosLdRadial, KCosParallel,
                       KCosTabulated, KCosTabulatedLd, KDiskLight, KDiskLightCos, KSphereLd, KSphereCosLd, KProjectedCap,
                       KArea, KGamitoSingle, KGamitoRetry>;
#elif APSE_RT_GROUP == 0
using Kinds = KindList<KRadial, KLdRadial, KParallel>;
#elif APSE_RT_GROUP == 1
using Kinds = KindList<KTabulated, KTabulatedLd, KArea, KGamitoSingle, KGamitoRetry>;
#elif APSE_RT_GROUP == 2
using Kinds = KindList<KCosRadial, KCosLdRadial>;
#elif APSE_RT_GROUP == 3
using Kinds = KindList<KCosParallel>;
#elif APSE_RT_GROUP == 4
using Kinds = KindList<KCosTabulated, KCosTabulatedLd>;
#elif APSE_RT_GROUP == 5
using Kinds = KindList<KDiskLight>;
#elif APSE_RT_GROUP == 6
using Kinds = KindList<KDiskLightCos>;
#elif APSE_RT_GROUP == 7
using Kinds = KindList<KSphereLd, KSphereCosLd, KProjectedCap>;
#else
#error "APSE_RT_GROUP must be 0 to 7"
#endif

// ---------------------------------------------------------------------------------------------
// Host side: the configurations, the cases, the comparison.

struct NamedConfig {
    const char* name;
    double o[3], c[3], n[3], rn[3];
    double r;
};

/// The configurations, in double (rounded once to T). Adversarial ones after the first two.
inline std::vector<NamedConfig> named_configs() {
    const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
    const double far6[3] = {0.3e6 / 1.3, 0.4e6 / 1.3, 1.2e6 / 1.3}, far8[3] = {0.3e8 / 1.3, 0.4e8 / 1.3, 1.2e8 / 1.3};
    return {
        {"ordinary", {0, 0, 0}, {0.3, -0.2, 2}, {0.1, 0.2, -1}, {0, 0, 1}, 0.7},
        {"near and large (0.05 above the centre)", {0, 0, 0}, {0, 0, 0.05}, {0, 0, 1}, {0.3, 0, 1}, 1},
        {"far: 1e6 radii", {0, 0, 0}, {far6[0], far6[1], far6[2]}, {0.2, 0.1, -1}, {0, 0, 1}, 1},
        {"far: 1e8 radii", {0, 0, 0}, {far8[0], far8[1], far8[2]}, {0.2, 0.1, -1}, {0.1, 0, 1}, 1},
        {"grazing: 1e-3 above the plane, 0.2 outside the rim", {1.2, 0, 1e-3}, {0, 0, 0}, {0, 0, 1}, {-1, 0, -0.2}, 1},
        {"grazing and far: 1e-4 of the distance above the plane", {1000, 0, 0.1}, {0, 0, 0}, {0, 0, 1}, {-1, 0, 0}, 1},
        {"just above the rim", {1, 0, 1e-2}, {0, 0, 0}, {0, 0, 1}, {0, 0, -1}, 1},
        {"in the disk's plane (empty)", {2, 0, 0}, {0, 0, 0}, {0, 0, 1}, {-1, 0, 0}, 1},
        {"receiver's horizon cuts the light", {0, 0, 0}, {0.5, 0, 1}, {0, 0, -1}, {1, 0, 0.05}, 1},
        {"below the receiver's horizon", {0, 0, 0}, {0, 0, 1}, {0, 0, -1}, {0, 0, -1}, 0.5},
        {"zero receiver normal", {0, 0, 0}, {0.2, 0.1, 1.5}, {0, 0, -1}, {0, 0, 0}, 0.6},
        {"large coordinates (1e6), light 2 away", {1e6, -1e6, 3e5}, {1e6 + 0.3, -1e6, 3e5 + 2}, {0, 0.3, -1}, {0, 0, 1}, 0.8},
        {"NaN radius", {0, 0, 0}, {0, 0, 2}, {0, 0, 1}, {0, 0, 1}, nan},
        {"infinite shading point", {inf, 0, 0}, {0, 0, 2}, {0, 0, 1}, {0, 0, 1}, 1},
    };
}

template <class T> V3<T> to_vec(const double (&a)[3]) { return V3<T>(T(a[0]), T(a[1]), T(a[2])); }

template <class T> std::vector<Config<T>> configs_for() {
    std::vector<Config<T>> out;
    for (const NamedConfig& nc : named_configs())
        out.push_back({to_vec<T>(nc.o), to_vec<T>(nc.c), to_vec<T>(nc.n), to_vec<T>(nc.rn), T(nc.r)});
    return out;
}

/// The points of the square: a 6 x 6 grid of cell centres, the corners and edges exactly,
/// one ulp inside 1, a subnormal-small coordinate, out-of-range (clamped) and NaN coordinates.
template <class T> std::vector<V2<T>> square_points() {
    std::vector<V2<T>> u;
    for (int i = 0; i < 6; ++i)
        for (int j = 0; j < 6; ++j) u.emplace_back(T((i + 0.5) / 6), T((j + 0.5) / 6));
    const T one_minus = T(1) - std::numeric_limits<T>::epsilon() / 2, nan = std::numeric_limits<T>::quiet_NaN();
    const T tiny = std::numeric_limits<T>::min();
    const T extra[][2] = {{0, 0}, {1, 1}, {0, 1}, {1, 0}, {0.5, 0.5}, {one_minus, 0.5}, {0.5, one_minus}, {0.25, 1},
                          {0.75, 0}, {0, 0.5}, {1, 0.5}, {tiny, 0.3}, {0.3, tiny}, {one_minus, one_minus}, {-0.25, 1.5},
                          {2, -1}, {nan, 0.5}, {0.5, nan}, {0.1, 0.999}, {0.999, 0.001}};
    for (const auto& e : extra) u.emplace_back(e[0], e[1]);
    return u;
}

/// Host evaluation of a whole kind (the reference).
template <class Kind, class T>
std::vector<Output<T>> host_run(const std::vector<Config<T>>& configs, const std::vector<Case<T>>& cases,
                                const apse::TabulationView& view) {
    std::vector<Output<T>> out(cases.size());
    for (std::size_t i = 0; i < cases.size(); ++i) out[i] = Kind::template run<T>(configs[cases[i].config], cases[i], view);
    return out;
}

/// The cases of one kind: every variant x configuration x point of the square; w is the host's
/// own sample direction (every fifth case its opposite), or the light's centre direction when
/// the host has no sample.
template <class Kind, class T>
std::vector<Case<T>> make_cases(const std::vector<Config<T>>& configs, const apse::TabulationView& view) {
    std::vector<Case<T>> cases;
    const std::vector<V2<T>> us = square_points<T>();
    for (int v = 0; v < Kind::variants; ++v)
        for (int c = 0; c < int(configs.size()); ++c)
            for (std::size_t j = 0; j < us.size(); ++j) {
                Case<T> k{c, v, us[j], V3<T>(T(0), T(0), T(1))};
                const Output<T> h = Kind::template run<T>(configs[c], k, view);
                if (h.pdf > T(0)) {
                    k.w = j % 5 == 4 ? -h.dir : h.dir;
                } else {
                    const V3<T> d = configs[c].c - configs[c].o;
                    const T len = std::sqrt(glm::dot(d, d));
                    if (len > T(0) && std::isfinite(len)) k.w = d / len;
                }
                cases.push_back(k);
            }
    return cases;
}

constexpr double kDirect = 64;     // eps: see the file comment, step 1
constexpr double kNeighbour = 4;   // eps: see the file comment, step 2
constexpr int kPerturbations = 40;
constexpr double kReach = 1024;    // eps: w is in the light's closure if the host's invert(w) maps back to within this // host evaluations spanning the neighbourhood (step 2)

inline bool finite_output_scalar(double x) { return std::isfinite(x); }

template <class T> bool finite_output(const Output<T>& o) {
    const T v[] = {o.dir.x, o.dir.y, o.dir.z, o.pdf, o.dist, o.pdf_w, o.inv.x, o.inv.y};
    for (T x : v)
        if (!std::isfinite(x)) return false;
    return true;
}

/// The compared fields of an Output, and whether each is relative (pdf, distance) or absolute.
constexpr int kFields = 8;
template <class T> void fields(const Output<T>& o, double (&f)[kFields]) {
    f[0] = o.dir.x; f[1] = o.dir.y; f[2] = o.dir.z; f[3] = o.pdf; f[4] = o.dist; f[5] = o.pdf_w; f[6] = o.inv.x; f[7] = o.inv.y;
}
inline bool relative_field(int i) { return i == 3 || i == 4 || i == 5; }

/// |device − host| of field f: relative to the larger of the two for pdf and distance; for
/// invert's u1 modulo 1 (u1 of the radial maps is an azimuth: 0 and 1 are the same point).
inline double difference(int f, double h, double d) {
    if (h == d) return 0.0;
    double a = std::fabs(d - h);
    if (relative_field(f)) {
        const double s = std::fabs(h) > std::fabs(d) ? std::fabs(h) : std::fabs(d);
        return a / s;
    }
    if (f == 6 && a > 0.5) a = 1.0 - a;
    return a;
}
inline int field_group(int i) { return i < 3 ? 0 : (i < 6 ? i - 2 : 4); }  // dir, pdf, dist, pdf(w), invert (x2)
constexpr int kGroupsOfFields = 5;
inline const char* group_name(int g) {
    static const char* const n[] = {"dir", "pdf", "dist", "pdf(w)", "invert"};
    return n[g];
}

struct Rng {  // splitmix64
    std::uint64_t s;
    std::uint64_t next() {
        std::uint64_t z = (s += 0x9e3779b97f4a7c15ULL);
        z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
        z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
        return z ^ (z >> 31);
    }
    double sign() { return (next() >> 63) ? 1.0 : -1.0; }
};

/// The configuration and case moved by `scale` eps (see the file comment, step 2).
template <class T>
void perturb(Config<T>& g, Case<T>& k, double scale, Rng& rng) {
    const double e = scale * double(std::numeric_limits<T>::epsilon());
    const V3<T> d = g.c - g.o;
    const double dist = std::sqrt(double(d.x) * d.x + double(d.y) * d.y + double(d.z) * d.z);
    auto move3 = [&](V3<T>& v, double size) {
        for (int i = 0; i < 3; ++i) v[i] = T(double(v[i]) + rng.sign() * e * size);
    };
    auto size3 = [](const V3<T>& v) { return std::sqrt(double(v.x) * v.x + double(v.y) * v.y + double(v.z) * v.z); };
    if (std::isfinite(dist)) move3(g.o, dist);
    move3(g.n, size3(g.n));
    move3(g.rn, size3(g.rn));
    g.r = T(double(g.r) * (1 + rng.sign() * e));
    move3(k.w, size3(k.w));
    for (int i = 0; i < 2; ++i) k.u[i] = T(double(k.u[i]) + rng.sign() * e);
}

template <class T> double distance(const V3<T>& a, const V3<T>& b) {
    const double x = double(a.x) - b.x, y = double(a.y) - b.y, z = double(a.z) - b.z;
    return std::sqrt(x * x + y * y + z * z);
}
template <class T> int k_config(const Case<T>& k) { return k.config; }

/// The configuration and case with one input coordinate (0-14: o, n, rn, w, r, u) moved by
/// `scale` eps of its size (as perturb).
template <class T>
void perturb_one(Config<T>& g, Case<T>& k, int which, double scale) {
    const double e = scale * double(std::numeric_limits<T>::epsilon());
    auto size3 = [](const V3<T>& v) { return std::sqrt(double(v.x) * v.x + double(v.y) * v.y + double(v.z) * v.z); };
    const V3<T> d = g.c - g.o;
    const double dist = size3(d);
    if (which < 3) {
        if (std::isfinite(dist)) g.o[which] = T(double(g.o[which]) + e * dist);
    } else if (which < 6) {
        g.n[which - 3] = T(double(g.n[which - 3]) + e * size3(g.n));
    } else if (which < 9) {
        g.rn[which - 6] = T(double(g.rn[which - 6]) + e * size3(g.rn));
    } else if (which < 12) {
        k.w[which - 9] = T(double(k.w[which - 9]) + e * size3(k.w));
    } else if (which == 12) {
        g.r = T(double(g.r) * (1 + e));
    } else {
        k.u[which - 13] = T(double(k.u[which - 13]) + e);
    }
}
constexpr int kInputs = 15;

/// True if w is within kNeighbour eps of a singular point of the maps (rule 4): the centre of the
/// disk's or the sphere's ellipse (where the radial maps' azimuth is undefined, so invert's u1
/// is arbitrary, and the tabulated maps' density is the limit of its bins' densities, computed
/// in a branch of its own) or an end of its minor axis (the parallel map's edges u1 = 0 and 1
/// collapse there: u2 is arbitrary). There pdf(w) and invert(w) are not compared; the count is reported.
template <class T> bool near_singular_point(const Config<T>& g, const V3<T>& w) {
    const double tol = kNeighbour * double(std::numeric_limits<T>::epsilon());
    const apse::SphericalEllipse<T> es[2] = {apse::project_disk(g.o, g.c, g.n, g.r), apse::project_sphere(g.o, g.c, g.r)};
    for (const auto& e : es) {
        if (e.empty()) continue;
        const V3<T> tip = e.cos_beta * e.z + e.sin_beta * e.y, tip2 = e.cos_beta * e.z - e.sin_beta * e.y;
        if (distance(w, e.z) <= tol || distance(w, tip) <= tol || distance(w, tip2) <= tol) return true;
    }
    return false;
}

/// Rule 5, for the distance of the point samplers: the device's point o + dist·dir lies on the
/// light's surface (surface 1: the disk's plane, 2: the sphere) to within kDirect eps of the
/// point's magnitude |o| + dist, the accuracy with which T holds the point. Where the ray nearly
/// grazes the surface (the rim of a sphere's cap, a disk seen edge-on) the distance along it is
/// ill-conditioned in the direction's last bits; the point it gives is not.
template <class T> bool point_on_surface(int surface, const Config<T>& g, const Output<T>& d) {
    if (surface == 0 || !(d.pdf > 0)) return false;
    const double eps = double(std::numeric_limits<T>::epsilon());
    const double o[3] = {g.o.x, g.o.y, g.o.z}, c[3] = {g.c.x, g.c.y, g.c.z}, dir[3] = {d.dir.x, d.dir.y, d.dir.z};
    double p[3], r2 = 0, on = 0, nn = 0, osize = 0;
    for (int k = 0; k < 3; ++k) {
        p[k] = o[k] + double(d.dist) * dir[k] - c[k];  // the point relative to the centre
        r2 += p[k] * p[k];
        on += p[k] * double(g.n[k]);
        nn += double(g.n[k]) * double(g.n[k]);
        osize += o[k] * o[k];
    }
    const double tol = kDirect * eps * (std::sqrt(osize) + double(d.dist));
    if (surface == 1) return nn > 0 && std::fabs(on) / std::sqrt(nn) <= tol;
    return std::fabs(std::sqrt(r2) - double(g.r)) <= tol;
}

/// Per-sampler results (one line of the report).
struct Tally {
    int cases = 0, failed = 0, neighbourhood = 0, singular = 0, nonfinite_device = 0, nonfinite_host = 0;
    double max_diff[kGroupsOfFields] = {0, 0, 0, 0, 0};  // in eps (relative for pdf/dist)
};

/// Compares the device's outputs of one kind with the host's; prints the first failures.
template <class Kind, class T>
Tally compare(const std::vector<Config<T>>& configs, const std::vector<Case<T>>& cases,
              const std::vector<Output<T>>& host, const std::vector<Output<T>>& device, int variant,
              const apse::TabulationView& view) {
    Tally t;
    const double eps = double(std::numeric_limits<T>::epsilon());
    const std::vector<NamedConfig> names = named_configs();
    for (std::size_t i = 0; i < cases.size(); ++i) {
        if (cases[i].variant != variant) continue;
        ++t.cases;
        const bool fh = finite_output(host[i]), fd = finite_output(device[i]);
        if (!fh) ++t.nonfinite_host;
        if (!fd) ++t.nonfinite_device;
        double h[kFields], d[kFields];
        fields(host[i], h);
        fields(device[i], d);
        bool direct = true;
        double diff[kFields];
        for (int f = 0; f < kFields; ++f) {
            diff[f] = difference(f, h[f], d[f]) / eps;
            if (!(diff[f] <= kDirect)) direct = false;
        }
        bool ok = fh && fd;
        int bad_field = -1;
        if (ok && !direct) {
            double lo[kFields], hi[kFields];
            for (int f = 0; f < kFields; ++f) lo[f] = hi[f] = h[f];
            Rng rng{0x5eed0000u + i};
            // all inputs at once with random signs, at 4, 2, 1, 1/2, 1/4 eps; w and u alone, the
            // same; then each input alone by +-kNeighbour and +-1 eps
            for (int j = 0; j < 2 * kPerturbations + 4 * kInputs; ++j) {
                Config<T> g = configs[cases[i].config];
                Case<T> k = cases[i];
                if (j < kPerturbations) {
                    perturb(g, k, kNeighbour / double(1 << (j % 5)), rng);
                } else if (j < 2 * kPerturbations) {  // w alone (around a singular point: its azimuths)
                    Config<T> g2 = g;
                    perturb(g2, k, kNeighbour / double(1 << (j % 5)), rng);
                } else {
                    const int a = (j - 2 * kPerturbations) / 4, m = (j - 2 * kPerturbations) % 4;
                    perturb_one(g, k, a, (m & 1 ? -1.0 : 1.0) * (m & 2 ? 1.0 : kNeighbour));
                }
                double p[kFields];
                fields(Kind::template run<T>(g, k, view), p);
                for (int f = 0; f < kFields; ++f) {
                    if (!std::isfinite(p[f])) continue;
                    lo[f] = p[f] < lo[f] ? p[f] : lo[f];
                    hi[f] = p[f] > hi[f] ? p[f] : hi[f];
                }
            }
            // invert of a direction inside the light: also accepted if the host's sample of the
            // device's point is as close to w as the host's sample of its own point (rule 3)
            bool round_trip = false;
            if (Kind::invertible) {
                Case<T> kh = cases[i], kd = cases[i];
                kh.u = host[i].inv;
                kd.u = device[i].inv;
                const V3<T> sh = Kind::template run<T>(configs[k_config(cases[i])], kh, view).dir;
                const V3<T> sd = Kind::template run<T>(configs[k_config(cases[i])], kd, view).dir;
                const double reach = distance(sh, cases[i].w);  // host's own round trip
                const bool in_light = h[5] > 0 || d[5] > 0 || reach <= std::sqrt(eps);  // inside, or on the rim
                round_trip = in_light && distance(sd, cases[i].w) <= 2 * reach + kDirect * eps;
            }
            const bool singular = near_singular_point(configs[cases[i].config], cases[i].w);
            if (singular) ++t.singular;
            const bool on_surface = point_on_surface(surface_of<Kind>::value, configs[cases[i].config], device[i]);
            for (int f = 0; f < kFields && ok; ++f) {
                if (diff[f] <= kDirect) continue;
                if (f >= 6 && round_trip) continue;
                if (f == 4 && on_surface) continue;
                if (f >= 5 && singular) continue;
                const double scale = relative_field(f) ? (std::fabs(lo[f]) > std::fabs(hi[f]) ? std::fabs(lo[f]) : std::fabs(hi[f])) : 1.0;
                const double slack = kDirect * eps * (scale > 0 ? scale : 1.0);
                if (!(d[f] >= lo[f] - slack && d[f] <= hi[f] + slack)) {
                    ok = false;
                    bad_field = f;
                }
            }
            if (ok) ++t.neighbourhood;
        }
        if (ok && direct) {
            for (int f = 0; f < kFields; ++f) {
                const int g = field_group(f);
                if (diff[f] > t.max_diff[g]) t.max_diff[g] = diff[f];
            }
        } else if (!ok) {
            if (t.failed < 3) {
                const Case<T>& k = cases[i];
                std::printf("  FAIL %s [%s] config \"%s\" u = (%.9g, %.9g): %s\n", Kind::name,
                            Kind::variants > 1 ? variant_name(variant) : "", names[k.config].name, double(k.u.x),
                            double(k.u.y), bad_field < 0 ? "non-finite output" : group_name(field_group(bad_field)));
                const int p = std::numeric_limits<T>::max_digits10;
                for (int side = 0; side < 2; ++side) {
                    const double* v = side == 0 ? h : d;
                    std::printf("    %s dir (%.*g %.*g %.*g) pdf %.*g dist %.*g pdf(w) %.*g invert (%.*g %.*g)\n",
                                side == 0 ? "host  " : "device", p, v[0], p, v[1], p, v[2], p, v[3], p, v[4], p, v[5], p, v[6],
                                p, v[7]);
                }
            }
            ++t.failed;
        }
    }
    return t;
}

/// Runs every kind of the group through `device` (device.template run<Kind, T>(configs, cases)
/// returns the device's outputs) and compares; prints one line per sampler and variant.
/// Returns the number of failed samplers; adds to passed/failed.
template <class T, class Device, class... K>
void run_all(Device& device, KindList<K...>, const apse::TabulationView& host_view, int& passed, int& failed) {
    const char* tname = sizeof(T) == 4 ? "float" : "double";
    const std::vector<Config<T>> configs = configs_for<T>();
    auto one = [&](auto kind_tag) {
        using Kind = decltype(kind_tag);
        const std::vector<Case<T>> cases = make_cases<Kind, T>(configs, host_view);
        const std::vector<Output<T>> host = host_run<Kind, T>(configs, cases, host_view);
        const std::vector<Output<T>> dev = device.template run<Kind, T>(configs, cases);
        if (dev.size() != cases.size()) {
            std::printf("| %-47s | %-6s | device run failed |\n", Kind::name, tname);
            failed += Kind::variants;
            return;
        }
        for (int v = 0; v < Kind::variants; ++v) {
            const Tally t = compare<Kind, T>(configs, cases, host, dev, v, host_view);
            const bool ok = t.failed == 0 && t.nonfinite_device == 0 && t.nonfinite_host == 0;
            char label[96];
            std::snprintf(label, sizeof label, "%s%s%s%s", Kind::name, Kind::variants > 1 ? " [" : "",
                          Kind::variants > 1 ? variant_name(v) : "", Kind::variants > 1 ? "]" : "");
            std::printf("| %-47s | %-6s | %5d | %4d | %4d | %4d | %3d/%-3d | %8.3g | %8.3g | %8.3g | %8.3g | %8.3g | %s |\n", label,
                        tname, t.cases, t.failed, t.neighbourhood, t.singular, t.nonfinite_device, t.nonfinite_host, t.max_diff[0],
                        t.max_diff[1], t.max_diff[2], t.max_diff[3], t.max_diff[4], ok ? "pass" : "FAIL");
            (ok ? passed : failed) += 1;
        }
    };
    (one(K{}), ...);
}

inline void print_header() {
    std::printf("Max |device - host| of the cases within the direct bound (%g eps), in eps of T (relative for pdf,\n"
                "dist, pdf(w)). nbhd: cases beyond it passed by rules 2-5 (runtime_cases.hpp); sing: those of them\n"
                "whose w is a singular point of the maps (pdf(w), invert not compared); nonfin: non-finite outputs,\n"
                "device/host.\n\n",
                kDirect);
    std::printf("| %-47s | %-6s | %5s | %4s | %4s | %4s | %7s | %8s | %8s | %8s | %8s | %8s | %s |\n", "sampler", "T", "cases",
                "fail", "nbhd", "sing", "nonfin", "dir", "pdf", "dist", "pdf(w)", "invert", "result");
    std::printf("|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
}

}  // namespace apse_rt
