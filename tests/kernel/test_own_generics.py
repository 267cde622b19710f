"""A generic class creating an object whose actual generics are its own, in order (LINKABLE [G]
in LINKED_QUEUE [G]): codegen shares Current's `_gen_` for an object of that very class, and asks
kernel.types.own_generics for an heir's (scoopc/codegen/calls.py, generics_desc)."""

from __future__ import annotations

import sys
from pathlib import Path

from scoopc.kernel import types

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "golden"))
from golden_support import Config, compile_program, run_program  # noqa: E402


class Pair:
    _key_ = "PAIR"


class Swapped(Pair):
    """An heir that passes its generics to PAIR the other way round (SWAPPED [A, B] inherits PAIR [B, A])."""

    _key_ = "SWAPPED"
    _ancestor_gen_ = {"PAIR": lambda g: (g[1], g[0])}


def test_own_generics_of_the_class_itself_and_of_an_heir():
    pair = Pair()
    pair._gen_ = ("A", "B")
    assert types.own_generics(pair, "PAIR") is pair._gen_
    swapped = Swapped()
    swapped._gen_ = ("A", "B")
    assert types.own_generics(swapped, "PAIR") == ("B", "A")
    assert types.own_generics(swapped, "PAIR") == tuple(types.formal(swapped, "PAIR", i) for i in range(2))


SOURCES = {
    "pair.e": """class PAIR [A, B]
create
	make
feature
	make do end
	copied: PAIR [A, B]
		do
			create Result.make
		end
end
""",
    "swapped.e": """class SWAPPED [X, Y]
inherit
	PAIR [Y, X]
create
	make
end
""",
    "own_generics.e": """class OWN_GENERICS
create
	make
feature
	make
		local
			p: PAIR [INTEGER, STRING]
			s: SWAPPED [INTEGER, STRING]
		do
			create p.make
			create s.make
			print (p.copied.generating_type.out + "%N")
			print (s.copied.generating_type.out + "%N")
		end
end
""",
}


def test_a_created_object_gets_the_generics_its_class_sees(tmp_path):
    folder = tmp_path / "own_generics"
    folder.mkdir()
    for name, text in SOURCES.items():
        (folder / name).write_text(text)
    compiled, texts = compile_program(folder, tmp_path / "out", "all")
    assert "self._gen_ if type(self) is PAIR else _T.own_generics(self, 'PAIR')" in texts["pair.py"]
    outcome = run_program(compiled, Config())
    assert outcome.status == 0, outcome.err
    assert outcome.out.splitlines() == ["PAIR [INTEGER_32, STRING_8]", "PAIR [STRING_8, INTEGER_32]"]
