"""Math for a terminal: expressions as sympy's unicode pretty-printer draws them, beside text.

>>> import sympy as sp
>>> print("\\n".join(pretty("a = ", -2 * sp.Symbol("g") / 3)))
    -2⋅g
a = ─────
      3
>>> print("\\n".join(pretty("L = ", sp.Symbol("M") * sp.Symbol("ell") ** 2 / 12)))
       2
    M⋅ℓ
L = ────
     12
>>> greek("the bodies turn together at the rate omega, about the axle")
'the bodies turn together at the rate ω, about the axle'
"""
from __future__ import annotations

import re

import sympy as sp
from sympy.printing.pretty.pretty import PrettyPrinter
from sympy.printing.pretty.pretty_symbology import greek_unicode
from sympy.printing.pretty.stringpict import prettyForm, stringPict

from derive.text import printed_form
from derive.text.latex import changes_a_letter

class _Printer(PrettyPrinter):
    """sympy's unicode pretty-printer, with the script letter the documents print as \\ell (a length beside
    an angular momentum L: derive.publishing.letters) drawn as itself, where sympy writes the name ell, and
    a change Delta_K, Delta_theta as the documents print it, ΔK and Δθ (sympy writes Δ with a subscript)."""

    def _print_Symbol(self, e, bold_name=False):
        if e.name == "ell" or e.name.startswith(("ell_", "ell^")):
            e = sp.Symbol("\N{SCRIPT SMALL L}" + e.name[3:], **e.assumptions0)
        change = re.fullmatch(r"Delta_([A-Za-z]+)", e.name)  # the change of K, of theta: as the documents print it
        if change and changes_a_letter(change[1]):
            return prettyForm("\N{GREEK CAPITAL LETTER DELTA}" + greek_unicode.get(change[1], change[1]))
        return super()._print_Symbol(e, bold_name)


#: sympy's unicode pretty-printer, lines unbroken (a terminal narrower than the equation scrolls it).
_PRETTY = _Printer({"use_unicode": True, "wrap_line": False})


def pretty(*parts) -> list[str]:
    """Text and expressions (sympy objects, matrices too) side by side on one baseline, as sympy's
    pretty-printer draws them, fractions over several lines: the lines, trailing spaces trimmed."""
    forms = [prettyForm(p) if isinstance(p, str) else _PRETTY._print(printed_form.textbook(p)) for p in parts]
    return [line.rstrip() for line in prettyForm(*stringPict.next(*forms)).render(wrap_line=False).splitlines()]


def indented(lines: list[str], indent: str = "  ") -> list[str]:
    return [indent + line for line in lines]


#: A Greek letter's name as a whole word (omega, Omega), which a step's words name a symbol by.
_GREEK = re.compile(r"\b(" + "|".join(sorted(greek_unicode, key=len, reverse=True)) + r")\b")


def greek(text: str) -> str:
    """A step's words with each Greek letter's name as the letter, as the equations beside it print it
    (the documents set the name as math: derive.text.prose)."""
    return _GREEK.sub(lambda m: greek_unicode[m[1]], text)
