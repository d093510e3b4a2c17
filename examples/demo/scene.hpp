// apse demo — the four scenes and their per-pixel estimators (a tiny ray tracer).
// SPDX-License-Identifier: MIT
#pragma once

/// @file scene.hpp
/// Scenes (y is up; the light is invisible to camera rays; direct lighting only):
///  1. `plane`  — the talk's disk light perpendicular to a diffuse ground plane;
///  2. `medium` — the talk's disk light inside a homogeneous medium (single scattering along
///     camera rays, equiangular distance sampling: the same for every sampler);
///  3. `spheres` — the authors' scene: three diffuse spheres of radius 2 on a plane, a
///     two-sided disk light of radius 3 at (1, 3, 4);
///  4. `sphere` — a sphere light sunk a little into a diffuse ground plane, so that every ground
///     point sees it cut by its horizon, and a diffuse ball beside it casting a shadow. The
///     emitter blocks camera rays (pictures draw it white; its pixels are 0 in the images).
/// One camera ray per pixel through its centre, so the pixel value is a well-defined integral
/// over the light only (scene 1 has it in closed form: plane_radiance_exact; scene 4 where
/// nothing occludes the light: sphere_radiance_exact).

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <type_traits>
#include <vector>

#include "points.hpp"
#include "samplers.hpp"

namespace demo {

struct Sphere {
    vec3 center;
    float radius;
};

enum class SceneType { plane, medium, spheres, sphere_light };

struct Scene {
    std::string name, title, label;      // label: the convergence plot's panel
    SceneType type;
    std::vector<Kind> kinds;             // the samplers compared, the first is the reference
    Disk light{};                        // scenes 1–3
    SphereEmitter lamp{};                // scene 4
    vec3 eye, look_at;
    float fov_deg;
    float albedo = 0.8f;
    std::vector<Sphere> spheres;         // scenes 3 and 4 (diffuse, occluders)
    float sigma_s = 0, sigma_t = 0;      // scene 2: homogeneous medium inside a box
    vec3 box_min{0.0f}, box_max{0.0f};
    vec3 tint{1.0f};                     // light colour for display only
    vec2 inset{0.5f};                    // centre of the zoomed inset, in [0,1]^2 of the image
};

inline std::vector<Scene> make_scenes() {
    std::vector<Scene> s(4);
    for (int i = 0; i < 3; ++i) s[i].kinds = disk_kinds();
    s[0].name = s[0].label = "plane";
    s[0].title = "Disk light perpendicular to a ground plane";
    s[0].type = SceneType::plane;
    s[0].light = {vec3(0.0f, 1.05f, 0.0f), glm::normalize(vec3(1.0f, 0.0f, 0.35f)), 1.0f, 6.0f};
    s[0].eye = vec3(0.3f, 3.2f, 5.5f);
    s[0].look_at = vec3(0.0f, 0.2f, 0.0f);
    s[0].fov_deg = 50.0f;
    s[0].tint = vec3(1.0f, 0.9f, 0.75f);
    s[0].inset = vec2(0.5f, 0.6f);

    s[1].name = s[1].label = "medium";
    s[1].title = "Disk light inside a homogeneous medium";
    s[1].type = SceneType::medium;
    s[1].light = {vec3(0.0f), glm::normalize(vec3(1.0f, 0.25f, 0.5f)), 1.0f, 12.0f};
    s[1].eye = vec3(0.0f, 0.6f, 5.0f);
    s[1].look_at = vec3(0.0f, 0.0f, 0.0f);
    s[1].fov_deg = 45.0f;
    s[1].sigma_s = 0.25f;
    s[1].sigma_t = 0.3f;
    s[1].box_min = vec3(-3.0f);
    s[1].box_max = vec3(3.0f);
    s[1].tint = vec3(0.8f, 0.9f, 1.0f);
    s[1].inset = vec2(0.55f, 0.5f);

    s[2].name = s[2].label = "spheres";
    s[2].title = "Spheres (after the authors' scene)";
    s[2].type = SceneType::spheres;
    s[2].light = {vec3(1.0f, 3.0f, 4.0f), glm::normalize(vec3(0.0f, -1.0f, -1.0f)), 3.0f, 1.5f};
    s[2].spheres = {{vec3(-4.0f, 2.0f, -0.5f), 2.0f}, {vec3(1.0f, 2.0f, -3.0f), 2.0f}, {vec3(6.0f, 2.0f, -0.5f), 2.0f}};
    s[2].eye = vec3(1.0f, 16.0f, 17.0f);
    s[2].look_at = vec3(1.0f, 0.0f, -3.0f);
    s[2].fov_deg = 50.0f;
    s[2].tint = vec3(1.0f, 0.95f, 0.85f);
    s[2].inset = vec2(0.45f, 0.8f);

    s[3].name = "sphere";
    s[3].label = "sphere light";
    s[3].title = "Sphere light cut by the horizon";
    s[3].type = SceneType::sphere_light;
    s[3].kinds = sphere_kinds();
    s[3].lamp = {vec3(0.0f, 0.7f, 0.0f), 1.0f, 2.0f};  // 0.3 below the ground
    s[3].spheres = {{vec3(1.5f, 0.35f, 0.7f), 0.35f}};
    s[3].eye = vec3(-0.6f, 4.2f, 5.0f);
    s[3].look_at = vec3(0.6f, 0.0f, 0.1f);
    s[3].fov_deg = 50.0f;
    s[3].tint = vec3(1.0f, 0.85f, 0.7f);
    s[3].inset = vec2(0.78f, 0.62f);  // the ball's penumbra and unoccluded ground beside it
    return s;
}

/// Pinhole camera ray through the centre of pixel (x, y) of a w × h image.
inline void camera_ray(const Scene& s, int x, int y, int w, int h, vec3& o, vec3& d) {
    const vec3 fwd = glm::normalize(s.look_at - s.eye);
    const vec3 right = glm::normalize(glm::cross(fwd, vec3(0.0f, 1.0f, 0.0f)));
    const vec3 up = glm::cross(right, fwd);
    const float t = std::tan(0.5f * s.fov_deg * 3.14159265f / 180.0f);
    const float sx = (2.0f * (static_cast<float>(x) + 0.5f) / static_cast<float>(w) - 1.0f) * t *
                     static_cast<float>(w) / static_cast<float>(h);
    const float sy = (1.0f - 2.0f * (static_cast<float>(y) + 0.5f) / static_cast<float>(h)) * t;
    o = s.eye;
    d = glm::normalize(fwd + sx * right + sy * up);
}

/// Nearest positive hit of the ray with a sphere (or -1).
inline float hit_sphere(const Sphere& sp, const vec3& o, const vec3& d) {
    const vec3 oc = o - sp.center;
    const float b = glm::dot(oc, d), c = glm::dot(oc, oc) - sp.radius * sp.radius;
    const float disc = b * b - c;
    if (disc < 0.0f) return -1.0f;
    const float q = std::sqrt(disc);
    const float t0 = -b - q;
    if (t0 > 1e-4f) return t0;
    const float t1 = -b + q;
    return t1 > 1e-4f ? t1 : -1.0f;
}

/// Distance to the nearest surface (ground y = 0 and the spheres; 1e30 if none) with its normal
/// and whether it is the ground.
inline float nearest_surface(const Scene& s, const vec3& o, const vec3& d, vec3& n, bool& ground) {
    float best = 1e30f;
    ground = false;
    if (d.y < 0.0f && o.y > 0.0f) {
        best = -o.y / d.y;
        n = vec3(0.0f, 1.0f, 0.0f);
        ground = true;
    }
    for (const Sphere& sp : s.spheres) {
        const float t = hit_sphere(sp, o, d);
        if (t > 0.0f && t < best) {
            best = t;
            n = glm::normalize(o + t * d - sp.center);
            ground = false;
        }
    }
    return best;
}

/// True if the camera ray meets scene 4's emitter before any surface.
inline bool hits_emitter_first(const Scene& s, const vec3& o, const vec3& d) {
    if (s.type != SceneType::sphere_light) return false;
    vec3 n;
    bool ground;
    const float t = hit_sphere({s.lamp.center, s.lamp.radius}, o, d);
    return t > 0.0f && t < nearest_surface(s, o, d, n, ground);
}

/// Nearest surface hit: point, normal and whether it is the ground; false if the ray meets
/// nothing (or scene 4's emitter first).
inline bool hit_surface(const Scene& s, const vec3& o, const vec3& d, vec3& p, vec3& n, bool& ground) {
    const float best = nearest_surface(s, o, d, n, ground);
    if (best >= 1e30f || hits_emitter_first(s, o, d)) return false;
    p = o + best * d;
    return true;
}

/// True if nothing blocks the segment from p (at or above the ground) along d up to distance
/// dist: the spheres, and the ground for a segment ending below it (the part of scene 4's
/// emitter under the ground; every other light is above it).
inline bool unoccluded(const Scene& s, const vec3& p, const vec3& d, float dist) {
    if (p.y + dist * d.y < 0.0f) return false;
    for (const Sphere& sp : s.spheres) {
        const float t = hit_sphere(sp, p, d);
        if (t > 0.0f && t < dist) return false;
    }
    return true;
}

/// Closed-form irradiance vector J(p) = ∫_disk w dw (solid angle, unit Le) of a disk (centre c,
/// unit normal n, radius r) at p, so that the irradiance on a surface of normal m, with the
/// whole disk above its horizon, is Le m·J. With v = p − c, h = |v·n|, q = v − (v·n)n,
/// ρ = |q|, S = h² + ρ² + r², Q = sqrt(S² − 4ρ²r²) (derived from ∫ dA/d⁴ and ∫ (x − p)/d⁴ dA
/// over the disk, both elementary in polar coordinates about the foot point):
///   normal part  (π/2)(1 − (h² + ρ² − r²)/Q) = 2π r² h² / (Q (Q + h² + ρ² − r²)), towards the plane;
///   radial part  (π h/(2ρ))(S/Q − 1) = 2π h ρ r² / (Q (S + Q)), towards the axis.
/// Checked against quadrature by plane_reference_selfcheck().
inline glm::dvec3 disk_irradiance_vector(const glm::dvec3& p, const glm::dvec3& c, const glm::dvec3& n, double r) {
    const double pi = 3.14159265358979323846;
    const glm::dvec3 v = p - c;
    const double vn = glm::dot(v, n), h = std::fabs(vn);
    const glm::dvec3 q = v - vn * n;
    const double rho2 = glm::dot(q, q), r2 = r * r;
    const double S = h * h + rho2 + r2;
    const double Q = std::sqrt(std::max(S * S - 4.0 * rho2 * r2, 0.0));
    const double m = h * h + rho2 - r2;
    const double jn = m >= 0.0 ? 2.0 * pi * r2 * h * h / (Q * (Q + m)) : 0.5 * pi * (1.0 - m / Q);
    const double jr_over_rho = 2.0 * pi * h * r2 / (Q * (S + Q));
    return -(vn >= 0.0 ? 1.0 : -1.0) * jn * n - jr_over_rho * q;
}

/// Scene 1's exact pixel value at the ground point p: (albedo/π) Le up·J(p).
inline double plane_radiance_exact(const Scene& s, const glm::dvec3& p) {
    const glm::dvec3 J = disk_irradiance_vector(p, glm::dvec3(s.light.center), glm::dvec3(s.light.normal),
                                                s.light.radius);
    return s.albedo / 3.14159265358979323846 * s.light.Le * std::max(J.y, 0.0);
}

/// Max relative error of disk_irradiance_vector·up against a 600 × 600 midpoint quadrature
/// over the disk at a few ground points (expected ~1e-5: the quadrature's error).
inline double plane_reference_selfcheck(const Scene& s) {
    const glm::dvec3 c(s.light.center), n(s.light.normal);
    const double r = s.light.radius, pi = 3.14159265358979323846;
    const glm::dvec3 e1 = glm::normalize(glm::cross(n, std::fabs(n.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0)));
    const glm::dvec3 e2 = glm::cross(n, e1);
    const glm::dvec3 pts[] = {{0.3, 0, 0.2}, {1.5, 0, -0.7}, {-2.0, 0, 1.0}, {0.05, 0, 3.0}, {4, 0, 4}};
    double worst = 0.0;
    const int N = 600;
    for (const glm::dvec3& p : pts) {
        double sum = 0.0;
        for (int i = 0; i < N; ++i)
            for (int j = 0; j < N; ++j) {
                const double rr = r * std::sqrt((i + 0.5) / N), ph = 2.0 * pi * (j + 0.5) / N;
                const glm::dvec3 x = c + rr * std::cos(ph) * e1 + rr * std::sin(ph) * e2;
                const glm::dvec3 w = x - p;
                const double d2 = glm::dot(w, w);
                sum += std::max(w.y, 0.0) * std::fabs(glm::dot(w, n)) / (d2 * d2);
            }
        const double quad = sum * pi * r * r / (double(N) * N);
        const double exact = disk_irradiance_vector(p, c, n, r).y;
        worst = std::max(worst, std::fabs(quad - exact) / exact);
    }
    return worst;
}

/// Irradiance at p on a surface of unit normal n from a sphere (centre c, radius r) of unit
/// radiance, E = ∫_cap max(0, n·ω) dω (solid angle), the cap cut by the horizon where it crosses
/// it; 0 for p inside or on the sphere. With d = |c − p|, sin σ = r/d (the cap's half-angle σ)
/// and cos θ = n·(c − p)/d: π sin²σ cos θ while the whole cap is above the horizon (cos θ ≥
/// sin σ), 0 below it (cos θ ≤ −sin σ), and between them the classical form factor of a
/// differential area to a sphere cut by its plane (as in Lagarde & de Rousiers 2014, "Moving
/// Frostbite to PBR", area lights): with x = cot σ, y = −x cot θ,
///   E = (cos θ acos y − x sin θ √(1 − y²)) sin²σ + atan(sin θ √(1 − y²) / x).
/// Checked against quadrature by sphere_reference_selfcheck().
inline double sphere_irradiance(const glm::dvec3& p, const glm::dvec3& n, const glm::dvec3& c, double r) {
    const double pi = 3.14159265358979323846;
    const glm::dvec3 v = c - p;
    const double d = std::sqrt(glm::dot(v, v));
    if (!(d > r)) return 0.0;
    const double sin2s = (r / d) * (r / d), cos_t = glm::dot(n, v) / d;
    if (cos_t * cos_t >= sin2s) return cos_t > 0.0 ? pi * sin2s * cos_t : 0.0;
    const double sin_t = std::sqrt(std::max(1.0 - cos_t * cos_t, 0.0));
    const double x = std::sqrt((d - r) * (d + r)) / r;
    const double y = std::clamp(-x * cos_t / sin_t, -1.0, 1.0);
    const double sy = sin_t * std::sqrt(std::max(1.0 - y * y, 0.0));
    return std::max((cos_t * std::acos(y) - x * sy) * sin2s + std::atan2(sy, x), 0.0);
}

/// True if scene 4's closed form is its pixel value at the ground point p: every occluder is
/// entirely behind the light seen from p, or its cone of directions from p does not overlap the
/// light's (then nothing but the horizon cuts the light's cap).
inline bool sphere_reference_is_exact(const Scene& s, const glm::dvec3& p) {
    const glm::dvec3 vl = glm::dvec3(s.lamp.center) - p;
    const double dl = std::sqrt(glm::dot(vl, vl));
    if (!(dl > s.lamp.radius)) return true;  // no light either way
    const double al = std::asin(s.lamp.radius / dl);
    for (const Sphere& sp : s.spheres) {
        const glm::dvec3 vo = glm::dvec3(sp.center) - p;
        const double d_occ = std::sqrt(glm::dot(vo, vo));
        if (d_occ - sp.radius > dl + s.lamp.radius) continue;  // behind the light
        const double ao = std::asin(std::min(sp.radius / d_occ, 1.0));
        const double between = std::acos(std::clamp(glm::dot(vl, vo) / (dl * d_occ), -1.0, 1.0));
        if (between <= al + ao + 1e-6) return false;
    }
    return true;
}

/// Scene 4's exact pixel value at the ground point p where nothing occludes the light:
/// (albedo/π) Le E(p).
inline double sphere_radiance_exact(const Scene& s, const glm::dvec3& p) {
    return s.albedo / 3.14159265358979323846 * s.lamp.Le *
           sphere_irradiance(p, glm::dvec3(0, 1, 0), glm::dvec3(s.lamp.center), s.lamp.radius);
}

/// Max relative error of sphere_irradiance against a 600 × 600 midpoint quadrature over the
/// cap (in cos θ' and φ about its axis: dω = d cos θ' dφ) for receivers with the cap above,
/// cut by and mostly below their horizon (~1e-7: the quadrature's error, from the cells the
/// horizon's kink crosses).
inline double sphere_reference_selfcheck(const Scene& s) {
    const double pi = 3.14159265358979323846, r = s.lamp.radius;
    const glm::dvec3 c(s.lamp.center);
    struct Receiver {
        glm::dvec3 p, n;
    };
    const Receiver rs[] = {{{1.5, 0, 0.4}, {0, 1, 0}},   {{-3.0, 0, 2.0}, {0, 1, 0}},
                           {{0.2, 0, 5.0}, {0, 1, 0}},   {{0.0, 3.0, 0.0}, {0, -1, 0}},
                           {{2.0, 0.5, 1.0}, glm::normalize(glm::dvec3(-1, 0.2, 0.3))},
                           {{2.0, 0.5, 1.0}, glm::normalize(glm::dvec3(0.2, 1, 0.2))}};
    double worst = 0.0;
    const int N = 600;
    for (const Receiver& q : rs) {
        const glm::dvec3 v = c - q.p;
        const double d = std::sqrt(glm::dot(v, v));
        const glm::dvec3 a = v / d;
        const glm::dvec3 e1 = glm::normalize(glm::cross(a, std::fabs(a.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0)));
        const glm::dvec3 e2 = glm::cross(a, e1);
        const double cos_s = std::sqrt((d - r) * (d + r)) / d;
        double sum = 0.0;
        for (int i = 0; i < N; ++i)
            for (int j = 0; j < N; ++j) {
                const double u = cos_s + (1.0 - cos_s) * (i + 0.5) / N, ph = 2.0 * pi * (j + 0.5) / N;
                const double sn = std::sqrt(std::max(1.0 - u * u, 0.0));
                const glm::dvec3 w = u * a + sn * std::cos(ph) * e1 + sn * std::sin(ph) * e2;
                sum += std::max(glm::dot(q.n, w), 0.0);
            }
        const double quad = sum * (1.0 - cos_s) * 2.0 * pi / (double(N) * N);
        const double exact = sphere_irradiance(q.p, q.n, c, r);
        worst = std::max(worst, std::fabs(quad - exact) / exact);
    }
    return worst;
}

/// Ray–box slab test: the [t0, t1] of the ray inside the box (false if it misses).
inline bool box_interval(const vec3& lo, const vec3& hi, const vec3& o, const vec3& d, float& t0, float& t1) {
    t0 = 0.0f;
    t1 = 1e30f;
    for (int a = 0; a < 3; ++a) {
        const float inv = 1.0f / d[a];
        float ta = (lo[a] - o[a]) * inv, tb = (hi[a] - o[a]) * inv;
        if (ta > tb) std::swap(ta, tb);
        t0 = std::max(t0, ta);
        t1 = std::min(t1, tb);
    }
    return t1 > t0;
}

/// True if a shading point at p can receive light from `light`: outside a sphere light (a
/// point inside or on it sees no cap); every point for a disk.
inline bool outside_light(const Disk&, const vec3&) { return true; }
inline bool outside_light(const SphereEmitter& L, const vec3& p) { return glm::length(p - L.center) > L.radius; }

/// Single scattering along the camera ray (o, d) in scene 2's medium: the running means of
/// shade_pixel.
template <class Factory>
void shade_medium(const Scene& s, const Factory& make, const vec3& o, const vec3& d, const PixelPoints& pts,
                  const int* marks, int nmarks, float* out) {
    const float inv_pi = 0.31830988618f;
    double sum = 0.0;
    int mark = 0;
    const int n = marks[nmarks - 1];
    float t0, t1;
    const bool inside = box_interval(s.box_min, s.box_max, o, d, t0, t1);
    // equiangular sampling of the distance about the light's centre, pdf ∝ 1/(D^2 + (t − tc)^2), with
    // D the ray's distance from the centre but at least the light's radius: the in-scattered
    // light is flat within about a radius of the disk and falls as 1/distance^2 beyond, which
    // D = radius matches. (With D the bare distance, rays passing within a small D of the centre
    // put their samples within ~D of it, and the estimate's variance grows as 1/D: a speck of
    // dark and bright pixels around the light's centre at 16 spp, whatever the light sampler.)
    const float tc = glm::dot(s.light.center - o, d);
    const float D = std::max(glm::length(o + tc * d - s.light.center), s.light.radius);
    const float a0 = std::atan((t0 - tc) / D), a1 = std::atan((t1 - tc) / D);
    const float phase = 0.25f * inv_pi;
    for (int i = 0; i < n; ++i) {
        if (inside) {
            float u1, u2;
            pts.light(static_cast<std::uint32_t>(i), u1, u2);
            const float ang = a0 + pts.extra(static_cast<std::uint32_t>(i)) * (a1 - a0);
            const float off = D * std::tan(ang);
            const float t = tc + off;
            const float pdf_t = D / ((a1 - a0) * (D * D + off * off));
            const vec3 p = o + t * d;
            const LightSample ls = make(p, vec3(0.0f), s.light).sample(vec2(u1, u2));  // no surface
            if (ls.pdf > 0.0f) {
                const float tr = std::exp(-s.sigma_t * (t - t0)) * std::exp(-s.sigma_t * ls.distance);
                sum += static_cast<double>(s.sigma_s * tr * phase * s.light.Le / (pdf_t * ls.pdf));
            }
        }
        if (i + 1 == marks[mark]) out[mark++] = static_cast<float>(sum / (i + 1));
    }
}

/// Direct lighting from `light` (a Disk or a SphereEmitter) of the diffuse surface the camera
/// ray (o, d) meets, with shadow rays (but on scene 1's bare plane): the running means of
/// shade_pixel. Scene 1's points and scene 4's ground points are shaded exactly at the hit
/// point (where the closed forms are evaluated), the others 1e-3 off the surface.
template <class Factory, class Light>
void shade_surface(const Scene& s, const Factory& make, const Light& light, const vec3& o, const vec3& d,
                   const PixelPoints& pts, const int* marks, int nmarks, float* out) {
    const float inv_pi = 0.31830988618f;
    double sum = 0.0;
    int mark = 0;
    const int n = marks[nmarks - 1];
    vec3 p = o + d, nrm(0.0f, 1.0f, 0.0f);  // (unused when the ray hits nothing)
    bool ground = false;
    const bool hit = hit_surface(s, o, d, p, nrm, ground);
    const bool exact_at_p = s.type == SceneType::plane || (s.type == SceneType::sphere_light && ground);
    const vec3 po = exact_at_p ? p : p + 1e-3f * nrm;
    const bool lit = hit && outside_light(light, po);
    const auto sampler = make(po, nrm, light);  // per shading point set-up, once
    const float f = s.albedo * inv_pi * light.Le;
    for (int i = 0; i < n; ++i) {
        if (lit) {
            float u1, u2;
            pts.light(static_cast<std::uint32_t>(i), u1, u2);
            const LightSample ls = sampler.sample(vec2(u1, u2));
            const float c = glm::dot(nrm, ls.direction);
            if (ls.pdf > 0.0f && c > 0.0f &&
                (s.type == SceneType::plane || unoccluded(s, po, ls.direction, ls.distance)))
                sum += static_cast<double>(f * c / ls.pdf);
        }
        if (i + 1 == marks[mark]) out[mark++] = static_cast<float>(sum / (i + 1));
    }
}

/// Renders the samples of one pixel with the factory's sampler (a disk-light factory, or a
/// sphere-light one for scene 4), writing the running mean after marks[k] samples to out[k]
/// (marks increasing; the last is the number of samples). `salt` changes the points (the
/// references use other points than the renders they judge).
template <class Factory>
void shade_pixel(const Scene& s, const Factory& make, int x, int y, int w, int h, const int* marks, int nmarks,
                 std::uint32_t salt, float* out) {
    vec3 o, d;
    camera_ray(s, x, y, w, h, o, d);
    const PixelPoints pts((static_cast<std::uint32_t>(y * w + x) * 2654435761u + 12345u) ^ hash32(salt));
    if constexpr (std::is_invocable_v<const Factory&, const vec3&, const vec3&, const SphereEmitter&>)
        shade_surface(s, make, s.lamp, o, d, pts, marks, nmarks, out);
    else if (s.type == SceneType::medium)
        shade_medium(s, make, o, d, pts, marks, nmarks, out);
    else
        shade_surface(s, make, s.light, o, d, pts, marks, nmarks, out);
}

}  // namespace demo
