"""The jinja environments: LaTeX templates from templates/, and problem question text.

Templates use LaTeX-friendly delimiters (\\VAR{...}, \\BLOCK{...}, \\#{...}) so braces stay
LaTeX's; both environments are sandboxed and strict (an undefined name is an error, not
blank text), because question text comes from problem files.

>>> question("A mass {{ m }} hangs.", {"m": "$2\\\\,\\\\mathrm{kg}$"})
'A mass $2\\\\,\\\\mathrm{kg}$ hangs.'
"""
from __future__ import annotations

from functools import lru_cache

import jinja2
import sympy as sp
from jinja2.sandbox import SandboxedEnvironment

from derive import latex_safety, library

def tex_escape(text: str) -> str:
    """Plain text made safe to typeset: LaTeX's special characters escaped."""
    return "".join(latex_safety.SPECIALS.get(c, c) for c in str(text))


def latex_of(expression) -> str:
    """sympy's LaTeX for an expression or equation."""
    return sp.latex(expression)


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


@lru_cache(maxsize=1)
def _questions() -> SandboxedEnvironment:
    return SandboxedEnvironment(undefined=jinja2.StrictUndefined, autoescape=False)


def question(text: str, values: dict[str, str]) -> str:
    """Render a problem's question text, `{{ name }}` standing for a parameter's value and unit.

    Raises jinja2 errors (UndefinedError, TemplateSyntaxError, SecurityError) for names or
    syntax the problem does not declare. The result is made safe for LaTeX by
    `latex_safety.question_latex`: math kept, specials outside it escaped, LatexError for
    what could misuse TeX.
    """
    return latex_safety.question_latex(_questions().from_string(text).render(**values))


def render(template: str, **context) -> str:
    return templates().get_template(template).render(**context)
