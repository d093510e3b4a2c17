"""Helpers shared by apse's mpmath reference generators (tools/gen_*_reference.py): rounding to
float32, the exact hexadecimal and 30-digit decimal strings the test data store, and 3-vectors
of mpmath numbers. The arithmetic runs at the precision the calling generator sets (mpmath's
global context, mp.mp.dps)."""

import struct

import mpmath as mp


def f32(x):
    """Round a Python float to the nearest float32 (returned as a Python float, exact)."""
    return struct.unpack("<f", struct.pack("<f", float(x)))[0]


def hexf(x):
    """The exact hexadecimal string of a value that is a float32."""
    x = float(x)
    assert f32(x) == x, x
    return x.hex()


def dec(x):
    """x to 30 significant digits, in scientific notation."""
    return mp.nstr(mp.mpf(x), 30, min_fixed=1, max_fixed=0)


def mvec(v):
    return [mp.mpf(t) for t in v]


def dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def sub(a, b):
    return [a[i] - b[i] for i in range(3)]


def add(a, b):
    return [a[i] + b[i] for i in range(3)]


def scale(a, s):
    return [t * s for t in a]


def norm(a):
    return mp.sqrt(dot(a, a))
