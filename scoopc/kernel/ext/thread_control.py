"""THREAD_CONTROL's `external "Python"` features (stdlib/thread/thread_control.e): the calling
Python thread (scoopc/kernel/threads.py)."""

import time

from .. import threads


def current_thread_id(current):
    return threads.current_ident()


def yield_(current):
    time.sleep(0)


def join_all(current):
    threads.join_all(current)


def host_sleep(current, nanoseconds):
    threads.sleep(current, nanoseconds)
