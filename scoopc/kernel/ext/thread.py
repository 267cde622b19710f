"""THREAD's `external "Python"` features (stdlib/thread/thread.e): a daemon Python thread per
launch, running the frozen `thr_main` (which calls `execute`); scoopc/kernel/threads.py."""

from .. import threads


def thread_id(current):
    return threads.state(current).ident


def terminated(current):
    return threads.state(current).terminated


def is_launchable(current):
    return threads.state(current).thread is None


def is_last_launch_successful(current):
    return threads.last_launch_successful()


def start_thread(current):
    threads.launch(current, current.thr_main)


def reset_launch_state(current):
    current.__dict__["_thread_state_"] = threads.ThreadState()


def host_exit(current):
    raise threads.ThreadExit()


def join(current):
    threads.join(current)


def join_with_timeout(current, a_timeout_ms):
    return threads.join(current, a_timeout_ms)
