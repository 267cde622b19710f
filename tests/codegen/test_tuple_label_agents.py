"""Agents on TUPLE labels: `agent t.x` reads item x of t when called (the item as it is then), and
`agent {TUPLE [x: INTEGER; name: STRING]}.name` takes the tuple as its open target. The code
generator stopped on both with an internal error."""

import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "golden"))
from golden_support import Config, compile_program, run_program  # noqa: E402

LABELS = """class
	LABELS

create
	make

feature

	make
		local
			t: TUPLE [x: INTEGER; name: STRING]
			f: FUNCTION [INTEGER]
			g: FUNCTION [TUPLE [TUPLE [x: INTEGER; name: STRING]], STRING]
		do
			t := [3, "abc"]
			f := agent t.x
			print (f.item ([]).out + "%N")
			t.x := 7
			print (f.item ([]).out + "%N")
			g := agent {TUPLE [x: INTEGER; name: STRING]}.name
			print (g.item ([t]) + " " + g.item ([[1, "other"]]) + "%N")
		end

end
"""


def test_agents_on_tuple_labels_compile_and_read_the_item_when_called(tmp_path):
    source = tmp_path / "labels"
    source.mkdir()
    (source / "labels.e").write_text(LABELS)
    compiled, _ = compile_program(source, tmp_path / "out")
    outcome = run_program(compiled, Config())
    assert (outcome.status, outcome.out) == (0, "3\n7\nabc other\n"), outcome.err
