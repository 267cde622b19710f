"""CONSOLE: output through the runtime (untorn, stderr through `print_error`), input from
`sys.stdin` read at call time with EiffelBase's CONSOLE behaviour."""

import io
import sys

import pytest

from scoopc import kernel
from scoopc.kernel import strings as K
from scoopc.kernel.ext import console as C, file as F, io_medium as M
from scoopc.runtime.main import finish, start


class Region:
    id = 1

    def __init__(self):
        self.out, self.err, self.flushes = [], [], 0

    def print(self, text):
        self.out.append(text)

    def print_error(self, text):
        self.err.append(text)

    def flush_output(self):
        self.flushes += 1


class Str:
    pass


class Obj:
    def __init__(self, region):
        self._region_ = region


@pytest.fixture
def region():
    saved = dict(kernel.CLASSES)
    kernel.CLASSES.clear()  # only the classes below: no exception class of an earlier program
    for key in ("STRING_8", "STRING_32", "IMMUTABLE_STRING_8", "IMMUTABLE_STRING_32"):
        kernel.CLASSES[key] = type(key, (Str,), {})
    yield Region()
    kernel.CLASSES.clear()
    kernel.CLASSES.update(saved)


def console(region, maker, name):
    c = Obj(region)
    maker(c, K.new_string_8(region, name))
    return c


def stdin_console(region, monkeypatch, text):
    monkeypatch.setattr(sys, "stdin", io.StringIO(text))
    return console(region, C.make_open_stdin, "stdin")


def last(c):
    return K.text(M.last_string(c))


def test_output_goes_through_the_runtime_one_call_one_write(region):
    out = console(region, C.make_open_stdout, "stdout")
    err = console(region, C.make_open_stderr, "stderr")
    M.put_string(out, K.new_string_8(region, "hello"))
    M.put_new_line(out)
    M.put_integer(out, 7)
    M.put_double(out, 1.5)
    M.put_boolean(out, False)
    M.put_string(out, K.new_string_8(region, ""))  # nothing written
    M.put_string(err, K.new_string_8(region, "oops\n"))
    assert region.out == ["hello", "\n", "7", "1.5", "False"]
    assert region.err == ["oops\n"]
    M.flush(out)
    assert region.flushes == 1


def test_console_status(region, monkeypatch):
    out = console(region, C.make_open_stdout, "stdout")
    inp = stdin_console(region, monkeypatch, "")
    assert K.text(F.name(out)) == "stdout" and M.exists(out) and M.is_open_write(out)
    assert M.extendible(out) and not M.is_open_read(out) and not M.readable(out)
    assert F.count(out) == 1 and not F.is_empty(out) and F.position(out) == 0
    assert M.is_open_read(inp) and not M.extendible(inp) and M.readable(inp)
    assert M.is_readable(inp) and not M.is_writable(inp) and M.is_writable(out)
    M.read_line(inp)
    assert F.end_of_file(inp) and not M.readable(inp) and last(inp) == ""
    M.close(out)
    assert M.is_closed(out)


def test_read_line_loop_until_end_of_file(region, monkeypatch):
    inp = stdin_console(region, monkeypatch, "alpha\nbeta\n")
    seen = []
    M.read_line(inp)
    while not F.end_of_file(inp):
        seen.append(last(inp))
        M.read_line(inp)
    assert seen == ["alpha", "beta"]
    assert region.flushes >= 3  # the output is flushed before every read


def test_read_integer_consumes_the_rest_of_the_line_on_the_console(region, monkeypatch):
    inp = stdin_console(region, monkeypatch, " 12 apples\n-5\nname\n7")
    M.read_integer(inp)
    assert M.last_integer(inp) == 12 and M.last_character(inp) == "\n"
    M.read_integer_16(inp)
    assert M.last_integer_16(inp) == -5
    M.read_line(inp)  # the next line, not the end of the previous one
    assert last(inp) == "name"
    M.read_natural(inp)
    assert M.last_natural(inp) == 7 and F.end_of_file(inp)


def test_read_double_swallows_one_new_line_on_the_console(region, monkeypatch):
    inp = stdin_console(region, monkeypatch, "2.5\n\nrest\n")
    M.read_double(inp)
    assert M.last_double(inp) == 2.5
    M.read_line(inp)  # one new line swallowed: the empty line remains
    assert last(inp) == ""
    M.read_line(inp)
    assert last(inp) == "rest"


def test_read_word_character_stream_next_line(region, monkeypatch):
    inp = stdin_console(region, monkeypatch, "  one two\nthree\nfour")
    M.read_word(inp)
    assert last(inp) == "one"
    M.read_character(inp)
    assert M.last_character(inp) == " "
    F.next_line(inp)
    M.read_stream(inp, 3)
    assert last(inp) == "thr" and M.bytes_read(inp) == 3
    M.read_line(inp)
    assert last(inp) == "ee"
    M.read_stream(inp, 10)
    assert last(inp) == "four" and F.end_of_file(inp)


def test_stdin_is_read_at_call_time(region, monkeypatch):
    inp = stdin_console(region, monkeypatch, "first\n")
    M.read_line(inp)
    M.read_line(inp)
    assert F.end_of_file(inp)
    monkeypatch.setattr(sys, "stdin", io.StringIO("second\n"))  # a new stdin: a fresh start
    assert not F.end_of_file(inp)
    M.read_line(inp)
    assert last(inp) == "second"
    other = console(region, C.make_open_stdin, "stdin")  # another region's `io.input`
    monkeypatch.setattr(sys, "stdin", io.StringIO("a\nb\n"))
    M.read_line(inp)
    M.read_line(other)
    assert (last(inp), last(other)) == ("a", "b")  # one shared stdin, as C's


def test_writing_on_stdin_or_reading_stdout_fails(region, monkeypatch):
    inp = stdin_console(region, monkeypatch, "")
    out = console(region, C.make_open_stdout, "stdout")
    with pytest.raises(OSError):
        M.put_string(inp, K.new_string_8(region, "x"))
    with pytest.raises(OSError):
        M.read_line(out)
    with pytest.raises(OSError):
        F.start(inp)


def test_with_the_real_runtime_stdout_and_stderr_are_the_runs():
    out, err = io.StringIO(), io.StringIO()
    saved = dict(kernel.CLASSES)
    kernel.CLASSES["STRING_8"] = type("STRING_8", (Str,), {})
    rt, root = start(stdout=out, stderr=err, deadlock_tick=0.05)
    try:
        o = console(root, C.make_open_stdout, "stdout")
        e = console(root, C.make_open_stderr, "stderr")
        M.put_string(o, K.new_string_8(root, "to out\n"))
        M.put_string(e, K.new_string_8(root, "to err\n"))
        M.flush(o)
    finally:
        status = finish(rt, root)
        kernel.CLASSES.clear()
        kernel.CLASSES.update(saved)
    assert status == 0
    assert out.getvalue() == "to out\n" and err.getvalue() == "to err\n"


def test_console_input_is_bytes_and_output_gives_them_back(region, monkeypatch):
    """EiffelStudio reads and writes the console as bytes: "é" read is two characters (UTF-8 C3 A9)
    and written back is the same two bytes; a byte that is not UTF-8 goes out as itself."""
    inp = stdin_console(region, monkeypatch, "é∀\nçx")
    M.read_line(inp)
    assert last(inp) == "\xc3\xa9\xe2\x88\x80"
    M.read_character(inp)
    M.read_stream(inp, 2)
    assert M.last_character(inp) == "\xc3" and last(inp) == "\xa7x" and M.bytes_read(inp) == 2
    out = console(region, C.make_open_stdout, "stdout")
    M.put_string(out, K.new_string_8(region, "\xc3\xa9"))
    M.put_string(out, K.new_string_8(region, "caf\xe9"))
    M.put_character(out, "\xe9")
    assert region.out == ["é", "caf\udce9", "\udce9"]  # surrogate escapes: the runtime writes the bytes


def test_console_input_from_a_byte_stream_keeps_bytes_that_are_not_utf8(region, monkeypatch):
    stdin = io.TextIOWrapper(io.BytesIO(b"caf\xe9\n\xfe"), encoding="utf-8")  # strict: text reads would fail
    monkeypatch.setattr(sys, "stdin", stdin)
    inp = console(region, C.make_open_stdin, "stdin")
    M.read_line(inp)
    M.read_character(inp)
    assert last(inp) == "caf\xe9" and M.last_character(inp) == "\xfe"
