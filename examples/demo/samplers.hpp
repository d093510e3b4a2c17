// apse demo — one adapter over every disk-light sampler the demo compares.
// SPDX-License-Identifier: MIT
#pragma once

/// @file samplers.hpp
/// The samplers compared, each wrapped in a *factory* that builds the per-shading-point sampler
/// (the set-up a renderer does once per shading point) from the shading point, the receiver's
/// normal (zero in the medium, where there is no surface) and the light — a disk or a sphere —
/// and a uniform `LightSample` result (apse::PointSample): direction, solid-angle pdf (0 = no
/// sample: skip it), point on the light and distance to it.

#include <array>
#include <vector>

#include <apse/apse.hpp>
#include <apse/baselines/area.hpp>
#include <apse/baselines/gamito.hpp>
#include <apse/comparison.hpp>

// pbrt-v4's uniform cone sampling of sphere lights, the reference apse's benchmarks use too.
#include "../../bench/support/cone_sampler.hpp"

namespace demo {

using vec2 = glm::vec2;
using vec3 = glm::vec3;

/// A disk light: centre, normal (unit), radius, emitted radiance (two-sided, invisible).
struct Disk {
    vec3 center, normal;
    float radius, Le;
};

/// A sphere light: centre, radius, emitted radiance (uniform).
struct SphereEmitter {
    vec3 center;
    float radius, Le;
};

/// One light sample from a shading point: direction, pdf (solid angle; 0 = no sample), point on
/// the disk, distance to it.
using LightSample = apse::PointSample<float>;

/// The samplers. `cone` (pbrt-v4's uniform cone sampling) exists for sphere lights only and plays
/// the role of `area` there (the reference the others are measured against); Gamito and area
/// sampling exist for disks only.
enum class Kind { area, gamito, radial, ld_radial, parallel, tabulated, cosine, cone };

inline const char* kind_name(Kind k) {
    switch (k) {
    case Kind::area: return "area";
    case Kind::gamito: return "Gamito";
    case Kind::radial: return "radial";
    case Kind::ld_radial: return "LD-radial";
    case Kind::parallel: return "parallel";
    case Kind::tabulated: return "tabulated";
    case Kind::cosine: return "cosine-weighted";
    case Kind::cone: return "cone";
    }
    return "?";
}

/// The samplers of the disk-light comparisons, in display order.
inline std::vector<Kind> disk_kinds() {
    return {Kind::area, Kind::gamito, Kind::radial, Kind::ld_radial, Kind::parallel, Kind::tabulated, Kind::cosine};
}

/// The samplers of the sphere-light comparison, in display order (the first is the reference).
inline std::vector<Kind> sphere_kinds() {
    return {Kind::cone, Kind::ld_radial, Kind::parallel, Kind::tabulated, Kind::cosine};
}

/// Wraps a baseline sampler with `sample(u) -> DirectionSample<float>` into LightSample (the point
/// where the sample's ray meets the disk's plane, apse::point_on_plane, as DiskLight does for the
/// maps).
template <class S> struct Wrapped {
    S s;
    vec3 o, center, normal;
    LightSample sample(const vec2& u) const { return apse::point_on_plane(s.sample(u), o, center, normal); }
};
template <class S> Wrapped<S> wrap(const S& s, const vec3& o, const Disk& L) {
    return Wrapped<S>{s, o, L.center, L.normal};
}

/// Per-kind factories: `(o, receiver normal, disk) -> sampler with sample(u) -> LightSample`.
struct AreaFactory {
    auto operator()(const vec3& o, const vec3&, const Disk& L) const {
        return wrap(apse::DiskAreaSampler<float>(o, L.center, L.normal, L.radius), o, L);
    }
};
struct GamitoFactory {  // Gamito's single shot (the paper's baseline), unbiased bookkeeping
    auto operator()(const vec3& o, const vec3&, const Disk& L) const {
        return wrap(apse::GamitoSingleShot<float>(o, L.center, L.normal, L.radius), o, L);
    }
};
template <class Map> struct MapFactory {
    auto operator()(const vec3& o, const vec3&, const Disk& L) const {
        return apse::DiskLight<Map>(o, L.center, L.normal, L.radius);
    }
};

struct TabulatedFactory {  // the paper's default: tabulated LD-radial (code `concentrictab`)
    apse::TabulationView view;
    auto operator()(const vec3& o, const vec3&, const Disk& L) const {
        return apse::DiskLight<apse::TabulatedLdRadialMap<float>>(o, L.center, L.normal, L.radius, view);
    }
};
/// Cosine-weighted over the tabulated LD-radial map (CosineWeighted): directions drawn ∝ the
/// receiver's clamped cosine; with a zero normal (the medium) it is the plain tabulated map.
struct CosineFactory {
    apse::TabulationView view;
    auto operator()(const vec3& o, const vec3& n, const Disk& L) const {
        return apse::DiskLight<apse::CosineWeighted<apse::TabulatedLdRadialMap<float>>>(o, L.center, L.normal,
                                                                                        L.radius, view, n);
    }
};
/// The shared table (apse::default_table(): built once, thread-safely; read-only while rendering).
inline apse::TabulationView tabulation_view() { return apse::default_table().view(); }

/// Sphere-light factories: `(o, receiver normal, sphere) -> sampler with sample(u) -> LightSample`
/// (apse::SphereLight gives the point on the sphere and the shadow-ray distance itself).
struct ConeFactory {  // pbrt-v4: uniform in the cone of directions the sphere subtends
    auto operator()(const vec3& o, const vec3&, const SphereEmitter& L) const {
        return apse_bench::ConeSampler<float, true>(o, L.center, L.radius);
    }
};
template <class Map> struct SphereMapFactory {
    auto operator()(const vec3& o, const vec3&, const SphereEmitter& L) const {
        return apse::SphereLight<Map>(o, L.center, L.radius);
    }
};
struct SphereTabulatedFactory {
    apse::TabulationView view;
    auto operator()(const vec3& o, const vec3&, const SphereEmitter& L) const {
        return apse::SphereLight<apse::TabulatedLdRadialMap<float>>(o, L.center, L.radius, view);
    }
};
/// Exactly ∝ the receiver's clamped cosine over the cap, also where the horizon cuts it.
struct SphereCosineFactory {
    apse::TabulationView view;
    auto operator()(const vec3& o, const vec3& n, const SphereEmitter& L) const {
        return apse::SphereLight<apse::CosineWeighted<apse::TabulatedLdRadialMap<float>>>(o, L.center, L.radius,
                                                                                          view, n);
    }
};

/// Calls f(factory) with the disk-light factory of kind k (one template instantiation per
/// kind); false (f not called) for a kind without one (cone).
template <class F> bool with_factory(Kind k, F&& f) {
    switch (k) {
    case Kind::area: f(AreaFactory{}); return true;
    case Kind::gamito: f(GamitoFactory{}); return true;
    case Kind::radial: f(MapFactory<apse::RadialMap<float>>{}); return true;
    case Kind::ld_radial: f(MapFactory<apse::LdRadialMap<float>>{}); return true;
    case Kind::parallel: f(MapFactory<apse::ParallelMap<float>>{}); return true;
    case Kind::tabulated: f(TabulatedFactory{tabulation_view()}); return true;
    case Kind::cosine: f(CosineFactory{tabulation_view()}); return true;
    case Kind::cone: return false;
    }
    return false;
}

/// Calls f(factory) with the sphere-light factory of kind k; false (f not called) for a kind
/// without one (area, Gamito).
template <class F> bool with_sphere_factory(Kind k, F&& f) {
    switch (k) {
    case Kind::cone: f(ConeFactory{}); return true;
    case Kind::radial: f(SphereMapFactory<apse::RadialMap<float>>{}); return true;
    case Kind::ld_radial: f(SphereMapFactory<apse::LdRadialMap<float>>{}); return true;
    case Kind::parallel: f(SphereMapFactory<apse::ParallelMap<float>>{}); return true;
    case Kind::tabulated: f(SphereTabulatedFactory{tabulation_view()}); return true;
    case Kind::cosine: f(SphereCosineFactory{tabulation_view()}); return true;
    case Kind::area:
    case Kind::gamito: return false;
    }
    return false;
}

}  // namespace demo
