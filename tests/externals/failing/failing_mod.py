"""The user's module of tests/externals/failing."""


def ratio(a, b):
    return a / b
