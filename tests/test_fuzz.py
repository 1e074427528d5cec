"""Fuzzing the loader and the expression parser with hypothesis (derandomized: the same examples
on every run). Whatever the input, only a one-line InputError escapes, within a time bound, and
nothing runs. The whole file takes about a minute on two cores (max_examples below)."""
import copy
import re
import tempfile
import time
from decimal import Decimal
from pathlib import Path

import pytest
import sympy as sp
import yaml
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from conftest import TEX_OWN_FILES, document, kept_scratch
from derive.text.latex import tex_escape
from derive.publishing import export, leftovers
from derive.core import expr, library, limits
from derive.text import latex_grammar, latex_safety
from derive.language import problem
from derive.core.errors import InputError

FUZZ = settings(derandomize=True, database=None, deadline=None, print_blob=False,
                suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large,
                                       HealthCheck.filter_too_much])
BOUND = 20  # seconds any one call may take (a safety net: typical calls take milliseconds)
SYMBOLS = {name: sp.Symbol(name, positive=True) for name in ("x", "y", "m", "R", "E", "I")}


def bounded(call, *args):
    """Call, allowing only InputError with a one-line message out, within BOUND seconds."""
    start = time.monotonic()
    try:
        with limits.time_limit("fuzz", seconds=BOUND):
            result = call(*args)
    except limits.TimeLimitError as error:
        if str(error).startswith("fuzz"):
            pytest.fail(f"{call.__name__} took over {BOUND} s on {args[0]!r:.200}")
        result = error
    except InputError as error:
        result = error
    if isinstance(result, InputError):
        assert str(result) and "\n" not in str(result), repr(str(result))
    assert time.monotonic() - start < BOUND
    return result


# --- expressions -------------------------------------------------------------------------------

EXPRESSION_ALPHABET = "0123456789.eE_+-*/^()[], xymREI" + "sqrtincoaexplgb" + "'\"@%!~<>=&|\\:;{}#\t\n"


@settings(FUZZ, max_examples=2000)
@given(st.one_of(st.text(max_size=120), st.text(alphabet=EXPRESSION_ALPHABET, max_size=120)))
def test_expression_random_text(text):
    result = bounded(expr.parse, text, SYMBOLS)
    assert isinstance(result, (sp.Expr, InputError))


def _numbers():
    return st.one_of(st.integers(-10**6, 10**6).map(str), st.integers(0, 2000).map(lambda k: f"10**{k}"),
                     st.decimals(allow_nan=False, allow_infinity=False, places=4).map(str),
                     st.sampled_from(["1e999", "1e-999", "1e1001", "9**9**9", "10**10**10**10", "0", "0.0"]))


def _expressions():
    leaves = st.one_of(_numbers(), st.sampled_from(sorted(SYMBOLS) + ["pi"]))
    return st.recursive(leaves, lambda inner: st.one_of(
        st.tuples(inner, st.sampled_from(["+", "-", "*", "/", "**", "^"]), inner).map(lambda t: f"({t[0]}{t[1]}{t[2]})"),
        st.tuples(st.sampled_from(sorted(expr.FUNCTIONS)), inner).map(lambda t: f"{t[0]}({t[1]})"),
        inner.map(lambda e: f"-{e}"),
    ), max_leaves=40)


@settings(FUZZ, max_examples=1500)
@given(_expressions())
def test_expression_generated(text):
    result = bounded(expr.parse, text, SYMBOLS)
    if isinstance(result, sp.Expr):
        assert not result.has(sp.zoo, sp.nan, sp.oo)


@settings(FUZZ, max_examples=100)
@given(st.lists(st.sampled_from(["10", "9", "2", "x", "0.5", "(x+1)", "1e300", "-1"]), min_size=2, max_size=12),
       st.sampled_from(["**", "^"]))
def test_power_towers(parts, operator):
    bounded(expr.parse, operator.join(parts), SYMBOLS)


@pytest.mark.parametrize("text", [
    "10**10**10**10", "9**9**9**9", "x**10**10**10", "(x+1)**1000", "x**60*x**60", "(x**20)**20", "2^3^4^5^6",
    "1e100000", "(" * 10000 + "x" + ")" * 10000, "-" * 900 + "x", "+".join(["x"] * 400), "x" * 100000,
    "sqrt(" * 70 + "x" + ")" * 70, "exp(exp(exp(exp(exp(1000)))))",
])
def test_expression_refused_fast_or_kept_small(text):
    start = time.monotonic()
    result = bounded(expr.parse, text, SYMBOLS)
    assert time.monotonic() - start < 2
    assert isinstance(result, InputError) or sp.count_ops(result) < 2000


@pytest.mark.parametrize("text", ["__import__('os').system('echo pwned > /tmp/derive-pwned')",
                                  "().__class__.__bases__[0].__subclasses__()", "open('/etc/passwd')",
                                  "eval('1')", "lambda: 1", "x.__class__", "[x for x in ()]", "exec('x=1')"])
def test_expression_runs_no_code(text):
    result = bounded(expr.parse, text, SYMBOLS)
    assert isinstance(result, InputError)
    assert not Path("/tmp/derive-pwned").exists()


# --- problem files -----------------------------------------------------------------------------

def _yaml_values():
    scalars = st.one_of(st.none(), st.booleans(), st.integers(), st.floats(allow_nan=True), st.text(max_size=30),
                        st.sampled_from(["m", "2*m", "kg", "m/s^2", "disk", "x**10**10", "$\\input{/etc/passwd}$",
                                         "{{ ''.__class__ }}", "1e999"]))
    return st.recursive(scalars, lambda inner: st.one_of(
        st.lists(inner, max_size=4), st.dictionaries(st.text(max_size=12), inner, max_size=4)), max_leaves=25)


@settings(FUZZ, max_examples=1000)
@given(st.one_of(st.text(max_size=300), _yaml_values().map(lambda v: yaml.safe_dump(v, allow_unicode=True))))
def test_problem_random_yaml(text):
    result = bounded(problem.parse, text, Path("fuzz.yaml"))
    assert isinstance(result, (problem.Problem, InputError))


def _library():
    documents = []
    for path in library.problem_files():
        documents.append(yaml.safe_load(path.read_text(encoding="utf-8")))
    return documents


LIBRARY = _library()


def _places(tree, path=()):
    """Every (path, value) of a loaded YAML tree, the root excluded."""
    items = tree.items() if isinstance(tree, dict) else enumerate(tree) if isinstance(tree, list) else []
    for key, value in items:
        yield path + (key,), value
        yield from _places(value, path + (key,))


def _junk():
    return st.one_of(_yaml_values(), _expressions(), st.sampled_from([
        "(x+1)**1000", "10**10**10**10", "exp(exp(exp(1000)))", "r**99*sin(phi)**99", "\\write18{ls}",
        "\\csname input\\endcsname", "^^5cinput{/etc/passwd}", "{% include '/etc/passwd' %}",
        "{{ cycler.__init__.__globals__ }}", "-1", "0", "../../etc", "/etc/passwd", "a" * 5000]))


@settings(FUZZ, max_examples=2500)
@given(st.integers(0, len(LIBRARY) - 1), st.integers(0, 10**6), _junk(), st.booleans())
def test_problem_mutated_library_file(which, where, junk, replace_key):
    document = copy.deepcopy(LIBRARY[which])
    places = list(_places(document))
    path, _ = places[where % len(places)]
    parent = document
    for key in path[:-1]:
        parent = parent[key]
    if replace_key and isinstance(parent, dict) and isinstance(junk, str):
        parent[junk] = parent.pop(path[-1])
    else:
        parent[path[-1]] = junk
    text = yaml.safe_dump(document, allow_unicode=True, sort_keys=False)
    result = bounded(problem.parse, text, Path("mutated.yaml"))
    assert isinstance(result, (problem.Problem, InputError))


# --- fixed hostile inputs ----------------------------------------------------------------------

BILLION_LAUGHS = "\n".join(
    ["a: &a [lol, lol, lol, lol, lol, lol, lol, lol, lol]"]
    + [f"{chr(98 + i)}: &{chr(98 + i)} [{', '.join(['*' + chr(97 + i)] * 9)}]" for i in range(8)]
    + ["id: x", "title: *i"])


@pytest.mark.parametrize("text, reason", [
    (BILLION_LAUGHS, "aliases"),
    ("a: " + "[" * 5000 + "]" * 5000, "nest"),  # libyaml refuses past 1,000 levels itself
    ("a: " + "[" * 50 + "]" * 50, "nested deeper than 40"),
    ("x: " + "y" * 10**6, "characters"),
    ("x: .inf", "finite"),
    ("x: !!python/object/apply:os.system [ls]", "constructor"),
    ("x: " + "9" * 6000, "cannot read"),
    ("? [a, b]\n: c", "key"),
])
def test_hostile_yaml_refused_fast(text, reason):
    start = time.monotonic()
    result = bounded(problem.parse, text, Path("hostile.yaml"))
    assert time.monotonic() - start < 2
    assert isinstance(result, InputError) and reason in str(result)


def test_library_files_still_load():
    for path in library.problem_files():
        problem.load(str(path))


def test_decimal_keys_and_values_stay_exact():
    from derive.language.reader import safe_load
    assert safe_load("m: 0.1") == {"m": Decimal("0.1")}


# --- question text: every text the check accepts compiles -----------------------------------

S = latex_grammar
HOSTILE = [r"\catcode`\^=11 ", "^^5c", "^^M", "^^", r"\iow_open:Nn \g_k_iow {key.csv}", r"\iow_now:Nn", r"\tl_set:Nn",
           r"\cs_new:Npn \x {\x}", r"\ExplSyntaxOn", r"\ExplSyntaxOff", r"\NewDocumentCommand{\x}{}{\x}", r"\use:c {in put}",
           r"\csname input\endcsname", r"\input{key}", r"\write18{ls}", r"\def\x{\x}\x", r"\makeatletter", r"\@gobble",
           r"\par", "\n\n", "\\\n", r"\\", r"\\[2pt]", r"\\*", r"\relax", r"\begingroup", r"\endgroup", r"\left", r"\right",
           r"\middle|", r"\begin{pmatrix}", r"\end{pmatrix}", r"\begin{aligned}", r"\end{aligned}", "[t]", r"\end", "$$",
           "{{ M }}", "{{ x }}", "{% x %}", "{# y #}", "}}", "{{", "'", "''", "^", "_", "&", "#", "%", "~", "$", "{", "}",
           "[", "]", "\\", r"\sqrt[", r"\text{", r"\emph{", r"\'", r"\^", r"\~", "\t", "\x00", "\x7f", "\u202e", "\u200d",
           "\ue000", "😀", "ع", "μ", "é", "Ж", "日本", "한", "°", "×", "—", "“", "\u00a0", "\u3000", "\u0301"]
NON_ASCII = ["μ", "ω", "é", "Ł", "Ж", "ђ", "ά", "日本", "ひら", "カタ", "한국", "°", "±", "×", "·", "→", "–", "—", "“", "”",
             "€", "ℏ", "≤", "½", "²", "、", "！", "\u00a0"]
WORDS = st.sampled_from(["a", "mass", "disk", "50%", "x_1", "a & b", "#1", "~", "^", "{x}", "}", "{", "q.", "R,", "(t)",
                         "--", "``q''", "<>|", "\"", "@", "`", "*", "?!", ";:"] + NON_ASCII)


def _text_words():
    return st.lists(WORDS, min_size=1, max_size=4).map(" ".join)


def _math():
    atoms = st.one_of(st.sampled_from(list("xyzRM0123+-=<>()[]/|,.;:!?*\"@`~")),
                      st.sampled_from(sorted(S.MATH_SYMBOLS | S.MATH_WORDS)).map(lambda n: "\\" + n + " "),
                      st.sampled_from(sorted(S.MATH_CONTROL_SYMBOLS)).map(lambda c: "\\" + c))

    def command(parts):
        name, first, second, words = parts
        arguments = {"math": [first, second], "text": [words], "name": ["sgn"]}
        taken = [arguments[kind].pop(0) if arguments[kind] else first for kind in S.MATH_COMMANDS[name]]
        return "\\" + name + "".join("{" + a + "}" for a in taken)

    def environment(parts):
        name, cells, rows = parts
        columns = S.MATH_ENVIRONMENTS[name] or 4
        return f"\\begin{{{name}}}" + " \\\\ ".join(" & ".join(cells[:columns]) for _ in range(rows)) + f"\\end{{{name}}}"

    def combine(inner):
        delimiters = st.sampled_from(sorted(S.DELIMITERS))
        return st.one_of(
            st.tuples(inner, inner).map(" ".join),
            st.tuples(inner, st.sampled_from(["^", "_", "'", "''", "'^", "^{}_"]), inner).map(
                lambda t: f"{t[0]}{t[1]}{{{t[2]}}}"),
            st.tuples(inner, st.sampled_from(list("abc123+-") + ["\\alpha", "\\prime", "\\mathrm{kg}", "\\text{max}"]),
                      st.sampled_from("^_")).map(lambda t: f"{{{t[0]}}}{t[2]}{t[1]}"),
            inner.map(lambda e: "{" + e + "}"),
            st.tuples(st.sampled_from(sorted(S.MATH_COMMANDS)), inner, inner, _text_words()).map(command),
            st.tuples(inner, inner).map(lambda t: f"\\sqrt[{t[0]}]{{{t[1]}}}"),
            st.tuples(delimiters, inner, delimiters, delimiters, inner).map(
                lambda t: f"\\left{t[0]} {t[1]} \\middle{t[3]} {t[4]} \\right{t[2]}"),
            st.tuples(st.sampled_from(sorted(S.MATH_ENVIRONMENTS)), st.lists(inner, min_size=1, max_size=3),
                      st.integers(1, 3)).map(environment),
        )

    return st.recursive(atoms, combine, max_leaves=10)


def _built_questions():
    piece = st.one_of(_text_words(), _math().map(lambda m: f"${m}$"),
                      st.tuples(st.sampled_from(sorted(S.TEXT_COMMANDS)), _text_words(), _math()).map(
                          lambda t: f"\\{t[0]}{{{t[1]} ${t[2]}$}}"),
                      st.sampled_from(sorted(S.TEXT_WORDS)).map(lambda w: f"\\{w} "),
                      st.sampled_from(sorted(S.TEXT_SYMBOLS)).map(lambda c: "\\" + c),
                      st.tuples(st.sampled_from(sorted(S.ACCENTS)), st.sampled_from("aeoAEO")).map("".join).map(
                          lambda a: "\\" + a),
                      st.sampled_from(["{{ M }}", "{{R}}", "\n", "\n\n"]))
    return st.lists(piece, min_size=1, max_size=6).map(" ".join)


def _questions():
    """Questions built from the allowlist, the same with something hostile put in, and soup."""
    mutated = st.tuples(_built_questions(), st.integers(0, 10**4), st.sampled_from(HOSTILE)).map(
        lambda t: t[0][:t[1] % (len(t[0]) + 1)] + t[2] + t[0][t[1] % (len(t[0]) + 1):])
    soup = st.lists(st.one_of(st.sampled_from(HOSTILE), st.from_regex(r"\\[A-Za-z]{1,9}", fullmatch=True),
                              st.text(alphabet="xyz 12+-=()[]", min_size=1, max_size=3)), max_size=12).map("".join)
    return st.one_of(_built_questions(), mutated, soup)


def _plain_texts():
    return st.lists(st.sampled_from([chr(c) for c in range(32, 127)] + NON_ASCII + HOSTILE), max_size=30).map("".join)


BATCH = 400  # items in one document
VALUES = {"M": "$2.50\\times10^{-3}\\,\\mathrm{kg}\\,\\mathrm{m}^{2}$", "R": "$0.5\\,{}^{\\circ}$"}


def _accepts(call, *args) -> bool:
    """Whether call(*args) returns; a LatexError it raises must have a one-line message."""
    try:
        call(*args)
    except latex_safety.LatexError as error:
        assert str(error) and "\n" not in str(error), repr(str(error))
        return False
    return True


#: A control word that must never pass: its backslash not itself escaped (`\\use:c` is a line break
#: and the letters "use:c").
REFUSED_ALWAYS = re.compile(r"\^\^|(?<!\\)(?:\\\\)*\\(iow_|tl_|cs_|use:|ExplSyntax|NewDocumentCommand|csname|catcode|input|write"
                            r"|def(?![A-Za-z]))"
                            "|[\x00\t\x7f\u202e\u200d\ue000😀ع]")


@pytest.fixture(scope="module")
def fuzzed() -> dict[str, list[str]]:
    """Generated questions and plain texts (derandomized), each checked: accepted, or refused
    in one line, fast; a question is accepted when read exactly when it can be typeset with the
    parameters' values. The LaTeX of the accepted ones, and the refused questions."""
    found = {"questions": [], "plain": [], "refused": []}

    @settings(FUZZ, max_examples=1500)
    @given(_questions(), _plain_texts())
    def check(question, plain):
        start = time.monotonic()
        accepted = _accepts(latex_safety.check_question, question, ["M", "R"])
        assert _accepts(latex_safety.question_latex, question, VALUES) == accepted
        if accepted:
            found["questions"].append(latex_safety.question_latex(question, VALUES))
        else:
            found["refused"].append(question)
        if _accepts(latex_safety.check_plain, plain, latex_safety.TITLE_LIMIT):
            found["plain"].append(tex_escape(plain))
        assert time.monotonic() - start < 1

    check()
    return found


def test_question_check_accepts_or_refuses_in_one_line(fuzzed):
    """The generators reach both sides of the check, and what must be refused is."""
    assert len(fuzzed["questions"]) > 400 and len(fuzzed["refused"]) > 400 and len(fuzzed["plain"]) > 400
    assert [q for q in fuzzed["questions"] if REFUSED_ALWAYS.search(q)] == []
    assert sum(bool(REFUSED_ALWAYS.search(q)) for q in fuzzed["refused"]) > 200


def _compile(items: list[str], folder: Path) -> str | None:
    """Compile the items (LaTeX of questions and plain texts) in the real preamble, each as a
    worksheet has a question (templates/worksheet.tex.j2); None, or the error. TeX must write
    nothing but its own files."""
    tex = folder / "fuzz.tex"
    body = "\\begin{enumerate}\n" + "".join(f"\\item \\textbf{{Title.}}\n{item}\n" for item in items) + "\\end{enumerate}"
    tex.write_text(document(body), encoding="utf-8")
    scratch = folder / f"scratch{len(list(folder.glob('scratch*')))}"
    try:
        with kept_scratch(scratch):
            export.pdf(tex)
        error = None
    except export.BuildError as failure:
        error = str(failure)
    written = {p.name for p in scratch.iterdir()} - {leftovers.MARK}  # derive's mark, written before TeX runs
    assert written <= {f"fuzz{suffix}" for suffix in TEX_OWN_FILES}, written
    return error


def _culprit(items: list[str], folder: Path) -> str:
    """Bisect a batch that does not compile down to one item that does not compile alone."""
    while len(items) > 1:
        half = items[:len(items) // 2]
        items = half if _compile(half, folder) else items[len(items) // 2:]
    return items[0]


def test_accepted_questions_compile(fuzzed):
    """Every question and plain text the checks accept compiles in the real preamble (pdflatex
    for Latin text, LuaLaTeX for the rest), in batches of BATCH (a failing batch is bisected
    to its culprit), and TeX writes nothing but its own files."""
    plain = [f"\\textbf{{{text}.}} $x = \\text{{{text}}}$" for text in fuzzed["plain"]]
    items = fuzzed["questions"] + plain
    with tempfile.TemporaryDirectory() as scratch:
        for engine in ("pdflatex", "lualatex"):
            texts = [item for item in items if export.engine(item) == engine]
            folder = Path(scratch) / engine
            folder.mkdir()
            for start in range(0, len(texts), BATCH):
                batch = texts[start:start + BATCH]
                if _compile(batch, folder):
                    culprit = _culprit(batch, folder)
                    pytest.fail(f"accepted but does not compile with {engine}: {culprit!r:.500}: "
                                f"{_compile([culprit], folder)}")
