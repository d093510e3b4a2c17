// apse — area-preserving parameterizations for spherical ellipses.
// SPDX-License-Identifier: MIT
#pragma once

/// @file baselines/area.hpp
/// Uniform-by-area sampling of a disk light — the classic baseline and the cost floor every
/// apse benchmark ratio is measured against, written as a renderer writes it: the disk's frame
/// (`DiskFrame`) is built once per light and stored with it; per shading point only c − o and
/// two tests; per sample one concentric point (signed polar form, no angle wrapping), one
/// sin/cos pair, one square root and one division. Directions are drawn from points uniform on
/// the disk (Shirley–Chiu concentric map, docs/math.md §4), and the density is converted to solid
/// angle: pdf = dist^2 / (|cos theta_l| pi r^2). Unbiased, but its pdf varies over the disk (the
/// spherical-ellipse maps are uniform in solid angle).

#include <cmath>

#include "../config.hpp"
#include "../detail/polar.hpp"
#include "../detail/glm.hpp"
#include "../detail/type_identity.hpp"
#include "../detail/vector.hpp"
#include "../disk_frame.hpp"
#include "../detail/math.hpp"
#include "../sample.hpp"

namespace apse {

/// Uniform-by-area sampler of a disk seen from the shading point `o`, with the pdf in **solid
/// angle**. Two-sided, like project_disk (|cos theta_l|): its pdf integrates to the disk's solid
/// angle at o, and E[1/pdf] = Omega. Empty (`sample` returns pdf 0, "no sample"; `pdf` returns 0
/// everywhere) for an invalid DiskFrame, NaN/Inf coordinates of o or c − o, or `o` in the disk's
/// plane (Omega = 0) — the same degenerate-input rules as project_disk. Per shading point: c − o
/// and the tests (from a stored DiskFrame); per sample: one concentric point, one sin/cos, one
/// square root, one division. Trivially copyable.
template <class T> class DiskAreaSampler {
    static_assert(detail::is_real_type<T>(), "apse: DiskAreaSampler<T>: T must be float or double");

public:
    using vec2 = glm::vec<2, T>;  ///< a point of the unit square
    using vec3 = glm::vec<3, T>;  ///< a 3-D vector (direction, point or normal)

    /// The sampler at `o` for the light's stored frame (the renderer's per-shading-point call).
    APSE_FUNC DiskAreaSampler(const vec3& o, const DiskFrame<T>& frame) noexcept
        : w_(frame.center - o), frame_(frame) {
        if (!frame.valid() || !detail::finite3(o) || !detail::finite3(w_) || !(glm::dot(w_, frame.n) != T(0)))
            frame_.inv_radius = T(0);  // empty (o in the disk's plane: Omega = 0)
    }

    /// Convenience: builds the frame at every call (DiskFrame::make), then as above — a normalised
    /// normal, a perpendicular and a cross product more per shading point than storing the frame.
    APSE_FUNC DiskAreaSampler(const vec3& o, const vec3& center, const vec3& normal,
                              detail::type_identity_t<T> radius) noexcept
        : DiskAreaSampler(o, DiskFrame<T>::make(center, normal, radius)) {}

    /// True if the sampler cannot produce samples (degenerate input, see the class comment).
    APSE_FUNC bool empty() const noexcept { return !(frame_.inv_radius > T(0)); }

    /// Direction towards the disk point rho (cos theta, sin theta) of the concentric map of
    /// u ∈ [0,1]^2 (coordinates clamped into it) and its solid-angle pdf
    /// dist^2 / (|cos theta_l| pi r^2). Empty sampler: pdf 0 and the direction is the (unit)
    /// normal. A pdf that would overflow (a sample exactly grazing, cos theta_l underflowing) is
    /// reported as 0.
    APSE_FUNC DirectionSample<T> sample(const vec2& u) const noexcept {
        if (empty()) return {frame_.n, T(0)};
        const detail::ConcentricSigned<T> pt = detail::concentric_to_disk_signed(u);
        const T rr = frame_.radius * pt.radius;
        const vec3 d = w_ + (rr * std::cos(pt.angle)) * frame_.e1 + (rr * std::sin(pt.angle)) * frame_.e2;
        const T len2 = glm::dot(d, d), len = std::sqrt(len2);
        const T dn = std::fabs(glm::dot(d, frame_.n));
        // one division: q = 1/(len dn); direction d/len = d (dn q); pdf = len^3/(dn pi r^2)
        const T q = T(1) / (len * dn);
        const T ratio = len * frame_.inv_radius;
        const T pdf = (ratio * ratio) * (len2 * q) * (T(1) / detail::pi_v<T>);
        if (!detail::is_finite(pdf)) return {detail::robust_normalize(d), T(0)};  // grazing, or overflow: no sample
        return {d * (dn * q), pdf};
    }

    /// Solid-angle density of `direction` (any non-zero length; it is normalised): the
    /// ray–disk intersection's dist^2 / (|cos theta_l| pi r^2), 0 if the ray misses the disk,
    /// for an empty sampler, or for a zero/NaN direction.
    APSE_FUNC T pdf(const vec3& direction) const noexcept {
        if (empty()) return T(0);
        const vec3 dir = detail::robust_normalize(direction);
        const T cos_l = glm::dot(dir, frame_.n);
        const T t = glm::dot(w_, frame_.n) / cos_l;  // distance along the ray to the plane
        if (!(t > T(0)) || !detail::is_finite(t)) return T(0);
        const vec3 p = t * dir - w_;  // hit point relative to the centre
        const T ratio = t * frame_.inv_radius;
        const vec3 pr = p * frame_.inv_radius;
        if (!(glm::dot(pr, pr) <= T(1))) return T(0);
        const T pdf = ratio * ratio * (T(1) / detail::pi_v<T>) / std::fabs(cos_l);
        return detail::is_finite(pdf) ? pdf : T(0);
    }

    /// The square point whose sample is `direction` (inverse of sample): the ray–disk hit point,
    /// then the inverse concentric map. A ray that hits the plane outside the disk gives the
    /// square-boundary point of the rim point in the same polar direction; a ray that misses the
    /// plane, a zero/NaN direction or an empty sampler give (0.5, 0.5) (the disk's centre).
    APSE_FUNC vec2 invert(const vec3& direction) const noexcept {
        const vec2 centre(T(0.5), T(0.5));
        if (empty()) return centre;
        const vec3 dir = detail::robust_normalize(direction);
        const T t = glm::dot(w_, frame_.n) / glm::dot(dir, frame_.n);
        if (!(t > T(0)) || !detail::is_finite(t)) return centre;
        const vec3 p = t * dir - w_;
        const T x = glm::dot(p, frame_.e1) * frame_.inv_radius, y = glm::dot(p, frame_.e2) * frame_.inv_radius;
        const T rho = std::sqrt(x * x + y * y);
        if (!(rho > T(0))) return centre;
        T turns = std::atan2(y, x) * (T(1) / detail::two_pi_v<T>);
        if (turns < T(0)) turns += T(1);
        return detail::concentric_from_disk(rho, turns);
    }

    /// The disk's unit normal as used (normalised; (0, 0, 1) for an invalid frame).
    APSE_FUNC const vec3& normal() const noexcept { return frame_.n; }

private:
    vec3 w_;              ///< center − o
    DiskFrame<T> frame_;  ///< the light's frame (inv_radius 0: empty sampler)
};

}  // namespace apse
