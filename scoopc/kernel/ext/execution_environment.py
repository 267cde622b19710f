"""EXECUTION_ENVIRONMENT's `external "Python"` features
(stdlib/base/kernel/execution_environment.e).

`sleep` uses the runtime clock (`Processor.sleep`), so a sleeping processor lets the others
run and virtual time works. `system` runs the command through the shell, with the program's
standard streams (flushed first), and waits; `return_code` is then its exit status (the
negated signal number if a signal ended it). `change_working_directory` sets `return_code`
to 0, or -1 on failure, as EiffelBase does.
"""

import os
import subprocess
import sys


def _s8(current, value):
    from scoopc.kernel import strings

    return strings.new_string_8(current._region_, value)


def _s32(current, value):
    from scoopc.kernel import strings

    return strings.new_string_32(current._region_, value)


def _text(obj):
    from scoopc.kernel import strings

    return strings.text(obj)


def item(current, key):
    value = os.environ.get(_text(key))
    return None if value is None else _s32(current, value)


def current_working_directory(current):
    return _s8(current, os.getcwd())


def home_directory_name(current):
    home = os.path.expanduser("~")
    return None if home == "~" else _s8(current, home)


def root_directory_name(current):
    if os.name == "nt":
        drive = os.path.splitdrive(os.getcwd())[0]
        return _s8(current, drive + "\\")
    return _s8(current, "/")


def default_shell(current):
    if os.name == "nt":
        shell = os.environ.get("COMSPEC") or "cmd.exe"
    else:
        shell = os.environ.get("SHELL") or "/bin/sh"
    return _s32(current, shell)


def available_cpu_count(current):
    return os.cpu_count() or 1


def return_code(current):
    return getattr(current, "_return_code", 0)


def put(current, value, key):
    os.environ[_text(key)] = _text(value)


def change_working_directory(current, path):
    try:
        os.chdir(_text(path))
        current._return_code = 0
    except OSError:
        current._return_code = -1


def sleep(current, nanoseconds):
    current._region_.sleep(nanoseconds)


def _flush_all(current):
    flush = getattr(current._region_, "flush_output", None)
    if flush is not None:
        flush()
    for stream in (sys.stdout, sys.stderr):
        try:
            stream.flush()
        except (OSError, ValueError):
            pass


def system(current, s):
    _flush_all(current)
    try:
        current._return_code = subprocess.run(_text(s), shell=True).returncode
    except OSError:
        current._return_code = -1


def launch(current, s):
    _flush_all(current)
    try:
        subprocess.Popen(_text(s), shell=True)
    except OSError:
        pass
