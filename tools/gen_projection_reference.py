#!/usr/bin/env python3
"""Reference tables for apse's projections (tests/data/projection/*.csv).

    python3 tools/gen_projection_reference.py            # rewrites tests/data/projection/*.csv
    python3 tools/gen_projection_reference.py --check    # recomputes and compares with the files
    python3 tools/gen_projection_reference.py --only=disks.csv   # one table (any of the five)

About 10 minutes on one core (the ellipsoid quadratures dominate).

Seeded and reproducible (byte-identical files on every run); needs only mpmath. Every input is
exactly representable in float32 and written as a hex float (float.hex()), so the float and the
double tests read the same geometry. Everything is computed from first principles with mpmath at
60 digits and written with 30 significant digits:

* alpha, beta and the frame of a **disk** by the geometric construction of docs/math.md §2 (the two rim
  points in the symmetry plane, atan2 angles, the chord through the centre direction), cross-
  checked against the eigen-decomposition of the quadric cone matrix (mp.eigsy);
* alpha, beta and the frame of an **ellipse** (any two non-parallel semi-diameters U, V) and of an
  **ellipsoid** from the eigen-decomposition of the cone matrix (docs/math.md §2b), cross-checked by
  solving the tangency condition along the computed axes (the boundary's angular distance from
  the cone axis at azimuth 0 and pi/2 must be alpha and beta, and no sampled azimuth may exceed
  alpha or fall below beta); **spheres** by asin(R / D);
* the solid angle by the R_J form (4/3) tan a tan b R_J(0, 1 + tan^2 b, 1 + tan^2 a, 1), cross-
  checked against an independent quadrature that uses no elliptic integral: for planar lights the
  integral of cos(theta_l) / dist^2 over the light in polar coordinates about the foot of o (the
  radial part exact, the angle by tanh-sinh), for ellipsoids the integral over the azimuth of
  1 - cos(theta_max) about the direction to the centre, theta_max from the tangency condition.
  Agreement is asserted to 1e-25 relative.

Every row also carries condition numbers kappa_* = sum_j |x_j d f / d x_j| / |f| over the inputs
the implementation rounds (the components of center - o, of the normal / axes, the sizes): a
double computation whose only error is the rounding of its inputs is accurate to ~kappa eps.

solid_angle.csv holds (tan alpha, tan beta) pairs from 2^-45 to 2^55 with Omega by the R_J form,
checked against the orthographic quadrature 4 int_0^{pi/2} (1 - cos theta_max(phi)) dphi.

Columns (shape tables): case, inputs (hex), empty (1 when the configuration must give the empty ellipse), alpha,
beta, omega, ze (3, centre direction), xe (3, major axis, up to sign), kappa_alpha, kappa_beta,
kappa_omega, kappa_frame (absolute sensitivity of ze).
"""

import math
import os
import random
import sys

import mpmath as mp

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from mp_reference import f32, hexf, dec, mvec, dot, cross, sub, add, scale, norm  # noqa: E402

mp.mp.dps = 60
SEED = 20170619
OUT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "tests", "data", "projection")


# ------------------------------------------------------------------------------------------------
# helpers
# ------------------------------------------------------------------------------------------------


def normalize(a):
    return scale(a, 1 / norm(a))


def any_perpendicular(z):
    if abs(z[0]) > abs(z[1]):
        inv = 1 / mp.sqrt(z[0] ** 2 + z[2] ** 2)
        return [-z[2] * inv, mp.mpf(0), z[0] * inv]
    inv = 1 / mp.sqrt(z[1] ** 2 + z[2] ** 2)
    return [mp.mpf(0), z[2] * inv, -z[1] * inv]


def solid_angle_rj(ta, tb):
    return mp.mpf(4) / 3 * ta * tb * mp.elliprj(0, 1 + tb * tb, 1 + ta * ta, 1)


class Ellipse:
    """Reference spherical ellipse: semi-arcs, tangents, frame, solid angle (R_J form)."""

    def __init__(self, ta, tb, xe, ye, ze):
        if tb > ta:
            ta, tb, xe, ye = tb, ta, ye, scale(xe, -1)
        self.ta, self.tb = ta, tb
        self.alpha, self.beta = mp.atan(ta), mp.atan(tb)
        self.xe, self.ye, self.ze = xe, ye, ze
        self.omega = solid_angle_rj(ta, tb)


def cone_ellipse(C, toward):
    """Spherical ellipse of the cone {v : v^T C v <= 0}, nappe containing `toward` (docs/math.md §2b)."""
    M = mp.matrix(3, 3)
    for i in range(3):
        for j in range(3):
            M[i, j] = (C[i][j] + C[j][i]) / 2
    E, Q = mp.eigsy(M)
    vals = [E[i] for i in range(3)]
    vecs = [[Q[j, i] for j in range(3)] for i in range(3)]
    neg = [i for i in range(3) if vals[i] < 0]
    pos = sorted([i for i in range(3) if vals[i] > 0], key=lambda i: vals[i])
    assert len(neg) == 1 and len(pos) == 2, vals
    k = neg[0]
    i2, i1 = pos  # i2: smaller positive eigenvalue -> major axis
    ze = normalize(vecs[k])
    if dot(ze, toward) < 0:
        ze = scale(ze, -1)
    xe = normalize(vecs[i2])
    ye = cross(ze, xe)
    ta = mp.sqrt(-vals[k] / vals[i2])
    tb = mp.sqrt(-vals[k] / vals[i1])
    return Ellipse(ta, tb, xe, ye, ze)


def rel(a, b):
    if b == 0:
        return abs(a)
    return abs(a - b) / abs(b)


# ------------------------------------------------------------------------------------------------
# disks: docs/math.md §2 geometric construction
# ------------------------------------------------------------------------------------------------


def disk_frame(o, c, n):
    """(d, h, xd, yd, zd) of the disk plane about o; None when o is in the plane."""
    n = normalize(n)
    w = sub(c, o)
    sd = dot(w, n)
    if sd == 0:
        return None
    zd = n if sd > 0 else scale(n, -1)
    d = abs(sd)
    v = sub(w, scale(zd, d))
    h = norm(v)
    yd = scale(v, 1 / h) if h > 0 else any_perpendicular(zd)
    xd = cross(yd, zd)
    return d, h, xd, yd, zd


def disk_ellipse(o, c, n, r):
    o, c, n, r = mvec(o), mvec(c), mvec(n), mp.mpf(r)
    f = disk_frame(o, c, n)
    if f is None or r <= 0:
        return None
    d, h, xd, yd, zd = f
    th0 = mp.atan2(h - r, d)
    th1 = mp.atan2(h + r, d)
    beta = (th1 - th0) / 2
    thc = (th1 + th0) / 2
    yh = d * mp.tan(thc)
    ell = mp.sqrt(r * r - (yh - h) ** 2)
    alpha = mp.atan2(ell * mp.cos(thc), d)
    ze = add(scale(yd, mp.sin(thc)), scale(zd, mp.cos(thc)))
    ye = add(scale(yd, mp.cos(thc)), scale(zd, -mp.sin(thc)))
    return Ellipse(mp.tan(alpha), mp.tan(beta), xd, ye, ze)


def disk_cone(o, c, n, r):
    """The disk as the planar ellipse U = r e1, V = r e2 (cross-check of the construction)."""
    n = normalize(mvec(n))
    e1 = any_perpendicular(n)
    e2 = cross(n, e1)
    return ellipse_cone(o, c, scale(e1, r), scale(e2, r))


# ------------------------------------------------------------------------------------------------
# planar ellipses {c + s U + t V : s^2 + t^2 <= 1}: cone matrix, quadrature
# ------------------------------------------------------------------------------------------------


def ellipse_cone(o, c, U, V):
    o, c, U, V = mvec(o), mvec(c), mvec(U), mvec(V)
    p = sub(c, o)
    # v = M (l s, l t, l), M = [U V p]: inside iff (M^-1 v)_1^2 + (M^-1 v)_2^2 <= (M^-1 v)_3^2;
    # the rows of M^-1 are proportional to V x p, p x U, U x V.
    r1, r2, r3 = cross(V, p), cross(p, U), cross(U, V)
    C = [[r1[i] * r1[j] + r2[i] * r2[j] - r3[i] * r3[j] for j in range(3)] for i in range(3)]
    if dot(p, r3) == 0:
        return None
    return cone_ellipse(C, p)


def planar_omega_quad(o, c, U, V):
    """int over the planar ellipse of cos(theta_l)/dist^2 dA, polar about the foot of o."""
    o, c, U, V = mvec(o), mvec(c), mvec(U), mvec(V)
    N = normalize(cross(U, V))
    sd = dot(sub(c, o), N)
    d = abs(sd)
    if d == 0:
        return mp.mpf(0)
    foot = add(o, scale(N, sd))
    e1 = normalize(U)
    e2 = cross(N, e1)
    # ellipse in plane coordinates about the foot: q = c0 + s u + t v
    c0 = [dot(sub(c, foot), e1), dot(sub(c, foot), e2)]
    u = [dot(U, e1), dot(U, e2)]
    v = [dot(V, e1), dot(V, e2)]
    det = u[0] * v[1] - u[1] * v[0]
    # inverse map: (s, t) = Minv (q - c0)
    mi = [[v[1] / det, -v[0] / det], [-u[1] / det, u[0] / det]]

    def st(q):
        return (mi[0][0] * q[0] + mi[0][1] * q[1], mi[1][0] * q[0] + mi[1][1] * q[1])

    # point of the ray rho (cos phi, sin phi): |A rho e - b|^2 = 1 with A e = Minv e, b = Minv c0
    b = st(c0)

    def interval(phi):
        e = st((mp.cos(phi), mp.sin(phi)))
        qa = e[0] ** 2 + e[1] ** 2
        qb = -2 * (e[0] * b[0] + e[1] * b[1])
        qc = b[0] ** 2 + b[1] ** 2 - 1
        disc = qb * qb - 4 * qa * qc
        if disc <= 0:
            return None
        sq = mp.sqrt(disc)
        r0 = (-qb - sq) / (2 * qa)
        r1 = (-qb + sq) / (2 * qa)
        if r1 <= 0:
            return None
        return max(r0, mp.mpf(0)), r1

    def radial(rho):
        return 1 - d / mp.sqrt(rho * rho + d * d)  # int_0^rho d x dx / (x^2 + d^2)^(3/2)

    def f(phi):
        iv = interval(phi)
        if iv is None:
            return mp.mpf(0)
        return radial(iv[1]) - radial(iv[0])

    inside = b[0] ** 2 + b[1] ** 2 < 1
    if inside:
        # smooth periodic integrand; split into quarters for tanh-sinh
        pts = [mp.pi * k / 4 for k in range(9)]
        return mp.quad(f, pts)
    # the foot is outside: integrate between the two tangent directions
    # tangent directions: disc(phi) = 0, solved in closed form on the unit circle
    phis = []
    # disc = qb^2 - 4 qa qc = 4 [ (e.b)^2 - |e|^2 (|b|^2 - 1) ], e = Minv (cos, sin)
    K = b[0] ** 2 + b[1] ** 2 - 1
    # e = (m00 x + m01 y, m10 x + m11 y); (e.b)^2 - K |e|^2 is a quadratic form in (x, y)
    gx = mi[0][0] * b[0] + mi[1][0] * b[1]
    gy = mi[0][1] * b[0] + mi[1][1] * b[1]
    axx = gx * gx - K * (mi[0][0] ** 2 + mi[1][0] ** 2)
    ayy = gy * gy - K * (mi[0][1] ** 2 + mi[1][1] ** 2)
    axy = gx * gy - K * (mi[0][0] * mi[0][1] + mi[1][0] * mi[1][1])
    # axx x^2 + 2 axy x y + ayy y^2 = 0 with (x, y) = (cos, sin)
    # tan: ayy t^2 + 2 axy t + axx = 0
    if K == 0:
        # the foot is on the rim: the rays with e.b > 0 enter the ellipse, a half-circle of them
        phi0 = mp.atan2(-gx, gy)  # gx cos + gy sin = 0
        if gx * mp.cos(phi0 + mp.pi / 2) + gy * mp.sin(phi0 + mp.pi / 2) < 0:
            phi0 += mp.pi
        return mp.quad(f, [phi0, phi0 + mp.pi / 2, phi0 + mp.pi])
    # axx x^2 + 2 axy x y + ayy y^2 = S + D cos 2phi + axy sin 2phi = 0 (S, D = (axx +- ayy)/2)
    S, D = (axx + ayy) / 2, (axx - ayy) / 2
    R = mp.sqrt(D * D + axy * axy)
    assert R > abs(S)
    psi = mp.atan2(axy, D)
    for sgn in (1, -1):
        phi = (psi + sgn * mp.acos(-S / R)) / 2
        for cand in (phi, phi + mp.pi):
            e = st((mp.cos(cand), mp.sin(cand)))
            if e[0] * b[0] + e[1] * b[1] > 0:  # the ray goes towards the ellipse
                phis.append(cand)
    assert len(phis) == 2, phis
    lo, hi = sorted(phis)
    if hi - lo > mp.pi:
        lo, hi = hi, lo + 2 * mp.pi
    mid = (lo + hi) / 2
    return mp.quad(f, [lo, mid, hi])


# ------------------------------------------------------------------------------------------------
# spheres and ellipsoids
# ------------------------------------------------------------------------------------------------


def sphere_ellipse(o, c, R):
    o, c, R = mvec(o), mvec(c), mp.mpf(R)
    p = sub(c, o)
    D = norm(p)
    if not D > R or R <= 0:
        return None
    ta = R / mp.sqrt(D * D - R * R)
    ze = scale(p, 1 / D)
    xe = any_perpendicular(ze)
    e = Ellipse(ta, ta, xe, cross(ze, xe), ze)
    om = 2 * mp.pi * (1 - mp.sqrt(1 - (R / D) ** 2))
    assert rel(e.omega, om) < mp.mpf(10) ** -40
    return e


def ellipsoid_matrix(A1, A2, A3):
    """A = sum e_i e_i^T / a_i^2 (orthogonal axes)."""
    A = [[mp.mpf(0)] * 3 for _ in range(3)]
    for Ai in (A1, A2, A3):
        a2 = dot(Ai, Ai)
        for i in range(3):
            for j in range(3):
                A[i][j] += Ai[i] * Ai[j] / (a2 * a2)
    return A


def mat_vec(A, v):
    return [sum(A[i][j] * v[j] for j in range(3)) for i in range(3)]


def ellipsoid_ellipse(o, c, A1, A2, A3):
    o, c, A1, A2, A3 = mvec(o), mvec(c), mvec(A1), mvec(A2), mvec(A3)
    A = ellipsoid_matrix(A1, A2, A3)
    q = sub(o, c)
    Aq = mat_vec(A, q)
    k = dot(q, Aq) - 1
    if not k > 0:
        return None
    C = [[k * A[i][j] - Aq[i] * Aq[j] for j in range(3)] for i in range(3)]
    return cone_ellipse(C, scale(q, -1))


def ellipsoid_tangency(o, c, A, pole, e1, e2, phi):
    """Polar angle (from `pole`) of the cone boundary at azimuth phi (frame e1, e2): the ray
    o + t v is tangent to the ellipsoid iff (q^T A v)^2 = (v^T A v)(q^T A q - 1), i.e. v^T C v = 0
    with C = (q^T A q - 1) A - (A q)(A q)^T; with v = cos(th) pole + sin(th) u this is a quadratic
    in tan(th), solved in closed form (no eigen-decomposition, no elliptic integral)."""
    q = sub(o, c)
    Aq = mat_vec(A, q)
    k = dot(q, Aq) - 1
    u = add(scale(e1, mp.cos(phi)), scale(e2, mp.sin(phi)))

    def quad_form(x, y):
        return k * dot(x, mat_vec(A, y)) - dot(Aq, x) * dot(Aq, y)

    cpp, cpu, cuu = quad_form(pole, pole), quad_form(pole, u), quad_form(u, u)
    assert cpp < 0  # the pole is inside the cone
    # along v(th), th in (0, pi), the form cpp cos^2 + 2 cpu cos sin + cuu sin^2 first vanishes at
    # cot(th) = (cpu + sqrt(D)) / |cpp|, D = cpu^2 - cpp cuu (the boundary can lie beyond pi/2
    # from the pole when the pole is far from the cone's axis)
    disc = mp.sqrt(cpu * cpu - cpp * cuu)
    if cpu >= 0:
        return mp.atan2(-cpp, cpu + disc)
    return mp.atan2(disc - cpu, cuu)


def ellipsoid_omega_quad(o, c, A1, A2, A3):
    o, c, A1, A2, A3 = mvec(o), mvec(c), mvec(A1), mvec(A2), mvec(A3)
    A = ellipsoid_matrix(A1, A2, A3)
    pole = normalize(sub(c, o))
    e1 = any_perpendicular(pole)
    e2 = cross(pole, e1)
    f = lambda phi: 1 - mp.cos(ellipsoid_tangency(o, c, A, pole, e1, e2, phi))
    return mp.quad(f, [mp.pi * k / 16 for k in range(33)])


def check_axes_by_tangency(o, c, A1, A2, A3, e):
    """alpha, beta of the eigen construction against the tangency condition along x_e, y_e."""
    o, c = mvec(o), mvec(c)
    A = ellipsoid_matrix(mvec(A1), mvec(A2), mvec(A3))
    if True:
        ta = ellipsoid_tangency(o, c, A, e.ze, e.xe, e.ye, mp.mpf(0))
        tb = ellipsoid_tangency(o, c, A, e.ze, e.xe, e.ye, mp.pi / 2)
        assert rel(ta, e.alpha) < mp.mpf(10) ** -30, (ta, e.alpha)
        assert rel(tb, e.beta) < mp.mpf(10) ** -30, (tb, e.beta)
        for k in range(1, 16):
            th = ellipsoid_tangency(o, c, A, e.ze, e.xe, e.ye, mp.pi * k / 16)
            assert e.beta * (1 - mp.mpf(10) ** -30) <= th <= e.alpha * (1 + mp.mpf(10) ** -30)


def planar_boundary_check(o, c, U, V, e):
    """alpha, beta against the planar ellipse's boundary seen along the cone axes: the angular
    distance from z_e of the boundary point in the direction x_e (y_e) is alpha (beta)."""
    o, c, U, V = mvec(o), mvec(c), mvec(U), mvec(V)
    N = cross(U, V)

    def boundary_angle(dirn):
        # points on the great circle through z_e towards dirn: v(th) = cos th z_e + sin th dirn;
        # find where the ray meets the plane inside the ellipse's boundary (bisection on th)
        M = [[U[i], V[i], N[i]] for i in range(3)]
        Mm = mp.matrix(M)
        Minv = Mm ** -1

        def inside(th):
            v = add(scale(e.ze, mp.cos(th)), scale(dirn, mp.sin(th)))
            den = dot(v, N)
            if den == 0:
                return False
            t = dot(sub(c, o), N) / den
            if t <= 0:
                return False
            P = sub(add(o, scale(v, t)), c)
            s = Minv * mp.matrix(P)
            return s[0] ** 2 + s[1] ** 2 <= 1

        lo, hi = mp.mpf(0), mp.pi / 2
        assert inside(lo)
        for _ in range(mp.mp.prec + 10):
            mid = (lo + hi) / 2
            if inside(mid):
                lo = mid
            else:
                hi = mid
        return (lo + hi) / 2

    with mp.workdps(50):
        a = boundary_angle(e.xe)
        b = boundary_angle(e.ye)
        assert rel(a, e.alpha) < mp.mpf(10) ** -25, (a, e.alpha)
        assert rel(b, e.beta) < mp.mpf(10) ** -25, (b, e.beta)


# ------------------------------------------------------------------------------------------------
# condition numbers (central differences at 60 digits)
# ------------------------------------------------------------------------------------------------


def outputs(e):
    if e is None:
        return None
    return [e.alpha, e.beta, e.omega] + list(e.ze)


def condition(fun, groups):
    """kappa for alpha, beta, omega and the frame: sum over every input scalar x of
    |x d f/d x| / |f| (frame: absolute). `groups` is the list of input vectors the implementation
    rounds; fun(groups) -> outputs."""
    base = outputs(fun(groups))
    h = mp.mpf(10) ** -25
    kap = [mp.mpf(0)] * 4
    for gi, g in enumerate(groups):
        for j in range(len(g)):
            if g[j] == 0:
                continue
            res = []
            for sgn in (1, -1):
                gg = [list(x) for x in groups]
                gg[gi][j] = g[j] * (1 + sgn * h)
                res.append(outputs(fun(gg)))
            if res[0] is None or res[1] is None:
                continue
            for k in range(3):
                dk = (res[0][k] - res[1][k]) / (2 * h)
                kap[k] += abs(dk) / abs(base[k]) if base[k] != 0 else 0
            dz = norm([(res[0][3 + i] - res[1][3 + i]) / (2 * h) for i in range(3)])
            kap[3] += dz
    return kap


# ------------------------------------------------------------------------------------------------
# configurations
# ------------------------------------------------------------------------------------------------


def rand_unit(rng):
    while True:
        v = [rng.gauss(0, 1) for _ in range(3)]
        n = math.sqrt(sum(t * t for t in v))
        if n > 1e-3:
            return [t / n for t in v]


def rand_f32_vec(rng, lo, hi):
    return [f32(rng.uniform(lo, hi)) for _ in range(3)]


PYTH = [  # orthogonal integer bases (rows orthogonal, equal norms)
    ([1, 2, 2], [2, 1, -2], [2, -2, 1]),
    ([2, 3, 6], [3, -6, 2], [6, 2, -3]),
    ([1, 4, 8], [4, 7, -4], [8, -4, 1]),
    ([2, 6, 9], [6, 7, -6], [9, -6, 2]),
    ([1, 0, 0], [0, 1, 0], [0, 0, 1]),
]


def canonical_disk(d, h, r, frame=0, flip=False, nscale=1.0, offset=(0.0, 0.0, 0.0), s=1.0):
    """Disk centre, normal, radius and o with o at height d above the plane and h from the axis
    (foot -> centre along the frame's second axis), in an exactly orthogonal integer frame."""
    b = PYTH[frame]
    nrm = math.sqrt(sum(t * t for t in b[0]))
    ex, ey, ez = [[t / nrm for t in v] for v in b]
    # centre at offset; o = centre - h ey + d ez (so the foot is at centre - h ey)
    c = [offset[i] for i in range(3)]
    o = [offset[i] + s * (-h * ey[i] + d * ez[i]) for i in range(3)]
    n = [t * nscale * (-1 if flip else 1) for t in b[2]]
    return [f32(t) for t in o], [f32(t) for t in c], [f32(t) for t in n], f32(r * s)


def disk_configs(rng):
    cfgs = []

    def add_cfg(name, o, c, n, r):
        cfgs.append((name, [f32(t) for t in o], [f32(t) for t in c], [f32(t) for t in n], f32(r)))

    # docs/math.md §10 table (o = 0, c = (h, 0, -d), n = +z, r = 1)
    for d, h in [(1, 0), (1, 0.5), (1, 1), (1, 2), (0.1, 3), (10, 5), (0.001, 0.5), (100, 0)]:
        add_cfg("math10", [0, 0, 0], [h, 0, -d], [0, 0, 1], 1)
    # generic random configurations
    for _ in range(90):
        o = rand_f32_vec(rng, -4, 4)
        c = rand_f32_vec(rng, -4, 4)
        n = [f32(t * rng.uniform(0.2, 5)) for t in rand_unit(rng)]
        add_cfg("generic", o, c, n, rng.uniform(0.05, 3))
    # behind the light (normal flipped): two-sided, same ellipse
    for _ in range(15):
        o = rand_f32_vec(rng, -4, 4)
        c = rand_f32_vec(rng, -4, 4)
        n = rand_unit(rng)
        if sum((c[i] - o[i]) * n[i] for i in range(3)) > 0:
            n = [-t for t in n]
        add_cfg("behind", o, c, n, rng.uniform(0.1, 2))
    # on the axis, in integer frames and axis-aligned
    for k, d in enumerate([1e-8, 1e-6, 1e-3, 0.1, 1, 3, 100, 1e4, 1e6, 1e8]):
        add_cfg("axis", *canonical_disk(d, 0, 1, frame=k % 5))
    # near the axis
    for k, (d, h) in enumerate([(1, 1e-9), (1, 1e-6), (1, 1e-3), (0.01, 1e-7), (100, 1e-4), (1e-6, 1e-9)]):
        add_cfg("near_axis", *canonical_disk(d, h, 1, frame=4))
    # just above the interior: Omega -> 2 pi
    for d in [1e-8, 1e-6, 1e-4, 1e-2]:
        for k, h in enumerate([0, 0.3, 0.9, 0.999]):
            add_cfg("above_interior", *canonical_disk(d, h, 1, frame=(k + 1) % 5 if d > 1e-6 else 4))
    # just outside, near the plane: Omega -> 0
    for d in [1e-8, 1e-6, 1e-4, 1e-2]:
        for h in [1.001, 1.5, 3, 100]:
            add_cfg("above_outside", *canonical_disk(d, h, 1, frame=4))
    # the rim and its neighbourhood
    for d in [1e-8, 1e-6, 1e-4, 1e-2, 0.1, 1, 10]:
        add_cfg("rim", *canonical_disk(d, 1, 1, frame=4))
    for d in [1e-7, 1e-5, 1e-3]:
        for h in [1 - 2.0 ** -20, 1 + 2.0 ** -20]:
            add_cfg("near_rim", *canonical_disk(d, h, 1, frame=4))
    # far away: 1e2 .. 1e8 radii, frontal, oblique, grazing
    for dist in [1e2, 1e4, 1e6, 1e8]:
        for ang in [0, 0.5, 1.2, 1.5, 1.5707]:
            add_cfg("far", *canonical_disk(dist * math.cos(ang), dist * math.sin(ang), 1, frame=4))
        add_cfg("far", *canonical_disk(dist * 0.6, dist * 0.8, 1, frame=1))
    # non-unit normals
    for ns in [2.0 ** -60, 2.0 ** -20, 3.7, 2.0 ** 40]:
        for k in range(3):
            add_cfg("nonunit_normal", *canonical_disk(rng.uniform(0.1, 3), rng.uniform(0, 3), rng.uniform(0.2, 2),
                                                      frame=k, nscale=ns))
    # scene scale (powers of two: the geometry, hence every output, is identical)
    for s in [2.0 ** -66, 2.0 ** -30, 2.0 ** 30, 2.0 ** 66]:
        for d, h in [(1, 0.5), (0.001, 0.5), (1e4, 1e3)]:
            add_cfg("scale", *canonical_disk(d, h, 1, frame=4, s=s))
    # translated far from the origin (the inputs' difference is rounded in float)
    for off in [(1000.0, -2000.0, 500.0), (1e5, 3e5, -2e5)]:
        for d, h in [(1, 0.5), (0.01, 0.2), (2, 3)]:
            o, c, n, r = canonical_disk(d, h, 1, frame=4)
            add_cfg("offset", [o[i] + off[i] for i in range(3)], [c[i] + off[i] for i in range(3)], n, r)
    # flipped normals and rotated frames of the special cases
    for k in range(4):
        add_cfg("behind", *canonical_disk(0.5 + k, 0.3 * k, 1, frame=k, flip=True))
    # in the plane: empty
    for h in [0, 0.5, 1, 2]:
        add_cfg("in_plane", *canonical_disk(0, h, 1, frame=4))
    return cfgs


def disk_fun(groups):
    o, w, n, r = groups
    c = add(o, w)
    return disk_ellipse(o, c, n, r[0])


def ellipse_configs(rng):
    cfgs = []

    def add_cfg(name, o, c, U, V):
        cfgs.append((name, [f32(t) for t in o], [f32(t) for t in c], [f32(t) for t in U], [f32(t) for t in V]))

    # disks written as ellipses (equal orthogonal axes): must agree with project_disk
    for k, (d, h) in enumerate([(1, 0), (1, 0.5), (1, 2), (0.1, 3), (1e-6, 0.5), (1e4, 2e3)]):
        b = PYTH[k % 5]
        add_cfg("disk_as_ellipse", [0, 0, d], [h, 0, 0], [1, 0, 0], [0, 1, 0])
        nrm = math.sqrt(sum(t * t for t in b[0]))
        o = [(-h * b[1][i] + d * b[2][i]) / nrm for i in range(3)]
        add_cfg("disk_as_ellipse", o, [0, 0, 0], [t / 4 for t in b[0]], [t / 4 for t in b[1]])
    # orthogonal axes, random positions
    for _ in range(30):
        b = PYTH[rng.randrange(5)]
        su, sv = rng.uniform(0.1, 2), rng.uniform(0.1, 2)
        nrm = math.sqrt(sum(t * t for t in b[0]))
        ku = 2.0 ** round(math.log2(su / nrm))
        kv = 2.0 ** round(math.log2(sv / nrm))
        U = [t * ku for t in b[0]]
        V = [t * kv for t in b[1]]
        if rng.random() < 0.5:
            U, V = V, U
        add_cfg("orthogonal", rand_f32_vec(rng, -3, 3), rand_f32_vec(rng, -3, 3), U, V)
    # general (non-orthogonal) semi-diameters
    for _ in range(25):
        U = [t * rng.uniform(0.2, 2) for t in rand_unit(rng)]
        V = [t * rng.uniform(0.2, 2) for t in rand_unit(rng)]
        add_cfg("conjugate", rand_f32_vec(rng, -3, 3), rand_f32_vec(rng, -3, 3), U, V)
    # thin ellipses, far, near the plane, grazing, behind
    for ratio in [1e-1, 1e-3, 1e-5]:
        add_cfg("thin", [0.3, -0.2, 1.5], [0, 0, 0], [2, 0, 0], [0, 2 * ratio, 0])
        add_cfg("thin", [0.3, -0.2, 1.5], [0, 0, 0], [0, 2 * ratio, 0], [2, 0, 0])
    for dist in [1e2, 1e4, 1e6, 1e8]:
        add_cfg("far", [dist * 0.6, dist * 0.2, dist * 0.77], [0, 0, 0], [2, 0, 0], [0, 0.5, 0])
        add_cfg("far", [dist * 0.99, 0, dist * 0.01], [0, 0, 0], [1, 0, 0], [0, 3, 0])
    for d in [1e-8, 1e-6, 1e-3]:
        add_cfg("near_plane", [0.5, 0.25, d], [0, 0, 0], [2, 0, 0], [0, 1, 0])  # above interior
        add_cfg("near_plane", [3, 1, d], [0, 0, 0], [2, 0, 0], [0, 1, 0])  # outside
        add_cfg("near_plane", [2, 0, d], [0, 0, 0], [2, 0, 0], [0, 1, 0])  # at the rim
    add_cfg("behind", [0.5, 0.2, -1], [0, 0, 0], [2, 0, 0], [0, 1, 0])
    add_cfg("behind", [0.5, 0.2, 1], [0, 0, 0], [0, 1, 0], [2, 0, 0])
    for h in [0, 1.5, 3]:
        add_cfg("in_plane", [h, 0, 0], [0, 0, 0], [2, 0, 0], [0, 1, 0])
    return cfgs


def ellipse_fun(groups):
    o, w, U, V = groups
    return ellipse_cone(o, add(o, w), U, V)


def sphere_configs(rng):
    cfgs = []

    def add_cfg(name, o, c, R):
        cfgs.append((name, [f32(t) for t in o], [f32(t) for t in c], f32(R)))

    for _ in range(20):
        o = rand_f32_vec(rng, -4, 4)
        c = rand_f32_vec(rng, -4, 4)
        D = math.dist(o, c)
        add_cfg("generic", o, c, rng.uniform(0.05, 0.95) * D)
    for dist in [1e2, 1e4, 1e6, 1e8]:
        add_cfg("far", [0, 0, 0], [dist * 0.6, 0, dist * 0.8], 1)
    for eps in [2.0 ** -20, 2.0 ** -10, 0.01]:
        add_cfg("near_surface", [0, 0, 1 + eps], [0, 0, 0], 1)
    add_cfg("on_surface", [0, 0, 1], [0, 0, 0], 1)
    add_cfg("inside", [0, 0.5, 0], [0, 0, 0], 1)
    add_cfg("inside", [0, 0, 0], [0, 0, 0], 1)
    return cfgs


def sphere_fun(groups):
    o, w, R = groups
    return sphere_ellipse(o, add(o, w), R[0])


def ellipsoid_configs(rng):
    cfgs = []

    def add_cfg(name, o, c, A1, A2, A3):
        cfgs.append((name, [f32(t) for t in o], [f32(t) for t in c], [f32(t) for t in A1], [f32(t) for t in A2],
                     [f32(t) for t in A3]))

    def axes(k, a1, a2, a3):
        b = PYTH[k]
        nrm = math.sqrt(sum(t * t for t in b[0]))
        out = []
        for v, a in zip(b, (a1, a2, a3)):
            kk = 2.0 ** round(math.log2(a / nrm))
            out.append([t * kk for t in v])
        return out

    for _ in range(20):
        A = axes(rng.randrange(5), rng.uniform(0.1, 2), rng.uniform(0.1, 2), rng.uniform(0.1, 2))
        while True:
            o = rand_f32_vec(rng, -5, 5)
            c = rand_f32_vec(rng, -5, 5)
            if ellipsoid_ellipse(o, c, *A) is not None:
                break
        add_cfg("generic", o, c, *A)
    # sphere as ellipsoid
    add_cfg("sphere_as_ellipsoid", [0.5, -1, 3], [0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1])
    add_cfg("sphere_as_ellipsoid", [1, 2, 2], [0, 0, 0], *axes(0, 0.5, 0.5, 0.5))
    # spheroids, pancakes, needles
    add_cfg("spheroid", [0.3, 0.2, 3], [0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 0.25])
    add_cfg("pancake", [0.3, 0.2, 3], [0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 2.0 ** -10])
    add_cfg("pancake", [3, 0.2, 0.5], [0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 2.0 ** -10])
    add_cfg("needle", [0.3, 0.2, 3], [0, 0, 0], [2.0 ** -8, 0, 0], [0, 2.0 ** -8, 0], [0, 0, 2])
    for dist in [1e2, 1e4, 1e6, 1e8]:
        add_cfg("far", [dist * 0.6, dist * 0.48, dist * 0.64], [0, 0, 0], *axes(1, 2, 1, 0.5))
    for eps in [2.0 ** -20, 2.0 ** -8]:
        add_cfg("near_surface", [0, 0, 0.5 + eps], [0, 0, 0], [2, 0, 0], [0, 1, 0], [0, 0, 0.5])
        add_cfg("near_surface", [2 + 2 * eps, 0, 0], [0, 0, 0], [2, 0, 0], [0, 1, 0], [0, 0, 0.5])
    add_cfg("inside", [0, 0, 0.25], [0, 0, 0], [2, 0, 0], [0, 1, 0], [0, 0, 0.5])
    add_cfg("inside", [0.25, 0.125, 0.0625], [0, 0, 0], *axes(2, 2, 1, 0.5))
    return cfgs


def ellipsoid_fun(groups):
    o, w, A1, A2, A3 = groups
    return ellipsoid_ellipse(o, add(o, w), A1, A2, A3)


# ------------------------------------------------------------------------------------------------
# output
# ------------------------------------------------------------------------------------------------


RESULT_COLUMNS = ["empty", "alpha", "beta", "omega", "ze_x", "ze_y", "ze_z", "xe_x", "xe_y", "xe_z",
                  "kappa_alpha", "kappa_beta", "kappa_omega", "kappa_frame"]


def result_fields(e, kap):
    if e is None:
        return ["1"] + ["0"] * 13
    return (["0", dec(e.alpha), dec(e.beta), dec(e.omega)] + [dec(t) for t in e.ze] + [dec(t) for t in e.xe]
            + [mp.nstr(k, 6) for k in kap])


def vecs_hex(*vs):
    out = []
    for v in vs:
        out += [hexf(t) for t in v]
    return out


def condition_without_o(fun, o, w, *rest):
    """kappa over the rounded inputs w = c - o and the rest (o itself is not perturbed: the
    implementation only uses the difference)."""
    def f(groups):
        return fun([o] + groups)
    return condition(f, [w] + list(rest))


def build_disks_rows(rng):
    rows = []
    for name, o, c, n, r in disk_configs(rng):
        e = disk_ellipse(o, c, n, r)
        kap = None
        if e is not None:
            ce = disk_cone(o, c, n, r)
            assert rel(ce.alpha, e.alpha) < mp.mpf(10) ** -30 and rel(ce.beta, e.beta) < mp.mpf(10) ** -30, name
            assert norm(sub(ce.ze, e.ze)) < mp.mpf(10) ** -30
            nn = normalize(mvec(n))
            e1 = any_perpendicular(nn)
            e2 = cross(nn, e1)
            with mp.workdps(40):
                q = planar_omega_quad(o, c, scale(e1, mp.mpf(r)), scale(e2, mp.mpf(r)))
            assert rel(q, e.omega) < mp.mpf(10) ** -25, (name, q, e.omega)
            w = sub(mvec(c), mvec(o))
            kap = condition_without_o(disk_fun, mvec(o), w, mvec(n), [mp.mpf(r)])
        rows.append([name] + vecs_hex(o, c, n) + [hexf(r)] + result_fields(e, kap))
    header = ["case", "o_x", "o_y", "o_z", "c_x", "c_y", "c_z", "n_x", "n_y", "n_z", "r"] + RESULT_COLUMNS
    return header, rows


def build_ellipses(rng):
    rows = []
    for name, o, c, U, V in ellipse_configs(rng):
        e = ellipse_cone(o, c, U, V)
        kap = None
        if e is not None:
            with mp.workdps(40):
                q = planar_omega_quad(o, c, U, V)
            assert rel(q, e.omega) < mp.mpf(10) ** -25, (name, q, e.omega)
            planar_boundary_check(o, c, U, V, e)
            kap = condition_without_o(ellipse_fun, mvec(o), sub(mvec(c), mvec(o)), mvec(U), mvec(V))
        rows.append([name] + vecs_hex(o, c, U, V) + result_fields(e, kap))
    header = (["case", "o_x", "o_y", "o_z", "c_x", "c_y", "c_z", "u_x", "u_y", "u_z", "v_x", "v_y", "v_z"]
              + RESULT_COLUMNS)
    return header, rows


def build_spheres(rng):
    rows = []
    for name, o, c, R in sphere_configs(rng):
        e = sphere_ellipse(o, c, R)
        kap = None
        if e is not None:
            kap = condition_without_o(sphere_fun, mvec(o), sub(mvec(c), mvec(o)), [mp.mpf(R)])
        rows.append([name] + vecs_hex(o, c) + [hexf(R)] + result_fields(e, kap))
    header = ["case", "o_x", "o_y", "o_z", "c_x", "c_y", "c_z", "radius"] + RESULT_COLUMNS
    return header, rows


def build_ellipsoids(rng):
    rows = []
    for name, o, c, A1, A2, A3 in ellipsoid_configs(rng):
        e = ellipsoid_ellipse(o, c, A1, A2, A3)
        kap = None
        if e is not None:
            q = ellipsoid_omega_quad(o, c, A1, A2, A3)
            assert rel(q, e.omega) < mp.mpf(10) ** -25, (name, q, e.omega)
            check_axes_by_tangency(o, c, A1, A2, A3, e)
            kap = condition_without_o(ellipsoid_fun, mvec(o), sub(mvec(c), mvec(o)), mvec(A1), mvec(A2), mvec(A3))
        rows.append([name] + vecs_hex(o, c, A1, A2, A3) + result_fields(e, kap))
    header = (["case", "o_x", "o_y", "o_z", "c_x", "c_y", "c_z", "a1_x", "a1_y", "a1_z", "a2_x", "a2_y", "a2_z",
               "a3_x", "a3_y", "a3_z"] + RESULT_COLUMNS)
    return header, rows


def solid_angle_quad(ta, tb):
    """Omega = 4 int_0^{pi/2} (1 - cos theta_max(phi)) dphi with sin theta_max = a b /
    sqrt(a^2 sin^2 + b^2 cos^2) (a, b = sin alpha, sin beta; docs/math.md §1): no elliptic integral."""
    a = ta / mp.sqrt(1 + ta * ta)
    b = tb / mp.sqrt(1 + tb * tb)

    def f(phi):
        s, c = mp.sin(phi), mp.cos(phi)
        r2 = (a * b) ** 2 / (a * a * s * s + b * b * c * c)
        return r2 / (1 + mp.sqrt(1 - r2))

    w = mp.atan(tb / ta)  # width of the integrand's peak at phi = 0 for thin ellipses
    pts = sorted(set([mp.mpf(0)] + [min(w * 4 ** k, mp.pi / 2) for k in range(-2, 12)] + [mp.pi / 2]))
    return 4 * mp.quad(f, pts)


def build_solid_angles(rng):
    """Solid angle of ellipses given by their tangents (float32-exact): Omega by the R_J form,
    checked against the orthographic quadrature."""
    rows = []
    cases = []
    for ta, tb in [(1, 1), (1, 0.5), (2.0 ** 26, 2.0 ** 26), (2.0 ** 26, 1), (2.0 ** 55, 2.0 ** 55),
                   (2.0 ** 55, 1), (2.0 ** 55, 2.0 ** -20), (2.0 ** -40, 2.0 ** -40), (2.0 ** -20, 2.0 ** -21),
                   (1e-6, 1e-6), (1e-6, 1e-12), (1e-3, 1e-9), (100, 1e-3), (1e4, 1e4), (1e8, 1e8), (1e8, 1e4)]:
        cases.append(("special", f32(ta), f32(tb)))
    for _ in range(120):
        ta = f32(2.0 ** rng.uniform(-45, 40))
        ratio = 1.0 if rng.random() < 0.15 else 10 ** rng.uniform(-7, 0)
        tb = f32(ta * ratio)
        if tb == 0:
            continue
        cases.append(("random", ta, tb))
    for name, ta, tb in cases:
        e = Ellipse(mp.mpf(ta), mp.mpf(tb), [1, 0, 0], [0, 1, 0], [0, 0, 1])
        with mp.workdps(50):
            q = solid_angle_quad(mp.mpf(ta), mp.mpf(tb))
        assert rel(q, e.omega) < mp.mpf(10) ** -25, (ta, tb, q, e.omega)
        rows.append([name, hexf(ta), hexf(tb), dec(e.omega)])
    return ["case", "tan_alpha", "tan_beta", "omega"], rows


def render(header, rows, comment):
    lines = ["# " + line for line in comment.strip().splitlines()]
    lines.append(",".join(header))
    lines += [",".join(r) for r in rows]
    return "\n".join(lines) + "\n"


def main():
    check = "--check" in sys.argv[1:]
    tables = {
        "disks.csv": (build_disks_rows, "Disks (o, centre c, normal n (any length), radius r) -> spherical ellipse.\n"
                      "Generated by tools/gen_projection_reference.py; do not edit."),
        "ellipses.csv": (build_ellipses, "Planar ellipses {c + s U + t V : s^2 + t^2 <= 1} -> spherical ellipse.\n"
                         "Generated by tools/gen_projection_reference.py; do not edit."),
        "spheres.csv": (build_spheres, "Spheres (centre c, radius) -> spherical cap.\n"
                        "Generated by tools/gen_projection_reference.py; do not edit."),
        "solid_angle.csv": (build_solid_angles, "Solid angle of spherical ellipses given by tan(alpha) >= tan(beta).\n"
                            "Generated by tools/gen_projection_reference.py; do not edit."),
        "ellipsoids.csv": (build_ellipsoids, "Ellipsoids (centre c, orthogonal semi-axes A1, A2, A3) -> spherical ellipse.\n"
                           "Generated by tools/gen_projection_reference.py; do not edit."),
    }
    os.makedirs(OUT, exist_ok=True)
    status = 0
    total = 0
    only = [a.split("=", 1)[1] for a in sys.argv[1:] if a.startswith("--only=")]
    for k, (fname, (builder, comment)) in enumerate(tables.items()):
        if only and fname not in only:
            continue
        rng = random.Random(SEED + k)
        header, rows = builder(rng)
        total += len(rows)
        text = render(header, rows, comment)
        path = os.path.join(OUT, fname)
        if check:
            old = open(path).read() if os.path.exists(path) else ""
            if old != text:
                print("MISMATCH", fname)
                status = 1
            else:
                print("ok", fname, len(rows))
        else:
            with open(path, "w") as f:
                f.write(text)
            print("wrote", path, len(rows), "rows")
    print("total", total, "configurations")
    return status


if __name__ == "__main__":
    sys.exit(main())
