"""The checker's recorded tables and its finer rules, on small programs written here."""

import textwrap
from pathlib import Path

import pytest

from scoopc import diagnostics, pipeline, syntax
from scoopc.project import collect


def check(tmp_path: Path, classes: dict, ecf: str = ""):
    for name, text in classes.items():
        (tmp_path / f"{name.lower()}.e").write_text(textwrap.dedent(text), encoding="utf-8")
    if ecf:
        (tmp_path / "app.ecf").write_text(ecf, encoding="utf-8")
        return pipeline.check_project(collect([str(tmp_path / "app.ecf")]))
    return pipeline.check_project(collect([str(tmp_path)]))


def codes(checked) -> list:
    return [(d.code, d.span.line) for d in checked.diagnostics if d.is_error]


def nodes(checked, kind):
    found = []
    for unit in checked.units:
        stack = [unit.tree]
        while stack:
            node = stack.pop()
            if isinstance(node, kind):
                found.append(node)
            for name in getattr(node, "__dataclass_fields__", ()):
                value = getattr(node, name)
                values = value if isinstance(value, tuple) else (value,)
                stack.extend(v for v in values if hasattr(v, "__dataclass_fields__"))
    return found


BUFFER = """\
    class BUFFER
    create
        make
    feature
        make do create items.make (4) end
        items: ARRAYED_LIST [INTEGER]
        count: INTEGER do Result := items.count end
        is_empty: BOOLEAN do Result := items.is_empty end
        put (x: INTEGER) do items.extend (x) end
        label: STRING do Result := "buffer" end
    end
"""


def test_wait_conditions_record_the_separate_arguments_used_as_targets(tmp_path):
    checked = check(
        tmp_path,
        {
            "BUFFER": BUFFER,
            "APP": """\
        class APP
        create
            make
        feature
            make do end
            take (a: separate BUFFER; b: separate BUFFER; n: INTEGER)
                require
                    not a.is_empty
                    n > 0
                    a.count + b.count > n
                do
                    a.put (n)
                end
        end
    """,
        },
    )
    assert codes(checked) == []
    waits = checked.semantics.tables.wait_args
    clauses = nodes(checked, syntax.AssertionClause)
    by_line = {c.span.line: waits.get(c) for c in clauses}
    assert by_line == {8: ("a",), 9: None, 10: ("a", "b")}


def test_separate_calls_lock_passing_and_adapted_results_are_recorded(tmp_path):
    checked = check(
        tmp_path,
        {
            "BUFFER": BUFFER,
            "APP": """\
        class APP
        create
            make
        feature
            make do end
            use (a: separate BUFFER)
                local
                    n: INTEGER
                do
                    a.put (1)
                    n := a.label.count
                    register (a)
                end
            register (b: separate BUFFER) do end
        end
    """,
        },
    )
    assert codes(checked) == []
    tables = checked.semantics.tables
    calls = {c.name.text: c for c in nodes(checked, syntax.QualifiedCall) if c.span.file.endswith("app.e")}
    assert calls["put"] in tables.separate_calls and calls["label"] in tables.separate_calls
    assert calls["count"] in tables.separate_calls  # on the adapted (separate) result
    assert str(tables.types[calls["label"]]) == "separate STRING_8"
    assert calls["label"] in tables.controlled
    assert tables.features[calls["put"]].written_in == "BUFFER"
    assert calls["put"] not in tables.lock_passing  # an INTEGER argument passes no lock
    registered = next(c for c in nodes(checked, syntax.UnqualifiedCall) if c.name.text == "register")
    assert registered not in tables.separate_calls  # a call on Current is not separate


def test_arguments_that_can_pass_locks_are_recorded(tmp_path):
    checked = check(
        tmp_path,
        {
            "BUFFER": BUFFER,
            "SINK": """\
        class SINK
        feature
            take (b: separate BUFFER; n: INTEGER; note_: separate STRING) do end
        end
    """,
            "APP": """\
        class APP
        create
            make
        feature
            make do end
            send (s: separate SINK; b: separate BUFFER; other: separate STRING)
                do
                    s.take (b, 3, other)
                    s.take (b, 4, "text")
                end
        end
    """,
        },
    )
    assert codes(checked) == []
    tables = checked.semantics.tables
    takes = [c for c in nodes(checked, syntax.QualifiedCall) if c.name.text == "take"]
    assert sorted(tables.lock_passing[c] for c in takes) == [(0, 2), (0, 2)]


def test_a_separate_query_result_cannot_become_non_separate(tmp_path):
    checked = check(
        tmp_path,
        {
            "BUFFER": BUFFER,
            "APP": """\
        class APP
        create
            make
        feature
            make do end
            use (a: separate BUFFER)
                local
                    s: STRING
                    t: separate STRING
                do
                    s := a.label
                    t := a.label
                    print (t.count)
                end
        end
    """,
        },
    )
    assert codes(checked) == [("VJAR", 11), ("VUTA(3)", 13)]
    hint = next(d for d in checked.diagnostics if d.code == "VJAR").hint
    assert "make_from_separate" in hint


def test_conversions_and_manifest_constants_take_their_type_from_the_context(tmp_path):
    checked = check(
        tmp_path,
        {
            "APP": """\
        class APP
        create
            make
        feature
            make
                local
                    r: REAL_64
                    big: INTEGER_64
                    small: INTEGER_8
                    i: INTEGER
                do
                    i := 3
                    r := i
                    r := i + 0.5
                    big := 5_000_000_000
                    big := i
                    small := 300
                end
        end
    """
        },
    )
    assert codes(checked) == [("VJAR", 17)]
    conversions = checked.semantics.tables.conversions
    assert sorted(str(target) for _, target in conversions.values()) == ["INTEGER_64", "REAL_64", "REAL_64"]


def test_void_safety_follows_the_ecf_setting(tmp_path):
    program = {
        "APP": """\
        class APP
        create
            make
        feature
            make
                local
                    s: detachable STRING
                do
                    print (s.count)
                end
        end
    """
    }
    ecf = """<?xml version="1.0"?>
<system xmlns="http://www.eiffel.com/developers/xml/configuration-1-22-0" name="app">
  <target name="app">
    <root class="APP" feature="make"/>
    <option void_safety="{level}"/>
    <cluster name="app" location="."/>
  </target>
</system>"""
    assert codes(check(tmp_path, program, ecf.format(level="all"))) == [("VUTA(2)", 9)]
    assert codes(check(tmp_path, program, ecf.format(level="none"))) == []


def test_object_tests_and_void_comparisons_make_a_target_attached(tmp_path):
    checked = check(
        tmp_path,
        {
            "APP": """\
        class APP
        create
            make
        feature
            make
                local
                    s: detachable STRING
                    n: INTEGER
                do
                    if attached s as l_s then n := l_s.count end
                    if s /= Void then n := s.count end
                    if s = Void or else s.is_empty then n := 0 end
                    n := s.count
                end
        end
    """
        },
    )
    assert codes(checked) == [("VUTA(2)", 13)]


def test_one_mistake_gives_one_diagnostic_and_a_failing_class_stops_there(tmp_path):
    checked = check(
        tmp_path,
        {
            "APP": """\
        class APP
        create
            make
        feature
            make
                local
                    x: UNKNOWN_CLASS
                do
                    x.go
                    x.stop
                end
        end
    """
        },
    )
    assert [d.code for d in checked.diagnostics] == ["VTCT"]


def test_every_validity_diagnostic_carries_a_hint():
    from scoopc.messages import MESSAGES

    ours = [code for code in MESSAGES if code.startswith("V") or code == "ONCE-KEY"]
    assert [code for code in ours if not MESSAGES[code].hint] == []


def test_a_user_class_named_like_a_library_class_hides_it_from_the_user_only(tmp_path):
    checked = check(
        tmp_path,
        {
            "CELL": """\
        class CELL
        create
            make
        feature
            make (v: INTEGER) do value := v end
            value: INTEGER
        end
    """,
            "APP": """\
        class APP
        create
            make
        feature
            make
                local
                    c: CELL
                    l: LINKED_LIST [INTEGER]
                do
                    create c.make (3)
                    create l.make
                    l.extend (c.value)
                    across ("a,b").split (',') as part loop print (part.item) end
                end
        end
    """,
        },
    )
    assert [diagnostics.short(d) for d in checked.diagnostics] == []


def test_incompatible_equality_is_a_warning_as_in_eiffelstudio(tmp_path):
    checked = check(
        tmp_path,
        {
            "APP": """\
        class APP
        create
            make
        feature
            make
                local
                    count: INTEGER
                    answer: STRING
                    ratio: REAL_64
                do
                    answer := "3"
                    if count = answer then print ("same") end
                    ratio := count
                    if ratio = count and count.out ~ answer then print ("fine") end
                end
        end
    """
        },
    )
    assert codes(checked) == []
    assert [(d.code, d.severity, d.span.line) for d in checked.diagnostics] == [("VWEQ", "warning", 12)]


ACCEPTED = {
    "like_anchor_follows_a_redeclaration": {
        "A": """\
        class A
        feature
            attr: detachable ANY
            other: like attr
        end
    """,
        "B": """\
        class B
        inherit
            A
                redefine attr end
        feature
            attr: detachable STRING
            g
                local
                    s: detachable STRING
                do
                    s := other
                end
        end
    """,
    },
    "like_current_on_a_formal_generic_target": {
        "BOX": """\
        class BOX [G -> COMPARABLE]
        feature
            value: detachable G
            copy_in (v: G): G
                do
                    Result := v.twin
                    value := Result
                end
        end
    """
    },
    "none_as_a_type": {
        "APP": """\
        class APP
        feature
            make
                local
                    t: TYPE [detachable ANY]
                    n: detachable NONE
                do
                    t := {ARRAY [attached NONE]}
                    n := Void
                end
        end
    """
    },
    "pre_17_05_agent_types_over_a_tuple_formal": {
        "EVENT": """\
        class EVENT [ARGS -> TUPLE create default_create end]
        create
            make
        feature
            make do create subscribers.make (1) end
            subscribers: ARRAYED_LIST [PROCEDURE [ANY, ARGS]]
            subscribe (p: PROCEDURE [ANY, ARGS]) do subscribers.extend (p) end
            publish (a: ARGS) do across subscribers as s loop s.item.call (a) end end
        end
    """,
        "APP": """\
        class APP
        feature
            make
                local
                    e: EVENT [TUPLE [INTEGER]]
                do
                    create e.make
                    e.subscribe (agent show)
                    e.publish ([5])
                end
            show (i: INTEGER) do print (i) end
        end
    """,
    },
    "agent_on_a_tuple_label_and_check_false": {
        "APP": """\
        class APP
        feature
            make
                local
                    f: FUNCTION [TUPLE [TUPLE [s: STRING]], STRING]
                do
                    f := agent {TUPLE [s: STRING]}.s
                    print (f.item ([["abc"]]))
                end
            anchor: STRING
                do
                    check False then end
                end
        end
    """
    },
    "inherited_creation_procedure_of_a_library_class": {
        "FOOD_BOX": """\
        class FOOD_BOX [G -> COMPARABLE]
        inherit
            ARRAYED_LIST [G]
        create
            make
        end
    """,
        "TAGGED_BOX": """\
        class TAGGED_BOX
        inherit
            ARRAYED_LIST [STRING]
                redefine make end
        create
            make
        feature
            make (n: INTEGER)
                do
                    Precursor (n)
                    tag := "box"
                end
            tag: STRING
        end
    """,
    },
    "effective_version_joined_with_deferred_ones_needs_only_a_conforming_signature": {
        "BASE": """\
        deferred class BASE
        feature
            put (x: separate ANY) deferred end
        end
    """,
        "LEFT": """\
        deferred class LEFT
        inherit
            BASE
        feature
            put (x: STRING) do print (x) end
        end
    """,
        "RIGHT": """\
        deferred class RIGHT
        inherit
            BASE
        end
    """,
        "BOTH": """\
        class BOTH
        inherit
            LEFT
            RIGHT
        end
    """,
    },
    "static_anchors": {
        "APP": """\
        class APP
        feature
            make
                local
                    n: like {STRING}.count
                do
                    n := 3
                end
            first: like {ARRAY [STRING]}.item
                do
                    Result := "x"
                end
        end
    """
    },
}


@pytest.mark.parametrize("case", sorted(ACCEPTED))
def test_forms_eiffelstudio_accepts_check_clean(tmp_path, case):
    checked = check(tmp_path, ACCEPTED[case])
    assert [diagnostics.short(d) for d in checked.diagnostics] == []


def test_a_missing_parent_is_reported_once_not_in_its_heirs_and_clients(tmp_path):
    checked = check(
        tmp_path,
        {
            "C": """\
        class C
        inherit
            UNKNOWN_PARENT
        create
            make
        end
    """,
            "APP": """\
        class APP
        create
            make
        feature
            make
                local
                    c: C
                do
                    create c.make
                    c.go
                    across c as x loop print (x.item) end
                end
        end
    """,
        },
    )
    assert codes(checked) == [("VTCT", 3)]


def test_formal_traitor_warns_only_where_a_result_is_used_as_non_separate(tmp_path):
    """FORMAL-TRAITOR on a `G` result of a separate call: not where it goes to a separate entity
    or argument (no traitor), but where it is attached as non-separate or is a call's target."""
    checked = check(
        tmp_path,
        {
            "CELL": """\
        class CELL [G]
        feature
            item: detachable G
            put (v: G) do item := v end
        end
    """,
            "RELAY": """\
        class RELAY [G]
        feature
            keep (c: separate CELL [G]; other: separate CELL [G])
                local
                    far: detachable separate G
                    near: detachable G
                do
                    far := c.item
                    store (c.item)
                    near := c.item
                end
            store (v: detachable separate G) do end
        end
    """,
        },
    )
    assert codes(checked) == []
    warnings = [(d.code, d.span.line) for d in checked.diagnostics]
    assert warnings == [("FORMAL-TRAITOR", 10)]
