"""A query whose body sets `Result` first, also inside a leading `check ... then` (whose failure
raises before anything could read it), starts without computing `Result`'s default value; one whose
check reads `Result` keeps it. The default of a formal generic costs a type lookup per call."""

import ast
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "golden"))
from golden_support import Config, compile_program, run_program  # noqa: E402

BOX = """class
	BOX [G]

create
	put

feature

	value: detachable G

	put (v: G)
		do
			value := v
		end

	item: G
			-- Set first inside a check: no default value needed.
		do
			check attached value as v then
				Result := v
			end
		end

	guarded: G
			-- The check reads Result: it must hold its default value.
		do
			check Result = Result and attached value as v then
				Result := v
			end
		end

end
"""

BOX_MAIN = """class
	BOX_MAIN

create
	make

feature

	make
		local
			b: BOX [INTEGER]
		do
			create b.put (5)
			print (b.item.out + " " + b.guarded.out + "%N")
		end

end
"""


def _function(tree: ast.Module, name: str) -> str:
    for node in ast.walk(tree):
        if isinstance(node, ast.FunctionDef) and node.name == name:
            return ast.unparse(node)
    raise AssertionError(f"no function {name}")


def test_a_result_set_first_inside_a_check_needs_no_default(tmp_path):
    source = tmp_path / "box_main"
    source.mkdir()
    (source / "box.e").write_text(BOX)
    (source / "box_main.e").write_text(BOX_MAIN)
    compiled, texts = compile_program(source, tmp_path / "out")
    tree = ast.parse(texts["box.py"])
    assert "default" not in _function(tree, "item")
    assert "default" in _function(tree, "guarded")
    assert run_program(compiled, Config()).out == "5 5\n"
