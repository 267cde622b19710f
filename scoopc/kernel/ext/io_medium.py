"""IO_MEDIUM's `external "Python"` features (stdlib/base/io/io_medium.e), and the host side of
every medium: the files of FILE / PLAIN_TEXT_FILE (scoopc.kernel.ext.file) and the standard
streams of CONSOLE (scoopc.kernel.ext.console).

Host state of a medium object (attributes whose names start with `_`):
  `_name` (str, the file name), `_mode` (EiffelBase's modes: CLOSED, READ, WRITE, APPEND,
  READ_WRITE, APPEND_READ), `_console` (None, "stdin", "stdout" or "stderr"), `_chan` (the open
  channel: a `file.FileChan`, the shared `console.STDIN`, or None), `_last_*` (what the last
  read gave). A channel has `getc`, `unget`, `readline`, `read` and `eof` (C's `feof`: sticky
  until a move); the standard input's also has `lock` and `sync`.

Behaviour follows EiffelBase (FILE, PLAIN_TEXT_FILE, CONSOLE and the C run-time's file.c):
* `end_of_file` is C's `feof`: it becomes true when a read hits the end, not before (the last
  line of a file without a final new line is read with `end_of_file` already true); moving
  (`start`, `go`, `move`, `finish`) clears it.
* `read_line` reads up to the new line, which is consumed and not kept; `read_word` skips
  blanks, then reads up to a blank (left unread); `read_stream (n)` reads at most n bytes.
* `read_integer` (and the other integer/natural reads) skips " %N%R%T", reads an optional sign
  and digits, and stops at the first other character: a file leaves it unread, the console
  consumes the rest of the line (EiffelBase's CONSOLE). A number too large wraps.
* `read_real`/`read_double` read like C's `scanf ("%lf")`; then a file skips the blanks that
  follow, the console one new line. At the end of the input they raise IO_FAILURE.
* `read_character` at the end gives '%/255/' (C's EOF as a character).
* `last_string` is one object per medium, refilled by every read, when the string helpers offer
  `set_text(obj, text)`; otherwise each read makes a new STRING_8.
Media are byte streams, as EiffelStudio's: a STRING_8's characters are bytes (see
scoopc/kernel/strings.py), written as they are and read one character per byte, so a file
copied through `read_line`/`put_string` is reproduced byte for byte and `"é"` read from a UTF-8
file has count 2; `count`, `position`, `go`, `move`, `read_stream` count bytes. Console output
goes through the runtime (`Processor.print` / `print_error`: one `put_...` call is never torn)
as text: the bytes read as UTF-8, a byte that is not UTF-8 as a surrogate escape, which the
runtime's output writes back as that byte. Console input reads `sys.stdin` at call time, under a
lock, with the standard output flushed first (a prompt shows before the program waits), and
takes its UTF-8 bytes.
"""

from scoopc.kernel import strings
from scoopc.kernel.ext.exception import failure
from scoopc.kernel.ext.single_math import to_single

CLOSED, READ, WRITE, APPEND, READ_WRITE, APPEND_READ = range(6)
_READ_MODES = (READ, READ_WRITE, APPEND_READ)
_BLANKS = " \t\n\r\v\f"  # C's isspace
_SEPARATORS = " \n\r\t"  # EiffelBase's leading separators of numbers
_EOF_CHARACTER = "\xff"  # C's EOF cast to a character


class _NoLock:
    def __enter__(self):
        return self

    def __exit__(self, *exc):
        return False


_NO_LOCK = _NoLock()


# --- helpers shared with file.py and console.py ---------------------------------------------


def text_of(s):
    return strings.text(s)


def new_string_8(current, text):
    return strings.new_string_8(current._region_, text)


def fail(current, message, kind="IO_FAILURE", cause=None):
    """The exception to raise for a failed operation on the medium."""
    name = getattr(current, "_name", None)
    where = f"{name}: " if name else ""
    return failure(current._region_, kind, where + message, cause)


def mode(current):
    return getattr(current, "_mode", CLOSED)


def is_console(current):
    return getattr(current, "_console", None) is not None


def set_last_string(current, text):
    obj = getattr(current, "_last_string", None)
    setter = getattr(strings, "set_text", None)
    if obj is not None and setter is not None:
        setter(obj, text)
    else:
        current._last_string = strings.new_string_8(current._region_, text)


def reset_lasts(current):
    """Forget what was read (FILE.reset): zeros, and an empty `last_string`."""
    for attr in [a for a in vars(current) if a.startswith("_last_") and a != "_last_string"]:
        delattr(current, attr)
    if getattr(current, "_last_string", None) is not None:
        set_last_string(current, "")


def _input(current):
    """(channel, lock) to read from; raises IO_FAILURE when the medium is not open for reading."""
    chan = getattr(current, "_chan", None)
    if chan is None or mode(current) not in _READ_MODES:
        raise fail(current, "not open for reading")
    lock = getattr(chan, "lock", None)
    if lock is None:
        return chan, _NO_LOCK
    flush = getattr(current._region_, "flush_output", None)
    if flush is not None:
        flush()  # a prompt shows before the program waits
    lock.acquire()
    try:
        chan.sync()
    except BaseException:
        lock.release()
        raise
    return chan, lock


class _Reading:
    """`with _Reading(current) as chan:` the input channel, held (stdin) while reading."""

    def __init__(self, current):
        self.chan, self.lock = _input(current)

    def __enter__(self):
        return self.chan

    def __exit__(self, *exc):
        if self.lock is not _NO_LOCK:
            self.lock.release()
        return False


def write(current, text):
    """Write 8-bit characters `text` (bytes) on the medium."""
    console = getattr(current, "_console", None)
    if console is not None and not text.isascii():
        text = strings.bytes_text(text)
    if console == "stdout":
        current._region_.print(text)
        return
    if console == "stderr":
        region = current._region_
        pe = getattr(region, "print_error", None)
        if pe is None:
            region.print(text)
        else:
            pe(text)
        return
    chan = getattr(current, "_chan", None)
    if chan is None or mode(current) < WRITE or console is not None:
        raise fail(current, "not open for writing")
    try:
        chan.write(text)
    except (OSError, ValueError) as e:
        raise fail(current, f"unable to write: {e}", cause=e) from e


def _wrap(value, bits, signed):
    value &= (1 << bits) - 1
    if signed and value >> (bits - 1):
        value -= 1 << bits
    return value


def _real_out(value, single):
    """`r.out` / `d.out`: the string helpers' formats (rebound to the basic types' `out`)."""
    return strings.real_32_out(value) if single else strings.real_64_out(value)


# --- Access ---------------------------------------------------------------------------------


def last_character(current):
    return getattr(current, "_last_character", "\x00")


def last_string(current):
    s = getattr(current, "_last_string", None)
    if s is None:
        s = current._last_string = new_string_8(current, "")
    return s


def _last(attr, default=0):
    def query(current):
        return getattr(current, attr, default)

    query.__name__ = attr[1:]
    return query


last_integer = last_integer_32 = _last("_last_integer")
last_natural = last_natural_32 = _last("_last_natural")
last_real = last_real_32 = _last("_last_real", 0.0)
last_double = last_real_64 = _last("_last_double", 0.0)
last_integer_8 = _last("_last_integer_8")
last_integer_16 = _last("_last_integer_16")
last_integer_64 = _last("_last_integer_64")
last_natural_8 = _last("_last_natural_8")
last_natural_16 = _last("_last_natural_16")
last_natural_64 = _last("_last_natural_64")


# --- Status report --------------------------------------------------------------------------


def exists(current):
    if is_console(current) or mode(current) != CLOSED:
        return True
    from scoopc.kernel.ext import file  # deferred: a cycle (scoopc.kernel.ext.file imports this module)

    return file.host_exists(current)


def is_open_read(current):
    return mode(current) in _READ_MODES


def is_open_write(current):
    return mode(current) >= WRITE


def is_closed(current):
    return mode(current) == CLOSED


def _permission(current, what):
    console = getattr(current, "_console", None)
    if console is not None:
        return (console == "stdin") == (what == "r")
    from scoopc.kernel.ext import file  # deferred: a cycle (scoopc.kernel.ext.file imports this module)

    return file.host_access(current, what)


def is_readable(current):
    return _permission(current, "r")


def is_writable(current):
    return _permission(current, "w")


def is_executable(current):
    return _permission(current, "x")


def readable(current):
    if mode(current) not in _READ_MODES:
        return False
    chan = getattr(current, "_chan", None)
    lock = getattr(chan, "lock", None)
    if lock is not None:
        with lock:
            chan.sync()
            return not chan.eof
    if chan is None or chan.eof:
        return False
    from scoopc.kernel.ext import file  # deferred: a cycle (scoopc.kernel.ext.file imports this module)

    return file.count(current) > 0


def extendible(current):
    return mode(current) >= WRITE


def is_plain_text(current):
    return True


def bytes_read(current):
    return getattr(current, "_bytes_read", 0)


# --- Status setting -------------------------------------------------------------------------


def close(current):
    chan = getattr(current, "_chan", None)
    current._chan = None
    current._mode = CLOSED
    fh = getattr(chan, "fh", None)
    if fh is not None:
        try:
            fh.close()
        except OSError as e:
            raise fail(current, f"unable to close: {e}", "OPERATING_SYSTEM_FAILURE", e) from e


# --- Output ---------------------------------------------------------------------------------


def put_new_line(current):
    write(current, "\n")


new_line = put_new_line


def put_string(current, s):
    text = s._s
    if text:
        write(current, text)


def put_character(current, c):
    write(current, c)


def put_integer(current, i):
    write(current, str(i))


put_integer_32 = put_natural = put_natural_32 = put_integer
put_integer_8 = put_integer_16 = put_integer_64 = put_integer
put_natural_8 = put_natural_16 = put_natural_64 = put_integer


def put_real(current, r):
    write(current, _real_out(r, True))


put_real_32 = put_real


def put_double(current, d):
    write(current, _real_out(d, False))


put_real_64 = put_double


def put_boolean(current, b):
    write(current, "True" if b else "False")


def flush(current):
    if is_console(current):
        flush_output = getattr(current._region_, "flush_output", None)
        if flush_output is not None:
            flush_output()
        return
    fh = getattr(getattr(current, "_chan", None), "fh", None)
    if fh is not None and mode(current) >= WRITE:
        try:
            fh.flush()
        except OSError as e:
            raise fail(current, f"unable to flush: {e}", cause=e) from e


# --- Input ----------------------------------------------------------------------------------


def _read_number_sequence(current, chan):
    """EiffelBase's integer reading (PLAIN_TEXT_FILE.read_integer_with_no_type and CONSOLE's):
    every character read becomes `last_character` (C's EOF character at the end)."""
    value, sign, started, stop = 0, 1, False, None
    while True:
        c = chan.getc()
        current._last_character = c or _EOF_CHARACTER
        if not c:
            break
        if not started and c in _SEPARATORS:
            continue
        if not started and c in "+-":
            started, sign = True, (-1 if c == "-" else 1)
            continue
        if "0" <= c <= "9":
            started = True
            value = value * 10 + (ord(c) - 48)
            continue
        stop = c  # not part of a number
        break
    if stop is not None:
        if is_console(current):  # CONSOLE: consume the rest of the line
            c = stop
            while c != "\n":
                c = chan.getc()
                current._last_character = c or _EOF_CHARACTER
                if not c:
                    break
        else:  # PLAIN_TEXT_FILE: leave it unread
            chan.unget(stop)
    return sign * value


def _integer_reader(attr, bits, signed):
    def read(current):
        with _Reading(current) as chan:
            setattr(current, attr, _wrap(_read_number_sequence(current, chan), bits, signed))

    read.__name__ = "read" + attr[5:]
    return read


read_integer = read_integer_32 = _integer_reader("_last_integer", 32, True)
read_natural = read_natural_32 = _integer_reader("_last_natural", 32, False)
read_integer_8 = _integer_reader("_last_integer_8", 8, True)
read_integer_16 = _integer_reader("_last_integer_16", 16, True)
read_integer_64 = _integer_reader("_last_integer_64", 64, True)
read_natural_8 = _integer_reader("_last_natural_8", 8, False)
read_natural_16 = _integer_reader("_last_natural_16", 16, False)
read_natural_64 = _integer_reader("_last_natural_64", 64, False)


def _scan_double(current, chan, what):
    """C's `scanf ("%lf")` then EiffelBase's `swallow_nl`; raises IO_FAILURE at the end."""
    c = chan.getc()
    while c and c in _BLANKS:
        c = chan.getc()
    if not c:
        raise fail(current, f"unable to read {what} value")
    text, digits, state = "", False, "sign"  # states: sign, int, frac, exp, expsign, expdigits
    while c:
        if state == "sign" and c in "+-":
            state = "int"
        elif state in ("sign", "int", "frac") and "0" <= c <= "9":
            digits, state = True, ("frac" if state == "frac" else "int")
        elif state in ("sign", "int") and c == ".":
            state = "frac"
        elif state in ("int", "frac") and digits and c in "eE":
            state = "exp"
        elif state == "exp" and c in "+-":
            state = "expsign"
        elif state in ("exp", "expsign", "expdigits") and "0" <= c <= "9":
            state = "expdigits"
        else:
            chan.unget(c)
            break
        text += c
        c = chan.getc()
    if state in ("exp", "expsign"):  # an exponent without digits is no part of it
        text = text[: text.lower().rindex("e")]
    value = float(text) if digits else 0.0
    if is_console(current):  # stdin: one new line
        c = chan.getc()
        if c and c != "\n":
            chan.unget(c)
    else:  # a file: fscanf (f, "\n") skips every blank
        c = chan.getc()
        while c and c in _BLANKS:
            c = chan.getc()
        if c:
            chan.unget(c)
    return value


def read_real(current):
    with _Reading(current) as chan:
        current._last_real = to_single(_scan_double(current, chan, "REAL"))


read_real_32 = read_real


def read_double(current):
    with _Reading(current) as chan:
        current._last_double = _scan_double(current, chan, "DOUBLE")


read_real_64 = read_double


def read_character(current):
    with _Reading(current) as chan:
        current._last_character = chan.getc() or _EOF_CHARACTER


def read_line(current):
    with _Reading(current) as chan:
        line, _ = chan.readline()
    set_last_string(current, line)


def read_word(current):
    with _Reading(current) as chan:
        c = chan.getc()
        while c and c in _BLANKS:
            c = chan.getc()
        word = ""
        while c and c not in _BLANKS:
            word += c
            c = chan.getc()
        if c:
            chan.unget(c)  # the blank after the word stays unread
    set_last_string(current, word)


def read_stream(current, nb_char):
    with _Reading(current) as chan:
        text, n = chan.read(max(nb_char, 0))
    current._bytes_read = n
    set_last_string(current, text)


def next_line_of(current):
    """Skip the rest of the current line (FILE.next_line; CONSOLE's too)."""
    with _Reading(current) as chan:
        chan.readline()
