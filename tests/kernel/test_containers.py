"""The `external "Python"` features of SPECIAL and TUPLE (scoopc/kernel/ext/special.py, tuple.py)
and scoopc/kernel/tuples.py, called directly on fake objects laid out as codegen_spec.md says.
The agent classes' are in test_agents.py."""

from array import array

import pytest

import scoopc.kernel as kernel
from scoopc.kernel import tuples, types
from scoopc.kernel.ext import special, tuple as tup

# --- Fakes ---------------------------------------------------------------------------------


class Region:
    """Stands for a `scoopc.runtime.Processor`."""


class Desc:
    """A TypeDesc as the externals use it: `key`, `default()`, `generics`, `attached`."""

    def __init__(self, key, generics=(), attached=False, default=None, factory=None):
        self.key, self.generics, self.attached = key, tuple(generics), attached
        self._default, self._factory = default, factory
        self.regions = []

    def default(self, region=None):
        self.regions.append(region)
        return self._factory() if self._factory else self._default


INT = Desc("INTEGER_32", attached=True, default=0)
STRING = Desc("STRING_8", attached=True)
ANY_D = Desc("ANY")


class Special:
    count = property(special.count)
    capacity = property(special.capacity)


class Tuple:
    count = property(tup.count)
    object_comparison = property(tup.object_comparison)


class Point:
    """A user expanded object (for fill_with_default)."""

    def __init__(self):
        self.x = 0


class Str:
    """A reference object with an Eiffel `is_equal`."""

    def __init__(self, s):
        self.s = s

    def is_equal(self, other):
        return self.s == other.s


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


def new_special(region, n, gen=INT, items=()):
    s = Special.__new__(Special)
    s._region_, s._gen_ = region, (gen,)
    special.make_empty(s, n)
    for v in items:
        special.extend(s, v)
    return s


def new_tuple(region, items, gen=()):
    return tuples.new_tuple(region, items, gen)


# --- SPECIAL -------------------------------------------------------------------------------


def test_make_empty(region):
    s = new_special(region, 5)
    assert (s.count, s.capacity, s._items) == (0, 5, [])
    with pytest.raises(ValueError):
        special.make_empty(s, -1)


def test_extend_item_put(region):
    s = new_special(region, 3, items=[10, 20])
    assert [special.item(s, i) for i in range(2)] == [10, 20]
    special.put(s, 7, 1)
    special.extend(s, 30)
    assert s._items == [10, 7, 30] and s.count == 3
    with pytest.raises(IndexError):
        special.extend(s, 40)  # full
    with pytest.raises(IndexError):
        special.item(s, -1)  # not Python's item from the end
    with pytest.raises(IndexError):
        special.put(s, 1, -1)
    with pytest.raises(IndexError):
        special.item(s, 3)


def test_fill_with(region):
    s = new_special(region, 6, items=[1, 2, 3])
    special.fill_with(s, 9, 1, 1)
    assert s._items == [1, 9, 3]
    special.fill_with(s, 5, 2, 4)  # past count: count grows to end + 1
    assert s._items == [1, 9, 5, 5, 5]
    special.fill_with(s, 0, 5, 4)  # empty range
    assert s.count == 5
    special.fill_with(s, 8, 5, 5)  # starting at count
    assert s._items == [1, 9, 5, 5, 5, 8]
    with pytest.raises(IndexError):
        special.fill_with(s, 0, 0, 6)  # beyond capacity
    t = new_special(region, 6, items=[1])
    with pytest.raises(IndexError):
        special.fill_with(t, 0, 2, 3)  # start beyond count
    with pytest.raises(IndexError):
        special.fill_with_default(t, 2, 3)


def test_fill_with_default_basic(region):
    s = new_special(region, 4, items=[5])
    special.fill_with_default(s, 0, 2)
    assert s._items == [0, 0, 0]
    c = new_special(region, 2, gen=Desc("CHARACTER_8", default="\x00"))
    special.fill_with_default(c, 0, 1)
    assert c._items == ["\x00", "\x00"]


def test_fill_with_default_expanded_fresh_objects(region):
    calls = []

    def make():
        calls.append(1)
        return Point()

    gen = Desc("POINT", factory=make)
    s = new_special(region, 3, gen=gen)
    special.fill_with_default(s, 0, 2)
    assert len(calls) == 3 and gen.regions == [region] * 3  # made in the SPECIAL's region
    assert len({id(p) for p in s._items}) == 3  # one object per slot
    special.fill_with_default(s, 1, 0)  # empty range: no default asked
    assert len(calls) == 3


def test_copy_data(region):
    src = new_special(region, 5, items=[1, 2, 3, 4, 5])
    dst = new_special(region, 6, items=[0, 0])
    special.copy_data(dst, src, 1, 1, 3)  # extends the count
    assert dst._items == [0, 2, 3, 4]
    special.copy_data(dst, src, 0, 0, 2)  # inside the count
    assert dst._items == [1, 2, 3, 4]
    special.copy_data(dst, src, 0, 4, 0)  # nothing
    assert dst.count == 4
    with pytest.raises(IndexError):
        special.copy_data(dst, src, 0, 3, 4)  # beyond capacity
    with pytest.raises(IndexError):
        special.copy_data(dst, src, 3, 0, 3)  # beyond the source's count
    with pytest.raises(IndexError):
        special.copy_data(dst, src, 0, 5, 1)  # destination beyond count


def test_move_data_overlapping(region):
    s = new_special(region, 8, items=[1, 2, 3, 4, 5])
    special.move_data(s, 0, 2, 4)  # forward overlap, extends count
    assert s._items == [1, 2, 1, 2, 3, 4]
    special.move_data(s, 2, 0, 4)  # backward overlap
    assert s._items == [1, 2, 3, 4, 3, 4]
    special.move_data(s, 0, 6, 2)  # to the end
    assert s._items == [1, 2, 3, 4, 3, 4, 1, 2]


def test_keep_head_tail(region):
    s = new_special(region, 5, items=[1, 2, 3, 4, 5])
    special.keep_tail(s, 3)
    assert s._items == [3, 4, 5]
    special.keep_tail(s, 3)
    assert s._items == [3, 4, 5]
    special.keep_head(s, 2)
    assert s._items == [3, 4] and s.capacity == 5
    special.keep_tail(s, 0)
    assert s._items == []
    with pytest.raises(ValueError):
        special.keep_head(s, -1)
    with pytest.raises(ValueError):
        special.keep_tail(s, -1)


def test_resized_area(region):
    gen = Desc("STRING_8")
    s = new_special(region, 3, gen=gen, items=["a", "b", "c"])
    bigger = special.resized_area(s, 10)
    assert type(bigger) is Special and bigger is not s
    assert bigger._region_ is region and bigger._gen_ == (gen,)
    assert (bigger.count, bigger.capacity, bigger._items) == (3, 10, ["a", "b", "c"])
    special.put(bigger, "z", 0)
    assert s._items == ["a", "b", "c"]  # storage of its own
    with pytest.raises(ValueError):
        special.resized_area(s, -1)
    with pytest.raises(ValueError):
        special.aliased_resized_area(s, -1)
    smaller = special.resized_area(s, 2)
    assert (smaller.count, smaller.capacity) == (2, 2)
    assert s.count == 3


def test_aliased_resized_area(region):
    s = new_special(region, 3, items=[1, 2, 3])
    r = special.aliased_resized_area(s, 8)
    assert r is s and (s.count, s.capacity) == (3, 8)
    r = special.aliased_resized_area(s, 2)
    assert r is s and (s.count, s.capacity, s._items) == (2, 2, [1, 2])


def test_wipe_out(region):
    s = new_special(region, 4, items=[1, 2])
    special.wipe_out(s)
    assert (s.count, s.capacity) == (0, 4)


def test_special_copy(region):
    s = new_special(region, 4, items=[1, 2])
    other_region = Region()
    t = Special.__new__(Special)  # as `twin` makes it: only `_region_`
    t._region_ = other_region
    special.copy(t, s)
    assert (t._items, t.capacity, t._gen_) == ([1, 2], 4, s._gen_)
    assert t._items is not s._items and t._region_ is other_region
    special.extend(t, 3)
    assert s.count == 2
    special.copy(s, s)  # copying itself changes nothing
    assert s._items == [1, 2]


def test_items_kept_in_a_buffer(region):
    """A SPECIAL of numbers passed to an external keeps its items in an array.array (a buffer
    numpy views): every feature works on it as on a list, and with a list-backed SPECIAL."""
    s = new_special(region, 6, items=[1, 2])
    s._items = array("i", s._items)
    special.fill_with(s, 7, 2, 3)
    listed = new_special(region, 3, items=[4, 5, 6])
    special.copy_data(s, listed, 1, 4, 2)
    assert list(s._items) == [1, 2, 7, 7, 5, 6] and type(s._items) is array
    special.copy_data(listed, s, 0, 0, 2)  # a run of the buffer into a list
    special.fill_with_default(s, 5, 5)
    assert listed._items == [1, 2, 6] and list(s._items) == [1, 2, 7, 7, 5, 0]
    special.keep_head(s, 3)
    special.extend(s, 9)
    assert [special.item(s, i) for i in range(s.count)] == [1, 2, 7, 9]
    special.wipe_out(s)
    assert (s.count, s.capacity) == (0, 6)


# --- TUPLE ---------------------------------------------------------------------------------


def test_new_tuple(registry, region):
    items = [1, "x"]
    t = tuples.new_tuple(region, items, (INT, STRING))
    assert type(t) is Tuple and t._region_ is region and t._gen_ == (INT, STRING)
    assert t._items == items and t._items is not items
    assert tuples.new_tuple(region, iter([]))._gen_ == ()


def test_items_of(registry, region):
    assert tuples.items_of(None) == ()
    assert tuples.items_of((1, 2)) == (1, 2)
    t = Tuple.__new__(Tuple)  # `create t` (default_create): no host storage
    t._region_, t._gen_ = region, (INT, STRING, Desc("BOOLEAN", default=False))
    assert tuples.items_of(t) == [0, None, False]
    assert t.count == 3


def test_twin(registry, region):
    t = new_tuple(region, [1, 2], (INT, INT))
    tup.compare_objects(t)
    other = Region()
    u = tuples.twin(other, t)
    assert type(u) is Tuple and u is not t and u._items == [1, 2] and u._items is not t._items
    assert u._region_ is other and u._gen_ == t._gen_ and u.object_comparison
    assert tuples.twin(region, None) is None
    p = (1, 2)
    assert tuples.twin(region, p) is p
    q = [1, 2]
    assert tuples.twin(region, q) == q and tuples.twin(region, q) is not q


def test_tuple_item_put_count(registry, region):
    t = new_tuple(region, [1, "a", None], (INT, STRING, ANY_D))
    assert t.count == 3
    assert [tup.item(t, i) for i in (1, 2, 3)] == [1, "a", None]
    tup.put(t, 5, 1)
    assert tup.item(t, 1) == 5
    with pytest.raises(IndexError):
        tup.item(t, 0)
    with pytest.raises(IndexError):
        tup.put(t, 1, 0)
    with pytest.raises(IndexError):
        tup.item(t, 4)


KEYS_AND_CODES = [
    ("ANY", 0),
    ("STRING_8", 0),
    ("CELL@BASE", 0),
    ("BOOLEAN", 1),
    ("CHARACTER_8", 2),
    ("REAL_64", 3),
    ("REAL_32", 4),
    ("POINTER", 5),
    ("INTEGER_8", 6),
    ("INTEGER_16", 7),
    ("INTEGER_32", 8),
    ("INTEGER_64", 9),
    ("NATURAL_8", 10),
    ("NATURAL_16", 11),
    ("NATURAL_32", 12),
    ("NATURAL_64", 13),
    ("CHARACTER_32", 14),
    ("INTEGER_32@BASE", 8),
]


@pytest.mark.parametrize("key, code", KEYS_AND_CODES)
def test_item_code_from_declared_type(registry, region, key, code):
    t = new_tuple(region, [None], (Desc(key),))
    assert tup.item_code(t, 1) == code


def test_item_code_from_value_when_type_unknown(registry, region):
    t = new_tuple(region, [True, 3, 2**40, 1.5, "a", "\u0394", "ab", None, Str("s")], ())
    assert [tup.item_code(t, i) for i in range(1, 10)] == [1, 8, 9, 3, 2, 14, 0, 0, 0]
    t = new_tuple(region, [1, 2], (Desc("INTEGER_64"),))  # `_gen_` shorter than the tuple
    assert (tup.item_code(t, 1), tup.item_code(t, 2)) == (9, 8)
    with pytest.raises(IndexError):
        tup.item_code(t, 3)


def test_valid_type_for_index(registry, region):
    gen = (
        Desc("INTEGER_32"),
        Desc("NATURAL_8"),
        Desc("BOOLEAN"),
        Desc("REAL_64"),
        Desc("CHARACTER_8"),
        Desc("CHARACTER_32"),
        STRING,
        ANY_D,
        Desc("POINTER"),
    )
    t = new_tuple(region, [d.default() for d in gen], gen)
    ok = tup.valid_type_for_index
    assert ok(t, 5, 1) and not ok(t, True, 1) and not ok(t, "5", 1) and not ok(t, None, 1)
    assert not ok(t, 2**31, 1) and ok(t, -(2**31), 1)
    assert ok(t, 255, 2) and not ok(t, 256, 2) and not ok(t, -1, 2)
    assert ok(t, False, 3) and not ok(t, 0, 3)
    assert ok(t, 1.5, 4) and ok(t, 1, 4) and not ok(t, True, 4) and not ok(t, "1", 4)
    assert ok(t, "a", 5) and not ok(t, "\u0394", 5) and not ok(t, "ab", 5)
    assert ok(t, "\u0394", 6) and not ok(t, 65, 6)
    assert ok(t, Str("s"), 7) and not ok(t, None, 7)  # attached reference: Void refused
    assert ok(t, None, 8) and ok(t, 3, 8)  # detachable ANY: anything
    assert ok(t, 12345, 9) and not ok(t, None, 9)
    u = new_tuple(region, [1, 2], (INT,))
    assert ok(u, "anything", 2)  # type not known: accepted


def test_type_code_helpers():
    assert tup.type_code(object()) == 0  # no key: a reference
    assert tup.value_fits(None, None) and tup.value_fits(None, "anything")


def test_object_comparison(registry, region):
    t = new_tuple(region, [], ())
    assert t.object_comparison is False
    tup.compare_objects(t)
    assert t.object_comparison is True
    tup.compare_references(t)
    assert t.object_comparison is False


# --- With the real TypeDesc (scoopc/kernel/types.py) ---------------------------------------


def test_real_typedesc_defaults(registry, region):
    s = new_special(region, 3, gen=types.t("REAL_64"))
    special.fill_with_default(s, 0, 2)
    assert s._items == [0.0, 0.0, 0.0]
    t = Tuple.__new__(Tuple)
    t._region_, t._gen_ = region, (types.t("BOOLEAN"), types.t("CHARACTER_32"), types.t("CELL", (), False))
    assert tuples.items_of(t) == [False, "\x00", None]
    assert [tup.item_code(t, i) for i in (1, 2, 3)] == [1, 14, 0]
