// apse — area-preserving parameterizations for spherical ellipses.
// SPDX-License-Identifier: MIT
#pragma once

/// @file disk_frame.hpp
/// `DiskFrame<T>`: a disk light's geometry as a renderer stores it, once per light — centre, unit
/// normal, an in-plane orthonormal frame, radius and its reciprocal.

#include <cmath>

#include "config.hpp"
#include "detail/glm.hpp"
#include "detail/type_identity.hpp"
#include "detail/vector.hpp"
#include "detail/math.hpp"

namespace apse {

/// A disk light's per-light data: the disk {p : (p − center)·n = 0, |p − center| <= radius} with
/// its unit normal and an in-plane orthonormal frame. Build it once per light (`make`) and keep it
/// with the light; per shading point, `project_disk(o, frame)`, `DiskLight(o, frame, ...)` and
/// `DiskAreaSampler(o, frame)` then need only the shading point (no normalisation). Invalid
/// (`valid()` false: every sampler built from it is empty) for radius <= 0 or non-finite, a
/// radius whose reciprocal overflows, a zero or non-finite normal, or a non-finite centre.
/// `normal` need not be unit length (it is normalised). Trivially copyable.
template <class T> struct DiskFrame {
    static_assert(detail::is_real_type<T>(), "apse: DiskFrame<T>: T must be float or double");
    using vec3 = glm::vec<3, T>;  ///< a 3-D vector (direction, point or normal)

    vec3 center;   ///< the disk's centre
    vec3 n;        ///< unit normal ((0, 0, 1) when invalid)
    vec3 e1;       ///< first unit in-plane axis
    vec3 e2;       ///< second unit in-plane axis, (e1, e2, n) right-handed
    T radius;      ///< r (0 when invalid)
    T inv_radius;  ///< 1/r (0 when invalid)

    /// The frame of the disk (center, normal, radius); see the struct comment for invalid input.
    static APSE_FUNC DiskFrame make(const vec3& center, const vec3& normal, detail::type_identity_t<T> radius) noexcept {
        DiskFrame f{center, vec3(T(0), T(0), T(1)), vec3(T(1), T(0), T(0)), vec3(T(0), T(1), T(0)), T(0), T(0)};
        const vec3 nn = detail::robust_normalize(normal);
        const T inv_r = T(1) / radius;
        if (!(radius > T(0)) || !detail::is_finite(radius) || !detail::is_finite(inv_r) || !(glm::dot(nn, nn) > T(0)) ||
            !detail::finite3(center))
            return f;
        f.n = nn;
        f.e1 = detail::any_perpendicular(nn);
        f.e2 = glm::cross(nn, f.e1);
        f.radius = radius;
        f.inv_radius = inv_r;
        return f;
    }

    /// True if samplers built from this frame can sample (see the struct comment).
    APSE_FUNC bool valid() const noexcept { return inv_radius > T(0); }
};

}  // namespace apse
