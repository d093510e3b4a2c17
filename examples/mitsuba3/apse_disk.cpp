// apse in Mitsuba 3: a disk-light emitter plugin (`apse_disk`, scalar_rgb) that samples the disk
// uniformly in solid angle with apse's area-preserving maps.
// SPDX-License-Identifier: MIT
//
// Two ways to place the light:
//   * attached to a `disk` shape (recommended): {'type': 'disk', 'to_world': ...,
//     'emitter': {'type': 'apse_disk', 'radiance': ..., 'sampler': 'ld_radial'}}. The disk is then
//     visible to camera and BSDF rays, which call eval() and pdf_direction() (MIS). A to_world
//     with unequal or non-orthogonal axes makes the disk an ellipse: it is sampled as one
//     (project_ellipse) instead of as a disk. The geometry is read when the shape attaches the
//     emitter; a later change of the disk's to_world (mi.traverse) is not followed.
//   * standalone: {'type': 'apse_disk', 'center': [..], 'normal': [..], 'radius': r, ...}. No
//     ray can hit such a light (like Mitsuba's point and spot lights), so its direction samples
//     are flagged `delta`: integrators then weigh them 1 instead of applying MIS with BSDF
//     samples that could never find the light.
// Parameters: radiance (rgb; spatially varying textures are refused), twosided (bool, default
// false: emits towards +normal only, as Mitsuba's `area`), sampler (area | radial | ld_radial |
// parallel | tabulated_ld_radial | cosine_ld_radial | cosine_tabulated_ld_radial; default
// ld_radial). The cosine_* samplers weight the map by the receiver's cosine
// (apse::CosineWeighted, with the receiver's geometric normal: see receiver_normal).
// `sampler: area` attached to a disk calls the shape's own sampling exactly as Mitsuba's `area`
// emitter does, so it renders the same image bit for bit; standalone it uses apse's
// DiskAreaSampler.

#include <apse/apse.hpp>
#include <apse/baselines/area.hpp>

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

namespace apse_disk_detail {

using apse_plugin::gvec2;
using apse_plugin::gvec3;

/// The light's geometry: the planar ellipse {center + s u + t v : s² + t² <= 1} (a disk of
/// radius |u| when u and v are orthogonal and of equal length) and its emitting normal.
struct Geometry {
    gvec3 center{0.f}, u{0.f}, v{0.f}, normal{0.f, 0.f, 1.f};
    float radius = 0.f;  ///< > 0: a disk of this radius; 0: a general ellipse
    apse::DiskFrame<float> frame{};  ///< the disk's stored frame (radius > 0)
};

/// The spherical ellipse the light subtends at o (two-sided).
inline apse::SphericalEllipse<float> project(const Geometry &g, const gvec3 &o) {
    return g.radius > 0.f ? apse::project_disk(o, g.frame)
                          : apse::project_ellipse(o, g.center, g.u, g.v);
}

/// The normal the cosine-weighted samplers weight by (apse_plugin::receiver_normal), from the
/// receiver's geometric normal n: the planar ellipse's signed heights above the receiver's tangent
/// plane span h ± e, h = n·(c − o), e = sqrt((n·u)² + (n·v)²).
inline gvec3 receiver_normal(const Geometry &g, const gvec3 &o, const gvec3 &n) {
    const float nu = glm::dot(n, g.u), nv = glm::dot(n, g.v);
    return apse_plugin::receiver_normal(n, glm::dot(n, g.center - o), std::sqrt(nu * nu + nv * nv));
}

/// The one place that turns a sampler name into a sampler for the shading point o with the
/// geometric normal n (used by the cosine_* samplers only, through receiver_normal): calls
/// f(s) with s offering sample(u) -> apse::DirectionSample<float> and pdf(w) (solid angle), and
/// returns its result. `area` (uniform by area) needs a disk (g.radius > 0).
template <typename F>
auto with_sampler(ApseSampler kind, const Geometry &g, const gvec3 &o, const gvec3 &n, F &&f) {
    if (kind == ApseSampler::area) return f(apse::DiskAreaSampler<float>(o, g.frame));
    const gvec3 n_r = apse_plugin::cosine_weighted(kind) ? receiver_normal(g, o, n) : gvec3(0.f);
    return f(apse_plugin::sampler_of(kind, project(g, o), n_r));
}

}  // namespace apse_disk_detail

template <typename Float, typename Spectrum>
class ApseDiskLight final : public Emitter<Float, Spectrum> {
public:
    MI_IMPORT_BASE(Emitter, m_flags, m_shape, m_medium)
    MI_IMPORT_TYPES(Shape, Texture)
    static_assert(!dr::is_jit_v<Float> && !is_polarized_v<Spectrum>,
                  "apse_disk is a scalar, unpolarized plugin (registered for scalar_rgb)");

    using gvec2 = apse_disk_detail::gvec2;
    using gvec3 = apse_disk_detail::gvec3;

    ApseDiskLight(const Properties &props) : Base(props) {
        m_radiance = props.get_emissive_texture<Texture>("radiance", 1.f);
        if (m_radiance->is_spatially_varying())
            Throw("apse_disk: the radiance must be uniform (apse samples by solid angle)");
        m_twosided = props.get<bool>("twosided", false);
        m_sampler = apse_plugin::parse_sampler(props.get<std::string>("sampler", "ld_radial"), "apse_disk");
        if (props.has_property("radius")) {
            const ScalarPoint3f c = props.get<ScalarPoint3f>("center");
            const ScalarVector3f n = props.get<ScalarVector3f>("normal");
            const ScalarFloat r = props.get<ScalarFloat>("radius");
            if (!(r > 0.f) || !(dr::norm(n) > 0.f))
                Throw("apse_disk: needs radius > 0 and a non-zero normal");
            const ScalarVector3f nn = dr::normalize(n);
            const auto [s, t] = coordinate_system(nn);
            set_geometry(c, s * r, t * r, nn, r);
            m_standalone = true;
        }
        m_flags = m_standalone ? +EmitterFlags::Empty : +EmitterFlags::Surface;
    }

    void set_shape(Shape *shape) override {
        if (m_standalone)
            Throw("apse_disk: give either center/normal/radius or attach it to a disk shape");
        Base::set_shape(shape);
        if (shape->shape_type() != +ShapeType::Disk)
            Throw("apse_disk: can only be attached to a 'disk' shape");
        apse_plugin::ToWorldReader<ScalarAffineTransform4f> reader;
        shape->traverse(&reader);
        if (!reader.found) Throw("apse_disk: the disk shape did not expose its to_world");
        const ScalarAffineTransform4f &m = reader.value;
        const ScalarVector3f u = m * ScalarVector3f(1.f, 0.f, 0.f),
                             v = m * ScalarVector3f(0.f, 1.f, 0.f);
        // The shape's own normal (inverse transpose: honours flip_normals).
        const ScalarVector3f n = dr::normalize(m * ScalarNormal3f(0.f, 0.f, 1.f));
        const ScalarFloat lu = dr::norm(u), lv = dr::norm(v);
        // A disk when the axes are orthogonal and equally long (to float rounding of to_world).
        const bool disk = dr::abs(lu - lv) <= 1e-6f * lu && dr::abs(dr::dot(u, v)) <= 1e-6f * lu * lv;
        set_geometry(m * ScalarPoint3f(0.f), u, v, n, disk ? lu : 0.f);
    }

    void traverse(TraversalCallback *cb) override {
        Base::traverse(cb);
        cb->put("radiance", m_radiance, ParamFlags::Differentiable);
    }

    Spectrum eval(const SurfaceInteraction3f &si, Mask active) const override {
        Spectrum result = m_radiance->eval(si, active);
        if (!m_twosided) result = dr::select(Frame3f::cos_theta(si.wi) > 0.f, result, 0.f);
        return result;
    }

    std::pair<DirectionSample3f, Spectrum>
    sample_direction(const Interaction3f &it, const Point2f &sample, Mask active) const override {
        if (use_shape_sampling()) {
            // Mitsuba's own disk light: the shape samples a point by area.
            DirectionSample3f ds = m_shape->sample_direction(it, sample, active);
            active &= ds.pdf != 0.f;
            if (!m_twosided) active &= dr::dot(ds.d, ds.n) < 0.f;
            SurfaceInteraction3f si(ds, it.wavelengths);
            Spectrum spec = m_radiance->eval(si, active) / ds.pdf;
            ds.emitter = this;
            return { ds, dr::select(active, spec, 0.f) };
        }
        DirectionSample3f ds = dr::zeros<DirectionSample3f>();
        const gvec3 o = apse_plugin::to_glm(it.p);
        if (!active || !lit(o)) return { ds, 0.f };
        const apse::DirectionSample<float> s = apse_disk_detail::with_sampler(
            m_sampler, m_geom, o, apse_plugin::to_glm(it.n), [&](const auto &sampler) { return sampler.sample(gvec2(sample.x(), sample.y())); });
        // Where the ray meets the light's plane: the point the visibility ray is traced to.
        const apse::PointSample<float> hit = apse::point_on_plane(s, o, m_geom.center, m_geom.normal);
        if (!(hit.pdf > 0.f)) return { ds, 0.f };
        ds.d = Vector3f(s.direction.x, s.direction.y, s.direction.z);
        ds.dist = hit.distance;
        ds.p = Point3f(hit.point.x, hit.point.y, hit.point.z);
        ds.n = m_normal;
        ds.time = it.time;
        ds.pdf = s.pdf;
        ds.delta = m_standalone;
        ds.emitter = this;
        SurfaceInteraction3f si(ds, it.wavelengths);
        return { ds, m_radiance->eval(si, true) / s.pdf };
    }

    Float pdf_direction(const Interaction3f &it, const DirectionSample3f &ds, Mask active) const override {
        if (use_shape_sampling()) {
            Float dp = dr::dot(ds.d, ds.n);
            if (m_twosided) dp = -dr::abs(dp);
            active &= dp < 0.f;
            const Float value = m_shape->pdf_direction(it, ds, active);
            return dr::select(active, value, 0.f);
        }
        const gvec3 o = apse_plugin::to_glm(it.p);
        if (!active || !lit(o)) return 0.f;
        const gvec3 w = apse_plugin::to_glm(ds.d);
        return apse_disk_detail::with_sampler(m_sampler, m_geom, o, apse_plugin::to_glm(it.n),
                                              [&](const auto &sampler) { return sampler.pdf(w); });
    }

    Spectrum eval_direction(const Interaction3f &it, const DirectionSample3f &ds, Mask active) const override {
        Float dp = dr::dot(ds.d, ds.n);
        if (m_twosided) dp = -dr::abs(dp);
        active &= dp < 0.f;
        SurfaceInteraction3f si(ds, it.wavelengths);
        return dr::select(active, m_radiance->eval(si, active), 0.f);
    }

    std::pair<PositionSample3f, Float> sample_position(Float time, const Point2f &sample,
                                                       Mask active) const override {
        PositionSample3f ps;
        if (m_shape) {
            ps = m_shape->sample_position(time, sample, active);
        } else {
            const Point2f p = warp::square_to_uniform_disk_concentric(sample);
            ps = dr::zeros<PositionSample3f>();
            ps.p = Point3f(m_center + p.x() * m_u + p.y() * m_v);
            ps.n = m_normal;
            ps.uv = sample;
            ps.time = time;
            ps.pdf = 1.f / (dr::Pi<ScalarFloat> * dr::norm(dr::cross(m_u, m_v)));
            ps.delta = false;
        }
        return { ps, dr::select(active && ps.pdf > 0.f, dr::rcp(ps.pdf), 0.f) };
    }

    Float pdf_position(const PositionSample3f &ps, Mask active) const override {
        if (m_shape) return m_shape->pdf_position(ps, active);
        return dr::select(active, 1.f / (dr::Pi<ScalarFloat> * dr::norm(dr::cross(m_u, m_v))), 0.f);
    }

    std::pair<Ray3f, Spectrum> sample_ray(Float time, Float wavelength_sample, const Point2f &sample2,
                                          const Point2f &sample3, Mask active) const override {
        auto [ps, pos_weight] = sample_position(time, sample2, active);
        // Cosine-weighted direction about the normal; two-sided lights pick the side with the
        // first coordinate.
        Point2f u = sample3;
        Mask back = false;
        if (m_twosided) {
            back = u.x() >= .5f;
            u.x() = dr::select(back, 2.f * u.x() - 1.f, 2.f * u.x());
        }
        Vector3f local = warp::square_to_cosine_hemisphere(u);
        if (back) local.z() = -local.z();
        SurfaceInteraction3f si(ps, dr::zeros<Wavelength>());
        auto [wavelengths, wav_weight] = sample_wavelengths(si, wavelength_sample, active);
        si.time = time;
        si.wavelengths = wavelengths;
        const Spectrum weight = pos_weight * wav_weight * (m_twosided ? 2.f : 1.f) * dr::Pi<ScalarFloat>;
        return { si.spawn_ray(si.to_world(local)), weight };
    }

    std::pair<Wavelength, Spectrum> sample_wavelengths(const SurfaceInteraction3f &si, Float sample,
                                                       Mask active) const override {
        return m_radiance->sample_spectrum(si, math::sample_shifted<Wavelength>(sample), active);
    }

    ScalarBoundingBox3f bbox() const override {
        if (m_shape) return m_shape->bbox();
        const ScalarVector3f e = dr::sqrt(dr::square(m_u) + dr::square(m_v));
        return ScalarBoundingBox3f(m_center - e, m_center + e);
    }

    std::string to_string() const override {
        std::ostringstream oss;
        oss << "ApseDiskLight[sampler = " << apse_plugin::sampler_name(m_sampler) << ", twosided = " << m_twosided
            << ", center = " << m_center << ", normal = " << m_normal << ", ";
        if (m_geom.radius > 0.f) oss << "radius = " << m_geom.radius;
        else oss << "ellipse with semi-axes " << m_u << ", " << m_v;
        oss << (m_standalone ? ", standalone]" : ", attached to a disk shape]");
        return oss.str();
    }

    MI_DECLARE_CLASS(ApseDiskLight)

private:
    /// Area sampling of an attached shape goes through the shape, exactly as Mitsuba's `area`.
    bool use_shape_sampling() const { return m_sampler == ApseSampler::area && m_shape; }

    /// Does the light emit towards o? (two-sided: always; else o strictly in front.)
    bool lit(const gvec3 &o) const {
        return m_twosided || apse::disk_faces(o, m_geom.center, m_geom.normal);
    }

    void set_geometry(const ScalarPoint3f &c, const ScalarVector3f &u, const ScalarVector3f &v,
                      const ScalarVector3f &n, ScalarFloat radius) {
        m_center = c;
        m_u = u;
        m_v = v;
        m_normal = n;
        m_geom.center = apse_plugin::to_glm(c);
        m_geom.u = apse_plugin::to_glm(u);
        m_geom.v = apse_plugin::to_glm(v);
        m_geom.normal = apse_plugin::to_glm(n);
        m_geom.radius = radius;
        m_geom.frame = apse::DiskFrame<float>::make(m_geom.center, m_geom.normal, radius);
    }

    ref<Texture> m_radiance;
    bool m_twosided = false;
    bool m_standalone = false;
    ApseSampler m_sampler = ApseSampler::ld_radial;
    apse_disk_detail::Geometry m_geom;
    ScalarPoint3f m_center;
    ScalarVector3f m_u, m_v, m_normal;

    MI_TRAVERSE_CB(Base, m_radiance)
};

NAMESPACE_END(mitsuba)

// Register the scalar_rgb variant only (MI_EXPORT_PLUGIN would instantiate every variant of the
// wheel, JIT ones included, which cannot call this scalar code).
extern "C" MI_EXPORT void init_plugin(std::string_view name, mitsuba::PluginRegisterFn fn) {
    using Light = mitsuba::ApseDiskLight<float, mitsuba::Color<float, 3>>;
    fn(name, "scalar_rgb", Light::Type,
       [](void *, const mitsuba::Properties &p) -> mitsuba::ref<mitsuba::Object> { return new Light(p); });
}
