// apse in Mitsuba 3: what the apse_disk and apse_sphere emitter plugins share — the names of the
// samplers, the map each name stands for, the receiver normal the cosine-weighted samplers weight
// by, and reading a shape's to_world.
// SPDX-License-Identifier: MIT
#pragma once

#include <apse/apse.hpp>

#include <string>
#include <type_traits>
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

/// A map type, passed to the callbacks below.
template <class Map> struct MapType { using type = Map; };

/// Calls f(MapType<Map>{}, std::bool_constant<cosine>{}) for the map `kind` names and whether
/// it is weighted by the receiver's cosine (apse::CosineWeighted over Map), and returns its
/// result. `area` is not a map: the plugins handle it before; here it stands for ld_radial.
template <class F> auto with_map(ApseSampler kind, F &&f) {
    switch (kind) {
        case ApseSampler::radial: return f(MapType<apse::RadialMap<float>>{}, std::false_type{});
        case ApseSampler::parallel: return f(MapType<apse::ParallelMap<float>>{}, std::false_type{});
        case ApseSampler::tabulated_ld_radial:
            return f(MapType<apse::TabulatedLdRadialMap<float>>{}, std::false_type{});
        case ApseSampler::cosine_ld_radial: return f(MapType<apse::LdRadialMap<float>>{}, std::true_type{});
        case ApseSampler::cosine_tabulated_ld_radial:
            return f(MapType<apse::TabulatedLdRadialMap<float>>{}, std::true_type{});
        case ApseSampler::area:
        case ApseSampler::ld_radial: break;
    }
    return f(MapType<apse::LdRadialMap<float>>{}, std::false_type{});
}

/// Calls f(args...) with what a Map takes after its ellipse — the table for the tabulated maps
/// (apse::default_table()), nothing for the others — and returns its result.
template <class Map, class F> auto with_map_args(F &&f) {
    if constexpr (std::is_same_v<Map, apse::TabulatedLdRadialMap<float>> ||
                  std::is_same_v<Map, apse::TabulatedMap<float>>)
        return f(apse::default_table().view());
    else
        return f();
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
