"""A course's defaults: `derive.toml` in the working folder, else the `[tool.derive]` table of its
pyproject.toml. Every key is optional; a set file's own fields and the command-line options
override them.

    course = "PHY141 Mechanics"     # the header of a set that names no course
    outputs = ["pdf", "moodle"]     # what `derive sheet` writes when the set names none (--to)
    digits = 12                     # significant digits of `derive solve` and `derive inertia`
    tolerance = "2%"                # an LMS tolerance for asks that give none (or an amount)

>>> import tempfile
>>> with tempfile.TemporaryDirectory() as folder:
...     _ = (Path(folder) / FILE).write_text('course = "PHY141"\\ndigits = 12\\n')
...     load(Path(folder))
Defaults(course='PHY141', outputs=None, digits=12, tolerance=None)
"""
from __future__ import annotations

import tomllib
from dataclasses import dataclass
from pathlib import Path

from derive.core.errors import InputError
from derive.core.spelling import did_you_mean

FILE = "derive.toml"
KEYS = ("course", "outputs", "digits", "tolerance")
COURSE_LIMIT = 200  # characters, as a set file's `course`
DIGITS = (1, 50)  # as --digits
#: What `derive sheet --to` (or a set's `outputs:`) can add to the .tex files and the keys.
OUTPUTS = ("pdf", "html", "md", "docx", "moodle", "qti", "distractors")
DEFAULT_OUTPUTS = frozenset({"pdf", "html"})


@dataclass(frozen=True)
class Defaults:
    course: str = ""
    outputs: frozenset[str] | None = None  # None: the built-in default (DEFAULT_OUTPUTS)
    digits: int | None = None  # None: 15
    tolerance: str | None = None  # None: one unit in the last digit shown


def outputs(text: str, where: str) -> frozenset[str]:
    """A comma-separated list of outputs, checked against OUTPUTS.

    >>> sorted(outputs("pdf, moodle", "--to"))
    ['moodle', 'pdf']
    """
    wanted = frozenset(f.strip() for f in text.split(",") if f.strip())
    unknown = sorted(wanted - set(OUTPUTS))
    if unknown:
        raise InputError(f"{where}: unknown output {unknown[0]!r} (outputs: {', '.join(OUTPUTS)})"
                         + did_you_mean(unknown[0], OUTPUTS))
    return wanted


def load(folder: Path | None = None) -> Defaults:
    """The defaults of `folder` (the working folder): derive.toml, else pyproject.toml's
    [tool.derive], else none."""
    folder = Path.cwd() if folder is None else folder
    own = folder / FILE
    if own.is_file():
        return _read(own, _toml(own), "")
    pyproject = folder / "pyproject.toml"
    if pyproject.is_file():
        tool = _toml(pyproject).get("tool", {})
        if isinstance(tool, dict) and "derive" in tool:
            return _read(pyproject, tool["derive"], "tool.derive.")
    return Defaults()


def _toml(path: Path) -> dict:
    try:
        with open(path, "rb") as file:
            return tomllib.load(file)
    except (OSError, UnicodeDecodeError, tomllib.TOMLDecodeError) as error:
        raise InputError(f"{path}: invalid TOML: {error}") from None


def _read(path: Path, table, prefix: str) -> Defaults:
    def fail(key: str, message: str) -> InputError:
        return InputError(f"{path}: {prefix}{key}: {message}")

    if not isinstance(table, dict):
        raise InputError(f"{path}: {prefix.rstrip('.') or 'the file'}: expected a table of {', '.join(KEYS)}")
    for key in table:
        if key not in KEYS:
            raise fail(key, f"unknown key (allowed: {', '.join(KEYS)})" + did_you_mean(key, KEYS))
    course = table.get("course", "")
    if not isinstance(course, str):
        raise fail("course", "expected text")
    from derive.text import latex_safety

    try:
        latex_safety.check_plain(course, COURSE_LIMIT)
    except latex_safety.LatexError as error:
        raise fail("course", str(error)) from None
    wanted = table.get("outputs")
    if wanted is not None:
        if not isinstance(wanted, list) or not all(isinstance(o, str) for o in wanted):
            raise fail("outputs", 'expected a list such as ["pdf", "moodle"]')
        wanted = outputs(",".join(wanted), f"{path}: {prefix}outputs")
    digits = table.get("digits")
    if digits is not None and (not isinstance(digits, int) or isinstance(digits, bool)
                               or not DIGITS[0] <= digits <= DIGITS[1]):
        raise fail("digits", f"expected a whole number from {DIGITS[0]} to {DIGITS[1]}")
    tolerance = table.get("tolerance")
    if tolerance is not None:
        from derive.language.ask_options import tolerance_policy

        try:
            tolerance = tolerance_policy(tolerance)
        except ValueError as error:
            raise fail("tolerance", str(error)) from None
    return Defaults(course, wanted, digits, tolerance)
