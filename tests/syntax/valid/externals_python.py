"""The Python side of tests/syntax/valid/externals_python.e: the external without an alias
(`log_message`) calls the function named like it in the module named like its class."""

import logging


def log_message(message):
    logging.getLogger("externals_python").info(message)
