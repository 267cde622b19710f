"""FILE / PLAIN_TEXT_FILE / IO_MEDIUM externals on real files (scoopc/kernel/ext/io_medium.py,
file.py), called directly on small fake objects, as generated code would call them."""

import os

import pytest

from scoopc import kernel
from scoopc.kernel import strings as K
from scoopc.kernel.errors import EiffelFailure
from scoopc.kernel.ext import file as F, io_medium as M


class Region:
    id = 1

    def __init__(self):
        self.out = []

    def print(self, text):
        self.out.append(text)

    def new(self, cls):
        obj = cls.__new__(cls)
        obj._region_ = self
        return obj


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


def s(region, text):
    return K.new_string_8(region, text)


def new_file(region, path, maker=F.make_with_name):
    f = Obj(region)
    maker(f, s(region, str(path)))
    return f


def last(f):
    return K.text(M.last_string(f))


def test_write_then_read_lines(region, tmp_path):
    path = tmp_path / "a.txt"
    f = new_file(region, path, F.make_open_write)
    assert M.is_open_write(f) and not M.is_open_read(f) and M.extendible(f)
    M.put_string(f, s(region, "first line"))
    M.put_new_line(f)
    M.put_integer(f, -42)
    M.put_character(f, " ")
    M.put_boolean(f, True)
    M.new_line(f)
    M.put_string(f, s(region, "no newline at end"))
    M.close(f)
    assert M.is_closed(f)
    assert path.read_bytes() == b"first line\n-42 True\nno newline at end"
    f = new_file(region, path, F.make_open_read)
    assert M.readable(f) and not F.end_of_file(f)
    M.read_line(f)
    assert last(f) == "first line" and not F.end_of_file(f)
    M.read_line(f)
    assert last(f) == "-42 True" and not F.end_of_file(f)
    M.read_line(f)  # the last line has no new line: feof is already set
    assert last(f) == "no newline at end" and F.end_of_file(f)
    assert not M.readable(f) and F.after(f) and F.off(f)
    M.close(f)


def test_end_of_file_becomes_true_only_when_a_read_hits_the_end(region, tmp_path):
    path = tmp_path / "b.txt"
    path.write_bytes(b"x\ny\n")
    f = new_file(region, path, F.make_open_read)
    lines = []
    M.read_line(f)
    while not F.end_of_file(f):  # EiffelBase's classic loop
        lines.append(last(f))
        M.read_line(f)
    assert lines == ["x", "y"] and last(f) == ""
    F.start(f)  # moving clears the end-of-file flag
    assert not F.end_of_file(f) and F.position(f) == 0
    M.read_line(f)
    assert last(f) == "x"


def test_last_string_is_one_object_refilled_by_every_read(region, tmp_path):
    path = tmp_path / "c.txt"
    path.write_bytes(b"one\ntwo\n")
    f = new_file(region, path, F.make_open_read)
    M.read_line(f)
    first = M.last_string(f)
    M.read_line(f)
    assert M.last_string(f) is first and K.text(first) == "two"


def test_read_integer_leaves_the_next_character_unread_in_a_file(region, tmp_path):
    path = tmp_path / "n.txt"
    path.write_bytes(b"  42\n-7 x\n99999999999\n")
    f = new_file(region, path, F.make_open_read)
    M.read_integer(f)
    assert M.last_integer(f) == 42 and M.last_character(f) == "\n"
    M.read_line(f)  # the rest of the line: empty, as in EiffelBase
    assert last(f) == ""
    M.read_integer_64(f)
    assert M.last_integer_64(f) == -7 and M.last_character(f) == " "
    M.read_word(f)
    assert last(f) == "x"
    M.read_integer(f)  # wraps around, as the converter's INTEGER_32 result
    assert M.last_integer(f) == 99999999999 - 2**32 * 23
    M.read_natural_8(f)  # at the end: nothing read
    assert M.last_natural_8(f) == 0 and F.end_of_file(f) and M.last_character(f) == "\xff"


def test_read_double_and_real_skip_the_blanks_after_the_number(region, tmp_path):
    path = tmp_path / "d.txt"
    path.write_bytes(b"3.25\n\n  -1e3 .5x\n")
    f = new_file(region, path, F.make_open_read)
    M.read_double(f)
    assert M.last_double(f) == 3.25 and M.last_real_64(f) == 3.25
    M.read_double(f)
    assert M.last_double(f) == -1000.0
    M.read_real(f)
    assert M.last_real(f) == 0.5 and M.last_real_32(f) == 0.5
    M.read_line(f)
    assert last(f) == "x"
    with pytest.raises(OSError):  # no IO_FAILURE class in this test: a Python error
        M.read_double(f)


def test_read_real_rounds_to_single_precision(region, tmp_path):
    path = tmp_path / "r.txt"
    path.write_bytes(b"0.1")
    f = new_file(region, path, F.make_open_read)
    M.read_real(f)
    assert M.last_real(f) == 0.10000000149011612


def test_read_word_character_and_stream(region, tmp_path):
    path = tmp_path / "w.txt"
    path.write_bytes("  hello\tw\u00f6rld\nabcdef".encode())
    f = new_file(region, path, F.make_open_read)
    M.read_word(f)
    assert last(f) == "hello"
    M.read_character(f)
    assert M.last_character(f) == "\t"
    M.read_word(f)
    assert last(f) == "w\xc3\xb6rld"  # one character per byte, as EiffelStudio reads
    assert F.position(f) == len("  hello\tw\u00f6rld".encode())  # bytes
    F.next_line(f)
    M.read_stream(f, 4)
    assert last(f) == "abcd" and M.bytes_read(f) == 4 and not F.end_of_file(f)
    M.read_stream(f, 10)
    assert last(f) == "ef" and M.bytes_read(f) == 2 and F.end_of_file(f)
    M.read_character(f)
    assert M.last_character(f) == "\xff"


def test_bytes_that_are_not_utf8_survive_a_copy(region, tmp_path):
    src, dst = tmp_path / "src.bin", tmp_path / "dst.bin"
    data = b"caf\xe9\n\xff\xfe ok\n"
    src.write_bytes(data)
    f = new_file(region, src, F.make_open_read)
    g = new_file(region, dst, F.make_open_write)
    M.read_line(f)
    while not F.end_of_file(f):
        M.put_string(g, M.last_string(f))
        M.put_new_line(g)
        M.read_line(f)
    M.close(g)
    assert dst.read_bytes() == data


def test_append_and_read_write_modes(region, tmp_path):
    path = tmp_path / "m.txt"
    path.write_bytes(b"abc\n")
    f = new_file(region, path, F.make_open_append)
    assert F.is_open_append(f) and not M.is_open_read(f)
    M.put_string(f, s(region, "def\n"))
    M.close(f)
    assert path.read_bytes() == b"abc\ndef\n"
    f = new_file(region, path, F.make_open_read_append)
    assert M.is_open_read(f) and F.is_open_append(f)
    M.read_line(f)  # reads from the start
    assert last(f) == "abc"
    M.put_string(f, s(region, "ghi\n"))  # writes at the end
    M.close(f)
    assert path.read_bytes() == b"abc\ndef\nghi\n"
    f = new_file(region, path, F.make_open_read_write)
    F.go(f, 4)
    M.put_string(f, s(region, "DEF"))
    F.start(f)
    M.read_line(f)
    M.read_line(f)
    assert last(f) == "DEF"
    F.finish(f)
    assert F.position(f) == F.count(f) == 12
    F.move(f, -4)
    M.read_line(f)
    assert last(f) == "ghi"
    M.close(f)
    f = new_file(region, path, F.make_create_read_write)
    assert F.count(f) == 0 and F.is_empty(f) and M.is_open_read(f) and M.is_open_write(f)
    M.put_string(f, s(region, "new"))
    assert F.count(f) == 3  # flushed to tell the size
    M.close(f)


def test_status_of_names(region, tmp_path):
    path = tmp_path / "s.txt"
    f = new_file(region, path)
    assert M.is_closed(f) and not M.exists(f) and not F.path_exists(f) and F.is_creatable(f)
    assert F.count(f) == 0 and K.text(F.name(f)) == str(path) and K.text(F.path_name(f)) == str(path)
    F.open_write(f)
    assert M.exists(f)
    M.close(f)
    assert M.exists(f) and F.is_plain(f) and not F.is_directory(f) and not F.is_creatable(f)
    assert not F.is_device(f) and not F.is_fifo(f) and not F.is_socket(f) and not F.is_symlink(f)
    assert M.is_readable(f) and M.is_writable(f) and M.is_plain_text(f)
    os.utime(path, (1000, 2000))
    assert F.date(f) == 2000 and F.access_date(f) == 1000 and F.change_date(f) > 0
    F.touch(f)
    assert F.date(f) > 2000
    d = new_file(region, tmp_path)
    assert F.is_directory(d) and not F.is_plain(d)
    link = tmp_path / "link"
    link.symlink_to(tmp_path / "missing")
    lf = new_file(region, link)
    assert F.path_exists(lf) and not M.exists(lf) and F.is_symlink(lf)
    F.delete(lf)
    assert not F.path_exists(lf)


def test_rename_reset_wipe_out_delete(region, tmp_path):
    path = tmp_path / "old.txt"
    path.write_bytes(b"12 34\n")
    f = new_file(region, path, F.make_open_read)
    M.read_integer(f)
    M.read_line(f)
    M.close(f)
    F.rename_file(f, s(region, str(tmp_path / "new.txt")))
    assert not path.exists() and K.text(F.name(f)) == str(tmp_path / "new.txt")
    F.reset(f, s(region, str(tmp_path / "new.txt")))
    assert M.last_integer(f) == 0 and last(f) == "" and M.is_closed(f)
    F.wipe_out(f)
    assert (tmp_path / "new.txt").read_bytes() == b""
    F.delete(f)
    assert not (tmp_path / "new.txt").exists()
    sub = tmp_path / "sub"
    sub.mkdir()
    F.delete(new_file(region, sub))
    assert not sub.exists()


def test_reals_are_written_as_their_out(region, tmp_path, monkeypatch):
    path = tmp_path / "o.txt"
    f = new_file(region, path, F.make_open_write)
    M.put_double(f, 0.1)
    M.put_character(f, " ")
    M.put_real(f, 2.5)
    monkeypatch.setattr(K, "real_64_out", lambda d: "D")  # the basic types' `out`, rebound
    M.put_real_64(f, 1.0)
    M.put_natural_64(f, 2**64 - 1)
    M.close(f)
    assert path.read_text() == "0.10000000000000001 2.5D18446744073709551615"


def test_failures_raise_eiffel_exceptions_when_the_classes_exist(region, tmp_path):
    class IO_FAILURE:
        def set_description(self, d):
            self.description = d

    class OPERATING_SYSTEM_FAILURE(IO_FAILURE):
        pass

    kernel.register("IO_FAILURE", IO_FAILURE)
    kernel.register("OPERATING_SYSTEM_FAILURE", OPERATING_SYSTEM_FAILURE)
    f = Obj(region)
    with pytest.raises(EiffelFailure) as info:
        F.make_open_read(f, s(region, str(tmp_path / "missing.txt")))
    exc = info.value.exception
    assert type(exc) is OPERATING_SYSTEM_FAILURE and exc._region_ is region
    assert "unable to open" in K.text(exc.description)
    g = new_file(region, tmp_path / "x.txt")
    with pytest.raises(EiffelFailure) as info:
        M.put_string(g, s(region, "closed"))
    assert type(info.value.exception) is IO_FAILURE
    with pytest.raises(EiffelFailure):
        M.read_line(g)
