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


#: Another word for a name derive knows by one: a cylinder's or a cone's length is its height, a
#: rod's height its length, a revolution or a turn the unit rev (spelling alone does not bring them
#: together: "revolutions" is closest to sympy's "volts").
SYNONYMS = {"length": ("height",), "height": ("length",),
            **dict.fromkeys(("revolution", "revolutions", "turn", "turns"), ("rev",))}


def did_you_mean(word: object, choices: Iterable[object]) -> str:
    """"; did you mean 'CHOICE'?" for a synonym of `word` among the choices, else the choice
    closest to it (difflib's ratio at least 0.6), else "".

    >>> did_you_mean("length", ["radius", "height"])
    "; did you mean 'height'?"
    """
    choices = [str(c) for c in choices]
    close = [c for c in SYNONYMS.get(str(word), ()) if c in choices] or difflib.get_close_matches(str(word), choices, n=1)
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
