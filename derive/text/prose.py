"""Sentences of a worked solution that hold math: words and expressions in the order they are read.

A part of a scene says what it contributes to a route in such sentences (`derive.parts`,
`Part.sentences`): "The cord does not slip on the disk, so ..." followed by the equation. The
words stay words (no pseudo-math) and the math stays sympy, so each output prints both its own
way: LaTeX with the math in `$...$` and the symbols named as the equations name them
(`latex.latex_of`: word subscripts upright), text with sympy's unicode pretty-printer.

>>> import sympy as sp
>>> v, w, R = sp.symbols("v omega R")
>>> s = Sentence(("The block moves with the rim: ", sp.Eq(v, w * R), "."))
>>> s.latex()
'The block moves with the rim: $v = R \\\\omega$.'
>>> s.text()
'The block moves with the rim: v = R⋅ω.'
>>> s.words
'The block moves with the rim: .'
"""
from __future__ import annotations

import re
from dataclasses import dataclass, replace
from typing import Callable, Iterable

import sympy as sp

from derive.text import typesetting
from derive.text.latex import latex_of, symbol_latex, tex_escape
from derive.text.terminal import pretty


@dataclass(frozen=True)
class Sentence:
    """`pieces`: words (str) and math (sympy expressions and equations), read in order. `body`:
    the body whose Newton–Euler balance the sentence explains (None: the scene's constraints)."""

    pieces: tuple
    body: str | None = None

    @property
    def words(self) -> str:
        """The words alone (what the prose checks read)."""
        return "".join(p for p in self.pieces if isinstance(p, str))

    def latex(self, tex: bool = False) -> str:
        r"""The sentence as LaTeX: words escaped, each piece of math in `$...$`; where LaTeX
        compiles it (`tex`), a piece too wide to share a line with words (a long fraction, a
        product in parentheses: inline math breaks only between its terms) on a line of its own,
        set smaller if it is wider than the line (derive.text.typesetting.fit).

        >>> x = sp.Symbol("x")
        >>> wide = Sentence(("its torque is ", sum(x**k / (k + 2) for k in range(12)), "."))
        >>> r"its torque is \[\fitwidth{1.00\linewidth}{" in wide.latex(tex=True), "\\[" in wide.latex()
        (True, False)
        """
        def math(piece) -> str:
            if tex and typesetting.width(piece) > typesetting.LINE / 2:
                return rf"\[{typesetting.fit(latex_of(piece), typesetting.width(piece), typesetting.LINE)}\]"
            return f"${latex_of(piece)}$"

        return "".join(tex_escape(p) if isinstance(p, str) else math(p) for p in self.pieces)

    def text(self) -> str:
        """The sentence for a terminal (a fraction takes three lines, on one baseline)."""
        return "\n".join(pretty(*self.pieces))

    def with_math(self, change: Callable[[sp.Basic], sp.Basic]) -> Sentence:
        """The sentence with `change` applied to each piece of math (the routes' `simplest`)."""
        def changed(piece):
            if isinstance(piece, sp.Eq):
                return sp.Eq(change(piece.lhs), change(piece.rhs), evaluate=False)
            return change(piece)
        return replace(self, pieces=tuple(p if isinstance(p, str) else changed(p) for p in self.pieces))


def capital(words: str) -> str:
    """`words` opening a sentence: the first letter a capital, the rest as it is (a name keeps its case).

    >>> capital("the ball's contact with the Dome")
    "The ball's contact with the Dome"
    """
    return words[:1].upper() + words[1:]


def repeats(said: str, lead: str) -> bool:
    """Whether `lead` (the words that introduce a step's equations) says again what the sentence
    `said` just said: every word of three letters or more of it (at least five such words) but one
    in four is a word of `said`. Math (`$...$`) is left out. A worked solution that printed both read
    "The constraints leave one coordinate of the scene: ... the kinetic energy is a function of it
    times the square of its rate." then "The constraints leave one coordinate; the kinetic energy in
    its rate:"; the documents print the sentence alone.

    >>> repeats("The constraints leave one coordinate of the scene, and the kinetic energy is a function "
    ...         "of it times the square of its rate.", "The constraints leave one coordinate; the kinetic energy in its rate")
    True
    >>> repeats("So energy is conserved: the kinetic energy at each x is the one at the start.", "Work and energy from the start")
    False
    """
    heard = set(_words(said))
    told = _words(lead)
    return len(told) >= 5 and sum(w in heard for w in told) >= 0.75 * len(told)


def _words(text: str) -> list[str]:
    return [w for w in re.findall(r"[a-z]+", re.sub(r"\$[^$]*\$", " ", text).lower()) if len(w) > 2]


#: Greek letters' names, which are never words of the prose: phi, psi and theta of Euler's angles.
GREEK = ("alpha", "beta", "gamma", "delta", "epsilon", "theta", "lambda", "mu", "nu", "rho", "sigma", "tau", "phi",
         "chi", "psi", "omega", "Omega", "Phi", "Psi", "Theta")


def stays_a_word(name: str) -> bool:
    """Whether a name in running text is left a word, not set as math: the article a, a word of small
    letters (an ask named angle, at or tb), a name that typesets as one (\\mathit{GM}).

    >>> [stays_a_word(n) for n in ("a", "angle", "tb", "theta", "v_0", "GM")]
    [True, True, True, False, False, True]
    """
    return name in ("a", "A") or symbol_latex(name).startswith(r"\mathit") or \
        bool(re.fullmatch("[a-z]{2,}", name)) and name not in GREEK


def set_as_math(text: str, names: Iterable[str]) -> str:
    r"""`text` as LaTeX, escaped, each word of it that is one of `names` (the symbols of a problem: its
    parameters, its asks, the symbols its steps typeset) or a Greek letter's name set as math: "as the
    center drops H" as "as the center drops $H$", "psi about the axis" as "$\\psi$ about the axis". A name that is a word of small letters (an ask named angle, at or tb)
    or typesets as one (\mathit) stays a word, and so does the article a.

    >>> set_as_math("Energy conservation as the center drops H, at a speed v_0 (x_ball's rate)", ["H", "v_0", "a", "x_ball"])
    "Energy conservation as the center drops $H$, at a speed $v_{0}$ ($x_{\\mathrm{ball}}$'s rate)"
    """
    shown = sorted({n for n in (*names, *GREEK) if not stays_a_word(n)}, key=lambda n: (-len(n), n))
    if not shown:
        return tex_escape(text)
    word = re.compile(r"(?<![\w\\])(" + "|".join(map(re.escape, shown)) + r")(?![\w])")
    pieces = word.split(text)
    return "".join(f"${symbol_latex(p)}$" if i % 2 else tex_escape(p) for i, p in enumerate(pieces))
