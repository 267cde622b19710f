"""IMMUTABLE_STRING_8's `external "Python"` features (stdlib/base/string/immutable_string_8.e).

Its other externals are READABLE_STRING_GENERAL's and READABLE_STRING_8's; operations that build
a string (`plus`, `substring`, `as_lower`, `mirrored`) give a new IMMUTABLE_STRING_8 there.
"""


def item(current, i):
    if i < 1:  # refused (the caller reports `valid_index')
        raise IndexError(i)
    return current._s[i - 1]
