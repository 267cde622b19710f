"""SEMAPHORE's `external "Python"` features (stdlib/thread/semaphore.e): threading.Semaphore,
waited on in slices (threads.wait_for) so a stopped run never leaves a thread waiting."""

import threading

from .. import threads


def initialize(current, a_count):
    current._semaphore_ = threading.Semaphore(a_count)


def is_set(current):
    return current.__dict__.get("_semaphore_") is not None


def host_wait(current):
    semaphore = current._semaphore_
    threads.wait_for(lambda seconds: semaphore.acquire(timeout=seconds), threads.runtime_of(current))


def host_try_wait(current):
    return current._semaphore_.acquire(False)


def host_post(current):
    current._semaphore_.release()


def host_destroy(current):
    current._semaphore_ = None
