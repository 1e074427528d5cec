"""derive: a symbolic mechanics engine and worksheet generator for rigid-body rotation.

The package stays light to import: `derive --help` must not load sympy.
"""
from pathlib import Path

#: The name on the package index (`pip install derive-mechanics`); the command is `derive`.
DISTRIBUTION = "derive-mechanics"

#: The most variants one build makes, from the command line or a set file (a course of a few
#: hundred students; a set file cannot ask for unbounded work).
MAX_VARIANTS = 1000


def version() -> str:
    """The installed distribution's version (importlib.metadata); in a source tree that is not
    installed (PYTHONPATH), the version in its pyproject.toml.

    >>> version().count(".") >= 1
    True
    """
    from importlib import metadata

    try:
        return metadata.version(DISTRIBUTION)
    except metadata.PackageNotFoundError:
        import tomllib

        with open(Path(__file__).resolve().parent.parent / "pyproject.toml", "rb") as file:
            return tomllib.load(file)["project"]["version"]
