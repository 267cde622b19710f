"""TIMER's `external "Python"` features (stdlib/roboscoop/util/timer.e): the runtime's clock
(virtual with `--virtual-clock`), in seconds."""
import scoopc.runtime as rt


def now(current):
    return rt.now_ns() / 1e9
