// apse — area-preserving parameterizations for spherical ellipses.
// SPDX-License-Identifier: MIT
#pragma once

/// @file baselines/gamito.hpp
/// The Gamito (EGSR 2016) baseline for disk lights, docs/math.md §7: sample the spherical rectangle
/// of the disk's circumscribed square (side 2r, one edge along the symmetry plane through o,
/// the centre and the normal) with the Ureña–Fajardo–King map (rectangle.hpp) and reject what
/// misses the disk. Two **unbiased** variants — the pdf each reports is the density it really
/// draws from (the authors' code reports 1/Omega_disk for single-shot samples and counts the
/// rejections as zero, which is biased low by the acceptance rate, ~0.75–0.83):
///  * GamitoSingleShot: one attempt; accepted -> pdf 1/Omega_square, rejected -> pdf 0.
///  * GamitoRetry: up to N attempts; the first accepted one is returned with pdf
///    (1 − (1 − A)^N) / Omega_disk, A = Omega_disk / Omega_square; N failures -> pdf 0.
/// Rejection spoils stratification (the paper's criticism): only the first attempt uses u.

#include <cmath>
#include <cstdint>
#include <cstring>

#include "../config.hpp"
#include "../detail/glm.hpp"
#include "../detail/vector.hpp"
#include "../detail/math.hpp"
#include "../projection_disk.hpp"
#include "../sample.hpp"
#include "../spherical_rectangle.hpp"

namespace apse {
namespace detail {

/// The disk's circumscribed square as a SphericalRectangle seen from o (docs/math.md §7): centred on
/// `center`, side 2·radius, edge_y along the in-plane direction from o's foot point to the
/// centre (any in-plane direction when o is on the axis), edge_x = edge_y × normal. Empty for
/// radius <= 0, a zero or non-finite normal, NaN/Inf coordinates, o in the plane.
template <class T>
APSE_FUNC SphericalRectangle<T> gamito_square(const glm::vec<3, T>& o, const glm::vec<3, T>& center,
                                              const glm::vec<3, T>& normal, T radius) noexcept {
    using vec3 = glm::vec<3, T>;  ///< a 3-D vector (direction, point or normal)
    const vec3 n = robust_normalize(normal);
    const vec3 w0 = center - o;
    if (!(radius > T(0)) || !detail::is_finite(radius) || !(glm::dot(n, n) > T(0)) || !finite3(w0))
        return SphericalRectangle<T>();
    const vec3 w = pow2_scale_for(detail::max_of(max_abs3(w0), T(1)))(w0);  // no overflow in the dots
    vec3 v = w - glm::dot(w, n) * n;  // foot of o -> centre, in the plane
    v -= glm::dot(v, n) * n;          // second Gram–Schmidt pass: exactly in the plane
    vec3 yd = robust_normalize(v);
    if (!(glm::dot(yd, yd) > T(0))) yd = any_perpendicular(n);  // on the axis
    const vec3 xd = glm::cross(yd, n);
    return SphericalRectangle<T>::from_center(o, center, radius * xd, radius * yd);
}

/// True if the rectangle coordinates st of a point of the circumscribed square lie in the disk
/// (the inscribed circle of [0,1]², boundary included).
template <class T> APSE_FUNC bool in_inscribed_disk(const glm::vec<2, T>& st) noexcept {
    const T a = T(2) * st.x - T(1), b = T(2) * st.y - T(1);
    return a * a + b * b <= T(1);
}

/// GamitoSingleShot's density at the world-space `direction`, in solid angle: the square's
/// 1/Omega_square where the direction meets the square inside its inscribed disk, else 0 (also
/// for NaN directions or an empty square). GamitoRetry's density is positive exactly where this is.
template <class T>
APSE_FUNC T on_disk_square_pdf(const SphericalRectangle<T>& square, const glm::vec<3, T>& direction) noexcept {
    const RectanglePoint<T> p = square.locate(direction);
    return in_inscribed_disk(p.st) ? p.pdf : T(0);
}

/// splitmix64's output function (a bijective 64-bit mixer with full avalanche).
APSE_FUNC std::uint64_t mix64(std::uint64_t z) noexcept {
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
}

/// The bit pattern of a float or double (zero-extended to 64 bits).
template <class T> APSE_FUNC std::uint64_t bits_of(T x) noexcept {
#if defined(__CUDA_ARCH__)
    if constexpr (sizeof(T) == sizeof(float)) return std::uint64_t(__float_as_uint(x));
    else return std::uint64_t(__double_as_longlong(x));
#else
    if constexpr (sizeof(T) == sizeof(float)) {
        std::uint32_t b;
        std::memcpy(&b, &x, sizeof b);
        return b;
    } else {
        std::uint64_t b;
        std::memcpy(&b, &x, sizeof b);
        return b;
    }
#endif
}

/// A number in [0, 1) from the top 24 (float) or 53 (double) bits of z.
template <class T> APSE_FUNC T unit_from_bits(std::uint64_t z) noexcept {
    if constexpr (sizeof(T) == sizeof(float)) return T(z >> 40) * T(0x1p-24);
    else return T(z >> 11) * T(0x1p-53);
}

/// The deterministic point sequence of GamitoRetry: attempt 0 is u itself; attempt k >= 1 is
/// (unit_from_bits(mix64(key + k γ)), unit_from_bits(mix64(key + k γ + δ))) with
/// key = mix64(bits(u.x) ^ mix64(bits(u.y))) and γ, δ odd 64-bit constants — a counter-based
/// generator keyed by u's bits, so retries behave as independent uniform points for all
/// practical purposes (the same assumption as any pseudo-random renderer).
template <class T> struct AttemptSequence {
    std::uint64_t key;
    APSE_FUNC explicit AttemptSequence(const glm::vec<2, T>& u) noexcept
        : key(mix64(bits_of(u.x) ^ mix64(bits_of(u.y) + 0x632be59bd9b4e019ULL))) {}
    APSE_FUNC glm::vec<2, T> operator()(const glm::vec<2, T>& u, int k) const noexcept {
        if (k == 0) return u;
        const std::uint64_t c = key + std::uint64_t(k) * 0x9e3779b97f4a7c15ULL;
        return glm::vec<2, T>(unit_from_bits<T>(mix64(c)), unit_from_bits<T>(mix64(c + 0xd1b54a32d192ed03ULL)));
    }
};

}  // namespace detail

/// Gamito single shot: one Ureña sample of the disk's circumscribed square (docs/math.md §7); if it
/// lands on the disk it is returned with pdf 1/Omega_square (the density it was drawn from),
/// otherwise "no sample" (pdf 0). E[f/pdf · 1_sample] = int_disk f: unbiased. Acceptance
/// probability Omega_disk/Omega_square (~0.75–0.83; far-field limit pi/4 for a frontal disk).
/// Cheap set-up: no elliptic integral (Omega_disk is never needed).
/// Domain as project_disk: `normal` any finite non-zero vector, radius > 0, two-sided; empty
/// (every pdf 0) for degenerate input or o in the disk's plane. Measure: solid angle.
template <class T> class GamitoSingleShot {
    static_assert(detail::is_real_type<T>(), "apse: GamitoSingleShot<T>: T must be float or double");

public:
    using vec2 = glm::vec<2, T>;  ///< a point of the unit square
    using vec3 = glm::vec<3, T>;  ///< a 3-D vector (direction, point or normal)

    /// An empty sampler.
    GamitoSingleShot() = default;

    /// The sampler of the disk {p : (p − center)·normal = 0, |p − center| <= radius} seen from o.
    APSE_FUNC GamitoSingleShot(const vec3& o, const vec3& center, const vec3& normal, T radius) noexcept
        : square_(detail::gamito_square(o, center, normal, radius)) {}

    /// True if no sample can be produced (degenerate disk, o in its plane).
    APSE_FUNC bool empty() const noexcept { return square_.empty(); }

    /// The circumscribed square's spherical rectangle (its solid angle: `.solid_angle()`).
    APSE_FUNC const SphericalRectangle<T>& bounding_rectangle() const noexcept { return square_; }

    /// One attempt at u in [0,1]² (clamped): the point, direction and pdf 1/Omega_square if it
    /// is on the disk; pdf 0 ("no sample", direction still a finite unit vector) if rejected.
    APSE_FUNC RectanglePoint<T> sample_point(const vec2& u) const noexcept {
        RectanglePoint<T> p = square_.sample_point(u);
        if (!detail::in_inscribed_disk(p.st)) p.pdf = T(0);
        return p;
    }

    /// `sample_point(u)` reduced to direction and solid-angle pdf.
    APSE_FUNC DirectionSample<T> sample(const vec2& u) const noexcept {
        const RectanglePoint<T> p = sample_point(u);
        return {p.direction, p.pdf};
    }

    /// The density `sample` draws from, in solid angle: 1/Omega_square on the disk, 0 off it
    /// (and for NaN directions or an empty sampler).
    APSE_FUNC T pdf(const vec3& direction) const noexcept { return detail::on_disk_square_pdf(square_, direction); }

private:
    SphericalRectangle<T> square_;
};

/// Gamito with bounded retries: up to `max_attempts` = N Ureña samples of the circumscribed
/// square (docs/math.md §7), the first on u and the others on the deterministic pseudo-random
/// sequence detail::AttemptSequence keyed by u's bits (no unbounded loop). The first one that
/// lands on the disk is returned with its exact density
///     pdf = (1 − (1 − A)^N) / Omega_disk,   A = Omega_disk / Omega_square
/// (each attempt accepts with probability A; given success the direction is uniform over the
/// disk; success has probability 1 − (1 − A)^N); N failures give "no sample" (pdf 0). Unbiased.
/// Omega_disk (solid_angle()) comes from project_disk(...).solid_angle() (one Carlson R_J at set-up; no closed
/// form in elementary functions exists for an off-axis disk). N is clamped to [1, 64]; N = 1 is
/// GamitoSingleShot with an extra elliptic integral. Domain and empty rules as GamitoSingleShot
/// (also empty if project_disk finds the disk empty). Measure: solid angle.
template <class T> class GamitoRetry {
    static_assert(detail::is_real_type<T>(), "apse: GamitoRetry<T>: T must be float or double");

public:
    using vec2 = glm::vec<2, T>;  ///< a point of the unit square
    using vec3 = glm::vec<3, T>;  ///< a 3-D vector (direction, point or normal)

    /// An empty sampler.
    GamitoRetry() = default;

    /// The sampler of the disk {p : (p − center)·normal = 0, |p − center| <= radius} seen from o.
    APSE_FUNC GamitoRetry(const vec3& o, const vec3& center, const vec3& normal, T radius,
                          int max_attempts = 8) noexcept
        : square_(detail::gamito_square(o, center, normal, radius)),
          attempts_(max_attempts < 1 ? 1 : (max_attempts > 64 ? 64 : max_attempts)) {
        const T disk = project_disk(o, center, normal, radius).solid_angle();
        const T square = square_.solid_angle();
        if (!(disk > T(0) && square > T(0))) return;
        disk_solid_angle_ = disk;
        acceptance_ = detail::min_of(disk / square, T(1));
        success_ = -std::expm1(T(attempts_) * std::log1p(-acceptance_));  // 1 − (1 − A)^N
        pdf_ = success_ / disk;
        if (!(pdf_ > T(0)) || !detail::is_finite(pdf_)) pdf_ = T(0);
    }

    /// True if no sample can be produced (degenerate disk, o in its plane).
    APSE_FUNC bool empty() const noexcept { return !(pdf_ > T(0)); }

    /// The circumscribed square's spherical rectangle.
    APSE_FUNC const SphericalRectangle<T>& bounding_rectangle() const noexcept { return square_; }
    /// N, the maximal number of attempts per sample.
    APSE_FUNC int max_attempts() const noexcept { return attempts_; }
    /// Omega_disk, the solid angle of the disk sampled (steradians, two-sided; 0 if empty).
    APSE_FUNC T solid_angle() const noexcept { return disk_solid_angle_; }
    /// A = Omega_disk / Omega_square, the acceptance probability of one attempt.
    APSE_FUNC T acceptance() const noexcept { return acceptance_; }
    /// 1 − (1 − A)^N, the probability that `sample` returns a sample.
    APSE_FUNC T success_probability() const noexcept { return success_; }

    /// Up to N attempts starting at u in [0,1]² (clamped): the first point on the disk with
    /// pdf (1 − (1 − A)^N)/Omega_disk; if all N miss, the last attempt with pdf 0 ("no sample").
    APSE_FUNC RectanglePoint<T> sample_point(const vec2& u) const noexcept {
        if (empty()) {
            RectanglePoint<T> p = square_.sample_point(u);
            p.pdf = T(0);
            return p;
        }
        const vec2 u0(detail::clamp(u.x, T(0), T(1)), detail::clamp(u.y, T(0), T(1)));
        const detail::AttemptSequence<T> seq(u0);
        RectanglePoint<T> p;
        for (int k = 0; k < attempts_; ++k) {
            p = square_.sample_point(seq(u0, k));
            if (detail::in_inscribed_disk(p.st)) {
                p.pdf = pdf_;
                return p;
            }
        }
        p.pdf = T(0);
        return p;
    }

    /// `sample_point(u)` reduced to direction and solid-angle pdf.
    APSE_FUNC DirectionSample<T> sample(const vec2& u) const noexcept {
        const RectanglePoint<T> p = sample_point(u);
        return {p.direction, p.pdf};
    }

    /// The density `sample` draws from, in solid angle: (1 − (1 − A)^N)/Omega_disk on the disk,
    /// 0 off it (and for NaN directions or an empty sampler).
    APSE_FUNC T pdf(const vec3& direction) const noexcept {
        return detail::on_disk_square_pdf(square_, direction) > T(0) ? pdf_ : T(0);
    }

private:
    SphericalRectangle<T> square_;
    int attempts_ = 1;
    T disk_solid_angle_ = T(0), acceptance_ = T(0), success_ = T(0), pdf_ = T(0);
};

}  // namespace apse
