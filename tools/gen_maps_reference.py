#!/usr/bin/env python3
"""Reference tables for apse's area-preserving maps (tests/data/maps/).

    python3 tools/gen_maps_reference.py            # rewrites tests/data/maps/*.txt

Seeded and reproducible (the same files byte for byte on every run); needs only mpmath.
Every input is exactly representable in float32 and written as a hex float (float.hex()), so the
float and the double tests see the same ellipse. An ellipse is given by its gnomonic semi-axes
tan(alpha) >= tan(beta) (what SphericalEllipse::from_tangents takes). References are computed at
40 digits and written with 30 significant digits.

Everything is computed from the *definitions* of docs/math.md §1, §4, §5 by quadrature, independently
of the closed forms the library uses:

ellipses.txt       id tan_alpha tan_beta Omega      Omega = 4 * int_0^{pi/2} (1 - cos theta_max(phi)) dphi
radial_area.txt    id phi Omega_r(phi)              int_0^phi (1 - cos theta_max) dphi', phi in [0, pi/2]
parallel_area.txt  id psi I(psi)                    int_0^psi 2 x_max(psi') dpsi', psi in [0, beta]
samples.txt        id map u1 u2 x y z               local direction (x major axis, z centre) of the
                                                    radial / parallel / ld_radial map at u, with the
                                                    azimuth / slice solved from the quadrature CDFs
                                                    (bisection to 1e-30)

with 1 - cos theta_max(phi) = r^2/(1 + sqrt(1 - r^2)), r = ab/sqrt(a^2 sin^2 phi + b^2 cos^2 phi)
(a = sin alpha, b = sin beta) and x_max(psi) = x_t/sqrt(1 + x_t^2 + tan^2 psi),
x_t = tan(alpha) sqrt(1 - tan^2 psi / tan^2 beta). The quadrature intervals are split at the
azimuths where the planar ellipse reaches k/16 of its area (so thin ellipses' narrow peaks are
resolved). As a cross-check the script also evaluates the Carlson forms of docs/math.md §3–§5 (R_J total,
cancellation-free Omega_r, Carlson Omega_p) and asserts agreement to 1e-25 relative.
"""

import os
import random
import sys

import mpmath as mp

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from mp_reference import f32, hexf, dec  # noqa: E402

mp.mp.dps = 40
SEED = 20170619
OUT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "tests", "data", "maps")
PI = mp.pi


class Ellipse:
    def __init__(self, ta, tb):
        self.ta, self.tb = mp.mpf(ta), mp.mpf(tb)
        self.alpha, self.beta = mp.atan(self.ta), mp.atan(self.tb)
        self.a, self.b = mp.sin(self.alpha), mp.sin(self.beta)

    # ---- radial (docs/math.md §4) -------------------------------------------------------------
    def wedge(self, phi):
        """1 - cos theta_max(phi): solid angle per unit azimuth."""
        a, b = self.a, self.b
        r2 = (a * b) ** 2 / ((a * mp.sin(phi)) ** 2 + (b * mp.cos(phi)) ** 2)
        return r2 / (1 + mp.sqrt(1 - r2))

    def splits(self, lo, hi):
        # azimuths where the planar ellipse has k/16 of its quadrant area
        pts = [mp.atan2(self.tb * mp.sin(k * PI / 32), self.ta * mp.cos(k * PI / 32)) for k in range(1, 16)]
        return [lo] + [p for p in pts if lo < p < hi] + [hi]

    def omega_r(self, phi):
        phi = mp.mpf(phi)
        if phi <= 0:
            return mp.mpf(0)
        return mp.quad(self.wedge, self.splits(mp.mpf(0), phi))

    def omega(self):
        return 4 * self.omega_r(PI / 2)

    def omega_r_carlson(self, phi):
        """docs/math.md §4 cancellation-free form (cross-check only)."""
        at, bt, a = self.ta, self.tb, self.a
        m = (at * at - bt * bt) / (1 + at * at)
        c = bt * mp.cos(self.alpha) / at
        t = mp.atan2(at * mp.sin(phi), bt * mp.cos(phi))
        s, ct = mp.sin(t), mp.cos(t)
        w = mp.sqrt(1 - m * s * s)
        ca = mp.cos(self.alpha)
        q = bt / at
        t1 = c * a * a / 3 * s ** 3 * mp.elliprj(ct * ct, w * w, 1, 1 - a * a * s * s)
        t2 = mp.atan2(q * s * ct * (a * a - m * s * s) / (w * (w + ca)), ct * ct + q * q * s * s * ca / w)
        return t1 + t2

    def omega_carlson(self):
        at, bt = self.ta, self.tb
        return mp.mpf(4) / 3 * at * bt * mp.elliprj(0, 1 + bt * bt, 1 + at * at, 1)

    # ---- parallel (docs/math.md §5) -----------------------------------------------------------
    def x_max(self, psi):
        yt = mp.tan(psi)
        g = 1 - (yt / self.tb) ** 2
        if g <= 0:
            return mp.mpf(0)
        xt = self.ta * mp.sqrt(g)
        return xt / mp.sqrt(1 + xt * xt + yt * yt)

    def half_area(self, psi):
        psi = mp.mpf(psi)
        if psi <= 0:
            return mp.mpf(0)
        return mp.quad(lambda p: 2 * self.x_max(p), mp.linspace(0, psi, 5))

    def half_area_carlson(self, psi):
        at, bt = self.ta, self.tb
        m = (at * at - bt * bt) / (1 + at * at)
        s = min(mp.tan(psi) / bt, mp.mpf(1))
        c2 = 1 - s * s
        y = 1 - m * s * s
        return 2 * self.a * bt * (s * mp.elliprf(c2, y, 1)
                                  - (1 + bt * bt) / 3 * s ** 3 * mp.elliprj(c2, y, 1, 1 + bt * bt * s * s))


def bisect(f, lo, hi, target, tol=mp.mpf(10) ** -32):
    """x in [lo, hi] with f(x) = target, f increasing."""
    for _ in range(200):
        mid = (lo + hi) / 2
        if f(mid) < target:
            lo = mid
        else:
            hi = mid
        if hi - lo < tol:
            break
    return (lo + hi) / 2


def radial_local(E, Q, u1, u2):
    u1, u2 = mp.mpf(u1), mp.mpf(u2)
    q = min(int(mp.floor(4 * u1)), 3)
    f = 4 * u1 - q
    if q % 2:
        f = 1 - f
    phi0 = bisect(E.omega_r_carlson, mp.mpf(0), PI / 2, f * Q) if 0 < f < 1 else (0 if f <= 0 else PI / 2)
    assert abs(E.omega_r(phi0) - f * Q) < mp.mpf(10) ** -28 * Q
    phi = q * PI / 2 + phi0 if q % 2 == 0 else (q + 1) * PI / 2 - phi0
    v = u2 * E.wedge(phi)  # 1 - cos theta
    st = mp.sqrt(v * (2 - v))
    return (st * mp.cos(phi), st * mp.sin(phi), 1 - v)


def parallel_local(E, Om, u1, u2):
    u1, u2 = mp.mpf(u1), mp.mpf(u2)
    half = Om / 2
    target = u1 * Om - half  # signed area from the major axis

    def signed(p):
        return E.half_area_carlson(p) if p >= 0 else -E.half_area_carlson(-p)
    psi = bisect(signed, -E.beta, E.beta, target)
    err = abs((E.half_area(abs(psi)) if psi >= 0 else -E.half_area(-psi)) - target)
    assert err < mp.mpf(10) ** -22 * Om, (E.ta, E.tb, err / Om)
    x = (2 * u2 - 1) * E.x_max(psi)
    r = mp.sqrt(1 - x * x)
    return (x, r * mp.sin(psi), r * mp.cos(psi))


def concentric(u1, u2):
    """Shirley–Chiu concentric map in polar form (rho, theta in [0, 2 pi)), docs/math.md §4."""
    A, B = 2 * mp.mpf(u1) - 1, 2 * mp.mpf(u2) - 1
    if A == 0 and B == 0:
        return mp.mpf(0), mp.mpf(0)
    if abs(A) > abs(B):
        rho, th = abs(A), PI / 4 * (B / A) + (0 if A > 0 else PI)
    else:
        rho, th = abs(B), PI / 2 - PI / 4 * (A / B) + (0 if B > 0 else PI)
    return rho, th % (2 * PI)


def ld_radial_local(E, Q, u1, u2):
    rho, th = concentric(u1, u2)
    return radial_local(E, Q, th / (2 * PI), rho * rho)


def main():
    rng = random.Random(SEED)
    os.makedirs(OUT, exist_ok=True)
    t = lambda x: f32(mp.tan(mp.mpf(x)))
    hp = float(PI / 2)
    specs = [
        (1e-5, 1e-5), (1e-5, 1e-9),                         # tiny circle, tiny and very thin
        (t(0.05), t(0.02)), (t(0.3), t(0.05)), (t(0.6), t(0.5)), (t(1.2), t(0.3)),
        (t(1.5), t(1.45)), (1.0, 1.0),                      # large, cap of 45 degrees
        (1e4, 9e3), (1e4, t(0.5)), (1e4, t(1e-4 * (hp - 1e-4))),   # nearly hemispherical: fat, mid, very thin
        (t(1.0), 1e-4),                                     # thin
        (t(0.75424914469804604), t(0.72322066612406759)),  # docs/math.md §10 disk d = 1, h = 0.5
    ]
    for i in range(3):                                      # random shapes
        a = rng.uniform(0.01, 1.5)
        specs.append((t(a), t(a * rng.uniform(0.05, 1.0))))
    ells = [Ellipse(f32(a), f32(b)) for a, b in specs]

    with open(os.path.join(OUT, "ellipses.txt"), "w") as f:
        f.write("# id tan_alpha tan_beta Omega   (tools/gen_maps_reference.py)\n")
        for i, E in enumerate(ells):
            om = E.omega()
            assert abs(om - E.omega_carlson()) < mp.mpf(10) ** -25 * om, (i, om, E.omega_carlson())
            E.Om = om
            f.write("%d %s %s %s\n" % (i, hexf(E.ta), hexf(E.tb), dec(om)))

    with open(os.path.join(OUT, "radial_area.txt"), "w") as f:
        f.write("# id phi Omega_r(phi)   quadrant cumulative area, phi in [0, pi/2]\n")
        for i, E in enumerate(ells):
            phis = [f32(x) for x in (1e-3, 0.1, 0.4, 0.7854, 1.2, 1.5)]
            # azimuths where the thin ellipses change fastest
            phis += [f32(mp.atan2(E.tb * mp.sin(k), E.ta * mp.cos(k))) for k in (0.3, 0.8, 1.3)]
            for phi in phis:
                v = E.omega_r(phi)
                assert abs(v - E.omega_r_carlson(mp.mpf(phi))) < mp.mpf(10) ** -25 * E.Om, (i, phi)
                f.write("%d %s %s\n" % (i, hexf(phi), dec(v)))

    with open(os.path.join(OUT, "parallel_area.txt"), "w") as f:
        f.write("# id psi I(psi)   half-area between the slices 0 and psi, psi in [0, beta]\n")
        for i, E in enumerate(ells):
            for frac in (0.01, 0.3, 0.6, 0.9, 0.99, 0.9999):
                psi = f32(frac * E.beta)
                if psi > E.beta:
                    continue
                v = E.half_area(psi)
                assert abs(v - E.half_area_carlson(mp.mpf(psi))) < mp.mpf(10) ** -22 * E.Om, (i, psi)
                f.write("%d %s %s\n" % (i, hexf(psi), dec(v)))

    with open(os.path.join(OUT, "samples.txt"), "w") as f:
        f.write("# id map u1 u2 x y z   local direction (x major axis, y minor, z centre)\n")
        for i, E in enumerate(ells):
            Q = E.Om / 4
            us = [(0.3, 0.6), (0.9, 0.25), (0.55, 0.999), (0.125, 0.5)]
            us += [(f32(rng.random()), f32(rng.random())) for _ in range(2)]
            for u1, u2 in us:
                u1, u2 = f32(u1), f32(u2)
                for name, fn, arg in (("radial", radial_local, Q), ("parallel", parallel_local, E.Om),
                                      ("ld_radial", ld_radial_local, Q)):
                    x, y, z = fn(E, arg, u1, u2)
                    f.write("%d %s %s %s %s %s %s\n" % (i, name, hexf(u1), hexf(u2), dec(x), dec(y), dec(z)))
    print("wrote", OUT)


if __name__ == "__main__":
    main()
