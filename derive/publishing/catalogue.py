"""The library as one browsable HTML page (`derive catalogue`), for choosing a week's set: each
problem's title, topic, difficulty, tags and source, its statement with the parameters as symbols
(no variant is drawn, so no derivation is needed), what it gives and asks, and its figure.

The statements, the symbols and the units are LaTeX (the problem files' questions are LaTeX), so
they go through pandoc to HTML with MathML (export.html_sections, one run for the whole library),
and the figures are the worksheets' own (figure.tikz, compiled in one document and drawn as SVG by
figure_files), embedded as data URIs (SVG, or PNG where the SVG is large: SVG_LIMIT): the page needs
no other file and no network. The page itself is a jinja2 template (templates/catalogue.html.j2)
with HTML autoescaping: nothing a problem file holds reaches the page unescaped but pandoc's HTML.

>>> from derive.language.problem import load
>>> print(_section(load("rolling_incline"))[:60])
\\section{rolling\\_incline}
A solid sphere of mass $M$ and ra
"""
from __future__ import annotations

import base64
import os
import tempfile
from dataclasses import dataclass
from pathlib import Path

import sympy as sp

from derive.language.problem import Problem, exact_decimal
from derive.publishing import export, figure, figure_files, render, variants
from derive.publishing.output_folder import OutputError
from derive.text.latex import latex_of, symbol_latex, tex_escape


@dataclass(frozen=True)
class Entry:
    """One problem as the catalogue shows it: its fields, and its HTML (pandoc's) and figure."""

    problem: Problem
    statement: str  # HTML of the question, with symbols for the parameters
    given: str  # HTML list: each parameter, its meaning and its value or range
    asked: str  # HTML list: each asked quantity and its unit
    figure: str | None  # a data URI of the figure's image, None without one

    @property
    def sheet(self) -> str:
        return f"derive sheet {self.problem.id}"


def _symbol(name: str, problem: Problem) -> str:
    return f"${latex_of(problem.parameters[name].symbol)}$"


def _number(value: sp.Expr) -> str:
    """A file's number as LaTeX: a decimal as written (0.2, 8e+37 as 8\\times10^{37}), another as math.

    >>> print(_number(sp.Rational(1, 5)), _number(sp.Integer(8 * 10**37)), _number(sp.pi / 6))
    0.2 8\\times10^{37} \\frac{\\pi}{6}
    """
    if value.is_Rational and set(sp.factorint(value.q)) <= {2, 5}:
        return variants.number_latex(format(exact_decimal(value).normalize(), "g"))
    return latex_of(value)


def _given(problem: Problem) -> str:
    items = []
    for name, p in problem.parameters.items():
        unit = "" if p.unit == "1" else f"\\,{variants.unit_latex(p.unit, False)}"
        amount = (f"${_number(p.range[0])}$ to ${_number(p.range[1])}{unit}$" if p.range is not None
                  else f"${_number(p.value)}{unit}$")
        items.append(f"\\item {_symbol(name, problem)}: {tex_escape(p.meaning)}, {amount}")
    return "\\begin{itemize}\n" + "\n".join(items) + "\n\\end{itemize}"


def _asked(problem: Problem) -> str:
    items = [f"\\item ${symbol_latex(ask.name)}$: {tex_escape(ask.meaning)}"
             + ("" if ask.unit == "1" else f", in ${variants.unit_latex(ask.unit, False)}$")
             for ask in problem.asks.values()]
    return "\\begin{itemize}\n" + "\n".join(items) + "\n\\end{itemize}"


def _section(problem: Problem) -> str:
    """The problem's three sections of the document pandoc converts: the statement, what it gives,
    what it asks (each section's heading is dropped by html_sections)."""
    symbols = {name: _symbol(name, problem) for name in problem.parameters}
    statement = render.question(problem.question, symbols)
    return "\n".join(f"\\section{{{tex_escape(problem.id)}}}\n{body}"
                     for body in (statement, _given(problem), _asked(problem)))


def _figures(problems: list[Problem]) -> dict[str, str]:
    """Each drawable problem's figure as a data URI: one LaTeX document for them all."""
    images = figure_files.drawn({p.id: tikz for p in problems if (tikz := figure.tikz(p))})
    return {name: _data_uri(image) for name, image in images.items()}


#: The largest SVG embedded: pdftocairo writes a curved, hatched surface as thousands of path
#: segments (a bowl's figure is 2 MB of SVG, 22 kB of PNG), and the library's SVGs alone would
#: make a 45 MB page; above this size the figure is embedded as its PNG (192 dpi), about 3 MB in all.
SVG_LIMIT = 64 * 1024


def _data_uri(image: figure_files.Image) -> str:
    kind, data = ("svg+xml", image.svg) if len(image.svg) <= SVG_LIMIT else ("png", image.png)
    return f"data:image/{kind};base64," + base64.b64encode(data).decode("ascii")


def entries(problems: list[Problem], figures: bool = True) -> list[Entry]:
    """The catalogue's entries, in the order given (figures=False: none drawn, no TeX needed)."""
    fragments = export.html_sections("\n".join(map(_section, problems)), mathml=True) if problems else []
    drawn = _figures(problems) if figures else {}
    return [Entry(p, *fragments[3 * i:3 * i + 3], drawn.get(p.id)) for i, p in enumerate(problems)]


def page(entries: list[Entry], title: str, version: str) -> str:
    """The HTML page: the problems grouped by topic, each topic's in the order given."""
    topics: dict[str, list[Entry]] = {}
    for entry in entries:
        topics.setdefault(entry.problem.topic, []).append(entry)
    return render.html("catalogue.html.j2", title=title, version=version, topics=topics, count=len(entries),
                       difficulties=sorted({e.problem.difficulty for e in entries if e.problem.difficulty}))


#: What marks a page as derive's: the generator of every catalogue (templates/catalogue.html.j2).
GENERATOR = '<meta name="generator" content="derive '


def write(out: Path, html: str) -> None:
    """Write the page to `out` whole (a temporary file beside it, renamed over it): an error leaves
    the old file. As with output folders, derive replaces only a page it wrote (its generator)."""
    if out.is_dir() or out.exists() and GENERATOR not in out.read_text(encoding="utf-8", errors="replace")[:2000]:
        raise OutputError(f"--out {out}: not a catalogue derive wrote; derive will not replace it: "
                          "move it away or name another file")
    out.parent.mkdir(parents=True, exist_ok=True)
    with tempfile.NamedTemporaryFile("w", encoding="utf-8", dir=out.parent, prefix=f".{out.name}.",
                                     delete=False) as file:
        file.write(html)
    umask = os.umask(0o022)  # read back: a temporary file is private, the page is not
    os.umask(umask)
    os.chmod(file.name, 0o666 & ~umask)
    os.replace(file.name, out)
