"""EiffelThread on Python threads: what THREAD, MUTEX, SEMAPHORE, CONDITION_VARIABLE and
READ_WRITE_LOCK (stdlib/thread/, externals in scoopc/kernel/ext/) share.

A thread launched by an Eiffel THREAD is a daemon Python thread that runs the object's routines
on behalf of the THREAD object's region (every object of a thread system lives in the root's
region: there is no `separate`). It has once values of its own (runtime/once.py), a list of the
threads it launched (`join_all` waits for them) and its own `is_last_launch_successful`.

Every wait (join, lock, wait, acquire) waits in slices and gives up with the runtime's
`Shutdown` when the run stops (a failure in another thread, Ctrl-C), so a program never hangs
on a thread that died. An exception that escapes `execute` ends the program as EiffelStudio's
does (its report and Eiffel trace, exit status 3): the runtime is told through `rt.fail`.
"""

from __future__ import annotations

import threading
import time

from ..runtime import Shutdown
from ..runtime.once import begin_thread_onces

SLICE = 0.05  # seconds between two looks at the runtime's stop flag

_local = threading.local()  # per Python thread: children, last launch, Eiffel thread state


class ThreadExit(BaseException):
    """`exit` of the calling Eiffel thread: not an Eiffel exception (rescue does not see it)."""


class ThreadState:
    """The Python side of one THREAD object."""

    __slots__ = ("thread", "ident", "terminated", "done", "launching")

    def __init__(self):
        self.thread = None  # the threading.Thread once launched
        self.ident = 0  # `thread_id': the running thread's identifier, 0 otherwise
        self.terminated = False
        self.done = threading.Event()
        self.launching = threading.Lock()


def state(obj) -> ThreadState:
    found = obj.__dict__.get("_thread_state_")
    if found is None:
        found = obj.__dict__.setdefault("_thread_state_", ThreadState())
    return found


def current_ident() -> int:
    return threading.get_ident()


def in_eiffel_thread() -> bool:
    """Is the calling thread one an Eiffel THREAD launched?"""
    return getattr(_local, "eiffel", False)


def _children() -> list:
    found = getattr(_local, "children", None)
    if found is None:
        found = _local.children = []
    return found


def last_launch_successful() -> bool:
    return getattr(_local, "launched", False)


def runtime_of(obj):
    return obj._region_.rt


def stopping(rt) -> bool:
    return rt is not None and rt.stopping


def wait_for(acquire, rt, timeout=None) -> bool:
    """Call `acquire(seconds)` (True when it got what it waits for) in slices until it succeeds,
    `timeout` seconds have passed (False) or the run stops (Shutdown)."""
    deadline = None if timeout is None else time.monotonic() + timeout
    while True:
        if stopping(rt):
            raise Shutdown()
        left = SLICE if deadline is None else min(SLICE, deadline - time.monotonic())
        if acquire(max(left, 0.0)):
            return True
        if deadline is not None and time.monotonic() >= deadline:
            return False


def launch(obj, body) -> None:
    """Start a thread running `body()` (THREAD.thr_main) for THREAD object `obj`."""
    st = state(obj)
    rt = runtime_of(obj)
    with st.launching:
        if st.thread is not None:  # another thread launched it first
            _local.launched = False
            return
        thread = threading.Thread(
            target=_run, args=(st, rt, obj._region_, body), daemon=True, name=f"eiffel-thread-{type(obj).__name__}"
        )
        st.thread = thread
        thread.start()
        st.ident = thread.ident or 0
    _children().append(st)
    _local.launched = True


def _run(st, rt, region, body) -> None:
    _local.eiffel = True
    begin_thread_onces()
    try:
        body()
    except (ThreadExit, Shutdown):
        pass
    except BaseException as error:  # noqa: BLE001 - an uncaught exception ends the program
        if rt is not None and not rt.stopping:
            describe = rt.describe
            text = describe(error, region) if describe is not None else f"{type(error).__name__}: {error}"
            rt.fail(text, error)
    finally:
        st.terminated = True
        st.ident = 0
        st.done.set()


def join(obj, timeout_ms=None) -> bool:
    """Wait until `obj`'s thread has terminated (at most `timeout_ms` milliseconds)."""
    st = state(obj)
    if st.terminated or st.thread is None:
        return st.terminated or st.thread is None
    timeout = None if timeout_ms is None else timeout_ms / 1000.0
    return wait_for(st.done.wait, runtime_of(obj), timeout)


def join_all(obj) -> None:
    """Wait until every thread launched by the calling thread has terminated."""
    rt = runtime_of(obj)
    children = _children()
    for st in list(children):
        wait_for(st.done.wait, rt)
    children[:] = [st for st in children if not st.terminated]


def sleep(obj, nanoseconds) -> None:
    """Suspend the calling thread (real time; the run's stop ends the sleep with Shutdown)."""
    rt = runtime_of(obj)
    deadline = time.monotonic() + nanoseconds / 1e9
    while True:
        if stopping(rt):
            raise Shutdown()
        left = deadline - time.monotonic()
        if left <= 0:
            return
        time.sleep(min(left, SLICE))


class Mutex:
    """A mutex the owning thread may lock again (counted), as a Windows critical section; only
    its owner may unlock it (MUTEX's precondition)."""

    __slots__ = ("lock", "owner", "count")

    def __init__(self):
        self.lock = threading.Lock()
        self.owner = 0
        self.count = 0

    def held_here(self) -> bool:
        return self.owner == threading.get_ident()

    def acquire(self, rt) -> None:
        me = threading.get_ident()
        if self.owner == me:
            self.count += 1
            return
        wait_for(lambda seconds: self.lock.acquire(timeout=seconds) if seconds > 0 else self.lock.acquire(False), rt)
        self.owner, self.count = me, 1

    def try_acquire(self) -> bool:
        me = threading.get_ident()
        if self.owner == me:
            self.count += 1
            return True
        if self.lock.acquire(False):
            self.owner, self.count = me, 1
            return True
        return False

    def release(self) -> None:
        self.count -= 1
        if self.count == 0:
            self.owner = 0
            self.lock.release()

    def release_all(self) -> int:
        """Unlock completely (a condition variable's wait); the count to restore."""
        count, self.count, self.owner = self.count, 0, 0
        self.lock.release()
        return count

    def restore(self, count, rt) -> None:
        wait_for(lambda seconds: self.lock.acquire(timeout=seconds) if seconds > 0 else self.lock.acquire(False), rt)
        self.owner, self.count = threading.get_ident(), count
