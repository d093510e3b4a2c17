// apse in Mitsuba 3: what the apse_disk and apse_sphere emitter plugins share — the names of the
// samplers, the map each name stands for (apse::RuntimeSampler), the receiver normal the
// cosine-weighted samplers weight by, and reading a shape's to_world.
// SPDX-License-Identifier: MIT
#pragma once

#include <apse/apse.hpp>
#include <apse/runtime_sampler.hpp>

#include <string>
#include <typeinfo>

#include <mitsuba/core/object.h>
#include <mitsuba/core/logger.h>

NAMESPACE_BEGIN(mitsuba)

/// How a plugin samples directions towards its light (the `sampler` parameter).
enum class ApseSampler {
    area, radial, ld_radial, parallel, tabulated_ld_radial, cosine_ld_radial, cosine_tabulated_ld_radial
};

namespace apse_plugin {

using gvec2 = glm::vec<2, float>;
using gvec3 = glm::vec<3, float>;

/// The `sampler` parameter's value for each ApseSampler, in enum order.
inline const char *sampler_name(ApseSampler kind) {
    static const char *names[] = { "area", "radial", "ld_radial", "parallel", "tabulated_ld_radial",
                                   "cosine_ld_radial", "cosine_tabulated_ld_radial" };
    return names[(int) kind];
}

/// The sampler called `name`; an unknown name is an error naming the plugin.
inline ApseSampler parse_sampler(const std::string &name, const char *plugin) {
    for (int k = 0; k <= (int) ApseSampler::cosine_tabulated_ld_radial; ++k)
        if (name == sampler_name(ApseSampler(k))) return ApseSampler(k);
    Throw("%s: unknown sampler \"%s\" (area, radial, ld_radial, parallel, tabulated_ld_radial, "
          "cosine_ld_radial, cosine_tabulated_ld_radial)", plugin, name);
}

/// The normal the cosine-weighted samplers weight by, from the receiver's geometric normal n
/// (Mitsuba's Interaction3f::n: not oriented towards the viewer, zero for medium interactions)
/// and the light's extent along n: its points' signed heights above the receiver's tangent plane
/// span [h − e, h + e]. Which side of the surface gathers light depends on the BSDF (one- or
/// two-sided, reflective or transmissive) and on the side it is seen from, which pdf_direction
/// is not told (integrators pass it a plain Interaction3f holding p and n only). So: the light
/// entirely on one side of the plane -> n oriented towards it (whatever side gathers, the whole
/// light is then above the horizon: the density is positive over all of it); the light
/// straddling the plane (either side may be the one that gathers), or n zero or NaN -> zero, the
/// plain map. A function of o, n and the light only, so sample_direction and pdf_direction
/// always pick the same density.
inline gvec3 receiver_normal(const gvec3 &n, float h, float e) {
    if (h > e) return n;
    if (-h > e) return -n;
    return gvec3(0.f);
}

/// The map a sampler name stands for (apse::MapKind; `area` is not a map: the plugins handle it
/// before, here it stands for ld_radial).
inline apse::MapKind map_kind(ApseSampler kind) {
    switch (kind) {
        case ApseSampler::radial: return apse::MapKind::radial;
        case ApseSampler::parallel: return apse::MapKind::parallel;
        case ApseSampler::tabulated_ld_radial:
        case ApseSampler::cosine_tabulated_ld_radial: return apse::MapKind::tabulated_ld_radial;
        case ApseSampler::area:
        case ApseSampler::ld_radial:
        case ApseSampler::cosine_ld_radial: break;
    }
    return apse::MapKind::ld_radial;
}

/// True for the samplers weighted by the receiver's cosine (apse::CosineWeighted over the map).
inline bool cosine_weighted(ApseSampler kind) {
    return kind == ApseSampler::cosine_ld_radial || kind == ApseSampler::cosine_tabulated_ld_radial;
}

/// The sampler `kind` names (any but `area`) of the spherical ellipse `e`, weighted by the
/// receiver normal `n_r` for the cosine_* samplers: apse's runtime sampler, which holds the map
/// chosen at run time (the tabulated maps read apse::default_table()).
inline apse::RuntimeSampler<float> sampler_of(ApseSampler kind, const apse::SphericalEllipse<float> &e,
                                              const gvec3 &n_r) {
    const apse::TabulationView table = apse::default_table().view();
    if (cosine_weighted(kind)) return apse::RuntimeSampler<float>(e, map_kind(kind), table, n_r);
    return apse::RuntimeSampler<float>(e, map_kind(kind), table);
}

/// A Mitsuba vector or point as a glm vector.
template <typename V> gvec3 to_glm(const V &p) { return gvec3(p.x(), p.y(), p.z()); }

/// Reads the `to_world` parameter a shape exposes through traverse().
template <typename Transform> class ToWorldReader final : public TraversalCallback {
public:
    bool found = false;
    Transform value;

protected:
    void put_value(std::string_view name, void *ptr, uint32_t, const std::type_info &type) override {
        if (name == "to_world" && type == typeid(Transform)) {
            value = *static_cast<const Transform *>(ptr);
            found = true;
        }
    }
    void put_object(std::string_view, Object *, uint32_t) override {}
};

}  // namespace apse_plugin

NAMESPACE_END(mitsuba)
