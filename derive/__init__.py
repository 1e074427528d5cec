"""derive: a symbolic mechanics engine and worksheet generator for rigid-body rotation.

The package stays light to import: `derive --help` must not load sympy. The Python API
(derive.api: `derive.load`, `derive.solve`, `derive.sheet`) is imported on first use.
"""
from importlib import import_module as _import_module

from derive.core.library import DISTRIBUTION, version
from derive.core.limits import MAX_DIGITS, MAX_VARIANTS

__all__ = ["load", "solve", "sheet", "version", "DISTRIBUTION", "MAX_VARIANTS", "MAX_DIGITS"]


def __getattr__(name: str):
    """The API's functions, imported when first used (they import sympy)."""
    if name in ("load", "solve", "sheet"):
        return getattr(_import_module("derive.api"), name)
    if name == "__version__":
        return version()
    raise AttributeError(f"module 'derive' has no attribute {name!r}")


def __dir__() -> list[str]:
    return sorted({*globals(), *__all__})
