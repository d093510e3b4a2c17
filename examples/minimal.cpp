// apse: the ~30 lines a renderer author copies — project a disk light, build a map, sample it
// with stratified points, and ask for the pdf of a BSDF-sampled direction (MIS).
#include <apse/apse.hpp>
#include <cmath>
#include <cstdio>

int main() {
    const glm::vec3 o(0.0f), n_surface(0.0f, 0.0f, 1.0f);                  // shading point, its normal
    const glm::vec3 center(0.5f, 0.2f, 2.0f), normal(0.0f, 0.0f, -1.0f);  // disk light
    const float radius = 1.0f, Le = 1.0f;

    // 1. Per shading point: project the disk to its spherical ellipse and build a map (set-up once).
    const apse::SphericalEllipse<float> ellipse = apse::project_disk(o, center, normal, radius);
    const apse::LdRadialMap<float> map(ellipse);  // or RadialMap / ParallelMap

    // 2. Sample it with stratified points (4 x 4 jittered grid here; any LD points work).
    double E = 0.0;  // irradiance: integral of Le cos(theta) over the disk's solid angle
    for (int i = 0; i < 16; ++i) {
        const glm::vec2 u((static_cast<float>(i % 4) + 0.5f) / 4.0f, (static_cast<float>(i / 4) + 0.5f) / 4.0f);
        const apse::DirectionSample<float> s = map.sample(u);  // s.pdf == 0: "no sample", skip
        if (s.pdf > 0.0f) E += Le * std::fmax(glm::dot(n_surface, s.direction), 0.0f) / s.pdf / 16.0;
    }

    // 3. MIS: the light's density (solid angle) of a direction found by BSDF sampling.
    const glm::vec3 w_bsdf = glm::normalize(center - o);
    const float p_light = map.pdf(w_bsdf);  // 1/Omega inside the disk's solid angle, else 0

    // Check against the closed form of the irradiance from a parallel disk (h = 2, rho^2 = 0.29).
    const double h2 = 4.0, rho2 = 0.29, r2 = 1.0, S = h2 + rho2 + r2;
    const double exact = 0.5 * 3.14159265358979 * (1.0 - (h2 + rho2 - r2) / std::sqrt(S * S - 4.0 * rho2 * r2));
    const bool ok = std::fabs(E / exact - 1.0) < 1e-2 && std::fabs(p_light * ellipse.solid_angle() - 1.0f) < 1e-5f;
    std::printf("Omega = %.6f sr, E = %.6f (exact %.6f), p_light = %.6f: %s\n", ellipse.solid_angle(), E, exact,
                p_light, ok ? "ok" : "FAILED");
    return ok ? 0 : 1;
}
