"""ARGUMENTS_32's `external "Python"` features (stdlib/base/kernel/arguments_32.e); the command
line is `scoopc.kernel.ext.arguments.PROGRAM`."""

from scoopc.kernel.ext import arguments as _arguments


def argument_count(current):
    return len(_arguments.PROGRAM) - 1


def i_th_argument(current, i):
    """A new IMMUTABLE_STRING_32 holding the `i`-th argument (the command name for 0)."""
    from scoopc.kernel import strings

    if i < 0:
        raise IndexError(f"argument index {i} is negative")
    return strings.new_immutable_32(current._region_, _arguments.PROGRAM[i])
