"""The SCOOP fast paths of codegen (scoopc/codegen/scoop.py, scoop_calls.py): which routines are
leaves, which separate calls are bound statically, where `command1`, `reserve1`, `leaf_call`
and ranges over integer intervals are emitted, and that each program still does what it says."""

from __future__ import annotations

import re
import sys
from pathlib import Path

import pytest

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "golden"))
from golden_support import Config, compile_program, run_program  # noqa: E402

COUNTER = """class COUNTER
create
	make
feature
	make do end
	value: INTEGER
	names: detachable separate STRING
	increment do value := value + 1 end
	add (n: INTEGER) do value := value + n end
	add_square (n: INTEGER) do add (square (n)) end
	square (n: INTEGER): INTEGER do Result := n * n end
	looped (n: INTEGER)
		local
			i: INTEGER
		do
			from i := 1 until i > n loop value := value + 1; i := i + 1 end
		end
	register (s: separate STRING) do names := s end
	factorial (n: INTEGER): INTEGER
		do
			if n <= 1 then Result := 1 else Result := n * factorial (n - 1) end
		end
end
"""

BASE_ITEM = """class BASE_ITEM
create
	make
feature
	make do end
	x: INTEGER
	step do x := x + 1 end
	bump do step end
end
"""

LOOPING_ITEM = """class LOOPING_ITEM
inherit
	BASE_ITEM
		redefine step end
create
	make
feature
	step
		do
			across 1 |..| 2 as k loop x := x + k.item end
		end
end
"""

BOX = """class BOX
create
	make
feature
	make do create items.make end
	items: LINKED_QUEUE [INTEGER]
	put (v: INTEGER) do items.extend (v) end
	first: INTEGER do Result := items.item end
	keeper: detachable separate COUNTER
	keep (c: separate COUNTER) do keeper := c end
end
"""

ROOT = """class FAST
create
	make
feature
	make
		local
			c: separate COUNTER
			b: separate BASE_ITEM
			l: separate LOOPING_ITEM
			box: separate BOX
		do
			create c.make
			inc (c)
			add_twice (c, 2)
			guarded (c)
			give (c, "x")
			show (c)
			loop_it (c)
			create b.make
			create l.make
			step_it (b)
			step_it (l)
			show_items (b, l)
			create box.make
			fill (box, c)
			show_box (box)
			across 1 |..| 3 as i loop print (i.item.out) end
			across 4 |..| 5 is k loop print (k.out) end
			across 6 |..| 7 as i loop if attached i as j then print (j.item.out) end end
			print ("%N")
		end
	inc (c: separate COUNTER) do c.increment end
	add_twice (c: separate COUNTER; n: INTEGER) do c.add (n); c.add_square (n) end
	guarded (c: separate COUNTER) require c.value > 0 do c.increment end
	give (c: separate COUNTER; s: STRING) do c.register (s) end
	show (c: separate COUNTER) do print (c.value.out + " " + c.factorial (4).out + "%N") end
	loop_it (c: separate COUNTER) do c.looped (2) end
	step_it (b: separate BASE_ITEM) do b.step end
	show_items (b: separate BASE_ITEM; l: separate LOOPING_ITEM) do print (b.x.out + " " + l.x.out + "%N") end
	fill (box: separate BOX; c: separate COUNTER) do box.put (7); box.keep (c) end
	show_box (box: separate BOX) do print (box.first.out + "%N") end
end
"""

SOURCES = {"counter.e": COUNTER, "base_item.e": BASE_ITEM, "looping_item.e": LOOPING_ITEM, "box.e": BOX, "fast.e": ROOT}


@pytest.fixture(scope="module")
def program(tmp_path_factory):
    folder = tmp_path_factory.mktemp("src") / "fast"
    folder.mkdir()
    for name, text in SOURCES.items():
        (folder / name).write_text(text)
    out = tmp_path_factory.mktemp("out")
    compiled, texts = compile_program(folder, out, "none")
    return compiled, texts


def routine(text: str, name: str) -> str:
    """The source of one generated method, with its decorators."""
    match = re.search(rf"((?:    @[\w.]+\n)*)    def {name}\(.*?(?=\n    (?:@|def |\w+ = )|\n_S\.register)", text, re.S)
    assert match, f"no routine {name}"
    return match.group(0)


def is_leaf(text: str, name: str) -> bool:
    return "@_rt.leaf" in routine(text, name).split("def ")[0]


def test_the_program_still_does_what_it_says(program):
    outcome = run_program(program[0], Config())
    assert outcome.status == 0, outcome.err
    assert outcome.out.splitlines() == ["8 24", "1 3", "7", "1234567"]


def test_leaves_are_decorated_and_only_leaves(program):
    counter = program[1]["counter.py"]
    for name in ("increment", "add", "add_square", "square", "register", "make"):
        assert is_leaf(counter, name), name
    assert not is_leaf(counter, "looped")  # a loop
    assert not is_leaf(counter, "factorial")  # recursion


def test_closed_world_an_heir_with_a_loop_makes_callers_non_leaves(program):
    base = program[1]["base_item.py"]
    assert is_leaf(base, "step")
    assert not is_leaf(base, "bump")  # LOOPING_ITEM's step loops
    assert not is_leaf(program[1]["looping_item.py"], "step")


def test_short_library_routines_count_as_leaves_but_are_never_decorated(program):
    box = program[1]["box.py"]
    assert is_leaf(box, "put") and is_leaf(box, "first")  # LINKED_QUEUE.extend / item
    assert is_leaf(box, "keep")  # stores its separate argument only
    assert "with here.reserve" not in routine(box, "keep")
    base = Path(program[0].library) / "eiffel_base"
    assert (base / "_scoop_facts.json").exists()
    assert not any("@_rt.leaf" in p.read_text() for p in base.glob("*.py"))


def test_one_separate_command_is_command1_statically_bound(program):
    text = program[1]["fast.py"]
    assert "here.leaf_command1(c, _M_counter.COUNTER.increment, (), _W_" in routine(text, "inc")
    assert "here.command1(c, _M_counter.COUNTER.looped, (2,), _W_" in routine(text, "loop_it")  # not a leaf


def test_leaf_calls_and_queries_inside_a_reservation(program):
    text = program[1]["fast.py"]
    body = routine(text, "add_twice")
    assert "with here.reserve1(c, _W_" in body
    assert "here.leaf_call(c, _M_counter.COUNTER.add, (n,))" in body
    assert "here.leaf_call(c, _M_counter.COUNTER.add_square, (n,))" in body
    show = routine(text, "show")
    assert "here.leaf_query(c, _G_" in show  # an attribute: a getter
    assert "here.query(c, _M_counter.COUNTER.factorial, (4,)" in show  # not a leaf: the general query


def test_a_precondition_is_a_clause_table_not_command1(program):
    text = program[1]["fast.py"]
    assert "with here.reserve1(c, _W_" in routine(text, "guarded") and "_PRE_" in routine(text, "guarded")
    assert re.search(r"_PRE_\d+ = \(\(lambda here, self, c: here\.leaf_query\(c, _G_\d+, \(\), _W_\d+\) > 0", text)


def test_a_reference_argument_takes_the_general_call(program):
    body = routine(program[1]["fast.py"], "give")
    assert "here.call(c, _M_counter.COUNTER.register, (" in body and "command1" not in body


def test_several_versions_are_bound_at_run_time(program):
    body = routine(program[1]["fast.py"], "step_it")
    assert "here.command1(b_, _S.routine_of(b_, 'step'), (), _W_" in body and "BASE_ITEM.step" not in body


def test_several_separate_arguments_reserve_together(program):
    body = routine(program[1]["fast.py"], "fill")
    assert "here.reserve((box, c), where=_W_" in body
    assert "here.leaf_call(box, _M_box.BOX.put, (7,))" in body
    assert "here.call(box, _M_box.BOX.keep, (c,))" in body  # c may pass locks


def test_across_an_integer_interval_is_a_range(program):
    text = routine(program[1]["fast.py"], "make")
    assert "for i in range(1, 3 + 1):" in text and "print_(_B.out_int(here, i))" in text
    assert "for k_ in range(4, 5 + 1):" in text
    assert "for i in _S.cursors(_B.interval(here, 6, 7)):" in text  # `i` itself is used


def test_a_program_with_its_own_expanded_class_has_no_leaves(tmp_path):
    folder = tmp_path / "exp"
    folder.mkdir()
    (folder / "point.e").write_text("expanded class POINT\nfeature\n\tx: INTEGER\nend\n")
    (folder / "exp.e").write_text(
        "class EXP\ncreate\n\tmake\nfeature\n\tmake do set (3) end\n"
        "\tn: INTEGER\n\tp: POINT\n\tset (v: INTEGER) do n := v end\nend\n"
    )
    compiled, texts = compile_program(folder, tmp_path / "out", "none")
    assert "@_rt.leaf" not in texts["exp.py"]


def test_a_class_named_like_a_library_class_keeps_the_library_facts(tmp_path):
    """A root named MUTEX shadows the library's MUTEX: the facts of the library (compiled alone)
    are read in the program's names, so `value := value + 1` (INTEGER_32.plus) is still a leaf;
    they were all dropped, and the mutex benchmark ran 2.8 times slower than its runtime-API twin."""
    folder = tmp_path / "mutex"
    folder.mkdir()
    (folder / "counter.e").write_text(COUNTER)
    (folder / "mutex.e").write_text(
        "class MUTEX\ncreate\n\tmake\nfeature\n\tmake\n\t\tlocal\n\t\t\tc: COUNTER\n"
        "\t\tdo\n\t\t\tcreate c.make\n\t\t\tc.increment\n\t\t\tc.add_square (3)\n"
        '\t\t\tprint (c.value.out + "%N")\n\t\tend\nend\n'
    )
    compiled, texts = compile_program(folder, tmp_path / "out", "none")
    assert is_leaf(texts["counter.py"], "increment") and is_leaf(texts["counter.py"], "add_square")
    assert run_program(compiled, Config()).out == "10\n"


# --- library leaves: the transport listeners' routines a program may run as leaves -----------------
LISTENING_ROOT = """class LISTENING
create
	make
feature
	make
		local
			odometry: separate ODOMETRY_SIGNALER
			range: separate RANGE_SIGNALER
		do
			create odometry.make_unconnected
			create range.make_unconnected
		end
end
"""

# An heir that makes the library's `note_reading' call another processor: in that program no
# signaler's `on_odometry' is a leaf any more (`on_odometry' calls `note_reading').
NOISY_HEIR = """class NOISY_ODOMETRY
inherit
	ODOMETRY_SIGNALER
		redefine note_reading end
create
	make_unconnected
feature
	log: detachable separate COUNTER
	note_reading
		do
			Precursor
			if attached log as l then tell (l) end
		end
	tell (l: separate COUNTER) do l.increment end
end
"""


def _library_leaves(tmp_path, sources):
    import json

    folder = tmp_path / "listening"
    folder.mkdir()
    for name, text in sources.items():
        (folder / name).write_text(text)
    compiled, _ = compile_program(folder, tmp_path / "out")
    return json.loads((compiled.folder / compiled.package / "_library_leaves.json").read_text())


def test_listener_callbacks_of_the_library_are_listed_as_leaves(tmp_path):
    leaves = _library_leaves(tmp_path, {"listening.e": LISTENING_ROOT})
    assert {"ODOMETRY_SIGNALER.on_odometry", "RANGE_SIGNALER.on_range"} <= set(leaves)
    assert "LASER_SIGNALER.on_scan" not in leaves  # it loops over the beams
    assert all(name.split(".")[0].endswith(("SIGNALER", "LISTENER")) for name in leaves)


def test_a_programs_heir_can_take_a_library_callback_out_of_the_leaves(tmp_path):
    leaves = _library_leaves(
        tmp_path, {"listening.e": LISTENING_ROOT, "noisy_odometry.e": NOISY_HEIR, "counter.e": COUNTER}
    )
    assert "ODOMETRY_SIGNALER.on_odometry" not in leaves
    assert "RANGE_SIGNALER.on_range" in leaves


def test_is_leaf_routine_reads_the_mark_and_the_programs_list(monkeypatch):
    from scoopc.kernel import link

    monkeypatch.setattr(link, "_LIBRARY_LEAVES", {"LIB_SIGNALER.on_data"})

    class LIB_SIGNALER:
        def on_data(self):
            pass

        def on_other(self):
            pass

    class MINE(LIB_SIGNALER):
        def on_other(self):
            pass

        on_other._scoop_leaf_ = True

    class REDEFINED(LIB_SIGNALER):
        def on_data(self):  # a program's version without the mark
            pass

    assert link.is_leaf_routine(MINE, "on_data")  # inherited library leaf
    assert link.is_leaf_routine(MINE, "on_other")  # the program's own mark
    assert not link.is_leaf_routine(LIB_SIGNALER, "on_other")
    assert not link.is_leaf_routine(REDEFINED, "on_data")
    assert not link.is_leaf_routine(MINE, "missing")


def test_each_program_loaded_replaces_the_list_of_library_leaves(tmp_path, monkeypatch):
    import json
    import types

    from scoopc.kernel import link

    monkeypatch.setattr(link, "_LIBRARY_LEAVES", set())
    for name, leaves in (("first", ["A.f", "B.g"]), ("second", ["B.g"]), ("third", None)):
        folder = tmp_path / name
        folder.mkdir()
        if leaves is not None:
            (folder / link.LIBRARY_LEAVES_FILE).write_text(json.dumps(leaves))
        module = types.ModuleType(name)
        module.__file__ = str(folder / "__init__.py")
        monkeypatch.setitem(sys.modules, name, module)
        link._read_library_leaves(name)
        assert link._LIBRARY_LEAVES == set(leaves or ())
