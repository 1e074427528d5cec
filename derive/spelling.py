"""'Did you mean': the one hint every refusal of an unknown name ends with (an id, a shape, a
part, a key, a unit, a parameter), from difflib's closest match.

>>> did_you_mean("rod_endpiont", ["rod_endpoint", "rod_midpoint", "string_wrapped_disk"])
"; did you mean 'rod_endpoint'?"
>>> did_you_mean("zeppelin", ["rod", "disk"])
''
"""
from __future__ import annotations

import difflib
from typing import Iterable


def did_you_mean(word: object, choices: Iterable[object]) -> str:
    """"; did you mean 'CHOICE'?" for the choice closest to `word` (difflib's ratio at least 0.6),
    else ""."""
    close = difflib.get_close_matches(str(word), [str(c) for c in choices], n=1)
    return f"; did you mean {close[0]!r}?" if close else ""


def no_such(what: str, name: object, known: Iterable[object], plural: str) -> str:
    """The refusal of a name a file or the command line uses but nothing declares.

    >>> no_such("body", "blok", ["disk", "block"], "bodies")
    "no body 'blok' (bodies: disk, block); did you mean 'block'?"
    >>> no_such("surface", "ramp", [], "surfaces")
    "no surface 'ramp' (surfaces: none)"
    """
    known = [str(k) for k in known]
    return f"no {what} {name!r} ({plural}: {', '.join(known) or 'none'})" + did_you_mean(name, known)
