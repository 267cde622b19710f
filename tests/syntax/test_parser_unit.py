"""Unit tests of the parser: precedence, literals, names, reserved words, syntax errors with
their exact positions, the AST dump, and the optional lark-cython accelerator."""

from __future__ import annotations

import pytest

from scoopc import diagnostics, syntax as s
from scoopc.parse import parser
from scoopc.source import SourceFile


def parse_text(text: str) -> parser.ParseResult:
    return parser.parse(SourceFile("t.e", text))


def parse_class(text: str) -> s.ClassDeclaration:
    result = parse_text(text)
    assert not result.diagnostics, [diagnostics.short(d) for d in result.diagnostics]
    return result.tree


def routine_body(body: str, declarations: str = "") -> tuple:
    tree = parse_class(f"class A\nfeature\n\tf{declarations}\n\t\tdo\n{body}\n\t\tend\nend\n")
    return tree.feature_clauses[0].features[0].body.body.instructions


def expression(text: str) -> s.Expression:
    (instruction,) = routine_body(f"x := {text}")
    return instruction.source


def show(e: s.Expression) -> str:
    """A compact prefix form of an expression, for precedence tests."""
    if isinstance(e, s.BinaryExpression):
        return f"({e.operator} {show(e.left)} {show(e.right)})"
    if isinstance(e, s.UnaryExpression):
        return f"({e.operator} {show(e.operand)})"
    if isinstance(e, s.Old):
        return f"(old {show(e.expression)})"
    if isinstance(e, s.UnqualifiedCall):
        return e.name.text + (f"({', '.join(map(show, e.arguments))})" if e.arguments else "")
    if isinstance(e, s.QualifiedCall):
        return f"{show(e.target)}.{e.name.text}"
    if isinstance(e, s.BracketExpression):
        return f"{show(e.target)}[{', '.join(map(show, e.arguments))}]"
    if isinstance(e, s.Parenthesized):
        return show(e.expression)
    if isinstance(e, (s.ManifestInteger, s.ManifestReal)):
        return e.text
    if isinstance(e, s.ObjectTest):
        return f"(attached {show(e.expression)})"
    return type(e).__name__


# ---- precedence and associativity -----------------------------------------------------------
@pytest.mark.parametrize(
    "text, tree",
    [
        ("a + b * c", "(+ a (* b c))"),
        ("a * b + c", "(+ (* a b) c)"),
        ("a - b - c", "(- (- a b) c)"),
        ("a ^ b ^ c", "(^ a (^ b c))"),
        ("a * b ^ c", "(* a (^ b c))"),
        ("-a ^ b", "(^ (- a) b)"),
        ("a // b \\\\ c", "(\\\\ (// a b) c)"),
        ("a / b * c", "(* (/ a b) c)"),
        ("not a and b", "(and (not a) b)"),
        ("a and b or c and d", "(or (and a b) (and c d))"),
        ("a or b xor c", "(xor (or a b) c)"),
        ("a and then b or else c", "(or else (and then a b) c)"),
        ("a implies b implies c", "(implies (implies a b) c)"),
        ("a or b implies c", "(implies (or a b) c)"),
        ("a = b and c /= d", "(and (= a b) (/= c d))"),
        ("a ~ b or a /~ c", "(or (~ a b) (/~ a c))"),
        ("a < b = (c >= d)", "(= (< a b) (>= c d))"),
        ("a |..| b + 1", "(|..| a (+ b 1))"),
        ("a + 1 < b |..| c", "(< (+ a 1) (|..| b c))"),
        ("a |>> 2 ^ 3", "(^ (|>> a 2) 3)"),
        ("a * b @ c", "(* a (@ b c))"),
        ("old a.b + 1", "(+ (old a.b) 1)"),
        ("not a.b [i]", "(not a.b[i])"),
        ("- - a", "(- (- a))"),
        ("a & b /= 0", "(/= (& a b) 0)"),
        ("attached a and b", "(and (attached a) b)"),
    ],
)
def test_operator_precedence_and_associativity(text, tree):
    assert show(expression(text)) == tree


def test_and_then_spans_both_words():
    e = expression("a and  then b")
    assert e.operator == "and then"
    assert (e.operator_span.column, e.operator_span.end_column) == (8, 17)


# ---- literals -------------------------------------------------------------------------------
@pytest.mark.parametrize(
    "text, value",
    [
        ("1_000_000", 1000000),
        ("0xFF", 255),
        ("0x7FFF_FFFF", 0x7FFFFFFF),
        ("0c17", 15),
        ("0b1010", 10),
        ("0", 0),
    ],
)
def test_integer_literals(text, value):
    e = expression(text)
    assert isinstance(e, s.ManifestInteger) and e.value == value and e.text == text


@pytest.mark.parametrize(
    "text, value",
    [
        ("1.5", 1.5),
        ("1.", 1.0),
        (".5", 0.5),
        ("1.5e10", 1.5e10),
        ("2.5E-3", 2.5e-3),
        ("1_000.25", 1000.25),
    ],
)
def test_real_literals(text, value):
    e = expression(text)
    assert isinstance(e, s.ManifestReal) and e.value == value


def test_interval_of_integers_is_not_a_real():
    (instruction,) = routine_body("inspect x when 1..5 then end")
    choice = instruction.when_parts[0].choices[0]
    assert (choice.lower.value, choice.upper.value) == (1, 5)


@pytest.mark.parametrize(
    "text, value",
    [
        ('"abc"', "abc"),
        ('"a%Nb%Tc"', "a\nb\tc"),
        ('"say %"hi%""', 'say "hi"'),
        ('"100%%"', "100%"),
        ('"%/65/%/0x42/"', "AB"),
        ('""', ""),
        ('"%(x%)"', "[x]"),
        ('"one %\n\t\t%two"', "one two"),
    ],
)
def test_string_escapes(text, value):
    e = expression(text)
    assert isinstance(e, s.ManifestString) and e.value == value and not e.verbatim


def test_aligned_verbatim_string_loses_common_indentation():
    e = expression('"[\n\t\t\tline one\n\t\t\t  indented\n\t\t]"')
    assert e.verbatim and e.value == "line one\n  indented"


def test_free_verbatim_string_keeps_indentation():
    e = expression('"{\n\tkept\n}"')
    assert e.value == "\tkept"


def test_verbatim_strings_do_not_interpret_percent():
    assert expression('"[\n100%N\n]"').value == "100%N"


@pytest.mark.parametrize("text, value", [("'a'", "a"), ("'%N'", "\n"), ("'%''", "'"), ("'%/65/'", "A"), ("'%%'", "%")])
def test_character_literals(text, value):
    e = expression(text)
    assert isinstance(e, s.ManifestCharacter) and e.value == value


def test_once_string():
    e = expression('once "shared"')
    assert isinstance(e, s.ManifestString) and e.once and e.value == "shared"


def test_typed_constants():
    e = expression("{INTEGER_64} -5")
    assert isinstance(e, s.TypedConstant) and e.type.name.text == "INTEGER_64"
    assert e.constant.value == -5 and e.constant.text == "-5"


# ---- names and keywords -----------------------------------------------------------------------
def test_keywords_are_case_insensitive_and_names_keep_their_spelling():
    tree = parse_class("CLASS Account\nFeature\n\tBalance: INTEGER\n\tF DO IF X THEN END END\nEND\n")
    assert tree.name.text == "Account" and tree.name.key == "account"
    attribute, routine = tree.feature_clauses[0].features
    assert attribute.names[0].name.text == "Balance" and attribute.names[0].name.key == "balance"
    assert isinstance(routine.body.body.instructions[0], s.Conditional)


def test_current_result_void_in_any_case():
    (instruction,) = routine_body("RESULT := current = VOID")
    assert isinstance(instruction.target, s.Result)
    assert isinstance(instruction.source.left, s.Current) and isinstance(instruction.source.right, s.Void)


@pytest.mark.parametrize(
    "text, word, line, column",
    [
        ("class A\nfeature\n\tloop: INTEGER\nend\n", "loop", 3, 2),
        ("class A\nfeature\n\tf (a, END: INTEGER) do end\nend\n", "END", 3, 8),
        ("class A\nfeature\n\tf\n\t\tlocal\n\t\t\tseparate: BOOLEAN\n\t\tdo\n\t\tend\nend\n", "separate", 5, 4),
        ("class A\nfeature\n\tf do x := y.then end\nend\n", "then", 3, 14),
        ("class A\nfeature\n\tf do Old := 3 end\nend\n", "Old", 3, 7),
    ],
)
def test_reserved_word_used_as_a_name(text, word, line, column):
    (d,) = parse_text(text).diagnostics
    assert d.code == "SYNTAX-RESERVED"
    assert (d.span.line, d.span.column) == (line, column)
    assert d.message == f"`{word}` is a reserved word and cannot be used as a name"


# ---- syntax errors ----------------------------------------------------------------------------
def only_error(text: str) -> str:
    result = parse_text(text)
    assert result.tree is None
    (d,) = result.diagnostics
    return diagnostics.short(d)


def test_missing_end_of_if_names_the_if():
    text = "class A\nfeature\n\tf\n\t\tdo\n\t\t\tif x then\n\t\t\t\ty := 1\n\t\tend\n\nfeature\nend\n"
    assert (
        only_error(text) == "t.e:5:4: error SYNTAX-END: missing `end` of the `if` opened at 5:4\n"
        "    t.e:7:3: note: the `end` was due before line 7"
    )


def test_missing_end_of_loop_names_the_from():
    text = (
        "class A\nfeature\n\tf\n\t\tdo\n\t\t\tfrom i := 1 until i > 3 loop\n\t\t\t\ti := i + 1\n\t\tend\nfeature\nend\n"
    )
    assert (
        only_error(text) == "t.e:5:4: error SYNTAX-END: missing `end` of the `from` opened at 5:4\n"
        "    t.e:7:3: note: the `end` was due before line 7"
    )


def test_missing_end_of_routine():
    text = "class A\nfeature\n\tf\n\t\tdo\n\t\t\tg\nfeature\nend\n"
    assert (
        only_error(text) == "t.e:4:3: error SYNTAX-END: missing `end` of the `do` of `f` opened at 4:3\n"
        "    t.e:6:1: note: the `end` was due before line 6"
    )


def test_missing_end_of_class_at_end_of_file():
    text = "class A\nfeature\n\tf do end\n"
    assert (
        only_error(text) == "t.e:1:1: error SYNTAX-END: missing `end` of the `class` opened at 1:1\n"
        "    t.e:3:1: note: the `end` was due before the end of the file"
    )


def test_missing_end_found_by_indentation_when_an_inner_construct_took_it():
    text = "class A\nfeature\n\tf\n\t\tdo\n\t\t\tif x then\n\t\t\t\tg\n\t\tend\n\nend\n"
    assert (
        only_error(text) == "t.e:5:4: error SYNTAX-END: missing `end` of the `if` opened at 5:4\n"
        "    t.e:7:3: note: the `end` was due before line 7"
    )


def test_missing_end_of_redefine():
    text = "class A\ninherit\n\tB\n\t\tredefine f\ncreate\n\tmake\nend\n"
    assert (
        only_error(text) == "t.e:4:3: error SYNTAX-END: missing `end` of the `redefine` opened at 4:3\n"
        "    t.e:5:1: note: the `end` was due before line 5"
    )


def test_missing_end_of_separate_block():
    text = "class A\nfeature\n\tf do\n\t\tseparate a as b do\n\t\t\tb.g\n\tend\nfeature\nend\n"
    assert (
        only_error(text) == "t.e:4:3: error SYNTAX-END: missing `end` of the `separate` opened at 4:3\n"
        "    t.e:6:2: note: the `end` was due before line 6"
    )


def test_missing_then_says_what_was_expected():
    text = "class A\nfeature\n\tf do\n\t\tif x > 0\n\t\t\tprint (x)\n\t\tend\n\tend\nend\n"
    assert only_error(text) == (
        "t.e:5:4: error SYNTAX: the name `print` is not allowed here; expected `then` or an operator"
    )


def test_missing_expression():
    text = "class A\nfeature\n\tf do x := end\nend\n"
    assert only_error(text) == "t.e:3:12: error SYNTAX: `end` is not allowed here; expected an expression"


def test_missing_type_after_colon():
    text = "class A\nfeature\n\tx: \nend\n"
    assert only_error(text).startswith("t.e:4:1: error SYNTAX: `end` is not allowed here; expected ")


def test_feature_without_type_or_body():
    text = "class A\nfeature\n\tcount INTEGER\nend\n"
    assert only_error(text).startswith(
        "t.e:3:8: error SYNTAX: the name `INTEGER` is not allowed here; expected `(`, `,`, `:`"
    )


def test_unterminated_string_at_its_quote():
    text = 'class A\nfeature\n\tf do print ("abc) end\nend\n'
    assert only_error(text).startswith("t.e:3:14: error SYNTAX-LEXICAL: unterminated string")


def test_bad_character_at_its_position():
    text = "class A\nfeature\n\tf do x := 6 \u00e9 7 end\nend\n"
    assert only_error(text) == "t.e:3:14: error SYNTAX-LEXICAL: `\u00e9` (U+00E9) is not part of any Eiffel token"


def test_bad_escape_points_at_the_percent():
    result = parse_text('class A\nfeature\n\tf do print ("ab%kc") end\nend\n')
    (d,) = result.diagnostics
    assert diagnostics.short(d) == (
        "t.e:3:17: error SYNTAX-LEXICAL: `%k` is not a special character code (use `%%` for a percent sign)"
    )
    assert (d.span.end_column - d.span.column) == 2


def test_bad_escape_on_a_continued_line():
    result = parse_text('class A\nfeature\n\tf do print ("ab%\n\t\t%c%k") end\nend\n')
    (d,) = result.diagnostics
    assert (d.span.line, d.span.column) == (4, 5)


def test_open_operand_outside_an_agent():
    (d,) = parse_text("class A\nfeature\n\tf do x := g (?) end\nend\n").diagnostics
    assert d.code == "SYNTAX" and (d.span.line, d.span.column) == (3, 15)


def test_two_classes_in_one_file():
    (d,) = parse_text("class A end\n\nclass B end\n").diagnostics
    assert diagnostics.short(d) == ("t.e:3:1: error SYNTAX-CLASS: class `B` is a second class in this file (after `A`)")


def test_empty_file():
    result = parse_text("-- nothing here\n")
    assert result.tree is None
    assert [d.code for d in result.diagnostics] == ["SYNTAX-CLASS"]


@pytest.mark.parametrize(
    "text",
    [
        "",
        "end",
        "class",
        "class A feature f do",
        "))))",
        '"',
        "class A feature f do x := ((((((((( end end",
        "\x00\x01",
        "class A feature f do across end end",
        "note\n",
        "%%%",
    ],
)
def test_garbage_gives_diagnostics_not_exceptions(text):
    result = parse_text(text)
    assert result.diagnostics and all(d.span is not None for d in result.diagnostics)


# ---- tree shape -------------------------------------------------------------------------------
def test_assignment_forms():
    a, b, c, d = routine_body("x := 1\nResult := 2\na [i] := 3\na.item (i) := 4")
    assert isinstance(a, s.Assignment) and isinstance(b, s.Assignment)
    assert isinstance(c, s.AssignerCall) and isinstance(c.target, s.BracketExpression)
    assert isinstance(d, s.AssignerCall) and isinstance(d.target, s.QualifiedCall)


def test_creation_forms():
    a, b, c = routine_body("create x\ncreate {B} x.make (1)\ncreate <NONE> x.make")
    assert a.type is None and a.procedure is None
    assert b.type.name.text == "B" and b.procedure.text == "make" and len(b.arguments) == 1
    assert c.processor.text == "NONE"
    e = expression("(create {B}.make).f")
    assert isinstance(e.target.expression, s.CreationExpression)


def test_agents():
    plain, open_target, inline = (
        expression(t)
        for t in ("agent f (?, 1)", "agent {STRING}.count", "agent (i: INTEGER): BOOLEAN do Result := i > 0 end")
    )
    assert plain.target is None and isinstance(plain.arguments[0], s.OpenOperand)
    assert isinstance(open_target.target, s.ManifestType) and open_target.arguments is None
    assert isinstance(inline, s.InlineAgent) and inline.arguments[0].name.text == "i"


def test_object_tests():
    e = expression("attached {STRING} y as z and then z.count > 0")
    test = e.left
    assert isinstance(test, s.ObjectTest) and test.type.name.text == "STRING" and test.local.text == "z"


def test_types_with_marks_anchors_and_tuples():
    tree = parse_class(
        "class A\nfeature\n\ta: detachable separate LIST [like Current]\n"
        "\tb: TUPLE [x, y: INTEGER; name: STRING]\n\tc: like a.item\nend\n"
    )
    a, b, c = (f.type for f in tree.feature_clauses[0].features)
    assert a.attachment == "detachable" and a.separate and isinstance(a.generics[0], s.AnchoredType)
    assert [label.text for label in b.labels] == ["x", "y", "name"]
    assert [t.name.text for t in b.generics] == ["INTEGER", "INTEGER", "STRING"]
    assert isinstance(c.anchor, s.QualifiedCall)


def test_trailing_class_note_after_an_attribute_belongs_to_the_class():
    tree = parse_class('class A\nfeature\n\tx: INTEGER\nnote\n\tauthor: "me"\nend\n')
    assert [n.tag.text for n in tree.notes] == ["author"]
    assert tree.feature_clauses[0].features[0].notes == ()


def test_spans_cover_constructs():
    (conditional,) = routine_body("\t\t\tif a then\n\t\t\t\tb\n\t\t\tend")
    assert (conditional.span.line, conditional.span.column) == (5, 4)
    assert (conditional.span.end_line, conditional.span.end_column) == (7, 7)


def test_dump_is_stable_and_shows_spans():
    tree = parse_class("class A\nfeature\n\tx: INTEGER\nend\n")
    assert s.dump(tree) == (
        "ClassDeclaration @1:1-4:4\n"
        "  name: 'A' @1:7-1:8\n"
        "  feature_clauses:\n"
        "    - FeatureClause @2:1-3:12\n"
        "      features:\n"
        "        - Attribute @3:2-3:12\n"
        "          names:\n"
        "            - FeatureName @3:2-3:3\n"
        "              name: 'x' @3:2-3:3\n"
        "          type: ClassType @3:5-3:12\n"
        "            name: 'INTEGER' @3:5-3:12\n"
    )


# ---- the parser itself ------------------------------------------------------------------------
def test_every_grammar_rule_has_a_builder_method():
    lark_parser, builder = parser._parser()
    missing = set()
    for rule in lark_parser.rules:
        name = rule.alias or rule.origin.name
        name = getattr(name, "value", name)
        inlined = rule.options.expand1 and not rule.alias and len(rule.expansion) == 1
        if not name.startswith("_") and not inlined and not hasattr(builder, name):
            missing.add(name)
    assert not missing


def test_accelerated_and_pure_parsers_agree(monkeypatch):
    pytest.importorskip("lark_cython")
    text = (
        "class A\ninherit B redefine f end\nfeature\n\tf (a: INTEGER): like a\n"
        "\t\trequire a > 0\n\t\tdo Result := a ^ 2 + {B}.c (agent g (?))\n"
        "\t\t\tacross l as c loop print (c.item) end\n\t\tensure Result > 0\n\t\tend\nend\n"
    )
    fast = s.dump(parse_text(text).tree)
    monkeypatch.setenv("SCOOPC_PURE_PARSER", "1")
    builder = parser.AstBuilder()
    pure = parser.make_parser(builder)
    builder.reset("t.e")
    assert s.dump(pure.parse(text)[0]) == fast


# ---- a missing `end` before the next routine (issue 22): the header parsed as a call ------------
def only_diagnostic(text: str):
    result = parse_text(text)
    (d,) = result.diagnostics
    return d


def test_missing_end_of_routine_before_a_routine_with_arguments_names_the_routine():
    text = (
        "class A\nfeature\n\tmake\n\t\tlocal\n\t\t\tn: INTEGER\n\t\tdo\n\t\t\tn := 3\n\t\t\tprint (n)\n\n"
        "\tother (x: INTEGER): INTEGER\n\t\tdo\n\t\t\tResult := x\n\t\tend\nend\n"
    )
    d = only_diagnostic(text)
    assert diagnostics.short(d) == (
        "t.e:6:3: error SYNTAX-END: missing `end` of the `do` of `make` opened at 6:3\n"
        "    t.e:10:2: note: the `end` was due before line 10"
    )
    assert d.hint == "every `do` needs its own `end`: add it before line 10, aligned with the `do`"


def test_missing_end_of_if_before_the_next_routine():
    text = (
        "class A\nfeature\n\tf\n\t\tdo\n\t\t\tif True then\n\t\t\t\tprint (1)\n\t\tend\n\n"
        "\tg (x: INTEGER)\n\t\tdo\n\t\tend\nend\n"
    )
    assert only_error(text).startswith("t.e:5:4: error SYNTAX-END: missing `end` of the `if` opened at 5:4")


def test_missing_end_of_inspect_and_across_and_check():
    inspect = "\t\t\tinspect x\n\t\t\twhen 1 then\n\t\t\t\tprint (1)\n"
    across = "\t\t\tacross 1 |..| 3 as i loop\n\t\t\t\tprint (i.item)\n"
    check = "\t\t\tcheck x > 0 then\n\t\t\t\tprint (x)\n"
    for body, word in ((inspect, "inspect"), (across, "across"), (check, "check")):
        text = f"class A\nfeature\n\tf (x: INTEGER)\n\t\tdo\n{body}\t\tend\n\n\tg (y: INTEGER)\n\t\tdo\n\t\tend\nend\n"
        assert only_error(text).startswith(f"t.e:5:4: error SYNTAX-END: missing `end` of the `{word}` opened at 5:4")


def test_else_if_gets_the_elseif_hint():
    text = (
        "class A\nfeature\n\tf (x: INTEGER)\n\t\tdo\n\t\t\tif x > 0 then\n\t\t\t\tprint (1)\n"
        "\t\t\telse if x < 0 then\n\t\t\t\tprint (2)\n\t\t\tend\n\t\tend\n\n\tg\n\t\tdo\n\t\tend\nend\n"
    )
    d = only_diagnostic(text)
    assert d.code == "SYNTAX-END" and "write `elseif`" in d.hint
