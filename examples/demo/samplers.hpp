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
#include <apse/runtime_sampler.hpp>

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
/// The apse samplers, chosen at run time as a scene file chooses them (apse::RuntimeSampler):
/// the map `map`, cosine-weighted over it when `cosine` (CosineWeighted: directions drawn ∝ the
/// receiver's clamped cosine; with a zero normal, in the medium, the plain map's samples).
struct MapChoice {
    apse::MapKind map;
    bool cosine;
    apse::TabulationView view;  ///< read by the tabulated maps only
};
struct MapFactory {
    MapChoice choice;
    auto operator()(const vec3& o, const vec3& n, const Disk& L) const {
        using Light = apse::DiskLight<apse::RuntimeSampler<float>>;
        return choice.cosine ? Light(o, L.center, L.normal, L.radius, choice.map, choice.view, n)
                             : Light(o, L.center, L.normal, L.radius, choice.map, choice.view);
    }
};
/// The shared table (apse::default_table(): built once, thread-safely; read-only while rendering).
inline apse::TabulationView tabulation_view() { return apse::default_table().view(); }

/// The apse sampler of kind k (radial, LD-radial, parallel, tabulated — the paper's default,
/// tabulated LD-radial, code `concentrictab` — or cosine-weighted over the tabulated one).
inline MapChoice map_choice(Kind k) {
    switch (k) {
    case Kind::radial: return {apse::MapKind::radial, false, tabulation_view()};
    case Kind::ld_radial: return {apse::MapKind::ld_radial, false, tabulation_view()};
    case Kind::parallel: return {apse::MapKind::parallel, false, tabulation_view()};
    case Kind::cosine: return {apse::MapKind::tabulated_ld_radial, true, tabulation_view()};
    default: return {apse::MapKind::tabulated_ld_radial, false, tabulation_view()};
    }
}

/// Sphere-light factories: `(o, receiver normal, sphere) -> sampler with sample(u) -> LightSample`
/// (apse::SphereLight gives the point on the sphere and the shadow-ray distance itself).
struct ConeFactory {  // pbrt-v4: uniform in the cone of directions the sphere subtends
    auto operator()(const vec3& o, const vec3&, const SphereEmitter& L) const {
        return apse_bench::ConeSampler<float, true>(o, L.center, L.radius);
    }
};
/// The apse samplers of sphere lights (apse::SphereLight over the runtime choice).
struct SphereMapFactory {
    MapChoice choice;
    auto operator()(const vec3& o, const vec3& n, const SphereEmitter& L) const {
        using Light = apse::SphereLight<apse::RuntimeSampler<float>>;
        return choice.cosine ? Light(o, L.center, L.radius, choice.map, choice.view, n)
                             : Light(o, L.center, L.radius, choice.map, choice.view);
    }
};

/// Calls f(factory) with the disk-light factory of kind k (one template instantiation for each
/// baseline, one for all the apse samplers); false (f not called) for a kind without one (cone).
template <class F> bool with_factory(Kind k, F&& f) {
    switch (k) {
    case Kind::area: f(AreaFactory{}); return true;
    case Kind::gamito: f(GamitoFactory{}); return true;
    case Kind::cone: return false;
    default: f(MapFactory{map_choice(k)}); return true;
    }
    return false;
}

/// Calls f(factory) with the sphere-light factory of kind k; false (f not called) for a kind
/// without one (area, Gamito).
template <class F> bool with_sphere_factory(Kind k, F&& f) {
    switch (k) {
    case Kind::cone: f(ConeFactory{}); return true;
    case Kind::area:
    case Kind::gamito: return false;
    default: f(SphereMapFactory{map_choice(k)}); return true;
    }
    return false;
}

}  // namespace demo
