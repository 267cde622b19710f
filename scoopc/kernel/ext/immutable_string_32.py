"""IMMUTABLE_STRING_32's `external "Python"` features (stdlib/base/string/immutable_string_32.e).

Its other externals are READABLE_STRING_GENERAL's and READABLE_STRING_32's.
"""


def item(current, i):
    if i < 1:  # refused (the caller reports `valid_index')
        raise IndexError(i)
    return current._s[i - 1]
