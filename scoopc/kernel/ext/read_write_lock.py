"""READ_WRITE_LOCK's `external "Python"` features (stdlib/thread/read_write_lock.e): readers
and a writer counted under one threading.Condition; a waiting writer holds new readers back,
so writers are not starved."""

import threading

from .. import threads


class _Lock:
    __slots__ = ("condition", "readers", "writer", "writers_waiting")

    def __init__(self):
        self.condition = threading.Condition(threading.Lock())
        self.readers = {}  # thread ident -> 1 for each thread holding the read lock
        self.writer = 0  # ident of the thread holding the write lock, 0 if none
        self.writers_waiting = 0


def initialize(current):
    current._rwlock_ = _Lock()


def is_set(current):
    return current.__dict__.get("_rwlock_") is not None


def host_is_read_locked_by_current_thread(current):
    return threading.get_ident() in current._rwlock_.readers


def host_is_write_locked_by_current_thread(current):
    return current._rwlock_.writer == threading.get_ident()


def _acquire(current, ready, take):
    lock = current._rwlock_
    rt = threads.runtime_of(current)

    def attempt(seconds):
        if ready(lock):
            take(lock)
            return True
        lock.condition.wait(seconds)
        if ready(lock):
            take(lock)
            return True
        return False

    with lock.condition:
        threads.wait_for(attempt, rt)


def host_acquire_read_lock(current):
    me = threading.get_ident()
    _acquire(
        current,
        lambda lock: lock.writer == 0 and lock.writers_waiting == 0,
        lambda lock: lock.readers.__setitem__(me, 1),
    )


def host_acquire_write_lock(current):
    me = threading.get_ident()
    lock = current._rwlock_
    with lock.condition:
        lock.writers_waiting += 1
    try:

        def take(lock):
            lock.writer = me
            lock.writers_waiting -= 1

        _acquire(current, lambda lock: lock.writer == 0 and not lock.readers, take)
    except BaseException:
        with lock.condition:
            if lock.writer != me:
                lock.writers_waiting -= 1
            lock.condition.notify_all()
        raise


def host_release_reader_lock(current):
    lock = current._rwlock_
    with lock.condition:
        del lock.readers[threading.get_ident()]
        lock.condition.notify_all()


def host_release_writer_lock(current):
    lock = current._rwlock_
    with lock.condition:
        lock.writer = 0
        lock.condition.notify_all()


def host_destroy(current):
    current._rwlock_ = None
