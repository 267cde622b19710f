"""The user's module of tests/externals/views: writes into the arrays it is given, keeps one."""

import numpy as np

KEPT = []


def double(a):
    a *= 2


def is_view(a):
    return not a.flags.owndata and a.flags.writeable


def keep(s):
    KEPT.append(s)
    s[1] = 5


def write_kept():
    KEPT[0][0] = 100  # the SPECIAL went on with its own copy: this does not reach it


def negate_bytes(b):
    assert b.dtype == np.int8
    b[0] = 127
    b[1] = ~b[1]  # -128 -> 127


def add_third(r):
    assert r.dtype == np.float32
    r += np.float32(1) / np.float32(3)
