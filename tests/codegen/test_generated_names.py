"""The generated module's own names (its imports, constants, externals' modules) start with an
underscore, which no Eiffel identifier can: user classes named like them (S, B, T, KS, P, W_3,
PRE_5, ...) and locals named `rt` or `here` work. A class name of 300 characters gets a bounded
module file name."""

import io

import scoopc

NAMES = [
    "S",
    "B",
    "T",
    "KS",
    "P",
    "AGENT_1",
    "M_T",
    "L_ANY",
    "W_1",
    "W_3",
    "W_4",
    "G_1",
    "PRE_4",
    "PRE_5",
    "X_CONSOLE",
    "EIFFEL_BASE",
]

ROOT = """class
	NAMES_MAIN

create
	make

feature

	make
		local
			rt, here: INTEGER
{locals}
		do
{creations}
			print ({sum})
			print ("%N")
			create buffer.make (9)
			show (buffer)
			rt := 2147483647
			here := rt + 1
			print (here)
			print ("%N")
		end

	buffer: separate W_1

	show (a: separate W_1)
		require
			positive: a.v > 0
		do
			print (a.v)
			print ("%N")
		end

end
"""


def leaf_class(name, value="a + 1"):
    return (
        f"class\n\t{name}\n\ncreate\n\tmake\n\nfeature\n\n\tv: INTEGER\n\n"
        f"\tmake (a: INTEGER)\n\t\tdo\n\t\t\tv := {value}\n\t\tend\n\nend\n"
    )


def run(folder, root):
    out, err = io.StringIO(), io.StringIO()
    result = scoopc.run([str(folder)], root=root, stdout=out, stderr=err)
    return result.status, out.getvalue(), err.getvalue()


def test_user_classes_named_like_the_generated_modules_own_names(tmp_path):
    for name in NAMES:
        (tmp_path / f"{name.lower()}.e").write_text(leaf_class(name))
    local = [f"\t\t\tx{i}: {name}" for i, name in enumerate(NAMES)]
    creations = [f"\t\t\tcreate x{i}.make ({i})" for i in range(len(NAMES))]
    total = " + ".join(f"x{i}.v" for i in range(len(NAMES)))
    text = ROOT.format(locals="\n".join(local), creations="\n".join(creations), sum=total)
    (tmp_path / "names_main.e").write_text(text)
    status, out, err = run(tmp_path, "NAMES_MAIN")
    expected = sum(i + 1 for i in range(len(NAMES)))
    assert (status, out.split()) == (0, [str(expected), "10", "-2147483648"]), err


def test_a_class_name_of_300_characters(tmp_path):
    long_name = "LONG_" + "X" * 295
    (tmp_path / "long.e").write_text(leaf_class(long_name, "7"))
    (tmp_path / "root_long.e").write_text(
        "class\n\tROOT_LONG\n\ncreate\n\tmake\n\nfeature\n\n\tmake\n\t\tlocal\n"
        f"\t\t\tx: {long_name}\n\t\tdo\n\t\t\tcreate x.make (0)\n\t\t\tprint (x.v)\n\t\tend\n\nend\n"
    )
    status, out, err = run(tmp_path, "ROOT_LONG")
    assert (status, out) == (0, "7"), err
