"""Helpers that generated code calls (`S.` in generated modules): object creation, separate
calls with dynamic binding, agents, tuples, iteration, contracts and their failures.

Each helper is small and states the Eiffel rule it implements; codegen decides statically what
it can, these handle what only the run time knows (the dynamic class of a target, lock passing).
"""

from __future__ import annotations

from ..runtime import DirtyRegionError, PreconditionViolation
from . import CLASSES, basic, register as _register, types as T
from .boxes import BY_KIND as _BOX_KINDS, box
from .errors import EiffelFailure

register = _register


# --- failures ------------------------------------------------------------------------------------
class ContractViolation(Exception):
    """An assertion of the program is false: kind (precondition, postcondition, invariant,
    check, loop_invariant, variant), tag, where = (class, routine, file, line)."""

    def __init__(self, kind, tag, where):
        self.kind, self.tag, self.where = kind, tag, where
        super().__init__(f"{kind.replace('_', ' ')} {tag or '(untagged)'} violated")


class EiffelRuntimeError(Exception):
    """A run-time failure the language defines (bad inspect value, Void call target, ...)."""

    def __init__(self, kind, message, where=None):
        self.kind, self.where = kind, where
        super().__init__(message)


def assertion_failed(kind, tag, where):
    raise ContractViolation(kind, tag, where)


def bad_inspect(value, where):
    raise EiffelRuntimeError("bad_inspect_value", f"no `when` branch matches the value {value!r}", where)


def inspect_text(value, where):
    """The characters of a string inspected (`inspect s when "a" then`): strings are matched by
    value; a Void string is a call on a Void target."""
    if value is None:
        raise EiffelRuntimeError("void_target", "`inspect` on a Void string", where)
    return value._s


def variant_start(value, where, tag=None):
    if value < 0:
        raise ContractViolation("variant", tag, where)
    return value


def variant_step(previous, value, where, tag=None):
    if value < 0 or value >= previous:
        raise ContractViolation("variant", tag, where)
    return value


class _OldFailure:
    __slots__ = ("error",)

    def __init__(self, error):
        self.error = error


def old(fn):
    """`old e`, evaluated at routine entry; a failure surfaces only if the postcondition uses it."""
    try:
        return fn()
    except Exception as error:  # noqa: BLE001 - kept and re-raised where it is used
        return _OldFailure(error)


_LAST = {}


def caught(here, error):
    """Entering a rescue clause: remember the exception (EXCEPTION_MANAGER.last_exception) as
    an Eiffel EXCEPTION object when the failure is one the language defines."""
    _LAST[here] = exception_object(here, error)


_CONTRACT_CLASSES = {
    "precondition": "PRECONDITION_VIOLATION",
    "postcondition": "POSTCONDITION_VIOLATION",
    "invariant": "INVARIANT_VIOLATION",
    "check": "CHECK_VIOLATION",
    "loop_invariant": "LOOP_INVARIANT_VIOLATION",
    "variant": "VARIANT_VIOLATION",
}
_RUNTIME_CLASSES = {
    "bad_inspect_value": "BAD_INSPECT_VALUE",
    "void_target": "VOID_TARGET",
    "external_failure": "EXTERNAL_FAILURE",
}


def exception_object(here, error):
    """The EXCEPTION object EiffelStudio's runtime would make for `error` (a Python exception
    raised by generated code or the runtime), its description the assertion tag; the error
    itself when no class fits."""
    if isinstance(error, EiffelFailure):
        return error
    while isinstance(error, DirtyRegionError) and error.__cause__ is not None:
        error = error.__cause__
    tag = None
    if isinstance(error, ContractViolation):
        name, tag = _CONTRACT_CLASSES.get(error.kind), error.tag
    elif isinstance(error, PreconditionViolation):
        name, tag = "PRECONDITION_VIOLATION", error.tag
    elif isinstance(error, EiffelRuntimeError):
        name = _RUNTIME_CLASSES.get(error.kind)
    elif isinstance(error, (AttributeError, TypeError)) and "NoneType" in str(error):
        name = "VOID_TARGET"
    elif isinstance(error, ZeroDivisionError):
        name = "FLOATING_POINT_FAILURE"
    else:
        name = None
    cls = CLASSES.get(name) if name else None
    if cls is None:
        return error
    exception = create(here, cls, None, None, ())
    if tag:
        from .strings import new_string_32  # deferred: start-up (loaded on first use only)

        exception.description = new_string_32(here, tag)
    return EiffelFailure(exception)


GUARDS = set()  # code objects of the precondition checks generated around externals


def guard(fn):
    """Decorates the precondition check generated around an `external "Python"` routine: its
    frame is the external's own, so Eiffel traces leave it out, as they leave out the host's."""
    GUARDS.add(fn.__code__)
    return fn


def last_caught(here):
    return _LAST.get(here)


def missing_external(cls, name):
    def missing(*args):
        raise EiffelRuntimeError("external_failure", f"external feature {cls}.{name} is not available")

    missing.__name__ = name
    return missing


# --- objects -------------------------------------------------------------------------------------
def create(here, cls, gen, creator, args, invariant=False):
    """`create x.make (args)` in the current region (non-separate). `cls()` is the bare object:
    generated classes define no `__init__` (Processor.new)."""
    obj = cls()
    obj._region_ = here
    if gen is not None:
        obj._gen_ = gen
    if creator is not None:
        getattr(obj, creator)(*args)
    if invariant:
        check_invariant(obj)
    return obj


def create_formal(here, desc, creator, args):
    """`create x.make` where x's type is a formal generic: the actual type's class at run time."""
    if desc.is_basic:
        return desc.default()
    if desc.pyclass is CLASSES.get("TUPLE"):
        return new_default_tuple(here, tuple(desc.generics or ()))
    return create(here, desc.pyclass, desc.generics or None, creator, args)


def new_expanded(region, cls, gen):
    return create(region, cls, gen or None, "default_create", ())


def copy_expanded(value):
    """Expanded semantics: attaching a value of an expanded class copies it."""
    if value is None or not hasattr(value, "_region_"):
        return value
    return value.twin


def static_target(here, cls):
    """`{T}.f`: a throwaway object of T for a routine that does not use Current."""
    obj = cls.__new__(cls)
    obj._region_ = here
    return obj


def check_invariant(obj):
    check = getattr(obj, "_invariant_", None)
    if check is not None:
        check()


def call_checked(target, name, args):
    """A qualified call followed by the target's class invariant (assertions `all`)."""
    member = getattr(target, name)
    result = member(*args) if callable(member) else member
    check_invariant(target)
    return result


def parent_invariant(cls, obj):
    check = cls.__dict__.get("_invariant_")
    if check is None:
        for base in cls.__mro__[1:]:
            check = base.__dict__.get("_invariant_")
            if check is not None:
                break
    if check is not None:
        check(obj)


def attempt(value, desc):
    """`x ?= e` (assignment attempt): e if it conforms to x's type, else Void."""
    return value if value is not None and desc.accepts(value) else None


def conforms(value, desc):
    return value is not None and desc.accepts(value)


class SelfInitialising:
    """An attached attribute with an `attribute` body: the body runs when the attribute is read
    while still Void (never set, or its body left it Void), and its result is kept. An actual
    generic that is expanded is never Void: the attribute starts at its default."""

    def __init__(self, init, name):
        self.init, self.name = init, name

    def __get__(self, obj, owner=None):
        if obj is None:
            return self
        value = self.init(obj)
        if value is not None:
            obj.__dict__[self.name] = value
        return value


class SelfInitialisingFormal(SelfInitialising):
    """`x: G attribute ... end`: self-initialising only when the actual generic of G is a
    reference type (an expanded one is never Void: its default is kept)."""

    def __init__(self, init, name, written_in, index):
        super().__init__(init, name)
        self.written_in, self.index = written_in, index

    def __get__(self, obj, owner=None):
        if obj is None:
            return self
        desc = T.formal(obj, self.written_in, self.index)
        default = desc.default(obj._region_)
        if default is not None:
            obj.__dict__[self.name] = default
            return default
        return super().__get__(obj, owner)


class FormalDefault:
    """The default of an attribute whose type is a formal generic (0 for INTEGER, Void, ...)."""

    def __init__(self, written_in, index, name):
        self.written_in, self.index, self.name = written_in, index, name

    def __get__(self, obj, owner=None):
        if obj is None:
            return self
        value = T.formal(obj, self.written_in, self.index).default(obj._region_)
        if not isinstance(value, (int, float, str, type(None))):
            obj.__dict__[self.name] = value
        return value


class ExpandedDefault:
    def __init__(self, desc, name):
        self.desc, self.name = desc, name

    def __get__(self, obj, owner=None):
        if obj is None:
            return self
        value = obj.__dict__[self.name] = self.desc.default(obj._region_)
        return value


def alias_attribute(primary):
    """Another name of an attribute (a join or rename seen through another ancestor)."""
    return property(lambda self: getattr(self, primary))


# --- separate calls -----------------------------------------------------------------------------
_ROUTINES: dict = {}


def routine_of(target, name):
    """The function implementing feature `name` in target's class, callable as f(target, *args)."""
    key = (type(target), name)
    found = _ROUTINES.get(key)
    if found is None:
        member = getattr(type(target), name)
        if isinstance(member, property):
            found = member.fget
        elif callable(member):
            found = member
        else:

            def found(obj, _name=name):
                return getattr(obj, _name)

        _ROUTINES[key] = found
    return found


_GETTERS: dict = {}


def getter(name):
    """The reader of attribute (or constant) `name`, as a leaf routine: f(target) -> value
    (a statically bound separate query of an attribute)."""
    found = _GETTERS.get(name)
    if found is None:
        if not name.isidentifier():
            raise ValueError(f"not an attribute name: {name!r}")
        scope: dict = {}
        exec(f"def get_{name}(obj):\n    return obj.{name}\n", scope)  # noqa: S102 - an identifier
        found = scope[f"get_{name}"]
        found._scoop_leaf_ = True
        _GETTERS[name] = found
    return found


def scall(here, target, name, args, can_pass):
    """A command on a controlled separate target (asynchronous, or synchronous with lock passing)."""
    if target is None:
        raise EiffelRuntimeError("void_target", f"call of `{name}` on a Void target")
    routine = routine_of(target, name)
    if not can_pass and getattr(routine, "_scoop_leaf_", False):
        here.leaf_call(target, routine, args)
    else:
        here.call(target, routine, args)


def squery(here, target, name, args, can_pass, where=None):
    """A query on a controlled separate target: waits for the result (wait by necessity)."""
    if target is None:
        raise EiffelRuntimeError("void_target", f"call of `{name}` on a Void target", where)
    routine = routine_of(target, name)
    if not can_pass and getattr(routine, "_scoop_leaf_", False):
        return here.leaf_query(target, routine, args, where)
    return here.query(target, routine, args, where)


# --- tuples, arrays, types -------------------------------------------------------------------------
def new_tuple(here, items, gen):
    cls = CLASSES["TUPLE"]
    obj = cls.__new__(cls)
    obj._region_ = here
    obj._items = items
    obj._gen_ = gen
    return obj


def new_default_tuple(here, gen):
    """`create t` of a TUPLE type: one item per declared type, each its default value (as
    EiffelStudio's TUPLE creation)."""
    return new_tuple(here, [g.default(here) for g in gen], gen)


def tuple_item(t, index):
    return t._items[index]


def tuple_put(t, index, value):
    t._items[index] = value


def manifest_array(here, cls, gen, items):
    """`<<a, b, c>>`: an ARRAY indexed from 1."""
    array = create(
        here, cls, gen, "make_filled", (gen[0].default(here), 1, len(items)) if items else (gen[0].default(here), 1, 0)
    )
    for index, item in enumerate(items, start=1):
        array.put(item, index)
    return array


_TYPE_OBJECTS: dict = {}


def type_object(here, desc):
    """`{T}` and `generating_type`: one TYPE object per type."""
    found = _TYPE_OBJECTS.get(desc)
    if found is None:
        cls = CLASSES["TYPE"]
        found = cls.__new__(cls)
        found._region_ = here
        found._gen_ = (desc,)
        _TYPE_OBJECTS[desc] = found
    return found


# --- iteration -------------------------------------------------------------------------------------
def cursors(iterable):
    """`across e as c`: the cursor itself at each position (c.item is the item)."""
    cursor = iterable.new_cursor
    while not cursor.after:
        yield cursor
        cursor.forth()


def take_while(test, positions):
    """`across ... until e`: the positions before the first one where `e` holds."""
    for position in positions:
        if not test(position):
            return
        yield position


def items(iterable):
    """`across e is x`: each item."""
    cursor = iterable.new_cursor
    while not cursor.after:
        yield cursor.item
        cursor.forth()


# --- agents ----------------------------------------------------------------------------------------
_DISPATCHERS: dict = {}


def dispatcher(name, is_property):
    """The function an agent calls: feature `name` of its target, bound dynamically."""
    key = (name, is_property)
    found = _DISPATCHERS.get(key)
    if found is None:
        from . import basic  # deferred: start-up (loaded on first use only)

        if is_property:

            def found(target, _name=name):
                result = basic.query(target, _name)
                check = getattr(target, "_invariant_", None)
                if check is not None:  # an agent call is a qualified call
                    check()
                return result
        else:

            def found(target, *args, _name=name):
                result = basic.call(target, _name, args)
                check = getattr(target, "_invariant_", None)
                if check is not None:
                    check()
                return result

        _DISPATCHERS[key] = found
    return found


def new_agent(here, cls, gen, fn, slots, opened):
    obj = cls.__new__(cls)
    target = slots[0]
    obj._region_ = getattr(target, "_region_", here) if 0 not in opened else here
    obj._gen_ = gen
    obj._fn = fn
    obj._slots = slots
    obj._open = opened
    return obj


def box_formal(value, desc):
    """A value of a formal generic type attached to a reference type: boxed when the actual
    generic is a basic class a bare Python value does not say (REAL_32, INTEGER_64, ...)."""
    key = desc.key
    if key in _BOX_KINDS and value is not None:
        return box(key, value)
    return value


def formal_query(target, name, here, desc):
    """`x.out` (`generator`, ...) with x of a formal generic type: answered for the actual
    generic's basic class when x is a bare basic value."""

    if desc.key in _BOX_KINDS and type(target) in (int, float, str):
        return basic.query_as(desc.key, target, name, here)
    return basic.query(target, name, here)


def _make_once_string(here, text, maker, cell):
    return maker(here, text)


def once_string(here, key, text, maker):
    return here.once(key, _make_once_string, (here, text, maker))


__all__ = ["EiffelFailure", "T", "box"]
