#!/usr/bin/env python3
"""Numerical check of the formulas written in docs/math.md (§1–§13), at 40 digits with mpmath.

    python3 tools/check_math_notes.py          # under a minute on one core; exit status 1 on a failure

Each check compares a formula of docs/math.md with an independent evaluation: quadrature of its
definition, a geometric construction, ray/shape membership, mpmath's own elliptic integrals, or
the Jacobian of a map by finite differences. It prints the largest discrepancy of each check and
fails if it exceeds the check's bound. It also prints the numbers docs/math.md quotes that come
from a formula rather than from the library (the §4 first-guess errors, the §6 ratios of the
authors' Newton derivative, the §6 acceptance of the authors' tabulation, the §10 values).
This checks the mathematics; the library itself is checked by tests/ against the tables of the
tools/gen_*_reference.py generators; tools/check_math_references.py checks that the files,
functions and test cases docs/math.md names exist.
"""

import math
import random
import sys

from mpmath import (mp, mpf, mpc, sqrt, sin, cos, tan, atan, atan2, asin, atanh, pi, quad, diff, floor,
                    elliprj, elliprf, elliprc, ellippi, ellipf, ellipk, agm, matrix, eigsy, det)

mp.dps = 40
FAILED = []
RESULTS = {}


def rec(name, err, bound):
    """Records |err| for the check `name`, which passes if its largest |err| is <= bound."""
    worst, _ = RESULTS.get(name, (mpf(0), bound))
    RESULTS[name] = (max(worst, abs(mpf(err))), bound)


def report(title):
    print(f"\n{title}")
    for name, (worst, bound) in RESULTS.items():
        ok = worst <= bound
        if not ok:
            FAILED.append(name)
        print(f"  {'ok  ' if ok else 'FAIL'} {name:52s} {mp.nstr(worst, 3):>10s}  (bound {mp.nstr(bound, 2)})")
    RESULTS.clear()


def wedge(a, b, phi):
    """1 - cos theta_max(phi) of the ellipse with orthographic semi-axes a, b (§1)."""
    r2 = (a * b) ** 2 / ((a * sin(phi)) ** 2 + (b * cos(phi)) ** 2)
    return r2 / (1 + sqrt(1 - r2))


def omega_r_tau(a, b, ca, cb, tb, m, tau):
    """§4: Omega_r in the orthographic eccentric anomaly tau."""
    ct, st = cos(tau), sin(tau)
    c = sqrt(ca ** 2 * ct ** 2 + cb ** 2 * st ** 2)
    term1 = a * b * cb ** 2 / (3 * ca) * st ** 3 * elliprj(ct ** 2, 1, c ** 2 / ca ** 2, ct ** 2 + cb ** 2 * st ** 2)
    term2 = atan2((b / a) * st * ct * (tb ** 2 * c ** 2 + m * ct ** 2) / (1 + c), ct ** 2 + (b / a) ** 2 * c * st ** 2)
    return term1 + term2


SHAPES = [(mpf('0.3'), mpf('0.05')), (mpf('1.2'), mpf('0.3')), (mpf('0.7'), mpf('0.69')),
          (mpf('1.5'), mpf('1.45')), (mpf('1.5707'), mpf('0.01')), (mpf('0.01'), mpf('0.002'))]
EXACT = mpf(10) ** -30   # identities and closed forms, evaluated at 40 digits
BOOTH = mpf(10) ** -25   # the paper's forms lose digits to cancellation even at 40 digits


def check_ellipse_forms():
    """§1 boundary and anomalies, §3 solid angle, §4 radial area and density, §5 parallel area."""
    for al, be in SHAPES:
        ta, tb, a, b, ca, cb = tan(al), tan(be), sin(al), sin(be), cos(al), cos(be)
        m = (ta ** 2 - tb ** 2) / (1 + ta ** 2)
        for phi in (mpf('0.1'), mpf('0.7'), mpf('1.3')):
            th = atan(1 / sqrt(cos(phi) ** 2 / ta ** 2 + sin(phi) ** 2 / tb ** 2))  # gnomonic boundary
            r = a * b / sqrt(a * a * sin(phi) ** 2 + b * b * cos(phi) ** 2)
            rec('§1 r(phi) = sin theta_max', (r - sin(th)) / r, EXACT)
            rec('§1 1 - cos theta_max = r^2/(1 + sqrt(1 - r^2))', (wedge(a, b, phi) - (1 - cos(th))) / (1 - cos(th)), EXACT)
            tau = atan2(a * sin(phi), b * cos(phi))
            c = sqrt(ca ** 2 * cos(tau) ** 2 + cb ** 2 * sin(tau) ** 2)
            rec('§1 C(tau) = cos theta_max', c - cos(th), EXACT)
            t = atan2(cb * sin(tau) / c, ca * cos(tau) / c)
            rec('§1 tan phi = (t_b/t_a) tan t', atan2(tb * sin(t), ta * cos(t)) - phi, EXACT)
            rec('§1 sqrt(1 - m sin^2 t) = cos alpha / C', sqrt(1 - m * sin(t) ** 2) - ca / c, EXACT)
        om = 4 * quad(lambda p: wedge(a, b, p), [0, pi / 4, pi / 2])
        rec('§3 (4/3) ta tb R_J(0, 1+tb^2, 1+ta^2, 1)', (mpf(4) / 3 * ta * tb * elliprj(0, 1 + tb ** 2, 1 + ta ** 2, 1) - om) / om, EXACT)
        pp = ca ** 2 * cb ** 2
        rec('§3 homogeneous form sqrt(P) R_J(0, ca^2, cb^2, P)', (mpf(4) / 3 * a * ca * b * cb * sqrt(pp) * elliprj(0, ca ** 2, cb ** 2, pp) - om) / om, EXACT)
        rec('§1 1 - m = cos^2 alpha / cos^2 beta', (1 - m) - ca ** 2 / cb ** 2, EXACT)
        cc, n = tb * ca / ta, 1 - tb ** 2 / ta ** 2
        rec('§3 c, n, m in a, b', max(abs(cc - b * (1 - a * a) / (a * sqrt(1 - b * b))), abs(n - (a * a - b * b) / (a * a * (1 - b * b))),
                                     abs(m - (a * a - b * b) / (1 - b * b))), EXACT)
        rec('§3 m <= n < 1, n = m/a^2', 0 if (m <= n < 1 and abs(n - m / a ** 2) < EXACT) else 1, 0)
        rec('§3 paper form 2 pi - 4 c Pi(n|m)', (2 * pi - 4 * cc * ellippi(n, m) - om) / om, BOOTH)
        rec('§3 DLMF 19.7.9 step: Omega/4 = c (a^2/3) R_J(0, 1-m, 1, 1-a^2)', (cc * a * a / 3 * elliprj(0, 1 - m, 1, 1 - a * a) - om / 4) / om, EXACT)
        rec('§3 parallel-map form (Legendre)', (4 * a / tb * ((1 + tb ** 2) * ellippi(-tb ** 2, m) - ellipk(m)) - om) / om, EXACT)
        rec('§3 parallel-map form (Carlson)', (4 * a * tb * (elliprf(0, 1 - m, 1) - (1 + tb ** 2) / 3 * elliprj(0, 1 - m, 1, 1 + tb ** 2)) - om) / om, EXACT)
        for phi in (mpf('0.05'), mpf('0.4'), mpf('1.0'), mpf('1.5')):
            ref = quad(lambda p: wedge(a, b, p), [0, phi])
            tau = atan2(a * sin(phi), b * cos(phi))
            rec('§4 Omega_r(tau) form', (omega_r_tau(a, b, ca, cb, tb, m, tau) - ref) / om, EXACT)
            t = atan2(ta * sin(phi), tb * cos(phi))
            rec('§4 paper form phi - c Pi(n; t|m)', (phi - cc * ellippi(n, t, m) - ref) / om, BOOTH)
            s, ct = sin(t), cos(t)
            w, q = sqrt(1 - m * s * s), tb / ta
            form_t = cc * a * a / 3 * s ** 3 * elliprj(ct ** 2, w * w, 1, 1 - a * a * s * s) + \
                atan2(q * s * ct * (a * a - m * s * s) / (w * (w + ca)), ct ** 2 + q * q * s * s * ca / w)
            rec('§4 Omega_r(t) form', (form_t - ref) / om, EXACT)
            h = mpf(10) ** -12
            c = sqrt(ca ** 2 * cos(tau) ** 2 + cb ** 2 * sin(tau) ** 2)
            slope = (omega_r_tau(a, b, ca, cb, tb, m, tau + h) - omega_r_tau(a, b, ca, cb, tb, m, tau - h)) / (2 * h)
            rec('§4 dOmega_r/dtau = ab/(1 + C)', (slope - a * b / (1 + c)) / (a * b), mpf(10) ** -20)
            d2 = (a * b / (1 + sqrt(ca ** 2 * cos(tau + h) ** 2 + cb ** 2 * sin(tau + h) ** 2)) -
                  a * b / (1 + sqrt(ca ** 2 * cos(tau - h) ** 2 + cb ** 2 * sin(tau - h) ** 2))) / (2 * h)
            rec('§4 second derivative', (d2 + a * b / (1 + c) ** 2 * (a * a - b * b) * sin(tau) * cos(tau) / c) / (a * b), mpf(10) ** -20)
        rec('§4 kappa = cos(a/2)/cos(b/2) = sqrt((1+ca)/(1+cb))', sqrt((1 + ca) / (1 + cb)) - cos(al / 2) / cos(be / 2), EXACT)
        z = mpc(0, atanh(ca / cb))
        rec('§6 C(tau) = 0 at tau = i atanh(ca/cb)', abs(ca ** 2 * mp.cos(z) ** 2 + cb ** 2 * mp.sin(z) ** 2), EXACT)
        for psi in (be * mpf('0.1'), be * mpf('0.5'), be * mpf('0.93'), be * (1 - mpf(10) ** -6)):
            yt = tan(psi)
            xt = ta * sqrt(1 - yt ** 2 / tb ** 2)
            xm = xt / sqrt(1 + xt ** 2 + yt ** 2)
            s_ = sin(be - psi) * sin(be + psi)
            nn = sqrt(b * b * ca * ca + a * a * s_)
            rec('§5 x_max = a sqrt(S)/N', (xm - a * sqrt(s_) / nn) / a, EXACT)
            rec('§5 2 x_max = 2 sin a sqrt((1 - p tan^2)/(1 - m p tan^2))',
                (2 * xm - 2 * a * sqrt((1 - yt ** 2 / tb ** 2) / (1 - m * yt ** 2 / tb ** 2))) / a, EXACT)
            pt = (a * sqrt(s_) / nn, b * ca * sin(psi) / nn, b * ca * cos(psi) / nn)
            rec('§5 P on the boundary (orthographic ellipse, unit)', max(abs((pt[0] / a) ** 2 + (pt[1] / b) ** 2 - 1),
                                                                   abs(sum(v * v for v in pt) - 1)), EXACT)
            rec('§5 1 - x_max^2 = (b cos alpha / N)^2', (1 - xm ** 2) - (b * ca / nn) ** 2, EXACT)
            e = be - psi
            rec('§5 sin psi, cos psi, S from e = beta - psi',
                max(abs(sin(psi) - (b * cos(e) - cb * sin(e))), abs(cos(psi) - (cb * cos(e) + b * sin(e))),
                    abs(s_ - sin(e) * (b * cos(psi) + cb * sin(psi)))), EXACT)
            ref = quad(lambda x: 2 * a * sqrt(sin(be - x) * sin(be + x)) / sqrt(b * b * ca * ca + a * a * sin(be - x) * sin(be + x)),
                       [0, psi / 2, psi])
            th = asin(min(mpf(1), yt / tb))
            s = sin(th)
            rec('§5 I(psi) Legendre form', (2 * a / tb * ((1 + tb ** 2) * ellippi(-tb ** 2, th, m) - ellipf(th, m)) - ref) / om, BOOTH)
            rec('§5 I(psi) Carlson form', (2 * a * tb * (s * elliprf(cos(th) ** 2, 1 - m * s * s, 1) -
                                                          (1 + tb ** 2) / 3 * s ** 3 * elliprj(cos(th) ** 2, 1 - m * s * s, 1, 1 + tb ** 2 * s * s)) - ref) / om, EXACT)
            tau_p = atan2(pt[1] / b, pt[0] / a)
            tri = 2 * atan2(a * sqrt(s_) * sin(psi), nn * (1 + pt[2] + cos(psi)) + b * ca)
            rec('§5 I = 2 (sector + triangle)', (2 * (omega_r_tau(a, b, ca, cb, tb, m, tau_p) + tri) - ref) / om, EXACT)
            mv = (mpf(0), sin(psi), cos(psi))
            triple = abs(pt[0] * mv[1] - pt[1] * mv[0])  # |z . (P x M)| with z = (0, 0, 1)
            vos = 2 * atan2(triple, 1 + pt[2] + mv[2] + sum(u * v for u, v in zip(pt, mv)))
            rec('§5 triangle = Van Oosterom-Strackee', tri - vos, EXACT)
    # the strip of a half-disk behind the parallel map's planar first guess
    for th in (mpf('0.2'), mpf('1.1')):
        rec('§5 half-disk strip fraction (2 theta + sin 2 theta)/pi', quad(lambda y: 2 * sqrt(1 - y * y), [0, sin(th)]) / (pi / 2) - (2 * th + sin(2 * th)) / pi, EXACT)
    report('Ellipse formulas (§1, §3, §4, §5)')


def disk_geometric(d, h, r):
    """§2 geometric construction: alpha, beta, theta_c."""
    th0, th1 = atan2(h - r, d), atan2(h + r, d)
    thc = (th1 + th0) / 2
    ell = sqrt(r * r - (d * tan(thc) - h) ** 2)
    return atan2(ell * cos(thc), d), (th1 - th0) / 2, thc


def disk_closed(d, h, r):
    """§2 closed form."""
    t = d * d + h * h - r * r
    delta = sqrt(t * t + 4 * d * d * r * r)
    lam = (t + delta) / 2
    big_a, big_b = sqrt(lam + r * r), sqrt(lam * delta)
    f = dict(ta=r / sqrt(lam), tb=r * d / lam, ca=sqrt(lam) / big_a, sa=r / big_a, omca=r * r / (big_a * (big_a + sqrt(lam))),
             cb=lam / big_b, sb=d * r / big_b, omcb=d * d * r * r / (big_b * (big_b + lam)), omm=delta / big_a ** 2,
             sinc=h * lam / (big_a * big_b), cosc=d * (lam + r * r) / (big_a * big_b), lam=lam, t=t)
    if t < 0:
        dd = delta - t
        f['ta_neg'], f['tb_neg'] = sqrt(dd / 2) / d, dd / (2 * d * r)
    return f


def disk_bruteforce(d, h, r):
    """Omega = integral of d / dist^3 over the disk, polar about the foot point, radial part exact."""
    def angular(t):
        bb = h * sin(t)
        disc = bb * bb - (h * h - r * r)
        if disc <= 0:
            return mpf(0)
        r1, r2 = max(mpf(0), bb - sqrt(disc)), bb + sqrt(disc)
        if r2 <= 0:
            return mpf(0)
        return d / sqrt(r1 * r1 + d * d) - d / sqrt(r2 * r2 + d * d)
    if h < r:
        return quad(angular, [-pi / 2, 0, pi / 2, pi, 3 * pi / 2])
    t0 = asin(r / h)
    return 2 * quad(angular, [pi / 2 - t0, pi / 2 - t0 / 2, pi / 2])


def ellipse_of_cone(c, toward):
    """§2b: tan alpha, tan beta and frame from the eigen-decomposition of the cone matrix."""
    ev, vecs = eigsy(matrix(c))
    vals = [ev[i] for i in range(3)]
    ineg = min(range(3), key=lambda i: vals[i])
    pos = sorted((i for i in range(3) if i != ineg), key=lambda i: -vals[i])
    z = [vecs[j, ineg] for j in range(3)]
    if sum(u * v for u, v in zip(z, toward)) < 0:
        z = [-v for v in z]
    return sqrt(-vals[ineg] / vals[pos[1]]), sqrt(-vals[ineg] / vals[pos[0]]), z, [vecs[j, pos[1]] for j in range(3)]


def check_projection():
    """§2 disk closed form against the geometric construction and brute force; §2b cones."""
    for d, h in [(1, '0.5'), (1, 1), (1, 2), ('0.1', 3), (10, 5), ('0.001', '0.5'), (2, '0.3'), ('0.5', '1.5'),
                 ('1e-3', '0.9999'), ('1e-3', '1.0001')]:
        d, h, r = mpf(d), mpf(h), mpf(1)
        al, be, thc = disk_geometric(d, h, r)
        f = disk_closed(d, h, r)
        rec('§2 tan alpha = r/sqrt(lambda), tan beta = r d/lambda', max(abs(f['ta'] / tan(al) - 1), abs(f['tb'] / tan(be) - 1)), EXACT)
        if 'ta_neg' in f:
            rec('§2 T < 0 forms', max(abs(f['ta_neg'] / f['ta'] - 1), abs(f['tb_neg'] / f['tb'] - 1)), EXACT)
        for key, val in [('ca', cos(al)), ('sa', sin(al)), ('omca', 1 - cos(al)), ('cb', cos(be)), ('sb', sin(be)),
                         ('omcb', 1 - cos(be)), ('sinc', sin(thc)), ('cosc', cos(thc))]:
            rec('§2 fields from lambda (A, B)', f[key] / val - 1, EXACT)
        m = (tan(al) ** 2 - tan(be) ** 2) / (1 + tan(al) ** 2)
        rec('§2 1 - m = Delta/A^2', f['omm'] / (1 - m) - 1, EXACT)
        rec('§2 alpha >= beta and lambda >= d^2', 0 if (f['lam'] >= d * d and al >= be) else 1, 0)
        rec('§2 tan a tan b = r^2 d / lambda^(3/2)', f['ta'] * f['tb'] / (r * r * d / f['lam'] ** mpf(1.5)) - 1, EXACT)
        om = mpf(4) / 3 * f['ta'] * f['tb'] * elliprj(0, 1 + f['tb'] ** 2, 1 + f['ta'] ** 2, 1)
        rec('§2/§3 disk Omega vs brute-force integral', om / disk_bruteforce(d, h, r) - 1, EXACT)
    rng = random.Random(11)

    def rnd(lo=-1.0, hi=1.0):
        return mpf(rng.uniform(lo, hi))
    for _ in range(6):
        d, h, r = rnd(0.1, 3), rnd(0, 3), rnd(0.2, 2)
        # disk as a planar ellipse: C = B^T J B with M = r I, centre (0, h)
        f = disk_closed(d, h, r)
        cone = [[d * d * r * r, 0, 0], [0, d * d * r * r, -d * h * r * r], [0, -d * h * r * r, (h * h - r * r) * r * r]]
        ta, tb, z, x = ellipse_of_cone(cone, [0, h, d])
        rec('§2b eigen-decomposition reproduces the disk', max(abs(ta / f['ta'] - 1), abs(tb / f['tb'] - 1), 1 - abs(x[0])), EXACT)
        # general planar ellipse (conjugate semi-diameters)
        c = [rnd(), rnd()]
        mm = [[rnd() * 2, rnd()], [rnd(), rnd() * 2]]
        dm = mm[0][0] * mm[1][1] - mm[0][1] * mm[1][0]
        adj = [[mm[1][1], -mm[0][1]], [-mm[1][0], mm[0][0]]]
        bm = [[d * adj[0][0], d * adj[0][1], -(adj[0][0] * c[0] + adj[0][1] * c[1])],
              [d * adj[1][0], d * adj[1][1], -(adj[1][0] * c[0] + adj[1][1] * c[1])], [0, 0, dm]]
        jd = [1, 1, -1]
        cm = [[sum(bm[k][i] * jd[k] * bm[k][j] for k in range(3)) for j in range(3)] for i in range(3)]
        for _ in range(200):
            v = [rnd(-2, 2), rnd(-2, 2), mpf(1)]
            qx, qy = d * v[0] / v[2] - c[0], d * v[1] / v[2] - c[1]
            s0, s1 = (adj[0][0] * qx + adj[0][1] * qy) / dm, (adj[1][0] * qx + adj[1][1] * qy) / dm
            inside = s0 * s0 + s1 * s1 <= 1
            rec('§2b ellipse cone: v^T C v <= 0 iff the ray hits', 0 if inside == (sum(v[i] * cm[i][j] * v[j] for i in range(3) for j in range(3)) <= 0) else 1, 0)
        pm = [[mm[0][0], mm[0][1], c[0]], [mm[1][0], mm[1][1], c[1]], [0, 0, d]]
        cinv = matrix([[sum(pm[i][k] * jd[k] * pm[j][k] for k in range(3)) for j in range(3)] for i in range(3)])
        prod = matrix(cm) * cinv
        sc = (d * dm) ** 2
        rec('§2b C^-1 = P J P^T / (d det M)^2', max(abs(prod[i, j] - (sc if i == j else 0)) for i in range(3) for j in range(3)) / sc, EXACT)
        rec('§2b det C = -d^4 det(M)^4', det(matrix(cm)) / (-(d ** 4) * dm ** 4) - 1, EXACT)
        # ellipsoid
        ax = [rnd(0.2, 2) for _ in range(3)]
        q = [rnd() * 4 + 3, rnd() * 4, rnd() * 4]
        aq = [q[i] / ax[i] ** 2 for i in range(3)]
        k = sum(u * v for u, v in zip(q, aq)) - 1
        ce = [[(k / ax[i] ** 2 if i == j else 0) - aq[i] * aq[j] for j in range(3)] for i in range(3)]
        dual = matrix([[(ax[i] ** 2 if i == j else 0) - q[i] * q[j] for j in range(3)] for i in range(3)])
        prod = matrix(ce) * dual
        rec('§2b ellipsoid C^-1 = (A^-1 - q q^T)/(q^T A q - 1)', max(abs(prod[i, j] - (k if i == j else 0)) for i in range(3) for j in range(3)) / k, EXACT)
        rec('§2b ellipsoid det C = -(q^T A q - 1)^2 det A', det(matrix(ce)) / (-(k ** 2) / (ax[0] * ax[1] * ax[2]) ** 2) - 1, EXACT)
        for _ in range(50):
            v = [rnd(), rnd(), rnd()]
            disc = sum(u * w for u, w in zip(v, aq)) ** 2 - sum(v[i] ** 2 / ax[i] ** 2 for i in range(3)) * k
            rec('§2b ellipsoid: v^T C v = -discriminant', (sum(v[i] * ce[i][j] * v[j] for i in range(3) for j in range(3)) + disc) / max(abs(disc), mpf(1)), EXACT)
        rr, dd = rnd(0.1, 1), rnd(1.1, 5)
        cs = [[(dd * dd / rr ** 2 - 1) / rr ** 2 if i == j else 0 for j in range(3)] for i in range(3)]
        cs[2][2] -= dd * dd / rr ** 4
        ta, tb, _, _ = ellipse_of_cone(cs, [0, 0, -1])
        rec('§2b sphere: tan alpha = R/sqrt((D-R)(D+R))', ta / (rr / sqrt((dd - rr) * (dd + rr))) - 1, EXACT)
        rec('§2b sphere: Omega = 2 pi (1 - sqrt(1 - R^2/D^2))',
            mpf(4) / 3 * ta * tb * elliprj(0, 1 + tb ** 2, 1 + ta ** 2, 1) / (2 * pi * (1 - sqrt(1 - rr * rr / (dd * dd)))) - 1, EXACT)
    report('Projection (§2, §2b)')


def check_elliptic():
    """§1b: Legendre/Carlson relations, cel, duplication, series, the n < 0 forms, large p."""
    rng = random.Random(3)
    for _ in range(30):
        y, z, p = [mpf(10) ** rng.uniform(-6, 6) for _ in range(3)]
        big, small, q = sqrt(max(y, z)), sqrt(min(y, z)), sqrt(p)
        e, bb, aa, two_n = big * small, mpf(1), mpf(0), mpf(1)
        for _ in range(200):
            g = e / q
            aa, bb, q = aa + bb / q, 2 * (bb + aa * g), q + g
            big0, big = big, big + small
            two_n *= 2
            if abs(big0 - small) <= mpf(10) ** -35 * big0:
                break
            small = 2 * sqrt(e)
            e = small * big
        rj = mpf(3) / 2 * pi * (bb + aa * big) / (big * (big + q)) / sqrt(p)
        rec('§1b Bulirsch cel: R_J(0, y, z, p)', rj / elliprj(0, y, z, p) - 1, EXACT)
        rec('§1b Bulirsch cel: R_F(0, y, z)', (pi / 2 * two_n / big) / elliprf(0, y, z) - 1, EXACT)
        a_, g_ = sqrt(z), sqrt(y)
        integral = 3 * quad(lambda t: sin(t) ** 2 / ((a_ * a_ * cos(t) ** 2 + p * sin(t) ** 2) * sqrt(a_ * a_ * cos(t) ** 2 + g_ * g_ * sin(t) ** 2)), [0, pi / 4, pi / 2])
        rec('§1b R_J(0, y, z, p) as an integral over [0, pi/2]', integral / elliprj(0, y, z, p) - 1, mpf(10) ** -25)
        rec('§1b R_F(0, y, z) = pi/(2 M(sqrt y, sqrt z))', (pi / (2 * agm(sqrt(y), sqrt(z)))) / elliprf(0, y, z) - 1, EXACT)
    for _ in range(20):
        x, y, z, p = [mpf(10) ** rng.uniform(-2, 2) for _ in range(4)]
        ref = elliprj(x, y, z, p)
        delta, total, f = (p - x) * (p - y) * (p - z), mpf(0), mpf(1)
        for _ in range(6):
            sx, sy, sz, sp = sqrt(x), sqrt(y), sqrt(z), sqrt(p)
            lam = sx * sy + sy * sz + sz * sx
            dk = (sp + sx) * (sp + sy) * (sp + sz)
            ek = delta / dk ** 2
            rec('§1b 1 + e_k = 2 sqrt(p_k)(p_k + lambda_k)/d_k', (1 + ek) - 2 * sp * (p + lam) / dk, EXACT)
            total += f * elliprc(1, 1 + ek) / dk
            x, y, z, p = (x + lam) / 4, (y + lam) / 4, (z + lam) / 4, (p + lam) / 4
            f, delta = f / 4, delta / 64
        rec('§1b duplication with the R_C sum', (f * elliprj(x, y, z, p) + 6 * total) / ref - 1, EXACT)
    for eps in (mpf('0.1'), mpf('0.01')):   # degree-9 tails: the error must scale as eps^10
        for _ in range(10):
            xx, yy = eps * mpf(rng.uniform(-1, 1)), eps * mpf(rng.uniform(-1, 1))
            zz = -(xx + yy)
            e2, e3 = xx * yy - zz * zz, xx * yy * zz
            ser = 1 + (e2 * (mpf(-1) / 10 + e2 / 24) + e2 ** 3 * (mpf(-5) / 208 + e2 * mpf(35) / 2176) +
                       e3 * ((mpf(1) / 14 - e2 * 3 / 44) + e2 ** 2 * (mpf(1) / 16 - e2 * mpf(35) / 608) +
                             e3 * (mpf(3) / 104 - e2 * mpf(15) / 272 + e3 * mpf(5) / 304)))
            rec('§1b R_F degree-9 series: error / eps^10', (ser - elliprf(1 - xx, 1 - yy, 1 - zz)) / eps ** 10, 2)
    for _ in range(40):
        phi = mpf(rng.uniform(0.01, 1.55))
        s, c = sin(phi), cos(phi)
        m = mpf(rng.choice([rng.uniform(-50, 0), rng.uniform(0, 0.999)]))
        n = mpf(rng.choice([rng.uniform(-1e4, -0.25), rng.uniform(-0.25, 0.99)]))
        y = c * c + (1 - m) * s * s
        big_f = s * elliprf(c * c, y, 1)
        rec('§1 F = s R_F(c^2, 1 - m s^2, 1)', big_f / ellipf(phi, m) - 1, EXACT)
        if n >= -0.25:
            v = big_f + n / 3 * s ** 3 * elliprj(c * c, y, 1, c * c + (1 - n) * s * s)
            vc = elliprf(0, 1 - m, 1) + n / 3 * elliprj(0, 1 - m, 1, 1 - n)
        elif m >= 0:
            k = m / -n
            q = 1 + k * s * s
            v = s * elliprc(c * c * y, (1 - n * s * s) * q) + k / 3 * s ** 3 * elliprj(c * c, y, 1, q)
            vc = pi / 2 / (sqrt(1 - n) * sqrt(1 + k)) + k / 3 * elliprj(0, 1 - m, 1, 1 + k)
        else:
            q = c * c + (1 - m) * s * s / (1 - n)
            v = (big_f - n * s * c * elliprc(y, (1 - n * s * s) * q) - n * (1 - m) / (3 * (1 - n)) * s ** 3 * elliprj(c * c, y, 1, q)) / (1 - n)
            vc = (elliprf(0, 1 - m, 1) - n * (1 - m) / (3 * (1 - n)) * elliprj(0, 1 - m, 1, (1 - m) / (1 - n))) / (1 - n)
        rec('§1b Pi(n; phi|m) in the form used for its n, m', v / ellippi(n, phi, m) - 1, EXACT)
        rec('§1b Pi(n|m) in the form used for its n, m', vc / ellippi(n, m) - 1, EXACT)
    for _ in range(20):
        x, y, z = sorted(mpf(10) ** rng.uniform(-3, 3) for _ in range(3))
        p = z * mpf(10) ** rng.uniform(5, 20)
        q = y - (y - x) * (z - y) / (p - y)
        v = (3 * elliprf(x, y, z) - 3 * elliprc(x * z / y, p * q / y) + (y - q) * elliprj(x, y, z, q)) / (p - y)
        rec('§1b large-p reduction (DLMF 19.21.12)', v / elliprj(x, y, z, p) - 1, EXACT)
    for x, y in ((mpf(1), mpf(3)), (mpf('0.2'), mpf(5)), (mpf(4), mpf('0.5'))):
        closed = atan(sqrt((y - x) / x)) / sqrt(y - x) if x < y else \
            mp.log1p((sqrt(x - y) + (x - y) / (sqrt(x) + sqrt(y))) / sqrt(y)) / sqrt(x - y)
        rec('§1b R_C closed forms', closed / elliprc(x, y) - 1, EXACT)
    report('Elliptic integrals (§1, §1b)')


def check_maps_and_tables():
    """§4 Lambert guess, §6 tabulated density, the authors' derivative and tabulation."""
    print('\nNumbers quoted in docs/math.md')
    for al, be in ((mpf('1e-3'), mpf('1e-4')), (mpf('0.3'), mpf('0.05')), (mpf('1.5'), mpf('0.1'))):
        a, b, ca, cb = sin(al), sin(be), cos(al), cos(be)
        area = lambda t_: quad(lambda t: a * b / (1 + sqrt(ca ** 2 * cos(t) ** 2 + cb ** 2 * sin(t) ** 2)), [0, t_])  # noqa: E731
        kap, quarter = cos(al / 2) / cos(be / 2), area(pi / 2)
        worst = max(abs(area(atan(kap * tan(f * pi / 2))) / quarter - f) for f in (mpf(i) / 10 for i in range(1, 10)))
        print(f'  §4 Lambert first guess, CDF error, (alpha, beta) = ({mp.nstr(al, 2)}, {mp.nstr(be, 2)}): {mp.nstr(worst, 2)}')
    for al, be in ((mpf('1.5'), mpf('1.45')), (mpf('1.2'), mpf('0.3')), (mpf('0.6'), mpf('0.5')), (mpf('0.3'), mpf('0.05'))):
        a, b, ta, tb = sin(al), sin(be), tan(al), tan(be)
        aa, bb = a * sqrt(1 - b * b), b * sqrt(1 - a * a)
        m, n, c = (ta ** 2 - tb ** 2) / (1 + ta ** 2), 1 - tb ** 2 / ta ** 2, tb * cos(al) / ta
        ratios = []
        for phi in (mpf(i) / 40 * pi for i in range(1, 20)):
            s2 = sin(atan((aa / bb) * tan(phi))) ** 2
            coded = 1 - c * aa * bb / ((1 - n * s2) * sqrt(1 - m * s2) * (bb * cos(phi) ** 2 + aa * sin(phi) ** 2))
            true = 1 - c * aa * bb / ((1 - n * s2) * sqrt(1 - m * s2) * (bb * bb * cos(phi) ** 2 + aa * aa * sin(phi) ** 2))
            rec('§6 chain-rule derivative = 1 - cos theta_max(phi)', true / wedge(a, b, phi) - 1, EXACT)
            ratios.append(coded / true)
        print(f'  §6 authors\' derivative / true, (alpha, beta) = ({mp.nstr(al, 3)}, {mp.nstr(be, 3)}): '
              f'{mp.nstr(min(ratios), 3)} .. {mp.nstr(max(ratios), 3)}')
    # §6 the authors' tabulation: expectation of a constant emitter = sum_i P_i A_i / W_i (double precision)
    gx = (0.0, 0.5384693101056831, -0.5384693101056831, 0.9061798459386640, -0.9061798459386640)
    gw = (0.5688888888888889, 0.4786286704993665, 0.4786286704993665, 0.2369268850561891, 0.2369268850561891)

    def fwedge(a, b, phi):
        r2 = (a * b) ** 2 / ((a * math.sin(phi)) ** 2 + (b * math.cos(phi)) ** 2)
        return r2 / (1 + math.sqrt(1 - r2))

    def bin_areas(a, b, nb, sub=8):
        h = math.pi / 2 / nb
        return [sum(sum(w * fwedge(a, b, i * h + (j + 0.5) * h / sub + 0.5 * h / sub * x) for x, w in zip(gx, gw)) * 0.5 * h / sub
                    for j in range(sub)) for i in range(nb)]

    for nb in (32, 512):
        vals = []
        for al in (0.05, 0.3, 0.7, 1.0, 1.3, 1.5):
            for ratio in (0.1, 0.3, 0.5, 0.9, 0.99):
                be = al * ratio
                a, b = math.sin(al), math.sin(be)
                k = min(int(nb * be / al), nb - 1)
                ref = bin_areas(math.sin(math.pi / 4), math.sin(math.pi / 4 * (k + 1) / nb), nb)
                act = bin_areas(a, b, nb)
                h = math.pi / 2 / nb
                vals.append(sum(ref[i] / sum(ref) * act[i] / (h * fwedge(a, b, i * h)) for i in range(nb)))
        print(f'  §6 authors\' tabulation, N = {nb}: expectation / truth of a constant emitter {min(vals):.6f} .. {max(vals):.6f}')
    # §6 apse's tabulated map: the reported density is the map's true density, for any monotone table
    rng = random.Random(5)
    mp.dps = 30
    for al, be in ((mpf('0.3'), mpf('0.1')), (mpf('1.4'), mpf('0.2')), (mpf('1.0'), mpf('0.9'))):
        a, b, ca, cb = sin(al), sin(be), cos(al), cos(be)
        kap = sqrt((1 + ca) / (1 + cb))
        nb = 8
        cdf = [mpf(0)]
        for _ in range(nb):
            cdf.append(cdf[-1] + mpf(rng.uniform(0.5, 1.5)))
        cdf = [v / cdf[-1] for v in cdf]
        width = pi / 2 / nb

        def sample(u1, u2):
            q = min(int(floor(4 * u1)), 3)
            f = 4 * u1 - q
            if q % 2:
                f = 1 - f
            k = min(max(i for i in range(nb) if cdf[i] <= f), nb - 1)
            lam = (k + (f - cdf[k]) / (cdf[k + 1] - cdf[k])) * width
            px, py = cos(lam), kap * sin(lam)
            ct, st = px / sqrt(px * px + py * py), py / sqrt(px * px + py * py)
            c = sqrt(ca ** 2 * ct ** 2 + cb ** 2 * st ** 2)
            r2 = (a * ct) ** 2 + (b * st) ** 2
            v = u2 * r2 / (1 + c)
            sth = sqrt(v * (2 - v))
            w = [a * ct * sth / sqrt(r2), b * st * sth / sqrt(r2), (1 - u2) + u2 * c]
            if q in (1, 2):
                w[0] = -w[0]
            if q >= 2:
                w[1] = -w[1]
            return w, nb * (cdf[k + 1] - cdf[k]) * kap * (1 + c) / (2 * pi * a * b * (kap ** 2 * ct ** 2 + st ** 2))
        for _ in range(6):
            u1, u2, h = mpf(rng.uniform(0.01, 0.99)), mpf(rng.uniform(0.05, 0.95)), mpf(10) ** -10
            _, pdf = sample(u1, u2)
            d1 = [(p - q) / (2 * h) for p, q in zip(sample(u1 + h, u2)[0], sample(u1 - h, u2)[0])]
            d2 = [(p - q) / (2 * h) for p, q in zip(sample(u1, u2 + h)[0], sample(u1, u2 - h)[0])]
            cr = (d1[1] * d2[2] - d1[2] * d2[1], d1[2] * d2[0] - d1[0] * d2[2], d1[0] * d2[1] - d1[1] * d2[0])
            rec('§6 tabulated: 1/|Jacobian| = reported pdf (any table)', 1 / sqrt(sum(v * v for v in cr)) / pdf - 1, mpf(10) ** -15)
        for lam in (mpf('0.3'), mpf('1.2')):
            tau = atan(kap * tan(lam))
            c = sqrt(ca ** 2 * cos(tau) ** 2 + cb ** 2 * sin(tau) ** 2)
            dens = a * b * kap / ((1 + c) * (cos(lam) ** 2 + kap ** 2 * sin(lam) ** 2))
            num = diff(lambda l_: quad(lambda t: a * b / (1 + sqrt(ca ** 2 * cos(t) ** 2 + cb ** 2 * sin(t) ** 2)), [0, atan(kap * tan(l_))]), lam)
            rec('§6 dOmega_r/dlambda closed form', num / dens - 1, mpf(10) ** -20)
            rec('§6 the two forms of dOmega_r/dlambda', dens / (a * b * (kap ** 2 * cos(tau) ** 2 + sin(tau) ** 2) / (kap * (1 + c))) - 1, mpf(10) ** -20)
    mp.dps = 40
    report('Inversion and tabulation (§4, §6)')


def print_reference_values():
    """§10: the reference disks and, for d = 1, h = 0.5, the frame, areas and sampled directions."""
    print('\n§10 reference values (d, h, alpha, beta, Omega; Omega also by the brute-force integral)')
    for d, h in [(1, 0), (1, '0.5'), (1, 1), (1, 2), ('0.1', 3), (10, 5), ('0.001', '0.5'), (100, 0)]:
        d, h = mpf(d), mpf(h)
        f = disk_closed(d, h, mpf(1))
        om = mpf(4) / 3 * f['ta'] * f['tb'] * elliprj(0, 1 + f['tb'] ** 2, 1 + f['ta'] ** 2, 1)
        rec('§10 Omega = brute-force integral', om / disk_bruteforce(d, h, mpf(1)) - 1, EXACT)
        print(f"  {mp.nstr(d, 3):>6s} {mp.nstr(h, 3):>4s} {mp.nstr(atan(f['ta']), 32)} {mp.nstr(atan(f['tb']), 32)} {mp.nstr(om, 32)}")
    f = disk_closed(mpf(1), mpf('0.5'), mpf(1))
    ta, tb = f['ta'], f['tb']
    al, be = atan(ta), atan(tb)
    a, b, ca, cb = sin(al), sin(be), cos(al), cos(be)
    m = (ta ** 2 - tb ** 2) / (1 + ta ** 2)
    om = mpf(4) / 3 * ta * tb * elliprj(0, 1 + tb ** 2, 1 + ta ** 2, 1)
    print(f"  d = 1, h = 0.5: y = ({mp.nstr(f['cosc'], 20)}, 0, {mp.nstr(f['sinc'], 20)}), "
          f"z = ({mp.nstr(f['sinc'], 20)}, 0, {mp.nstr(-f['cosc'], 20)})")

    def omega_r(phi):
        return omega_r_tau(a, b, ca, cb, tb, m, atan2(a * sin(phi), b * cos(phi))) if phi > 0 else mpf(0)

    def half(psi):
        s = min(mpf(1), tan(psi) / tb)
        return 2 * a * tb * (s * elliprf(1 - s * s, 1 - m * s * s, 1) - (1 + tb ** 2) / 3 * s ** 3 * elliprj(1 - s * s, 1 - m * s * s, 1, 1 + tb ** 2 * s * s))

    def bisect(fn, lo, hi, target):
        for _ in range(160):
            mid = (lo + hi) / 2
            lo, hi = (mid, hi) if fn(mid) < target else (lo, mid)
        return (lo + hi) / 2

    def radial(u1, u2):
        q = min(int(floor(4 * u1)), 3)
        f_ = 4 * u1 - q
        if q % 2:
            f_ = 1 - f_
        phi0 = bisect(omega_r, mpf(0), pi / 2, f_ * om / 4)
        phi = q * pi / 2 + phi0 if q % 2 == 0 else (q + 1) * pi / 2 - phi0
        v = u2 * wedge(a, b, phi)
        return sqrt(v * (2 - v)) * cos(phi), sqrt(v * (2 - v)) * sin(phi), 1 - v

    def parallel(u1, u2):
        psi = bisect(lambda p: half(p) if p >= 0 else -half(-p), -be, be, u1 * om - om / 2)
        yt = tan(abs(psi))
        xt = ta * sqrt(1 - yt ** 2 / tb ** 2)
        x = (2 * u2 - 1) * xt / sqrt(1 + xt ** 2 + yt ** 2)
        return x, sqrt(1 - x * x) * sin(psi), sqrt(1 - x * x) * cos(psi)

    def concentric(u1, u2):
        aa, bb = 2 * u1 - 1, 2 * u2 - 1
        if abs(aa) > abs(bb):
            return abs(aa), pi / 4 * (bb / aa) + (pi if aa < 0 else (2 * pi if bb < 0 else 0))
        return abs(bb), pi / 2 - pi / 4 * (aa / bb) + (pi if bb < 0 else 0)

    print(f"  Omega_r(0.7) = {mp.nstr(omega_r(mpf('0.7')), 20)}, Omega_p(0.3 beta) = {mp.nstr(om / 2 + half(mpf('0.3') * be), 20)}")
    u1, u2 = mpf('0.3'), mpf('0.6')
    rho, ang = concentric(u1, u2)
    for name, w in (('radial', radial(u1, u2)), ('parallel', parallel(u1, u2)), ('LD-radial', radial(ang / (2 * pi), rho ** 2))):
        print(f"  {name:9s} (0.3, 0.6): " + ', '.join(mp.nstr(v, 20) for v in w))
    report('Reference values (§10)')


def check_projected_solid_angle():
    """§13: F against quadrature of its density, the two forms of c sin(theta), the rim's
    theta_max against the cone, E's series, the horizon's crossings of the boundary and dphi/dt."""
    rnd = random.Random(13)
    tiny = mpf(10) ** -30
    for _ in range(40):
        a, b = mpf(rnd.uniform(0, 1)), mpf(rnd.uniform(-1, 1))
        end = mpf(rnd.uniform(0.01, 1.5))
        if a * cos(end) + b * sin(end) < 0:
            continue
        F = (a * sin(end) ** 2 + b * (end - sin(end) * cos(end))) / 2
        rec('§13 F(d) = ∫ sin t (a cos t + b sin t) dt', F / quad(lambda t: sin(t) * (a * cos(t) + b * sin(t)), [0, end]) - 1, tiny)
        # n_z <= 0: c = K sin d and sin theta = (s sin d − n_z cos d)/K around theta_0
        nz, s = -mpf(rnd.uniform(0, 1)), mpf(rnd.uniform(0.01, 1))
        K = sqrt(nz ** 2 + s ** 2)
        th0 = atan2(-nz, s)
        d = mpf(rnd.uniform(0, 1))
        th = th0 + d
        rec('§13 c = K sin d after the horizon', (nz * cos(th) + s * sin(th)) - K * sin(d), tiny)
        rec('§13 sin theta = (s sin d − n_z cos d)/K', sin(th) - (s * sin(d) - nz * cos(d)) / K, tiny)
    for x in (mpf('1e-6'), mpf('0.1'), mpf('0.3'), mpf('0.49')):  # E's Taylor series (9 terms)
        y2, p = 4 * x * x, mpf(1)
        for den in (342, 272, 210, 156, 110, 72, 42, 20):
            p = 1 - y2 / den * p
        rec('§13 E series below d = 1/2 (relative)', (mpf(2) / 3 * x ** 3 * p) / (x - sin(x) * cos(x)) - 1, mpf('1e-16'))
    for ta, tb in ((mpf(3), mpf('0.5')), (mpf('0.01'), mpf('0.002')), (mpf(40), mpf(2))):
        for phi in (mpf('0.2'), mpf('1.1'), mpf('2.5')):
            D = cos(phi) ** 2 / ta ** 2 + sin(phi) ** 2 / tb ** 2
            st, ct = 1 / sqrt(1 + D), sqrt(D) / sqrt(1 + D)
            gx, gy = st * cos(phi) / ct, st * sin(phi) / ct  # the rim point in the gnomonic plane
            rec('§13 theta_max on the cone', (gx / ta) ** 2 + (gy / tb) ** 2 - 1, tiny)
        # the horizon's line n_x x + n_y y = −n_z crosses the boundary at psi_n ± gamma
        nx, ny, nz = mpf('0.7'), mpf('0.4'), -mpf('0.3') * min(ta, tb)
        L = sqrt((nx * ta) ** 2 + (ny * tb) ** 2)
        psin, gam = atan2(ny * tb, nx * ta), mp.acos(-nz / L)
        for psi in (psin + gam, psin - gam):
            rec('§13 the horizon crosses the boundary at psi_n ± gamma', nx * ta * cos(psi) + ny * tb * sin(psi) + nz, tiny)
    for q in (mpf('0.05'), mpf('0.6'), mpf(1)):  # dphi/dt = 2 pi q / (cos^2 tau + q^2 sin^2 tau)
        for t in (mpf('0.03'), mpf('0.11'), mpf('0.2')):
            phi = lambda tt: atan2(q * sin(2 * pi * tt), cos(2 * pi * tt))
            tau = 2 * pi * t
            rec('§13 dphi/dt', diff(phi, t) / (2 * pi * q / (cos(tau) ** 2 + q ** 2 * sin(tau) ** 2)) - 1, mpf('1e-25'))
    report('Projected-solid-angle sampling (§13)')


def check_tabulated_cosine_warp():
    """§13 (the tabulated maps' warp): the cosine along a ray in r = sqrt(u2), the horizon's
    radius r_h, the two forms of the model c~ at a cut ray, its mass polynomial G, and c~'s
    exactness at the centre, the rim and the horizon."""
    rnd = random.Random(1313)
    tiny = mpf(10) ** -30
    checked = 0
    while checked < 60:
        tmax = mpf(rnd.uniform(0.001, 1.5))  # the ray's rim angle
        C, st = cos(tmax), sin(tmax)
        h, ipc = 1 - C, 1 / (1 + C)
        nz, s = mpf(rnd.uniform(0.01, 1)), mpf(rnd.uniform(-1, 1))
        b = s * st
        r = mpf(rnd.uniform(0, 1))
        theta = mp.acos(1 - h * r * r)  # u2 = r^2: cos theta = 1 − h u2
        c_true = nz * cos(theta) + s * sin(theta)
        rec('§13 warp: sin theta = r sqrt(h (2 − h r^2))', sin(theta) - r * sqrt(h * (2 - h * r * r)), tiny)
        rec('§13 warp: h = sin^2 theta_max / (1 + C)', h - st ** 2 * ipc, tiny)
        rim = nz * C + b
        if rim >= 0:  # the whole ray above the horizon: c~ = nz (1 − h r^2) + b r
            g2, g3, g4 = nz, 2 * b / 3, -nz * h / 2
            model = lambda x: nz * (1 - h * x * x) + b * x
            rec('§13 warp: c~ exact at the rim', model(1) - rim, tiny)
            end = mpf(1)
        else:  # cut at r_h: beta = sqrt(K (K + |b|) ipc), r_h = nz / beta
            K = sqrt(nz ** 2 * st ** 2 + b ** 2)
            beta = sqrt(K * (K + abs(b)) * ipc)
            rh = nz / beta
            th_h = atan2(nz, -s)  # tan theta_h = nz / (−s)
            rec('§13 warp: r_h^2 = (1 − cos theta_h)/h', rh ** 2 - (1 - cos(th_h)) / h, tiny)
            rec('§13 warp: the cosine vanishes at r_h', nz * cos(th_h) + s * sin(th_h), tiny)
            bstar = nz * h * rh - beta
            model = lambda x: beta * (rh - x) * (1 + h * rh * x)
            rec('§13 warp: beta (rh − r)(1 + h rh r) = nz (1 − h r^2) + B* r',
                model(r) - (nz * (1 - h * r * r) + bstar * r), tiny)
            g2, g3, g4 = nz, 2 * bstar / 3, -nz * h / 2
            end = rh
            r = r * rh  # a point of [0, r_h]
        rec('§13 warp: c~ exact at the centre', model(0) - nz, tiny)
        G = r * r * (g2 + r * (g3 + g4 * r))
        rec('§13 warp: G(r) = ∫ 2 x c~(x) dx', G - quad(lambda x: 2 * x * model(x), [0, r]), tiny)
        rec('§13 warp: G(end) = ∫ c~ du2', end ** 2 * (g2 + end * (g3 + g4 * end)) - quad(lambda u: model(sqrt(u)), [0, end ** 2]), mpf(10) ** -25)
        checked += 1
    report("The tabulated maps' cosine warp (§13)")


if __name__ == '__main__':
    check_ellipse_forms()
    check_projection()
    check_elliptic()
    check_maps_and_tables()
    print_reference_values()
    check_projected_solid_angle()
    check_tabulated_cosine_warp()
    if FAILED:
        print(f'\n{len(FAILED)} check(s) failed: ' + ', '.join(FAILED))
        sys.exit(1)
    print('\nall checks passed')
