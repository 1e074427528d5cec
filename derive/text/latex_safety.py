r"""What text from a problem file may reach the typesetter: an allowlist, read the way TeX reads.

Every text field goes through one of two checks, each with a length bound (`*_LIMIT`):

- **Plain text** (titles, topics, meanings, sources, corrections; set files' titles):
  `check_plain`. The templates' `tex` filter escapes it whole, so LaTeX there would print as
  written: a control word (`\emph`, `\input`) is refused, and so are `^^` escapes.
- **The question**: `check_question` when the file is read, `question_latex` when it is
  typeset. It is LaTeX-flavoured, read token by token as TeX reads it with the standard
  catcodes (a control word is `\` and letters, a control symbol `\` and one other character;
  problem text can never change catcodes; derive.text.latex_grammar reads it). Only the commands
  of its tables may appear, each with its mandatory arguments in braces. `$...$` is math: `MATH_SYMBOLS`, `MATH_WORDS`,
  `MATH_COMMANDS`, `\left`/`\middle`/`\right` with `DELIMITERS`, the `MATH_ENVIRONMENTS` (the
  only places for `&` and `\\`); `^` and `_` take an argument, once each per atom; braces
  balance. Between the math is text: `TEXT_COMMANDS` (with an argument), `TEXT_WORDS`,
  `TEXT_SYMBOLS`, `ACCENTS`, LaTeX's other specials escaped (`50%` prints 50%, a lone `{` a
  brace). `{{ NAME }}` stands for a parameter's value (NAME must be a parameter: text only,
  not in math); every other `{{`, `{%` or `{#` is literal text. One paragraph (a blank line
  may start another; `\\` and `\par` may not), groups at most `MAX_DEPTH` deep. Text so read
  compiles: tests/test_fuzz.py compiles every text it accepts.
- **Characters**, everywhere: those the fonts have (derive.text.latex_characters); math is ASCII.

Every refusal is a LatexError with a one-line reason.

The tokenizer is written here rather than taken from pylatexenc (2.11, evaluated): its
control words are TeX's (`\iow_open:Nn` is `\iow` then text) and it gives the arguments of
macros it is told about, but it reads `^` and `_` as plain characters (`$I^$` parses, and
double superscripts pass), accepts `&` and `\\` anywhere, knows nothing of `^^` escapes or
primes, and cannot parse `$` inside `\text{}`; the checks need TeX's view of every token, so
the tokenizer is one regular expression and the parser a short recursive descent.

>>> question_latex("50% of {{ m }}, $\\omega_0^2$ & \\emph{more}_x", {"m": "$2\\,\\mathrm{kg}$"})
'50\\% of $2\\,\\mathrm{kg}$, $\\omega_0^2$ \\& \\emph{more}\\_x'
>>> check_question("$I^$", ())
Traceback (most recent call last):
...
derive.text.latex_characters.LatexError: `^` at '$I^$' needs an argument: a character, a symbol such as \alpha, or {...}
"""
from __future__ import annotations

import re
from functools import lru_cache
from typing import Mapping

from derive.text.latex_characters import LatexError, check_characters
from derive.text.latex_grammar import Parser, check_escapes, check_length, command_at
from derive.text.stencil import Stencil

# --- length bounds (characters) ----------------------------------------------------------------
TITLE_LIMIT = 200
TOPIC_LIMIT = 60
NAME_LIMIT = 100  # ids, units, the path an ask is `of`
MEANING_LIMIT = 300  # meanings of parameters and asks, the `because` of a condition
SOURCE_LIMIT = 300
CORRECTION_LIMIT = 1000
QUESTION_LIMIT = 5000


def check_plain(text: str, limit: int) -> None:
    """Refuse plain text (escaped whole when typeset) that is too long, holds a character that
    may not be typeset, a LaTeX command (it would print as written) or a `^^` escape.

    >>> check_plain("Rolling 50% & more, § 4 — Ω", TITLE_LIMIT)
    >>> check_plain("\\\\iow_open:Nn", TITLE_LIMIT)
    Traceback (most recent call last):
    ...
    derive.text.latex_characters.LatexError: \\iow_open:Nn: this text is plain, not LaTeX (it would print as written)
    """
    check_length(text, limit)
    check_characters(text)
    check_escapes(text)
    command = re.search(r"\\[A-Za-z]", text)
    if command:
        raise LatexError(f"{command_at(text, command.start())}: this text is plain, not LaTeX (it would print as written)")


def check_question(text: str, parameters, limit: int = QUESTION_LIMIT) -> None:
    """Refuse a question that `question_latex` would not typeset; `{{ NAME }}` may name any of
    `parameters`.

    >>> check_question("A mass {{ m }} on $\\\\frac{1}{2}$ of a \\\\emph{rope}.", ["m"])
    >>> check_question("$\\\\use:c {in put}$", [])
    Traceback (most recent call last):
    ...
    derive.text.latex_characters.LatexError: \\use:c is not allowed in math
    """
    Parser(text, dict.fromkeys(parameters), limit).question()


def question_latex(text: str, values: Mapping[str, str], limit: int = QUESTION_LIMIT) -> str:
    """The question as LaTeX: refused as `check_question` would (LatexError), math kept, text
    escaped but for the allowed commands, each `{{ NAME }}` replaced by values[NAME] (itself
    read as question text, without placeholders). No template engine: nothing is evaluated.
    The question is read once for every set of values (a set's variants: `question_stencil`).

    >>> question_latex("{{ ''.__class__ }} costs {{ m }}", {"m": "$2$"})
    "\\\\{\\\\{ ''.\\\\_\\\\_class\\\\_\\\\_ \\\\}\\\\} costs $2$"
    """
    return question_stencil(text, tuple(values), limit).fill(
        {name: "" if value is None else _value(value, limit) for name, value in values.items()})


@lru_cache(maxsize=1024)
def question_stencil(text: str, names: tuple[str, ...], limit: int = QUESTION_LIMIT) -> Stencil:
    r"""The question read once, as `question_latex` reads it, and cut at its placeholders (a
    stencil's holes: no question holds their characters, check_characters): a set's variants fill
    it with their values (`quantity`), not reading it again.

    >>> question_stencil("A {{ m }} mass & {{ g }}", ("m", "g")).fill({"m": quantity("2", "\\,\\mathrm{kg}"), "g": "$9$"})
    'A $2\\,\\mathrm{kg}$ mass \\& $9$'
    """
    return Stencil(Parser(text, dict.fromkeys(names, ""), limit).question())


_NUMBER = re.compile(r"-?[0-9]+(?:\.[0-9]+)?(?:\\times10\^\{-?[0-9]+\})?")


def quantity(number: str, unit: str = "") -> str:
    r"""A value as a question shows it, `$NUMBER UNIT$` (a decimal number as derive writes it,
    1.2\times10^{-5}; what follows it, a unit's LaTeX after a thin space, units.after_number), read
    as `question_latex` reads a value: the unit once, in a value of its own, and the number by its
    form (a set writes thousands of values).

    >>> quantity("-1.5\\times10^{-3}", "\\,\\mathrm{m}"), quantity("3")
    ('$-1.5\\times10^{-3}\\,\\mathrm{m}$', '$3$')
    >>> quantity("1}\\input{x")
    Traceback (most recent call last):
    ...
    derive.text.latex_characters.LatexError: '1}\\input{x' is not a number as derive writes one
    """
    if not _NUMBER.fullmatch(number):
        raise LatexError(f"{number!r} is not a number as derive writes one")
    text = f"${number}{unit}$"
    return text if _kept(unit) else _value(text, QUESTION_LIMIT)


@lru_cache(maxsize=256)
def _kept(unit: str) -> bool:
    """Whether a value with this unit reads as written (then any number's does: `quantity`)."""
    text = f"$1{unit}$"
    return _value(text, QUESTION_LIMIT) == text


@lru_cache(maxsize=4096)  # a value drawn to its significant figures recurs across variants
def _value(text: str, limit: int) -> str:
    """A placeholder's value, read as question text without placeholders."""
    return Parser(text, {}, limit, units=True).question()
