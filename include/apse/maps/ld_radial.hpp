// apse — area-preserving parameterizations for spherical ellipses.
// SPDX-License-Identifier: MIT
#pragma once

/// @file maps/ld_radial.hpp
/// `LdRadialMap<T>`: the paper's LD-radial ("low-distortion radial") map (authors' code:
/// `concentric`), docs/math.md §4 — the Shirley–Chiu concentric map first, then the radial map with
/// u1 = angle/(2 pi) (azimuthal area fraction) and u2 = radius^2 (radial solid-angle fraction).
/// Both steps preserve area, so the composition does; it is continuous on the whole closed
/// square (centre → ellipse centre, boundary → ellipse boundary).
///
/// The composition itself (namespace detail: ld_sample, ld_invert) is written once for
/// LdRadialMap (over RadialMap) and TabulatedLdRadialMap (over TabulatedMap, tabulated.hpp):
/// `Radial` provides `ellipse()`, `sample_folded(fold, u2, iterations)` (the sample at a quadrant
/// and its area fraction) and `local_coordinates(l)` (docs/math.md §4 inverse on the unit local
/// direction l). The concentric map preserves area, so the
/// composition has the radial map's density.

#include <cmath>

#include "../config.hpp"
#include "../detail/math.hpp"
#include "../sample.hpp"
#include "../spherical_ellipse.hpp"
#include "../detail/concentric.hpp"
#include "../detail/glm.hpp"
#include "../detail/quadrant.hpp"
#include "cap.hpp"
#include "radial.hpp"

namespace apse {
namespace detail {

/// sample() of the LD composition over `radial` (`valid`: the radial map can sample). u is
/// clamped into [0, 1]^2; a NaN coordinate or !valid gives pdf 0 and the centre direction, with
/// `iterations` = 0; otherwise the radial map's sample at (turns, radius^2) of the concentric
/// image of u, its pdf and its `iterations` (the turns folded onto a quadrant directly from u,
/// detail::concentric_fold: no branches).
template <class T, class Radial>
APSE_HOT_INLINE DirectionSample<T> ld_sample(const Radial& radial, bool valid, const glm::vec<2, T>& u,
                                       int& iterations) noexcept {
    iterations = 0;
    bool ok = valid;
    const glm::vec<2, T> uc = clamp_unit(u, ok);
    if (!ok) return {radial.ellipse().z, T(0)};
    const ConcentricFold<T> disk = concentric_fold(uc);
    return radial.sample_folded(disk.fold, disk.radius2, iterations);
}

/// invert() of the LD composition over `radial`: the radial map's (u1, u2) of the world-space
/// direction `d` (any non-zero length), then the inverse concentric map of (radius sqrt(u2),
/// turns u1). !valid or a zero/NaN/infinite direction gives (0, 0).
template <class T, class Radial>
APSE_FUNC glm::vec<2, T> ld_invert(const Radial& radial, bool valid, const glm::vec<3, T>& d) noexcept {
    if (!valid) return glm::vec<2, T>(T(0));
    bool ok = true;
    const glm::vec<3, T> l = normalize_direction(radial.ellipse().to_local(d), ok);
    if (!ok) return glm::vec<2, T>(T(0));
    const glm::vec<2, T> polar = radial.local_coordinates(l);
    return concentric_from_disk(std::sqrt(polar.y), polar.x);
}

}  // namespace detail

namespace detail {

/// The LD-radial composition over the radial map `Radial` (detail::RadialMap or
/// detail::TabulatedMap): the concentric map first, then the radial map's sample at (turns,
/// radius^2) — the whole sampler interface, written once for LdRadialMap and
/// TabulatedLdRadialMap (maps/tabulated_ld_radial.hpp), which add their cap sampler. The
/// concentric map preserves area, so the composition has the radial map's density.
template <class Radial> class LdComposition {
public:
    using vec2 = typename Radial::vec2;   ///< a point of the unit square
    using vec3 = typename Radial::vec3;   ///< a 3-D vector (direction, point or normal)
    using T = typename vec3::value_type;  ///< float or double

    /// The ellipse this map samples.
    APSE_FUNC const SphericalEllipse<T>& ellipse() const noexcept { return radial_.ellipse(); }

    /// True if the map cannot sample (empty ellipse; tabulated: invalid table): every sample and
    /// pdf is then 0.
    APSE_FUNC bool empty() const noexcept { return radial_.empty(); }

    /// Direction for the point u of the unit square: world-space unit vector inside the ellipse
    /// with its density in solid angle (1/Omega for LdRadialMap; the tabulated map's own,
    /// exactly). u is clamped into [0, 1]^2; a NaN coordinate or an empty map gives pdf 0 (and
    /// the centre direction). The inversion iterations or table-walk steps:
    /// apse::sample_with_diagnostics (diagnostics.hpp).
    APSE_FUNC DirectionSample<T> sample(const vec2& u) const noexcept {
        int iterations = 0;
        return sample_counted(u, iterations);
    }

    /// The point of the unit square that sample() maps to the world-space direction `d` (any
    /// non-zero length): the radial map's inverse, then the inverse concentric map (exact inside
    /// the ellipse; the angle is undefined at the centre). Outside: the point whose image is the
    /// boundary point at the same azimuth; zero/NaN/infinite direction or empty map: (0, 0).
    APSE_FUNC vec2 invert(const vec3& d) const noexcept { return ld_invert(radial_, !radial_.empty(), d); }

    /// Density of sample() at `d`, in solid angle (the radial map's); 0 outside the ellipse.
    APSE_FUNC T pdf(const vec3& d) const noexcept { return radial_.pdf(d); }

    /// The underlying radial map.
    APSE_FUNC const Radial& radial() const noexcept { return radial_; }

    /// sample(u), counting the radial map's iterations (or table-walk steps) in `iterations`.
    APSE_HOT_INLINE DirectionSample<T> sample_counted(const vec2& u, int& iterations) const noexcept {
        return ld_sample(radial_, !radial_.empty(), u, iterations);
    }

protected:
    /// The radial map built in place from `args` (the ellipse, and the table for the tabulated map).
    template <class... Args>
    APSE_FUNC explicit LdComposition(const Args&... args) noexcept : radial_(args...) {}

    Radial radial_;
};

}  // namespace detail

/// LD-radial area-preserving map of the unit square onto a spherical ellipse (docs/math.md §4):
/// the radial map (comparison.hpp's RadialMap) composed with the concentric map
/// (detail::LdComposition; the same set-up, inversion and accuracy as the radial map),
/// continuous on the whole closed square; density 1/Omega. Trivially copyable.
template <class T> class LdRadialMap : public detail::LdComposition<detail::RadialMap<T>> {
    static_assert(detail::is_real_type<T>(), "apse: LdRadialMap<T>: T must be float or double");

public:
    /// What SphereLight holds for this map: the same samples on a cap, without the
    /// general-ellipse path (maps/cap.hpp).
    using CapSampler = detail::CapMap<T, true, false>;

    /// Builds the map for `ellipse` (empty allowed: every sample then has pdf 0).
    APSE_HOT_INLINE explicit LdRadialMap(const SphericalEllipse<T>& ellipse) noexcept
        : detail::LdComposition<detail::RadialMap<T>>(ellipse) {}

    /// Solid angle Omega of the ellipse (steradians); 0 when empty.
    APSE_FUNC T solid_angle() const noexcept { return this->radial_.solid_angle(); }
};

}  // namespace apse
