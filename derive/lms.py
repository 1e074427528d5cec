"""Learning-management-system exports: Moodle XML (cloze) and a QTI 1.2 zip for Canvas.

Each problem and variant becomes one Moodle cloze question with a field per asked quantity,
and one Canvas item per asked quantity: numerical (the answer and its tolerance) or, with
wrong choices derived from mistaken set-ups, multiple choice. The tolerance follows the
answer's policy: one unit in the last significant digit shown (the default), a percentage
(`2%`) or an absolute amount in the answer's unit. Canvas keeps four decimal places of a
numeric answer and its margin, so a quantity whose margin would fall below 1e-4 is asked in a
scaled unit (10^-k UNIT). `check` holds every exported tolerance to the LMS's limits.

>>> tolerance("-4.44")
'0.01'
>>> tolerance("250", "2%")
'5'
>>> scaled("1.5e-05", "1e-06", "m")
('0.015', '0.001', '10^-3 m')
"""
from __future__ import annotations

import html
import io
import random
import re
import zipfile
from dataclasses import dataclass
from decimal import Decimal
from xml.sax.saxutils import escape

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
        return format(Decimal(1).scaleb(number.adjusted() - digits + 1), "f") if number != 0 else "0"
    if policy.endswith("%"):
        return format((abs(number) * Decimal(policy[:-1]) / 100).normalize(), "f")
    return format(Decimal(policy).normalize(), "f")


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


#: What each LMS can hold: Moodle compares in double precision; Canvas keeps 4 decimal places.
LIMITS = {"moodle": "a tolerance of at least 1e-14 of the answer (double precision)",
          "qti": "a margin of at least 1e-4 after scaling (Canvas keeps four decimal places)"}


def check(items: list[Item], target: str) -> None:
    """Refuse a tolerance the LMS cannot honour, or one so wide that it accepts zero and the
    wrong sign: InputError naming the problem, the variant and the answer."""
    for item in items:
        value, tol = abs(Decimal(item.value)), Decimal(item.tolerance)
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


def _html(text: str) -> str:
    """Question text for an LMS: HTML-escaped, $...$ math as MathJax \\( ... \\)."""
    return re.sub(r"\$([^$]+)\$", lambda m: r"\(" + m.group(1) + r"\)", html.escape(text, quote=False))


def _cloze(item: Item) -> str:
    """A cloze field: NUMERICAL with its tolerance, or MULTICHOICE with the unit on each choice."""
    if not item.wrong:
        return f"{{1:NUMERICAL:={item.value}:{item.tolerance}}} {escape(item.unit)}"
    options = "~".join(f"{'=' if right else '%0%'}{_cloze_text(f'{v} {item.unit}')}" for v, right in choices(item))
    return f"{{1:MULTICHOICE_V:{options}}}"


def _cloze_text(text: str) -> str:
    """Text inside a cloze field: Moodle's own specials (} # ~ / " \\) escaped with a backslash."""
    return escape(re.sub(r'([}#~/"\\])', r"\\\1", text))


def moodle(items: list[Item], category: str) -> str:
    """Moodle XML: a category and one cloze question per problem and variant."""
    groups: dict[tuple[str, int], list[Item]] = {}
    for item in items:
        groups.setdefault((item.problem, item.variant), []).append(item)
    parts = ['<?xml version="1.0" encoding="UTF-8"?>', "<quiz>",
             f'  <question type="category"><category><text>$course$/derive/{escape(category)}</text></category></question>']
    for (problem, variant), group in groups.items():
        fields = "".join(f"<p>{escape(i.meaning)}: \\({escape(i.name)}\\) = {_cloze(i)}</p>" for i in group)
        text = f"<p>{_html(group[0].question)}</p>{fields}"
        parts += [
            '  <question type="cloze">',
            f"    <name><text>{escape(problem)} variant {variant}</text></name>",
            f'    <questiontext format="html"><text><![CDATA[{text}]]></text></questiontext>',
            "    <generalfeedback><text></text></generalfeedback>",
            "  </question>",
        ]
    parts.append("</quiz>")
    return "\n".join(parts) + "\n"


def _metadata(kind: str) -> str:
    return (f"<itemmetadata><qtimetadata><qtimetadatafield><fieldlabel>question_type</fieldlabel>\n"
            f"        <fieldentry>{kind}</fieldentry></qtimetadatafield></qtimetadata></itemmetadata>")


def _qti_item(item: Item, number: int) -> str:
    if item.wrong:
        return _qti_choice_item(item, number)
    value, margin, unit = scaled(item.value, item.tolerance, item.unit)
    low, high = Decimal(value) - Decimal(margin), Decimal(value) + Decimal(margin)
    text = _html(item.question) + f"<p>{html.escape(item.meaning)} (in {html.escape(unit)}):</p>"
    return f"""    <item ident="item{number}" title="{escape(item.problem)} v{item.variant} {escape(item.name)}">
      {_metadata("numerical_question")}
      <presentation>
        <material><mattext texttype="text/html">{escape(text)}</mattext></material>
        <response_str ident="response1" rcardinality="Single"><render_fib fibtype="Decimal">
          <response_label ident="answer1"/></render_fib></response_str>
      </presentation>
      <resprocessing>
        <outcomes><decvar maxvalue="100" minvalue="0" varname="SCORE" vartype="Decimal"/></outcomes>
        <respcondition continue="No"><conditionvar><or>
          <varequal respident="response1">{value}</varequal>
          <and><vargte respident="response1">{low}</vargte><varlte respident="response1">{high}</varlte></and>
        </or></conditionvar><setvar action="Set" varname="SCORE">100</setvar></respcondition>
      </resprocessing>
    </item>"""


def _qti_choice_item(item: Item, number: int) -> str:
    options = choices(item)
    labels = "\n".join(
        f'          <response_label ident="choice{n}"><material><mattext texttype="text/plain">'
        f"{escape(v)} {escape(item.unit)}</mattext></material></response_label>" for n, (v, _) in enumerate(options))
    (right,) = [n for n, (_, is_right) in enumerate(options) if is_right]
    text = _html(item.question) + f"<p>{html.escape(item.meaning)}:</p>"
    return f"""    <item ident="item{number}" title="{escape(item.problem)} v{item.variant} {escape(item.name)}">
      {_metadata("multiple_choice_question")}
      <presentation>
        <material><mattext texttype="text/html">{escape(text)}</mattext></material>
        <response_lid ident="response1" rcardinality="Single"><render_choice>
{labels}
        </render_choice></response_lid>
      </presentation>
      <resprocessing>
        <outcomes><decvar maxvalue="100" minvalue="0" varname="SCORE" vartype="Decimal"/></outcomes>
        <respcondition continue="No"><conditionvar><varequal respident="response1">choice{right}</varequal>
        </conditionvar><setvar action="Set" varname="SCORE">100</setvar></respcondition>
      </resprocessing>
    </item>"""


def qti(items: list[Item], title: str) -> bytes:
    """A QTI 1.2 zip for Canvas: imsmanifest.xml and one assessment of numerical or
    multiple-choice items."""
    body = "\n".join(_qti_item(item, n) for n, item in enumerate(items, start=1))
    assessment = f"""<?xml version="1.0" encoding="UTF-8"?>
<questestinterop xmlns="http://www.imsglobal.org/xsd/ims_qtiasiv1p2">
  <assessment ident="derive_assessment" title="{escape(title)}">
    <section ident="root_section">
{body}
    </section>
  </assessment>
</questestinterop>
"""
    manifest = """<?xml version="1.0" encoding="UTF-8"?>
<manifest identifier="derive_manifest" xmlns="http://www.imsglobal.org/xsd/imsccv1p1/imscp_v1p1">
  <metadata><schema>IMS Content</schema><schemaversion>1.1.3</schemaversion></metadata>
  <organizations/>
  <resources>
    <resource identifier="derive_assessment" type="imsqti_xmlv1p2" href="assessment/assessment.xml">
      <file href="assessment/assessment.xml"/>
    </resource>
  </resources>
</manifest>
"""
    buffer = io.BytesIO()
    with zipfile.ZipFile(buffer, "w", zipfile.ZIP_DEFLATED) as archive:
        for name, text in (("imsmanifest.xml", manifest), ("assessment/assessment.xml", assessment)):
            info = zipfile.ZipInfo(name, date_time=(1980, 1, 1, 0, 0, 0))  # the same bytes every build
            archive.writestr(info, text)
    return buffer.getvalue()
