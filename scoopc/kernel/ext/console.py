"""CONSOLE's `external "Python"` features (stdlib/base/io/console.e): `make_open_stdin`,
`make_open_stdout`, `make_open_stderr`; the rest is IO_MEDIUM's and FILE's, which treat a
console object specially (scoopc.kernel.ext.io_medium).

Output goes through the runtime (`Processor.print` for the standard output, `print_error` for
the standard error): one `put_...` call is written whole. Input reads `sys.stdin` at call
time through `STDIN`, shared by every console object of every region, as C's `stdin`, one
character per byte of its UTF-8 text (EiffelStudio reads bytes).
"""

import sys
import threading

from scoopc.kernel import strings
from scoopc.kernel.ext import io_medium as M


class StdinChan:
    """The process's standard input (`sys.stdin` at call time), shared by every console
    object, as C's `stdin`: characters pushed back in `pb`, one end-of-file flag."""

    def __init__(self):
        self.lock = threading.RLock()
        self.stream = None
        self.pb = ""
        self.eof = False

    def sync(self):
        if sys.stdin is not self.stream:  # replaced (tests): start afresh on the new one
            self.stream, self.pb, self.eof = sys.stdin, "", False

    def _read(self, n):
        """At most `n` bytes of the stream, one character each: from its byte buffer when it has
        one (any bytes, UTF-8 or not), else `n` characters of a text stream as their UTF-8 bytes."""
        stream = self.stream
        if stream is None:
            return ""
        raw = getattr(stream, "buffer", None)
        if raw is not None:
            return raw.read(n).decode("latin-1")
        return strings.utf8_bytes(stream.read(n))

    def _line(self):
        raw = getattr(self.stream, "buffer", None)
        if raw is not None:
            return raw.readline().decode("latin-1")
        return strings.utf8_bytes(self.stream.readline())

    def getc(self):
        if self.eof:
            return ""
        if not self.pb:
            self.pb = self._read(1)
            if not self.pb:
                self.eof = True
                return ""
        c, self.pb = self.pb[0], self.pb[1:]
        return c

    def unget(self, text):
        self.pb = text + self.pb

    def readline(self):
        if self.eof:
            return "", False
        data, self.pb = self.pb, ""
        i = data.find("\n")
        if i < 0 and self.stream is not None:
            data += self._line()
            i = data.find("\n")
        if i < 0:
            self.eof = True
            return data, False
        self.pb = data[i + 1 :]
        return data[:i], True

    def read(self, n):
        if self.eof:
            return "", 0
        data, self.pb = self.pb[:n], self.pb[n:]
        while len(data) < n:
            more = self._read(n - len(data))
            if not more:
                self.eof = True
                break
            data += more
        data, self.pb = data[:n], data[n:] + self.pb
        return data, len(data)


STDIN = StdinChan()


def _attach(current, fn, which, mode, chan):
    current._name = M.text_of(fn)
    current._console = which
    current._mode = mode
    current._chan = chan


def make_open_stdin(current, fn):
    _attach(current, fn, "stdin", M.READ, STDIN)


def make_open_stdout(current, fn):
    _attach(current, fn, "stdout", M.WRITE, None)


def make_open_stderr(current, fn):
    _attach(current, fn, "stderr", M.WRITE, None)
