"""CONDITION_VARIABLE's `external "Python"` features (stdlib/thread/condition_variable.e): a
queue of waiters, each with a lock of its own that `signal` releases (as Python's own
threading.Condition does), over the MUTEX's threads.Mutex."""

import threading
from collections import deque

from .. import threads


def initialize(current):
    current._waiters_ = deque()
    current._waiters_lock_ = threading.Lock()


def is_set(current):
    return current.__dict__.get("_waiters_") is not None


def host_signal(current):
    with current._waiters_lock_:
        if current._waiters_:
            current._waiters_.popleft().release()


def host_broadcast(current):
    with current._waiters_lock_:
        while current._waiters_:
            current._waiters_.popleft().release()


def _wait(current, a_mutex, timeout):
    rt = threads.runtime_of(current)
    waiter = threading.Lock()
    waiter.acquire()
    with current._waiters_lock_:
        current._waiters_.append(waiter)
    mutex = a_mutex._mutex_
    count = mutex.release_all()
    signalled = False
    try:
        signalled = threads.wait_for(lambda seconds: waiter.acquire(timeout=seconds), rt, timeout)
    finally:
        if not signalled:
            with current._waiters_lock_:
                try:
                    current._waiters_.remove(waiter)
                except ValueError:  # signalled just after the timeout: count it
                    signalled = True
        mutex.restore(count, None)
    return signalled


def host_wait(current, a_mutex):
    _wait(current, a_mutex, None)


def host_wait_with_timeout(current, a_mutex, a_timeout):
    return _wait(current, a_mutex, a_timeout / 1000.0)


def host_destroy(current):
    current._waiters_ = None
