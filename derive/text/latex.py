r"""Text and sympy expressions as LaTeX: plain text escaped (`tex_escape`), a symbol's name as a
reader expects it (`symbol_latex`), an expression or equation in the grouping a textbook prints
(`latex_of`). The engine's sentences (derive.text.prose), the figures and every document print through
them.

>>> tex_escape("50% & more")
'50\\% \\& more'
"""
from __future__ import annotations

import re
from functools import lru_cache

import sympy as sp
from sympy.printing.conventions import split_super_sub
from sympy.printing.latex import LatexPrinter, translate
from sympy.simplify import fraction
from sympy.printing.pretty.pretty_symbology import greek_unicode
from sympy.printing.str import StrPrinter

from derive.text import printed_form
from derive.text.latex_grammar import SPECIALS


@lru_cache(maxsize=1024)  # a problem's id, title and the set's are escaped in every variant
def tex_escape(text: str) -> str:
    """Plain text made safe to typeset: LaTeX's special characters escaped."""
    return "".join(SPECIALS.get(c, c) for c in str(text))


#: A name that is a letter and its index: one small letter (vb, tb: v at b), digits and capitals (v1x, vB,
#: FAx), or a word a subscript is (xtop, Jrod); a word that is no index (rise, turn) is set as a word.
_INDEXED = re.compile(r"([A-Za-z])([a-z]|[0-9A-Z][0-9A-Za-z]{0,2}|top|bottom|rod|max|min|cm)")


@lru_cache(maxsize=1024)  # a symbol is typeset in every variant
def symbol_latex(name: str) -> str:
    r"""LaTeX of a symbol's name as a reader expects it: a Greek name as its letter, a word
    subscript upright, a word as one symbol.

    sympy's own LaTeX (split_super_sub, translate) does the splitting and the Greek; it sets every
    subscript in italics (Omega_fast as f a s t) and a word as a product (Rcm as R c m), so these
    rules are written here: a subscript of two letters or more is upright (a one-letter subscript
    may be an index, x_i, and stays italic); a capital followed by one or two small letters is the
    capital with them as its subscript (Rcm as R_cm; Mass stays a word); a letter then a Greek
    name is a product (dphi as d phi); a Greek name and one small letter is the letter with its index (mus
    as mu_s); d and one letter is a change (dE as Delta E); a letter and an
    index is the letter with it as its subscript (vx as v_x, vB as v_B, tb as t_b, xtop as x_top); a
    word of small letters is set upright, as a label is (angle); any other name is one italic symbol.

    >>> symbol_latex("Omega_fast"), symbol_latex("Rcm"), symbol_latex("theta_c"), symbol_latex("omega0")
    ('\\Omega_{\\mathrm{fast}}', 'R_{\\mathrm{cm}}', '\\theta_{c}', '\\omega_{0}')
    >>> symbol_latex("dphi_exact"), symbol_latex("GM"), symbol_latex("a_theta"), symbol_latex("Mass")
    ('d\\phi_{\\mathrm{exact}}', '\\mathit{GM}', 'a_{\\theta}', '\\mathit{Mass}')
    >>> symbol_latex("dE"), symbol_latex("vx"), symbol_latex("FAx"), symbol_latex("tb"), symbol_latex("angle")
    ('\\Delta E', 'v_{x}', 'F_{\\mathrm{Ax}}', 't_{b}', '\\mathrm{angle}')
    >>> symbol_latex("mus"), symbol_latex("muk"), symbol_latex("thetac")
    ('\\mu_{s}', '\\mu_{k}', '\\theta_{c}')
    >>> symbol_latex("omega_1'"), symbol_latex("Delta_K"), symbol_latex("Delta_theta")
    ("\\omega_{1}'", '\\Delta K', '\\Delta \\theta')
    """
    if name.startswith("\\"):  # a name the engine gives in LaTeX (derivation.LAGRANGIAN)
        return name
    if name.endswith("'"):  # a value after (omega_1'): the prime after the subscript, as a textbook sets it
        bare = name.rstrip("'")
        return symbol_latex(bare) + "'" * (len(name) - len(bare))
    base, supers, subs = split_super_sub(name)
    letter = translate(base)
    if base == "Delta" and len(subs) == 1 and not supers and changes_a_letter(subs[0]):  # Delta_K, Delta_theta: a change
        return rf"\Delta {translate(subs[0])}"
    if letter == base and len(base) > 1:  # a word: not a Greek name, nor a letter with an accent
        index = _INDEXED.fullmatch(base)
        if base[0].isupper() and base[1:].islower() and len(base) <= 3:  # Rcm, Mp; not a word (Mass)
            letter, subs = base[0], [base[1:], *subs]
        elif translate(base[1:]) != base[1:]:
            letter = base[0] + translate(base[1:])
        elif (greek := _greek_and_index(base)) and not subs:  # mus, muk: mu_s, mu_k, a coefficient's usual names
            letter, subs = translate(greek[0]), [greek[1]]
        elif base[0] == "d" and len(base) == 2 and not subs:  # dE, dp: the change of E, of p
            letter = rf"\Delta {translate(base[1])}"
        elif index and not subs and not base.isupper():  # vx, v1x, FAx, tb: a letter and its index (GM is G M)
            letter, subs = index[1], [index[2]]
        elif base.isalpha() and base.islower():  # a word (angle, spin): upright, as a label is set
            letter = rf"\mathrm{{{base}}}"
        else:
            letter = rf"\mathit{{{base}}}"

    def script(parts: list[str]) -> str:
        return ",".join(translate(p) if translate(p) != p or len(p) == 1 or p.isdigit() else rf"\mathrm{{{p}}}"
                        for p in parts)

    return letter + (f"_{{{script(subs)}}}" if subs else "") + (f"^{{{script(supers)}}}" if supers else "")


def _greek_and_index(name: str) -> tuple[str, str] | None:
    """(a Greek letter's name, one small Latin letter) where `name` is the two run together (mus: mu, s),
    else None."""
    for cut in range(2, len(name)):
        head, tail = name[:cut], name[cut:]
        if translate(head) != head and len(tail) == 1 and tail.islower():
            return head, tail
    return None


def changes_a_letter(name: str) -> bool:
    """Whether `name` is what a Delta before it changes: one Latin letter, or a Greek letter's name."""
    return len(name) == 1 and name.isalpha() or translate(name) != name


def latex_of(expression) -> str:
    r"""sympy's LaTeX for an expression or equation, its symbols named by symbol_latex, in the
    grouping a textbook prints (`printed_form.textbook`: one square root, sin for cos tan).

    >>> latex_of(sp.Eq(sp.Symbol("Omega_fast"), sp.Symbol("M") * sp.Symbol("Rcm")))
    '\\Omega_{\\mathrm{fast}} = M R_{\\mathrm{cm}}'
    """
    named = {s: symbol_latex(s.name) for s in (expression.atoms(sp.Symbol) if isinstance(expression, sp.Basic) else ())
             if not isinstance(s, sp.Dummy)}  # bound ones too (an integral's dx); a Dummy keeps sympy's own mark
    return _Printer({"symbol_names": named}).doprint(printed_form.textbook(expression))


class _Printer(LatexPrinter):
    r"""sympy's LaTeX printer, a sum that it would open with a minus sign opened with its first
    positive term, as a teacher writes pi/2 - alpha, 1 - x/(3 g) and sin(theta) - mu cos(theta)
    (sympy orders the terms by their symbols, a number last: - alpha + pi/2).

    >>> a, g, x = sp.symbols("alpha g x", positive=True)
    >>> latex_of(sp.pi / 2 - a), latex_of(1 - x / (3 * g)), latex_of(x - 1), latex_of(-a - x)
    ('\\frac{\\pi}{2} - \\alpha', '1 - \\frac{x}{3 g}', 'x - 1', '- \\alpha - x')
    """

    _in_fraction = False  # printing a \frac's numerator or denominator

    def _print_Mul(self, expr) -> str:
        r"""A fraction as \frac, but inside another one's numerator or denominator written flat, a/b
        (a fraction in a fraction prints in a script size, which no solution manual does: issue 37).

        >>> h, R, w = sp.symbols("h R omega", positive=True)
        >>> latex_of(w * (3 + h**2 / R**2) / 6), latex_of(1 / (1 + h / (2 * R)))
        ('\\frac{\\omega \\left(3 + h^{2} / R^{2}\\right)}{6}', '\\frac{1}{1 + h / \\left(2 R\\right)}')
        """
        negative = expr.could_extract_minus_sign()
        numerator, denominator = fraction(-expr if negative else expr, exact=True)
        if denominator == 1 or not self._in_fraction:
            self._in_fraction, outer = denominator != 1 or self._in_fraction, self._in_fraction
            try:
                return super()._print_Mul(expr)
            finally:
                self._in_fraction = outer
        top, bottom = self._print(numerator), self._print(denominator)
        if isinstance(numerator, sp.Add):
            top = rf"\left({top}\right)"
        if isinstance(denominator, (sp.Add, sp.Mul)):
            bottom = rf"\left({bottom}\right)"
        return ("- " if negative else "") + f"{top} / {bottom}"

    def _print_Rational(self, expr) -> str:
        if self._in_fraction and expr.q != 1:  # a half in a fraction's numerator: 1/2, as _print_Mul
            return f"{'- ' if expr.p < 0 else ''}{abs(expr.p)} / {expr.q}"
        return super()._print_Rational(expr)

    def _as_ordered_terms(self, expr, order=None):
        terms = super()._as_ordered_terms(expr, order=order)
        if isinstance(expr, sp.Add) and terms[0].could_extract_minus_sign():
            first = next((t for t in terms if not t.could_extract_minus_sign()), None)
            if first is not None:
                return [first, *(t for t in terms if t is not first)]
        return terms


_SUPERSCRIPTS = str.maketrans("0123456789-", "⁰¹²³⁴⁵⁶⁷⁸⁹⁻")


class _SpokenNames(StrPrinter):
    """sympy's str printer, each symbol's name spoken: a Greek name as its letter, a subscript after
    a space (the terms keep the order of the names as given)."""

    def _print_Symbol(self, symbol: sp.Symbol) -> str:
        base, supers, subs = split_super_sub(symbol.name)
        return " ".join(greek_unicode.get(part, part) for part in (base, *subs, *supers))


def spoken(expression: sp.Expr) -> str:
    """An expression as plain text that reads as math, for an image's alternative text: a product
    spaced (M g, not M*g), a Greek name as its letter, a subscript after a space (T string), a
    whole power as a superscript.

    sympy's str printer gives the grouping; the rest is the text it prints, rewritten here, since
    sympy has no printer for words (its pretty printer draws fractions on several lines).

    >>> M, g, mu_k, N, T = sp.symbols("M g mu_k N T_string")
    >>> spoken(M * g), spoken(mu_k * N), spoken(T), spoken(M * g**2 / 2)
    ('M g', 'N μ k', 'T string', 'M g²/2')
    """
    text = _SpokenNames().doprint(expression)
    text = re.sub(r"\*\*(-?\d+)", lambda m: m.group(1).translate(_SUPERSCRIPTS), text)
    return text.replace("**", "^").replace("*", " ")
