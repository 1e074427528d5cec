"""LaTeX templates from templates/ (jinja), the HTML ones (jinja, autoescaped), and problem
question text (no template engine).

Templates use LaTeX-friendly delimiters (\\VAR{...}, \\BLOCK{...}, \\#{...}) so braces stay
LaTeX's; the environment is sandboxed and strict (an undefined name is an error, not blank
text). Question text comes from problem files: its `{{ NAME }}` placeholders are replaced by
`derive.text.latex_safety.question_latex`, which reads it as TeX would and evaluates nothing.

>>> question("A mass {{ m }} hangs.", {"m": "$2\\\\,\\\\mathrm{kg}$"})
'A mass $2\\\\,\\\\mathrm{kg}$ hangs.'
"""
from __future__ import annotations

from functools import lru_cache

import jinja2
from jinja2.sandbox import SandboxedEnvironment

from derive.text import latex_safety
from derive.core import library
from derive.text.latex import latex_of, tex_escape


@lru_cache(maxsize=1)
def templates() -> SandboxedEnvironment:
    env = SandboxedEnvironment(
        loader=jinja2.FileSystemLoader(str(library.templates_dir())),
        block_start_string=r"\BLOCK{", block_end_string="}",
        variable_start_string=r"\VAR{", variable_end_string="}",
        comment_start_string=r"\#{", comment_end_string="}",
        line_statement_prefix="%%", line_comment_prefix="%#",
        trim_blocks=True, lstrip_blocks=True, autoescape=False,
        undefined=jinja2.StrictUndefined, keep_trailing_newline=True,
    )
    env.filters["tex"] = tex_escape
    env.filters["latex"] = latex_of
    return env


def question(text: str, values: dict[str, str]) -> str:
    """A problem's question as LaTeX, `{{ name }}` standing for a parameter's value and unit:
    `latex_safety.question_latex` (a LatexError for text it refuses, values included)."""
    return latex_safety.question_latex(text, values)


def render(template: str, **context) -> str:
    return templates().get_template(template).render(**context)


@lru_cache(maxsize=1)
def html_templates() -> SandboxedEnvironment:
    """jinja's own delimiters for the HTML templates (*.html.j2), every value HTML-escaped unless
    marked safe (pandoc's HTML): the LaTeX environment above escapes nothing."""
    return SandboxedEnvironment(loader=jinja2.FileSystemLoader(str(library.templates_dir())), autoescape=True,
                                undefined=jinja2.StrictUndefined, trim_blocks=True, lstrip_blocks=True)


def html(template: str, **context) -> str:
    return html_templates().get_template(template).render(**context)
