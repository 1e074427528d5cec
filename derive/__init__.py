"""derive: a symbolic mechanics engine and worksheet generator for rigid-body rotation.

The package stays light to import: `derive --help` must not load sympy. The Python API
(derive.api: `derive.load`, `derive.solve`, `derive.sheet`) is imported on first use.
"""
from importlib import import_module as _import_module
from pathlib import Path

#: The name on the package index (`pip install derive-mechanics`); the command is `derive`.
DISTRIBUTION = "derive-mechanics"
__all__ = ["load", "solve", "sheet", "version", "MAX_VARIANTS", "MAX_DIGITS"]

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


#: The most significant digits a value is computed to (`--digits`, `digits=`).
MAX_DIGITS = 50


def __getattr__(name: str):
    """The API's functions, imported when first used (they import sympy)."""
    if name in ("load", "solve", "sheet"):
        return getattr(_import_module("derive.api"), name)
    if name == "__version__":
        return version()
    raise AttributeError(f"module 'derive' has no attribute {name!r}")


def __dir__() -> list[str]:
    return sorted({*globals(), *__all__})
