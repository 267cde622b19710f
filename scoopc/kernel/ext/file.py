"""FILE's `external "Python"` features (stdlib/base/io/file.e), for PLAIN_TEXT_FILE and CONSOLE.

A file object's host state is described in scoopc.kernel.ext.io_medium; `FileChan` is its open
channel (a binary Python file). Opening modes are EiffelBase's (C's fopen "r", "w", "a", "r+",
"w+", "a+"; "a+" reads from the start, as glibc). Failures of the operating system (a file that
cannot be opened, renamed, deleted, ...) raise OPERATING_SYSTEM_FAILURE, as EiffelStudio's `esys`.
Status queries on a file name (`exists`, `is_plain`, `date`, ...) follow symbolic links, except
`path_exists` and `is_symlink`.
"""

import os
import stat as _stat

from scoopc.kernel import strings
from scoopc.kernel.ext import io_medium as M


def decode(data):
    """Bytes read as 8-bit characters, one each."""
    return bytes(data).decode("latin-1")


def encode(text):
    """8-bit characters as the bytes they are."""
    return strings.raw_bytes(text)


class FileChan:
    """An open file: a binary Python file, with bytes read ahead or pushed back in `pb`."""

    def __init__(self, fh):
        self.fh = fh
        self.pb = bytearray()
        self.eof = False

    def _fill(self, n):
        """Have at least `n` bytes in `pb` if the file holds them (never sets `eof`)."""
        while len(self.pb) < n:
            data = self.fh.read(n - len(self.pb))
            if not data:
                return False
            self.pb += data
        return True

    def getc(self):
        """The next character (one byte), or '' at the end."""
        if self.eof or not self._fill(1):
            self.eof = True
            return ""
        c = chr(self.pb[0])
        del self.pb[:1]
        return c

    def unget(self, text):
        self.pb[0:0] = encode(text)

    def readline(self):
        """(line without its new line, whether a new line ended it)."""
        if self.eof:
            return "", False
        data = bytes(self.pb)
        self.pb.clear()
        i = data.find(b"\n")
        if i < 0:
            data += self.fh.readline()
            i = data.find(b"\n")
        if i < 0:
            self.eof = True
            return decode(data), False
        self.pb[:] = data[i + 1 :]
        return decode(data[:i]), True

    def read(self, n):
        """At most `n` bytes: (text, number of bytes)."""
        if self.eof:
            return "", 0
        self._fill(n)
        data = bytes(self.pb[:n])
        del self.pb[:n]
        if len(data) < n:
            self.eof = True
        return decode(data), len(data)

    def sync(self):
        """Give back what was read ahead, so the file's own position is the medium's."""
        if self.pb:
            try:
                self.fh.seek(-len(self.pb), 1)
            except (OSError, ValueError):
                pass
            self.pb.clear()

    def write(self, text):
        self.sync()
        self.fh.write(encode(text))

    def seek(self, offset, whence):
        self.sync()
        self.fh.seek(offset, whence)
        self.eof = False

    def tell(self):
        return self.fh.tell() - len(self.pb)


# --- host helpers (also used by io_medium) -----------------------------------------------


def _name(current):
    return getattr(current, "_name", "")


def _os_fail(current, what, e):
    return M.fail(current, f"{what}: {e.strerror or e}", "OPERATING_SYSTEM_FAILURE", e)


def _stat_of(current, follow=True):
    try:
        return os.stat(_name(current)) if follow else os.lstat(_name(current))
    except OSError as e:
        raise _os_fail(current, "unable to get the file's status", e) from e


def host_exists(current):
    return os.path.exists(_name(current))


def host_access(current, what):
    flag = {"r": os.R_OK, "w": os.W_OK, "x": os.X_OK}[what]
    if os.access in os.supports_effective_ids:
        return os.access(_name(current), flag, effective_ids=True)
    return os.access(_name(current), flag)


def _designate(current, fn):
    current._name = M.text_of(fn)
    current._mode = M.CLOSED
    current._chan = None
    current._console = None


_PYTHON_MODES = {M.READ: "rb", M.WRITE: "wb", M.APPEND: "ab", M.READ_WRITE: "r+b", M.APPEND_READ: "a+b"}


def _open(current, mode, python_mode=None):
    try:
        fh = open(_name(current), python_mode or _PYTHON_MODES[mode])
        if mode == M.APPEND_READ:
            fh.seek(0)  # reading starts at the beginning; writes append
    except OSError as e:
        raise _os_fail(current, "unable to open", e) from e
    current._chan = FileChan(fh)
    current._mode = mode


def _chan(current):
    chan = getattr(current, "_chan", None)
    if chan is None:
        raise M.fail(current, "file not open")
    if not hasattr(chan, "seek"):
        raise _os_fail(current, "cannot move in the standard input", OSError("not seekable"))
    return chan


def _wrap32(n):
    return ((n + 2**31) % 2**32) - 2**31


# --- Initialization -----------------------------------------------------------------------


def make_with_name(current, fn):
    _designate(current, fn)


make = make_with_name


def make_open_read(current, fn):
    _designate(current, fn)
    _open(current, M.READ)


def make_open_write(current, fn):
    _designate(current, fn)
    _open(current, M.WRITE)


def make_open_append(current, fn):
    _designate(current, fn)
    _open(current, M.APPEND)


def make_open_read_write(current, fn):
    _designate(current, fn)
    _open(current, M.READ_WRITE)


def make_create_read_write(current, fn):
    _designate(current, fn)
    _open(current, M.READ_WRITE, "w+b")


def make_open_read_append(current, fn):
    _designate(current, fn)
    _open(current, M.APPEND_READ)


# --- Access -------------------------------------------------------------------------------


def name(current):
    return M.new_string_8(current, _name(current))


def position(current):
    chan = getattr(current, "_chan", None)
    if chan is None or not hasattr(chan, "tell"):
        return 0
    return chan.tell()


def date(current):
    return _wrap32(int(_stat_of(current).st_mtime))


def access_date(current):
    return _wrap32(int(_stat_of(current).st_atime))


def change_date(current):
    return _wrap32(int(_stat_of(current).st_ctime))


# --- Measurement --------------------------------------------------------------------------


def count(current):
    """Size in bytes (0 if there is no such file); 1 for the console, as EiffelBase's."""
    if M.is_console(current):
        return 1
    fh = getattr(getattr(current, "_chan", None), "fh", None)
    try:
        if fh is not None:
            if M.mode(current) >= M.WRITE:
                fh.flush()
            return _wrap32(os.fstat(fh.fileno()).st_size)
        return _wrap32(os.stat(_name(current)).st_size)
    except OSError:
        return 0


# --- Status report ------------------------------------------------------------------------


def is_open_append(current):
    return M.mode(current) in (M.APPEND, M.APPEND_READ)


def end_of_file(current):
    chan = getattr(current, "_chan", None)
    if chan is None:
        return False
    lock = getattr(chan, "lock", None)
    if lock is not None:
        with lock:
            chan.sync()
            return chan.eof
    return chan.eof


def after(current):
    return M.mode(current) != M.CLOSED and (end_of_file(current) or count(current) == 0)


def off(current):
    return count(current) == 0 or M.mode(current) == M.CLOSED or end_of_file(current)


def is_empty(current):
    return not M.is_console(current) and count(current) == 0


def path_exists(current):
    return os.path.lexists(_name(current))


def is_creatable(current):
    """No such file yet, and its directory exists and may be written."""
    path = _name(current)
    if os.path.exists(path):
        return False
    parent = os.path.dirname(os.path.abspath(path))
    return os.path.isdir(parent) and os.access(parent, os.W_OK | os.X_OK)


def _mode_is(test, follow=True):
    def query(current):
        return bool(test(_stat_of(current, follow).st_mode))

    return query


is_plain = _mode_is(_stat.S_ISREG)
is_directory = _mode_is(_stat.S_ISDIR)
is_device = _mode_is(lambda m: _stat.S_ISCHR(m) or _stat.S_ISBLK(m))
is_block = _mode_is(_stat.S_ISBLK)
is_character = _mode_is(_stat.S_ISCHR)
is_fifo = _mode_is(_stat.S_ISFIFO)
is_socket = _mode_is(_stat.S_ISSOCK)
is_symlink = _mode_is(_stat.S_ISLNK, follow=False)


# --- Status setting -----------------------------------------------------------------------


def open_read(current):
    _open(current, M.READ)


def open_write(current):
    _open(current, M.WRITE)


def open_append(current):
    _open(current, M.APPEND)


def open_read_write(current):
    _open(current, M.READ_WRITE)


def create_read_write(current):
    _open(current, M.READ_WRITE, "w+b")


def open_read_append(current):
    _open(current, M.APPEND_READ)


# --- Cursor movement ----------------------------------------------------------------------


def _seek(current, offset, whence):
    chan = _chan(current)
    try:
        chan.seek(offset, whence)
    except (OSError, ValueError) as e:
        raise _os_fail(current, "unable to move", e if isinstance(e, OSError) else OSError(str(e))) from e


def start(current):
    _seek(current, 0, os.SEEK_SET)


def finish(current):
    _seek(current, 0, os.SEEK_END)


def go(current, abs_position):
    _seek(current, abs_position, os.SEEK_SET)


def move(current, offset):
    _seek(current, offset, os.SEEK_CUR)


def next_line(current):
    M.next_line_of(current)


# --- Element change -----------------------------------------------------------------------


def reset(current, fn):
    if M.mode(current) != M.CLOSED:
        M.close(current)
    current._name = M.text_of(fn)
    M.reset_lasts(current)


def rename_file(current, new_name):
    new = M.text_of(new_name)
    try:
        os.rename(_name(current), new)
    except OSError as e:
        raise _os_fail(current, f"unable to rename to {new}", e) from e
    current._name = new


def touch(current):
    try:
        os.utime(_name(current), None)
    except OSError as e:
        raise _os_fail(current, "unable to touch", e) from e


def delete(current):
    path = _name(current)
    try:
        if os.path.isdir(path) and not os.path.islink(path):
            os.rmdir(path)
        else:
            os.unlink(path)
    except OSError as e:
        raise _os_fail(current, "unable to delete", e) from e


def wipe_out(current):
    try:
        open(_name(current), "wb").close()
    except OSError as e:
        raise _os_fail(current, "unable to empty", e) from e


# --- Implementation -----------------------------------------------------------------------


def path_name(current):
    return strings.new_string_32(current._region_, _name(current))
