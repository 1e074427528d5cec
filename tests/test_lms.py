"""The exports instructors import: Markdown, DOCX, Moodle XML and a QTI zip for Canvas."""
import json
import re
import xml.etree.ElementTree as ET
import zipfile
from decimal import Decimal

import pytest

from conftest import run_derive
from derive import lms


@pytest.fixture(scope="module")
def exported(tmp_path_factory):
    out = tmp_path_factory.mktemp("lms") / "demo"
    done = run_derive("sheet", "demo", "--variants", "2", "--seed", "4", "--to", "md,docx,moodle,qti", "--out", str(out))
    assert done.returncode == 0, done.stderr
    return out


def test_moodle_xml_has_a_cloze_question_per_problem_and_variant_with_every_answer(exported):
    key = json.loads((exported / "key.json").read_text())
    quiz = ET.parse(exported / "moodle.xml").getroot()
    questions = [q for q in quiz.findall("question") if q.get("type") == "cloze"]
    assert len(questions) == 2 * 3
    fields = [f for q in questions for f in re.findall(r"\{1:NUMERICAL:=([^:]+):([^}]+)\}", q.find("questiontext/text").text)]
    values = [a["value"] for v in key["variants"] for p in v["problems"].values() for a in p["answers"].values()]
    assert sorted(f[0] for f in fields) == sorted(values)
    assert all(Decimal(tolerance) > 0 for _, tolerance in fields)


def test_qti_zip_has_a_manifest_and_numerical_items(exported):
    with zipfile.ZipFile(exported / "canvas-qti.zip") as archive:
        manifest = ET.fromstring(archive.read("imsmanifest.xml"))
        (resource,) = [e for e in manifest.iter() if e.tag.endswith("resource")]
        assessment = ET.fromstring(archive.read(resource.get("href")))
    items = [e for e in assessment.iter() if e.tag.endswith("}item")]
    assert len(items) == 2 * (1 + 3 + 2)
    for item in items:
        equal = [e.text for e in item.iter() if e.tag.endswith("varequal")]
        low = [e.text for e in item.iter() if e.tag.endswith("vargte")]
        high = [e.text for e in item.iter() if e.tag.endswith("varlte")]
        assert Decimal(low[0]) < Decimal(equal[0]) < Decimal(high[0])


def test_markdown_and_docx_keep_the_math(exported):
    assert "$" in (exported / "worksheet.md").read_text()
    with zipfile.ZipFile(exported / "worksheet.docx") as document:
        assert "m:oMath" in document.read("word/document.xml").decode()


def test_exports_are_deterministic(exported, tmp_path):
    again = tmp_path / "again"
    done = run_derive("sheet", "demo", "--variants", "2", "--seed", "4", "--to", "moodle,qti", "--out", str(again))
    assert done.returncode == 0
    for name in ("moodle.xml", "canvas-qti.zip"):
        assert (again / name).read_bytes() == (exported / name).read_bytes()


def test_small_answers_are_scaled_for_canvas_and_tolerances_follow_the_digits():
    assert lms.scaled("0.0000123", "m") == ("12.3", "10^-6 m")
    assert lms.scaled("0.5", "m") == ("0.5", "m")
    assert lms.tolerance("9.81") == "0.01" and lms.tolerance("1.20e+3") == "10"
