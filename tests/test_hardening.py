"""Problem and set files treated as untrusted: time limits, LaTeX safety, the template sandbox,
output names, interrupted builds, pandoc's arguments."""
import os
import re
import subprocess
import threading
import time
import unicodedata
import zipfile
from pathlib import Path

import pytest
import yaml
from jinja2.exceptions import SecurityError, TemplateNotFound, UndefinedError

from conftest import ROOT, document, kept_scratch, run_derive
from derive.text.latex import tex_escape
from derive.publishing import export, leftovers, render
from derive.text import latex_characters, latex_grammar, latex_safety
from derive.core import library, limits
from derive.language import problem, problem_sets
from derive.solution.answers import Solution
from derive.core.errors import InputError, ProblemError

EXOTIC = """\
id: exotic
title: An exotic density
topic: inertia
parameters:
  M: {meaning: mass, unit: kg, value: 2}
  R: {meaning: radius, unit: m, value: 0.5}
scene:
  bodies:
    plate: {shape: disk, mass: M, radius: R, density: (2+cos(r/R))^7*exp(r/R)^3*sin(phi)^6}
ask:
  I: {meaning: moment of inertia, of: plate.inertia, unit: kg*m^2}
question: |
  Find the moment of inertia of a disk of mass {{ M }} and radius {{ R }}.
"""


def problem_text(question="A disk of mass {{ M }} turns.", title="A disk", meaning="mass", ask_meaning="inertia",
                 problem_id="plain_disk"):
    return f"""\
id: {problem_id}
title: "{title}"
topic: inertia
parameters:
  M: {{meaning: "{meaning}", unit: kg, range: [1, 2], sig_figs: 2}}
  R: {{meaning: radius, unit: m, value: 0.5}}
scene:
  bodies:
    disk: {{shape: disk, mass: M, radius: R}}
ask:
  I: {{meaning: "{ask_meaning}", of: disk.inertia, unit: kg*m^2}}
question: |
  {question}
"""


def one_line_exit_2(result):
    assert result.returncode == 2, (result.returncode, result.stderr)
    assert "Traceback" not in result.stderr
    assert len(result.stderr.strip().splitlines()) == 1, result.stderr
    return result.stderr


# --- time limits -------------------------------------------------------------------------------

def test_exotic_density_gives_up_within_the_limit(tmp_path, monkeypatch):
    """This density kept sympy integrating for minutes; with a 2 s limit the ask stops at once."""
    path = tmp_path / "exotic.yaml"
    path.write_text(EXOTIC)
    monkeypatch.setenv("DERIVE_TIME_LIMIT", "2")
    solution = Solution(problem.load(str(path)))
    start = time.monotonic()
    with pytest.raises(limits.TimeLimitError) as caught:
        solution.expression("I")
    assert time.monotonic() - start < 5
    message = str(caught.value)
    assert message.startswith(f"{path}: ask.I: integrating over the disk: gave up after 2 s")
    assert "DERIVE_TIME_LIMIT" in message and "--time-limit" in message
    assert message.endswith("; faster: a density that is a polynomial in the shape's coordinates "
                            "(sympy integrates one at once)")  # the restatement known to be faster
    assert isinstance(caught.value, InputError)


def test_exotic_density_on_the_command_line(tmp_path):
    path = tmp_path / "exotic.yaml"
    path.write_text(EXOTIC)
    start = time.monotonic()
    result = run_derive("--time-limit", "2", "solve", str(path))
    assert time.monotonic() - start < 15
    assert "ask.I: integrating over the disk: gave up after 2 s" in one_line_exit_2(result)


def test_time_limit_nests_and_cleans_up(monkeypatch):
    monkeypatch.setenv("DERIVE_TIME_LIMIT", "0.3")
    with pytest.raises(limits.TimeLimitError, match=r"^outer: inner: gave up after 0\.3 s"):
        with limits.time_limit("outer"):
            with limits.time_limit("inner"):
                while True:
                    pass
    assert limits.signal.getitimer(limits.signal.ITIMER_REAL) == (0.0, 0.0)
    with pytest.raises(limits.TimeLimitError, match=r"^outer: inner: gave up after 0\.3 s .*; faster: a later start$"):
        with limits.time_limit("outer", faster="an earlier start"):
            with limits.time_limit("inner", faster="a later start"):  # the innermost step's restatement
                while True:
                    pass
    assert limits._faster == [] and limits._steps == []
    assert limits.signal.getsignal(limits.signal.SIGALRM) in (limits.signal.SIG_DFL, None)
    with limits.time_limit("quick"):  # after a timeout, the next step runs normally
        assert sum(range(100)) == 4950


def test_time_limit_survives_code_that_swallows_exceptions(monkeypatch):
    """The alarm is a BaseException and repeats: `except Exception: pass` cannot hide it."""
    start = time.monotonic()
    with pytest.raises(limits.TimeLimitError):
        with limits.time_limit("stubborn", seconds=0.2):
            while True:
                try:
                    time.sleep(0.01)
                except Exception:  # noqa: BLE001 - what sympy does in places
                    pass
    assert time.monotonic() - start < 2


@pytest.mark.parametrize("value, expected", [("", 60.0), ("5", 5.0), ("0", None), ("off", None), ("1.5", 1.5)])
def test_time_limit_setting(monkeypatch, value, expected):
    monkeypatch.setenv("DERIVE_TIME_LIMIT", value)
    assert limits.seconds() == expected


def test_time_limit_bad_setting(monkeypatch):
    monkeypatch.setenv("DERIVE_TIME_LIMIT", "soon")
    with pytest.raises(InputError, match="DERIVE_TIME_LIMIT=soon: expected a number of seconds"):
        limits.seconds()


def test_time_limit_off_the_main_thread_runs_unbounded():
    outcome = []

    def work():
        with limits.time_limit("in a thread", seconds=0.05):
            time.sleep(0.2)
            outcome.append("done")

    thread = threading.Thread(target=work)
    thread.start()
    thread.join()
    assert outcome == ["done"]


def test_configure_overrides_the_environment(monkeypatch):
    monkeypatch.setenv("DERIVE_TIME_LIMIT", "5")
    limits.configure(7)
    try:
        assert limits.seconds() == 7
    finally:
        limits.configure(None)
    assert limits.seconds() == 5


# --- LaTeX safety ------------------------------------------------------------------------------

DANGEROUS = [
    r"\write18{rm -rf ~}", r"\immediate\write18{ls}", r"\input{/etc/passwd}", r"\include{../x}",
    r"\openout1=x.tex", r"\catcode`\^=11", r"\csname input\endcsname{/etc/passwd}",
    r"$\csname input\endcsname$", r"$x \input{/etc/passwd}$", r"^^5cinput{/etc/passwd}", r"$^^5c input$",
    r"$\def\x{1}$", r"\makeatletter", r"$\pdffiledump{/etc/passwd}$", r"$\directlua{os.execute('ls')}$",
    r"$\begin{filecontents}{x}\end{filecontents}$", r"$\usepackage{shellesc}$", r"$\InputIfFileExists{x}{}{}$",
    r"$\scantokens{x}$", r"$\expandafter\x$",
    # expl3 and xparse: names with _ and : that a denylist read as \iow or \use
    r"$\ExplSyntaxOn \iow_new:N \g_k_iow \iow_open:Nn \g_k_iow {key.csv} \iow_now:Nn \g_k_iow {x} \ExplSyntaxOff$",
    r"$\ExplSyntaxOn$", r"$\use:c {in put} {/etc/passwd}$", r"\use:c {in put}", r"$\NewDocumentCommand{\x}{}{\x}\x$",
    r"$\tl_set:Nn \l_x_tl {1}$", r"$\cs_new:Npn \x {\x}$", r"$\lowercase{\def}$", r"$\let\x\input$",
]


@pytest.mark.parametrize("text", DANGEROUS)
def test_dangerous_latex_in_the_question_is_refused(text):
    with pytest.raises(ProblemError) as caught:
        problem.parse(problem_text(question=text), Path("evil.yaml"))
    message = str(caught.value)
    assert message.startswith("evil.yaml: question: ") and "\n" not in message


@pytest.mark.parametrize("text, shown", [
    (r"$\iow_open:Nn \g_k_iow {key.csv}$", r"\iow_open:Nn"), (r"\ExplSyntaxOn", r"\ExplSyntaxOn"),
    (r"$\use:c {in put}$", r"\use:c"), (r"$\NewDocumentCommand{\x}{}{\x}$", r"\NewDocumentCommand"),
    (r"$\csname input\endcsname$", r"\csname"), (r"\@gobble x", r"\@gobble"), (r"$x \par y$", r"\par"),
])
def test_a_refused_command_is_named_whole(text, shown):
    with pytest.raises(ProblemError) as caught:
        problem.parse(problem_text(question=text), Path("q.yaml"))
    assert str(caught.value).startswith(f"q.yaml: question: {shown} is not allowed")


@pytest.mark.parametrize("field", ["title", "meaning", "ask_meaning"])
@pytest.mark.parametrize("text", [r"\\input{/etc/passwd}", r"\\write18{ls}", r"\\csname x\\endcsname", "^^5c",
                                  r"\\iow_open:Nn"])
def test_dangerous_latex_in_other_text_is_refused(field, text):
    with pytest.raises(ProblemError) as caught:
        problem.parse(problem_text(**{field: text}), Path("evil.yaml"))
    where = {"title": "title", "meaning": "parameters.M.meaning", "ask_meaning": "ask.I.meaning"}[field]
    assert str(caught.value).startswith(f"evil.yaml: {where}: ")


def parse_with(path: str, value) -> problem.Problem:
    """The plain disk problem with one field (a dotted path: parameters.M.meaning) set to value."""
    document = yaml.safe_load(problem_text())
    *parents, last = path.split(".")
    place = document
    for key in parents:
        place = place.setdefault(key, {})
    place[last] = value
    return problem.parse(yaml.safe_dump(document, allow_unicode=True), Path("f.yaml"))


@pytest.mark.parametrize("path, value, field", [
    ("source", r"\input{/etc/passwd}", "source"), ("source", "notes \u202e§2", "source"),
    ("corrections", [{"where": "§1", "notes": r"\write18{ls}", "derived": "x"}], "corrections[0].notes"),
    ("corrections", [{"where": "§1", "notes": "a", "derived": "b", "proof": "^^5c"}], "corrections[0].proof"),
    ("corrections", [{"where": "§1", "notes": "a", "derived": 7}], "corrections[0].derived"),
])
def test_source_and_corrections_are_checked_text(path, value, field):
    with pytest.raises(ProblemError, match=rf"^f\.yaml: {re.escape(field)}: "):
        parse_with(path, value)


LIMITED = [("title", latex_safety.TITLE_LIMIT), ("topic", latex_safety.TOPIC_LIMIT),
           ("parameters.M.meaning", latex_safety.MEANING_LIMIT), ("ask.I.meaning", latex_safety.MEANING_LIMIT),
           ("source", latex_safety.SOURCE_LIMIT), ("question", latex_safety.QUESTION_LIMIT)]


@pytest.mark.parametrize("path, limit", LIMITED + [("corrections", latex_safety.CORRECTION_LIMIT)])
def test_every_text_field_has_a_length_bound(path, limit):
    def value(length):
        text = "word " * (length // 5) + "x" * (length % 5)
        return [{"where": "§1", "notes": "a", "derived": text}] if path == "corrections" else text

    parse_with(path, value(limit))  # at the bound: accepted
    field = "corrections[0].derived" if path == "corrections" else path
    with pytest.raises(ProblemError, match=rf"^f\.yaml: {re.escape(field)}: {limit + 1} characters: at most {limit}$"):
        parse_with(path, value(limit + 1))


def test_check_plain_for_set_files():
    latex_safety.check_plain("Week 9 — rotation, 50% & more", latex_safety.TITLE_LIMIT)
    for text, reason in [("x" * 201, "201 characters"), (r"\textbf{x}", r"\textbf: this text is plain"),
                         ("a\u200db", "U+200D ZERO WIDTH JOINER"), ("two\nlines", "U+000A")]:
        with pytest.raises(latex_safety.LatexError, match=re.escape(reason)):
            latex_safety.check_plain(text, latex_safety.TITLE_LIMIT)


@pytest.mark.parametrize("text, reason", [
    (r"Find \alpha.", r"\alpha is not allowed outside math (math goes between $...$)"),
    (r"Mass $m {{ M }}$.", "a {{ placeholder }} becomes $value$: put it outside $...$"),
    (r"Mass {{ Q }}.", "{{ Q }}: not a parameter (parameters: M, R)"),
    (r"Mass $x % comment$.", "'%' in math at 'Mass $x % commen' starts a comment: write \\%"),
    (r"Mass $x}}{{$.", "unbalanced braces: '}' at 'Mass $x}}{{$.' closes no group"),
    (r"Mass $\frac{1}{2$.", "unbalanced braces: a '{' is not closed"),
    # questions that passed the old check and did not compile
    (r"$I^$", "`^` at '$I^$' needs an argument"),
    ("\\par\\\\", r"\par is not allowed"),
    ("x \\\\ y", r"\\ (a line break) is not allowed outside a math environment"),
    ("\\textbf{" * 300 + "x" + "}" * 300, "groups nested more than 10 deep"),
    (r"$x^2^3$", "double superscript at '$x^2^3$'"), (r"$x_1_2$", "double subscript"),
    (r"${\bar{x}_b}_a$", "double subscript"), (r"$\mathrm{{\vec{x}'}}^2$", "double superscript"),
    (r"$x^2'$", "double superscript"), (r"$x' ^2$", "double superscript"), (r"$x'_1'$", "double superscript"),
    (r"$\frac12$", r"\frac at '$\frac12$' needs its argument in braces"),
    (r"$x_\frac{1}{2}$", "`_` at '$x_\\frac{1' needs an argument"), (r"$x^~$", "`^` at '$x^~$' needs an argument"),
    (r"$\operatorname*{x}$", r"\operatorname at '$\operato' needs its argument in braces"),
    (r"$\operatorname{\alpha}$", "takes letters only"),
    (r"$a & b$", "'&' at '$a & b$' outside a math environment"),
    (r"$\begin{cases} a & b & c \end{cases}$", "a row of cases has at most 2 columns"),
    (r"$\begin{gathered} a & b \end{gathered}$", "a row of gathered has at most 1 columns"),
    (r"$\begin{pmatrix} {a & b} \end{pmatrix}$", "'&' at "),
    (r"$\begin{pmatrix} a \\ [b] \end{pmatrix}$", "'[' after \\\\ at"),
    (r"$\begin{aligned} [a] \end{aligned}$", r"'[' right after \begin{aligned}"),
    (r"$\begin{pmatrix} a \end{bmatrix}$", r"is closed by \end{bmatrix}"),
    (r"$\begin{pmatrix*} a \end{pmatrix*}$", "the math environments are"),
    (r"$\begin{pmatrix} a$", r"\begin{pmatrix} is not closed"), (r"$\end{pmatrix}$", r"without a \begin"),
    (r"$\left( x$", r"\left is not closed by \right"), (r"$x \right)$", r"\right at '$x \right)$' without a \left"),
    (r"$\left< x \right>$", r"\left at '$\left< x' needs a delimiter: one of ( ) . / ["), (r"$\middle| x$", r"\middle at"),
    (r"$\left( {x \middle| y} \right)$", r"\middle at"),
    (r"$\sqrt[\left[ x \right]]{y}$", "a ']' inside \\sqrt[...]"), (r"$\sqrt[3{x}$", r"\sqrt[ is not closed by ]"),
    (r"$\sqrt[\sqrt[3]{2}]{x}$", "a \\sqrt[...] inside the index of another"),
    (r"$a # b$", "'#' is not allowed in math"), (r"$\emph{x}$", r"\emph is not allowed in math (it is text"),
    ("$a\n\nb$", "a blank line inside math"), ("\\emph{a\n\nb}", r"a blank line inside \emph{...}"),
    (r"\emph x", r"\emph at '\emph x' needs its argument in braces"), (r"\emph{x", r"\emph{...} is not closed"),
    (r"\'{} and \'1", r"the accent \' at"), (r"$$x$$", "$$ (display math)"), (r"costs $5", "unpaired '$'"),
    ("a\\\nb", "\\ at the end of a line is not allowed"),
    ("$x \\text{a {{ M }} $\\mu$ \\input{y}}$", r"\input is not allowed outside math"),
])
def test_question_policy(text, reason):
    with pytest.raises(ProblemError) as caught:
        problem.parse(problem_text(question=text.replace("\n", "\n  ")), Path("q.yaml"))
    message = str(caught.value)
    assert message.startswith("q.yaml: question: ") and reason in message and "\n" not in message, message


@pytest.mark.parametrize("text, latex", [
    (r"A \emph{uniform} disk, 50% of $\omega_0^2 \cdot \frac{1}{2}$ & #1 a_b ~ ^ {x} \% \ldots done",
     r"A \emph{uniform} disk, 50\% of $\omega_0^2 \cdot \frac{1}{2}$ \& \#1 a\_b \textasciitilde{} "
     r"\textasciicircum{} \{x\} \% \ldots{} done"),
    (r"$K_\mathrm{rot}$, $x'^2 + y''$, $\sqrt[3]{x}$ and $\left(\frac{a}{b}\right)^{\!2}$",
     r"$K_\mathrm{rot}$, $x'^2 + y''$, $\sqrt[3]{x}$ and $\left(\frac{a}{b}\right)^{\!2}$"),
    (r"$\text{if $x > 0$, 50% of}~\alpha$ \textbf{b {c}} \'e \"{o} \ldots{} x",
     r"$\text{if $x > 0$, 50\% of}~\alpha$ \textbf{b \{c\}} \'{e} \"{o} \ldots{} x"),
    (r"$\begin{pmatrix} a & b \\ c & d \end{pmatrix}$, $\begin{cases} 1 & x > 0 \\ 0 & \text{else} \end{cases}$",
     r"$\begin{pmatrix} a & b \\ c & d \end{pmatrix}$, $\begin{cases} 1 & x > 0 \\ 0 & \text{else} \end{cases}$"),
    ("one\n\ntwo {% x %} {# y #} {{ ''.a }}", r"one" "\n\n" r"two \{\% x \%\} \{\# y \#\} \{\{ ''.a \}\}"),
])
def test_accepted_questions_keep_their_latex(text, latex):
    latex_safety.check_question(text, ["M"])
    assert latex_safety.question_latex(text, {}) == latex


def test_render_time_check_catches_text_that_skipped_the_reader():
    with pytest.raises(latex_safety.LatexError, match=r"\\input is not allowed in math"):
        render.question("{{ v }}", {"v": r"$\input{/etc/passwd}$"})
    with pytest.raises(latex_safety.LatexError, match=r"\\foo is not allowed outside math"):
        render.question("x {{ v }}", {"v": r"\foo"})
    with pytest.raises(latex_safety.LatexError, match="not a parameter"):
        render.question("x {{ w }}", {"v": "1"})


def test_values_are_not_read_as_placeholders():
    """A value holding {{ v }} is text: one substitution, no second round."""
    with pytest.raises(latex_safety.LatexError, match=r"\{\{ v \}\}: not a parameter \(parameters: none\)"):
        render.question("x {{ v }}", {"v": "{{ v }}"})
    assert render.question("x {{ v }}", {"v": "{{ 'v' }} 5%"}) == r"x \{\{ 'v' \}\} 5\%"


def test_library_questions_are_unchanged_by_the_escaping():
    """Every library question typesets as written, each {{ NAME }} replaced by its value."""
    for path in library.problem_files():
        p = problem.load(str(path))
        values = {name: "$1\\,\\mathrm{kg}$" for name in p.parameters}
        as_written = re.sub(r"\{\{ *(\w+) *\}\}", lambda m: values[m.group(1)], p.question)
        assert render.question(p.question, values) == as_written, p.id


def vocabulary_question() -> str:
    """A question that uses every entry of latex_grammar's tables, each where it may stand."""
    s = latex_grammar
    kinds = {"math": "{a}", "text": "{b $c^2$ 5%}", "name": "{sgn}"}
    parts = [f"$x^\\{n}_\\{n} \\{n} y$" for n in sorted(s.MATH_SYMBOLS)]
    parts += [f"$x^{{\\{n}}} \\{n} y$" for n in sorted(s.MATH_WORDS)]
    parts += ["$\\" + n + "".join(kinds[k] for k in args) + "^2$" for n, args in sorted(s.MATH_COMMANDS.items())]
    parts += [f"$x^\\{n}{{a}}_\\{n}{{b}}$" for n in sorted(s.SCRIPT_COMMANDS)]
    parts += [f"$a\\{c}b$" for c in sorted(s.MATH_CONTROL_SYMBOLS)]
    parts += [f"$\\left{d} x \\middle{d} y \\right{d}$" for d in sorted(s.DELIMITERS)]
    parts += [f"$x^{c} y_{c}$" for c in sorted(s.SCRIPT_CHARACTERS)]
    parts += ["$" + "".join(sorted(s.MATH_CHARACTERS)).replace("\n", "") + "$"]
    for name, columns in sorted(s.MATH_ENVIRONMENTS.items()):
        row = " & ".join("a" * (columns or 12))
        parts.append(f"$\\begin{{{name}}} {row} \\\\ {row} \\end{{{name}}}^2$")
    parts += [r"$\sqrt[3]{x} x'' y'^2 z_1' w'_1 \hat{x}' {\bar{x}}_a {\bar{x}_b\,}_a \bar{\hat{x}_b}_a$"]
    parts += [f"\\{n}{{word $x$}}" for n in sorted(s.TEXT_COMMANDS)]
    parts += [f"\\{n} x \\{n}{{}}x" for n in sorted(s.TEXT_WORDS)]
    parts += [f"a\\{c}b" for c in sorted(s.TEXT_SYMBOLS)]
    parts += [f"\\{a}e \\{a}{{O}}" for a in sorted(s.ACCENTS)]
    parts += [" ".join(sorted(s.SPECIALS)).replace("\\", "").replace("$", r"\$")]
    return "\n".join(parts)


@pytest.mark.parametrize("extra", ["", "Ж"], ids=["pdflatex", "lualatex"])
def test_every_allowed_command_compiles(tmp_path, extra):
    latex = latex_safety.question_latex(vocabulary_question() + extra, {}, limit=10**5)
    tex = tmp_path / "vocabulary.tex"
    tex.write_text(document(latex), encoding="utf-8")
    assert export.engine(tex.read_text()) == ("lualatex" if extra else "pdflatex")
    assert export.pdf(tex).stat().st_size > 0


# --- characters --------------------------------------------------------------------------------

@pytest.mark.parametrize("character, reason", [
    ("😀", "U+1F600 GRINNING FACE is not allowed: not in a script the fonts cover (supported: Latin, Greek"),
    ("\u202e", "U+202E RIGHT-TO-LEFT OVERRIDE is not allowed: an invisible format character"),
    ("\u200d", "U+200D ZERO WIDTH JOINER is not allowed: an invisible format character"),
    ("\ue000", "U+E000 is not allowed: a private-use character"), ("\u0378", "U+0378 is not allowed: an unassigned"),
    ("\ud800", "U+D800 is not allowed: a lone surrogate"), ("\t", "U+0009 is not allowed: a control character"),
    ("\x1b", "U+001B is not allowed: a control character"), ("\u0301", "U+0301 COMBINING ACUTE ACCENT is not allowed"),
    ("\u2028", "U+2028 LINE SEPARATOR is not allowed"), ("ع", "U+0639 ARABIC LETTER AIN is not allowed: not in a script"),
    ("ש", "U+05E9 HEBREW LETTER SHIN"), ("क", "U+0915 DEVANAGARI LETTER KA"), ("☺", "U+263A WHITE SMILING FACE"),
])
@pytest.mark.parametrize("path", ["title", "question", "parameters.M.meaning", "source"])
def test_unsupported_characters_are_refused_in_one_line(path, character, reason):
    text = f"A disk {character} of mass {{{{ M }}}}" if path == "question" else f"A disk {character}"
    with pytest.raises(ProblemError) as caught:
        parse_with(path, text)
    if character == "\ud800":  # only a YAML escape can write one: libyaml's parser refuses it, by its line
        assert re.fullmatch(r"f\.yaml: line \d+: invalid YAML: found invalid Unicode character escape code",
                            str(caught.value)), str(caught.value)
        return
    assert str(caught.value).startswith(f"f.yaml: {path}: {reason}"), str(caught.value)


@pytest.mark.parametrize("text, reason", [
    ("$μ$", "'μ' (U+03BC GREEK SMALL LETTER MU) in math: write \\mu"), ("$Ω$", "write \\Omega"),
    ("$2 × 3$", "write \\times"), ("$30°$", "write ^\\circ"), ("$é$", "math is ASCII"),
])
def test_non_ascii_in_math_is_refused_with_a_hint(text, reason):
    with pytest.raises(latex_safety.LatexError) as caught:
        latex_safety.check_question(text, ())
    assert reason in str(caught.value)


def supported_characters(sample: int) -> dict[str, str]:
    """Every character latex_safety lets text hold beyond ASCII, by script (of Han and Hangul
    syllables one in `sample`)."""
    found = {"symbols": "".join(sorted(latex_characters.SYMBOLS))}
    for script, first, last in latex_characters.SUPPORTED:
        step = sample if last - first > 2000 else 1
        found[script] = found.get(script, "") + "".join(
            chr(c) for c in range(first, last + 1, step) if latex_characters.refusal(chr(c)) is None)
    return found


SAMPLES = "μ ω Ω é ß Ł ő Ж жёлтый Ґ ά ῷ 日本語 中文 ひらがな カタカナ 한국어 ° ± × · → – — “ ” € ℏ ≤ ∞ ½ ²"
#: Scripts whose every character pdftotext gives back (NFKC-normalized); of the others (CJK:
#: it gives some back as other code points of the same glyph) the SAMPLES.
EXTRACTED_WHOLE = {"Latin-1", "Latin", "Greek", "Cyrillic", "punctuation", "superscripts", "number forms",
                   "arrows", "symbols"}


def pdf_text(pdf: Path) -> str:
    run = subprocess.run(["pdftotext", "-enc", "UTF-8", str(pdf), "-"], capture_output=True, text=True, check=True)
    return unicodedata.normalize("NFKC", run.stdout)


def test_every_supported_character_typesets(tmp_path):
    """LuaLaTeX with the preamble's fonts: no missing glyph, in every font of the templates
    (text, bold titles, italics, \\texttt, and \\text in math for meanings), and the text comes
    out of the PDF."""
    scripts = supported_characters(sample=37)
    characters = "".join(scripts.values())
    assert all(latex_characters.refusal(c) is None for c in SAMPLES.replace(" ", ""))
    lines = [" ".join(characters[i:i + 40]) for i in range(0, len(characters), 40)]
    body = "\n\n".join(f"{line}\n\n\\textbf{{{line}}}\n\n\\textit{{{line}}}\n\n\\texttt{{{line}}}\n\n"
                        f"$\\text{{{line}}}$" for line in lines)
    tex = tmp_path / "scripts.tex"
    tex.write_text(document(latex_safety.question_latex(SAMPLES, {}) + "\n\n" + body), encoding="utf-8")
    assert export.engine(tex.read_text(encoding="utf-8")) == "lualatex"
    with kept_scratch(tmp_path / "scratch") as scratch:
        export.pdf(tex)
    log = (scratch / "scripts.log").read_text(encoding="utf-8", errors="replace")
    assert "Missing character" not in log, [line for line in log.splitlines() if "Missing character" in line][:5]
    text = pdf_text(tex.with_suffix(".pdf"))
    assert [s for s in SAMPLES.split() if unicodedata.normalize("NFKC", s) not in text] == []
    whole = "".join(found for script, found in scripts.items() if script in EXTRACTED_WHOLE)
    assert [c for c in whole if unicodedata.normalize("NFKC", c).strip() not in text] == []


def test_latin_text_typesets_with_pdflatex(tmp_path):
    """The non-ASCII characters export.PDFLATEX_TEXT gives to pdflatex are supported and come out."""
    latin = "".join(sorted(c for c in export.PDFLATEX_TEXT if not c.isascii()))
    assert all(latex_characters.refusal(c) is None for c in latin)
    tex = tmp_path / "latin.tex"
    tex.write_text(document(f"{latin}\n\n\\textbf{{{latin}}}\n\n\\texttt{{{latin}}}\n\n$\\text{{{latin}}}$"),
                   encoding="utf-8")
    assert export.engine(tex.read_text(encoding="utf-8")) == "pdflatex"
    export.pdf(tex)
    text = pdf_text(tex.with_suffix(".pdf"))
    assert [c for c in latin.replace("…", "") if c not in text] == []  # … prints as . . .


SPECIAL_TITLE = "Specials 50% & #1 a_b ~x^2 {y} \\\\ $z$"  # YAML "...\\" is one backslash


def test_specials_in_titles_and_meanings_are_escaped_and_compile(tmp_path):
    path = tmp_path / "specials.yaml"
    path.write_text(problem_text(title=SPECIAL_TITLE, ask_meaning="I_z at 100% & more",
                                 question="A disk of mass {{ M }}: 5% off & #1 a_b ~ ^ {x}."))
    (tmp_path / "specials_set.yaml").write_text(f"title: 'Set 100% & #2 ~'\nproblems: [{path}]\n")
    out = tmp_path / "out"
    result = run_derive("sheet", str(tmp_path / "specials_set.yaml"), "--out", str(out), "--to", "pdf")
    assert result.returncode == 0, result.stderr
    worksheet = (out / "worksheet.tex").read_text()
    assert r"Specials 50\% \& \#1 a\_b \textasciitilde{}x\textasciicircum{}2 \{y\} \textbackslash{} \$z\$" in worksheet
    assert r"5\% off \& \#1 a\_b \textasciitilde{} \textasciicircum{} \{x\}." in worksheet
    assert r"Set 100\% \& \#2 \textasciitilde{}" in worksheet
    assert r"I\_z at 100\% \& more" in (out / "solutions.tex").read_text()
    assert (out / "worksheet.pdf").stat().st_size > 0 and (out / "solutions.pdf").stat().st_size > 0


def test_a_sheet_in_any_script_builds_every_format(tmp_path):
    """Titles, meanings and questions in Greek, accented Latin, Cyrillic and CJK: the whole
    build (LuaLaTeX chosen for the PDFs) exits 0 and every text reaches the PDF, HTML and DOCX."""
    path = tmp_path / "scripts.yaml"
    path.write_text(problem_text(title="Диск — μ, ω, é", meaning="masse du disque", ask_meaning="慣性モーメント",
                                 question="Ein Rad (Ж, 日本) der Masse {{ M }} dreht sich."), encoding="utf-8")
    (tmp_path / "scripts_set.yaml").write_text(f"title: 'Übung 7 — Вращение 回転'\nproblems: [{path}]\n",
                                               encoding="utf-8")
    out = tmp_path / "out"
    result = run_derive("sheet", str(tmp_path / "scripts_set.yaml"), "--out", str(out), "--to", "pdf,html,docx")
    assert result.returncode == 0, result.stderr
    assert export.engine((out / "worksheet.tex").read_text(encoding="utf-8")) == "lualatex"
    worksheet, solutions = pdf_text(out / "worksheet.pdf"), pdf_text(out / "solutions.pdf")
    for text in ("Диск — μ, ω, é", "Übung 7 — Вращение 回転", "Ein Rad (Ж, 日本) der Masse"):
        assert text in worksheet, text
    assert "慣性モーメント" in solutions
    html = (out / "worksheet.html").read_text(encoding="utf-8")
    assert "Вращение 回転" in html and "Ж, 日本" in html
    assert (out / "worksheet.docx").stat().st_size > 0


def test_latexmk_runs_without_shell_escape_and_with_paranoid_files(monkeypatch, tmp_path):
    seen = {}

    def fake_run(command, cwd, env, seconds):
        seen.update(args=command, env=env, files=sorted(p.name for p in cwd.iterdir()), cwd=cwd)
        raise export.subprocess.TimeoutExpired(command, seconds)

    monkeypatch.setattr(export, "_run_in_own_group", fake_run)
    (tmp_path / "x.tex").write_text("\\documentclass{article}")
    (tmp_path / "key.csv").write_text("the key")
    with pytest.raises(export.BuildError, match="did not compile within"):
        export.pdf(tmp_path / "x.tex")
    assert "-no-shell-escape" in seen["args"] and not any("shell-escape" in a and "no" not in a for a in seen["args"])
    assert seen["env"]["openin_any"] == "p" and seen["env"]["openout_any"] == "p"
    # A scratch folder with the .tex alone (and derive's mark, for a later run to sweep it if this one is killed).
    assert seen["files"] == [leftovers.MARK, "x.tex"] and seen["cwd"] != tmp_path


WRITER = r"""\documentclass{article}
\begin{document}
\immediate\openout1=key.csv \immediate\write1{I = 42}\immediate\closeout1
\immediate\openout2=../key.tex \immediate\write2{forged}\immediate\closeout2
Hello.
\end{document}
"""


def test_tex_cannot_write_beside_its_document(tmp_path):
    """A TeX run that writes files (as a forged key once did) writes only in its scratch folder."""
    (tmp_path / "key.csv").write_text("the key")
    (tmp_path / "w.tex").write_text(WRITER)
    try:
        export.pdf(tmp_path / "w.tex")
    except export.BuildError:
        pass  # TeX may refuse ../key.tex outright
    assert (tmp_path / "key.csv").read_text() == "the key"
    assert not (tmp_path / "key.tex").exists() and not (tmp_path.parent / "key.tex").exists()
    assert sorted(p.name for p in tmp_path.iterdir()) in (["key.csv", "w.tex"], ["key.csv", "w.aux", "w.pdf", "w.tex"])


# --- the template sandbox ----------------------------------------------------------------------

@pytest.mark.parametrize("text", ["{{ ''.__class__.__mro__ }}", "{{ cycler.__init__.__globals__ }}",
                                  "{{ ''.__class__.__mro__[1].__subclasses__() }}", "{{ lipsum.__globals__ }}",
                                  "{{ namespace.__init__.__globals__.os }}", "{% include '/etc/passwd' %}",
                                  "{% import '../README.md' as x %}", "{# a comment #} {{- M -}}"])
def test_question_text_is_no_template(text):
    """No template engine reads a question: jinja's syntax is literal text, printed as written."""
    p = problem.parse(problem_text(question=text), Path("sandbox.yaml"))
    assert render.question(p.question, {"M": "$1$", "R": "$2$"}) == tex_escape(text) + "\n"


def test_placeholders_name_parameters_only():
    text = "{% for c in ''.__class__.__mro__ %}{{ c }}{% endfor %}"
    with pytest.raises(ProblemError, match=r"^sandbox\.yaml: question: \{\{ c \}\}: not a parameter \(parameters: M, R\)$"):
        problem.parse(problem_text(question=text), Path("sandbox.yaml"))
    with pytest.raises(latex_safety.LatexError, match="not a parameter"):
        render.question(text, {})


@pytest.mark.parametrize("name", ["../README.md", "/etc/passwd", "../../../../etc/passwd", "./../README.md"])
def test_templates_cannot_include_files_outside_the_folder(name):
    env = render.templates()
    with pytest.raises(TemplateNotFound):
        env.from_string("\\BLOCK{include '" + name + "'}").render()


def test_templates_cannot_reach_python():
    with pytest.raises((SecurityError, UndefinedError)):
        render.templates().from_string("\\VAR{''.__class__.__mro__}").render()


def test_hostile_files_on_the_command_line(tmp_path):
    files = {
        "sandbox.yaml": problem_text(question="{{ ''.__class__.__mro__ }} {{ config }}"),
        "tex.yaml": problem_text(question=r"\input{/etc/passwd}"),
        "expl3.yaml": problem_text(question=r"$\ExplSyntaxOn \iow_new:N \g_k_iow \iow_open:Nn \g_k_iow {key.csv} "
                                            r"\iow_now:Nn \g_k_iow {forged} \ExplSyntaxOff$"),
        "tower.yaml": problem_text().replace("value: 0.5", "value: 10**10**10**10"),
        "bomb.yaml": "a: &a [x, x, x, x, x, x, x, x]\nb: &b [*a, *a, *a, *a, *a, *a, *a, *a]\nid: *b\n",
        "junk.yaml": "\x00\x01 not yaml at all: [",
        "nested.yaml": "a: " + "[" * 3000 + "]" * 3000,
    }
    for name, text in files.items():
        (tmp_path / name).write_text(text)
        start = time.monotonic()
        stderr = one_line_exit_2(run_derive("solve", str(tmp_path / name)))
        assert time.monotonic() - start < 15
        assert str(tmp_path / name) in stderr, stderr


# --- output names and interrupted builds -------------------------------------------------------

@pytest.mark.parametrize("bad", ["../evil", "/etc/evil", "a b", "x;rm", "a/b", "_x", "1x", "x.y"])
def test_problem_ids_that_could_leave_the_output_folder_are_refused(bad):
    with pytest.raises(ProblemError, match="id: an id is letters, digits and _"):
        problem.parse(problem_text(problem_id=f'"{bad}"'), Path("ids.yaml"))


@pytest.mark.parametrize("stem", ["a b", "x;y", "-x", "x.y", "$(x)"])
def test_set_ids_from_odd_file_names_are_refused(tmp_path, stem):
    path = tmp_path / f"{stem}.yaml"
    path.write_text("title: x\nproblems: [rod_endpoint]\n")
    with pytest.raises(library.LibraryError, match="a set's id is its file name"):
        library.find_set(str(path))


@pytest.mark.parametrize("reference", ["../../etc/passwd", "/etc/passwd", "..", "../x.yaml"])
def test_set_references_that_are_no_set_files(reference):
    with pytest.raises(InputError):
        problem_sets.load_set(reference)


def _build(out):
    from derive.publishing import worksheets
    return worksheets.build("demo", variants=2, seed=1, out_dir=str(out), formats=frozenset())


def test_build_writes_only_inside_its_output_folder(tmp_path):
    out = tmp_path / "here" / "out"
    written = _build(out)
    assert written and all(p.resolve().parent == out.resolve() for p in written)
    everything = [p for p in tmp_path.rglob("*")]
    assert all(p == out.parent or out in p.parents or p == out for p in everything), everything


@pytest.mark.parametrize("interrupt", [KeyboardInterrupt, RuntimeError])
def test_interrupted_build_leaves_the_previous_one(tmp_path, monkeypatch, interrupt):
    out = tmp_path / "out"
    _build(out)
    before = {p.name: p.read_bytes() for p in out.iterdir()}
    calls = []
    original = render.render

    def fails_midway(template, **context):
        calls.append(template)
        if len(calls) == 2:
            raise interrupt("stop")
        return original(template, **context)

    monkeypatch.setattr(render, "render", fails_midway)
    with pytest.raises(interrupt):
        _build(out)
    assert {p.name: p.read_bytes() for p in out.iterdir()} == before
    assert sorted(p.name for p in tmp_path.iterdir()) == ["out"]  # no staging folder left behind


def test_interrupted_build_on_the_command_line(tmp_path):
    """Ctrl-C (SIGINT) in the middle of a build: exit 130, the previous build intact."""
    import signal
    import subprocess
    import sys
    out = tmp_path / "out"
    _build(out)
    before = {p.name: p.read_bytes() for p in out.iterdir()}
    process = subprocess.Popen([str(Path(sys.executable).parent / "derive"), "sheet", "demo", "--variants", "2",
                                "--seed", "1", "--out", str(out), "--to", "pdf"], cwd=ROOT,
                               stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    deadline = time.monotonic() + 60
    while time.monotonic() < deadline and not any(p.name.startswith(".out.partial") for p in tmp_path.iterdir()):
        time.sleep(0.05)
    process.send_signal(signal.SIGINT)
    process.communicate(timeout=120)
    assert process.returncode in (130, 1, -signal.SIGINT)
    assert {p.name: p.read_bytes() for p in out.iterdir()} == before
    assert sorted(p.name for p in tmp_path.iterdir()) == ["out"]


# --- pandoc ------------------------------------------------------------------------------------

def test_pandoc_gets_no_filters_and_one_title_argument(monkeypatch, tmp_path):
    import pypandoc
    seen = []
    monkeypatch.setattr(pypandoc, "convert_text", lambda *a, **k: seen.append(k["extra_args"]))
    title = "Week 9 --lua-filter=evil.lua --filter x -F y"
    for target in export.PANDOC_TARGETS:
        export.convert("", tmp_path / "w", target, title)
    for args in seen:
        assert not any(a.startswith(("--filter", "--lua-filter", "-F", "-L", "--defaults", "-d")) for a in args), args
        assert f"--metadata=title:{title}" in args and "--sandbox" in args


def test_pandoc_reads_no_file_from_raw_latex(tmp_path):
    secret = tmp_path / "secret.tex"
    secret.write_text("SECRETTEXT")
    tex = ("\\documentclass{article}\\begin{document}Hello --lua-filter=x.lua \\input{" + str(secret)
           + "}\\end{document}\n")
    html = export.convert(tex, tmp_path / "w", "html", "t").read_text()
    assert "SECRETTEXT" not in html and "Hello" in html
    assert os.path.exists(secret)
    picture = tmp_path / "secret.png"  # an image's file neither: a DOCX gets its figures as data URIs
    picture.write_bytes(b"\x89PNG\r\n\x1a\n" + b"SECRETIMAGE")
    docx = export.convert(f"\\documentclass{{article}}\\begin{{document}}\\includegraphics{{{picture}}}\\end{{document}}\n",
                          tmp_path / "w", "docx", "t")
    with zipfile.ZipFile(docx) as document:
        assert not any(name.startswith("word/media/") for name in document.namelist())


def test_a_compile_past_its_time_limit_is_stopped_with_its_whole_process_group(tmp_path, monkeypatch):
    """TeX looping forever: after the limit every process of the compile is gone (latexmk's
    pdflatex child once kept spinning, re-parented, after latexmk was killed)."""
    (tmp_path / "loop.tex").write_text("\\documentclass{article}\\def\\x{\\x}\\begin{document}\\x\\end{document}\n")
    monkeypatch.setenv("DERIVE_TEX_TIME_LIMIT", "3")
    groups = []
    popen = export.subprocess.Popen

    def recorded(*args, **kwargs):
        process = popen(*args, **kwargs)
        groups.append(process.pid)
        return process

    monkeypatch.setattr(export.subprocess, "Popen", recorded)
    outcome = []

    def compile_it():
        try:
            export.pdf(tmp_path / "loop.tex")
        except export.BuildError as error:
            outcome.append(str(error))

    worker = threading.Thread(target=compile_it, daemon=True)  # a hang fails the test, not the suite
    worker.start()
    worker.join(timeout=60)
    assert not worker.is_alive(), "the compile did not stop at its time limit"
    assert outcome and "did not compile within 3 s" in outcome[0]
    (group,) = groups
    time.sleep(0.2)
    alive = []  # processes of the compile's group not yet dead (a zombie is dead, waiting for its reaper)
    for proc in Path("/proc").iterdir():
        try:
            fields = (proc / "stat").read_text().rsplit(")", 1)[1].split()
        except (OSError, IndexError):
            continue
        if int(fields[2]) == group and fields[0] != "Z":
            alive.append(proc.name)
    assert not alive


def test_tex_time_limit_setting(monkeypatch):
    monkeypatch.setenv("DERIVE_TEX_TIME_LIMIT", "soon")
    with pytest.raises(InputError, match="DERIVE_TEX_TIME_LIMIT=soon"):
        export.tex_time_limit()
    monkeypatch.setenv("DERIVE_TEX_TIME_LIMIT", "45")
    assert export.tex_time_limit() == 45


def test_siunitx_units_come_only_from_derives_own_values():
    """A value derive writes may carry siunitx's \\unit (the PDFs); a question's own text may not,
    since pandoc and MathJax, which show the other formats, read none of it."""
    for text in ("$2\\,\\unit{kg}$", "$\\degree$", "$\\micro m$"):
        with pytest.raises(latex_safety.LatexError, match="not allowed in math"):
            latex_safety.check_question(text, ())
    shown = latex_safety.question_latex("A mass {{ m }}.", {"m": "$2\\,\\unit{kg.m^{2}/s}$"})
    assert shown == "A mass $2\\,\\unit{kg.m^{2}/s}$."
    with pytest.raises(latex_safety.LatexError):  # inside a value, \unit's argument is still checked math
        latex_safety.question_latex("{{ m }}", {"m": "$\\unit{\\input{x}}$"})
