// apse in Mitsuba 3: a sphere-light emitter plugin (`apse_sphere`, scalar_rgb) that samples the
// cap a sphere subtends with apse's maps (apse::SphereLight), uniformly in solid angle or, with
// the cosine_* samplers, weighted by the receiver's cosine.
// SPDX-License-Identifier: MIT
//
// Two ways to place the light:
//   * attached to a `sphere` shape (recommended): {'type': 'sphere', 'center': [..], 'radius': r,
//     'emitter': {'type': 'apse_sphere', 'radiance': ..., 'sampler': 'ld_radial'}}. The sphere is
//     then visible to camera and BSDF rays, which call eval() and pdf_direction() (MIS). The
//     geometry (centre and radius, from the shape's to_world) is read when the shape attaches
//     the emitter; a later change of the sphere's to_world (mi.traverse) is not followed.
//   * standalone: {'type': 'apse_sphere', 'center': [..], 'radius': r, ...}. No ray can hit such
//     a light (like Mitsuba's point and spot lights), so its direction samples are flagged
//     `delta`: integrators then weigh them 1 instead of applying MIS with BSDF samples that could
//     never find the light.
// The sphere emits outwards, as Mitsuba's `area` emitter on a sphere: seen from outside, all of
// the cap it subtends faces the viewer; shading points inside or on it receive no light samples.
// Parameters: radiance (rgb; spatially varying textures are refused), sampler (area | radial |
// ld_radial | parallel | tabulated_ld_radial | cosine_ld_radial | cosine_tabulated_ld_radial;
// default ld_radial). The cosine_* samplers weight the map by the receiver's cosine
// (apse::CosineWeighted, with the receiver's geometric normal: see receiver_normal).
// `sampler: area` calls the shape's own sampling exactly as Mitsuba's `area` emitter does (for a
// sphere that is uniform sampling of the cone it subtends), so it renders the same image bit for
// bit; it needs the shape.

#include <apse/apse.hpp>

#include "apse_plugin.hpp"

#include <cmath>
#include <string>

#include <mitsuba/core/properties.h>
#include <mitsuba/core/warp.h>
#include <mitsuba/render/emitter.h>
#include <mitsuba/render/interaction.h>
#include <mitsuba/render/medium.h>
#include <mitsuba/render/records.h>
#include <mitsuba/render/shape.h>
#include <mitsuba/render/texture.h>

NAMESPACE_BEGIN(mitsuba)

namespace apse_sphere_detail {

using apse_plugin::gvec2;
using apse_plugin::gvec3;

/// The normal the cosine-weighted samplers weight by (apse_plugin::receiver_normal), from the
/// receiver's geometric normal n: the sphere's signed heights above the receiver's tangent plane
/// span h ± r |n|, h = n·(c − o). The sphere entirely on one side of the plane is the same as
/// the cap it subtends entirely on that side of the horizon.
inline gvec3 receiver_normal(const gvec3 &c, float r, const gvec3 &o, const gvec3 &n) {
    return apse_plugin::receiver_normal(n, glm::dot(n, c - o), r * glm::length(n));
}

/// The one place that turns a sampler name (any but `area`) into apse::SphereLight's sampler
/// arguments for the shading point o with the geometric normal n (used by the cosine_* samplers
/// only, through receiver_normal): calls f(args...) with what SphereLight<RuntimeSampler<float>>
/// and sphere_light_pdf take after the radius (the map, the table, the receiver normal), and
/// returns its result.
template <typename F>
auto with_sampler(ApseSampler kind, const gvec3 &c, float r, const gvec3 &o, const gvec3 &n, F &&f) {
    const apse::TabulationView table = apse::default_table().view();
    if (apse_plugin::cosine_weighted(kind))
        return f(apse_plugin::map_kind(kind), table, receiver_normal(c, r, o, n));
    return f(apse_plugin::map_kind(kind), table);
}

}  // namespace apse_sphere_detail

template <typename Float, typename Spectrum>
class ApseSphereLight final : public Emitter<Float, Spectrum> {
public:
    MI_IMPORT_BASE(Emitter, m_flags, m_shape, m_medium)
    MI_IMPORT_TYPES(Shape, Texture)
    static_assert(!dr::is_jit_v<Float> && !is_polarized_v<Spectrum>,
                  "apse_sphere is a scalar, unpolarized plugin (registered for scalar_rgb)");

    using gvec2 = apse_sphere_detail::gvec2;
    using gvec3 = apse_sphere_detail::gvec3;

    ApseSphereLight(const Properties &props) : Base(props) {
        m_radiance = props.get_emissive_texture<Texture>("radiance", 1.f);
        if (m_radiance->is_spatially_varying())
            Throw("apse_sphere: the radiance must be uniform (apse samples by solid angle)");
        m_sampler = apse_plugin::parse_sampler(props.get<std::string>("sampler", "ld_radial"), "apse_sphere");
        if (props.has_property("radius")) {
            const ScalarPoint3f c = props.get<ScalarPoint3f>("center", ScalarPoint3f(0.f));
            const ScalarFloat r = props.get<ScalarFloat>("radius");
            if (!(r > 0.f) || !dr::isfinite(r)) Throw("apse_sphere: needs a finite radius > 0");
            if (m_sampler == ApseSampler::area)
                Throw("apse_sphere: sampler \"area\" is the sphere shape's own sampling: attach the "
                      "emitter to a sphere shape, or choose a map");
            set_geometry(c, r);
            m_standalone = true;
        }
        m_flags = m_standalone ? +EmitterFlags::Empty : +EmitterFlags::Surface;
    }

    void set_shape(Shape *shape) override {
        if (m_standalone)
            Throw("apse_sphere: give either center/radius or attach it to a sphere shape");
        Base::set_shape(shape);
        if (shape->shape_type() != +ShapeType::Sphere)
            Throw("apse_sphere: can only be attached to a 'sphere' shape");
        apse_plugin::ToWorldReader<ScalarAffineTransform4f> reader;
        shape->traverse(&reader);
        if (!reader.found) Throw("apse_sphere: the sphere shape did not expose its to_world");
        const ScalarAffineTransform4f &m = reader.value;
        const ScalarVector3f a = m * ScalarVector3f(1.f, 0.f, 0.f), b = m * ScalarVector3f(0.f, 1.f, 0.f),
                             e = m * ScalarVector3f(0.f, 0.f, 1.f);
        const ScalarFloat r = dr::norm(a);
        // Mitsuba's sphere refuses non-uniform scales and shears; check anyway (to float rounding).
        const ScalarFloat tol = 1e-6f * r;
        if (dr::abs(dr::norm(b) - r) > tol || dr::abs(dr::norm(e) - r) > tol || dr::abs(dr::dot(a, b)) > tol * r ||
            dr::abs(dr::dot(a, e)) > tol * r || dr::abs(dr::dot(b, e)) > tol * r)
            Throw("apse_sphere: the sphere's to_world is not a uniform scale");
        set_geometry(m * ScalarPoint3f(0.f), r);
        // flip_normals makes the sphere emit inwards, where apse's caps do not reach.
        const PositionSample3f ps = shape->sample_position(0.f, Point2f(.25f, .5f), true);
        if (!(dr::dot(ps.n, ps.p - m_center) > 0.f))
            Throw("apse_sphere: the sphere must emit outwards (flip_normals is not supported)");
    }

    void traverse(TraversalCallback *cb) override {
        Base::traverse(cb);
        cb->put("radiance", m_radiance, ParamFlags::Differentiable);
    }

    Spectrum eval(const SurfaceInteraction3f &si, Mask active) const override {
        return dr::select(Frame3f::cos_theta(si.wi) > 0.f, m_radiance->eval(si, active), 0.f);
    }

    std::pair<DirectionSample3f, Spectrum>
    sample_direction(const Interaction3f &it, const Point2f &sample, Mask active) const override {
        if (m_sampler == ApseSampler::area) {
            // Mitsuba's own sphere light: the shape samples the cone it subtends.
            DirectionSample3f ds = m_shape->sample_direction(it, sample, active);
            active &= dr::dot(ds.d, ds.n) < 0.f && ds.pdf != 0.f;
            SurfaceInteraction3f si(ds, it.wavelengths);
            Spectrum spec = m_radiance->eval(si, active) / ds.pdf;
            ds.emitter = this;
            return { ds, dr::select(active, spec, 0.f) };
        }
        DirectionSample3f ds = dr::zeros<DirectionSample3f>();
        if (!active) return { ds, 0.f };
        const gvec3 o = apse_plugin::to_glm(it.p);
        const apse::PointSample<float> s = apse_sphere_detail::with_sampler(
            m_sampler, m_c, m_radius, o, apse_plugin::to_glm(it.n), [&](const auto &...args) {
                return apse::SphereLight<apse::RuntimeSampler<float>>(o, m_c, m_radius, args...)
                    .sample(gvec2(sample.x(), sample.y()));
            });
        if (!(s.pdf > 0.f)) return { ds, 0.f };
        ds.d = Vector3f(s.direction.x, s.direction.y, s.direction.z);
        ds.dist = s.distance;
        ds.p = Point3f(s.point.x, s.point.y, s.point.z);
        ds.n = dr::normalize(ds.p - m_center);
        ds.time = it.time;
        ds.pdf = s.pdf;
        ds.delta = m_standalone;
        ds.emitter = this;
        SurfaceInteraction3f si(ds, it.wavelengths);
        return { ds, m_radiance->eval(si, true) / s.pdf };
    }

    Float pdf_direction(const Interaction3f &it, const DirectionSample3f &ds, Mask active) const override {
        if (m_sampler == ApseSampler::area) {
            active &= dr::dot(ds.d, ds.n) < 0.f;
            const Float value = m_shape->pdf_direction(it, ds, active);
            return dr::select(active, value, 0.f);
        }
        if (!active) return 0.f;
        const gvec3 o = apse_plugin::to_glm(it.p), w = apse_plugin::to_glm(ds.d);
        return apse_sphere_detail::with_sampler(
            m_sampler, m_c, m_radius, o, apse_plugin::to_glm(it.n), [&](const auto &...args) {
                return apse::sphere_light_pdf<apse::RuntimeSampler<float>>(o, m_c, m_radius, w, args...);
            });
    }

    Spectrum eval_direction(const Interaction3f &it, const DirectionSample3f &ds, Mask active) const override {
        active &= dr::dot(ds.d, ds.n) < 0.f;
        SurfaceInteraction3f si(ds, it.wavelengths);
        return dr::select(active, m_radiance->eval(si, active), 0.f);
    }

    std::pair<PositionSample3f, Float> sample_position(Float time, const Point2f &sample,
                                                       Mask active) const override {
        PositionSample3f ps;
        if (m_shape) {
            ps = m_shape->sample_position(time, sample, active);
        } else {
            const Vector3f d = warp::square_to_uniform_sphere(sample);
            ps = dr::zeros<PositionSample3f>();
            ps.p = m_center + m_radius * d;
            ps.n = d;
            ps.uv = sample;
            ps.time = time;
            ps.pdf = 1.f / (4.f * dr::Pi<ScalarFloat> * m_radius * m_radius);
            ps.delta = false;
        }
        return { ps, dr::select(active && ps.pdf > 0.f, dr::rcp(ps.pdf), 0.f) };
    }

    Float pdf_position(const PositionSample3f &ps, Mask active) const override {
        if (m_shape) return m_shape->pdf_position(ps, active);
        return dr::select(active, 1.f / (4.f * dr::Pi<ScalarFloat> * m_radius * m_radius), 0.f);
    }

    std::pair<Ray3f, Spectrum> sample_ray(Float time, Float wavelength_sample, const Point2f &sample2,
                                          const Point2f &sample3, Mask active) const override {
        auto [ps, pos_weight] = sample_position(time, sample2, active);
        // Cosine-weighted direction about the outward normal.
        const Vector3f local = warp::square_to_cosine_hemisphere(sample3);
        SurfaceInteraction3f si(ps, dr::zeros<Wavelength>());
        auto [wavelengths, wav_weight] = sample_wavelengths(si, wavelength_sample, active);
        si.time = time;
        si.wavelengths = wavelengths;
        return { si.spawn_ray(si.to_world(local)), pos_weight * wav_weight * dr::Pi<ScalarFloat> };
    }

    std::pair<Wavelength, Spectrum> sample_wavelengths(const SurfaceInteraction3f &si, Float sample,
                                                       Mask active) const override {
        return m_radiance->sample_spectrum(si, math::sample_shifted<Wavelength>(sample), active);
    }

    ScalarBoundingBox3f bbox() const override {
        if (m_shape) return m_shape->bbox();
        return ScalarBoundingBox3f(m_center - m_radius, m_center + m_radius);
    }

    std::string to_string() const override {
        std::ostringstream oss;
        oss << "ApseSphereLight[sampler = " << apse_plugin::sampler_name(m_sampler) << ", center = " << m_center
            << ", radius = " << m_radius << (m_standalone ? ", standalone]" : ", attached to a sphere shape]");
        return oss.str();
    }

    MI_DECLARE_CLASS(ApseSphereLight)

private:
    void set_geometry(const ScalarPoint3f &c, ScalarFloat r) {
        m_center = c;
        m_radius = r;
        m_c = apse_plugin::to_glm(c);
    }

    ref<Texture> m_radiance;
    bool m_standalone = false;
    ApseSampler m_sampler = ApseSampler::ld_radial;
    ScalarPoint3f m_center;
    ScalarFloat m_radius = 0.f;
    gvec3 m_c{0.f};  ///< m_center for apse

    MI_TRAVERSE_CB(Base, m_radiance)
};

NAMESPACE_END(mitsuba)

// Register the scalar_rgb variant only (MI_EXPORT_PLUGIN would instantiate every variant of the
// wheel, JIT ones included, which cannot call this scalar code).
extern "C" MI_EXPORT void init_plugin(std::string_view name, mitsuba::PluginRegisterFn fn) {
    using Light = mitsuba::ApseSphereLight<float, mitsuba::Color<float, 3>>;
    fn(name, "scalar_rgb", Light::Type,
       [](void *, const mitsuba::Properties &p) -> mitsuba::ref<mitsuba::Object> { return new Light(p); });
}
