"""Basic values reattached to a reference type: `print (r)` with `r: REAL` (REAL_32), an ANY or a
COMPARABLE holding an INTEGER_64. A bare Python value is read as its default class (int:
INTEGER_32, float: REAL_64, str: CHARACTER_8); where the static type says another basic class
and the value leaves for a reference type, generated code boxes it (`S.box`) in one of these
subclasses, which remember the Eiffel class for `out`, `generator`, object tests and dynamic
dispatch. Arithmetic on a box gives a plain value again (int and float operations return their
base types), so a box never spreads beyond the reference it was made for.
"""


class Real32(float):
    __slots__ = ()
    _kind_ = "REAL_32"


class Character32(str):
    __slots__ = ()
    _kind_ = "CHARACTER_32"


def _integer(kind):
    return type(kind.title().replace("_", ""), (int,), {"__slots__": (), "_kind_": kind})


Integer8, Integer16, Integer64 = (_integer(k) for k in ("INTEGER_8", "INTEGER_16", "INTEGER_64"))
Natural8, Natural16, Natural32, Natural64 = (
    _integer(k) for k in ("NATURAL_8", "NATURAL_16", "NATURAL_32", "NATURAL_64")
)

KINDS = {
    cls: cls._kind_
    for cls in (Real32, Character32, Integer8, Integer16, Integer64, Natural8, Natural16, Natural32, Natural64)
}
BY_KIND = {kind: cls for cls, kind in KINDS.items()}


def box(kind, value):
    """`value` (of basic class `kind`) as a reference: boxed unless its Python type says it."""
    cls = BY_KIND.get(kind)
    if cls is None or type(value) is cls:
        return value
    return cls(value)
