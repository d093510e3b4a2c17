// The seeded sphere-light configurations shared by apse's sampler benchmarks (bench_samplers.cpp)
// and the sphere study (sphere_study.cpp). 1024 unit spheres: centres uniform in [-2, 2]³,
// shading points 1.05–50 radii from the centre (log-uniform) in a direction uniform on the sphere,
// each with three receiver normals: `above` (the cap wholly above the receiver's horizon: the
// centre's angle gamma from the normal uniform in [0, pi/2 − alpha]), `cut` (the cap straddles the
// horizon: gamma uniform in (pi/2 − alpha, pi/2 + alpha)) and `mixed` (`cut` for 30 % of the
// configurations, `above` otherwise). splitmix64 with a fixed seed, computed in double and rounded
// once, so float and double see the same configurations. The points of the unit square are the
// disk benchmarks' (disk_configs.hpp).
#pragma once

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace apse_bench {

template <class T> struct SphereConfig {
    glm::vec<3, T> o;      ///< shading point
    glm::vec<3, T> c;      ///< sphere centre
    T r;                   ///< radius (1)
    glm::vec<3, T> above;  ///< receiver normal with the cap above the horizon
    glm::vec<3, T> cut;    ///< receiver normal with the cap cut by the horizon
    glm::vec<3, T> mixed;  ///< `cut` for 30 % of the configurations, else `above`
};

template <class T> struct SphereConfigs {
    static constexpr std::size_t count = 1024;  // a power of two: index with & (count - 1)
    std::vector<SphereConfig<T>> spheres;

    SphereConfigs() {
        std::uint64_t state = 20190502;
        auto next = [&state]() {  // splitmix64, uniform in [0, 1)
            std::uint64_t z = (state += 0x9e3779b97f4a7c15ULL);
            z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
            z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
            return double((z ^ (z >> 31)) >> 11) * 0x1p-53;
        };
        auto sphere = [&]() {
            const double z = 2 * next() - 1, phi = 6.283185307179586 * next();
            const double s = std::sqrt(1 - z * z);
            return glm::dvec3(s * std::cos(phi), s * std::sin(phi), z);
        };
        const double half_pi = 1.5707963267948966;
        for (std::size_t i = 0; i < count; ++i) {
            const glm::dvec3 c(4 * next() - 2, 4 * next() - 2, 4 * next() - 2);
            const double dist = std::pow(50.0 / 1.05, next()) * 1.05;
            const glm::dvec3 dir = sphere();  // from the centre to o
            const glm::dvec3 o = c + dist * dir;
            const double alpha = std::asin(1 / dist);
            // a unit vector perpendicular to the centre direction -dir, at a random azimuth
            glm::dvec3 t = glm::cross(dir, sphere());
            t = glm::length(t) > 1e-6 ? glm::normalize(t) : glm::normalize(glm::cross(dir, glm::dvec3(0.6, 0.8, 0)));
            auto normal = [&](double gamma) { return std::cos(gamma) * (-dir) + std::sin(gamma) * t; };
            const glm::dvec3 above = normal((half_pi - alpha) * next());
            const glm::dvec3 cut = normal(half_pi + alpha * (2 * next() - 1));
            spheres.push_back({glm::vec<3, T>(o), glm::vec<3, T>(c), T(1), glm::vec<3, T>(above), glm::vec<3, T>(cut),
                               glm::vec<3, T>(i % 10 < 3 ? cut : above)});
        }
    }
};

/// The configurations for T, built on first use (outside any timing loop if called before it).
template <class T> const SphereConfigs<T>& sphere_configs() {
    static const SphereConfigs<T> s;
    return s;
}

}  // namespace apse_bench
