"""ARRAY's accessors `item` (`at`, `[]`) and `put`: `external "Python"` bodies
(scoopc/kernel/ext/array.py) that must behave exactly as the Eiffel bodies they stand for, for an
ARRAY and for a descendant that redefines `valid_index`; and the leaf facts that count such a
redefinition (scoopc/codegen/scoop.py, CALLING_EXTERNALS)."""

from __future__ import annotations

import re
import sys
from pathlib import Path

import pytest

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "golden"))
from golden_support import Config, compile_program, run_program  # noqa: E402

ROOT = """class ARRAY_ACCESS
inherit
	EXCEPTIONS
create
	make
feature
	make
		local
			a: ARRAY [INTEGER]
			p: PICKY_ARRAY
			words: ARRAY [STRING]
		do
			create a.make_filled (0, -2, 2)
			a [-2] := 5
			a.put (7, 2)
			print (a [-2].out + " " + a.item (2).out + " " + a.at (0).out + " " + a.count.out + "%N")
			read (a, 3)
			read (a, -3)
			write (a, 3)
			create p.make_filled (1, 1, 3)
			p [3] := 4
			print (p [1].out + " " + p [3].out + "%N")
			read (p, 2)
			write (p, 2)
			read (p, 4)
			words := <<"a", "b">>
			words [2] := "c"
			print (words [1] + words [2] + "%N")
		end

	read (a: ARRAY [INTEGER]; i: INTEGER)
		do
			access (a, i, False)
		end

	write (a: ARRAY [INTEGER]; i: INTEGER)
		do
			access (a, i, True)
		end

	access (a: ARRAY [INTEGER]; i: INTEGER; writing: BOOLEAN)
			-- Read `a [i]', or write 9 there and read it back; print it, or the failure's tag.
		local
			failed: BOOLEAN
			what: STRING
		do
			what := "read "
			if writing then
				what := "write "
			end
			if failed then
				print (what + i.out + ": " + tag_name_of_last + "%N")
			else
				if writing then
					a [i] := 9
				end
				print (what + i.out + ": " + a [i].out + "%N")
			end
		rescue
			failed := True
			retry
		end

	tag_name_of_last: STRING
		do
			Result := "?"
			if attached tag_name as t then
				Result := t
			end
			if assertion_violation then
				Result := Result + " (assertion)"
			end
		end
end
"""

PICKY = """class PICKY_ARRAY
inherit
	ARRAY [INTEGER]
		redefine
			valid_index
		end
create
	make_filled
feature
	valid_index (i: INTEGER): BOOLEAN
			-- Every index of the array but 2.
		do
			Result := i /= 2 and Precursor (i)
		end
end
"""

LOOPING = """class PICKY_ARRAY
inherit
	ARRAY [INTEGER]
		redefine
			valid_index
		end
create
	make_filled
feature
	valid_index (i: INTEGER): BOOLEAN
			-- Every index of the array but 2, found by a loop.
		do
			Result := Precursor (i)
			across 2 |..| 2 as k loop
				if k.item = i then
					Result := False
				end
			end
		end
end
"""

HOLDER = """class HOLDER
create
	make
feature
	make do create cells.make_filled (0, 1, 3) end
	cells: ARRAY [INTEGER]
	cell (i: INTEGER): INTEGER do Result := cells [i] end
	set_cell (i, v: INTEGER) do cells [i] := v end
end
"""


def _program(tmp_path: Path, picky: str):
    folder = tmp_path / "array_access"
    folder.mkdir()
    (folder / "array_access.e").write_text(ROOT)
    (folder / "picky_array.e").write_text(picky)
    (folder / "holder.e").write_text(HOLDER)
    return compile_program(folder, tmp_path / "out", "all")


def _routine(text: str, name: str) -> str:
    match = re.search(rf"((?:    @[\w.]+\n)*)    def {name}\(.*?(?=\n    (?:@|def |\w+ = )|\n_S\.register)", text, re.S)
    assert match, f"no routine {name}"
    return match.group(0)


EXPECTED = [
    "5 7 0 5",
    "read 3: valid_key (assertion)",
    "read -3: valid_key (assertion)",
    "write 3: valid_key (assertion)",
    "1 4",
    "read 2: valid_key (assertion)",
    "write 2: valid_key (assertion)",
    "read 4: valid_key (assertion)",
    "ac",
]


@pytest.mark.parametrize("picky", [PICKY, LOOPING], ids=["redefined", "redefined_with_a_loop"])
def test_accessors_behave_as_their_eiffel_bodies(tmp_path, picky):
    compiled, _ = _program(tmp_path, picky)
    outcome = run_program(compiled, Config())
    assert outcome.status == 0, outcome.err
    assert outcome.out.splitlines() == EXPECTED


def test_array_accessors_are_leaves_unless_an_heir_makes_valid_index_one_no_longer(tmp_path):
    for picky, leaves in ((PICKY, True), (LOOPING, False)):
        folder = tmp_path / str(leaves)
        folder.mkdir()
        holder = _program(folder, picky)[1]["holder.py"]
        for name in ("cell", "set_cell"):
            assert ("@_rt.leaf" in _routine(holder, name)) is leaves, (name, leaves)
