"""Pre-ECMA syntax is named with its modern spelling (SYNTAX-OBSOLETE), at the right place."""

import pytest

from scoopc.parse import parser
from scoopc.source import SourceFile

CASES = [
    ('indexing\n\tdescription: "x"\nclass X end\n', (1, 1), "`indexing` is the obsolete spelling of `note`"),
    ("class X\ncreation\n\tmake\nfeature\n\tmake do end\nend\n", (2, 1), "`creation`"),
    ("class X\nfeature\n\tf is do end\nend\n", (3, 4), "`is` before a routine body"),
    ("class X\nfeature\n\tc: INTEGER is 5\nend\n", (3, 13), "`is` before a routine body"),
    ('class X\nfeature\n\tinfix "+" (o: X): X do end\nend\n', (3, 8), '`infix "op"`'),
    ('class X\nfeature\n\tprefix "-": X do end\nend\n', (3, 9), '`prefix "op"`'),
    ("class X\nfeature\n\tx: ?STRING\nend\n", (3, 5), "`?T` is the obsolete spelling of `detachable T`"),
    (
        "class X\nfeature\n\tf (a: ANY) do if {s: STRING} a then end end\nend\n",
        (3, 21),
        "`{x: T} e` is the obsolete form of an object test",
    ),
]


@pytest.mark.parametrize("text, position, message", CASES, ids=[c[2][:30] for c in CASES])
def test_obsolete_syntax_is_named(text, position, message):
    (d,) = parser.parse(SourceFile("old.e", text)).diagnostics
    assert (d.code, (d.span.line, d.span.column)) == ("SYNTAX-OBSOLETE", position)
    assert message in d.message and d.hint


def test_is_as_a_name_is_a_reserved_word_not_obsolete_syntax():
    (d,) = parser.parse(SourceFile("n.e", "class X\nfeature\n\tis: INTEGER\nend\n")).diagnostics
    assert d.code == "SYNTAX-RESERVED"
