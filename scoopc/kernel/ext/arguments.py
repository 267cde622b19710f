"""ARGUMENTS' `external "Python"` features (stdlib/base/kernel/arguments.e).

The program's command line is `PROGRAM`: index 0 is the command name (EiffelBase's
`argument (0)`), then the arguments. The launcher (scoopc.kernel.launcher) sets it with `set_arguments`
before the root creation procedure runs; ARGUMENTS_32 reads the same list.
"""

from scoopc.kernel import strings
from scoopc.kernel.launcher import PROGRAM, set_arguments  # noqa: F401 - set_arguments: tests and embedders


def argument_count(current):
    return len(PROGRAM) - 1


def i_th_argument(current, i):
    """A new STRING_8 holding the `i`-th argument (the command name for 0): its bytes, as C's
    `argv` has them (ARGUMENTS_32 has its characters)."""
    if i < 0:
        raise IndexError(f"argument index {i} is negative")
    return strings.new_string_8_of(current._region_, PROGRAM[i])
