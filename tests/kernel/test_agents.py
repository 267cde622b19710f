"""The `external "Python"` features of ROUTINE, PROCEDURE and FUNCTION (scoopc/kernel/ext/routine.py,
procedure.py, function.py), called directly on fake agents laid out as codegen_spec.md says (`_fn`,
`_slots`, `_open`, `_gen_[0]` the OPEN_ARGS TypeDesc)."""

import os
import types as pytypes
import zlib

import pytest

import scoopc.kernel as kernel
from scoopc.kernel import types
from scoopc.kernel.ext import function, procedure, routine, tuple as tup
from scoopc.kernel.tuples import new_tuple

# --- Fakes ---------------------------------------------------------------------------------


class Region:
    """Stands for a `scoopc.runtime.Processor`."""


class Desc:
    """A TypeDesc as the externals use it: `key`, `generics`, `attached`, `default(region)`."""

    def __init__(self, key, generics=(), attached=False):
        self.key, self.generics, self.attached = key, tuple(generics), attached

    def default(self, region=None):
        return None


INT = Desc("INTEGER_32", attached=True)
STRING = Desc("STRING_8", attached=True)
ANY_D = Desc("ANY")


class Tuple:
    count = property(tup.count)
    object_comparison = property(tup.object_comparison)


class Str:
    """A reference object with an Eiffel `is_equal`."""

    def __init__(self, s):
        self.s = s

    def is_equal(self, other):
        return self.s == other.s


class Target:
    def __init__(self):
        self.log = []

    def show(self, a, b):
        self.log.append((a, b))


def show(t, a, b):
    """The routine of `agent t.show (?, ?)`: operands target first."""
    t.show(a, b)


def add(t, a, b):
    return a + b


class Procedure:
    _region_ = None
    call = procedure.call
    flexible_call = routine.flexible_call


class Function:
    _region_ = None
    last_result = None
    item = function.item

    def call(self, args):  # FUNCTION.call is Eiffel
        self.last_result = function.item(self, args)


class Cell:
    """A generated class as types.py sees one: `_key_`, `_conforms_`."""

    _key_ = "CELL"
    _conforms_ = frozenset({"CELL", "ANY"})


class Other:
    _key_ = "OTHER"
    _conforms_ = frozenset({"OTHER", "ANY"})


@pytest.fixture
def registry():
    saved = dict(kernel.CLASSES)
    kernel.register("TUPLE", Tuple)
    yield kernel.CLASSES
    kernel.CLASSES.clear()
    kernel.CLASSES.update(saved)


@pytest.fixture
def region():
    return Region()


def agent(cls, fn, slots, open_, open_types=None, region=None):
    a = cls.__new__(cls)
    a._region_ = region
    a._fn, a._slots, a._open = fn, list(slots), tuple(open_)
    if open_types is not None:
        a._gen_ = (Desc("TUPLE", generics=open_types),)
    return a


# --- Agents: calls -------------------------------------------------------------------------


def test_procedure_call_closed_target(registry, region):
    tgt = Target()
    p = agent(Procedure, show, [tgt, None, None], (1, 2), (INT, STRING))
    procedure.call(p, new_tuple(region, [1, "a"], (INT, STRING)))
    procedure.call(p, new_tuple(region, [2, "b", "extra"], ()))  # extra items ignored
    procedure.call(p, (3, "c"))  # a Python tuple
    assert tgt.log == [(1, "a"), (2, "b"), (3, "c")]
    assert p._slots == [tgt, None, None]  # slots never written
    assert procedure.call(p, (4, "d")) is None


def test_procedure_call_mixed_open_closed(registry, region):
    tgt = Target()
    p = agent(Procedure, show, [None, "closed", None], (0, 2))  # agent {TARGET}.show ("closed", ?)
    procedure.call(p, (tgt, "open"))
    assert tgt.log == [("closed", "open")]
    q = agent(Procedure, show, [tgt, 1, 2], ())  # everything closed
    procedure.call(q, None)
    procedure.call(q, new_tuple(region, [], ()))
    assert tgt.log[1:] == [(1, 2), (1, 2)]


def test_call_with_too_few_operands(registry, region):
    p = agent(Procedure, show, [Target(), None, None], (1, 2))
    with pytest.raises(TypeError):
        procedure.call(p, (1,))
    with pytest.raises(TypeError):
        procedure.call(p, None)


def test_function_item_and_flexible_item(registry, region):
    f = agent(Function, add, [object(), 10, None], (2,), (INT,))
    assert function.item(f, new_tuple(region, [5], (INT,))) == 15
    assert function.flexible_item(f, (1, "ignored")) == 11
    assert f.last_result is None  # `item` leaves `last_result` alone


def test_reentrant_call(registry, region):
    def countdown(t, n):
        return 0 if n == 0 else 1 + function.item(f, (n - 1,))

    f = agent(Function, countdown, [object(), None], (1,))
    assert function.item(f, (5,)) == 5
    assert f._slots[1] is None


def test_flexible_call_uses_dynamic_call(registry, region):
    tgt = Target()
    p = agent(Procedure, show, [tgt, None, None], (1, 2))
    routine.flexible_call(p, (1, 2, 3))
    assert tgt.log == [(1, 2)]
    f = agent(Function, add, [None, None, None], (1, 2))
    f.flexible_call = routine.flexible_call.__get__(f)
    f.flexible_call(new_tuple(region, [3, 4], ()))
    assert f.last_result == 7  # through FUNCTION's `call`


# --- Agents: queries -----------------------------------------------------------------------


def test_open_count_and_target_closed(registry):
    tgt = Target()
    p = agent(Procedure, show, [tgt, None, None], (1, 2))
    assert routine.open_count(p) == 2 and routine.is_target_closed(p)
    q = agent(Procedure, show, [None, 1, None], (0, 2))
    assert routine.open_count(q) == 2 and not routine.is_target_closed(q)
    r = agent(Procedure, show, [tgt, 1, 2], ())
    assert routine.open_count(r) == 0 and routine.is_target_closed(r)


def test_operands_and_target(registry, region):
    tgt = Target()
    p = agent(Procedure, show, [tgt, None, None], (1, 2))
    assert routine.operands(p) is None and routine.target(p) is tgt
    args = new_tuple(region, [1, "a"], (INT, STRING))
    routine.set_operands(p, args)
    assert routine.operands(p) is args  # kept, not copied (EiffelBase)
    assert routine.target(p) is tgt
    q = agent(Procedure, show, [None, None, None], (0, 1, 2))
    assert routine.target(q) is None  # open target, no operands
    routine.set_operands(q, new_tuple(region, [], ()))
    assert routine.target(q) is None
    other = Target()
    routine.set_operands(q, new_tuple(region, [other, 1, 2], ()))
    assert routine.target(q) is other  # open target: item 1 of `operands`
    routine.set_operands(q, None)
    assert routine.operands(q) is None


def test_valid_operands(registry, region):
    tgt = Target()
    p = agent(Procedure, show, [tgt, None, None], (1, 2), (INT, STRING))
    ok = routine.valid_operands
    assert ok(p, new_tuple(region, [1, Str("a")], (INT, STRING)))
    assert ok(p, (1, Str("a"), "extra"))
    assert not ok(p, None)
    assert not ok(p, (1,))
    assert not ok(p, ("1", Str("a")))  # STRING where INTEGER_32 is open
    assert not ok(p, (True, Str("a")))  # BOOLEAN is not an INTEGER
    assert not ok(p, (2**40, Str("a")))  # out of INTEGER_32's range
    assert not ok(p, (1, None))  # Void for an attached STRING
    closed = agent(Procedure, show, [tgt, 1, 2], (), ())
    assert ok(closed, None) and ok(closed, new_tuple(region, [], ())) and ok(closed, (9,))
    q = agent(Procedure, show, [None, None, None], (0, 1, 2), (ANY_D, ANY_D, ANY_D))
    assert ok(q, (tgt, 1, 2))
    assert not ok(q, (None, 1, 2))  # open target must not be Void
    untyped = agent(Procedure, show, [tgt, None, None], (1, 2))  # no `_gen_`: counts only
    assert ok(untyped, ("x", None)) and not ok(untyped, ("x",))


# --- Agents: comparison, hashing, duplication ----------------------------------------------


def test_is_equal(registry, region):
    tgt, other = Target(), Target()
    p = agent(Procedure, show, [tgt, None, None], (1, 2))
    assert routine.is_equal(p, p)
    assert routine.is_equal(p, agent(Procedure, show, [tgt, "ignored", None], (1, 2)))
    assert not routine.is_equal(p, agent(Procedure, show, [other, None, None], (1, 2)))
    assert not routine.is_equal(p, agent(Procedure, add, [tgt, None, None], (1, 2)))
    assert not routine.is_equal(p, agent(Procedure, show, [tgt, None, None], (2,)))
    assert not routine.is_equal(p, None)
    a = agent(Procedure, show, [tgt, 1, None], (2,))
    assert routine.is_equal(a, agent(Procedure, show, [tgt, 1, None], (2,)))  # basic: by value
    assert not routine.is_equal(a, agent(Procedure, show, [tgt, True, None], (2,)))
    assert not routine.is_equal(a, agent(Procedure, show, [tgt, 2, None], (2,)))
    s = agent(Procedure, show, [tgt, Str("x"), None], (2,))
    assert not routine.is_equal(s, agent(Procedure, show, [tgt, Str("x"), None], (2,)))  # by identity


def test_is_equal_compares_operands(registry, region):
    tgt = Target()
    p = agent(Procedure, show, [tgt, None, None], (1, 2))
    q = agent(Procedure, show, [tgt, None, None], (1, 2))
    routine.set_operands(p, new_tuple(region, [1, 2], ()))
    assert not routine.is_equal(p, q)
    routine.set_operands(q, new_tuple(region, [1, 2], ()))
    assert routine.is_equal(p, q)
    routine.set_operands(q, new_tuple(region, [1, 3], ()))
    assert not routine.is_equal(p, q)
    x = Str("x")
    routine.set_operands(p, new_tuple(region, [x, 2], ()))
    routine.set_operands(q, new_tuple(region, [Str("x"), 2], ()))
    assert not routine.is_equal(p, q)  # `=` on items
    tup.compare_objects(routine.operands(p))
    assert not routine.is_equal(p, q)  # different comparison criteria
    tup.compare_objects(routine.operands(q))
    assert routine.is_equal(p, q)  # `~` on items
    routine.set_operands(q, new_tuple(region, [Str("y"), 2], ()))
    tup.compare_objects(routine.operands(q))
    assert not routine.is_equal(p, q)
    routine.set_operands(q, new_tuple(region, [Target(), 2], ()))
    tup.compare_objects(routine.operands(q))
    assert not routine.is_equal(p, q)  # `~` needs the same dynamic type
    routine.set_operands(q, new_tuple(region, [x], ()))
    tup.compare_objects(routine.operands(q))
    assert not routine.is_equal(p, q)  # count
    routine.set_operands(q, (x, 2))
    assert not routine.is_equal(p, q)  # a Python tuple is not a TUPLE object's type


def test_is_equal_same_agent_expression_evaluated_twice(registry):
    tgt = Target()

    def make(k):
        return agent(Procedure, lambda t, a: t.show(a, k), [tgt, None], (1,))

    assert routine.is_equal(make(1), make(1))  # two closures of one code object
    assert not routine.is_equal(make(1), make(2))

    def make_default(k):
        return agent(Procedure, lambda t, a, k=k: t.show(a, k), [tgt, None], (1,))

    assert routine.is_equal(make_default(1), make_default(1))
    assert not routine.is_equal(make_default(1), make_default(2))

    def make_late():
        v = None
        code = (lambda t: t.show(v, v)).__code__
        fn = pytypes.FunctionType(code, globals(), None, None, (pytypes.CellType(),))
        return agent(Procedure, fn, [tgt], ())

    assert not routine.is_equal(make_late(), make_late())  # an empty cell
    bound1 = agent(Procedure, tgt.show, [None, None], (0, 1))
    bound2 = agent(Procedure, tgt.show, [None, None], (0, 1))
    assert routine.is_equal(bound1, bound2)
    assert not routine.is_equal(bound1, agent(Procedure, Target().show, [None, None], (0, 1)))


def test_hash_code(registry):
    p = agent(Procedure, show, [Target(), None, None], (1, 2))
    q = agent(Procedure, show, [Target(), 1, None], (2,))
    h = routine.hash_code(p)
    assert 0 <= h < 2**31
    assert routine.hash_code(q) == h  # the routine only, as EiffelBase
    assert routine.hash_code(agent(Procedure, add, [None] * 3, (0, 1, 2))) != h
    code = show.__code__
    name = f"{os.path.basename(__file__)}:{code.co_firstlineno}:{getattr(code, 'co_qualname', code.co_name)}"
    assert h == zlib.crc32(name.encode()) & 0x7FFFFFFF  # deterministic, no `id`
    bound = agent(Procedure, Target().show, [None, None], (0, 1))
    assert routine.hash_code(bound) == routine.hash_code(agent(Procedure, Target().show, [None, None], (0, 1)))
    assert routine.hash_code(agent(Procedure, len, [None], (0,))) >= 0  # no code object


def test_routine_copy(registry, region):
    tgt = Target()
    other_region = Region()
    f = agent(Function, add, [tgt, 1, None], (2,), (INT,), region=region)
    f.last_result = 42
    ops = new_tuple(region, [5], (INT,))
    routine.set_operands(f, ops)
    g = Function.__new__(Function)
    g._region_ = other_region
    g.stale = "not in other"
    routine.copy(g, f)
    assert g._region_ is other_region and not hasattr(g, "stale")
    assert (g._fn, g._slots, g._open, g._gen_, g.last_result) == (add, f._slots, (2,), f._gen_, 42)
    assert g._slots is not f._slots
    assert routine.operands(g) is not ops and routine.operands(g)._items == [5]
    assert routine.operands(g)._region_ is other_region
    assert routine.is_equal(g, f) and function.item(g, (2,)) == 3
    h = agent(Function, add, [tgt, 1, None], (2,))
    routine.set_operands(h, new_tuple(region, [1], ()))
    routine.copy(h, agent(Function, add, [tgt, 1, None], (2,)))
    assert routine.operands(h) is None  # Void operands copied too
    before = dict(f.__dict__)
    routine.copy(f, f)
    assert f.__dict__ == before


def test_real_typedesc_conformance(registry, region):
    cell = types.t("CELL")
    tgt = Target()
    p = agent(Procedure, show, [tgt, None, None], (1, 2), (cell, types.t("ANY", (), False)))
    assert routine.valid_operands(p, (Cell(), None))
    assert routine.valid_operands(p, (Cell(), 5))  # a basic value is an ANY
    assert not routine.valid_operands(p, (Other(), None))  # OTHER does not conform to CELL
    assert not routine.valid_operands(p, (5, None))  # nor does INTEGER_32
    assert not routine.valid_operands(p, (None, None))  # CELL is attached
    assert routine.valid_operands(p, (object(), None))  # not a generated object: let through
    n = new_tuple(region, [Cell(), 1], (types.t("NUMERIC", (), False), types.t("NUMERIC")))
    assert not tup.valid_type_for_index(n, Cell(), 1) and tup.valid_type_for_index(n, None, 1)
    assert tup.valid_type_for_index(n, 2.5, 2) and not tup.valid_type_for_index(n, None, 2)
