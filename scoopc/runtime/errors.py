"""Exceptions the SCOOP runtime raises into generated code, and the run-time failure record."""

from __future__ import annotations


class ScoopError(Exception):
    """Base class of the runtime's own exceptions."""


class PreconditionViolation(ScoopError):
    """A precondition clause is false and is not a wait condition (no newly reserved target)."""

    def __init__(self, tag: str | None, where: object) -> None:
        super().__init__(f"precondition {tag or '(untagged)'} violated at {fmt_where(where)}")
        self.tag, self.where = tag, where


class DirtyRegionError(ScoopError):
    """EiffelStudio's dirty processor exception: a synchronous call on a region where an
    earlier asynchronous call of this reservation failed (the call is not executed), or a
    synchronous call that failed itself; `__cause__` is that failure."""

    asynchronous = False  # True: the failure was an earlier asynchronous call's
    proc: object = None  # the region whose call failed
    noticed: object = None  # where the general path raises it, if not where it was (direct.py)


DIRTY_TAG = "EVE/Qs dirty processor exception"


def dirty_error(proc: object, failure: BaseException | None) -> DirtyRegionError:
    """The exception a client gets instead of its synchronous call on dirty `proc`."""
    error = DirtyRegionError(f"{DIRTY_TAG}: an earlier asynchronous call on {proc} failed")
    error.asynchronous = True
    error.proc = proc
    error.__cause__ = failure
    return error


def sync_failure(proc: object, failure: Exception) -> Exception:
    """What a client gets when its synchronous call (query, lock-passing call, callback) on
    the active region `proc` fails: EiffelStudio's supplier marks itself dirty, then, the
    call being synchronous, cleans itself and answers SCOOP_MESSAGE_DIRTY, on which the
    client raises its dirty processor exception (processor.c, `rt_processor_execute_call`;
    private_queue.c, `rt_private_queue_log_call`). Calls on passive regions and on the
    client's own region are plain calls there too: their failures are not wrapped."""
    if isinstance(failure, DeadlockError):
        return failure
    error = DirtyRegionError(f"{DIRTY_TAG}: a synchronous call on {proc} failed")
    error.proc = proc
    error.__cause__ = failure
    return error


class UncontrolledTarget(ScoopError):
    """A separate call on a region the client does not hold: a compiler bug, not a user error."""


class Shutdown(BaseException):
    """Raised in processors when the runtime shuts down (Ctrl-C, deadlock, fatal failure).
    A BaseException so Eiffel `rescue` clauses (which catch Exception) do not swallow it."""


class DeadlockError(ScoopError):
    """Ends the root routine when a deadlock was detected; the report is in `args[0]`."""


# The `where` of the private queue a separate creation opens: its report names the creation.
# Compared by value (`==`): a compiled runtime (docs/RUNTIME.md section 10) copies tuples.
CREATION: tuple[str, str, str, int] = ("", "creation", "", 0)


def fmt_where(where: object) -> str:
    """`(class, routine, file, line)` -> 'CLASS.routine (file:line)'; tolerant of None/str."""
    if where is None:
        return "?"
    if isinstance(where, tuple) and len(where) == 4:
        cls, routine, file, line = where
        return f"{cls}.{routine} ({file}:{line})"
    return str(where)


# Raised through user code untouched by the paths that turn a call's failure into a dirty
# region: the runtime's own stop signal, and Ctrl-C arriving on the main thread while it runs
# a call on a supplier's behalf (client-executed), which must stop the program, not be "lost".
PASS_THROUGH = (Shutdown, KeyboardInterrupt)
