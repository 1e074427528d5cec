"""Learning-management-system exports: Moodle XML (cloze) here, and what both exports share; the
QTI 1.2 zip for Canvas is derive.publishing.canvas.

Both are laid out for a quiz that gives each student one variant of each problem and grades it
on import. Moodle: a question category per problem (`$course$/derive/SET/PROBLEM`) holding one
cloze question per variant, with a field per asked quantity, for the quiz's "random question
from category". Canvas: a question group (a `<section>` that picks 1) per problem and asked
quantity, with one item per variant worth `POINTS` points, in a graded quiz (`assessment_meta.xml`,
quiz type `assignment`). An item is numerical (the answer and its tolerance) or, with wrong choices
derived from mistaken set-ups, multiple choice, each wrong choice's feedback naming the mistake that
gives it. Each question's general feedback is the worked
solution of its variant (the solutions sheet's own text, as HTML with MathJax math). A problem's
figure (a PNG, derive.publishing.figure_files) travels inside the file: in each Moodle question's text, in the
Canvas zip once, and is shown below the question at its printed width. So does each free-body
diagram the worked solution shows beside a Newton–Euler balance (`_feedback`), in each Moodle
question's general feedback and in the Canvas zip once, with its body and forces as its alt text.

The tolerance follows the answer's policy: one unit in the last significant digit shown (the
default), a percentage (`2%`) or an absolute amount in the answer's unit. Canvas keeps four decimal
places of a numeric answer and its margin, so a quantity whose margin would fall below 1e-4 is
asked in a scaled unit (10⁻ᵏ UNIT), one for all the variants of a question (`exponent`). Moodle
widens every interval it grades by 1e-14 · max(1, |answer|) (question/type/numerical/question.php,
get_tolerance_interval; Moodle 4.5 by 1e-14 · max(|tolerance|, |answer|, 1e-14)), so below 1e-14
any answer within 1e-28 of a tiny one would pass, zero and the wrong sign too: a quantity whose
tolerance falls below 1e-8 is asked in a scaled unit there as well (`MOODLE_FLOOR`), so that the
widening is at most a millionth of the tolerance. `check` holds every exported tolerance to the
LMS's limits.

A field is labelled as the worksheets name its symbol (latex.symbol_latex: Omega_fast as
\\(\\Omega_{\\mathrm{fast}}\\)) and its unit is text as a student reads it (kg·m², none for a pure
number: units.unicode_unit, applied where the items are made).

Every file is built by lxml's serializer, never by string formatting: titles, meanings and the
question's HTML (its `<p>`s serialized too) are text content or attribute values, so no text from
a problem or set file can end an element or an attribute. Moodle's cloze syntax is Moodle's own
escaping inside that text (`_cloze_text`).

>>> tolerance("-4.44")
'0.01'
>>> tolerance("250", "2%")
'5'
>>> k = exponent(["1e-06", "1e-08"])
>>> k, scaled("1.5e-05", "1e-06", k), scaled_unit("m", k)
(6, ('15', '1'), '10⁻⁶ m')
"""
from __future__ import annotations

import base64
import random
import re
from collections.abc import Callable, Iterable
from dataclasses import dataclass
from functools import lru_cache
from decimal import Decimal
from typing import Mapping

import lxml.html
from lxml import etree
from lxml.builder import E

from derive.text.latex import symbol_latex
from derive.core import units
from derive.core.errors import InputError
from derive.publishing.figure_files import FOLDER, Image


@dataclass(frozen=True)
class Item:
    """One asked quantity of one variant: what the question shows and what it accepts."""

    problem: str
    title: str
    variant: int
    question: str  # LaTeX-flavoured text with $...$ math
    name: str
    meaning: str
    value: str
    unit: str  # as the question shows it: "kg·m²", "" for a pure number (units.unicode_unit)
    tolerance: str  # absolute, in `unit`
    wrong: tuple[str, ...] = ()  # wrong choices (multiple choice); none: a numerical question
    solution: str = ""  # the variant's worked solution, HTML with MathJax math: the general feedback
    mistakes: tuple[str, ...] = ()  # what gives each wrong choice (distractors): its feedback
    direction: str = ""  # which way it points, its value the magnitude (derive.model.directions); "" none
    senses: tuple[str, ...] = ()  # the ways it can point, where they differ between variants: asked too


def tolerance(value: str, policy: str | None = None) -> str:
    """The absolute tolerance of a decimal answer under a policy: None for one unit in its
    last significant digit, "P%" for P percent of it, or an absolute amount ("0.05")."""
    number = Decimal(value)
    if policy is None:
        return _last_place(number.as_tuple().exponent) if number != 0 else "0"
    if policy.endswith("%"):
        return _plain((abs(number) * Decimal(policy[:-1]) / 100).normalize())
    return _absolute(policy)


def unfair(value: str, tolerance: str) -> str | None:
    """Why a tolerance would grade a right answer wrong or a wrong one right, or None: narrower than
    the rounding of the digits shown (a student who gives more digits, or rounds the given values
    as shown, would be marked wrong), or as wide as the answer (zero and the wrong sign pass).

    >>> unfair("2.13", "0.01"), unfair("2.13", "0.001"), unfair("2.13", "3")
    (None, 'narrower than the digits shown: 2.13 is rounded by up to 0.005', 'as wide as the answer: zero and the wrong sign would pass')
    """
    number, margin = Decimal(value), Decimal(tolerance)
    if not number:
        return None
    rounding = Decimal(5).scaleb(number.as_tuple().exponent - 1)
    if margin < rounding:
        return f"narrower than the digits shown: {value} is rounded by up to {_plain(rounding)}"
    if accepts_zero(number, margin):
        return "as wide as the answer: zero and the wrong sign would pass"
    return None


def accepts_zero(value: Decimal, margin: Decimal) -> bool:
    """Whether a margin around a (nonzero) answer reaches zero, and so the wrong sign."""
    return margin >= abs(value)


@lru_cache(maxsize=None)  # a set's answers share a few places
def _last_place(exponent: int) -> str:
    """One unit in the decimal place 10^exponent.

    >>> _last_place(-3), _last_place(2)
    ('0.001', '100')
    """
    return _plain(Decimal(1).scaleb(exponent))


@lru_cache(maxsize=None)
def _absolute(policy: str) -> str:
    return _plain(Decimal(policy).normalize())


def _plain(number: Decimal) -> str:
    """A decimal as positional digits, or with an exponent beyond 10^-6..10^15 (1e-320, not 320 zeros).

    >>> _plain(Decimal("0.001")), _plain(Decimal("1E-321")), _plain(Decimal("1E+397"))
    ('0.001', '1E-321', '1E+397')
    """
    return format(number, "f") if -6 <= number.adjusted() < 16 else str(number.normalize())


CANVAS_PLACES = 4  # Canvas rounds a numeric answer and its margin to four decimal places


#: The least tolerance Moodle is given, in the question's unit and as a share of the answer: Moodle
#: widens the interval it grades by 1e-14 · max(1, |answer|) (see the module), a millionth of this.
MOODLE_FLOOR = Decimal("1e-8")


def exponent(margins: Iterable[str], floor: Decimal = Decimal(1).scaleb(-CANVAS_PLACES)) -> int:
    """The k of a question's unit, 10^-k times the answer's (k a multiple of 3; 0: the unit itself):
    the least for which every margin of its variants is at least `floor` (Canvas's: 1e-4, which
    survives its rounding to four places; Moodle's: MOODLE_FLOOR). One unit for all the variants
    of a question, whichever a student is given.

    >>> exponent(["0.01", "0"]), exponent(["1e-7", "1e-5"]), exponent(["1e-30", "1e-28"])
    (0, 3, 27)
    >>> exponent(["1e-7"], MOODLE_FLOOR), exponent(["1e-48"], MOODLE_FLOOR)
    (0, 42)
    """
    return max((3 * ((floor.adjusted() - tol.adjusted() + 2) // 3)
                for tol in map(Decimal, margins) if 0 < tol < floor), default=0)


def scaled(value: str, margin: str, k: int) -> tuple[str, str]:
    """(value, margin) restated in a unit of 10^-k times the answer's; unchanged for k = 0."""
    if not k:
        return value, margin
    return format(Decimal(value).scaleb(k), "f"), format(Decimal(margin).scaleb(k).normalize(), "f")


def scaled_unit(unit: str, k: int) -> str:
    """The unit 10^-k UNIT as text ("" for a pure number: 10⁻³ alone).

    >>> scaled_unit("kg·m²", 45), scaled_unit("", 3), scaled_unit("m", 0)
    ('10⁻⁴⁵ kg·m²', '10⁻³', 'm')
    """
    return f"10{units.superscript(str(-k))} {unit}".rstrip() if k else unit


def _questions(items: list[Item]) -> dict[tuple[str, str], list[Item]]:
    """The items by question (problem, asked quantity): each one's variants."""
    questions: dict[tuple[str, str], list[Item]] = {}
    for item in items:
        questions.setdefault((item.problem, item.name), []).append(item)
    return questions


def _exponent(question: list[Item], target: str) -> int:
    """The k of a question's unit 10^-k UNIT, one for all its variants, numerical or multiple choice:
    where any is numerical, the least that each LMS grades right (`exponent`: Canvas's four places,
    Moodle's widening), and where that needs a scaled unit at all, one that shows the largest
    value between 1 and 1000 if that is larger (587 × 10⁻⁴⁸ kg·m², not 0.000587 × 10⁻⁴² kg·m²);
    where every one is multiple choice, what shows its largest value between 1 and 1000 (12.3 ×
    10⁻⁶ m, not 0.0000123 m), or the unit itself where its values read well in it (1e-3 to 1e6).

    >>> item = Item("p", "P", 1, "", "I", "inertia", "1.23e-5", "kg·m²", "1e-7", ("2.46e-5", "6.1e-6", "1e-5"))
    >>> _exponent([item], "qti"), choice_text("1.23e-5", "kg·m²", 6)
    (6, '12.3 × 10⁻⁶ kg·m²')
    >>> tiny = Item("p", "P", 1, "", "I", "inertia", "5.87e-46", "kg·m²", "1e-48")
    >>> _exponent([tiny], "moodle"), _exponent([tiny], "qti")
    (48, 48)
    """
    numerical = [item.tolerance for item in question if not item.wrong]
    largest = max(abs(Decimal(v)) for item in question for v in (item.value, *item.wrong))
    readable = -3 * (largest.adjusted() // 3) if largest else 0
    if numerical:
        k = exponent(numerical) if target == "qti" else exponent(numerical, MOODLE_FLOOR)
        return max(k, readable) if k else 0
    return 0 if not largest or Decimal("1e-3") <= largest < Decimal("1e6") else readable


def choice_text(value: str, unit: str, k: int) -> str:
    """A multiple-choice option: the value in the question's unit 10^-k UNIT (`_exponent`), as text."""
    if not k:
        return _with_unit(value, unit)
    return _with_unit(f"{format(Decimal(value).scaleb(k), 'f')} × 10{units.superscript(str(-k))}", unit)


#: Magnitudes both LMSs store as numbers (double precision, with room for the tolerance).
DOUBLE_RANGE = (Decimal("1e-300"), Decimal("1e300"))
#: What each LMS can hold: Moodle compares in double precision; Canvas keeps 4 decimal places.
LIMITS = {"moodle": "a tolerance of at least 1e-8 of the answer (Moodle widens every interval by 1e-14 of it)",
          "qti": "a margin of at least 1e-4 after scaling (Canvas keeps four decimal places)"}


def check(items: list[Item], target: str) -> None:
    """Refuse a tolerance the LMS cannot honour, or one so wide that it accepts zero and the
    wrong sign: InputError naming the problem, the variant and the answer."""
    scales = {question: _exponent(group, target) for question, group in _questions(items).items()}
    for item in items:
        value, tol = abs(Decimal(item.value)), Decimal(item.tolerance)
        if value and not DOUBLE_RANGE[0] <= value <= DOUBLE_RANGE[1]:
            raise InputError(f"{item.problem} variant {item.variant}: ask.{item.name}: "
                             f"{_with_unit(item.value, item.unit)} lies outside what an LMS stores "
                             f"(double precision, 1e-300 to 1e300): ask it in another unit")
        where = f"{item.problem} variant {item.variant}: ask.{item.name}.tolerance"
        if value and accepts_zero(value, tol):
            raise InputError(f"{where}: ±{_with_unit(item.tolerance, item.unit)} accepts zero and the wrong sign "
                             f"(the answer is {item.value}); narrow it")
        if target == "moodle" and value and tol < value * MOODLE_FLOOR:
            raise InputError(f"{where}: ±{_with_unit(item.tolerance, item.unit)} is finer than Moodle can compare "
                             f"({LIMITS['moodle']}); use fewer significant figures")
        if target == "qti" and value and not item.wrong and not _survives_canvas(*scaled(item.value, item.tolerance,
                                                                      scales[item.problem, item.name])):
            raise InputError(f"{where}: Canvas needs {LIMITS['qti']}")


def _survives_canvas(value: str, margin: str) -> bool:
    """After Canvas rounds the answer and the margin to four places, the margin is not zero
    and the accepted interval still holds the exact answer."""
    places = Decimal(1).scaleb(-CANVAS_PLACES)
    kept, kept_margin = Decimal(value).quantize(places), Decimal(margin).quantize(places)
    return kept_margin > 0 and abs(kept - Decimal(value)) <= kept_margin


def choices(item: Item) -> list[tuple[str, bool, str]]:
    """The right value among the wrong ones, (value, right, feedback), in an order fixed by the item
    (the same every build, different between items). A wrong one's feedback names the mistake that
    gives it (`Item.mistakes`); the right one has none."""
    why = [f"Not this one: it is what {m} gives." for m in item.mistakes] or [""] * len(item.wrong)
    result = [(item.value, True, "")] + [(w, False, reason) for w, reason in zip(item.wrong, why)]
    random.Random(f"{item.problem}/{item.variant}/{item.name}").shuffle(result)
    return result


def _mathjax(text: str) -> str:
    """Question text for an LMS: $...$ math as MathJax \\( ... \\).

    >>> _mathjax("A mass $m$ hangs.")
    'A mass \\\\(m\\\\) hangs.'
    """
    return re.sub(r"\$([^$]+)\$", lambda m: r"\(" + m.group(1) + r"\)", text)


def _paragraphs(*texts: str) -> str:
    """HTML for an LMS's question text: one <p> per text, escaped by the serializer.

    >>> _paragraphs("a < b", "c")
    '<p>a &lt; b</p><p>c</p>'
    """
    return "".join(etree.tostring(E.p(text), encoding="unicode", method="html") for text in texts)


def _figure(source: str, image: Image, title: str) -> str:
    """HTML of a problem's figure: its image from `source` in a paragraph, at its printed width.

    >>> _figure("@@PLUGINFILE@@/a.png", Image("a", b"", b"", 150), "A & B")
    '<p><img src="@@PLUGINFILE@@/a.png" alt="Figure: A &amp; B" width="200"></p>'
    """
    img = E.img(src=source, alt=f"Figure: {title}", width=str(image.pixels))
    return etree.tostring(E.p(img), encoding="unicode", method="html")


def _feedback(html: str, figures: Mapping[str, Image], source: Callable[[Image], str]) -> tuple[str, list[Image]]:
    """A worked solution's HTML for an LMS, and the images it shows: each <img> of
    FOLDER/NAME.png (a free-body diagram, as derive.publishing.worksheets writes it for pandoc) shown from
    `source(image)` of the figure NAME, at its printed width, its alt the figure's words. Each
    image must be one of `figures`; HTML without an image is returned as it is.

    >>> fbd = Image("p-free-body-disk", b"", b"", 75, "Free-body diagram of the disk: weight M*g.")
    >>> _feedback('<p>Forces:</p><p><img src="figures/p-free-body-disk.png" alt="image"></p>',
    ...           {fbd.name: fbd}, lambda image: "@@PLUGINFILE@@/" + image.file("png"))[0]
    '<p>Forces:</p><p><img src="@@PLUGINFILE@@/p-free-body-disk.png" alt="Free-body diagram of the disk: weight M*g." width="100"></p>'
    """
    pieces = lxml.html.fragments_fromstring(html) if "<img" in html else []
    images = [img for piece in pieces if not isinstance(piece, str) for img in piece.iter("img")]
    if not images:
        return html, []
    by_file = {image.file("png"): image for image in figures.values()}
    shown = []
    for img in images:
        folder, _, name = (img.get("src") or "").partition("/")
        if folder != FOLDER or name not in by_file:
            raise ValueError(f"a worked solution shows {img.get('src')!r}, which is none of the build's figures")
        image = by_file[name]
        img.attrib.clear()
        img.set("src", source(image))
        img.set("alt", image.alt)
        img.set("width", str(image.pixels))
        shown += [image] if image not in shown else []
    return "".join(p if isinstance(p, str) else lxml.html.tostring(p, encoding="unicode") for p in pieces), shown


def _xml(root: etree._Element) -> bytes:
    """A whole XML document, UTF-8 with its declaration, indented (the same bytes every build)."""
    return etree.tostring(root, encoding="UTF-8", xml_declaration=True, pretty_print=True)


def _with_unit(text: str, unit: str) -> str:
    """A value (or a field) followed by its unit, or alone for a pure number.

    >>> _with_unit("2.13", "kg·m²"), _with_unit("0.286", "")
    ('2.13 kg·m²', '0.286')
    """
    return f"{text} {unit}" if unit else text


def _label(item: Item) -> str:
    r"""What an asked quantity is: its meaning and its symbol in MathJax math.

    >>> _label(Item("p", "P", 1, "", "Omega_fast", "fast precession rate", "1.5", "rad/s", "0.1"))
    'fast precession rate: \\(\\Omega_{\\mathrm{fast}}\\)'
    """
    magnitude = ", its magnitude" if item.direction and "magnitude" not in item.meaning else ""
    return f"{item.meaning}{magnitude}: \\({symbol_latex(item.name)}\\)"


def _cloze(item: Item, k: int) -> str:
    """A cloze field: NUMERICAL with its tolerance and the unit after it, or MULTICHOICE with the
    unit on each choice, in the question's unit 10^-k UNIT (`_exponent`).

    >>> _cloze(Item("p", "P", 1, "", "I", "inertia", "5.87e-46", "kg·m²", "1e-48"), 48)
    '{1:NUMERICAL:=587:1} 10⁻⁴⁸ kg·m²'
    """
    if not item.wrong:
        value, margin = scaled(item.value, item.tolerance, k)
        return _with_unit(f"{{1:NUMERICAL:={value}:{margin}}}", scaled_unit(item.unit, k)) + _direction_field(item)
    options = "~".join(f"{'=' if right else '%0%'}{_cloze_text(choice_text(v, item.unit, k))}"
                       + (f"#{_cloze_text(why)}" if why else "") for v, right, why in choices(item))
    return f"{{1:MULTICHOICE_V:{options}}}" + _direction_field(item)


def _direction_field(item: Item) -> str:
    """Where the way a quantity points differs between variants, a second cloze field asks it: a
    drop-down of the ways (`Item.senses`), the right one marked.

    >>> _direction_field(Item("p", "P", 1, "", "f", "friction", "2.1", "N", "0.1", direction="up the slope",
    ...                       senses=("down the slope", "up the slope")))
    ', {1:MULTICHOICE:%0%down the slope~=up the slope}'
    """
    if not item.senses:
        return ""
    return ", {1:MULTICHOICE:" + "~".join(f"{'=' if sense == item.direction else '%0%'}{_cloze_text(sense)}"
                                         for sense in item.senses) + "}"


#: Characters written as numeric character references in Moodle's question HTML. Until the HTML
#: is serialized (which would escape the `&` of a reference) each stands as a private-use mark.
_REFERENCED = "{~\\&"
_MARK = {c: chr(0xE000 + i) for i, c in enumerate(_REFERENCED)}
_REFERENCE = {mark: f"&#{ord(c)};" for c, mark in _MARK.items()}


def _cloze_text(text: str) -> str:
    """Text inside a cloze field (a choice), written so that Moodle reads back exactly `text`.

    Moodle's parser (question/type/multianswer/questiontype.php, qtype_multianswer_extract_question
    and ANSWER_ALTERNATIVE_ANSWER_REGEX `.+?(?<!\\\\|&|&amp;)(?=[~#}]|$)`) ends a choice at a `~`,
    `#` or `}` that no `\\`, `&` or `&amp;` precedes, then html_entity_decode()s it and undoes two
    escapes only: `\\}` and `\\#`. So `}` and `#` take a backslash; `~`, `\\` and `&`, which no
    backslash escapes, become character references (&#126;: its `#` follows `&`, so it ends
    nothing) that html_entity_decode turns back; everything else, `/` and `"` included, is written
    as it is (a backslash before it would be shown: `m\\/s^2`).

    >>> _cloze_text("m/s^2"), _cloze_text("a}b#c")
    ('m/s^2', 'a\\\\}b\\\\#c')
    """
    marked = "".join(_MARK[c] if c in "~\\&" else c for c in text)
    return re.sub(r"([}#])", r"\\\1", marked)


def _literal_braces(text: str) -> str:
    """A problem's text with each `{` marked, to become the reference &#123; in Moodle's question
    text: Moodle's cloze parser reads `{1:NUMERICAL:=0}` in the raw HTML as an answer field, so a
    meaning or question must not be able to write one; the browser shows &#123; as `{` (and
    MathJax reads the decoded text)."""
    return text.replace("{", _MARK["{"])


def _references(html: str) -> str:
    """Serialized HTML with each private-use mark as its character reference."""
    return re.sub("[" + "".join(_REFERENCE) + "]", lambda m: _REFERENCE[m.group()], html)


def _category(*names: str) -> str:
    """A Moodle category path in the course's context, each name's `/` doubled as Moodle's
    question/format.php writes and reads a path (assemble_category_path, split_category_path).

    >>> _category("derive", "week 3", "a/b")
    '$course$/derive/week 3/a//b'
    """
    return "/".join(["$course$", *(name.replace("/", "//") for name in names)])


# Moodle's XML import, as this export relies on it (moodle, question/format/xml/format.php):
# import_category reads a category "question" (<category><text>PATH</text>, <info format=...>), and
# question/format.php (create_category_path) creates the path, under the context's top category,
# and files the questions that follow in it; import_multianswer hands the question text to
# qtype_multianswer_extract_question (question/type/multianswer/questiontype.php, see _cloze_text)
# and imports <generalfeedback> with its format. Moodle's MathJax filter typesets \( \) and \[ \].
# A question's files: import_multianswer reads <questiontext> with import_text_with_files, whose
# import_files_as_draft stores each <file name=... path=... encoding="base64"> child (after
# base64_decode) in the question text's file area as path + name, where the text refers to it as
# @@PLUGINFILE@@/name (the form Moodle's own XML export writes, write_files); the files belong to
# their question, so each question carries its own copy. import_multianswer reads <generalfeedback>
# the same way ("Restore files in generalfeedback": import_text_with_files(question, ['#',
# 'generalfeedback', 0], ...)), so a free-body diagram is a <file> of the feedback it is shown in.
# The importer would store an SVG as well (import_files_as_draft base64_decodes any file), but
# Moodle serves every SVG as a download (lib/filelib.php, send_file and send_stored_file: "Make sure
# we force download of SVG files", for XSS), so the images are PNG.
def _file(image: Image) -> etree._Element:
    """An image as Moodle XML carries it: a base64 <file> at the file area's root, its PNG."""
    return E.file(base64.b64encode(image.png).decode("ascii"), name=image.file("png"), path="/", encoding="base64")


def moodle(items: list[Item], set_id: str, figures: Mapping[str, Image] = {}) -> str:
    """Moodle XML: for each problem its category, `$course$/derive/SET/PROBLEM` (a category
    "question" before the problem's variants: Moodle files the questions after it there), then one
    cloze question per variant with a field per asked quantity, the problem's figure (`figures`,
    by problem id) below its text, and the variant's worked solution as general feedback. A quiz's
    "random question" from a problem's category gives each student one variant of it. The feedback
    shows each free-body diagram of the solution (figures/NAME.png: `figures` by name) from a <file>
    of its own."""
    problems: dict[str, dict[int, list[Item]]] = {}
    scales = {question: _exponent(group, "moodle") for question, group in _questions(items).items()}
    for item in items:
        problems.setdefault(item.problem, {}).setdefault(item.variant, []).append(item)
    quiz = E.quiz()
    for problem, variants in problems.items():
        title = next(iter(variants.values()))[0].title
        quiz.append(E.question(E.category(E.text(_category("derive", set_id, problem))),
                               E.info(E.text(_paragraphs(title)), format="html"), type="category"))
        image = figures.get(problem)
        shown = _figure(f"@@PLUGINFILE@@/{image.file('png')}", image, _literal_braces(title)) if image else ""
        for variant, group in variants.items():
            fields = [f"{_literal_braces(_label(i))} = {_cloze(i, scales[problem, i.name])}" for i in group]
            html = _references(_paragraphs(_mathjax(_literal_braces(group[0].question))) + shown
                               + _paragraphs(*fields))
            files = [_file(image)] if image else []  # an element of its own in each question
            feedback, diagrams = _feedback(group[0].solution, figures, lambda diagram: f"@@PLUGINFILE@@/{diagram.file('png')}")
            quiz.append(E.question(
                E.name(E.text(f"{problem} variant {variant}")),
                E.questiontext(E.text(html), *files, format="html"),
                E.generalfeedback(E.text(feedback), *map(_file, diagrams), format="html"),
                type="cloze"))
    return _xml(quiz).decode()
