// apse — area-preserving parameterizations for spherical ellipses.
// SPDX-License-Identifier: MIT
#pragma once

/// @file detail/polar.hpp
/// The steps from a point of the unit square to a direction in the ellipse's frame that every map
/// shares (docs/math.md §4–5), written once here: every map solves its cumulative-area equation
/// on one quadrant (radial) or one half (parallel) of the ellipse and reaches the others by
/// reflection; the LD-radial maps first take the square to the disk.
///
/// * `clamp_unit` — the input policy for points of the square (NaN is reported, finite values
///   are clamped into [0, 1]);
/// * `normalize_direction` — the input policy for directions given to invert() (any non-zero
///   finite length; zero, NaN or infinite is reported);
/// * `fold_quadrant` / `unfold_quadrant_fraction` — u1 in [0, 1] ↔ (quadrant q, fraction f of
///   that quadrant's area measured from the major axis), reflected in odd quadrants so the map
///   is continuous across quadrant boundaries;
/// * `quadrant_of` / `place_in_quadrant` — a local direction ↔ (quadrant, |x|, |y|);
/// * `fold_half` / `unfold_half_fraction` — u1 in [0, 1] ↔ (side ±1 of the major axis, fraction
///   of that half's area measured from the minor-axis end), the parallel map's symmetry;
/// * the Shirley–Chiu concentric map of the unit square onto the unit disk and its inverse, in
///   polar form (`concentric_to_disk`, `concentric_fold`, `concentric_from_disk`). It is
///   area-preserving (up to the factor pi) and maps concentric squares to concentric circles, so
///   it keeps stratification. Used by uniform-by-area disk sampling (signed form: point =
///   radius (cos angle, sin angle), angle in [−pi/4, 3pi/4]) and by the LD-radial map
///   (azimuthal area fraction `turns` = angle / (2 pi), radial fraction radius^2);
/// * the polar step of the radial maps (`radial_direction`, `radial_fraction`), written once for
///   RadialMap and TabulatedMap: once u1 has fixed the azimuth, i.e. the boundary point of the
///   ellipse at that azimuth, u2 picks the polar angle uniformly in solid angle along the wedge
///   from the centre to that boundary point; and the inverse, u2 of a direction;
/// * the LD-radial composition over a radial map (`LdComposition`: the concentric map first, then
///   the radial map), written once for LdRadialMap and TabulatedLdRadialMap.

#include <cmath>
#include <type_traits>
#include <utility>

#include "../config.hpp"
#include "math.hpp"
#include "glm.hpp"

namespace apse {
namespace detail {

/// x clamped to [0, 1]; `ok` is cleared when x is NaN (the caller then reports "no sample").
template <class T> APSE_HOT_INLINE T clamp_unit(T x, bool& ok) noexcept {
    const bool nan = is_nan(x);
    if (nan) ok = false;
    return nan ? T(0) : clamp_non_nan(x, T(0), T(1));
}

/// The point u of the square with both coordinates through clamp_unit (x first, then y).
template <class T> APSE_HOT_INLINE glm::vec<2, T> clamp_unit(const glm::vec<2, T>& u, bool& ok) noexcept {
    const T x = clamp_unit(u.x, ok);
    const T y = clamp_unit(u.y, ok);
    return glm::vec<2, T>(x, y);
}

/// v divided by its length; `ok` is cleared (and v returned unchanged) when the length is zero,
/// NaN or infinite (the caller then reports "no point").
template <class T> APSE_FUNC glm::vec<3, T> normalize_direction(const glm::vec<3, T>& v, bool& ok) noexcept {
    const T len = std::sqrt(v.x * v.x + v.y * v.y + v.z * v.z);
    if (!(len > T(0)) || !is_finite(len)) {
        ok = false;
        return v;
    }
    return v / len;
}

/// A point of [0, 1] folded onto one quadrant.
template <class T> struct QuadrantFold {
    T sign_x;      ///< ±1: the quadrant as the signs of its x and y (counter-clockwise from the +x
    T sign_y;      ///< (major) axis: q = 0 (+, +), 1 (−, +), 2 (−, −), 3 (+, −))
    T fraction;    ///< fraction of the quadrant's area, measured from the major axis, in [0, 1]
};

/// u1 in [0, 1] → quadrant q = floor(4 u1) (u1 = 1 belongs to quadrant 3) and the fraction
/// f = 4 u1 − q, reflected (1 − f) in the odd quadrants: f is then always measured from the major
/// axis, and azimuth = q pi/2 + phi0 (q even) or (q + 1) pi/2 − phi0 (q odd) is continuous in u1.
/// Without branches (a random u1's quadrant is unpredictable): f is the triangle wave
/// 1 − |1 − |4 u1 − 2|| (exact for u1 >= 1/4; below, within one rounding of 2, 2^-52 in double),
/// y < 0 in the lower half (u1 > 1/2) and x < 0 in the middle quadrants (|4 u1 − 2| < 1). On the
/// quadrants' boundaries (u1 = 1/4, 1/2, 3/4) the point is on an axis, where the sign that
/// differs from q's multiplies zero.
template <class T> APSE_HOT_INLINE QuadrantFold<T> fold_quadrant(T u1) noexcept {
    const T g = std::fabs(T(4) * clamp(u1, T(0), T(1)) - T(2));  // distance from the −x axis, [0, 2]
    const T f = T(1) - std::fabs(T(1) - g);
    return {std::copysign(T(1), g - T(1)), std::copysign(T(1), T(0.5) - u1), clamp_non_nan(f, T(0), T(1))};
}

/// Inverse of fold_quadrant: (q, f) → u1 = (q + f)/4 (q even) or (q + 1 − f)/4 (q odd).
template <class T> APSE_FUNC T unfold_quadrant_fraction(int q, T f) noexcept {
    return ((q & 1) ? (T(q + 1) - f) : (T(q) + f)) * T(0.25);
}

/// Inverse of fold_quadrant from the fold itself, without branches (for a random point): the
/// quadrant's base (0, 2, 2, 4 quarter turns for q = 0..3, from the signs) plus the fraction,
/// reflected in the odd quadrants (where sign_x sign_y = −1).
template <class T> APSE_FUNC T unfold_quadrant(const QuadrantFold<T>& fold) noexcept {
    const T base = fold.sign_y > T(0) ? T(1) - fold.sign_x : T(3) + fold.sign_x;
    return T(0.25) * (base + fold.sign_x * fold.sign_y * fold.fraction);
}

/// Maps a first-quadrant local (x >= 0, y >= 0) onto the quadrant of `fold` by the reflections
/// (x, y) → (±x, ±y): (sign_x x, sign_y y, z). Exact (and free of branches).
template <class T>
APSE_HOT_INLINE glm::vec<3, T> place_in_quadrant(const QuadrantFold<T>& fold, T x, T y, T z) noexcept {
    return glm::vec<3, T>(fold.sign_x * x, fold.sign_y * y, z);
}

/// Quadrant of a local direction (the inverse of place_in_quadrant): q such that the reflections
/// of quadrant q (fold_quadrant) take (|x|, |y|) back to (x, y). Points on the axes go to the quadrant
/// for which the fraction is 0 or 1 consistently with fold_quadrant (+x axis → q = 0 with f = 0,
/// +y → q = 0 with f = 1, −x → q = 1 with f = 0, −y → q = 2 with f = 1: the same u1
/// as the neighbouring quadrant would give).
template <class T> APSE_FUNC int quadrant_of(T x, T y) noexcept {
    if (y >= T(0)) return (x >= T(0)) ? 0 : 1;
    return (x > T(0)) ? 3 : 2;
}

/// A point of [0, 1] folded onto one half of the ellipse (sides of the major axis).
template <class T> struct HalfFold {
    T side;      ///< −1 (u1 < 1/2: y < 0) or +1
    T fraction;  ///< fraction of the half's area measured from the minor-axis end, in [0, 1]
};

/// u1 in [0, 1] → side and edge fraction g: u1 < 1/2 → (−1, 2 u1); else (+1, 2 − 2 u1). Exact
/// (both products and the difference, by Sterbenz, are exact): g = 0 at the ends of the minor
/// axis (u1 = 0, 1), g = 1 on the major axis (u1 = 1/2).
template <class T> APSE_FUNC HalfFold<T> fold_half(T u1) noexcept {
    if (u1 < T(0.5)) return {T(-1), clamp(T(2) * u1, T(0), T(1))};
    return {T(1), clamp(T(2) - T(2) * u1, T(0), T(1))};
}

/// Inverse of fold_half: (side, g) → u1 = g/2 (side < 0) or 1 − g/2.
template <class T> APSE_FUNC T unfold_half_fraction(T side, T g) noexcept {
    return side < T(0) ? T(0.5) * g : T(1) - T(0.5) * g;
}

/// A point of the unit disk in polar form: `radius` in [0, 1], `turns` = angle / (2 pi) in
/// [0, 1) (computed directly, without rounding through pi).
template <class T> struct ConcentricPolar {
    T radius;  ///< in [0, 1]
    T turns;   ///< angle / (2 pi), in [0, 1)
    /// The polar angle in radians, in [0, 2 pi).
    APSE_FUNC T angle() const noexcept { return two_pi_v<T> * turns; }
};

/// Concentric map (docs/math.md §4): A = 2u1 − 1, B = 2u2 − 1; if |A| > |B|: radius |A|,
/// angle (pi/4)(B/A) (+pi if A < 0, +2pi if A > 0 > B); else radius |B|,
/// angle pi/2 − (pi/4)(A/B) (+pi if B < 0); the square's centre → (0, 0).
/// Domain [0, 1]^2; coordinates outside are clamped into it (NaN → 0).
template <class T> APSE_FUNC ConcentricPolar<T> concentric_to_disk(const glm::vec<2, T>& u) noexcept {
    const T a = T(2) * clamp(u.x, T(0), T(1)) - T(1);
    const T b = T(2) * clamp(u.y, T(0), T(1)) - T(1);
    if (a == T(0) && b == T(0)) return {T(0), T(0)};
    T radius, turns;
    if (std::fabs(a) > std::fabs(b)) {
        radius = std::fabs(a);
        turns = T(0.125) * (b / a);  // in (-1/8, 1/8)
        if (a < T(0)) turns += T(0.5);
        else if (turns < T(0)) turns += T(1);
    } else {
        radius = std::fabs(b);
        turns = T(0.25) - T(0.125) * (a / b);  // in [1/8, 3/8]
        if (b < T(0)) turns += T(0.5);
    }
    if (!(turns < T(1))) turns = T(0);  // 1 − tiny rounded up: the same point
    return {radius, turns};
}

/// The concentric map's point of u, folded as the LD-radial map reads it: the quadrant and the
/// fraction of its quarter turn that fold_quadrant(turns) gives, the radius and its square.
template <class T> struct ConcentricFold {
    QuadrantFold<T> fold;  ///< quadrant (signs of the disk point's x, y) and the fraction of the
                           ///< quarter turn measured from the x axis
    T radius;              ///< radius, in [0, 1]
    T radius2;             ///< radius^2
};

/// concentric_to_disk(u) folded onto the first quadrant, without branches: with A = 2u1 − 1 and
/// B = 2u2 − 1, the disk point's x has the sign of A and y that of B, the radius is
/// M = max(|A|, |B|), and the angle from the x axis is (pi/4)|B|/|A| (|A| > |B|) or
/// pi/2 − (pi/4)|A|/|B|: the fraction of the quarter turn is |B|/(2|A|) or 1 − |A|/(2|B|), both
/// 1/2 + (|B| − |A|)/(2M). The same point as fold_quadrant(concentric_to_disk(u).turns) up to
/// rounding (an absolute error of about one ulp of 1/2 in the fraction). u in [0, 1]^2, not
/// checked (the caller clamps: clamp_unit); the square's centre → radius 0.
template <class T> APSE_HOT_INLINE ConcentricFold<T> concentric_fold(const glm::vec<2, T>& u) noexcept {
    const T a = T(2) * u.x - T(1);
    const T b = T(2) * u.y - T(1);
    const T fa = std::fabs(a), fb = std::fabs(b);
    const T m = max_of(fa, fb);
    // (|B| − |A|)/(2M) with the centre (0/0) sent to 0: away from the centre M >= 2^-53 (a and b
    // are multiples of 2^-53), so the divisor is 2M itself there.
    const T fraction = T(0.5) + (fb - fa) / max_of(m + m, T(0x1p-64));
    return {{std::copysign(T(1), a), std::copysign(T(1), b), clamp_non_nan(fraction, T(0), T(1))}, m, m * m};
}

/// A point of the unit disk in signed polar form: radius (cos angle, sin angle) with `radius`
/// in [−1, 1] and `angle` in [−pi/4, 3pi/4] (the form a renderer writes: no angle wrapping).
template <class T> struct ConcentricSigned {
    T radius;  ///< in [−1, 1]
    T angle;   ///< radians, in [−pi/4, 3pi/4]
};

/// The concentric map's point of u (the same point as concentric_to_disk(u)), in signed polar
/// form: A = 2u1 − 1, B = 2u2 − 1; if |A| > |B|: (A, (pi/4)(B/A)), else (B, pi/2 − (pi/4)(A/B));
/// the square's centre → (0, 0). One division. Domain [0, 1]^2; coordinates outside are clamped
/// into it (NaN → 0).
template <class T> APSE_HOT_INLINE ConcentricSigned<T> concentric_to_disk_signed(const glm::vec<2, T>& u) noexcept {
    const T a = T(2) * clamp(u.x, T(0), T(1)) - T(1);
    const T b = T(2) * clamp(u.y, T(0), T(1)) - T(1);
    const T quarter_pi = T(0.25) * pi_v<T>;
    if (std::fabs(a) > std::fabs(b)) return {a, quarter_pi * (b / a)};
    if (b == T(0)) return {T(0), T(0)};
    return {b, half_pi_v<T> - quarter_pi * (a / b)};
}

/// Inverse of concentric_to_disk: the square point of the disk point (radius, turns) (radius in
/// [0, 1], turns = angle / (2 pi), any real: reduced modulo 1). Radii above 1 are clamped to 1.
template <class T> APSE_FUNC glm::vec<2, T> concentric_from_disk(T radius, T turns) noexcept {
    const T rho = clamp(radius, T(0), T(1));
    T t = turns - std::floor(turns);  // [0, 1]
    if (!(t >= T(0) && t < T(1))) t = T(0);
    const T s = T(8) * t;  // eighths of a turn, [0, 8)
    T a, b;
    if (s < T(1) || s >= T(7)) {  // right sector: A = rho, B/A = 8 turns (turns in [-1/8, 1/8))
        a = rho;
        b = rho * (s < T(1) ? s : s - T(8));
    } else if (s < T(3)) {  // top: B = rho, A/B = 2 − 8 turns
        b = rho;
        a = rho * (T(2) - s);
    } else if (s < T(5)) {  // left: A = −rho, B/A = 8 turns − 4
        a = -rho;
        b = -rho * (s - T(4));
    } else {  // bottom: B = −rho, A/B = 6 − 8 turns
        b = -rho;
        a = -rho * (T(6) - s);
    }
    return glm::vec<2, T>(T(0.5) * (a + T(1)), T(0.5) * (b + T(1)));
}

/// The ellipse's semi-axis constants that the polar step of the radial maps needs (the boundary
/// point of an azimuth and C(tau)): all that the tabulated maps keep.
template <class T> struct EllipseAxes {
    T a, b;          ///< sin alpha, sin beta
    T ca, cb;        ///< cos alpha, cos beta
    T ca2, cb2;      ///< their squares

    /// The constants of `e` (a SphericalEllipse<T>).
    template <class Ellipse> static APSE_FUNC EllipseAxes make(const Ellipse& e) noexcept {
        return {e.sin_alpha, e.sin_beta, e.cos_alpha, e.cos_beta, e.cos_alpha * e.cos_alpha, e.cos_beta * e.cos_beta};
    }

    /// C(tau) = cos theta_max from (cos tau, sin tau).
    APSE_FUNC T c_max(T ct, T st) const noexcept { return std::sqrt(ca2 * ct * ct + cb2 * st * st); }
};

/// The local direction (x along the major axis, z the centre) at the solid-angle fraction u2 in
/// [0, 1] of the wedge towards the first-quadrant boundary point with orthographic eccentric
/// anomaly (cos tau, sin tau) = (px, py)/n, given unnormalised (any n > 0: n = 1 for a unit
/// pair), and cos theta_max = c there (k.c_max), reflected into quadrant q (place_in_quadrant).
/// `g` = 1/(n^2 (1 + C)) (the caller may have it from a paired or shared division).
/// sin theta_max = r = |(a cos tau, b sin tau)|; 1 − cos theta = v = u2 (1 − C), 1 − C = r^2/(1 + C),
/// so v = u2 |(a px, b py)|^2 g; cos theta = (1 − u2) + u2 C (no cancellation near the horizon of
/// large ellipses); the in-plane part is (a px, b py) sin theta / (n r), with
/// sin theta / (n r) = sqrt(u2 (2 − v) g): no division here and one square root (r itself is
/// never needed). u2 = 0 gives the centre, u2 = 1 the boundary point.
template <class T>
APSE_FUNC glm::vec<3, T> radial_direction(const EllipseAxes<T>& k, const QuadrantFold<T>& q, T px, T py, T c, T g,
                                          T u2) noexcept {
    const T ax = k.a * px, by = k.b * py;
    const T v = u2 * ((ax * ax + by * by) * g);
    const T scale = std::sqrt(u2 * (T(2) - v) * g);
    return place_in_quadrant(q, ax * scale, by * scale, (T(1) - u2) + u2 * c);
}

/// radial_direction for a unit (cos tau, sin tau) = (ct, st), with 1/(1 + C) computed here (one
/// division).
template <class T>
APSE_FUNC glm::vec<3, T> radial_direction(const EllipseAxes<T>& k, const QuadrantFold<T>& q, T ct, T st, T c,
                                          T u2) noexcept {
    return radial_direction(k, q, ct, st, c, T(1) / (T(1) + c), u2);
}

/// The orthographic eccentric anomaly (cos tau, sin tau) of the Lambert anomaly lambda given as
/// (cl, sl) = (cos lambda, sin lambda) >= 0: tan tau = kappa tan lambda, kappa =
/// cos(alpha/2)/cos(beta/2) (the equal-area image of a small ellipse, exact for caps; the radial
/// map's first guess and the tabulated map's variable). Writes (ct, st), both >= 0.
template <class T> APSE_FUNC void lambert_tau(T kappa, T cl, T sl, T& ct, T& st) noexcept {
    const T px = cl, py = kappa * sl, n = std::sqrt(px * px + py * py);
    ct = n > T(0) ? px / n : T(1);
    st = n > T(0) ? py / n : T(0);
}

/// The two terms of the inverse of radial_direction's u2: u2 = one_minus_cos / one_minus_c.
template <class T> struct RadialFraction {
    T one_minus_cos;  ///< 1 − cos theta of the direction
    T one_minus_c;    ///< 1 − C of the boundary point at its azimuth
};

/// The terms of u2 for the unit local direction (x, y, z), z > 0 (x, y of either sign), whose
/// azimuth has the first-quadrant boundary point (ct, st) with cos theta_max = c there:
/// 1 − z = (x^2 + y^2)/(1 + z) and 1 − C = r^2/(1 + C) (both without cancellation). The caller
/// divides and clamps (and chooses what a zero 1 − C gives).
template <class T>
APSE_FUNC RadialFraction<T> radial_fraction(const EllipseAxes<T>& k, T x, T y, T z, T ct, T st, T c) noexcept {
    const T ax = k.a * ct, by = k.b * st;
    const T one_minus_z = (x * x + y * y) / (T(1) + z);
    const T one_minus_c = (ax * ax + by * by) / (T(1) + c);
    return {one_minus_z, one_minus_c};
}

/// sample() of the LD composition over `radial` (`valid`: the radial map can sample). u is
/// clamped into [0, 1]^2; a NaN coordinate or !valid gives pdf 0 and the centre direction, with
/// `iterations` = 0; otherwise the radial map's sample at (turns, radius^2) of the concentric
/// image of u, its pdf and its `iterations` (the turns folded onto a quadrant directly from u,
/// detail::concentric_fold: no branches).
template <class T, class Radial>
APSE_HOT_INLINE auto ld_sample(const Radial& radial, bool valid, const glm::vec<2, T>& u, int& iterations) noexcept {
    using Sample = decltype(radial.sample_folded(QuadrantFold<T>{}, T(0), iterations));  // DirectionSample<T>
    iterations = 0;
    bool ok = valid;
    const glm::vec<2, T> uc = clamp_unit(u, ok);
    if (!ok) return Sample{radial.ellipse().z, T(0)};
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

/// The LD-radial composition over the radial map `Radial` (detail::RadialMap or
/// detail::TabulatedMap): the concentric map first, then the radial map's sample at (turns,
/// radius^2) — the whole sampler interface, written once for LdRadialMap and
/// TabulatedLdRadialMap, which add their cap sampler. `Radial` provides `ellipse()`, `empty()`,
/// `pdf(d)`, `sample_folded(fold, u2, iterations)` (the sample at a quadrant and its area
/// fraction) and `local_coordinates(l)` (docs/math.md §4 inverse on the unit local direction
/// l). The concentric map preserves area, so the composition has the radial map's density.
template <class Radial> class LdComposition {
public:
    using vec2 = typename Radial::vec2;   ///< a point of the unit square
    using vec3 = typename Radial::vec3;   ///< a 3-D vector (direction, point or normal)
    using T = typename vec3::value_type;  ///< float or double
    /// SphericalEllipse<T> (named through the radial map: this header needs no public type)
    using Ellipse = std::decay_t<decltype(std::declval<const Radial&>().ellipse())>;
    /// DirectionSample<T>
    using Sample = decltype(std::declval<const Radial&>().sample_folded(QuadrantFold<T>{}, T(0), std::declval<int&>()));

    /// The ellipse this map samples.
    APSE_FUNC const Ellipse& ellipse() const noexcept { return radial_.ellipse(); }

    /// True if the map cannot sample (empty ellipse; tabulated: invalid table): every sample and
    /// pdf is then 0.
    APSE_FUNC bool empty() const noexcept { return radial_.empty(); }

    /// Direction for the point u of the unit square: world-space unit vector inside the ellipse
    /// with its density in solid angle (1/Omega for LdRadialMap; the tabulated map's own,
    /// exactly). u is clamped into [0, 1]^2; a NaN coordinate or an empty map gives pdf 0 (and
    /// the centre direction). The inversion iterations or table-walk steps:
    /// apse::sample_with_diagnostics (diagnostics.hpp).
    APSE_FUNC Sample sample(const vec2& u) const noexcept {
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
    APSE_HOT_INLINE Sample sample_counted(const vec2& u, int& iterations) const noexcept {
        return ld_sample(radial_, !radial_.empty(), u, iterations);
    }

protected:
    /// The radial map built in place from `args` (the ellipse, and the table for the tabulated map).
    template <class... Args>
    APSE_FUNC explicit LdComposition(const Args&... args) noexcept : radial_(args...) {}

    Radial radial_;
};

}  // namespace detail
}  // namespace apse
