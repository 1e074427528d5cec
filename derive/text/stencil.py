"""Text laid out once with holes, filled for each variant by one join.

What a variant adds to a set's documents (its numbers in the worksheet, the worked solutions and
the keys) is the same layout every time with other values in it. The layout is rendered once per
problem by the code or template that writes it, with `hole(name)` where a value goes, and cut at
the holes (`Stencil`); a variant then costs one join of its values, not another pass of the
template engine, the JSON writer or the CSV writer (issue 17: the per-variant path of a set).

A hole is a run of private-use characters (U+E000, U+E001) around its name: no text of derive
holds them (latex_safety.check_characters refuses them in a problem file), and LaTeX escaping,
JSON string escaping and CSV quoting all leave them as they are, so a hole comes through any of
those writers intact. Values are filled as they are: the caller encodes them for the document
(a JSON token, a CSV cell), as it would have written them.

>>> s = Stencil(f"Given $m = {hole('m')}$ and $g = {hole('g')}$.")
>>> s.fill({"m": "2.0", "g": "9.81"})
'Given $m = 2.0$ and $g = 9.81$.'
>>> s.names
('m', 'g')
"""
from __future__ import annotations

import re
from typing import Mapping

_OPEN, _CLOSE = "\ue000", "\ue001"
_HOLE = re.compile(f"{_OPEN}([^{_CLOSE}]*){_CLOSE}")


def hole(name: str) -> str:
    """The mark of a value named `name` in text a stencil is cut from."""
    return f"{_OPEN}{name}{_CLOSE}"


class Stencil:
    """Text cut at its holes: `fill` puts each variant's values in.

    Each hole's line indent (the spaces that begin the line it is on) is kept in `indents`: a
    value that spans lines, a JSON object, is written at that indent.

    >>> Stencil('{\\n  "a": ' + hole("a") + "\\n}").indents
    {'a': '  '}
    """

    def __init__(self, text: str):
        pieces = _HOLE.split(text)
        self.names = tuple(pieces[1::2])
        self._pieces = [piece if i % 2 == 0 else None for i, piece in enumerate(pieces)]  # the text between holes
        self.indents = {}
        for match in _HOLE.finditer(text):
            line = text[text.rfind("\n", 0, match.start()) + 1:match.start()]
            self.indents[match.group(1)] = line[:len(line) - len(line.lstrip(" "))]

    def fill(self, values: Mapping[str, str]) -> str:
        """The text with each hole's value (every hole must have one)."""
        pieces = self._pieces.copy()
        pieces[1::2] = map(values.__getitem__, self.names)  # in C: a set fills thousands of stencils
        return "".join(pieces)
