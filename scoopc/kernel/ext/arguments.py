"""ARGUMENTS' `external "Python"` features (stdlib/base/kernel/arguments.e).

The program's command line is `PROGRAM`: index 0 is the command name (EiffelBase's
`argument (0)`), then the arguments. The launcher sets it with `set_arguments` before the root
creation procedure runs; ARGUMENTS_32 reads the same list.
"""
import sys

PROGRAM = [sys.argv[0] if sys.argv and sys.argv[0] else "program"]


def set_arguments(args):
    """Make `args` (command name first, then the arguments: strings) the program's command line."""
    args = [str(a) for a in args]
    if not args:
        raise ValueError("set_arguments: the command name (index 0) is required")
    PROGRAM[:] = args


def argument_count(current):
    return len(PROGRAM) - 1


def i_th_argument(current, i):
    """A new STRING_8 holding the `i`-th argument (the command name for 0)."""
    from scoopc.kernel import strings
    if i < 0:
        raise IndexError(f"argument index {i} is negative")
    return strings.new_string_8(current._region_, PROGRAM[i])
