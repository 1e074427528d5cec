"""Where problems, sets and templates live, how an id becomes a file, and the installed version.

The library is the `problems/` folder of the source tree (or its copy inside an installed
wheel), or the folder named by the DERIVE_LIBRARY environment variable.

>>> find_problem("string_wrapped_disk").name
'string_wrapped_disk.yaml'
"""
from __future__ import annotations

import os
import re
from collections.abc import Callable
from pathlib import Path

from derive.core.errors import InputError
from derive.core.spelling import did_you_mean

_PACKAGE = Path(__file__).resolve().parent.parent  # the derive package
#: The name on the package index (`pip install derive-mechanics`); the command is `derive`.
DISTRIBUTION = "derive-mechanics"
ID_PATTERN = re.compile(r"[A-Za-z][A-Za-z0-9_]*")  # problem ids: file names and LaTeX labels
SET_ID_PATTERN = re.compile(r"[A-Za-z][A-Za-z0-9_-]*")


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

        with open(_PACKAGE.parent / "pyproject.toml", "rb") as file:
            return tomllib.load(file)["project"]["version"]


class LibraryError(InputError):
    """A problem or set that is neither a file nor a library id."""


def _data_dir(name: str) -> Path:
    for candidate in (_PACKAGE.parent / name, _PACKAGE / "_data" / name):
        if candidate.is_dir():
            return candidate
    raise LibraryError(f"the {name}/ folder of derive is missing from the installation")


def problems_dir() -> Path:
    return Path(os.environ["DERIVE_LIBRARY"]) if os.environ.get("DERIVE_LIBRARY") else _data_dir("problems")


def templates_dir() -> Path:
    return _data_dir("templates")


def matches(search: str, *texts: str) -> bool:
    """Whether every word of `search` is in the texts (an id's underscores separate words): a whole
    word, or the start of one for a word of four letters or more (pulley finds pulleys; yo does
    not find you). `derive list --search`.

    >>> matches("wrapped disk", "string_wrapped_disk"), matches("pulle", "it is pulled"), matches("yo", "you")
    (True, True, False)
    """
    found = re.findall(r"[a-z0-9]+", " ".join(texts).replace("_", " ").lower())
    return all(any(w == word or len(word) >= 4 and w.startswith(word) for w in found)
               for word in re.findall(r"[a-z0-9]+", search.lower()))


def problem_files() -> list[Path]:
    """Every problem file of the library, sorted by path (sets excluded)."""
    root = problems_dir()
    return sorted(p for p in root.rglob("*.yaml") if "sets" not in p.relative_to(root).parts)


def _find(reference: str, candidates: Callable[[], list[Path]], kind: str) -> Path:
    """The file `reference` names, or the one of `candidates` (listed only where a library id is given)
    whose stem it is."""
    path = Path(reference)
    if path.suffix in (".yaml", ".yml") or os.sep in reference:
        if path.is_file():
            return path
        raise LibraryError(f"{reference}: no such {kind} file")
    if not ID_PATTERN.fullmatch(reference):
        raise LibraryError(f"{reference!r} is not a file and not a library id (letters, digits, _)")
    listed = candidates()
    for candidate in listed:
        if candidate.stem == reference:
            return candidate
    hint = did_you_mean(reference, [c.stem for c in listed])
    raise LibraryError(f"no {kind} file or library id {reference!r} (see `derive list`){hint}")


def find_problem(reference: str) -> Path:
    """A problem file path, or the library problem with that id."""
    return _find(reference, problem_files, "problem")


def set_files() -> list[Path]:
    """Every set file of the library (problems/sets/), sorted."""
    return sorted((problems_dir() / "sets").glob("*.yaml"))


def find_set_or_problem(reference: str) -> Path:
    """What `derive sheet` is given: a file, or the id of a set or (if no set has it) of a problem.

    >>> find_set_or_problem("demo").parent.name, find_set_or_problem("rod_endpoint").stem
    ('sets', 'rod_endpoint')
    """
    return _find(reference, lambda: set_files() + problem_files(), "set or problem")


def find_set(reference: str) -> Path:
    """A set file path, or the set of that id in problems/sets/. The set's id is the file's
    stem, and names the output folder (build/<id>): it must match SET_ID_PATTERN."""
    path = _find(reference, set_files, "set")
    if not SET_ID_PATTERN.fullmatch(path.stem):
        raise LibraryError(f"{reference}: a set's id is its file name, {path.stem!r}: use letters, digits, _ and -, "
                           "starting with a letter")
    return path
