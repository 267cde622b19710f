"""Fakes for the string tests (test_strings*.py, test_string_*.py): objects laid out as
codegen_spec.md says (`_region_`, `_s`, ...), fake classes registered as STRING_8, STRING_32,
IMMUTABLE_STRING_8 and IMMUTABLE_STRING_32 while `registered()` is active."""

import contextlib
import math
from pathlib import Path

import scoopc.kernel as kernel
from scoopc.kernel.ext import immutable_string_8, immutable_string_32, readable_string_general as g, string_8, string_32

ROOT = Path(__file__).resolve().parents[2]
GENERAL = {"READABLE_STRING_GENERAL", "COMPARABLE", "PART_COMPARABLE", "HASHABLE", "ANY"}


# --- Fakes -----------------------------------------------------------------------------------


class Region:
    """Stands for a `scoopc.runtime.Processor`."""


class Fake:
    """Binds a few features as codegen does (`name = ext.name`, `property(ext.name)`)."""

    count = property(g.count)
    capacity = property(g.capacity)
    hash_code = property(g.hash_code)
    is_equal = g.is_equal
    substring = g.substring

    def __repr__(self):
        return f"{type(self).__name__}({self._s!r})"


class S8(Fake):
    _key_ = "STRING_8"
    _conforms_ = frozenset(GENERAL | {"READABLE_STRING_8", "STRING_GENERAL", "STRING_8"})
    item = string_8.item
    put = string_8.put
    append = string_8.append


class S32(Fake):
    _key_ = "STRING_32"
    _conforms_ = frozenset(GENERAL | {"READABLE_STRING_32", "STRING_GENERAL", "STRING_32"})
    item = string_32.item


class I8(Fake):
    _key_ = "IMMUTABLE_STRING_8"
    _conforms_ = frozenset(GENERAL | {"READABLE_STRING_8", "IMMUTABLE_STRING_GENERAL", "IMMUTABLE_STRING_8"})
    item = immutable_string_8.item


class I32(Fake):
    _key_ = "IMMUTABLE_STRING_32"
    _conforms_ = frozenset(GENERAL | {"READABLE_STRING_32", "IMMUTABLE_STRING_GENERAL", "IMMUTABLE_STRING_32"})
    item = immutable_string_32.item


class MyString(S8):
    """A user descendant of STRING_8."""

    _key_ = "MY_STRING"
    _conforms_ = S8._conforms_ | {"MY_STRING"}
    extra = 7


R = Region()


@contextlib.contextmanager
def registered():
    """The fake classes registered under the string classes' keys; the registry restored after."""
    saved = dict(kernel.CLASSES)
    for key, pycls in (("STRING_8", S8), ("STRING_32", S32), ("IMMUTABLE_STRING_8", I8), ("IMMUTABLE_STRING_32", I32)):
        kernel.register(key, pycls)
    try:
        yield
    finally:
        kernel.CLASSES.clear()
        kernel.CLASSES.update(saved)


def created(pycls, creator, *args):
    """`create x.creator (args)` as support.create does."""
    obj = pycls.__new__(pycls)
    obj._region_ = R
    creator(obj, *args)
    return obj


def twin(obj):
    """ANY.twin as ISE: the fields copied, then the dynamic `copy`."""
    new = type(obj).__new__(type(obj))
    new.__dict__.update(obj.__dict__)
    g.copy(new, obj)
    return new


def ise_hash_reference(s):
    """Straight from ISE's loop, INTEGER_32 arithmetic with C remainders."""
    h = 0
    for c in s:
        r = int(math.fmod(h, 8388593))
        h = ((r << 8) + ord(c)) & 0xFFFFFFFF
        if h >= 1 << 31:
            h -= 1 << 32
    return h
