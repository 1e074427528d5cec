"""What LaTeX from a problem file may reach the typesetter (and pandoc).

The policy, for every text field of a problem file (title, topic, meanings, question):

- Refused everywhere, in text and inside math: commands that read or write files, run
  programs or change how TeX reads its input (`FORBIDDEN`, and any command whose name
  contains input, include, write, open, read, catcode, csname, lua, shell, or starts with
  pdf), TeX's `^^` character escapes (`^^5c` is a backslash), and control characters.
- Titles and meanings are plain text: the templates' `tex` filter escapes them whole.
- The question is LaTeX-flavoured. `$...$` is math and passes as written (its braces must
  balance, a `%` must be `\\%`, an environment must be a math one such as pmatrix or cases).
  Outside math, LaTeX's specials are escaped (% $ & # _ { } ~ ^ \\) except the small
  whitelist `TEXT_COMMANDS` (\\emph{...}, \\textbf{...}, \\ldots, \\% ...); another command
  outside math is refused when the file is read (it would print as written). `{{ NAME }}`
  placeholders of declared parameters are the only jinja allowed, and outside math (each
  becomes `$value$`).

`check` runs when a file is read (derive.reader: an error naming the file and the field);
`question_latex` runs again on the rendered question (derive.render), so text that did not
come through the reader is escaped and checked too.

>>> question_latex("50% of $\\\\omega_0$ & \\\\emph{more}_x")
'50\\\\% of $\\\\omega_0$ \\\\& \\\\emph{more}\\\\_x'
>>> forbidden("csname"), forbidden("pdffiledump"), forbidden("omega")
(True, True, False)
"""
from __future__ import annotations

import re

from derive.errors import InputError

FORBIDDEN = frozenset({
    "input", "include", "includeonly", "InputIfFileExists", "IfFileExists", "endinput", "openin", "openout",
    "read", "readline", "write", "immediate", "newwrite", "newread", "closein", "closeout",
    "catcode", "lccode", "uccode", "sfcode", "mathcode", "delcode", "csname", "endcsname", "expandafter",
    "noexpand", "def", "edef", "gdef", "xdef", "let", "futurelet", "global", "newcommand", "renewcommand",
    "providecommand", "DeclareRobustCommand", "newenvironment", "renewenvironment", "usepackage",
    "RequirePackage", "documentclass", "special", "directlua", "latelua", "ShellEscape", "scantokens",
    "makeatletter", "makeatother", "everypar", "everymath", "everydisplay", "everyeof", "everyjob",
    "output", "loop", "afterassignment", "aftergroup", "verbatiminput", "lstinputlisting", "inputminted",
    "import", "subimport", "subfile", "includegraphics", "href", "url", "jobname", "string", "detokenize",
    "uppercase", "lowercase", "begingroup", "endgroup", "batchmode", "nonstopmode", "scrollmode",
    "errorstopmode",
})
_FORBIDDEN_PART = re.compile(r"input|include|write|open|read|catcode|csname|lua|shell|^pdf", re.IGNORECASE)

#: Commands allowed outside math: with one argument in braces, or alone.
TEXT_COMMANDS = frozenset({"emph", "textbf", "textit", "texttt", "underline"})
TEXT_WORDS = frozenset({"ldots", "dots", "quad", "qquad", "S", "P", "textdegree", "newline", "par"})
#: Escaped specials, spacing and accents allowed outside math (a backslash and one character).
ACCENTS = frozenset("'`\"^~=.")
TEXT_SYMBOLS = frozenset("%$&#_{}" + ",;:! ") | ACCENTS
MATH_ENVIRONMENTS = frozenset({"matrix", "pmatrix", "bmatrix", "Bmatrix", "vmatrix", "Vmatrix", "smallmatrix",
                               "cases", "aligned", "gathered", "split", "array"})

SPECIALS = {"\\": r"\textbackslash{}", "{": r"\{", "}": r"\}", "$": r"\$", "&": r"\&", "#": r"\#",
            "%": r"\%", "_": r"\_", "~": r"\textasciitilde{}", "^": r"\textasciicircum{}"}

_TOKEN = re.compile(r"\\(?:[A-Za-z]+|.)|.", re.S)
_CONTROL = re.compile(r"[\x00-\x08\x0b-\x1f\x7f]")
_PLACEHOLDER = re.compile(r"\{\{\s*([A-Za-z_][A-Za-z0-9_]*)\s*\}\}")
_JINJA = re.compile(r"\{\{|\{%|\{#|\}\}|%\}|#\}")


class LatexError(InputError):
    """LaTeX in a problem file that derive will not typeset."""


def forbidden(name: str) -> bool:
    """Whether a control word (its name, without the backslash) is refused."""
    return name in FORBIDDEN or bool(_FORBIDDEN_PART.search(name))


def _refuse_everywhere(text: str) -> None:
    if "^^" in text:
        raise LatexError("'^^' is not allowed (TeX reads ^^5c as a backslash): write ^{} or \\^{}")
    control = _CONTROL.search(text)
    if control:
        raise LatexError(f"control character {control.group()!r} is not allowed")
    for match in re.finditer(r"\\(?:[A-Za-z]+|.)", text, re.S):
        name = match.group()[1:]
        if name.isalpha() and forbidden(name):
            raise LatexError(f"\\{name} is not allowed (it could read or write files, or change how TeX "
                             "reads its input)")


def _split(text: str) -> list[tuple[bool, str]]:
    """(is_math, piece) in order: $...$ pieces and the text between. A \\$ is text; an unpaired
    $ and an empty $$ (display math) are text too."""
    tokens = _TOKEN.findall(text)
    dollars = [i for i, token in enumerate(tokens) if token == "$"]
    math = {}
    k = 0
    while k + 1 < len(dollars):
        first, second = dollars[k], dollars[k + 1]
        if second == first + 1:  # $$: not math
            k += 1
            continue
        math[first] = second
        k += 2
    pieces, i, text_start = [], 0, 0
    while i < len(tokens):
        if i in math:
            if i > text_start:
                pieces.append((False, "".join(tokens[text_start:i])))
            pieces.append((True, "".join(tokens[i:math[i] + 1])))
            i = text_start = math[i] + 1
        else:
            i += 1
    if text_start < len(tokens):
        pieces.append((False, "".join(tokens[text_start:])))
    return pieces


def _check_math(math: str) -> None:
    depth = 0
    for token in _TOKEN.findall(math):
        if token == "%":
            raise LatexError(f"'%' in math {math[:40]!r} starts a comment: write \\%")
        depth += (token == "{") - (token == "}")
        if depth < 0:
            raise LatexError(f"unbalanced braces in math {math[:40]!r}")
    if depth:
        raise LatexError(f"unbalanced braces in math {math[:40]!r}")
    for name in re.findall(r"\\(?:begin|end)\s*\{([^}]*)\}", math):
        if name.strip().rstrip("*") not in MATH_ENVIRONMENTS:
            raise LatexError(f"environment {name!r} is not allowed in math (allowed: {', '.join(sorted(MATH_ENVIRONMENTS))})")


def _check_text(text: str) -> None:
    for match in re.finditer(r"\\(?:[A-Za-z]+|.)?", text, re.S):
        token = match.group()
        name = token[1:]
        if name in TEXT_COMMANDS and text.startswith("{", match.end()):
            continue
        if name in TEXT_WORDS or (len(name) == 1 and name in TEXT_SYMBOLS) or token == "\\\\":
            continue
        allowed = ", ".join(f"\\{c}{{...}}" for c in sorted(TEXT_COMMANDS))
        hint = " (math goes between $...$)" if name.isalpha() else ""
        raise LatexError(f"LaTeX command {token!r} is not allowed outside math{hint}; allowed: {allowed}, "
                         f"{', '.join(chr(92) + w for w in sorted(TEXT_WORDS))} and \\% \\$ \\& \\# \\_ \\{{ \\}}")


def check(text: str, question: bool = False, placeholders=()) -> None:
    """Refuse text that could misuse TeX (see the module's policy); raise LatexError.

    With `question`, the text is the question: its math is checked, commands outside math
    must be whitelisted, and `{{ NAME }}` (NAME one of `placeholders`) is the only jinja.
    """
    _refuse_everywhere(text)
    if not question:
        return
    for is_math, piece in _split(text):
        if is_math:
            if _JINJA.search(piece):
                raise LatexError("a {{ placeholder }} becomes $value$: put it outside $...$")
            _check_math(piece)
            continue
        for name in _PLACEHOLDER.findall(piece):
            if name not in placeholders:
                raise LatexError(f"{{{{ {name} }}}}: not a parameter (parameters: {', '.join(placeholders) or 'none'})")
        rest = _PLACEHOLDER.sub("", piece)
        jinja = _JINJA.search(rest)
        if jinja:
            snippet = rest[max(0, jinja.start() - 10): jinja.end() + 30].strip()
            raise LatexError(f"only {{{{ NAME }}}} placeholders of parameters are allowed, not {snippet!r}")
        _check_text(rest)


def _escape_text(text: str) -> str:
    """Text outside math: specials escaped, the whitelisted commands kept."""
    out, braces, argument = [], [], False
    tokens = _TOKEN.findall(text)
    for i, token in enumerate(tokens):
        following = tokens[i + 1] if i + 1 < len(tokens) else ""
        if argument:  # the "{" of a command just kept
            out.append("{")
            braces.append("argument")
            argument = False
        elif token.startswith("\\") and len(token) > 1:
            name = token[1:]
            if (name in TEXT_COMMANDS or name in ACCENTS) and following == "{":
                out.append(token)
                argument = True
            elif name in TEXT_WORDS:
                out.append(token + "{}")
            elif name in TEXT_SYMBOLS or name == "\\":
                out.append(token)
            else:
                out.append(SPECIALS["\\"] + "".join(SPECIALS.get(c, c) for c in name))
        elif token == "{":
            braces.append("literal")
            out.append(r"\{")
        elif token == "}":
            out.append("}" if (braces.pop() if braces else "literal") == "argument" else r"\}")
        else:
            out.append(SPECIALS.get(token, token))
    return "".join(out) + "}" * braces.count("argument")


def question_latex(rendered: str) -> str:
    """The rendered question made safe: refused as `check` would (LatexError), math kept,
    the text between escaped but for the whitelisted commands."""
    _refuse_everywhere(rendered)
    parts = []
    for is_math, piece in _split(rendered):
        if is_math:
            _check_math(piece)
            parts.append(piece)
        else:
            parts.append(_escape_text(piece))
    return "".join(parts)
