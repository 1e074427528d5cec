r"""How TeX reads a question's text, and what it may hold (the policy: derive.text.latex_safety): the
vocabulary of the question (the tables below), the tokenizer (one regular expression, TeX's
standard catcodes) and `Parser`, the recursive descent that checks the text and builds its LaTeX.

>>> Parser("$x^2$ & 5%", {}, 100).question()
'$x^2$ \\& 5\\%'
"""
from __future__ import annotations

import re
import unicodedata
from contextlib import contextmanager
from typing import Mapping

from derive.text.latex_characters import LatexError, check_characters, describe
from derive.text.stencil import hole

MAX_DEPTH = 10  # groups, arguments, environments and \left...\right inside one another

# --- the question's vocabulary -----------------------------------------------------------------
#: Text commands with one argument, itself text.
TEXT_COMMANDS = frozenset({"emph", "textbf", "textit", "texttt", "underline"})
#: Text commands without arguments (written with {} after them, so the next space stays).
TEXT_WORDS = frozenset({"ldots", "dots", "quad", "qquad", "S", "P", "textdegree"})
#: Control symbols of text: escaped specials and spacing.
TEXT_SYMBOLS = frozenset("%$&#_{}" + ",;:! ")
#: Accents of text, on one letter: \'e or \'{e}.
ACCENTS = frozenset("'`\"^~=.")

#: Math commands that are one math character to TeX (a \mathchar or \delimiter): `x^\alpha`
#: needs no braces.
MATH_SYMBOLS = frozenset("""
    alpha beta gamma delta epsilon varepsilon zeta eta theta vartheta iota kappa lambda mu nu xi
    pi varpi rho varrho sigma varsigma tau upsilon phi varphi chi psi omega
    Gamma Delta Theta Lambda Xi Pi Sigma Upsilon Phi Psi Omega
    leq geq le ge approx sim simeq propto equiv ll gg perp parallel mid in subset subseteq supset
    supseteq to gets rightarrow leftarrow leftrightarrow Rightarrow Leftarrow Leftrightarrow uparrow
    downarrow cdot times pm mp div ast star circ bullet cap cup wedge vee oplus otimes dagger
    infty partial nabla ell prime emptyset forall exists neg Re Im
    langle rangle lfloor rfloor lceil rceil vert Vert backslash
""".split())
#: Math commands without arguments that are macros: in a script they need braces (x^{\hbar}).
MATH_WORDS = frozenset("""
    hbar neq ne cong notin mapsto longrightarrow implies iff angle
    int iint iiint oint sum prod lim max min sup inf det dim arg deg gcd exp ln log
    sin cos tan cot sec csc arcsin arccos arctan sinh cosh tanh coth
    ldots cdots vdots ddots dots quad qquad
""".split())
#: Math commands with arguments: the kind of each mandatory argument, always in braces: "math",
#: "text" (read as text: \text{if $x > 0$}) or "name" (letters: \operatorname{sgn}). \sqrt may
#: also take an index, \sqrt[3]{x}.
MATH_COMMANDS = {
    "frac": ("math", "math"), "dfrac": ("math", "math"), "tfrac": ("math", "math"), "binom": ("math", "math"),
    "overset": ("math", "math"), "underset": ("math", "math"), "sqrt": ("math",),
    "hat": ("math",), "bar": ("math",), "vec": ("math",), "dot": ("math",), "ddot": ("math",),
    "tilde": ("math",), "widehat": ("math",), "widetilde": ("math",), "overline": ("math",),
    "underline": ("math",), "overrightarrow": ("math",), "boldsymbol": ("math",),
    "mathrm": ("math",), "mathbf": ("math",), "mathit": ("math",), "mathsf": ("math",), "mathtt": ("math",),
    "mathcal": ("math",), "text": ("text",), "operatorname": ("name",),
}
#: What the values derive puts in a question may use besides (units.siunitx_unit, in the PDFs),
#: and a question's own text may not: pandoc and MathJax, which show the other formats, read none.
UNIT_COMMANDS = {"unit": ("math",), "degree": (), "micro": ()}
#: Math accents: alone in a group (or a math alphabet), TeX takes one out, scripts and all.
MATH_ACCENTS = frozenset({"hat", "bar", "vec", "dot", "ddot", "tilde", "widehat", "widetilde"})
#: Math alphabets: their argument is a group of the list they stand in.
MATH_ALPHABETS = frozenset({"mathrm", "mathbf", "mathit", "mathsf", "mathtt", "mathcal"})
#: Commands with arguments that may follow ^ or _ without braces (K_\mathrm{rot}): TeX reads
#: their expansion as a group.
SCRIPT_COMMANDS = MATH_ALPHABETS | {"text"}
#: Control symbols of math: spacing and escaped specials.
MATH_CONTROL_SYMBOLS = frozenset(",;:! {}|%$&#_")
#: Delimiters after \left, \middle and \right: characters, control symbols and words.
DELIMITERS = frozenset({"(", ")", "[", "]", "|", "/", ".", r"\{", r"\}", r"\|"}) | frozenset(
    "\\" + name for name in ("langle", "rangle", "lfloor", "rfloor", "lceil", "rceil", "vert", "Vert",
                             "uparrow", "downarrow", "backslash"))
#: Math environments and the columns a row of each may have (None: any number; each `&` starts
#: a column); rows end with \\.
MATH_ENVIRONMENTS = {"matrix": 10, "pmatrix": 10, "bmatrix": 10, "Bmatrix": 10, "vmatrix": 10, "Vmatrix": 10,
                     "smallmatrix": 10, "cases": 2, "aligned": None, "gathered": 1}
#: Environments whose \begin{...} takes an optional [position]: a `[` after it would be read so.
POSITIONED = frozenset({"aligned", "gathered"})
#: Characters of math besides letters and digits (~ is a tie; ' a prime).
MATH_CHARACTERS = frozenset("+-*/=<>()[]|,.;:!?'\"@`~ \n")
#: Characters that may follow ^ or _ alone (x^2, x_i, x^-).
SCRIPT_CHARACTERS = frozenset("+-*/=<>|,.;:!?") | frozenset(
    "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789")

#: LaTeX's special characters and what prints each in text.
SPECIALS = {"\\": r"\textbackslash{}", "{": r"\{", "}": r"\}", "$": r"\$", "&": r"\&", "#": r"\#",
            "%": r"\%", "_": r"\_", "~": r"\textasciitilde{}", "^": r"\textasciicircum{}"}


def check_length(text: str, limit: int) -> None:
    """Refuse text longer than `limit` characters."""
    if len(text) > limit:
        raise LatexError(f"{len(text)} characters: at most {limit}")


def check_escapes(text: str) -> None:
    """Refuse TeX's `^^` escapes."""
    if "^^" in text:
        raise LatexError("'^^' is not allowed (TeX reads ^^5c as a backslash): write ^{} or \\^{}")


# --- the parser --------------------------------------------------------------------------------
_TOKEN = re.compile(r"""
    (?P<placeholder>\{\{\s*(?P<name>[A-Za-z_][A-Za-z0-9_]*)\s*\}\})
  | (?P<par>\n[ ]*\n[ \n]*)            # a blank line: a new paragraph
  | \\[A-Za-z]+ | \\. | .              # a control word, a control symbol, a character
""", re.S | re.X)
_SHOWN = re.compile(r"\\[A-Za-z@_:]+|\\.?", re.S)  # a command as a person reads it: \iow_open:Nn
_SPACE = (" ", "\n")
_LETTER = re.compile("[A-Za-z]")
_MATH_NAMES = MATH_SYMBOLS | MATH_WORDS | set(MATH_COMMANDS)
_PAR = "\n\n"  # the kind of a blank-line token


def command_at(text: str, at: int) -> str:
    """The command at `at` as a person reads it: \\iow_open:Nn, not TeX's \\iow."""
    shown = _SHOWN.match(text, at).group()
    return "\\ at the end of a line" if shown == "\\\n" else shown


#: What to write in math for some non-ASCII characters (Greek letters: their command).
MATH_UNICODE = {"×": r"\times", "·": r"\cdot", "⋅": r"\cdot", "±": r"\pm", "∓": r"\mp", "°": r"^\circ",
                "→": r"\to", "←": r"\leftarrow", "≤": r"\leq", "≥": r"\geq", "≠": r"\neq", "≈": r"\approx",
                "∞": r"\infty", "∂": r"\partial", "∇": r"\nabla", "−": "-", "′": "'", "∝": r"\propto",
                "∫": r"\int", "∑": r"\sum", "√": r"\sqrt{...}", "ℏ": r"\hbar", "ℓ": r"\ell", "…": r"\ldots",
                "÷": r"\div", "²": "^2", "³": "^3", "–": "-", "—": "-"}


def math_hint(character: str) -> str:
    """What to write in math instead of a non-ASCII character.

    >>> math_hint("μ"), math_hint("Ω"), math_hint("×")
    ('write \\\\mu', 'write \\\\Omega', 'write \\\\times')
    """
    if character in MATH_UNICODE:
        return f"write {MATH_UNICODE[character]}"
    words = unicodedata.name(character, "").split()
    if len(words) == 4 and words[0] == "GREEK" and words[2] == "LETTER":
        letter = words[3].lower().replace("lamda", "lambda")
        command = letter.capitalize() if words[1] == "CAPITAL" else letter
        if command in MATH_SYMBOLS:
            return f"write \\{command}"
    return "math is ASCII: write a command such as \\alpha, or words in \\text{...}"


class Parser:
    """One pass over a question: checks it and builds its LaTeX (see the module's policy)."""

    def __init__(self, text: str, values: Mapping[str, str | None], limit: int, units: bool = False):
        check_length(text, limit)
        self.units = units  # a value derive wrote: its unit may be siunitx's (UNIT_COMMANDS)
        check_characters(text, newlines=True)
        check_escapes(text)
        self.source = text
        self.values = values
        self.limit = limit
        self.tokens = []  # (kind, text, offset): kind is the token, _PAR, or "{{" with text the name
        for match in _TOKEN.finditer(text):
            if match.group("placeholder"):
                self.tokens.append(("{{", match.group("name"), match.start()))
            elif match.group("par"):
                self.tokens.append((_PAR, match.group(), match.start()))
            else:
                self.tokens.append((match.group(), match.group(), match.start()))
        self.i = 0
        self.depth = 0
        self.lone_accent = None  # see math_mode

    # tokens
    def peek(self, ahead: int = 0) -> str | None:
        """The kind of the next token (or the one `ahead` of it); None at the end."""
        i = self.i + ahead
        return self.tokens[i][0] if i < len(self.tokens) else None

    def take(self) -> tuple[str, str, int]:
        token = self.tokens[self.i]
        self.i += 1
        return token

    def spaces(self) -> str:
        """Skip spaces and single line breaks (TeX skips them before an argument); return them."""
        start = self.i
        while self.peek() in _SPACE:
            self.i += 1
        return "".join(text for _, text, _ in self.tokens[start:self.i])

    def at(self, offset: int) -> str:
        """A snippet of the source around an offset, on one line, to name a place in an error."""
        return "'" + self.source[max(0, offset - 10):offset + 8].replace("\n", " ").strip() + "'"

    @contextmanager
    def nested(self, offset: int):
        self.depth += 1
        if self.depth > MAX_DEPTH:
            raise LatexError(f"groups nested more than {MAX_DEPTH} deep at {self.at(offset)}")
        try:
            yield
        finally:
            self.depth -= 1

    def question(self) -> str:
        return self.text_mode(None)

    # text
    def text_mode(self, command: str | None) -> str:
        """Text up to the end, or (inside `command`'s argument) to the `}` that closes it."""
        out, braces = [], 0
        while True:
            if self.peek() is None:
                if command:
                    raise LatexError(f"{command}{{...}} is not closed: a '}}' is missing")
                return "".join(out)
            kind, text, offset = self.take()
            if kind == "}" and command and not braces:
                return "".join(out)
            if kind in ("{", "}"):
                braces += 1 if kind == "{" else -(braces > 0)
                out.append(SPECIALS[kind])
            elif kind == "$":
                out.append(self.math_piece(offset))
            elif kind == "{{":
                out.append(self.placeholder(text))
            elif kind == _PAR:
                if command:
                    raise LatexError(f"a blank line inside {command}{{...}} at {self.at(offset)}")
                out.append(text)
            elif kind.startswith("\\"):
                out.append(self.text_command(kind, offset))
            else:
                out.append(SPECIALS.get(kind, kind))

    def placeholder(self, name: str) -> str:
        if name not in self.values:
            raise LatexError(f"{{{{ {name} }}}}: not a parameter (parameters: {', '.join(self.values) or 'none'})")
        return "" if self.values[name] is None else hole(name)  # a value goes in its hole

    def text_command(self, token: str, offset: int) -> str:
        name = token[1:]
        if name in TEXT_COMMANDS:
            return token + self.spaces() + self.argument(token, offset, "text")
        if name in TEXT_WORDS:
            if self.peek() == "{" and self.peek(1) == "}":
                self.i += 2  # \ldots{}: the usual way to keep the space after it
            return token + "{}"
        if name in TEXT_SYMBOLS:
            return token
        if name in ACCENTS:
            return token + self.accent(token, offset)
        if token == "\\\\":
            raise LatexError("\\\\ (a line break) is not allowed outside a math environment: the question "
                             "is one paragraph (a blank line may start another)")
        shown = command_at(self.source, offset)
        hint = " (math goes between $...$)" if name in _MATH_NAMES else ""
        allowed = ", ".join(f"\\{c}{{...}}" for c in sorted(TEXT_COMMANDS))
        words = ", ".join("\\" + w for w in sorted(TEXT_WORDS))
        raise LatexError(f"{shown} is not allowed outside math{hint}; allowed: {allowed}, {words}, accents "
                         "and \\% \\$ \\& \\# \\_ \\{ \\}")

    def accent(self, token: str, offset: int) -> str:
        """The letter of an accent: \\'e or \\'{e}, written {e}."""
        braced = self.peek() == "{"
        letter = self.peek(braced) or ""
        if not (_LETTER.fullmatch(letter) and (not braced or self.peek(2) == "}")):
            raise LatexError(f"the accent {token} at {self.at(offset)} goes on one letter: {token}e or {token}{{e}}")
        self.i += 3 if braced else 1
        return "{" + letter + "}"

    def argument(self, command: str, offset: int, kind: str) -> str:
        """A mandatory argument in braces: text, math or a name (letters)."""
        if self.peek() != "{":
            raise LatexError(f"{command} at {self.at(offset)} needs its argument in braces")
        _, _, start = self.take()
        with self.nested(start):
            if kind == "text":
                return "{" + self.text_mode(command) + "}"
            if kind == "name":
                name = self.letters()
                if not name or self.peek() != "}":
                    raise LatexError(f"{command}{{...}} at {self.at(offset)} takes letters only")
                self.i += 1
                return "{" + name + "}"
            return "{" + self.math_mode("}", start) + "}"

    def letters(self) -> str:
        start = self.i
        while _LETTER.fullmatch(self.peek() or ""):
            self.i += 1
        return "".join(kind for kind, _, _ in self.tokens[start:self.i])

    # math
    def math_piece(self, offset: int) -> str:
        if self.peek() == "$":
            raise LatexError(f"$$ (display math) at {self.at(offset)} is not allowed: write $...$")
        with self.nested(offset):
            return "$" + self.math_mode("$", offset) + "$"

    def math_mode(self, end: str, opened: int, environment: str | None = None, index: bool = False) -> str:
        """Math up to `end`: "$", "}" (a group), "]" (the index of \\sqrt), "\\right" or "\\end"
        (an `environment`'s body). `index`: inside \\sqrt[...], where TeX ends the index at the
        first `]` outside braces. Sets self.lone_accent: the scripts of the list's only atom if that
        is an accent, which TeX hoists out of a group ({\\bar{x}_b}_a is a double subscript)."""
        out = []
        sup = sub = None  # the atom's superscript and subscript: None, "prime" (a ' sequence going on), "done"
        tabs = items = 0  # the row's & so far; the atoms and glue of the list so far
        accent = False  # whether the last atom is an accent (one TeX would hoist out of a group)
        while True:
            if self.peek() is None or (self.peek() == "$" and end != "$"):
                raise LatexError(self.unclosed(end, opened, environment))
            kind, text, offset = self.take()
            if sup == "prime" and kind not in ("'", "^"):
                sup = "done"  # LaTeX's ' merges only with a ' or ^ right after it
            if kind in _SPACE:
                out.append(text)
                continue
            if kind in ("^", "_", "'"):
                taken = sup if kind != "_" else sub
                if taken == "done":
                    raise LatexError(f"double {'sub' if kind == '_' else 'super'}script at {self.at(offset)}: "
                                     "put both in one group, x^{ab}")
                if kind == "'":
                    sup = "prime"
                    out.append(text)
                    continue
                if kind == "^":
                    sup = "done"
                else:
                    sub = "done"
                out.append(text + self.script(kind, offset, index))
                continue
            atom, sup, sub = (sup, sub), None, None  # anything else is a new atom (or glue, after which TeX starts one)
            if kind == end:
                self.lone_accent = atom if items == 1 and accent else None
                return "".join(out)
            items, accent, hoisted = items + 1, False, None
            if kind == "]" and index:
                raise LatexError(f"a ']' inside \\sqrt[...] at {self.at(offset)} ends the index: put it in braces")
            if kind == "&":
                if environment is None:
                    raise LatexError(f"'&' at {self.at(offset)} outside a math environment ({self.environments()})")
                tabs += 1
                most = MATH_ENVIRONMENTS[environment]
                if most is not None and tabs >= most:
                    raise LatexError(f"a row of {environment} has at most {most} columns ({most - 1} '&') at "
                                     f"{self.at(offset)}")
                out.append(text)
            elif kind == "\\\\":
                if environment is None:
                    raise LatexError(f"\\\\ at {self.at(offset)} outside a math environment ({self.environments()})")
                tabs = 0
                out.append(text + self.after_row(offset))
            elif kind.startswith("\\"):
                out.append(self.math_command(kind, offset, index, end))
                hoisted = self.lone_accent if kind[1:] in MATH_ALPHABETS else None
                accent = kind[1:] in MATH_ACCENTS or hoisted is not None
            elif kind == "{":
                with self.nested(offset):
                    out.append("{" + self.math_mode("}", offset) + "}")
                hoisted = self.lone_accent
                accent = hoisted is not None
            else:
                out.append(self.math_character(kind, offset))
            if hoisted:  # TeX took the group's lone accent out of it, with its scripts
                sup, sub = hoisted

    def unclosed(self, end: str, opened: int, environment: str | None) -> str:
        what = {"$": "unpaired '$' (write \\$ for a dollar sign)", "}": "unbalanced braces: a '{' is not closed",
                "]": "\\sqrt[ is not closed by ]", "\\right": "\\left is not closed by \\right",
                "\\end": f"\\begin{{{environment}}} is not closed by \\end{{{environment}}}"}[end]
        return f"{what} at {self.at(opened)}"

    def math_character(self, kind: str, offset: int) -> str:
        if kind.isascii() and (kind.isalnum() or kind in MATH_CHARACTERS):
            return kind
        if kind == "}":
            raise LatexError(f"unbalanced braces: '}}' at {self.at(offset)} closes no group")
        if kind == "%":
            raise LatexError(f"'%' in math at {self.at(offset)} starts a comment: write \\%")
        if kind == "{{":
            raise LatexError("a {{ placeholder }} becomes $value$: put it outside $...$")
        if kind == _PAR:
            raise LatexError(f"a blank line inside math at {self.at(offset)}")
        if not kind.isascii():
            raise LatexError(f"{kind!r} ({describe(kind)}) in math: {math_hint(kind)}")
        raise LatexError(f"{kind!r} is not allowed in math at {self.at(offset)}")

    @staticmethod
    def environments() -> str:
        return "only in " + ", ".join(sorted(MATH_ENVIRONMENTS))

    def script(self, kind: str, offset: int, index: bool) -> str:
        """The argument of ^ or _: a character, a math symbol, a SCRIPT_COMMANDS command or a group."""
        spaces = self.spaces()
        token = self.peek()
        if token == "{":
            _, _, start = self.take()
            with self.nested(start):
                return spaces + "{" + self.math_mode("}", start) + "}"
        if token is not None and token in SCRIPT_CHARACTERS:
            self.i += 1
            return spaces + token
        if token is not None and token.startswith("\\") and token[1:] in MATH_SYMBOLS:
            self.i += 1
            return spaces + token
        if token is not None and token.startswith("\\") and token[1:] in SCRIPT_COMMANDS:
            _, _, start = self.take()
            return spaces + self.math_command(token, start, index, None)
        raise LatexError(f"`{kind}` at {self.at(offset)} needs an argument: a character, a symbol such as \\alpha, "
                         "or {...}")

    def after_row(self, offset: int) -> str:
        """The spaces after a \\\\ of an environment: a [ or * next would be read as its option."""
        spaces = self.spaces()
        if self.peek() in ("[", "*"):
            raise LatexError(f"{self.peek()!r} after \\\\ at {self.at(offset)} would be read as its option: "
                             "write {[} or {*}")
        return spaces

    def delimiter(self, command: str, offset: int, index: bool) -> str:
        spaces = self.spaces()
        token = self.peek()
        if token not in DELIMITERS:
            raise LatexError(f"{command} at {self.at(offset)} needs a delimiter: one of "
                             f"{' '.join(sorted(DELIMITERS))}")
        if token == "]" and index:
            raise LatexError(f"a ']' inside \\sqrt[...] at {self.at(offset)} ends the index: put it in braces")
        self.i += 1
        return spaces + token

    def math_command(self, token: str, offset: int, index: bool, end: str | None) -> str:
        name = token[1:]
        if name in MATH_CONTROL_SYMBOLS or name in MATH_SYMBOLS or name in MATH_WORDS:
            return token
        if name == "sqrt":
            spaces = self.spaces()
            if self.peek() == "[":
                if index:  # TeX would end the outer index at this one's ]
                    raise LatexError(f"a \\sqrt[...] inside the index of another at {self.at(offset)}: put it in braces")
                _, _, start = self.take()
                with self.nested(start):
                    spaces += "[" + self.math_mode("]", start, index=True) + "]"
            return token + spaces + self.spaces() + self.argument(token, offset, "math")
        if self.units and name in UNIT_COMMANDS:
            return token + "".join(self.spaces() + self.argument(token, offset, kind) for kind in UNIT_COMMANDS[name])
        if name in MATH_COMMANDS:
            return token + "".join(self.spaces() + self.argument(token, offset, kind) for kind in MATH_COMMANDS[name])
        if name == "left":
            with self.nested(offset):
                opening = self.delimiter(token, offset, index)
                body = self.math_mode("\\right", offset, index=index)
                return token + opening + body + "\\right" + self.delimiter("\\right", offset, index)
        if name == "middle" and end == "\\right":
            return token + self.delimiter(token, offset, index)
        if name == "begin":
            return self.environment(offset, index)
        if name in ("right", "middle", "end"):
            opening = "\\begin" if name == "end" else "\\left"
            raise LatexError(f"{token} at {self.at(offset)} without a {opening}")
        hint = " (it is text: write it outside $...$)" if name in TEXT_COMMANDS | TEXT_WORDS else ""
        raise LatexError(f"{command_at(self.source, offset)} is not allowed in math{hint}")

    def environment_name(self, command: str, offset: int) -> str:
        if self.peek() != "{":
            raise LatexError(f"\\{command} at {self.at(offset)} needs an environment name in braces")
        self.i += 1
        name = self.letters()
        if self.peek() != "}" or name not in MATH_ENVIRONMENTS:
            raise LatexError(f"\\{command}{{{name}...}} at {self.at(offset)}: the math environments are "
                             f"{', '.join(sorted(MATH_ENVIRONMENTS))}")
        self.i += 1
        return name

    def environment(self, offset: int, index: bool) -> str:
        name = self.environment_name("begin", offset)
        with self.nested(offset):
            spaces = self.spaces()
            if name in POSITIONED and self.peek() == "[":
                raise LatexError(f"'[' right after \\begin{{{name}}} at {self.at(offset)} would be read as its "
                                 "position: write {[}")
            body = spaces + self.math_mode("\\end", offset, environment=name, index=index)
            closing = self.environment_name("end", offset)
            if closing != name:
                raise LatexError(f"\\begin{{{name}}} at {self.at(offset)} is closed by \\end{{{closing}}}")
        return f"\\begin{{{name}}}{body}\\end{{{name}}}"
