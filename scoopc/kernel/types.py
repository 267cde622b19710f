"""Run-time types: what generated code keeps of Eiffel types (actual generics of objects, the
types of object tests and of `create {T}`, `generating_type`).

A TypeDesc names a class by its universe key and lists its actual generics; descriptors are
interned (`t(key, generics)` returns the same object for the same type), so building one inside
a routine costs a dictionary lookup.
"""

from __future__ import annotations

from . import CLASSES
from .boxes import KINDS as BOXES

_BASIC_DEFAULTS = {
    "INTEGER_8": 0,
    "INTEGER_16": 0,
    "INTEGER_32": 0,
    "INTEGER_64": 0,
    "NATURAL_8": 0,
    "NATURAL_16": 0,
    "NATURAL_32": 0,
    "NATURAL_64": 0,
    "REAL_32": 0.0,
    "REAL_64": 0.0,
    "BOOLEAN": False,
    "CHARACTER_8": "\x00",
    "CHARACTER_32": "\x00",
    "POINTER": 0,
}
_PYTHON_TYPES = {
    "INTEGER_8": int,
    "INTEGER_16": int,
    "INTEGER_32": int,
    "INTEGER_64": int,
    "NATURAL_8": int,
    "NATURAL_16": int,
    "NATURAL_32": int,
    "NATURAL_64": int,
    "REAL_32": float,
    "REAL_64": float,
    "BOOLEAN": bool,
    "CHARACTER_8": str,
    "CHARACTER_32": str,
    "POINTER": int,
}
# The basic classes' conforming ancestors (a Python value's dynamic type is one of them).
_BASIC_ANCESTORS = {
    int: frozenset({"INTEGER_32", "NUMERIC", "COMPARABLE", "PART_COMPARABLE", "HASHABLE", "ANY"}),
    float: frozenset({"REAL_64", "NUMERIC", "COMPARABLE", "PART_COMPARABLE", "HASHABLE", "ANY"}),
    bool: frozenset({"BOOLEAN", "HASHABLE", "ANY"}),
    str: frozenset({"CHARACTER_8", "COMPARABLE", "PART_COMPARABLE", "HASHABLE", "ANY"}),
}
_INTEGER_KINDS = frozenset(k for k, v in _PYTHON_TYPES.items() if v is int)
_INTERNED: dict = {}


class TypeDesc:
    """An Eiffel type at run time: class key, actual generics, attachment mark."""

    __slots__ = ("key", "generics", "attached", "expanded_class", "_name")

    def __init__(self, key: str, generics: tuple, attached: bool):
        self.key, self.generics, self.attached = key, generics, attached
        self.expanded_class = None
        self._name = None

    @property
    def pyclass(self):
        return CLASSES.get(self.key)

    @property
    def is_basic(self) -> bool:
        return self.key in _BASIC_DEFAULTS

    @property
    def is_expanded(self) -> bool:
        if self.is_basic:
            return True
        cls = self.pyclass
        return cls is not None and getattr(cls, "_expanded_", False)

    def default(self, region=None):
        """The default value of an entity of this type: 0, False, Void, or a new expanded object."""
        value = _BASIC_DEFAULTS.get(self.key, _NOTHING)
        if value is not _NOTHING:
            return value
        cls = self.pyclass
        if cls is not None and getattr(cls, "_expanded_", False):
            from .support import new_expanded  # deferred: a cycle (scoopc.kernel.support imports this module)

            return new_expanded(region, cls, self.generics)
        return None

    @property
    def name(self) -> str:
        """As EiffelStudio prints a type: `ARRAY [INTEGER_32]`, `detachable STRING_8` inside generics."""
        if self._name is None:
            _name_all(self)
        return self._name  # type: ignore[return-value]

    @property
    def inner_name(self) -> str:
        return self.name if self.attached or self.is_expanded else "detachable " + self.name

    def accepts(self, value) -> bool:
        """Does `value` (not Void) conform to this type? (object tests, `attached {T} x`)
        A bare int/float/str is taken for any basic class of its Python type; a boxed one
        (scoopc/kernel/boxes.py) for its own class only."""
        boxed = BOXES.get(type(value))
        kind = _PYTHON_TYPES.get(self.key)
        if kind is not None:
            if boxed is not None:
                return boxed == self.key
            return type(value) is kind
        if isinstance(value, (bool, int, float, str)):
            return self.key in _BASIC_ANCESTORS[type(value).__mro__[-2] if boxed else type(value)]
        conforms = getattr(type(value), "_conforms_", None)
        if conforms is None or self.key not in conforms:
            return False
        if not self.generics:
            return True
        actual = ancestor_generics(type(value), getattr(value, "_gen_", ()), self.key)
        if actual is None or len(actual) != len(self.generics):
            return True  # generics not known at run time
        return all(mine.conforms_to(theirs) for mine, theirs in zip(actual, self.generics))

    def conforms_to(self, other: TypeDesc) -> bool:
        if other.key == "ANY" or self is other:
            return True
        if self.key in _INTEGER_KINDS or other.key in _INTEGER_KINDS or self.is_basic or other.is_basic:
            return self.key == other.key
        cls = self.pyclass
        conforms = getattr(cls, "_conforms_", frozenset({self.key})) if cls is not None else {self.key}
        if other.key not in conforms:
            return False
        if not other.generics:
            return True
        actual = ancestor_generics(cls, self.generics, other.key) if cls is not None else None
        if actual is None or len(actual) != len(other.generics):
            return True
        return all(a.conforms_to(b) for a, b in zip(actual, other.generics))

    def __repr__(self) -> str:
        return self.name


_NOTHING = object()


def t(key: str, generics: tuple = (), attached: bool = True) -> TypeDesc:
    """The interned descriptor of a type."""
    k = (key, generics, attached)
    found = _INTERNED.get(k)
    if found is None:
        found = _INTERNED[k] = TypeDesc(key, generics, attached)
    return found


def of(value) -> TypeDesc:
    """The dynamic type of a value (for `generating_type`, `same_type`, `like Current`)."""
    kind = type(value)
    boxed = BOXES.get(kind)
    if boxed is not None:
        return t(boxed)
    if kind is bool:
        return t("BOOLEAN")
    if kind is int:
        return t("INTEGER_32")
    if kind is float:
        return t("REAL_64")
    if kind is str:
        return t("CHARACTER_8")
    return t(kind._key_, getattr(value, "_gen_", ()))


def ancestor_generics(cls, generics: tuple, ancestor: str):
    """The actual generics of `ancestor` for an object of class `cls` with actual generics
    `generics` (`ARRAYED_LIST [DOG]` seen as a `LIST` has `(DOG,)`); None when unknown."""
    if cls._key_ == ancestor:
        return generics
    table = getattr(cls, "_ancestor_gen_", None)
    found = table.get(ancestor) if table else None
    return found(generics) if found is not None else None


def formal(obj, written_in: str, index: int) -> TypeDesc:
    """Formal generic `index` of class `written_in` (the class whose code asks) for the object
    `obj`, whose dynamic class may be a descendant with other generics."""
    cls = type(obj)
    if cls._key_ == written_in:
        return obj._gen_[index]
    return cls._ancestor_gen_[written_in](getattr(obj, "_gen_", ()))[index]


def own_generics(obj, written_in: str) -> tuple:
    """The actual generics of class `written_in` (the class whose code asks) for the object `obj`
    of a descendant class: all of them, in order (what `formal` gives one by one)."""
    cls = type(obj)
    if cls._key_ == written_in:
        return obj._gen_
    return tuple(cls._ancestor_gen_[written_in](getattr(obj, "_gen_", ())))


def _name_all(top: TypeDesc) -> None:
    """Name `top` and the types inside it not named yet, innermost first: no recursion, for a type
    nested 2,000 deep (an ARRAY of ARRAYs ...)."""
    order, pending = [], [top]
    while pending:
        ty = pending.pop()
        if ty._name is None:
            order.append(ty)
            pending.extend(ty.generics)
    for ty in reversed(order):  # each after the types inside it
        base = ty.key.split("@")[0]
        if ty.generics:
            base += " [" + ", ".join(g.inner_name for g in ty.generics) + "]"
        ty._name = base
