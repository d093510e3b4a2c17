// apse in a few lines: the README's example (the code between the "readme" markers, which the
// test readme_example finds word for word in README.md) — the irradiance at a shading point from
// a one-sided disk light, with the tabulated LD-radial map through DiskLight — and a main() that
// checks it against the closed form and asks for the pdf of a BSDF-sampled direction (MIS).
// Built and run as a test.
// [readme-begin]
#include <apse/apse.hpp>

// Irradiance at a shading point o (normal n) from a one-sided disk light: 16 stratified samples.
float irradiance(glm::vec3 o, glm::vec3 n, glm::vec3 center, glm::vec3 normal, float radius) {
    if (!apse::disk_faces(o, center, normal)) return 0.0f;  // o behind the light: cull
    const apse::DiskLight<apse::TabulatedLdRadialMap<float>> light(
        o, center, normal, radius, apse::default_table().view());  // set-up: once per shading point
    float E = 0.0f;
    for (int i = 0; i < 16; ++i) {  // a 4 x 4 grid of strata here; any stratified or QMC points
        const apse::PointSample<float> s = light.sample(glm::vec2(i % 4 + 0.5f, i / 4 + 0.5f) / 4.0f);
        if (s.pdf > 0.0f)  // pdf in solid angle, 0 = no sample; shadow ray: s.direction, s.distance
            E += std::fmax(glm::dot(n, s.direction), 0.0f) / s.pdf / 16.0f;
    }
    return E;  // MIS: light.pdf(w) is the density of a BSDF-sampled direction w (0 off the light)
}
// [readme-end]

#include <cmath>
#include <cstdio>

int main() {
    const glm::vec3 o(0.0f), n(0.0f, 0.0f, 1.0f);                         // shading point, its normal
    const glm::vec3 center(0.5f, 0.2f, 2.0f), normal(0.0f, 0.0f, -1.0f);  // disk light facing o
    const float radius = 1.0f;
    const float E = irradiance(o, n, center, normal, radius);

    // The closed form of the irradiance from a parallel disk (h = 2, rho^2 = 0.29, r = 1).
    const double h2 = 4.0, rho2 = 0.29, r2 = 1.0, S = h2 + rho2 + r2;
    const double exact = 0.5 * 3.14159265358979 * (1.0 - (h2 + rho2 - r2) / std::sqrt(S * S - 4.0 * rho2 * r2));

    // MIS: the light's density (solid angle) of a direction found by BSDF sampling — the density
    // the light samples from (the tabulated map's own, within 1 % of 1/Omega), also stateless.
    const apse::TabulationView table = apse::default_table().view();
    const apse::DiskLight<apse::TabulatedLdRadialMap<float>> light(o, center, normal, radius, table);
    const glm::vec3 w_bsdf = glm::normalize(center - o);
    const float p_light = light.pdf(w_bsdf);
    const float p_stateless =
        apse::disk_light_pdf<apse::TabulatedLdRadialMap<float>>(o, center, normal, radius, w_bsdf, table);
    const float omega = light.solid_angle();

    const bool ok = std::fabs(E / exact - 1.0) < 1e-2 && std::fabs(p_light * omega - 1.0f) < 1e-2f &&
                    std::fabs(p_stateless / p_light - 1.0f) < 1e-5f && irradiance(o, n, center, -normal, radius) == 0.0f;
    std::printf("Omega = %.6f sr, E = %.6f (exact %.6f), p_light = %.6f (stateless %.6f): %s\n", omega, E, exact,
                p_light, p_stateless, ok ? "ok" : "FAILED");
    return ok ? 0 : 1;
}
