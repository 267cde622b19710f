"""Output to a reader that has gone (`scoopc run app.e | head`): dropped, never an exception in
the program's routines."""

from scoopc.runtime.output import Output


class GoneReader:
    def __init__(self):
        self.writes = 0

    def write(self, text):
        self.writes += 1
        raise BrokenPipeError()

    def flush(self):
        raise BrokenPipeError()


class Proc:
    id = 3


def test_writes_after_the_reader_has_gone_are_dropped():
    stream = GoneReader()
    out = Output(stream, trace=False)
    out.write(Proc(), "one\n")
    out.write(Proc(), "two\n")
    out.flush()
    assert out.broken and stream.writes == 1


def test_traced_lines_are_dropped_too():
    stream = GoneReader()
    out = Output(stream, trace=True)
    out.write(Proc(), "one\nunfinished")
    out.flush()
    assert out.broken and stream.writes == 1
