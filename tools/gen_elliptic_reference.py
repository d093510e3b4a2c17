#!/usr/bin/env python3
"""Generate the elliptic-integral reference tables used by apse's C++ tests.

Writes one CSV per function into tests/data/elliptic/ (or --out DIR):

    carlson_rf.csv     x,y,z,value,category        R_F(x,y,z)
    carlson_rd.csv     x,y,z,value,category        R_D(x,y,z)
    carlson_rj.csv     x,y,z,p,value,category      R_J(x,y,z,p), p > 0 only
    carlson_rc.csv     x,y,value,category          R_C(x,y)
    ellint_f.csv       phi,m,value,category        F(phi|m)
    ellint_pi.csv      n,phi,m,value,category      Pi(n;phi|m)
    comp_ellint_k.csv  m,value,category            K(m)
    comp_ellint_pi.csv n,m,value,category          Pi(n|m)
    carlson_rj_wide.csv x,y,z,p,value,category     R_J over the whole exponent range (see below)

Legendre integrals use the PARAMETER m = k^2 (as mpmath and DLMF), and the sign convention
Pi(n;phi|m) = int_0^phi dtheta / ((1 - n sin^2 theta) sqrt(1 - m sin^2 theta)).

Run from anywhere:

    python3 tools/gen_elliptic_reference.py [--out DIR]

Requirements: python3 with mpmath (1.3.0 used); nothing else. Takes well under a few minutes.

Exact-in-float rule: every input is rounded to IEEE binary32 (struct.pack('f', ...)) BEFORE the
reference is computed, and the reference is computed for that exact rounded value. Inputs are
written as hexadecimal floating literals (Python float.hex(), parsed exactly by std::strtod), so
the very same table serves the float and the double instantiations. Reference values are written
with 30 significant digits; every nonzero value satisfies 1e-30 < |value| < 1e30 (the only zero
values are the exact ones, F(0|m) = Pi(n;0|m) = 0, category phi_zero).

References are computed with mpmath at mp.dps = 40 (elliprf, elliprd, elliprj, elliprc, ellipf,
ellippi, ellipk). Each of these is cross-checked, inside this script, against an independent
evaluation: mp.quad (tanh-sinh) of the DEFINING integral at the same precision, for every 10th
"random" row and for every special-case row. The script aborts (exit status 1, nothing written)
if any cross-check disagrees by more than 1e-25 relative. It also checks a few exact identities
(R_D(x,y,z) = R_J(x,y,z,z), Pi(0;phi|m) = F(phi|m), ...).

carlson_rj_wide.csv holds R_J at arguments spread over the whole exponent range of double
(category wide_double: inputs exact in binary64, subnormals included) or of float (wide_float:
exact in binary32), e.g. R_J(1e300, 1e-300, 1e-300, 0.5): one huge argument and the others tiny,
in every position, p anywhere, and the other splits of the four arguments into a large and a
small group. Only rows whose reference is a normal number of that type are kept. mpmath's elliprj
needs about as many digits as the arguments' ratio has (at 40 digits it returns inf for the
example), so these references use mp.dps = 40 + 1.1 log10(max/min) and are checked against the
same evaluation at 20 more digits and against the quadrature (every float row, every 3rd double
row: seconds each), whose integrand is normalised by the size of the result (mp.quad's
tolerance is absolute).

The output is deterministic (fixed seed, no time stamps): running it twice gives byte-identical
files.
"""

import argparse
import math
import os
import random
import sys
import time

import mpmath
from mpmath import mp, mpf

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import mp_reference  # noqa: E402
from mp_reference import f32  # noqa: E402

SEED = 20170619
DPS = 40
TOL = mpf('1e-25')
# Plain random rows: only every 10th of them is cross-checked by quadrature (all others are).
SAMPLED_CATEGORIES = ('random', 'y_gt_x', 'y_lt_x')
GENERATOR = 'tools/gen_elliptic_reference.py'
VALUE_DIGITS = 30

mp.dps = DPS


# ---------------------------------------------------------------------------------------------
# float32 helpers
# ---------------------------------------------------------------------------------------------

def hexf(x):
    """mp_reference.hexf, except that a zero is always written 0x0.0p+0 (never -0.0)."""
    if float(x) == 0.0:
        return '0x0.0p+0'
    return mp_reference.hexf(x)


F32_HALF_PI = f32(math.pi / 2)  # 0x1.921fb60000000p+0, slightly LARGER than pi/2
assert F32_HALF_PI > math.pi / 2


def loguniform(r, lo, hi):
    return math.exp(r.uniform(math.log(lo), math.log(hi)))


def pos32(r, lo=1e-4, hi=1e4):
    """Log-uniform positive float32 in [lo, hi]."""
    return f32(loguniform(r, lo, hi))


def param_m(r):
    """A float32 parameter m < 1: ordinary, large negative, or close to 1."""
    u = r.random()
    if u < 0.4:
        v = f32(r.uniform(-1.0, 1.0))
    elif u < 0.65:
        v = f32(-loguniform(r, 1e-4, 1e4))
    else:
        v = f32(1.0 - loguniform(r, 2.0 ** -24, 1.0))
    assert v < 1.0
    return v


def phi32(r):
    return f32(r.uniform(-math.pi / 2, math.pi / 2))


# ---------------------------------------------------------------------------------------------
# Independent evaluations: quadrature of the defining integrals
# ---------------------------------------------------------------------------------------------

def _carlson_points(args):
    """Break points, in s = log t, for int_0^inf dt: log of every positive argument and every
    power of 10 in between.  The integrand e^s f(e^s) decays exponentially at both ends (also
    with a zero argument), which tanh-sinh on the infinite end intervals handles to full
    precision; the break points resolve the different scales."""
    pos = sorted(set(mpf(a) for a in args if a > 0))
    pts = set(pos)
    lo, hi = pos[0], pos[-1]
    e = int(mpmath.floor(mpmath.log10(lo))) + 1
    while mpf(10) ** e < hi:
        pts.add(mpf(10) ** e)
        e += 1
    return [-mpmath.inf] + [mpmath.log(p) for p in sorted(pts)] + [mpmath.inf]


def carlson_quad(f, args):
    """int_0^inf f(t) dt, computed as int_-inf^inf e^s f(e^s) ds."""
    def g(s):
        t = mpmath.exp(s)
        return t * f(t)
    return mpmath.quad(g, _carlson_points(args))


def quad_rf(x, y, z):
    x, y, z = mpf(x), mpf(y), mpf(z)
    f = lambda t: 1 / mpmath.sqrt((t + x) * (t + y) * (t + z))
    return carlson_quad(f, [x, y, z]) / 2


def quad_rd(x, y, z):
    x, y, z = mpf(x), mpf(y), mpf(z)
    f = lambda t: 1 / ((t + z) * mpmath.sqrt((t + x) * (t + y) * (t + z)))
    return 3 * carlson_quad(f, [x, y, z]) / 2


def quad_rj(x, y, z, p):
    x, y, z, p = mpf(x), mpf(y), mpf(z), mpf(p)
    f = lambda t: 1 / ((t + p) * mpmath.sqrt((t + x) * (t + y) * (t + z)))
    return 3 * carlson_quad(f, [x, y, z, p]) / 2


def quad_rc(x, y):
    x, y = mpf(x), mpf(y)
    f = lambda t: 1 / ((t + y) * mpmath.sqrt(t + x))
    return carlson_quad(f, [x, y]) / 2


def _theta_points(phi, m, n=0):
    """Break points on [0, |phi|] for the Legendre integrands.  Their peaks sit at theta = 0
    when m or n is large negative (width ~ 1/sqrt(|m|)) and at theta = pi/2 when m or n -> 1
    (width ~ sqrt(1 - m)); geometric break points towards the peak, down to a quarter of its
    width, resolve them."""
    a = abs(mpf(phi))
    hp = mpmath.pi / 2
    pts = {mpf(0), a}
    big = max(-mpf(m), -mpf(n), mpf(1))
    near = min(1 - mpf(m), 1 - mpf(n), mpf(1))
    deep0 = int(mpmath.ceil(mpmath.log(mpmath.sqrt(big), 2))) + 2
    deep1 = int(mpmath.ceil(-mpmath.log(mpmath.sqrt(near), 2))) + 2
    for j in range(1, deep0 + 1):
        t = mpf(2) ** -j
        if t < a:
            pts.add(t)
    for j in range(1, deep1 + 1):
        t = hp - mpf(2) ** -j
        if 0 < t < a:
            pts.add(t)
    if hp < a:
        pts.add(hp)
    return sorted(pts)


def quad_legendre(integrand, phi, m, n=0):
    phi = mpf(phi)
    if phi == 0:
        return mpf(0)
    # The integrands are even in theta, so F and Pi are odd in phi.
    v = mpmath.quad(integrand, _theta_points(phi, m, n))
    return v if phi > 0 else -v


def quad_f(phi, m):
    m = mpf(m)
    return quad_legendre(lambda t: 1 / mpmath.sqrt(1 - m * mpmath.sin(t) ** 2), phi, m)


def quad_pi(n, phi, m):
    n, m = mpf(n), mpf(m)

    def f(t):
        s2 = mpmath.sin(t) ** 2
        return 1 / ((1 - n * s2) * mpmath.sqrt(1 - m * s2))

    return quad_legendre(f, phi, m, n)


# ---------------------------------------------------------------------------------------------
# Tables
# ---------------------------------------------------------------------------------------------

class Table:
    def __init__(self, name, args, ref, quad, describe):
        self.name, self.args, self.ref, self.quad, self.describe = name, args, ref, quad, describe
        self.rows = []  # (inputs tuple of float32-exact floats, category)
        self.seen = set()

    def add(self, inputs, category):
        inputs = tuple(f32(v) for v in inputs)
        assert ',' not in category and category == category.lower()
        if inputs not in self.seen:  # drop exact duplicates (keep the first category)
            self.seen.add(inputs)
            self.rows.append((inputs, category))


def build_tables(r):
    tables = []

    # ---- R_F(x, y, z) ------------------------------------------------------------------------
    t = Table('carlson_rf', ['x', 'y', 'z'], mpmath.elliprf, quad_rf,
              'R_F(x,y,z) = 1/2 int_0^inf dt / sqrt((t+x)(t+y)(t+z)); x,y,z >= 0, at most one 0')
    for _ in range(320):
        t.add((pos32(r), pos32(r), pos32(r)), 'random')
    for i in range(60):  # zero in each position
        v = [0.0, pos32(r), pos32(r)]
        k = i % 3
        v[0], v[k] = v[k], v[0]
        t.add(v, 'one_zero')
    for _ in range(20):
        a = pos32(r)
        t.add((a, a, a), 'equal')
    t.add((1.0, 1.0, 1.0), 'equal')
    for i in range(45):
        a, b = pos32(r), pos32(r)
        t.add([(a, a, b), (a, b, a), (b, a, a)][i % 3], 'two_equal')
    for i in range(15):  # two equal with the third one zero: R_F(0,a,a) = pi/(2 sqrt a)
        a = pos32(r)
        t.add([(0.0, a, a), (a, 0.0, a), (a, a, 0.0)][i % 3], 'two_equal')
    for i in range(48):  # extreme ratios: each argument near 1e-4 or near 1e4
        v = [pos32(r, 1e-4, 2e-4) if (i >> k) & 1 else pos32(r, 5e3, 1e4) for k in range(3)]
        if i % 8 == 7:
            v[i % 3] = 0.0
        t.add(v, 'extreme')
    tables.append(t)

    # ---- R_D(x, y, z) ------------------------------------------------------------------------
    t = Table('carlson_rd', ['x', 'y', 'z'], mpmath.elliprd, quad_rd,
              'R_D(x,y,z) = 3/2 int_0^inf dt / ((t+z) sqrt((t+x)(t+y)(t+z))); '
              'x,y >= 0 at most one 0, z > 0')
    for _ in range(320):
        t.add((pos32(r), pos32(r), pos32(r)), 'random')
    for i in range(50):
        a, c = pos32(r), pos32(r)
        t.add((0.0, a, c) if i % 2 == 0 else (a, 0.0, c), 'one_zero')
    for _ in range(20):
        a = pos32(r)
        t.add((a, a, a), 'equal')
    t.add((1.0, 1.0, 1.0), 'equal')
    for i in range(45):
        a, b = pos32(r), pos32(r)
        t.add([(a, a, b), (a, b, b), (b, a, b)][i % 3], 'two_equal')
    for i in range(10):  # R_D(0, a, a) and R_D(a, 0, a)
        a = pos32(r)
        t.add((0.0, a, a) if i % 2 == 0 else (a, 0.0, a), 'two_equal')
    for i in range(48):
        v = [pos32(r, 1e-4, 2e-4) if (i >> k) & 1 else pos32(r, 5e3, 1e4) for k in range(3)]
        if i % 8 == 7:
            v[i % 2] = 0.0
        t.add(v, 'extreme')
    tables.append(t)

    # ---- R_J(x, y, z, p) ---------------------------------------------------------------------
    t = Table('carlson_rj', ['x', 'y', 'z', 'p'], mpmath.elliprj, quad_rj,
              'R_J(x,y,z,p) = 3/2 int_0^inf dt / ((t+p) sqrt((t+x)(t+y)(t+z))); '
              'x,y,z >= 0 at most one 0, p > 0')
    for _ in range(320):
        t.add((pos32(r), pos32(r), pos32(r), pos32(r)), 'random')
    for i in range(45):
        v = [pos32(r), pos32(r), pos32(r)]
        v[i % 3] = 0.0
        t.add(v + [pos32(r)], 'one_zero')
    for _ in range(20):
        a = pos32(r)
        t.add((a, a, a, a), 'equal')
    t.add((1.0, 1.0, 1.0, 1.0), 'equal')
    for i in range(40):
        a, b, c = pos32(r), pos32(r), pos32(r)
        t.add([(a, a, b, c), (b, a, a, c), (a, b, c, c), (a, a, a, b)][i % 4], 'two_equal')
    for i in range(48):
        v = [pos32(r, 1e-4, 2e-4) if (i >> k) & 1 else pos32(r, 5e3, 1e4) for k in range(4)]
        if i % 8 == 7:
            v[i % 3] = 0.0
        t.add(v, 'extreme')
    for i in range(40):  # p much smaller than x, y, z
        v = [pos32(r, 1e-1, 1e4) for _ in range(3)]
        if i % 4 == 3:
            v[i % 3] = 0.0
        t.add(v + [pos32(r, 1e-4, 1e-2)], 'p_small')
    for i in range(40):  # p much larger than x, y, z
        v = [pos32(r, 1e-4, 1e1) for _ in range(3)]
        if i % 4 == 3:
            v[i % 3] = 0.0
        t.add(v + [pos32(r, 1e2, 1e4)], 'p_large')
    for i in range(40):  # p == z: R_J(x,y,z,z) = R_D(x,y,z)
        v = [pos32(r), pos32(r), pos32(r)]
        if i % 5 == 4:
            v[i % 2] = 0.0
        t.add(v + [v[2]], 'p_eq_z')
    for _ in range(30):  # the solid-angle form (docs/math.md §3): R_J(0, 1+tan^2 b, 1+tan^2 a, 1)
        ta = loguniform(r, 1e-4, 1e3)
        tb = ta * r.uniform(0.0, 1.0)
        tb = max(tb, 1e-4)
        t.add((0.0, 1.0 + tb * tb, 1.0 + ta * ta, 1.0), 'solid_angle')
    # Complete R_J(0, y, z, p) with p/max(y, z) = 2^-k from 2^40 down to 2^-125: both sides of
    # the switch between Bulirsch's transformation and duplication (2^-64 float, 2^-120 double).
    # Own generator, so that the rows above stay as they were.
    rw = random.Random(SEED + 1)
    ks = [-40, -24, -8, 0, 8, 24, 40, 56, 62, 63, 64, 65, 66, 80, 100, 118, 119, 120, 121, 122, 125]
    ks += [rw.randint(-40, 125) for _ in range(27)]
    for i, k in enumerate(ks):
        big, small = pos32(rw, 1.0, 1e4), pos32(rw, 1e-4, 1e4)
        v = [big, min(small, big)] if i % 2 == 0 else [min(small, big), big]
        v.insert(i % 3, 0.0)
        t.add(v + [max(v) * 2.0 ** -k], 'complete_p_wide')
    tables.append(t)

    # ---- R_C(x, y) ---------------------------------------------------------------------------
    t = Table('carlson_rc', ['x', 'y'], mpmath.elliprc, quad_rc,
              'R_C(x,y) = 1/2 int_0^inf dt / ((t+y) sqrt(t+x)); x >= 0, y > 0')
    for _ in range(320):
        x, y = pos32(r), pos32(r)
        t.add((x, y), 'y_gt_x' if y > x else ('y_lt_x' if y < x else 'equal'))
    for _ in range(30):
        t.add((0.0, pos32(r)), 'x_zero')
    for _ in range(25):
        a = pos32(r)
        t.add((a, a), 'equal')
    t.add((1.0, 1.0), 'equal')
    for i in range(48):  # y = x (1 +- 2^-k): the branch switch at x = y
        a = pos32(r, 1e-3, 1e3)
        k = 1 + (i // 2) % 24
        y = f32(a * (1.0 + 2.0 ** -k)) if i % 2 == 0 else f32(a * (1.0 - 2.0 ** -k))
        if y == a:
            y = f32(a * (1.0 + 2.0 ** -(k - 2)))
        t.add((a, y), 'near_equal')
    for i in range(40):  # ratios ~1e8 both ways
        a, b = pos32(r, 1e-4, 2e-4), pos32(r, 5e3, 1e4)
        t.add((a, b) if i % 2 == 0 else (b, a), 'extreme')
    tables.append(t)

    # ---- F(phi | m) --------------------------------------------------------------------------
    t = Table('ellint_f', ['phi', 'm'], mpmath.ellipf, quad_f,
              'F(phi|m) = int_0^phi dtheta / sqrt(1 - m sin^2 theta); m = k^2 < 1')
    for _ in range(320):
        t.add((phi32(r), param_m(r)), 'random')
    for _ in range(20):
        t.add((phi32(r), 0.0), 'm_zero')
    for _ in range(40):
        t.add((phi32(r), -pos32(r, 1e-4, 1e4)), 'm_negative')
    for k in range(1, 25):  # 1 - 2^-k, k = 1..24 (1 - 2^-24 is the largest float below 1)
        m = 1.0 - 2.0 ** -k
        t.add((phi32(r), m), 'm_near_one')
        t.add((f32(r.uniform(1.2, math.pi / 2)), m), 'm_near_one')
    for i in range(40):  # phi = +-float32(pi/2) (> pi/2 in magnitude)
        m = [0.0, param_m(r), -pos32(r), 1.0 - 2.0 ** -(1 + i % 24)][i % 4]
        t.add((F32_HALF_PI if i % 2 == 0 else -F32_HALF_PI, m), 'phi_half_pi')
    for i in range(10):
        t.add((0.0, param_m(r)), 'phi_zero')
    for i in range(30):  # tiny |phi|
        t.add((pos32(r, 1e-8, 1e-2) * (1 if i % 2 == 0 else -1), param_m(r)), 'phi_small')
    tables.append(t)

    # ---- Pi(n; phi | m) ----------------------------------------------------------------------
    t = Table('ellint_pi', ['n', 'phi', 'm'], mpmath.ellippi, quad_pi,
              'Pi(n;phi|m) = int_0^phi dtheta / ((1 - n sin^2 theta) sqrt(1 - m sin^2 theta)); '
              'm = k^2 < 1, n < 1')
    for _ in range(320):
        t.add((param_m(r), phi32(r), param_m(r)), 'random')
    for _ in range(25):
        t.add((0.0, phi32(r), param_m(r)), 'n_zero')
    for i in range(50):  # n = -tan^2(beta), down to -1e4 (parallel map)
        phi = F32_HALF_PI if i % 5 == 0 else phi32(r)
        t.add((-pos32(r, 1e-4, 1e4), phi, param_m(r)), 'n_negative')
    for k in range(1, 25):
        n = 1.0 - 2.0 ** -k
        t.add((n, phi32(r), param_m(r)), 'n_near_one')
        t.add((n, f32(r.uniform(1.2, math.pi / 2)), param_m(r)), 'n_near_one')
    for k in range(1, 25):
        m = 1.0 - 2.0 ** -k
        t.add((param_m(r), phi32(r), m), 'm_near_one')
    for _ in range(25):
        t.add((param_m(r), phi32(r), -pos32(r)), 'm_negative')
    for i in range(40):
        n = [0.0, param_m(r), -pos32(r), 1.0 - 2.0 ** -(1 + i % 24)][i % 4]
        m = [param_m(r), 1.0 - 2.0 ** -(1 + (7 * i) % 24)][(i // 4) % 2]
        t.add((n, F32_HALF_PI if i % 2 == 0 else -F32_HALF_PI, m), 'phi_half_pi')
    for _ in range(10):
        t.add((param_m(r), 0.0, param_m(r)), 'phi_zero')
    for i in range(20):
        t.add((param_m(r), pos32(r, 1e-8, 1e-2) * (1 if i % 2 == 0 else -1), param_m(r)),
              'phi_small')
    tables.append(t)

    # ---- K(m) --------------------------------------------------------------------------------
    t = Table('comp_ellint_k', ['m'], mpmath.ellipk, lambda m: quad_f(mpmath.pi / 2, m),
              'K(m) = F(pi/2|m) = int_0^(pi/2) dtheta / sqrt(1 - m sin^2 theta); m = k^2 < 1')
    for _ in range(300):
        t.add((param_m(r),), 'random')
    t.add((0.0,), 'm_zero')
    for _ in range(30):
        t.add((f32(r.uniform(-1.0, 1.0) * loguniform(r, 1e-8, 1e-2)),), 'm_small')
    for _ in range(50):
        t.add((-pos32(r),), 'm_negative')
    t.add((-1e4,), 'm_negative')
    for k in range(1, 25):
        t.add((1.0 - 2.0 ** -k,), 'm_near_one')
    for j in range(3, 40, 2):  # 1 - j 2^-24 (odd j: neighbours of the largest floats below 1)
        t.add((1.0 - j * 2.0 ** -24,), 'm_near_one')
    tables.append(t)

    # ---- Pi(n | m) ---------------------------------------------------------------------------
    t = Table('comp_ellint_pi', ['n', 'm'], mpmath.ellippi,
              lambda n, m: quad_pi(n, mpmath.pi / 2, m),
              'Pi(n|m) = Pi(n;pi/2|m) = int_0^(pi/2) dtheta / ((1 - n sin^2 theta) '
              'sqrt(1 - m sin^2 theta)); m = k^2 < 1, n < 1')
    for _ in range(320):
        t.add((param_m(r), param_m(r)), 'random')
    for _ in range(25):
        t.add((0.0, param_m(r)), 'n_zero')
    for _ in range(30):  # Pi(m|m) = E(m)/(1-m)
        m = param_m(r)
        t.add((m, m), 'n_eq_m')
    for k in range(1, 25):
        t.add((1.0 - 2.0 ** -k, param_m(r)), 'n_near_one')
        t.add((1.0 - 2.0 ** -k, 1.0 - 2.0 ** -(1 + (5 * k) % 24)), 'n_near_one')
    for _ in range(40):
        t.add((-pos32(r), param_m(r)), 'n_negative')
    t.add((-1e4, 0.0), 'n_negative')
    for k in range(1, 25):
        t.add((param_m(r), 1.0 - 2.0 ** -k), 'm_near_one')
    for _ in range(25):
        t.add((param_m(r), -pos32(r)), 'm_negative')
    for _ in range(30):  # the Booth solid-angle form (docs/math.md §3): m < n < 1
        ta = loguniform(r, 1e-2, 1e2)
        tb = ta * r.uniform(0.01, 1.0)
        n = f32(1.0 - (tb / ta) ** 2)
        m = f32((ta * ta - tb * tb) / (1.0 + ta * ta))
        t.add((n, m), 'solid_angle')
    for _ in range(30):  # the parallel-map form (docs/math.md §3): Pi(-tan^2 b | m)
        ta = loguniform(r, 1e-2, 1e2)
        tb = ta * r.uniform(0.01, 1.0)
        m = f32((ta * ta - tb * tb) / (1.0 + ta * ta))
        t.add((-tb * tb, m), 'parallel_form')
    tables.append(t)

    return tables


# ---------------------------------------------------------------------------------------------
# R_J over the whole exponent range
# ---------------------------------------------------------------------------------------------

DBL_MIN, DBL_MAX = 2.0 ** -1022, 1.7976931348623157e308
FLT_MIN, FLT_MAX = 2.0 ** -126, 3.4028234663852886e38


def wide_dps(args):
    pos = [mpf(a) for a in args if a > 0]
    return int(DPS + 1.1 * float(mpmath.log10(max(pos) / min(pos))))


def wide_rj(args, extra=0):
    with mpmath.workdps(wide_dps(args) + extra):
        return +mpmath.elliprj(*[mpf(a) for a in args])


def wide_quad(args):
    """The quadrature of quad_rj with the integrand scaled to a result of order 1."""
    with mpmath.workdps(DPS):
        scale = mpmath.ldexp(1, -int(mpmath.floor(mpmath.log(wide_rj(args), 2))))
        x, y, z, p = [mpf(a) for a in args]
        f = lambda t: scale / ((t + p) * mpmath.sqrt((t + x) * (t + y) * (t + z)))
        return 3 * carlson_quad(f, [x, y, z, p]) / 2 / scale


def wide_rows(r):
    """(inputs, category): per type, one huge argument with the others tiny in every position
    (x huge, y and z tiny, p anywhere, and permutations), p tiny or huge, and random splits of
    the four arguments into two groups a large factor apart; a zero argument in some rows."""
    rows = []
    for kind, (lo, hi), rnd, n in (('wide_double', (-1074, 1023), float, 12),
                                   ('wide_float', (-149, 127), f32, 24)):
        span = hi - lo

        def val(e):
            e = min(max(e, lo), hi - 1)
            v = rnd(r.uniform(1.0, 2.0) * 2.0 ** e)
            return v if v > 0 else rnd(2.0 ** lo)

        # the finding's family: x huge, y and z tiny, p anywhere (and the other positions)
        for i in range(n):
            big = r.uniform(hi - span * 0.15, hi - 1)
            small = [r.uniform(lo, lo + span * 0.45) for _ in range(2)]
            pe = r.uniform(lo, hi - 1)
            v = [val(big), val(small[0]), val(small[1])]
            if i % 6 == 5:
                v[1] = 0.0
            j = i % 3
            v[0], v[j] = v[j], v[0]
            rows.append((v + [val(pe)], kind))
        # p tiny or huge, x, y, z spread
        for i in range(n // 2):
            v = [val(r.uniform(lo, hi)) for _ in range(3)]
            pe = r.uniform(lo, lo + span * 0.1) if i % 2 == 0 else r.uniform(hi - span * 0.1, hi - 1)
            rows.append((v + [val(pe)], kind))
        # two groups: k of the four arguments large, the others small
        for i in range(n):
            gap = r.uniform(span * 0.3, span * 0.9)
            base = r.uniform(lo, hi - gap)
            es = [base + r.uniform(0, (span - gap) * 0.1) for _ in range(4)]
            for k in r.sample(range(4), 1 + i % 3):
                es[k] += gap
            v = [val(e) for e in es]
            if i % 8 == 7:
                v[r.randrange(3)] = 0.0
            rows.append((v, kind))
    return rows


def build_wide(r, stats):
    """The rows of carlson_rj_wide.csv whose reference is a normal number of their type."""
    out = []
    for inputs, category in wide_rows(r):
        assert sum(v == 0 for v in inputs[:3]) <= 1 and inputs[3] > 0
        v = wide_rj(inputs)
        tiny, huge = (DBL_MIN, DBL_MAX) if category == 'wide_double' else (FLT_MIN, FLT_MAX)
        if not (tiny <= v <= huge):
            continue
        checks = [(wide_rj(inputs, 20), 'mpmath at 20 more digits')]
        # the quadrature over ~2000 decades takes seconds: every 3rd wide_double row, every wide_float row
        if category == 'wide_float' or len(out) % 3 == 0:
            checks.append((wide_quad(inputs), 'quadrature'))
        for check, what in checks:
            e = relerr(v, check)
            stats['checked'] += 1
            if e > stats['max'].get('carlson_rj_wide', (mpf(-1),))[0]:
                stats['max']['carlson_rj_wide'] = (e, inputs, category)
            if e > TOL:
                raise SystemExit('CROSS-CHECK FAILED carlson_rj_wide%s [%s]: %s vs %s %s'
                                 % (inputs, category, mpmath.nstr(v, 35), what, mpmath.nstr(check, 35)))
        out.append((tuple(inputs), category, v))
    return out


def write_wide(rows, outdir):
    cats = []
    for _, c, _ in rows:
        if c not in cats:
            cats.append(c)
    lines = [
        '# apse elliptic-integral reference table: carlson_rj_wide',
        '# generator: %s (mpmath %s, mp.dps = 40 + 1.1 log10(max/min), random.Random(%d))'
        % (GENERATOR, mpmath.__version__, SEED + 2),
        '# R_J(x,y,z,p) = 3/2 int_0^inf dt / ((t+p) sqrt((t+x)(t+y)(t+z))) with arguments spread over '
        'the whole exponent range',
        '# columns: inputs (x, y, z, p) as hexadecimal float literals, exact in binary64 (wide_double) '
        'or binary32 (wide_float);',
        '#   value = reference for those exact inputs, %d significant decimal digits, a normal number '
        'of the category\'s type;' % VALUE_DIGITS,
        '#   category = %s' % ' '.join(cats),
        '# cross-checked against mpmath at 20 more digits (every row) and against mp.quad of the defining '
        'integral, normalised (every wide_float row, every 3rd wide_double row), to < 1e-25 relative',
        'x,y,z,p,value,category',
    ]
    for inputs, category, v in rows:
        hx = [('0x0.0p+0' if a == 0 else float(a).hex()) for a in inputs]
        if category == 'wide_float':
            assert all(f32(a) == a for a in inputs)
        lines.append(','.join(hx + [fmt_value(v), category]))
    path = os.path.join(outdir, 'carlson_rj_wide.csv')
    with open(path, 'w', newline='\n') as fh:
        fh.write('\n'.join(lines) + '\n')
    return path


# ---------------------------------------------------------------------------------------------
# Evaluation, cross-checks, output
# ---------------------------------------------------------------------------------------------

def relerr(a, b):
    if a == b:
        return mpf(0)
    return abs(a - b) / max(abs(a), abs(b))


def evaluate(table, stats):
    values = []
    nrandom = 0
    for inputs, category in table.rows:
        args = [mpf(v) for v in inputs]  # exact: float32 -> binary64 -> mpf
        v = table.ref(*args)
        if not mpmath.isfinite(v) or mpmath.im(v) != 0:
            raise SystemExit('%s%s: non-finite or complex reference %s' % (table.name, inputs, v))
        v = mpmath.re(v)
        if v != 0 and not (mpf('1e-30') < abs(v) < mpf('1e30')):
            raise SystemExit('%s%s: reference %s outside float range' % (table.name, inputs, v))
        if v == 0 and category != 'phi_zero':
            raise SystemExit('%s%s: unexpected zero reference' % (table.name, inputs))
        check = True
        if category in SAMPLED_CATEGORIES:
            check = nrandom % 10 == 0
            nrandom += 1
        if check:
            q = table.quad(*args)
            e = relerr(v, q)
            stats['checked'] += 1
            key = table.name
            if e > stats['max'].get(key, (mpf(-1),))[0]:
                stats['max'][key] = (e, inputs, category)
            if e > TOL:
                raise SystemExit('CROSS-CHECK FAILED %s%s [%s]: mpmath %s vs quad %s (rel %s)'
                                 % (table.name, inputs, category, mpmath.nstr(v, 35),
                                    mpmath.nstr(q, 35), mpmath.nstr(e, 3)))
        values.append(v)
    return values


def identity_checks(tables, values):
    """Cheap exact identities between the tables' references (beyond the quadrature checks)."""
    byname = {t.name: (t, vals) for t, vals in zip(tables, values)}
    worst = mpf(0)

    def chk(a, b, what):
        nonlocal worst
        e = relerr(a, b)
        worst = max(worst, e)
        if e > TOL:
            raise SystemExit('IDENTITY FAILED %s: %s vs %s' % (what, a, b))

    t, vals = byname['carlson_rj']
    for (inp, cat), v in zip(t.rows, vals):
        if cat == 'p_eq_z':
            chk(v, mpmath.elliprd(*[mpf(a) for a in inp[:3]]), 'R_J(x,y,z,z) = R_D(x,y,z)')
    t, vals = byname['carlson_rc']
    for (inp, cat), v in zip(t.rows, vals):
        x, y = mpf(inp[0]), mpf(inp[1])
        chk(v, mpmath.elliprf(x, y, y), 'R_C(x,y) = R_F(x,y,y)')
    t, vals = byname['ellint_pi']
    for (inp, cat), v in zip(t.rows, vals):
        if cat == 'n_zero':
            chk(v, mpmath.ellipf(mpf(inp[1]), mpf(inp[2])), 'Pi(0;phi|m) = F(phi|m)')
    t, vals = byname['comp_ellint_pi']
    for (inp, cat), v in zip(t.rows, vals):
        m = mpf(inp[1])
        if cat == 'n_eq_m':
            chk(v, mpmath.ellipe(m) / (1 - m), 'Pi(m|m) = E(m)/(1-m)')
        if cat == 'n_zero':
            chk(v, mpmath.ellipk(m), 'Pi(0|m) = K(m)')
    return worst


def fmt_value(v):
    if v == 0:
        return '0'
    s = mpmath.nstr(v, VALUE_DIGITS, min_fixed=-4, max_fixed=6)
    float(s)  # parseable
    return s


def write_table(table, values, outdir):
    cats = []
    for _, c in table.rows:
        if c not in cats:
            cats.append(c)
    lines = [
        '# apse elliptic-integral reference table: %s' % table.name,
        '# generator: %s (mpmath %s, mp.dps = %d, random.Random(%d))'
        % (GENERATOR, mpmath.__version__, DPS, SEED),
        '# %s' % table.describe,
        '# Legendre parameter convention: m = k^2 (parameter, not modulus k)',
        '# columns: inputs (%s) as hexadecimal float literals, each exactly representable in '
        'IEEE binary32;' % ', '.join(table.args),
        '#   value = reference for those exact inputs, %d significant decimal digits;'
        % VALUE_DIGITS,
        '#   category = how the row was chosen (%s)' % ' '.join(cats),
        '# cross-checked against mp.quad of the defining integral (every 10th row of categories '
        '%s; all other rows) to < 1e-25 relative' % '/'.join(SAMPLED_CATEGORIES),
        ','.join(table.args + ['value', 'category']),
    ]
    for (inputs, category), v in zip(table.rows, values):
        lines.append(','.join([hexf(a) for a in inputs] + [fmt_value(v), category]))
    path = os.path.join(outdir, table.name + '.csv')
    with open(path, 'w', newline='\n') as fh:
        fh.write('\n'.join(lines) + '\n')
    return path


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    default_out = os.path.join(os.path.dirname(here), 'tests', 'data', 'elliptic')
    ap = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    ap.add_argument('--out', default=default_out, help='output directory (default: %(default)s)')
    ap.add_argument('--quiet', action='store_true')
    opts = ap.parse_args()

    t0 = time.time()
    r = random.Random(SEED)
    tables = build_tables(r)
    stats = {'checked': 0, 'max': {}}
    values = []
    for t in tables:
        t1 = time.time()
        values.append(evaluate(t, stats))
        if not opts.quiet:
            e, inp, cat = stats['max'][t.name]
            print('%-15s %4d rows, max rel discrepancy vs quadrature %s (%s %s)  [%.1fs]'
                  % (t.name, len(t.rows), mpmath.nstr(e, 3), cat,
                     ','.join(repr(a) for a in inp), time.time() - t1))
    worst_id = identity_checks(tables, values)
    t1 = time.time()
    wide = build_wide(random.Random(SEED + 2), stats)
    if not opts.quiet:
        e, inp, cat = stats['max']['carlson_rj_wide']
        print('%-15s %4d rows, max rel discrepancy vs 20 more digits / quadrature %s (%s)  [%.1fs]'
              % ('carlson_rj_wide', len(wide), mpmath.nstr(e, 3), cat, time.time() - t1))

    os.makedirs(opts.out, exist_ok=True)
    for t, vals in zip(tables, values):
        write_table(t, vals, opts.out)
    write_wide(wide, opts.out)
    if not opts.quiet:
        worst = max(e for e, _, _ in stats['max'].values())
        print('%d rows cross-checked by quadrature, max rel discrepancy %s; identities max %s'
              % (stats['checked'], mpmath.nstr(worst, 3), mpmath.nstr(worst_id, 3)))
        print('wrote %d tables to %s in %.1fs' % (len(tables), opts.out, time.time() - t0))
    return 0


if __name__ == '__main__':
    sys.exit(main())
