#!/usr/bin/env python3
"""Reference tables for apse's rectangle and Gamito baselines (tests/data/rectangle/).

    python3 tools/gen_rectangle_reference.py            # rewrites tests/data/rectangle/*.txt

Seeded and reproducible (the same files byte for byte on every run); needs only mpmath.
Every input is exactly representable in float32 and written as a hex float (float.hex()), so the
float and the double tests see the same geometry. References are computed with mpmath at 60
digits and written with 30 significant digits.

solid_angle.txt   planar rectangle (o, corner s, edges ex, ey; ex . ey == 0 exactly, integer edge
                  directions) -> solid angle seen from o (two-sided). Computed with the exact
                  corner formula  Omega = sum +-atan(x y / (d sqrt(x^2 + y^2 + d^2)))  at 60 digits
                  (it cancels at most ~20 digits here) and checked against an independent
                  quadrature, int_{x0}^{x1} d (y/((x^2+d^2) sqrt(x^2+y^2+d^2)))|_{y0}^{y1} dx
                  (the inner y-integral of cos(theta)/dist^2 done exactly), to <= 1e-25.
                  kappa = 1 + (|s - o| + |ex| + |ey|) / d is the condition number of the solid
                  angle with respect to the float rounding of the inputs' difference (the plane
                  distance d is the small quantity when o grazes the plane).
map.txt           reference points of the Urena-Fajardo-King map u -> direction, solved at 60
                  digits from the definition (u1 = solid angle of the sub-rectangle [x0, x] x
                  [y0, y1] / Omega by bisection; u2 uniform in h = y / sqrt(x^2 + y^2 + d^2)).
gamito_disks.txt  disks (o, centre c, normal n (not unit), radius r) -> solid angle of the disk,
                  int over the disk of cos(theta) d(omega) with cos(theta) = omega . z_d (z_d: the
                  plane normal pointing from o towards the plane), and the solid angle of the
                  bounding square of docs/math.md §7. Disk integrals by quadrature in polar
                  coordinates about o's foot point (radial part exact), cos integral checked
                  against the closed-form parallel disk form factor, square against the rectangle
                  quadrature above.
"""

import os
import random
import sys

import mpmath as mp

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from mp_reference import f32, hexf, dec, mvec, dot, cross, sub, add, scale, norm  # noqa: E402

mp.mp.dps = 60
SEED = 20130619
OUT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "tests", "data", "rectangle")


# ------------------------------------------------------------------------------------------------
# planar rectangle
# ------------------------------------------------------------------------------------------------


def local_frame(o, s, ex, ey):
    """(x0, x1, y0, y1, d, frame) of the rectangle in coordinates about o (exact orthogonal edges)."""
    o, s, ex, ey = mvec(o), mvec(s), mvec(ex), mvec(ey)
    assert dot(ex, ey) == 0
    w, h = norm(ex), norm(ey)
    xh, yh = scale(ex, 1 / w), scale(ey, 1 / h)
    zh = cross(xh, yh)
    delta = sub(s, o)
    x0, y0, z0 = dot(delta, xh), dot(delta, yh), dot(delta, zh)
    return x0, x0 + w, y0, y0 + h, abs(z0), (xh, yh, zh, delta, w, h)


def corner_term(x, y, d):
    return mp.atan(x * y / (d * mp.sqrt(x * x + y * y + d * d)))


def rect_omega_exact(x0, x1, y0, y1, d):
    if d == 0:
        return mp.mpf(0)
    return (corner_term(x1, y1, d) - corner_term(x0, y1, d)
            - corner_term(x1, y0, d) + corner_term(x0, y0, d))


def rect_omega_quad(x0, x1, y0, y1, d):
    """int_{x0}^{x1} dx int_{y0}^{y1} d dy / (x^2+y^2+d^2)^{3/2}, inner integral exact."""
    if d == 0:
        return mp.mpf(0)

    def column(x):
        q = x * x + d * d
        return d * (y1 / mp.sqrt(q + y1 * y1) - y0 / mp.sqrt(q + y0 * y0)) / q

    pts = [x0]
    # resolve the peak of the integrand at the foot point (x = 0) and its width d
    for p in (-d, 0, d):
        if x0 < p < x1:
            pts.append(p)
    pts.append(x1)
    return mp.quad(column, sorted(pts), maxdegree=12)


def strip_omega_exact(x0, x, y0, y1, d):
    return rect_omega_exact(x0, x, y0, y1, d)


def reference_map(x0, x1, y0, y1, d, frame, u1, u2):
    """Direction (world, unit) and rectangle coordinates (s, t) of the map at (u1, u2)."""
    xh, yh, zh, delta, w, h = frame
    total = rect_omega_exact(x0, x1, y0, y1, d)
    target = mp.mpf(u1) * total
    lo, hi = x0, x1
    for _ in range(mp.mp.prec + 8):  # bisection to full working precision
        mid = (lo + hi) / 2
        if strip_omega_exact(x0, mid, y0, y1, d) < target:
            lo = mid
        else:
            hi = mid
    x = (lo + hi) / 2
    q = x * x + d * d
    h0 = y0 / mp.sqrt(q + y0 * y0)
    h1 = y1 / mp.sqrt(q + y1 * y1)
    hv = (1 - mp.mpf(u2)) * h0 + mp.mpf(u2) * h1
    y = hv * mp.sqrt(q) / mp.sqrt(1 - hv * hv)
    v = add(add(delta, scale(xh, x - x0)), scale(yh, y - y0))
    return scale(v, 1 / norm(v)), (x - x0) / w, (y - y0) / h


def rand_f32(rng, lo, hi):
    return f32(rng.uniform(lo, hi))


def rand_int_vec(rng, m=9):
    while True:
        v = [rng.randint(-m, m) for _ in range(3)]
        if any(v):
            return v


def orthogonal_edges(rng, size_x, size_y):
    """Integer edge directions p and p x q (exactly orthogonal), scaled by powers of two so the
    edge lengths are within a factor 2 of the requested sizes; float32-exact."""
    while True:
        p = rand_int_vec(rng)
        q = rand_int_vec(rng)
        e = cross(p, q)
        if any(e):
            break
    lp = float(norm(mvec(p)))
    le = float(norm(mvec(e)))
    kx = round(mp.log(size_x / lp, 2))
    ky = round(mp.log(size_y / le, 2))
    ex = [f32(t * 2.0 ** kx) for t in p]
    ey = [f32(t * 2.0 ** ky) for t in e]
    assert [t * 2.0 ** kx for t in p] == ex and [t * 2.0 ** ky for t in e] == ey
    return ex, ey


def axis_rect(w, h):
    return [f32(w), 0.0, 0.0], [0.0, f32(h), 0.0]


def rectangle_configs(rng):
    cfgs = []

    def add_cfg(name, o, s, ex, ey):
        o, s = [f32(t) for t in o], [f32(t) for t in s]
        cfgs.append((name, o, s, ex, ey))

    # 1. random orientations, sizes and positions
    for i in range(60):
        ex, ey = orthogonal_edges(rng, 2.0 ** rng.uniform(-2, 1.5), 2.0 ** rng.uniform(-2, 1.5))
        s = [rand_f32(rng, -2, 2) for _ in range(3)]
        o = [rand_f32(rng, -2, 2) for _ in range(3)]
        add_cfg("random%02d" % i, o, s, ex, ey)
    # 2. axis-aligned unit square [0,1]^2 at z = 0, o close above (inside / outside / edge / corner)
    ex, ey = axis_rect(1, 1)
    for i, (px, py, d) in enumerate([(0.5, 0.5, 1e-3), (0.25, 0.75, 1e-2), (0.5, 0.5, 0.25),
                                     (0.0, 0.5, 0.1), (0.0, 0.0, 0.05), (1.5, 0.5, 0.5),
                                     (0.5, 0.5, 1e-6), (0.999, 0.001, 1e-4), (-0.5, -0.5, 0.2),
                                     (0.5, 0.5, -0.3)]):
        add_cfg("near%02d" % i, [px, py, d], [0, 0, 0], ex, ey)
    # 3. far away: on axis and oblique, unit square and random orientations
    for i, dist in enumerate([1e2, 1e4, 1e6, 1e8]):
        add_cfg("far_axis_%g" % dist, [0.5, 0.5, dist], [0, 0, 0], ex, ey)
        add_cfg("far_oblique_%g" % dist, [0.577 * dist, -0.577 * dist, 0.577 * dist], [0, 0, 0], ex, ey)
        exr, eyr = orthogonal_edges(rng, 1.0, 1.0)
        direction = [rng.gauss(0, 1) for _ in range(3)]
        ln = sum(t * t for t in direction) ** 0.5
        add_cfg("far_random_%g" % dist, [t / ln * dist for t in direction], [0.25, -0.5, 1.0], exr, eyr)
    # 4. grazing: o almost in the plane, outside the rectangle; and exactly in the plane
    for i, (px, py, d) in enumerate([(2.0, 0.5, 1e-6), (0.5, -3.0, 1e-4), (5.0, 5.0, 1e-3),
                                     (-1.0, 0.25, 2.0 ** -30), (30.0, 0.5, 0.01)]):
        add_cfg("grazing%02d" % i, [px, py, d], [0, 0, 0], ex, ey)
    add_cfg("in_plane_outside", [2.0, 0.5, 0.0], [0, 0, 0], ex, ey)
    add_cfg("in_plane_inside", [0.5, 0.5, 0.0], [0, 0, 0], ex, ey)
    # 5. tiny rectangles at distance ~1 (on axis, oblique, random orientation)
    for k in (-10, -20, -33):
        w = 2.0 ** k
        et, ft = axis_rect(w, w * 0.75)
        add_cfg("tiny_axis_2^%d" % k, [0.0, 0.0, 1.0], [0, 0, 0], et, ft)
        add_cfg("tiny_oblique_2^%d" % k, [-0.75, 0.5, 0.5], [0, 0, 0], et, ft)
        exr, eyr = orthogonal_edges(rng, w, w)
        add_cfg("tiny_random_2^%d" % k, [rand_f32(rng, -1, 1) for _ in range(3)], [0.125, 0.25, 0.5], exr, eyr)
    # 6. long and thin
    for i, (w, h) in enumerate([(1.0, 1e-6), (1e4, 1.0), (1e-3, 10.0)]):
        et, ft = axis_rect(w, h)
        add_cfg("thin%02d" % i, [0.3, 0.2, 0.7], [-0.5 * f32(w), -0.5 * f32(h), 0.0], et, ft)
    # 7. random configurations with o far relative to the rectangle size (1e1..1e5)
    for i in range(20):
        size = 2.0 ** rng.uniform(-3, 3)
        exr, eyr = orthogonal_edges(rng, size, size * 2.0 ** rng.uniform(-1, 1))
        dist = size * 10.0 ** rng.uniform(1, 5)
        direction = [rng.gauss(0, 1) for _ in range(3)]
        ln = sum(t * t for t in direction) ** 0.5
        s = [rand_f32(rng, -1, 1) for _ in range(3)]
        add_cfg("distant%02d" % i, [s[j] + direction[j] / ln * dist for j in range(3)], s, exr, eyr)
    return cfgs


def write_rectangles(rng):
    cfgs = rectangle_configs(rng)
    rows, maps = [], []
    worst = mp.mpf(0)
    map_us = [(0.5, 0.5), (0.125, 0.875), (0.9375, 0.0625), (0.0, 1.0), (1.0, 0.25)]
    for idx, (name, o, s, ex, ey) in enumerate(cfgs):
        x0, x1, y0, y1, d, frame = local_frame(o, s, ex, ey)
        om = rect_omega_exact(x0, x1, y0, y1, d)
        if d > 0:
            with mp.workdps(40):
                oq = rect_omega_quad(x0, x1, y0, y1, d)
            rel = abs(oq - om) / om
            worst = max(worst, rel)
            assert rel < mp.mpf("1e-25"), (name, rel)
            kappa = 1 + (norm(frame[3]) + frame[4] + frame[5]) / d
        else:
            kappa = mp.inf
        rows.append(" ".join([name] + [hexf(t) for t in o + s + ex + ey] +
                             [dec(om), dec(kappa) if d > 0 else "inf"]))
        if d > 0 and (idx % 4 == 0 or not name.startswith(("random", "distant"))):
            for u1, u2 in map_us[: 2 if name.startswith("random") else 5]:
                w, st, tt = reference_map(x0, x1, y0, y1, d, frame, mp.mpf(f32(u1)), mp.mpf(f32(u2)))
                maps.append(" ".join([name, hexf(f32(u1)), hexf(f32(u2))] + [dec(t) for t in w] +
                                     [dec(st), dec(tt)]))
    with open(os.path.join(OUT, "solid_angle.txt"), "w") as f:
        f.write("# generated by tools/gen_rectangle_reference.py (seed %d, mpmath %d digits)\n"
                % (SEED, mp.mp.dps))
        f.write("# name ox oy oz sx sy sz exx exy exz eyx eyy eyz | solid_angle kappa\n")
        f.write("# inputs: float32-exact hex floats; ex . ey == 0 exactly; solid angle two-sided,\n")
        f.write("# 0 when o is in the plane (kappa inf); max |quadrature - formula| / Omega = %s\n"
                % mp.nstr(worst, 3))
        f.write("\n".join(rows) + "\n")
    with open(os.path.join(OUT, "map.txt"), "w") as f:
        f.write("# generated by tools/gen_rectangle_reference.py (seed %d, mpmath %d digits)\n"
                % (SEED, mp.mp.dps))
        f.write("# name u1 u2 | direction_x direction_y direction_z s t\n")
        f.write("# name refers to solid_angle.txt; (s, t) = rectangle coordinates: point = corner + s ex + t ey\n")
        f.write("\n".join(maps) + "\n")
    return len(rows), len(maps), worst


# ------------------------------------------------------------------------------------------------
# disks (Gamito)
# ------------------------------------------------------------------------------------------------


def disk_geometry(o, c, n, r):
    o, c, n, r = mvec(o), mvec(c), mvec(n), mp.mpf(r)
    n = scale(n, 1 / norm(n))
    sd = dot(sub(o, c), n)
    d = abs(sd)
    foot = sub(o, scale(n, sd))
    h = norm(sub(c, foot))
    return o, c, n, r, sd, d, foot, h


def disk_chords(h, r, psi):
    """Distances s1 <= s2 from the foot point, along the ray at angle psi from the direction to
    the centre, where the ray is inside the disk (s1 = 0 when the foot is inside)."""
    hc = h * mp.cos(psi)
    disc = r * r - (h * mp.sin(psi)) ** 2
    root = mp.sqrt(max(disc, 0))
    if h < r:
        return mp.mpf(0), hc + root
    return hc - root, hc + root


def disk_integrals(o, c, n, r):
    """(solid angle, int cos theta d omega) by quadrature over the azimuth about the foot point."""
    o, c, n, r, sd, d, foot, h = disk_geometry(o, c, n, r)

    def omega_psi(psi):
        s1, s2 = disk_chords(h, r, psi)
        q1, q2 = mp.sqrt(s1 * s1 + d * d), mp.sqrt(s2 * s2 + d * d)
        return d * (s2 * s2 - s1 * s1) / (q1 * q2 * (q1 + q2))  # d/q1 - d/q2

    def cos_psi(psi):
        s1, s2 = disk_chords(h, r, psi)
        return d * d * (s2 * s2 - s1 * s1) / (2 * (s1 * s1 + d * d) * (s2 * s2 + d * d))

    top = mp.pi if h < r else mp.asin(r / h)
    pts = [0, top / 2, top]
    om = 2 * mp.quad(omega_psi, pts, maxdegree=12)
    ci = 2 * mp.quad(cos_psi, pts, maxdegree=12)
    # closed-form parallel-disk form factor: int cos d omega = pi F
    ff = (1 - (d * d + h * h - r * r) / mp.sqrt((d * d + h * h + r * r) ** 2 - 4 * h * h * r * r)) / 2
    assert abs(mp.pi * ff - ci) / ci < mp.mpf("1e-25"), (ci, mp.pi * ff)
    return om, ci


def bounding_square(o, c, n, r):
    """The square of docs/math.md §7: one edge along the symmetry plane (the in-plane direction
    from o's foot point to c), side 2r, centred on c. On the axis (h = 0) any orientation gives
    the same solid angle (rotational symmetry), so a fixed perpendicular is used."""
    o, c, n, r, sd, d, foot, h = disk_geometry(o, c, n, r)
    if h > 0:
        yd = scale(sub(c, foot), 1 / h)
    else:
        a = [mp.mpf(1), 0, 0] if abs(n[0]) < mp.mpf("0.9") else [mp.mpf(0), 1, 0]
        yd = cross(n, a)
        yd = scale(yd, 1 / norm(yd))
    xd = cross(n, yd)
    s = sub(sub(c, scale(xd, r)), scale(yd, r))
    x0 = dot(sub(s, o), xd)
    y0 = dot(sub(s, o), yd)
    return x0, x0 + 2 * r, y0, y0 + 2 * r, d


def write_disks(rng):
    cfgs = [  # (name, o, c, n, r): disk in the z = 0 plane unless rotated below
        ("typical", [1.0, 0.5, 2.0], [0, 0, 0], [0, 0, 1], 1.0),
        ("near_above", [0.25, 0.125, 0.5], [0, 0, 0], [0, 0, 1], 1.0),
        ("on_axis", [0.0, 0.0, 1.5], [0, 0, 0], [0, 0, 1], 1.0),
        ("oblique_far", [20.0, 0.0, 10.0], [0, 0, 0], [0, 0, 1], 1.0),
        ("grazing", [2.0, 1.0, 0.0625], [0, 0, 0], [0, 0, 1], 1.0),
        ("behind", [0.5, 0.0, -1.0], [0, 0, 0], [0, 0, 1], 1.0),
        ("far", [50.0, 30.0, 100.0], [0, 0, 0], [0, 0, 1], 1.0),
        ("very_close", [0.5, 0.25, 0.0078125], [0, 0, 0], [0, 0, 1], 1.0),
    ]
    for i in range(4):  # random orientations and radii (normals: integer vectors, not unit)
        n = rand_int_vec(rng, 5)
        c = [rand_f32(rng, -2, 2) for _ in range(3)]
        o = [rand_f32(rng, -3, 3) for _ in range(3)]
        cfgs.append(("random%d" % i, o, c, [float(t) for t in n], f32(2.0 ** rng.uniform(-1, 1))))
    rows = []
    for name, o, c, n, r in cfgs:
        o, c, n = [f32(t) for t in o], [f32(t) for t in c], [f32(t) for t in n]
        r = f32(r)
        om, ci = disk_integrals(o, c, n, r)
        x0, x1, y0, y1, d = bounding_square(o, c, n, r)
        sq = rect_omega_exact(x0, x1, y0, y1, d)
        with mp.workdps(40):
            sqq = rect_omega_quad(x0, x1, y0, y1, d)
        assert abs(sqq - sq) / sq < mp.mpf("1e-25")
        assert om < sq
        rows.append(" ".join([name] + [hexf(t) for t in o + c + n + [r]] + [dec(om), dec(ci), dec(sq)]))
    with open(os.path.join(OUT, "gamito_disks.txt"), "w") as f:
        f.write("# generated by tools/gen_rectangle_reference.py (seed %d, mpmath %d digits)\n"
                % (SEED, mp.mp.dps))
        f.write("# name ox oy oz cx cy cz nx ny nz r | disk_solid_angle int_cos_dw bounding_square_solid_angle\n")
        f.write("# cos = omega . z_d, z_d the disk plane's normal pointing from o towards the plane\n")
        f.write("\n".join(rows) + "\n")
    return len(rows)


def main():
    os.makedirs(OUT, exist_ok=True)
    rng = random.Random(SEED)
    nr, nm, worst = write_rectangles(rng)
    nd = write_disks(rng)
    print("wrote %d rectangles (max quadrature discrepancy %s), %d map points, %d disks to %s"
          % (nr, mp.nstr(worst, 3), nm, nd, os.path.normpath(OUT)))


if __name__ == "__main__":
    main()
