"""Every docstring example in derive runs and prints what it shows (the examples are how the next
person learns a module: a wrong one teaches wrong)."""
import doctest
import importlib
import pkgutil
from pathlib import Path

import pytest

import derive

MODULES = sorted(m.name for m in pkgutil.walk_packages(derive.__path__, "derive.") if m.name != "derive.__main__")


@pytest.mark.parametrize("name", MODULES)
def test_docstring_examples(name, monkeypatch):
    monkeypatch.chdir(Path(derive.__file__).parent.parent)  # examples load the library's files
    result = doctest.testmod(importlib.import_module(name), optionflags=doctest.ELLIPSIS)
    assert result.failed == 0, f"{result.failed} of {result.attempted} examples in {name} fail"
