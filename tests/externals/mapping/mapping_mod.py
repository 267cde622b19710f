"""The user's module of tests/externals/mapping: one function per mapping."""

import numpy as np


def twice(x):
    return 2 * x


def half(x):
    assert isinstance(x, float)
    return x / 2


def negate(b):
    assert isinstance(b, bool)
    return not b


def next_char(c):
    return chr(ord(c) + 1)


def natural_max():
    return np.uint8(255)


def greet(s):
    assert isinstance(s, str)
    return "hello " + s


def scale(a, f):
    assert isinstance(a, np.ndarray) and a.dtype == np.float64
    a *= f


def special_sum(s):
    assert s.dtype == np.int32
    return s.sum()


def ramp(n):
    return np.arange(n, dtype=float)


def squares(n):
    return [i * i for i in range(n)]


def nothing():
    return None


class Counter:
    def __init__(self, start):
        self.n = start

    def bump(self):
        self.n += 1

    def value(self):
        return self.n
