"""STRING_32's `external "Python"` features (stdlib/base/string/string_32.e).

The same as STRING_8's (scoopc/kernel/ext/string_8.py) but for the justifications, whose white
space is CHARACTER_PROPERTY.is_space (Unicode White_Space) instead of CHARACTER_8.is_space.
"""

from __future__ import annotations

from scoopc.kernel import strings as K

from .string_8 import (
    _center_justify,
    _left_justify,
    _right_justify,
    append,
    append_character,
    append_substring,
    extend,
    fill_character,
    fill_with,
    insert_character,
    insert_string,
    item,
    precede,
    prepend,
    prepend_character,
    prune,
    prune_all,
    prune_all_leading,
    prune_all_trailing,
    put,
    replace_substring,
    replace_substring_all,
    set,
    share,
)

# Bound by name from this module (codegen: `scoopc.kernel.ext.string_32.<feature>`).
__all__ = [
    "append",
    "append_character",
    "append_substring",
    "center_justify",
    "extend",
    "fill_character",
    "fill_with",
    "insert_character",
    "insert_string",
    "item",
    "left_justify",
    "precede",
    "prepend",
    "prepend_character",
    "prune",
    "prune_all",
    "prune_all_leading",
    "prune_all_trailing",
    "put",
    "replace_substring",
    "replace_substring_all",
    "right_justify",
    "set",
    "share",
]


def left_justify(current):
    _left_justify(current, K.WS32)


def right_justify(current):
    _right_justify(current, K.WS32)


def center_justify(current):
    _center_justify(current, K.WS32)
