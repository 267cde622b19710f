"""Class layouts: a class whose parents Python cannot linearise in the order written (`inherit ANY;
ARGUMENTS`, where one parent is another's ancestor) still derives from the parent that brings the
features, so the bindings its body makes name a class the module has imported."""

import io

import scoopc
from scoopc.exits import Exit

APPLICATION = """class
	APPLICATION

inherit
	ANY

	ARGUMENTS

create
	make

feature

	make
		do
			print (argument_count.out + " " + (Current).generating_type.name + "%N")
		end

end
"""


def test_a_parent_that_is_another_parents_ancestor_is_dropped_from_the_python_bases(tmp_path):
    (tmp_path / "application.e").write_text(APPLICATION)
    out = io.StringIO()
    result = scoopc.run([str(tmp_path)], stdout=out)
    assert result.status == Exit.OK, [str(d) for d in result.diagnostics]
    assert out.getvalue() == "0 APPLICATION\n"
