"""Learning-management-system exports: Moodle XML (cloze) and a QTI 1.2 zip for Canvas.

Each problem and variant becomes one Moodle cloze question with a field per asked quantity,
and one Canvas item per asked quantity: numerical (the answer and its tolerance) or, with
wrong choices derived from mistaken set-ups, multiple choice. The tolerance follows the
answer's policy: one unit in the last significant digit shown (the default), a percentage
(`2%`) or an absolute amount in the answer's unit. Canvas keeps four decimal places of a
numeric answer and its margin, so a quantity whose margin would fall below 1e-4 is asked in a
scaled unit (10^-k UNIT). `check` holds every exported tolerance to the LMS's limits.

Every file is built by lxml's serializer, never by string formatting: titles, meanings and the
question's HTML (its `<p>`s serialized too) are text content or attribute values, so no text from
a problem or set file can end an element or an attribute. Moodle's cloze syntax is Moodle's own
escaping inside that text (`_cloze_text`).

>>> tolerance("-4.44")
'0.01'
>>> tolerance("250", "2%")
'5'
>>> scaled("1.5e-05", "1e-06", "m")
('0.015', '0.001', '10^-3 m')
"""
from __future__ import annotations

import io
import random
import re
import zipfile
from dataclasses import dataclass
from decimal import Decimal

from lxml import etree
from lxml.builder import E, ElementMaker

from derive.errors import InputError


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
    unit: str
    tolerance: str  # absolute, in `unit`
    wrong: tuple[str, ...] = ()  # wrong choices (multiple choice); none: a numerical question


def tolerance(value: str, policy: str | None = None) -> str:
    """The absolute tolerance of a decimal answer under a policy: None for one unit in its
    last significant digit, "P%" for P percent of it, or an absolute amount ("0.05")."""
    number = Decimal(value)
    if policy is None:
        digits = len(number.as_tuple().digits)
        return _plain(Decimal(1).scaleb(number.adjusted() - digits + 1)) if number != 0 else "0"
    if policy.endswith("%"):
        return _plain((abs(number) * Decimal(policy[:-1]) / 100).normalize())
    return _plain(Decimal(policy).normalize())


def _plain(number: Decimal) -> str:
    """A decimal as positional digits, or with an exponent beyond 10^-6..10^15 (1e-320, not 320 zeros).

    >>> _plain(Decimal("0.001")), _plain(Decimal("1E-321")), _plain(Decimal("1E+397"))
    ('0.001', '1E-321', '1E+397')
    """
    return format(number, "f") if -6 <= number.adjusted() < 16 else str(number.normalize())


CANVAS_PLACES = 4  # Canvas rounds a numeric answer and its margin to four decimal places


def scaled(value: str, margin: str, unit: str) -> tuple[str, str, str]:
    """(value, margin, unit) restated in a unit of 10^-k UNIT (k a multiple of 3) so that the
    margin is at least 1e-4 and survives Canvas's rounding; unchanged when it already is."""
    number, tol = Decimal(value), Decimal(margin)
    smallest = Decimal(1).scaleb(-CANVAS_PLACES)
    if tol == 0 or tol >= smallest:
        return value, margin, unit
    k = 3 * ((smallest.adjusted() - tol.adjusted() + 2) // 3)
    return format(number.scaleb(k), "f"), format(tol.scaleb(k).normalize(), "f"), f"10^-{k} {unit}"


#: Magnitudes both LMSs store as numbers (double precision, with room for the tolerance).
DOUBLE_RANGE = (Decimal("1e-300"), Decimal("1e300"))
#: What each LMS can hold: Moodle compares in double precision; Canvas keeps 4 decimal places.
LIMITS = {"moodle": "a tolerance of at least 1e-14 of the answer (double precision)",
          "qti": "a margin of at least 1e-4 after scaling (Canvas keeps four decimal places)"}


def check(items: list[Item], target: str) -> None:
    """Refuse a tolerance the LMS cannot honour, or one so wide that it accepts zero and the
    wrong sign: InputError naming the problem, the variant and the answer."""
    for item in items:
        value, tol = abs(Decimal(item.value)), Decimal(item.tolerance)
        if value and not DOUBLE_RANGE[0] <= value <= DOUBLE_RANGE[1]:
            raise InputError(f"{item.problem} variant {item.variant}: ask.{item.name}: {item.value} {item.unit} lies "
                             f"outside what an LMS stores (double precision, 1e-300 to 1e300): ask it in another unit")
        where = f"{item.problem} variant {item.variant}: ask.{item.name}.tolerance"
        if value and tol >= value:
            raise InputError(f"{where}: ±{item.tolerance} {item.unit} accepts zero and the wrong sign "
                             f"(the answer is {item.value}); narrow it")
        if target == "moodle" and value and tol < value * Decimal("1e-14"):
            raise InputError(f"{where}: ±{item.tolerance} {item.unit} is finer than Moodle can compare "
                             f"({LIMITS['moodle']}); use fewer significant figures")
        if target == "qti" and value and not _survives_canvas(*scaled(item.value, item.tolerance, item.unit)[:2]):
            raise InputError(f"{where}: Canvas needs {LIMITS['qti']}")


def _survives_canvas(value: str, margin: str) -> bool:
    """After Canvas rounds the answer and the margin to four places, the margin is not zero
    and the accepted interval still holds the exact answer."""
    places = Decimal(1).scaleb(-CANVAS_PLACES)
    kept, kept_margin = Decimal(value).quantize(places), Decimal(margin).quantize(places)
    return kept_margin > 0 and abs(kept - Decimal(value)) <= kept_margin


def choices(item: Item) -> list[tuple[str, bool]]:
    """The right value among the wrong ones, (value, right), in an order fixed by the item
    (the same every build, different between items)."""
    result = [(item.value, True)] + [(w, False) for w in item.wrong]
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


def _xml(root: etree._Element) -> bytes:
    """A whole XML document, UTF-8 with its declaration, indented (the same bytes every build)."""
    return etree.tostring(root, encoding="UTF-8", xml_declaration=True, pretty_print=True)


def _cloze(item: Item) -> str:
    """A cloze field: NUMERICAL with its tolerance, or MULTICHOICE with the unit on each choice."""
    if not item.wrong:
        return f"{{1:NUMERICAL:={item.value}:{item.tolerance}}} {item.unit}"
    options = "~".join(f"{'=' if right else '%0%'}{_cloze_text(f'{v} {item.unit}')}" for v, right in choices(item))
    return f"{{1:MULTICHOICE_V:{options}}}"


def _cloze_text(text: str) -> str:
    """Text inside a cloze field: Moodle's own specials (} # ~ / " \\) escaped with a backslash."""
    return re.sub(r'([}#~/"\\])', r"\\\1", text)


_BRACE = "\ue000"  # a literal { of a problem's text, until the question's HTML is serialized


def _literal_braces(text: str) -> str:
    """A problem's text with each `{` marked, to become the HTML entity &#123; in Moodle's question
    text: Moodle's cloze parser reads `{1:NUMERICAL:=0}` in the raw HTML as an answer field, so a
    meaning or question must not be able to write one; the browser shows &#123; as `{` (and
    MathJax reads the decoded text)."""
    return text.replace("{", _BRACE)


def moodle(items: list[Item], category: str) -> str:
    """Moodle XML: a category and one cloze question per problem and variant."""
    groups: dict[tuple[str, int], list[Item]] = {}
    for item in items:
        groups.setdefault((item.problem, item.variant), []).append(item)
    quiz = E.quiz(E.question(E.category(E.text(f"$course$/derive/{category}")), type="category"))
    for (problem, variant), group in groups.items():
        fields = [f"{_literal_braces(i.meaning)}: \\({i.name}\\) = {_cloze(i)}" for i in group]
        html = _paragraphs(_mathjax(_literal_braces(group[0].question)), *fields).replace(_BRACE, "&#123;")
        quiz.append(E.question(
            E.name(E.text(f"{problem} variant {variant}")),
            E.questiontext(E.text(html), format="html"),
            E.generalfeedback(E.text()),
            type="cloze"))
    return _xml(quiz).decode()


QTI_NAMESPACE = "http://www.imsglobal.org/xsd/ims_qtiasiv1p2"
MANIFEST_NAMESPACE = "http://www.imsglobal.org/xsd/imsccv1p1/imscp_v1p1"
QTI = ElementMaker(namespace=QTI_NAMESPACE, nsmap={None: QTI_NAMESPACE})
MANIFEST = ElementMaker(namespace=MANIFEST_NAMESPACE, nsmap={None: MANIFEST_NAMESPACE})
ASSESSMENT = "assessment/assessment.xml"  # the zip's one resource, named in its manifest


def _numerical(item: Item) -> tuple[str, str, etree._Element, etree._Element]:
    """(question type, prompt, response, correct condition): the answer, or within its margin."""
    value, margin, unit = scaled(item.value, item.tolerance, item.unit)
    low, high = Decimal(value) - Decimal(margin), Decimal(value) + Decimal(margin)
    response = QTI.response_str(QTI.render_fib(QTI.response_label(ident="answer1"), fibtype="Decimal"),
                                ident="response1", rcardinality="Single")
    within = QTI("and", QTI.vargte(str(low), respident="response1"), QTI.varlte(str(high), respident="response1"))
    condition = QTI("or", QTI.varequal(value, respident="response1"), within)
    return "numerical_question", f"{item.meaning} (in {unit}):", response, condition


def _multiple_choice(item: Item) -> tuple[str, str, etree._Element, etree._Element]:
    """(question type, prompt, response, correct condition): the right choice among the wrong."""
    options = choices(item)
    labels = (QTI.response_label(QTI.material(QTI.mattext(f"{v} {item.unit}", texttype="text/plain")), ident=f"choice{n}")
              for n, (v, _) in enumerate(options))
    response = QTI.response_lid(QTI.render_choice(*labels), ident="response1", rcardinality="Single")
    (right,) = [n for n, (_, is_right) in enumerate(options) if is_right]
    return "multiple_choice_question", f"{item.meaning}:", response, QTI.varequal(f"choice{right}", respident="response1")


def _qti_item(item: Item, number: int) -> etree._Element:
    """A Canvas item: its question type, the question's HTML, the response and its scoring."""
    kind, prompt, response, condition = (_multiple_choice if item.wrong else _numerical)(item)
    text = _paragraphs(_mathjax(item.question), prompt)
    return QTI.item(
        QTI.itemmetadata(QTI.qtimetadata(QTI.qtimetadatafield(QTI.fieldlabel("question_type"), QTI.fieldentry(kind)))),
        QTI.presentation(QTI.material(QTI.mattext(text, texttype="text/html")), response),
        QTI.resprocessing(
            QTI.outcomes(QTI.decvar(maxvalue="100", minvalue="0", varname="SCORE", vartype="Decimal")),
            QTI.respcondition(QTI.conditionvar(condition), QTI.setvar("100", action="Set", varname="SCORE"),
                              {"continue": "No"})),
        ident=f"item{number}", title=f"{item.problem} v{item.variant} {item.name}")


def qti(items: list[Item], title: str) -> bytes:
    """A QTI 1.2 zip for Canvas: imsmanifest.xml and one assessment of numerical or
    multiple-choice items."""
    assessment = QTI.questestinterop(QTI.assessment(
        QTI.section(*(_qti_item(item, n) for n, item in enumerate(items, start=1)), ident="root_section"),
        ident="derive_assessment", title=title))
    manifest = MANIFEST.manifest(
        MANIFEST.metadata(MANIFEST.schema("IMS Content"), MANIFEST.schemaversion("1.1.3")),
        MANIFEST.organizations(),
        MANIFEST.resources(MANIFEST.resource(MANIFEST.file(href=ASSESSMENT), identifier="derive_assessment",
                                             type="imsqti_xmlv1p2", href=ASSESSMENT)),
        identifier="derive_manifest")
    buffer = io.BytesIO()
    with zipfile.ZipFile(buffer, "w") as archive:  # stored, as ZipInfo entries are by default
        for name, root in (("imsmanifest.xml", manifest), (ASSESSMENT, assessment)):
            info = zipfile.ZipInfo(name, date_time=(1980, 1, 1, 0, 0, 0))  # the same bytes every build
            archive.writestr(info, _xml(root))
    return buffer.getvalue()
