// apse — area-preserving parameterizations for spherical ellipses.
// SPDX-License-Identifier: MIT
#pragma once

/// @file projection.hpp
/// Shape → spherical ellipse seen from a shading point `o` (docs/math.md §2, §2b): disks in closed
/// form (projection_disk.hpp, the hot path of a disk light), oriented planar ellipses, spheres and
/// ellipsoids through their quadric tangent cone (projection_quadric.hpp). This header includes
/// both.
///
/// Conventions shared by every function here:
/// * Geometry is **two-sided**: a disk or ellipse seen from behind gives the same ellipse as
///   from the front. One-sided emitters cull with `disk_faces` / `ellipse_faces`.
/// * The result is a `SphericalEllipse<T>`; degenerate or invalid input gives the empty ellipse
///   (`empty()`, solid angle 0) — never NaN, never UB: non-positive, NaN or infinite sizes,
///   zero-length, parallel or non-finite axis vectors or normals, NaN/Inf coordinates, `o` in
///   the plane of a disk or ellipse (the integrand cos(theta_l) vanishes there: Omega = 0, also
///   for `o` exactly on the disk), `o` inside or on a sphere or ellipsoid, and lights so small or
///   so grazing that tan(beta) < 1e-19 (float) / 1e-154 (double) (their solid angle is below
///   ~4 tan(beta)).
/// * Lengths are rescaled internally by a power of two (exact), so any scene scale works,
///   from 1e-30 to 1e30 in float.
/// * Accuracy (docs/projection.md has the measured table): in double, alpha, beta and Omega to
///   ~1e-15 relative whenever the input is well conditioned; the subtraction center − o is the
///   one unavoidable rounding, so a point at height d above the plane (and h from the axis) of a
///   disk of radius r loses about log10(max(|c − o|, r)/d) digits when o is near the rim (|h − r|
///   ~ d) — e.g. 1e-8 relative at d = 1e-8 r in double. float: ~1e-6 relative (same caveat).

#include "projection_disk.hpp"
#include "projection_quadric.hpp"
