"""EXCEPTION_MANAGER's `external "Python"` features (stdlib/base/exceptions/exception_manager.e):
`last_exception`, `is_ignored`, `ignore`, `catch`.

The state is per processor (region), as EiffelStudio keeps it per thread: the exception being
handled by the current rescue clause, and the set of ignored exception types. Types are told
apart by class and actual generics, not by attachment marks (`{EXCEPTION}` and
`{detachable EXCEPTION}` are one type here, as one type id in EiffelStudio); a type is ignored
exactly, not its descendants (EiffelStudio's `ignore` keeps type ids).

For the runtime (rescue clauses, raising): `set_last_exception(region, exc)` records the
exception a rescue clause handles (None when none), `exception_is_ignored(region, exc)` tells
whether an exception object's dynamic type is ignored in that region.
"""

import threading
import weakref

from scoopc.kernel import support
from scoopc.kernel.errors import EiffelFailure
from scoopc.kernel.types import TypeDesc, of

# the Anchor of a region (its Processor may be compiled: no weak reference to it) -> _State
_STATES = weakref.WeakKeyDictionary()
_LOCK = threading.Lock()


class _State:
    __slots__ = ("last", "ignored")

    def __init__(self):
        self.last = None
        self.ignored = set()


def _state(region):
    key = region.anchor
    st = _STATES.get(key)
    if st is None:
        with _LOCK:
            st = _STATES.get(key)
            if st is None:
                st = _STATES[key] = _State()
    return st


def _desc_key(desc):
    key = getattr(desc, "key", None)
    if key is None:
        return desc
    return (key, tuple(_desc_key(g) for g in getattr(desc, "generics", ())))


def type_key(a_type):
    """The key of the type a TYPE value denotes: a TypeDesc itself, or a TYPE [X] object
    (whose `_gen_[0]` is X)."""
    if isinstance(a_type, TypeDesc):
        return _desc_key(a_type)
    gen = getattr(a_type, "_gen_", None)
    if gen:
        return _desc_key(gen[0])
    return _desc_key(getattr(a_type, "_desc", a_type))


# --- features ---------------------------------------------------------------------------


def last_exception(current):
    """The exception recorded by `set_last_exception`, else the one the generated rescue
    clause recorded through `scoopc.kernel.support.caught` (an EiffelFailure gives its
    EXCEPTION object; a Python exception that is not one gives Void)."""
    region = current._region_
    st = _STATES.get(region.anchor)
    if st is not None and st.last is not None:
        return st.last
    last_caught = getattr(support, "last_caught", None)
    error = last_caught(region) if last_caught is not None else None
    if error is None:
        return None
    if isinstance(error, EiffelFailure):
        return error.exception
    return error if hasattr(error, "_region_") else None


def is_ignored(current, a_exception):
    return type_key(a_exception) in _state(current._region_).ignored


def ignore(current, a_exception):
    _state(current._region_).ignored.add(type_key(a_exception))


def catch(current, a_exception):
    _state(current._region_).ignored.discard(type_key(a_exception))


# --- for the runtime --------------------------------------------------------------------


def set_last_exception(region, exc):
    """Record `exc` (an EXCEPTION object, or None) as the exception handled in `region`."""
    _state(region).last = exc


def exception_is_ignored(region, exc):
    """Is the dynamic type of the exception object `exc` ignored in `region`?"""
    st = _STATES.get(region.anchor)
    if st is None or not st.ignored:
        return False
    return _desc_key(of(exc)) in st.ignored
