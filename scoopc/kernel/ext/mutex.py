"""MUTEX's `external "Python"` features (stdlib/thread/mutex.e): threads.Mutex (re-entrant for
its owner, unlocked only by its owner: the Eiffel preconditions guard both)."""

from .. import threads


def initialize(current):
    current._mutex_ = threads.Mutex()


def _mutex(current):
    return current.__dict__.get("_mutex_")


def is_set(current):
    return _mutex(current) is not None


def host_is_locked_by_current_thread(current):
    return current._mutex_.held_here()


def host_lock(current):
    current._mutex_.acquire(threads.runtime_of(current))


def host_try_lock(current):
    return current._mutex_.try_acquire()


def host_unlock(current):
    current._mutex_.release()


def host_destroy(current):
    current._mutex_ = None
