"""Output of text that carries bytes which are not UTF-8 (surrogate escapes: a program's STRING_8
holds bytes): written as those bytes, on the standard output and on the error stream alike."""

import io

from scoopc.runtime.output import Output


class Proc:
    id = 1


def streams():
    out = io.TextIOWrapper(io.BytesIO(), encoding="utf-8")  # strict, as a terminal's
    err = io.TextIOWrapper(io.BytesIO(), encoding="utf-8", errors="backslashreplace")  # as sys.stderr
    return out, err


def test_escaped_bytes_are_written_as_themselves():
    out, err = streams()
    output = Output(out, trace=False)
    output.write(Proc(), "a")
    output.write(Proc(), "caf\udce9 é\n")
    output.write_other(err, "\udcff!")
    output.flush()
    err.flush()
    assert out.buffer.getvalue() == b"acaf\xe9 \xc3\xa9\n"
    assert err.buffer.getvalue() == b"\xff!"


def test_traced_lines_keep_the_bytes_too():
    out, _ = streams()
    output = Output(out, trace=True)
    output.write(Proc(), "\udce9\n")
    output.flush()
    assert out.buffer.getvalue() == b"[P1] \xe9\n"
