"""Learning-management-system exports: Moodle XML (cloze) and a QTI 1.2 zip for Canvas.

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
asked in a scaled unit (10⁻ᵏ UNIT), one for all the variants of a question (`exponent`). `check`
holds every exported tolerance to the LMS's limits.

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
import hashlib
import io
import random
import re
import zipfile
from collections.abc import Callable, Iterable
from dataclasses import dataclass
from functools import lru_cache
from decimal import Decimal
from typing import Mapping

import lxml.html
from lxml import etree
from lxml.builder import E, ElementMaker

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


def tolerance(value: str, policy: str | None = None) -> str:
    """The absolute tolerance of a decimal answer under a policy: None for one unit in its
    last significant digit, "P%" for P percent of it, or an absolute amount ("0.05")."""
    number = Decimal(value)
    if policy is None:
        return _last_place(number.as_tuple().exponent) if number != 0 else "0"
    if policy.endswith("%"):
        return _plain((abs(number) * Decimal(policy[:-1]) / 100).normalize())
    return _absolute(policy)


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


def exponent(margins: Iterable[str]) -> int:
    """The k of a question's unit, 10^-k times the answer's (k a multiple of 3; 0: the unit itself):
    the least for which every margin of its variants is at least 1e-4 and survives Canvas's
    rounding. One unit for all the variants of a question, whichever a student is given.

    >>> exponent(["0.01", "0"]), exponent(["1e-7", "1e-5"]), exponent(["1e-30", "1e-28"])
    (0, 3, 27)
    """
    smallest = Decimal(1).scaleb(-CANVAS_PLACES)
    return max((3 * ((smallest.adjusted() - tol.adjusted() + 2) // 3)
                for tol in map(Decimal, margins) if 0 < tol < smallest), default=0)


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
    where any is numerical, Canvas's (`exponent`) or Moodle's own unit (Moodle stores doubles);
    where every one is multiple choice, what shows its largest value between 1 and 1000 (12.3 ×
    10⁻⁶ m, not 0.0000123 m), or the unit itself where its values read well in it (1e-3 to 1e6).

    >>> item = Item("p", "P", 1, "", "I", "inertia", "1.23e-5", "kg·m²", "1e-7", ("2.46e-5", "6.1e-6", "1e-5"))
    >>> _exponent([item], "qti"), choice_text("1.23e-5", "kg·m²", 6)
    (6, '12.3 × 10⁻⁶ kg·m²')
    """
    numerical = [item.tolerance for item in question if not item.wrong]
    if numerical:
        return exponent(numerical) if target == "qti" else 0
    largest = max(abs(Decimal(v)) for item in question for v in (item.value, *item.wrong))
    if not largest or Decimal("1e-3") <= largest < Decimal("1e6"):
        return 0
    return -3 * (largest.adjusted() // 3)


def choice_text(value: str, unit: str, k: int) -> str:
    """A multiple-choice option: the value in the question's unit 10^-k UNIT (`_exponent`), as text."""
    if not k:
        return _with_unit(value, unit)
    return _with_unit(f"{format(Decimal(value).scaleb(k), 'f')} × 10{units.superscript(str(-k))}", unit)


#: Magnitudes both LMSs store as numbers (double precision, with room for the tolerance).
DOUBLE_RANGE = (Decimal("1e-300"), Decimal("1e300"))
#: What each LMS can hold: Moodle compares in double precision; Canvas keeps 4 decimal places.
LIMITS = {"moodle": "a tolerance of at least 1e-14 of the answer (double precision)",
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
        if value and tol >= value:
            raise InputError(f"{where}: ±{_with_unit(item.tolerance, item.unit)} accepts zero and the wrong sign "
                             f"(the answer is {item.value}); narrow it")
        if target == "moodle" and value and tol < value * Decimal("1e-14"):
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
    return f"{item.meaning}: \\({symbol_latex(item.name)}\\)"


def _cloze(item: Item, k: int) -> str:
    """A cloze field: NUMERICAL with its tolerance, or MULTICHOICE with the unit on each choice, in
    the question's unit 10^-k UNIT (`_exponent`)."""
    if not item.wrong:
        return _with_unit(f"{{1:NUMERICAL:={item.value}:{item.tolerance}}}", item.unit)
    options = "~".join(f"{'=' if right else '%0%'}{_cloze_text(choice_text(v, item.unit, k))}"
                       + (f"#{_cloze_text(why)}" if why else "") for v, right, why in choices(item))
    return f"{{1:MULTICHOICE_V:{options}}}"


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


# Canvas's QTI import, as this export relies on it (canvas-lms, and the packages it reads as its own):
# - the package: lib/cc/qti/qti_generator.rb (generate_quiz, generate_qti_only) writes a quiz as
#   ID/ID.xml, a resource of type imsqti_xmlv1p2 with a <dependency> on a second resource, of type
#   associatedcontent/imscc_xmlv1p1/learning-application-resource, whose file is
#   ID/assessment_meta.xml; ID is the resource's identifier and the assessment's ident. text2qti
#   (qti.py, xml_imsmanifest.py, xml_assessment_meta.py) and R/exams (exams2canvas ->
#   exams2qti12, inst/xml/canvas_manifest.xml, canvas_meta.xml) write the same layout.
# - the metadata: lib/cc/importer/canvas/quiz_metadata_converter.rb (post_process_assessments)
#   reads only a learning-application-resource's file named ASSESSMENT_ID/assessment_meta.xml,
#   then its quiz_type, points_possible, allowed_attempts ... and <assignment> (the gradebook
#   column); quiz_type "assignment" is a graded quiz.
# - the groups: gems/plugins/qti_exporter/lib/qti/assessment_test_converter.rb (process_section)
#   makes a section with a selection into a question group that picks that many, worth
#   points_per_item each; qti_generator.rb (add_group) writes it as
#   <selection_ordering><selection><selection_number>/<selection_extension><points_per_item>.
# - the items: lib/cc/qti/qti_items.rb (add_question) writes the fields question_type and
#   points_possible in itemmetadata, and a question's general feedback as
#   <itemfeedback ident="general_fb"> shown by a first respcondition (<other/>, continue Yes);
#   assessment_item_converter.rb (get_feedback) reads an ident matching general_ as the
#   question's neutral comments. Canvas typesets \( \) and \[ \] math with MathJax (exams2canvas
#   converts with "pandoc-mathjax" for it).
# - the figures: a file of the package is a resource of type webcontent listing it (text2qti:
#   xml_imsmanifest.py IMAGE, a resource per image with its <file>; markdown.py Image, whose src is
#   $IMS-CC-FILEBASE$/images/NAME), referred to from the HTML as $IMS-CC-FILEBASE$/PATH
#   (lib/cc/cc_helper.rb WEB_CONTENT_TOKEN); Canvas's link migrator (canvas_link_migrator,
#   link_parser.rb convert_link and parse_url) reads `$IMS-CC-FILEBASE$/(.*)` (or its %24-escaped
#   form) as a link to the imported file at that path.
QTI_NAMESPACE = "http://www.imsglobal.org/xsd/ims_qtiasiv1p2"
MANIFEST_NAMESPACE = "http://www.imsglobal.org/xsd/imsccv1p1/imscp_v1p1"
CANVAS_NAMESPACE = "http://canvas.instructure.com/xsd/cccv1p0"
QTI = ElementMaker(namespace=QTI_NAMESPACE, nsmap={None: QTI_NAMESPACE})
MANIFEST = ElementMaker(namespace=MANIFEST_NAMESPACE, nsmap={None: MANIFEST_NAMESPACE})
CANVAS = ElementMaker(namespace=CANVAS_NAMESPACE, nsmap={None: CANVAS_NAMESPACE})
QTI_RESOURCE = "imsqti_xmlv1p2"
META_RESOURCE = "associatedcontent/imscc_xmlv1p1/learning-application-resource"
FIGURE_RESOURCE = "webcontent"
POINTS = 1  # an asked quantity's points, as a Moodle cloze field's default weight
GROUP_TITLE_LIMIT = 255  # characters of a Canvas question group's name


def identifier(*parts: object) -> str:
    """An identifier for Canvas, from what names the thing (set, seed, problem, variant, ...): the
    same in every export of the same set and seed, different for anything else, so that a second
    import matches its own quiz and questions and no other export's.

    >>> identifier("quiz", "demo", 4) == identifier("quiz", "demo", 4) != identifier("quiz", "demo", 5)
    True
    """
    return "d" + hashlib.sha256("\x1f".join(map(str, parts)).encode()).hexdigest()[:32]


def _field(label: str, entry: str) -> etree._Element:
    return QTI.qtimetadatafield(QTI.fieldlabel(label), QTI.fieldentry(entry))


def _numerical(item: Item, k: int) -> tuple[str, str, etree._Element, etree._Element]:
    """(question type, prompt, response, correct condition, feedback by choice: none): the answer, or
    within its margin, in the question's unit 10^-k UNIT."""
    (value, margin), unit = scaled(item.value, item.tolerance, k), scaled_unit(item.unit, k)
    low, high = Decimal(value) - Decimal(margin), Decimal(value) + Decimal(margin)
    response = QTI.response_str(QTI.render_fib(QTI.response_label(ident="answer1"), fibtype="Decimal"),
                                ident="response1", rcardinality="Single")
    within = QTI("and", QTI.vargte(str(low), respident="response1"), QTI.varlte(str(high), respident="response1"))
    condition = QTI("or", QTI.varequal(value, respident="response1"), within)
    return "numerical_question", f"{_label(item)} (in {unit})" if unit else _label(item), response, condition, {}


def _multiple_choice(item: Item, k: int) -> tuple[str, str, etree._Element, etree._Element, dict[str, str]]:
    """(question type, prompt, response, correct condition, feedback by choice): the right choice
    among the wrong, each a value as text in the question's unit 10^-k UNIT (`choice_text`), each
    wrong one with the mistake that gives it."""
    options = choices(item)
    labels = (QTI.response_label(QTI.material(QTI.mattext(choice_text(v, item.unit, k), texttype="text/plain")),
                                 ident=f"choice{n}")
              for n, (v, _, _) in enumerate(options))
    response = QTI.response_lid(QTI.render_choice(*labels), ident="response1", rcardinality="Single")
    (right,) = [n for n, (_, is_right, _) in enumerate(options) if is_right]
    return ("multiple_choice_question", _label(item), response, QTI.varequal(f"choice{right}", respident="response1"),
            {f"choice{n}": why for n, (_, _, why) in enumerate(options) if why})


def _qti_item(item: Item, k: int, ident: str, figure: str = "", solution: str = "") -> etree._Element:
    """A Canvas item: its question type and points, the question's HTML (with the problem's
    `figure`, HTML), the response (numerical in the question's unit 10^-k UNIT), its scoring and
    the worked solution (`solution`, HTML: the item's, its images resolved) as general feedback; a
    wrong choice's feedback (`{choice}_fb`, as text2qti writes it and Canvas's
    assessment_item_converter reads it) names its mistake."""
    kind, prompt, response, condition, mistaken = _multiple_choice(item, k) if item.wrong else _numerical(item, k)
    text = _paragraphs(_mathjax(item.question)) + figure + _paragraphs(prompt)
    scoring = [QTI.respcondition(QTI.conditionvar(condition), QTI.setvar("100", action="Set", varname="SCORE"),
                                 {"continue": "No"})]
    feedback = []
    for choice, why in mistaken.items():
        scoring.insert(0, QTI.respcondition(QTI.conditionvar(QTI.varequal(choice, respident="response1")),
                                            QTI.displayfeedback(feedbacktype="Response", linkrefid=f"{choice}_fb"),
                                            {"continue": "Yes"}))
        feedback.append(QTI.itemfeedback(QTI.flow_mat(QTI.material(QTI.mattext(why, texttype="text/plain"))),
                                         ident=f"{choice}_fb"))
    if solution:
        scoring.insert(0, QTI.respcondition(QTI.conditionvar(QTI.other()),
                                            QTI.displayfeedback(feedbacktype="Response", linkrefid="general_fb"),
                                            {"continue": "Yes"}))
        feedback.append(QTI.itemfeedback(QTI.flow_mat(QTI.material(QTI.mattext(solution, texttype="text/html"))),
                                         ident="general_fb"))
    return QTI.item(
        QTI.itemmetadata(QTI.qtimetadata(_field("question_type", kind), _field("points_possible", str(POINTS)))),
        QTI.presentation(QTI.material(QTI.mattext(text, texttype="text/html")), response),
        QTI.resprocessing(QTI.outcomes(QTI.decvar(maxvalue="100", minvalue="0", varname="SCORE", vartype="Decimal")),
                          *scoring),
        *feedback,
        ident=ident, title=f"{item.problem} v{item.variant} {item.name}")


def qti(items: list[Item], title: str, set_id: str, seed: int, figures: Mapping[str, Image] = {}) -> bytes:
    """A QTI 1.2 zip for Canvas: a graded quiz with a question group per problem and asked
    quantity that picks one of its variants (numerical or multiple-choice items, worth POINTS
    each), its metadata (assessment_meta.xml), the problems' figures (`figures`, by problem id;
    figures/ID.png) and the free-body diagrams the feedback shows (figures/NAME.png, by name), and
    imsmanifest.xml listing them all.

    Canvas picks each group's item on its own, so a problem that asks for several quantities is one
    group per quantity: a Canvas item holds one numeric answer with a tolerance."""
    quiz = identifier("quiz", set_id, seed)
    groups = _questions(items)
    titles = {item.problem: item.title for item in items}
    paths = {problem: f"{FOLDER}/{figures[problem].file('png')}" for problem in titles if problem in figures}
    shown = {problem: _figure(f"$IMS-CC-FILEBASE$/{path}", figures[problem], titles[problem])
             for problem, path in paths.items()}
    solutions: dict[str, str] = {}  # each worked solution's HTML for Canvas, its diagrams' paths added to `paths`
    for item in items:
        if item.solution not in solutions:
            solutions[item.solution], diagrams = _feedback(item.solution, figures,
                                                           lambda image: f"$IMS-CC-FILEBASE$/{FOLDER}/{image.file('png')}")
            paths.update({image.name: f"{FOLDER}/{image.file('png')}" for image in diagrams})
    sections = [
        QTI.section(
            QTI.selection_ordering(QTI.selection(QTI.selection_number("1"),
                                                 QTI.selection_extension(QTI.points_per_item(str(POINTS))))),
            *(_qti_item(i, k, identifier("item", set_id, seed, problem, i.variant, name), shown.get(problem, ""),
                        solutions[i.solution]) for i in group),
            ident=identifier("group", set_id, seed, problem, name),
            title=f"{group[0].title}: {group[0].meaning}"[:GROUP_TITLE_LIMIT])
        for (problem, name), group in groups.items() for k in [_exponent(group, "qti")]]
    assessment = QTI.questestinterop(QTI.assessment(QTI.section(*sections, ident="root_section"),
                                                    ident=quiz, title=title))
    points = str(POINTS * len(groups))
    meta = CANVAS.quiz(
        CANVAS.title(title), CANVAS.description(""), CANVAS.shuffle_answers("false"),
        CANVAS.scoring_policy("keep_highest"), CANVAS.quiz_type("assignment"), CANVAS.points_possible(points),
        CANVAS.show_correct_answers("true"), CANVAS.allowed_attempts("1"), CANVAS.one_question_at_a_time("false"),
        CANVAS.cant_go_back("false"), CANVAS.available("false"),
        CANVAS.assignment(CANVAS.title(title), CANVAS.workflow_state("unpublished"), CANVAS.quiz_identifierref(quiz),
                          CANVAS.points_possible(points), CANVAS.grading_type("points"),
                          CANVAS.submission_types("online_quiz"), identifier=identifier("assignment", set_id, seed)),
        identifier=quiz)
    assessment_path, meta_path = f"{quiz}/{quiz}.xml", f"{quiz}/assessment_meta.xml"
    meta_id = identifier("metadata", set_id, seed)
    manifest = MANIFEST.manifest(
        MANIFEST.metadata(MANIFEST.schema("IMS Content"), MANIFEST.schemaversion("1.1.3")),
        MANIFEST.organizations(),
        MANIFEST.resources(
            MANIFEST.resource(MANIFEST.file(href=assessment_path), MANIFEST.dependency(identifierref=meta_id),
                              identifier=quiz, type=QTI_RESOURCE),
            MANIFEST.resource(MANIFEST.file(href=meta_path), identifier=meta_id, type=META_RESOURCE, href=meta_path),
            *(MANIFEST.resource(MANIFEST.file(href=path), identifier=identifier("figure", set_id, seed, name),
                                type=FIGURE_RESOURCE, href=path) for name, path in paths.items())),
        identifier=identifier("manifest", set_id, seed))
    buffer = io.BytesIO()
    with zipfile.ZipFile(buffer, "w") as archive:  # stored, as ZipInfo entries are by default
        files = [("imsmanifest.xml", _xml(manifest)), (assessment_path, _xml(assessment)), (meta_path, _xml(meta)),
                 *((path, figures[name].png) for name, path in paths.items())]
        for name, data in files:
            info = zipfile.ZipInfo(name, date_time=(1980, 1, 1, 0, 0, 0))  # the same bytes every build
            archive.writestr(info, data)
    return buffer.getvalue()
