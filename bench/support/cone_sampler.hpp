// pbrt-v4's sphere-light sampling, written here as the reference apse's sphere lights are measured
// against (bench_samplers.cpp, sphere_study.cpp): what a renderer runs today.
#pragma once

#include <apse/math.hpp>
#include <apse/sample.hpp>
#include <apse/sphere_light.hpp>

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <algorithm>
#include <cmath>

namespace apse_bench {

/// pbrt-v4's sampling of a sphere light from a point outside it, direction part
/// (Sphere::Sample(ctx, u) and SampleUniformCone): sin^2 theta_max = r^2 / d^2, cos theta_max
/// and 1 − cos theta_max (by its Taylor branch below sin^2 = 0.00068523, as pbrt), a frame around
/// the centre direction built per shading point (Frame::FromZ: Duff et al. 2017's branchless
/// basis), cos theta = 1 − u0 (1 − cos theta_max), phi = 2 pi u1; pdf 1 / (2 pi (1 − cos theta_max)).
/// With `Point`, also the nearest point of the sphere along the direction and its distance (the
/// shadow ray), by the closed form SphereLight uses for the radial maps
/// (detail::sphere_distance_at_polar: from cos theta and cos theta − cos theta_max, which the
/// cone sampler has as 1 − u0 times 1 − cos theta_max, or in pbrt's small-cap branch through
/// sin^2 theta_max − sin^2 theta = sin^2 theta_max (1 − u0)): the leanest a renderer could write.
template <class T, bool Point> class ConeSampler {
public:
    using vec2 = glm::vec<2, T>;
    using vec3 = glm::vec<3, T>;
    ConeSampler(const vec3& o, const vec3& c, T r) : o_(o), c_(c), r_(r) {
        const vec3 d = c - o;
        const T dist2 = glm::dot(d, d);
        dist_ = std::sqrt(dist2);
        z_ = d / dist_;
        sin2_max_ = r * r / dist2;
        cos_max_ = std::sqrt(std::max(T(0), T(1) - sin2_max_));
        omc_ = sin2_max_ < T(0.00068523) ? sin2_max_ / 2 : T(1) - cos_max_;
        dist_cos2_ = dist_ * cos_max_ * cos_max_;
        pdf_ = T(1) / (T(2) * apse::pi_v<T> * omc_);
        const T sign = std::copysign(T(1), z_.z), a = T(-1) / (sign + z_.z), b = z_.x * z_.y * a;
        x_ = vec3(T(1) + sign * z_.x * z_.x * a, sign * b, -sign * z_.x);
        y_ = vec3(b, sign + z_.y * z_.y * a, -z_.y);
    }
    auto sample(const vec2& u) const {
        T cos_t = T(1) - u.x * omc_, sin2_t = T(1) - cos_t * cos_t;
        T rim_product = omc_ * (T(1) - u.x) * (cos_t + cos_max_);  // sin^2 theta_max − sin^2 theta
        if (sin2_max_ < T(0.00068523)) {  // pbrt's small-cap branch
            sin2_t = sin2_max_ * u.x;
            cos_t = std::sqrt(T(1) - sin2_t);
            rim_product = sin2_max_ * (T(1) - u.x);
        }
        const T sin_t = std::sqrt(std::max(T(0), sin2_t)), phi = T(2) * apse::pi_v<T> * u.y;
        const vec3 w = (sin_t * std::cos(phi)) * x_ + (sin_t * std::sin(phi)) * y_ + cos_t * z_;
        if constexpr (Point) {
            const T t = dist_cos2_ / (cos_t + std::sqrt(rim_product));
            return apse::PointSample<T>{{w, pdf_}, o_ + t * w, t};
        } else {
            return apse::DirectionSample<T>{w, pdf_};
        }
    }

private:
    vec3 o_, c_;
    T r_, dist_;
    vec3 x_, y_, z_;
    T sin2_max_, cos_max_, omc_, pdf_, dist_cos2_;
};

}  // namespace apse_bench
