// apse inside a renderer's direct lighting: one light sample and one BSDF sample per shading
// point, combined by multiple importance sampling (balance heuristic), with the renderer's own
// vector type, scene data (a double radius) and sample sequence. The code between the
// "readme" markers is the example of docs/integration.md, word for word (the test
// readme_integration_example checks it); main() runs it for every map and checks the
// estimates against the closed-form answer. Built and run as a test.
#include <apse/apse.hpp>
#include <apse/runtime_sampler.hpp>  // the map chosen at run time (from the scene)

#include <cmath>
#include <cstdio>

// [readme-begin]
// The renderer's own types: its vector, and the disk emitter its scene loader builds (on any
// thread: default_table() builds the table once, thread-safely, and returns the same object).
struct Vec3 { float x, y, z; };
inline glm::vec3 to_glm(const Vec3& v) { return {v.x, v.y, v.z}; }

struct DiskEmitter {
    Vec3 center, normal;  // one-sided: emits on the side `normal` points to
    double radius;        // the scene's double; apse converts it to the vectors' float
    float radiance;
    apse::MapKind map = apse::MapKind::tabulated_ld_radial;  // read from the scene file
    apse::TabulationView table = apse::default_table().view();  // ignored by the exact maps
};

struct LightSample {
    glm::vec3 wi;    // unit direction towards the light
    float distance;  // shadow ray: from p along wi, up to distance shortened by the usual epsilon
    float pdf;       // solid angle; 0: no sample
};

// Light sampling. The side test is the caller's (apse's geometry is two-sided) and must be the
// emitter's own: the same one in pdf_light and in the renderer's hit test.
LightSample sample_light(const DiskEmitter& e, const glm::vec3& p, const glm::vec2& u) {
    const glm::vec3 c = to_glm(e.center), n = to_glm(e.normal);
    if (!apse::disk_faces(p, c, n)) return {glm::vec3(0.0f), 0.0f, 0.0f};
    const apse::DiskLight<apse::RuntimeSampler<float>> light(p, c, n, e.radius, e.map, e.table);
    const apse::PointSample<float> s = light.sample(u);
    return {s.direction, s.distance, s.pdf};
}

// The light's density of any direction, stateless (the MIS query for a BSDF-sampled direction):
// exactly the density sample_light draws from, for every map.
float pdf_light(const DiskEmitter& e, const glm::vec3& p, const glm::vec3& wi) {
    const glm::vec3 c = to_glm(e.center), n = to_glm(e.normal);
    if (!apse::disk_faces(p, c, n)) return 0.0f;
    return apse::disk_light_pdf<apse::RuntimeSampler<float>>(p, c, n, e.radius, wi, e.map, e.table);
}

// Direct light reflected by a white Lambertian surface (BRDF 1/pi) at p with normal ns (occlusion
// omitted): one light sample (u_light) and one cosine-weighted BSDF sample (u_bsdf).
float direct_light(const DiskEmitter& e, const glm::vec3& p, const glm::vec3& ns, const glm::vec2& u_light,
                   const glm::vec2& u_bsdf) {
    const float inv_pi = 0.318309886f;
    float result = 0.0f;
    const LightSample ls = sample_light(e, p, u_light);
    const float cos_l = glm::dot(ns, ls.wi);
    if (ls.pdf > 0.0f && cos_l > 0.0f) {  // && unoccluded(p, ls.wi, ls.distance * (1 - 1e-4f))
        const float p_bsdf = cos_l * inv_pi;
        result += e.radiance * inv_pi * cos_l / (ls.pdf + p_bsdf);  // (f cos / pdf) * pdf / (pdf + p_bsdf)
    }
    // the renderer's BSDF sample (cosine-weighted about ns) and its own ray-disk hit test
    const float r = std::sqrt(u_bsdf.x), phi = 6.28318531f * u_bsdf.y;
    const glm::vec3 t = glm::normalize(std::fabs(ns.x) > 0.5f ? glm::vec3(-ns.y, ns.x, 0.0f) : glm::vec3(0.0f, -ns.z, ns.y));
    const glm::vec3 wi = r * std::cos(phi) * t + r * std::sin(phi) * glm::cross(ns, t) +
                         std::sqrt(std::fmax(0.0f, 1.0f - u_bsdf.x)) * ns;
    const glm::vec3 c = to_glm(e.center), n = glm::normalize(to_glm(e.normal));
    const float dist = glm::dot(c - p, n) / glm::dot(wi, n);  // ray-plane distance
    const bool hit = glm::dot(p - c, n) > 0.0f && dist > 0.0f &&
                     glm::length(p + dist * wi - c) <= float(e.radius);
    const float p_l = hit ? pdf_light(e, p, wi) : 0.0f;
    // A "hit" the light sampler cannot produce (p_l == 0: a ray parallel to the disk, rounding at
    // the rim) is a set of measure zero: skip it rather than give it full weight (a firefly).
    if (p_l > 0.0f) {
        const float p_bsdf = glm::dot(ns, wi) * inv_pi;
        result += e.radiance * inv_pi * glm::dot(ns, wi) / (p_bsdf + p_l);  // (f cos / p_bsdf) * p_bsdf / (p_bsdf + p_l)
    }
    return result;
}
// [readme-end]

namespace {

/// The renderer's own sample sequence: a 2-D Kronecker (R2) sequence with a per-estimate random
/// rotation (Cranley–Patterson), as a renderer rotates its sequence per pixel.
glm::vec2 r2_point(int i, float rot_x, float rot_y) {
    const double a = 0.7548776662466927 * i + rot_x, b = 0.5698402909980532 * i + rot_y;
    return glm::vec2(float(a - std::floor(a)), float(b - std::floor(b)));
}

/// splitmix64 in [0, 1)
struct Random {
    unsigned long long state;
    float next() {
        unsigned long long z = (state += 0x9e3779b97f4a7c15ULL);
        z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
        z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
        return float((z ^ (z >> 31)) >> 40) * 0x1p-24f;
    }
};

}  // namespace

int main() {
    // A disk of radius 1 at height h = 2 above the receiver, parallel to it and facing it, its
    // centre rho = 0.5 off the receiver's normal: the reflected radiance of a white Lambertian
    // receiver is E / pi with the closed-form irradiance
    // E = (pi/2) (1 − (h² + rho² − r²) / sqrt((h² + rho² + r²)² − 4 rho² r²)).
    const double h2 = 4.0, rho2 = 0.25, r2 = 1.0, s = h2 + rho2 + r2;
    const double exact = 0.5 * (1.0 - (h2 + rho2 - r2) / std::sqrt(s * s - 4.0 * rho2 * r2));
    const glm::vec3 p(0.0f), ns(0.0f, 0.0f, 1.0f);
    const apse::MapKind maps[] = {apse::MapKind::radial, apse::MapKind::ld_radial, apse::MapKind::parallel,
                                  apse::MapKind::tabulated, apse::MapKind::tabulated_ld_radial};
    const char* names[] = {"radial", "ld_radial", "parallel", "tabulated", "tabulated_ld_radial"};
    bool ok = true;
    for (int m = 0; m < 5; ++m) {
        const DiskEmitter light{{0.5f, 0.0f, 2.0f}, {0.0f, 0.0f, -1.0f}, 1.0, 1.0f, maps[m]};
        // 400 independent estimates of 64 MIS pairs each (rotated sequences): the mean of the
        // estimates and its standard error
        Random rng{2017ULL + unsigned(m)};
        const int estimates = 400, pairs = 64;
        double sum = 0.0, sum2 = 0.0;
        for (int k = 0; k < estimates; ++k) {
            const float rx = rng.next(), ry = rng.next(), bx = rng.next(), by = rng.next();
            double estimate = 0.0;
            for (int i = 0; i < pairs; ++i)
                estimate += direct_light(light, p, ns, r2_point(i, rx, ry), r2_point(i, bx, by));
            estimate /= pairs;
            sum += estimate;
            sum2 += estimate * estimate;
        }
        const double mean = sum / estimates;
        const double se = std::sqrt(std::fmax(sum2 / estimates - mean * mean, 0.0) / (estimates - 1));
        // Unbiased MIS: within 4 standard errors (a false alarm has probability 6e-5 per map;
        // the estimates are deterministic, seeded), with a standard error below 1e-3 relative so
        // that the check means something (a weight that dropped or doubled a strategy's share
        // would be hundreds of standard errors off).
        const double z = (mean - exact) / se;
        const bool good = std::fabs(z) < 4.0 && se < 1e-3 * exact;
        std::printf("%-20s L = %.6f (exact %.6f), %+.2f standard errors (%.1e relative): %s\n", names[m], mean,
                    exact, z, se / exact, good ? "ok" : "FAILED");
        ok = ok && good;
    }
    return ok ? 0 : 1;
}
