"""The one base class of every bad-input error (exit status 2 on the command line).

>>> issubclass(InputError, ValueError)
True
>>> str(InputError("f.yaml: a\\nb: unknown key"))
'f.yaml: a\\\\nb: unknown key'
"""


class InputError(ValueError):
    """Bad input: a problem file, a set file or a command-line value. One line, naming where
    (line breaks and other control characters a file put in a name are shown escaped)."""

    def __str__(self) -> str:
        text = super().__str__()
        if text.isprintable():
            return text
        return "".join(c if c.isprintable() else repr(c)[1:-1] for c in text)


class ProblemError(InputError):
    """Bad input in a problem file or on the command line: 'FILE: FIELD: reason'."""


class EngineLimit(RuntimeError):
    """A setup the file states correctly but derive cannot yet derive: exit status 1, one line
    that begins "derive cannot yet", so that the file is not blamed.

    >>> str(EngineLimit("f.yaml", "decide the friction regimes of two contacts at once"))
    'f.yaml: derive cannot yet decide the friction regimes of two contacts at once'
    """

    def __init__(self, where: str, what: str):
        super().__init__(f"{where}: derive cannot yet {what}")


class MissingTool(Exception):
    """An external program derive needs (latexmk, pdflatex, pandoc) is not installed: exit status
    3, one line with the command that installs it.

    >>> str(MissingTool("latexmk", "apt-get install -y latexmk"))
    'latexmk is not installed; install it with: apt-get install -y latexmk'
    """

    def __init__(self, tool: str, install: str):
        super().__init__(f"{tool} is not installed; install it with: {install}")
        self.tool, self.install = tool, install


class Terminated(KeyboardInterrupt):
    """SIGTERM, raised by the command line's handler: a build stops and cleans up as on Ctrl-C
    (every `except KeyboardInterrupt` and `except BaseException` sees it), exit status 143."""
