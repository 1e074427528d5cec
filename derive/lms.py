"""Learning-management-system exports: Moodle XML (cloze) and a QTI 1.2 zip for Canvas.

Each problem and variant becomes one Moodle cloze question with a NUMERICAL field per asked
quantity, and one Canvas numerical item per asked quantity. The tolerance is one unit in the
last significant digit shown. Canvas keeps four decimal places of a numeric answer, so an
answer below 1e-4 in size is asked in a scaled unit (10^-k UNIT).

>>> tolerance("-4.44")
'0.01'
>>> scaled("1.5e-05", "m")
('15', '10^-6 m')
"""
from __future__ import annotations

import html
import io
import re
import zipfile
from dataclasses import dataclass
from decimal import Decimal
from xml.sax.saxutils import escape


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


def tolerance(value: str) -> str:
    """One unit in the last significant digit of a decimal string."""
    number = Decimal(value)
    digits = len(number.as_tuple().digits)
    return format(Decimal(1).scaleb(number.adjusted() - digits + 1), "f") if number != 0 else "0"


def scaled(value: str, unit: str) -> tuple[str, str]:
    """A value below 1e-4 in size restated in a unit of 10^-k (k a multiple of 3) so that Canvas
    keeps its significant digits; other values unchanged."""
    number = Decimal(value)
    if number == 0 or abs(number) >= Decimal("1e-4"):
        return value, unit
    k = 3 * ((-number.adjusted() + 2) // 3)
    digits = len(number.as_tuple().digits)
    shifted = number.scaleb(k)
    return format(shifted.quantize(Decimal(1).scaleb(shifted.adjusted() - digits + 1)), "f"), f"10^-{k} {unit}"


def _html(text: str) -> str:
    """Question text for an LMS: HTML-escaped, $...$ math as MathJax \\( ... \\)."""
    return re.sub(r"\$([^$]+)\$", lambda m: r"\(" + m.group(1) + r"\)", html.escape(text, quote=False))


def moodle(items: list[Item], category: str) -> str:
    """Moodle XML: a category and one cloze question per problem and variant."""
    groups: dict[tuple[str, int], list[Item]] = {}
    for item in items:
        groups.setdefault((item.problem, item.variant), []).append(item)
    parts = ['<?xml version="1.0" encoding="UTF-8"?>', "<quiz>",
             f'  <question type="category"><category><text>$course$/derive/{escape(category)}</text></category></question>']
    for (problem, variant), group in groups.items():
        fields = "".join(
            f"<p>{escape(i.meaning)}: \\({escape(i.name)}\\) = "
            f"{{1:NUMERICAL:={i.value}:{tolerance(i.value)}}} {escape(i.unit)}</p>" for i in group)
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


def _qti_item(item: Item, number: int) -> str:
    value, unit = scaled(item.value, item.unit)
    low = Decimal(value) - Decimal(tolerance(value))
    high = Decimal(value) + Decimal(tolerance(value))
    text = _html(item.question) + f"<p>{html.escape(item.meaning)} (in {html.escape(unit)}):</p>"
    return f"""    <item ident="item{number}" title="{escape(item.problem)} v{item.variant} {escape(item.name)}">
      <itemmetadata><qtimetadata><qtimetadatafield><fieldlabel>question_type</fieldlabel>
        <fieldentry>numerical_question</fieldentry></qtimetadatafield></qtimetadata></itemmetadata>
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


def qti(items: list[Item], title: str) -> bytes:
    """A QTI 1.2 zip for Canvas: imsmanifest.xml and one assessment of numerical items."""
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
