"""Math for a terminal: expressions as sympy's unicode pretty-printer draws them, beside text.

>>> import sympy as sp
>>> print("\\n".join(pretty("a = ", -2 * sp.Symbol("g") / 3)))
    -2⋅g
a = ─────
      3
"""
from __future__ import annotations

from sympy.printing.pretty.pretty import PrettyPrinter
from sympy.printing.pretty.stringpict import prettyForm, stringPict

from derive.text import printed_form

#: sympy's unicode pretty-printer, lines unbroken (a terminal narrower than the equation scrolls it).
_PRETTY = PrettyPrinter({"use_unicode": True, "wrap_line": False})


def pretty(*parts) -> list[str]:
    """Text and expressions (sympy objects, matrices too) side by side on one baseline, as sympy's
    pretty-printer draws them, fractions over several lines: the lines, trailing spaces trimmed."""
    forms = [prettyForm(p) if isinstance(p, str) else _PRETTY._print(printed_form.textbook(p)) for p in parts]
    return [line.rstrip() for line in prettyForm(*stringPict.next(*forms)).render(wrap_line=False).splitlines()]


def indented(lines: list[str], indent: str = "  ") -> list[str]:
    return [indent + line for line in lines]
