// apse — area-preserving parameterizations for spherical ellipses.
// SPDX-License-Identifier: MIT
#pragma once

// The samplers of the sampler concept (docs/usage.md, "The sampler concept"), the light they are
// built for and what is measured of each on it, shared by tests/test_sampler_concept.cpp (which
// asserts it, with the concept's compile-time checks) and tools/concept_report.cpp (which prints
// the measured table of docs/reliability.md, "The sampler concept"): one factory per sampler,
// with docs/usage.md's table as constants; the groups of samplers the test cases check; the grid
// of points u; the budgets; and measure(), which samples a sampler at every point, calls
// `on_sample` with each sample (where the test checks it) and returns the number of samples and
// the largest |pdf(sample)/pdf − 1| and |invert(sample(u)) − u|. No test framework is used here.

#include <apse/apse.hpp>
#include <apse/baselines/area.hpp>
#include <apse/baselines/gamito.hpp>
#include <apse/math.hpp>
#include <apse/runtime_sampler.hpp>
#include <apse/spherical_rectangle.hpp>

#include "default_table.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <type_traits>

namespace apse_test {
namespace sampler_concept {

template <class T> using V3 = glm::vec<3, T>;
template <class T> using V2 = glm::vec<2, T>;

// --- the scene ------------------------------------------------------------------------------------

/// A disk light seen from o, and a receiver normal at o (for CosineWeighted).
template <class T> struct Scene {
    V3<T> o, c, n;
    T r;
    V3<T> receiver;
};

/// The disk {z = −1, |p − (0.5, 0, −1)| <= 1} seen from the origin: an oblique, close light.
template <class T> Scene<T> normal_scene() {
    return {V3<T>(0), V3<T>(T(0.5), T(0), T(-1)), V3<T>(0, 0, 1), T(1), V3<T>(T(0.2), T(0.1), T(-1))};
}

// --- the samplers: one factory each, with docs/usage.md's table as constants -----------------------

template <class T> apse::SphericalEllipse<T> ellipse_of(const Scene<T>& s) { return apse::project_disk(s.o, s.c, s.n, s.r); }

/// The light a sampler samples: the scene's disk, or its circumscribed square [−0.5, 1.5] × [−1, 1]
/// at z = −1 (SphericalRectangle).
enum class Shape { disk, square };

/// The maps' building blocks a sampler has as public members (docs/math.md §4–§6): the local
/// coordinates of a direction (RadialMap, TabulatedMap), the cumulative areas (RadialMap's
/// quadrant_area, ParallelMap's half_area). A bit mask; none for every other sampler.
enum Blocks : int { no_blocks = 0, local_coords = 1, quadrant = 2, half = 4 };

struct Radial {
    static constexpr const char* name = "RadialMap";
    static constexpr bool invertible = true, has_solid_angle = true, counts = true;
    static constexpr Shape shape = Shape::disk;
    static constexpr int blocks = local_coords | quadrant;
    template <class T> static auto make(const Scene<T>& s) { return apse::RadialMap<T>(ellipse_of(s)); }
};
struct LdRadial {
    static constexpr const char* name = "LdRadialMap";
    static constexpr bool invertible = true, has_solid_angle = true, counts = true;
    static constexpr Shape shape = Shape::disk;
    static constexpr int blocks = no_blocks;
    template <class T> static auto make(const Scene<T>& s) { return apse::LdRadialMap<T>(ellipse_of(s)); }
};
struct Parallel {
    static constexpr const char* name = "ParallelMap";
    static constexpr bool invertible = true, has_solid_angle = true, counts = true;
    static constexpr Shape shape = Shape::disk;
    static constexpr int blocks = half;
    template <class T> static auto make(const Scene<T>& s) { return apse::ParallelMap<T>(ellipse_of(s)); }
};
struct Tabulated {  // no solid_angle(): the tabulated maps never compute Omega (docs/usage.md)
    static constexpr const char* name = "TabulatedMap";
    static constexpr bool invertible = true, has_solid_angle = false, counts = true;
    static constexpr Shape shape = Shape::disk;
    static constexpr int blocks = local_coords;
    template <class T> static auto make(const Scene<T>& s) {
        return apse::TabulatedMap<T>(ellipse_of(s), default_table().view());
    }
};
struct TabulatedLdRadial {
    static constexpr const char* name = "TabulatedLdRadialMap";
    static constexpr bool invertible = true, has_solid_angle = false, counts = true;
    static constexpr Shape shape = Shape::disk;
    static constexpr int blocks = no_blocks;
    template <class T> static auto make(const Scene<T>& s) {
        return apse::TabulatedLdRadialMap<T>(ellipse_of(s), default_table().view());
    }
};
template <class Plain> struct Cosine {  // CosineWeighted over a map, with the scene's receiver normal
    static constexpr const char* name = "CosineWeighted";
    static constexpr bool invertible = true, has_solid_angle = false, counts = false;
    static constexpr Shape shape = Shape::disk;
    static constexpr int blocks = no_blocks;
    template <class T> static auto make(const Scene<T>& s) {
        using Map = decltype(Plain::make(s));
        return apse::CosineWeighted<Map>(Plain::make(s), s.receiver);
    }
};
struct Area {  // from the light's stored frame
    static constexpr const char* name = "DiskAreaSampler(o, frame)";
    static constexpr bool invertible = true, has_solid_angle = false, counts = false;
    static constexpr Shape shape = Shape::disk;
    static constexpr int blocks = no_blocks;
    template <class T> static auto make(const Scene<T>& s) {
        return apse::DiskAreaSampler<T>(s.o, apse::DiskFrame<T>::make(s.c, s.n, s.r));
    }
};
struct AreaDirect {  // the convenience constructor
    static constexpr const char* name = "DiskAreaSampler(o, c, n, r)";
    static constexpr bool invertible = true, has_solid_angle = false, counts = false;
    static constexpr Shape shape = Shape::disk;
    static constexpr int blocks = no_blocks;
    template <class T> static auto make(const Scene<T>& s) { return apse::DiskAreaSampler<T>(s.o, s.c, s.n, s.r); }
};
struct GamitoSingle {  // no invert(): rejection is not a bijection; no solid_angle(): never computed
    static constexpr const char* name = "GamitoSingleShot";
    static constexpr bool invertible = false, has_solid_angle = false, counts = false;
    static constexpr Shape shape = Shape::disk;
    static constexpr int blocks = no_blocks;
    template <class T> static auto make(const Scene<T>& s) { return apse::GamitoSingleShot<T>(s.o, s.c, s.n, s.r); }
};
struct GamitoRetry {
    static constexpr const char* name = "GamitoRetry";
    static constexpr bool invertible = false, has_solid_angle = true, counts = false;
    static constexpr Shape shape = Shape::disk;
    static constexpr int blocks = no_blocks;
    template <class T> static auto make(const Scene<T>& s) { return apse::GamitoRetry<T>(s.o, s.c, s.n, s.r, 8); }
};
struct Rectangle {  // the disk's circumscribed square
    static constexpr const char* name = "SphericalRectangle";
    static constexpr bool invertible = true, has_solid_angle = true, counts = false;
    static constexpr Shape shape = Shape::square;
    static constexpr int blocks = no_blocks;
    template <class T> static auto make(const Scene<T>& s) {
        return apse::SphericalRectangle<T>::from_center(s.o, s.c, V3<T>(s.r, 0, 0), V3<T>(0, s.r, 0));
    }
};

/// The printed names of MapKind's maps (in its order) and of the map types.
constexpr const char* kind_names[5] = {"radial", "ld_radial", "parallel", "tabulated", "tabulated_ld"};
template <template <class> class Map> constexpr const char* map_name = "?";
template <> constexpr const char* map_name<apse::RadialMap> = "RadialMap";
template <> constexpr const char* map_name<apse::LdRadialMap> = "LdRadialMap";
template <> constexpr const char* map_name<apse::ParallelMap> = "ParallelMap";
template <> constexpr const char* map_name<apse::TabulatedMap> = "TabulatedMap";
template <> constexpr const char* map_name<apse::TabulatedLdRadialMap> = "TabulatedLdRadialMap";

/// The map chosen at run time (runtime_sampler.hpp), plain or with the scene's receiver normal;
/// the tabulated kinds read the default table.
template <apse::MapKind K, bool Cosine> struct Runtime {
    static inline const std::string name =
        std::string("RuntimeSampler ") + kind_names[int(K)] + (Cosine ? ", cosine" : "");
    static constexpr bool invertible = true, has_solid_angle = false, counts = false;
    static constexpr Shape shape = Shape::disk;
    static constexpr int blocks = no_blocks;
    template <class T> static auto make(const Scene<T>& s) {
        if constexpr (Cosine) return apse::RuntimeSampler<T>(ellipse_of(s), K, default_table().view(), s.receiver);
        else return apse::RuntimeSampler<T>(ellipse_of(s), K, default_table().view());
    }
};

/// DiskLight<RuntimeSampler>: the map chosen at run time, plain or with the receiver's normal
/// (the tabulated kinds read the default table).
template <apse::MapKind K, bool Cosine> struct Light {
    static inline const std::string name =
        std::string("DiskLight<Runtime> ") + kind_names[int(K)] + (Cosine ? ", cosine" : "");
    static constexpr bool invertible = true, has_solid_angle = true, counts = false;
    static constexpr Shape shape = Shape::disk;
    static constexpr int blocks = no_blocks;
    template <class T> static auto make(const Scene<T>& s) {
        using L = apse::DiskLight<apse::RuntimeSampler<T>>;
        if constexpr (Cosine) return L(s.o, s.c, s.n, s.r, K, default_table().view(), s.receiver);
        else return L(s.o, s.c, s.n, s.r, K, default_table().view());
    }
};

/// DiskLight over the map Map chosen at compile time (the tabulated maps read the default table),
/// plain or CosineWeighted<Map> with the receiver's normal; from (c, n, r) or from the stored
/// DiskFrame.
template <template <class> class Map, bool Cosine, bool Framed = false> struct TypedLight {
    static inline const std::string name = std::string("DiskLight<") + (Cosine ? "Cosine<" : "") + map_name<Map> +
                                           (Cosine ? ">>" : ">") + (Framed ? "(frame)" : "");
    static constexpr bool invertible = true, has_solid_angle = true, counts = false;
    static constexpr Shape shape = Shape::disk;
    static constexpr int blocks = no_blocks;
    template <class T, class... Args> static auto light(const Scene<T>& s, const Args&... args) {
        using S = std::conditional_t<Cosine, apse::CosineWeighted<Map<T>>, Map<T>>;
        if constexpr (Framed) return apse::DiskLight<S>(s.o, apse::DiskFrame<T>::make(s.c, s.n, s.r), args...);
        else return apse::DiskLight<S>(s.o, s.c, s.n, s.r, args...);
    }
    template <class T> static auto make(const Scene<T>& s) {
        return apse::detail::with_table_if_read<Map<T>>(default_table().view(), [&](const auto&... table) {
            if constexpr (Cosine) return light(s, table..., s.receiver);
            else return light(s, table...);
        });
    }
};

// --- the groups of samplers the test cases check ----------------------------------------------------

/// The factory F, as a value: each group below calls visit(Factory<F>{}) for each of its samplers.
template <class F> struct Factory {
    using type = F;
};

/// The five maps (the test checks CosineWeighted over each with it).
template <class Visit> void for_each_map(Visit visit) {
    visit(Factory<Radial>{});
    visit(Factory<LdRadial>{});
    visit(Factory<Parallel>{});
    visit(Factory<Tabulated>{});
    visit(Factory<TabulatedLdRadial>{});
}

/// The five maps and CosineWeighted over each.
template <class Visit> void for_each_map_and_cosine(Visit visit) {
    for_each_map([&](auto f) {
        using Plain = typename decltype(f)::type;
        visit(Factory<Plain>{});
        visit(Factory<Cosine<Plain>>{});
    });
}

/// The baselines: the area sampler (from a frame and from the disk), Gamito's two rejection
/// samplers and SphericalRectangle.
template <class Visit> void for_each_baseline(Visit visit) {
    visit(Factory<Area>{});
    visit(Factory<AreaDirect>{});
    visit(Factory<GamitoSingle>{});
    visit(Factory<GamitoRetry>{});
    visit(Factory<Rectangle>{});
}

/// S<kind, cosine> for each MapKind, plain, then cosine-weighted.
template <template <apse::MapKind, bool> class S, class Visit> void for_each_kind(Visit& visit) {
    using K = apse::MapKind;
    visit(Factory<S<K::radial, false>>{});
    visit(Factory<S<K::ld_radial, false>>{});
    visit(Factory<S<K::parallel, false>>{});
    visit(Factory<S<K::tabulated, false>>{});
    visit(Factory<S<K::tabulated_ld_radial, false>>{});
    visit(Factory<S<K::radial, true>>{});
    visit(Factory<S<K::ld_radial, true>>{});
    visit(Factory<S<K::parallel, true>>{});
    visit(Factory<S<K::tabulated, true>>{});
    visit(Factory<S<K::tabulated_ld_radial, true>>{});
}

/// RuntimeSampler, each map, plain and cosine-weighted.
template <class Visit> void for_each_runtime(Visit visit) { for_each_kind<Runtime>(visit); }

/// DiskLight<RuntimeSampler>, each map, plain and cosine-weighted.
template <class Visit> void for_each_runtime_light(Visit visit) { for_each_kind<Light>(visit); }

/// DiskLight<Sampler>, each map, plain and cosine-weighted, and two of them from the stored frame.
template <class Visit> void for_each_typed_light(Visit visit) {
    visit(Factory<TypedLight<apse::RadialMap, false>>{});
    visit(Factory<TypedLight<apse::LdRadialMap, false>>{});
    visit(Factory<TypedLight<apse::ParallelMap, false>>{});
    visit(Factory<TypedLight<apse::TabulatedMap, false>>{});
    visit(Factory<TypedLight<apse::TabulatedLdRadialMap, false>>{});
    visit(Factory<TypedLight<apse::RadialMap, true>>{});
    visit(Factory<TypedLight<apse::LdRadialMap, true>>{});
    visit(Factory<TypedLight<apse::ParallelMap, true>>{});
    visit(Factory<TypedLight<apse::TabulatedMap, true>>{});
    visit(Factory<TypedLight<apse::TabulatedLdRadialMap, true>>{});
    visit(Factory<TypedLight<apse::LdRadialMap, false, true>>{});
    visit(Factory<TypedLight<apse::TabulatedLdRadialMap, true, true>>{});
}

/// Every sampler the test checks on the normal light, group by group.
template <class Visit> void for_each_sampler(Visit visit) {
    for_each_map_and_cosine(visit);
    for_each_baseline(visit);
    for_each_runtime(visit);
    for_each_runtime_light(visit);
    for_each_typed_light(visit);
}

// --- the points, the budgets and the measure ----------------------------------------------------

/// Interior points of the square (away from the edges, the radial seam u1 ∈ {0, 1} and the
/// LD maps' centre, where invert is ambiguous): a kGrid × kGrid grid in [0.08, 0.92]².
constexpr int kGrid = 7;
constexpr int kPoints = kGrid * kGrid;
template <class T> V2<T> grid_point(int i, int j) {
    return V2<T>(T(0.08 + 0.84 * (i + 0.31) / kGrid), T(0.08 + 0.84 * (j + 0.67) / kGrid));
}

/// Budgets shared by every sampler on this moderate light: pdf(sample) against the reported pdf
/// and the round trip invert(sample(u)) − u, far above what a build measures (docs/reliability.md,
/// written by tools/concept_report), for other compilers' FMA contraction and vector paths. A
/// sample on the light within `on_light` of its size (a unit direction's rounding carried to a
/// plane ~1 away, with slack for the rim). A wrong pdf, a wrong inverse or a direction off the
/// light errs by far more (a pdf 0.2 % off fails).
template <class T> struct Budget {
    static constexpr double pdf = sizeof(T) == 4 ? 1e-5 : 1e-13;
    static constexpr double round_trip = sizeof(T) == 4 ? 1e-5 : 1e-13;
    static constexpr double on_light = sizeof(T) == 4 ? 1e-4 : 1e-10;
};

/// Every sampler but Gamito's single shot gives a sample at every point; the single shot accepts
/// ~75 % (pi/4 of the far-field square): at least half of the points.
constexpr int kGamitoSingleShotAccepted = (kPoints + 1) / 2;
template <class F> int required_accepted() {
    return std::string(F::name) == GamitoSingle::name ? kGamitoSingleShotAccepted : kPoints;
}

/// What measure() finds of one sampler.
struct Measure {
    int accepted = 0;       ///< points that gave a sample (pdf > 0)
    double pdf = 0;         ///< over them, the largest |pdf(sample)/pdf − 1|
    double round_trip = 0;  ///< ... and |invert(sample(u)) − u| (the larger coordinate; 0 without invert)
};

/// Samples s, the sampler of the factory F in T, at every grid point u, calls on_sample(u, sample)
/// with each, and measures the samples with pdf > 0.
template <class F, class T, class S, class OnSample> Measure measure(const S& s, OnSample on_sample) {
    Measure m;
    for (int i = 0; i < kGrid; ++i)
        for (int j = 0; j < kGrid; ++j) {
            const V2<T> u = grid_point<T>(i, j);
            const auto smp = s.sample(u);
            on_sample(u, smp);
            if (!(smp.pdf > T(0))) continue;  // rejected (Gamito single shot): no sample
            ++m.accepted;
            m.pdf = std::max(m.pdf, std::fabs(double(s.pdf(smp.direction)) / double(smp.pdf) - 1));
            if constexpr (F::invertible) {
                const V2<T> back = s.invert(smp.direction);
                m.round_trip = std::max(m.round_trip, double(std::max(std::fabs(back.x - u.x), std::fabs(back.y - u.y))));
            }
        }
    return m;
}

}  // namespace sampler_concept
}  // namespace apse_test
