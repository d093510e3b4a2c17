// The seeded disk configurations shared by apse's sampler benchmarks (bench_samplers.cpp).
// 1024 unit disks: centres uniform in [-2, 2]³, normals uniform on the sphere, shading points
// 0.1–1000 radii from the centre (log-uniform) in a direction uniform on the sphere (nudged off
// the disk's plane), each with the DiskFrame a renderer stores with the light (built here,
// outside any timing); plus 4096 points of the unit square. splitmix64 with a fixed seed, computed
// in double and rounded once, so float and double see the same configurations and points.
#pragma once

#include <apse/baselines/area.hpp>

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace apse_bench {

template <class T> struct DiskConfig {
    glm::vec<3, T> o;       ///< shading point
    glm::vec<3, T> c, n;    ///< disk centre and normal (unit)
    T r;                    ///< radius (1)
    glm::vec<3, T> half_x;  ///< half edges of the circumscribed square (unit; scale by r), edge_y
    glm::vec<3, T> half_y;  ///< along the in-plane direction from o's foot point to the centre
    apse::DiskFrame<T> frame;  ///< the light's frame for area sampling, built once per light
};

template <class T> struct DiskConfigs {
    static constexpr std::size_t disk_count = 1024;  // powers of two: index with & (count - 1)
    static constexpr std::size_t u_count = 4096;
    std::vector<DiskConfig<T>> disks;
    std::vector<glm::vec<2, T>> u;

    DiskConfigs() {
        std::uint64_t state = 20170619;
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
        for (std::size_t i = 0; i < disk_count; ++i) {
            const glm::dvec3 c(4 * next() - 2, 4 * next() - 2, 4 * next() - 2);
            const glm::dvec3 n = sphere();
            const double dist = std::pow(10.0, -1 + 4 * next());  // 0.1 .. 1000 radii
            glm::dvec3 dir = sphere();
            if (std::fabs(glm::dot(dir, n)) < 1e-3)  // not in the plane
                dir = glm::normalize(dir + 0.01 * n);
            const glm::dvec3 o = c + dist * dir;
            glm::dvec3 yd = (c - o) - glm::dot(c - o, n) * n;
            yd = glm::length(yd) > 1e-12 ? glm::normalize(yd)
                                         : glm::normalize(glm::cross(n, glm::dvec3(0.6, 0.8, 0)));
            const glm::dvec3 xd = glm::cross(yd, n);
            disks.push_back({glm::vec<3, T>(o), glm::vec<3, T>(c), glm::vec<3, T>(n), T(1),
                             glm::vec<3, T>(xd), glm::vec<3, T>(yd),
                             apse::DiskFrame<T>::make(glm::vec<3, T>(c), glm::vec<3, T>(n), T(1))});
        }
        for (std::size_t i = 0; i < u_count; ++i) u.emplace_back(T(next()), T(next()));
    }
};

/// The configurations for T, built on first use (outside any timing loop if called before it).
template <class T> const DiskConfigs<T>& disk_configs() {
    static const DiskConfigs<T> s;
    return s;
}

}  // namespace apse_bench
