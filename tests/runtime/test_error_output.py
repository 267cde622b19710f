"""`Processor.print_error` (CONSOLE's standard error) and `flush_output`."""

import io

from scoopc.runtime.main import finish, start


class Writer:
    def make(self):
        pass

    def say(self, text, n, error):
        for _ in range(n):
            if error:
                self._region_.print_error(text)
            else:
                self._region_.print(text)


class Flushes(io.StringIO):
    def __init__(self):
        super().__init__()
        self.flushes = 0

    def flush(self):
        self.flushes += 1


def test_error_output_is_never_torn_and_goes_to_stderr(harness):
    h = harness()
    root = h.root
    lines = ["".join(chr(65 + i) for _ in range(300)) + "\n" for i in range(6)]
    for i, line in enumerate(lines):
        p = root.new_separate(Writer, Writer.make)
        with root.reserve((p,)):
            root.call(p, Writer.say, (line, 100, i % 2 == 0))
    assert h.finish() == 0
    err = h.err.getvalue().splitlines(keepends=True)
    out = h.out.getvalue().splitlines(keepends=True)
    assert len(err) == 300 and set(err) == set(lines[0::2])
    assert len(out) == 300 and set(out) == set(lines[1::2])


def test_print_error_flushes_and_is_not_tagged():
    out, err = Flushes(), Flushes()
    rt, root = start(stdout=out, stderr=err, trace_processors=True, deadlock_tick=0.05)
    root.print_error("oops\n")
    assert err.getvalue() == "oops\n" and err.flushes == 1
    root.print("held")
    root.flush_output()
    assert out.flushes >= 1 and out.getvalue() == ""  # unfinished traced line stays held
    assert finish(rt, root) == 0
    assert out.getvalue() == "[P1] held\n"
