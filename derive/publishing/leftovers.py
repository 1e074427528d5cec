"""What derive leaves while it works, marked so that a later run can prove it derive's.

A folder derive makes for a while (a build's staging folder, a TeX scratch folder) gets a mark
file, `.derive-leftover`, whose content names the folder; a lock file gets that content itself.
A user's folder that merely has a name like derive's has no such file, so a run that finds a
killed run's leftovers removes only marked ones (or ones that prove derive's otherwise, see
derive.output_folder) and never a user's.

>>> text("derive-tex-12-ab")
'made by derive as derive-tex-12-ab; removed when done\\n'
>>> pid("12"), pid("99999999999999999999")
(12, None)
"""
from __future__ import annotations

import os
from pathlib import Path

MARK = ".derive-leftover"
#: The largest pid any system gives (pid_t is a C int); a larger number names no process.
PID_MAX = 2**31 - 1


def text(name: str) -> str:
    """The content of derive's mark of the folder or file called `name`."""
    return f"made by derive as {name}; removed when done\n"


def mark(folder: Path) -> None:
    """Mark `folder` as made by derive (see the module)."""
    (folder / MARK).write_text(text(folder.name), encoding="utf-8")


def being_marked(folder: Path) -> bool:
    """Whether `folder` holds nothing but a mark cut short: killed while the mark was written (two TeX
    compiles run at once, and a kill of one can fall in the other's `mark`), so empty or the start of
    derive's text for its name, a file no user's folder holds."""
    try:
        entries = list(folder.iterdir())
        if [e.name for e in entries] != [MARK] or entries[0].is_symlink() or not entries[0].is_file():
            return False
        return text(folder.name).startswith(entries[0].read_text(encoding="utf-8"))
    except (OSError, UnicodeDecodeError):
        return False


def marked(folder: Path) -> bool:
    """Whether `folder` carries derive's mark for its name (a regular file, not a symlink)."""
    path = folder / MARK
    try:
        return not path.is_symlink() and path.read_text(encoding="utf-8") == text(folder.name)
    except (OSError, UnicodeDecodeError):
        return False


def pid(digits: str) -> int | None:
    """The pid written in a leftover's name; None for a number no process can have."""
    number = int(digits)
    return number if 0 < number <= PID_MAX else None


def alive(process: int) -> bool:
    """Whether a process of this pid runs (one of another user's counts: it cannot be signalled)."""
    try:
        os.kill(process, 0)
    except ProcessLookupError:
        return False
    except PermissionError:
        return True
    return True
