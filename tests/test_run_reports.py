"""Run-time reports in Eiffel terms only (issue 22): every frame an Eiffel routine with its .e
file and line (a wait condition at its own line, never a Python `<lambda>`), and one report for
one failure: what follows from a failed creation (Void targets, a deadlock) is one line."""

import textwrap

from scoopc import cli
from scoopc.exits import Exit

WORKER_WAIT = """\
    class WORKER
    feature
        ready: BOOLEAN
            local
                a: ARRAY [INTEGER]
            do
                create a.make_filled (0, 1, 2)
                Result := a [5] > 0
            end
        go (n: INTEGER)
            require
                positive: n > 0
            do
                print (n)
            end
        value: INTEGER
    end
"""

APP_WAIT = """\
    class APP
    create make
    feature
        make
            local
                w: separate WORKER
            do
                create w
                run (w)
            end

        run (w: separate WORKER)
            require
                w.ready
            do
                w.go (1)
            end
    end
"""

APP_ASYNC = APP_WAIT.replace("            require\n                w.ready\n", "").replace(
    "w.go (1)", "w.go (0)\n                print (w.value)"
)

CREATED = """\
    class WORKER
    create make
    feature
        items: ARRAYED_LIST [INTEGER]
        ready: BOOLEAN
        make (n: INTEGER)
            do
                print (10 // n)
                create items.make (4)
                ready := True
            end
        add (x: INTEGER)
            do
                items.extend (x)
            end
        count: INTEGER
            do
                Result := items.count
            end
    end
"""

APP_VOID = """\
    class APP
    create make
    feature
        make
            local
                w: separate WORKER
            do
                create w.make (0)
                use (w)
            end

        use (w: separate WORKER)
            do
                w.add (3)
                w.add (4)
                print (w.count)
            end
    end
"""

APP_DEADLOCK = APP_VOID.replace(
    "use (w: separate WORKER)\n", "use (w: separate WORKER)\n        require\n            w.ready\n"
)


def run(tmp_path, capsys, classes: dict) -> tuple[int, str]:
    for name, text in classes.items():
        (tmp_path / f"{name}.e").write_text(textwrap.dedent(text))
    code = cli.main(["run", str(tmp_path), "--root", "APP"])
    _, err = capsys.readouterr()
    return code, err


def test_an_exception_in_a_wait_condition_is_traced_to_its_line(tmp_path, capsys):
    code, err = run(tmp_path, capsys, {"worker": WORKER_WAIT, "app": APP_WAIT})
    assert code == Exit.RUNTIME
    assert "<lambda>" not in err and "app.e:1)" not in err
    frames = [line.strip() for line in err.splitlines()[1:]]
    assert frames == [
        "in ARRAY.item (array.e:115)",
        "called by WORKER.ready (worker.e:8)",
        "called by APP.run, wait condition (app.e:14)",
        "called by APP.run (app.e:12)",
        "called by APP.make (app.e:9)",
    ]


def test_a_failed_asynchronous_call_shows_the_supplier_then_where_the_client_noticed(tmp_path, capsys):
    code, err = run(tmp_path, capsys, {"worker": WORKER_WAIT, "app": APP_ASYNC})
    assert code == Exit.RUNTIME
    assert err.splitlines()[1:] == [
        "  in WORKER.go (worker.e:12)",
        "  failure noticed in APP.run (app.e:15)",
        "  called by APP.make (app.e:9)",
    ]


def test_void_targets_after_a_failed_creation_are_one_line(tmp_path, capsys):
    code, err = run(tmp_path, capsys, {"worker": CREATED, "app": APP_VOID})
    assert code == Exit.RUNTIME
    assert err.splitlines() == [
        "scoopc: exception lost in the creation of P2(WORKER) by P1(APP): integer division by zero",
        "  in WORKER.make (worker.e:8)",
        "scoopc: run-time failure: a consequence of the exception lost on P2(WORKER) (reported above): "
        "feature call on a Void target in WORKER.add (worker.e:14) noticed in APP.use (app.e:16)",
    ]
    assert "reservation at ?" not in err


def test_a_deadlock_after_a_failed_creation_is_one_line(tmp_path, capsys):
    code, err = run(tmp_path, capsys, {"worker": CREATED, "app": APP_DEADLOCK})
    assert code == Exit.RUNTIME
    lines = err.splitlines()
    assert lines[:2] == [
        "scoopc: exception lost in the creation of P2(WORKER) by P1(APP): integer division by zero",
        "  in WORKER.make (worker.e:8)",
    ]
    assert len(lines) == 3 and lines[2].startswith(
        "scoopc: run-time failure: deadlock, a consequence of the lost exception reported above: P1(APP) in APP.use ("
    )
