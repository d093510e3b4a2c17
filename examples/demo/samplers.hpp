// apse demo — one adapter over every disk-light sampler the demo compares.
// SPDX-License-Identifier: MIT
#pragma once

/// @file samplers.hpp
/// The samplers compared, each wrapped in a *factory* that builds the per-shading-point sampler
/// (the set-up a renderer does once per shading point) from the shading point, the receiver's
/// normal (zero in the medium, where there is no surface) and the light, and a uniform
/// `LightSample` result (apse::PointSample): direction, solid-angle pdf (0 = no sample: skip it),
/// point on the disk and distance to it.

#include <array>
#include <vector>

#include <apse/apse.hpp>
#include <apse/baselines/area.hpp>
#include <apse/baselines/gamito.hpp>

namespace demo {

using vec2 = glm::vec2;
using vec3 = glm::vec3;

/// A disk light: centre, normal (unit), radius, emitted radiance (two-sided, invisible).
struct Disk {
    vec3 center, normal;
    float radius, Le;
};

/// One light sample from a shading point: direction, pdf (solid angle; 0 = no sample), point on
/// the disk, distance to it.
using LightSample = apse::PointSample<float>;

enum class Kind { area, gamito, radial, ld_radial, parallel, tabulated, cosine };

inline const char* kind_name(Kind k) {
    switch (k) {
    case Kind::area: return "area";
    case Kind::gamito: return "Gamito";
    case Kind::radial: return "radial";
    case Kind::ld_radial: return "LD-radial";
    case Kind::parallel: return "parallel";
    case Kind::tabulated: return "tabulated";
    case Kind::cosine: return "cosine-weighted";
    }
    return "?";
}

/// The samplers of the comparison, in display order.
inline std::vector<Kind> all_kinds() {
    return {Kind::area, Kind::gamito, Kind::radial, Kind::ld_radial, Kind::parallel, Kind::tabulated, Kind::cosine};
}

/// Wraps a sampler with `sample(u) -> DirectionSample<float>` into LightSample (the point where
/// the sample's ray meets the disk's plane, apse::point_on_plane, the same for every sampler).
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
        return wrap(Map(apse::project_disk(o, L.center, L.normal, L.radius)), o, L);
    }
};

struct TabulatedFactory {  // the paper's default: tabulated LD-radial (code `concentrictab`)
    apse::TabulationView view;
    auto operator()(const vec3& o, const vec3&, const Disk& L) const {
        return wrap(apse::TabulatedLdRadialMap<float>(apse::project_disk(o, L.center, L.normal, L.radius), view),
                    o, L);
    }
};
/// Cosine-weighted over the tabulated LD-radial map (CosineWeighted): directions drawn ∝ the
/// receiver's clamped cosine; with a zero normal (the medium) it is the plain tabulated map.
struct CosineFactory {
    apse::TabulationView view;
    auto operator()(const vec3& o, const vec3& n, const Disk& L) const {
        const apse::TabulatedLdRadialMap<float> map(apse::project_disk(o, L.center, L.normal, L.radius), view);
        return wrap(apse::CosineWeighted<apse::TabulatedLdRadialMap<float>>(map, n), o, L);
    }
};
/// The shared table (apse::default_table(): built once, thread-safely; read-only while rendering).
inline apse::TabulationView tabulation_view() { return apse::default_table().view(); }

/// Calls f(factory) with the factory of kind k (one template instantiation per kind).
template <class F> void with_factory(Kind k, F&& f) {
    switch (k) {
    case Kind::area: f(AreaFactory{}); break;
    case Kind::gamito: f(GamitoFactory{}); break;
    case Kind::radial: f(MapFactory<apse::RadialMap<float>>{}); break;
    case Kind::ld_radial: f(MapFactory<apse::LdRadialMap<float>>{}); break;
    case Kind::parallel: f(MapFactory<apse::ParallelMap<float>>{}); break;
    case Kind::tabulated: f(TabulatedFactory{tabulation_view()}); break;
    case Kind::cosine: f(CosineFactory{tabulation_view()}); break;
    }
}

}  // namespace demo
