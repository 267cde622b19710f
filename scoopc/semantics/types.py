"""Checker, types: the semantic form of Eiffel types (Ty) and substitution of formal generics.

Input: none (a value module). Output: Ty values used by every later pass and recorded for codegen.
"""

from __future__ import annotations

from dataclasses import dataclass, replace

# Class-name aliases EiffelStudio's configuration maps onto kernel classes.
ALIASES = {
    "INTEGER": "INTEGER_32",
    "NATURAL": "NATURAL_32",
    "REAL": "REAL_32",
    "DOUBLE": "REAL_64",
    "CHARACTER": "CHARACTER_8",
    "WIDE_CHARACTER": "CHARACTER_32",
    "STRING": "STRING_8",
}
INTEGERS = ("INTEGER_8", "INTEGER_16", "INTEGER_32", "INTEGER_64")
NATURALS = ("NATURAL_8", "NATURAL_16", "NATURAL_32", "NATURAL_64")
REALS = ("REAL_32", "REAL_64")
NUMERICS = INTEGERS + NATURALS + REALS
STRINGS = (
    "STRING_8",
    "STRING_32",
    "READABLE_STRING_8",
    "READABLE_STRING_32",
    "READABLE_STRING_GENERAL",
    "STRING_GENERAL",
    "IMMUTABLE_STRING_8",
    "IMMUTABLE_STRING_32",
    "IMMUTABLE_STRING_GENERAL",
)
BASIC = frozenset(NUMERICS + ("BOOLEAN", "CHARACTER_8", "CHARACTER_32", "POINTER"))
RANGES = {
    "INTEGER_8": (-(2**7), 2**7 - 1),
    "INTEGER_16": (-(2**15), 2**15 - 1),
    "INTEGER_32": (-(2**31), 2**31 - 1),
    "INTEGER_64": (-(2**63), 2**63 - 1),
    "NATURAL_8": (0, 2**8 - 1),
    "NATURAL_16": (0, 2**16 - 1),
    "NATURAL_32": (0, 2**32 - 1),
    "NATURAL_64": (0, 2**64 - 1),
}


@dataclass(frozen=True)
class Ty:
    """A type: a class type (name, actual generics), a formal generic (formal >= 0) or NONE.

    `attached` and `separate` are the marks after resolution; `labels` name TUPLE items.
    """

    name: str
    generics: tuple[Ty, ...] = ()
    attached: bool = True
    separate: bool = False
    formal: int = -1
    labels: tuple[str, ...] = ()

    @property
    def is_formal(self) -> bool:
        return self.formal >= 0

    @property
    def is_none(self) -> bool:
        return self.name == "NONE"

    def with_marks(self, attached: bool | None = None, separate: bool | None = None) -> Ty:
        a = self.attached if attached is None else attached
        s = self.separate if separate is None else separate
        return self if (a, s) == (self.attached, self.separate) else replace(self, attached=a, separate=s)

    def __str__(self) -> str:
        """The type as Eiffel writes it; made once per type (a TUPLE in a TUPLE, 2,000 deep, is named
        at each level)."""
        text = self.__dict__.get("_text")
        if text is None:
            text = self._text()
            object.__setattr__(self, "_text", text)  # not a field: equality, hashing and replace ignore it
        return text

    def _text(self) -> str:
        marks = ("separate " if self.separate else "") + ("" if self.attached or self.is_none else "detachable ")
        if not self.generics:
            return marks + self.name
        if self.labels:
            inner = "; ".join(f"{label}: {g}" for label, g in zip(self.labels, self.generics))
        else:
            inner = ", ".join(str(g) for g in self.generics)
        return f"{marks}{self.name} [{inner}]"


NONE = Ty("NONE", attached=False)
BOOLEAN = Ty("BOOLEAN")
INTEGER = Ty("INTEGER_32")
REAL_64 = Ty("REAL_64")
CHARACTER = Ty("CHARACTER_8")
STRING = Ty("STRING_8")
POINTER = Ty("POINTER")
ANY = Ty("ANY")


def substitute(ty: Ty, actuals: tuple[Ty, ...]) -> Ty:
    """`ty` with formal generic i replaced by actuals[i] (marks of the use site combine)."""
    if not actuals:
        return ty
    if ty.is_formal:
        if ty.formal >= len(actuals):
            return ty
        actual = actuals[ty.formal]
        attached = actual.attached if ty.attached else False
        return actual.with_marks(attached=attached, separate=actual.separate or ty.separate)
    if not ty.generics:
        return ty
    return replace(ty, generics=tuple(substitute(g, actuals) for g in ty.generics))


def has_formal(ty: Ty) -> bool:
    return ty.is_formal or any(has_formal(g) for g in ty.generics)
