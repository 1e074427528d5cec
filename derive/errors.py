"""The one base class of every bad-input error (exit status 2 on the command line).

>>> issubclass(InputError, ValueError)
True
"""


class InputError(ValueError):
    """Bad input: a problem file, a set file or a command-line value. One line, naming where."""


class ProblemError(InputError):
    """Bad input in a problem file or on the command line: 'FILE: FIELD: reason'."""
