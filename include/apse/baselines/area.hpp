// apse — area-preserving parameterizations for spherical ellipses.
// SPDX-License-Identifier: MIT
#pragma once

/// @file baselines/area.hpp
/// Uniform-by-area sampling of a disk light — the classic baseline and the cost floor every
/// apse benchmark ratio is measured against. Directions are drawn from points uniform on the
/// disk (Shirley–Chiu concentric map, MATH.md §4), and the density is converted to solid angle:
/// pdf = dist^2 / (|cos theta_l| pi r^2). Unbiased, but its pdf varies over the disk (the
/// spherical-ellipse maps are uniform in solid angle).

#include <cmath>

#include "../config.hpp"
#include "../detail/concentric.hpp"
#include "../detail/glm.hpp"
#include "../detail/vector.hpp"
#include "../math.hpp"
#include "../sample.hpp"

namespace apse {

/// Uniform-by-area sampler of the disk {p : (p − center)·n = 0, |p − center| <= radius} seen
/// from the shading point `o`, with the pdf in **solid angle**. Two-sided, like project_disk
/// (|cos theta_l|): its pdf integrates to the disk's solid angle at o, and E[1/pdf] = Omega.
/// The same degenerate-input rules as project_disk: radius <= 0, a zero or non-finite normal,
/// NaN/Inf coordinates, or `o` in the disk's plane (Omega = 0) make the sampler *empty*:
/// `sample` returns pdf 0 ("no sample") and `pdf` returns 0 everywhere. `normal` need not be
/// unit length (it is normalised). Cost: one concentric map, one normalisation, one division.
template <class T> class DiskAreaSampler {
public:
    using vec2 = glm::vec<2, T>;
    using vec3 = glm::vec<3, T>;

    /// Builds the sampler (precomputes the disk's in-plane frame and 1/(pi r^2)).
    APSE_FUNC DiskAreaSampler(const vec3& o, const vec3& center, const vec3& normal, T radius) noexcept
        : w_(center - o), e1_(T(1), T(0), T(0)), e2_(T(0), T(1), T(0)), n_(T(0), T(0), T(1)),
          radius_(radius), pdf_factor_(T(0)) {
        const vec3 n = detail::robust_normalize(normal);
        if (!(radius > T(0)) || !is_finite(radius) || !(glm::dot(n, n) > T(0)) || !detail::finite3(o) ||
            !detail::finite3(w_))
            return;
        if (!(glm::dot(w_, n) != T(0))) return;  // o in the disk's plane: Omega = 0
        n_ = n;
        e1_ = detail::any_perpendicular(n);
        e2_ = glm::cross(n, e1_);
        pdf_factor_ = T(1) / pi_v<T>;  // pdf = (dist / r)^2 / (|cos| pi)
    }

    /// True if the sampler cannot produce samples (degenerate input, see the class comment).
    APSE_FUNC bool empty() const noexcept { return !(pdf_factor_ > T(0)); }

    /// Direction towards the disk point ρ (cos θ, sin θ) of the concentric map of u ∈ [0,1]^2
    /// (coordinates clamped into it) and its solid-angle pdf dist^2 / (|cos theta_l| pi r^2).
    /// Empty sampler: pdf 0 and the direction is the (unit) normal. A pdf that would overflow
    /// (a sample exactly grazing, cos theta_l underflowing) is reported as 0.
    APSE_FUNC DirectionSample<T> sample(const vec2& u) const noexcept {
        if (empty()) return {n_, T(0)};
        const detail::ConcentricPolar<T> pt = detail::concentric_to_disk(u);
        const T ang = pt.angle();
        const T rr = radius_ * pt.radius;
        const vec3 d = w_ + (rr * std::cos(ang)) * e1_ + (rr * std::sin(ang)) * e2_;
        const T len = std::sqrt(glm::dot(d, d));
        const vec3 dir = d / len;
        const T cos_l = std::fabs(glm::dot(dir, n_));
        const T ratio = len / radius_;
        T pdf = ratio * ratio * pdf_factor_ / cos_l;
        if (!is_finite(pdf)) pdf = T(0);
        return {dir, pdf};
    }

    /// Solid-angle density of `direction` (any non-zero length; it is normalised): the
    /// ray–disk intersection's dist^2 / (|cos theta_l| pi r^2), 0 if the ray misses the disk,
    /// for an empty sampler, or for a zero/NaN direction.
    APSE_FUNC T pdf(const vec3& direction) const noexcept {
        if (empty()) return T(0);
        const vec3 dir = detail::robust_normalize(direction);
        const T cos_l = glm::dot(dir, n_);
        const T t = glm::dot(w_, n_) / cos_l;  // distance along the ray to the plane
        if (!(t > T(0)) || !is_finite(t)) return T(0);
        const vec3 p = t * dir - w_;  // hit point relative to the centre
        if (!(glm::dot(p, p) <= radius_ * radius_)) return T(0);
        const T ratio = t / radius_;
        const T pdf = ratio * ratio * pdf_factor_ / std::fabs(cos_l);
        return is_finite(pdf) ? pdf : T(0);
    }

    /// The square point whose sample is `direction` (inverse of sample): the ray–disk hit point,
    /// then the inverse concentric map. A ray that hits the plane outside the disk gives the
    /// square-boundary point of the rim point in the same polar direction; a ray that misses the
    /// plane, a zero/NaN direction or an empty sampler give (0.5, 0.5) (the disk's centre).
    APSE_FUNC vec2 invert(const vec3& direction) const noexcept {
        const vec2 centre(T(0.5), T(0.5));
        if (empty()) return centre;
        const vec3 dir = detail::robust_normalize(direction);
        const T t = glm::dot(w_, n_) / glm::dot(dir, n_);
        if (!(t > T(0)) || !is_finite(t)) return centre;
        const vec3 p = t * dir - w_;
        const T x = glm::dot(p, e1_), y = glm::dot(p, e2_);
        const T rho = std::sqrt(x * x + y * y) / radius_;
        if (!(rho > T(0))) return centre;
        T turns = std::atan2(y, x) * (T(1) / two_pi_v<T>);
        if (turns < T(0)) turns += T(1);
        return detail::concentric_from_disk(rho, turns);
    }

    /// The disk's unit normal as used (normalised; (0, 0, 1) for an empty sampler).
    APSE_FUNC const vec3& normal() const noexcept { return n_; }

private:
    vec3 w_;   ///< center − o
    vec3 e1_;  ///< in-plane frame
    vec3 e2_;
    vec3 n_;   ///< unit normal
    T radius_;
    T pdf_factor_;  ///< 1/pi, or 0 for an empty sampler
};

}  // namespace apse
