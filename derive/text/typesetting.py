r"""Long equations broken across lines, so that no line of a worked solution runs off the page.

LaTeX does not break display math by itself (breqn, which would, is not in the TeX Live derive
installs, and it is fragile), so an equation whose right side is a sum too wide for the line is
cut here between its terms, each line after the first indented under the `=`. How wide a term is
comes from `width`, an estimate in characters of typeset math from the expression itself: a
symbol is its letter and a smaller subscript, a fraction the wider of its numerator and its
denominator, a power its base and a smaller exponent. The estimate errs wide, so a line it passes
fits. An equation whose long side is its left (a constraint, `sum = 0`) is written the other way
round (`0 = sum`), so that it breaks the same way. A line still too wide (a term too wide by
itself: a long fraction) is set smaller where LaTeX compiles it (`fit`: the preamble's
``\fitwidth``, which shrinks it to the line only if it is wider).

>>> speeds = sp.symbols("v_ball v_block v_can v_hoop")
>>> print(rows(sp.Symbol("K"), sum(sp.Symbol("m") * v**2 / 2 for v in speeds), room=30))
K &= \frac{m v_{\mathrm{ball}}^{2}}{2} + \frac{m v_{\mathrm{block}}^{2}}{2} \\
&\quad + \frac{m v_{\mathrm{can}}^{2}}{2} + \frac{m v_{\mathrm{hoop}}^{2}}{2}
"""
from __future__ import annotations

import sympy as sp
from sympy.printing.conventions import split_super_sub

from derive.text.latex import latex_of, symbol_latex

#: Characters of display math a line of the page holds (16.6 cm of text at 11 pt), less the
#: alignment's indent; `room` below it where a note shares the line (the results' meanings).
LINE = 72
SCRIPT = 0.7  # a subscript or an exponent, set smaller
NEAR = 0.5  # of its room, past which a row may be wider than estimated (ERRS): LaTeX measures it (`fit`)
LEFT = 0.45  # of a line, the most the left sides of an align take (a wider one is set smaller)
ERRS = 1.35  # how much wider than estimated a side may typeset (cos(angle_ramp): a third)
TAG = 6  # characters an equation's number takes at the end of its line


def width(expression) -> float:
    """An estimate of how wide `expression` typesets, in characters of math at the text's size.

    >>> width(sp.Symbol("x")), width(sp.Symbol("theta_disk")), width(sp.Symbol("a") / 2)
    (1.0, 3.8, 2.0)
    """
    e = expression  # a sympy expression (never text: nothing here parses)
    if isinstance(e, int):
        return float(len(str(e)))
    if isinstance(e, sp.Symbol):
        base, supers, subs = split_super_sub(e.name)
        letter = 1 if symbol_latex(base).startswith("\\") or len(base) == 1 else len(base)
        return float(letter + SCRIPT * sum(len(s) for s in (*supers, *subs)))
    if isinstance(e, sp.Rational) and not isinstance(e, sp.Integer):
        return max(len(str(abs(e.p))), len(str(e.q))) + (1 if e.is_negative else 0)
    if isinstance(e, sp.Number):
        return len(str(e))
    if isinstance(e, sp.Add):
        return sum(width(t) for t in e.args) + 3 * (len(e.args) - 1)
    if isinstance(e, sp.Mul):
        numerator, denominator = sp.fraction(e)
        if denominator != 1:
            return max(width(numerator), width(denominator)) + 1
        factors = [f for f in e.args if f != -1]
        return sum(width(f) + 2 * isinstance(f, sp.Add) for f in factors) + 0.5 * (len(factors) - 1) + (1 if -1 in e.args else 0)
    if isinstance(e, sp.Pow):
        base = width(e.base) + 2 * isinstance(e.base, (sp.Add, sp.Mul))
        if e.exp == sp.Rational(1, 2):
            return base + 2
        if e.exp.is_negative:
            return max(base, 1) + 1  # a fraction
        return base + SCRIPT * width(e.exp)
    if isinstance(e, sp.Function):
        return len(type(e).__name__) + sum(width(a) for a in e.args) + 2
    if isinstance(e, sp.Eq):
        return width(e.lhs) + 3 + width(e.rhs)
    return len(sp.sstr(e))  # a derivative, an integral, a piecewise: as long as it reads


def _signed(term: sp.Expr, first: bool) -> str:
    """A term of a sum as a line shows it: "+ t" or "- t" after the first."""
    if term.could_extract_minus_sign():
        return "- " + latex_of(-term)
    return ("" if first else "+ ") + latex_of(term)


#: Of a line, what a note beside an equation takes (NOTE_WIDTH of \linewidth, a parbox).
NOTE_WIDTH = 0.3


def note(text: str, tex: bool = True) -> str:
    r"""A note beside an equation, in an align environment's last column (`text` already LaTeX):
    where LaTeX compiles it (`tex`), a narrow ragged box, so that a long meaning wraps instead of
    running off the page; for MathJax (the LMS feedback, through pandoc), which knows no \parbox
    or \raggedright and would show them as errors, the meaning as text.

    >>> note("tension in the cord", tex=False)
    ' && \\text{tension in the cord}'
    """
    if not tex:
        return rf" && \text{{{text}}}"
    return rf" && \parbox[t]{{{NOTE_WIDTH}\linewidth}}{{\raggedright\small {text}}}"


def fit(text: str, size: float, room: float) -> str:
    r"""A row's math (`text`, about `size` characters wide) where it has `room` characters: as it is
    when it fits, else in ``\fitwidth``, which sets it smaller where it is wider than that share of
    the line (the estimate errs wide: LaTeX measures it).

    >>> fit("x", 1, 10)
    'x'
    >>> fit("x", 80, 60)
    '\\fitwidth{0.83\\linewidth}{x}'
    """
    if size <= NEAR * room:  # clearly narrower: as it is
        return text
    return rf"\fitwidth{{{room / LINE:.2f}\linewidth}}{{{text}}}"


def _sides(lhs: sp.Expr, rhs: sp.Expr, room: float) -> tuple[sp.Expr, sp.Expr]:
    """The sides as written: a long sum on the left over a short right side, second (`0 = a + b`)."""
    if isinstance(lhs, sp.Add) and not isinstance(rhs, sp.Add) and width(lhs) > room / 2 > width(rhs):
        return rhs, lhs
    return lhs, rhs


def left_column(equations, room: float = LINE) -> float:
    """How wide (characters) the left sides of equations aligned together are written: the widest,
    at most `LEFT` of the line. Each row's right side keeps to the rest of the line (`rows`' `left`):
    the rows of an align share its columns, so that a long left side in one row and a long right
    side in another would together run off the page.

    >>> x, y = sp.symbols("x y")
    >>> left_column([sp.Eq(x, y), sp.Eq(x + y, 2 * y)])
    5.0
    """
    return max((min(width(_sides(e.lhs, e.rhs, room)[0]), LEFT * room) for e in equations), default=0.0)


def rows(lhs: sp.Expr, rhs: sp.Expr, room: float = LINE, beside: str = "", tex: bool = False,
         left: float | None = None) -> str:
    r"""`lhs = rhs` as rows of an align environment (`lhs &= ...`), the sum on the right cut between
    its terms where the line would be wider than `room` characters (`width`); `beside`, a `note`,
    ends the first row (the room left for the equation shrinks by its width). A long left side
    over a short right one is written second (`0 = a + b`); where LaTeX compiles it (`tex`), a row
    still too wide is set smaller (`fit`). `left`: how wide the left sides of the rows aligned
    with it are (`left_column`; by default its own).

    >>> a, b = sp.symbols("alpha_disk beta_disk")
    >>> print(rows(sum(a**k * b for k in range(1, 9)), sp.Integer(0), room=30))
    0 &= \alpha_{\mathrm{disk}}^{8} \beta_{\mathrm{disk}} + \alpha_{\mathrm{disk}}^{7} \beta_{\mathrm{disk}} \\
    &\quad + \alpha_{\mathrm{disk}}^{6} \beta_{\mathrm{disk}} + \alpha_{\mathrm{disk}}^{5} \beta_{\mathrm{disk}} \\
    &\quad + \alpha_{\mathrm{disk}}^{4} \beta_{\mathrm{disk}} + \alpha_{\mathrm{disk}}^{3} \beta_{\mathrm{disk}} \\
    &\quad + \alpha_{\mathrm{disk}}^{2} \beta_{\mathrm{disk}} + \alpha_{\mathrm{disk}} \beta_{\mathrm{disk}}
    """
    line_room = room * (1 - NOTE_WIDTH - 0.05) if beside else room
    lhs, rhs = _sides(lhs, rhs, room)
    left = min(width(lhs), LEFT * room) if left is None else left
    available = line_room - min(ERRS * left, LEFT * room) - 3  # beside the widest left side as it may typeset
    head = (fit(latex_of(lhs), width(lhs), LEFT * room) if tex else latex_of(lhs)) + " &= "  # wider: set smaller
    if width(rhs) <= available or not isinstance(rhs, sp.Add):
        return head + (fit(latex_of(rhs), width(rhs), available) if tex else latex_of(rhs)) + beside
    lines, line, used = [], [], 0.0
    for term in rhs.as_ordered_terms():
        size = width(term) + 3
        if line and used + size > available:
            lines.append((" ".join(line), used))
            line, used = [], 0.0
        line.append(_signed(term, not lines and not line))
        used += size
    lines.append((" ".join(line), used))
    texts = [fit(text, used, available) if tex else text for text, used in lines]
    texts[0] += beside
    return head + " \\\\\n&\\quad ".join(texts)
