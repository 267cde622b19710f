"""Features EiffelStudio's own SCOOP examples rely on (Src/examples/scoop, checked by hand in
/work/plan/faithfulness.md), each in a small program of our own, run through `scoopc run` on the
virtual clock. Outputs of concurrent programs are checked by their properties (per-actor order,
counts, mutual exclusion), never as one interleaving."""

from pathlib import Path

from scoopc import cli

HERE = Path(__file__).resolve().parent


def run(capsys, case: str, *options):
    code = cli.main(["run", "--virtual-clock", *options, str(HERE / case)])
    out, err = capsys.readouterr()
    return code, out, err


def test_a_once_function_is_once_per_processor_and_once_process_is_global(capsys):
    # baboon_crossing, search-insert-delete, senate_bus: `out` is a once; each actor, on its
    # own processor, prints its own name.
    code, out, err = run(capsys, "once_per_processor")
    assert code == 0, err
    lines = out.splitlines()
    assert sorted(line.split()[0] for line in lines) == ["greeter-1", "greeter-2", "greeter-3"]
    assert len({line.split()[-1] for line in lines}) == 1  # one PROCESS-wide value


def test_lock_passing_makes_calls_with_current_synchronous_and_allows_callbacks(capsys):
    # dining_philosophers: `left.pick (Current)` calls back `philosopher.id` under passed locks.
    code, out, err = run(capsys, "lock_passing_callback")
    assert code == 0, err
    lines = out.splitlines()
    assert len(lines) == 2 * 5 * 4
    for diner in ("1", "2"):
        mine = [line.rsplit(" ", 1)[0] for line in lines if line.endswith(" " + diner)]
        assert mine == ["plate A taken by", "plate B taken by", "plate A given back by", "plate B given back by"] * 5
    holder = {}
    for line in lines:
        plate, diner = line.split()[1], line.split()[-1]
        if "taken" in line:
            assert plate not in holder, line
            holder[plate] = diner
        else:
            assert holder.pop(plate) == diner


def test_a_failing_wait_condition_waits_for_another_processor(capsys):
    # counter (test_5), single_element_producer_consumer, dining_savages.
    code, out, err = run(capsys, "wait_condition_counter")
    assert code == 0, err
    lines = out.splitlines()
    assert sorted(lines) == ["stepper done", "waited until 3"]


def test_a_wait_condition_on_a_passive_region_is_woken_when_it_changes(capsys):
    # email_client: the mover waits on `a_controller.is_over`, the controller being passive.
    code, out, err = run(capsys, "passive_flag_wakeup")
    assert code == 0, err
    assert out.splitlines() == ["watching", "raising", "seen"]


def test_agents_of_passive_regions_run_on_the_processor_that_reserves_them(capsys):
    # processor_pool: tasks made with `create <NONE>` and run by pool processors.
    code, out, err = run(capsys, "passive_tasks_pool")
    assert code == 0, err
    lines = out.splitlines()
    assert sorted(line for line in lines if line.startswith("job")) == [f"job {i}" for i in range(1, 7)]
    assert lines.count("worker done") == 2


def test_random_real_item_is_single_precision_as_in_eiffelbase(capsys):
    # quicksort: `(random.real_item * 1000).floor`; item 755 of seed 14 is 905 in REAL_32
    # arithmetic (904 in REAL_64).
    code, out, err = run(capsys, "random_real_32")
    assert code == 0, err
    assert out.splitlines() == ["854", "22", "905"]


def test_an_agent_call_may_omit_the_empty_tuple(capsys):
    # processor_pool: `separate task as t do t.call end`.
    code, out, err = run(capsys, "agent_call_omitted_tuple")
    assert (code, out) == (0, "called\n42\n"), err


def test_every_program_here_checks_clean(capsys):
    for case in sorted(p for p in HERE.iterdir() if p.is_dir() and not p.name.startswith("_")):
        assert cli.main(["check", str(case)]) == 0, case.name
    assert "error" not in capsys.readouterr().err
