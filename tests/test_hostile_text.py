"""Text from untrusted files in every export: each file parses and shows the text as written.

Titles and meanings are plain text and may hold XML's, HTML's, jinja's and a spreadsheet's
specials; every export is built by a serializer, and key.csv neutralizes a formula.
"""
import csv
import io
import json
import re
import subprocess
import zipfile
from decimal import Decimal

import lxml.html
import pytest
import yaml
from lxml import etree

from conftest import qti_package, run_derive
from derive.publishing import canvas, lms
from derive.publishing.spreadsheet import safe_cell
from test_hardening import problem_text

HOSTILE = "\" ' < > & ]]> = {{ }}"
SET_TITLE, TITLE, MEANING, ASK = f"Set {HOSTILE}", f"Title {HOSTILE}", f"mass {HOSTILE}", f"=1+1 {HOSTILE}"
# MEANING, a parameter's, is shown by no output of a set (only by a handout): it must not break one.


def shown(text: str) -> str:
    """Typeset text as written: TeX and pandoc print an apostrophe as ’; lines joined."""
    return " ".join(text.replace("\u2019", "'").split())


def paragraphs(fragment: str) -> list[str]:
    """The text of each <p> of an LMS question's HTML."""
    return [p.text_content() for p in lxml.html.fragments_fromstring(fragment)]


def qti_assessment(archive: zipfile.ZipFile) -> etree._Element:
    """The assessment of a QTI zip, parsed, once its parsed manifest is found to list every other
    file (conftest.qti_package); its quiz metadata holds the set's title as written."""
    _, assessment, meta = qti_package(archive)
    assert meta.findtext("{*}title") == assessment.find("{*}assessment").get("title")
    return assessment


@pytest.fixture(scope="module")
def built(tmp_path_factory):
    folder = tmp_path_factory.mktemp("hostile")
    quoted = {name: text.replace('"', '\\"') for name, text in
              {"title": TITLE, "meaning": MEANING, "ask_meaning": ASK}.items()}
    problem = folder / "hostile.yaml"
    problem.write_text(problem_text(**quoted, question="A disk of mass {{ M }} turns."))
    week = folder / "week.yaml"
    week.write_text(yaml.safe_dump({"title": SET_TITLE, "problems": [str(problem)], "variants": 2}))
    out = folder / "out"
    done = run_derive("sheet", str(week), "--to", "pdf,html,md,docx,moodle,qti", "--out", str(out))
    assert done.returncode == 0, done.stderr
    return out


def test_pdfs_show_the_titles_and_meanings(built):
    expected = {"worksheet": [SET_TITLE, TITLE], "worksheet-1": [SET_TITLE, TITLE], "worksheet-2": [SET_TITLE, TITLE],
                "solutions": [SET_TITLE, TITLE, ASK], "key": [SET_TITLE]}
    for name, texts in expected.items():
        pdf = subprocess.run(["pdftotext", "-enc", "UTF-8", str(built / f"{name}.pdf"), "-"],
                             capture_output=True, text=True, check=True).stdout
        for text in texts:
            assert text in shown(pdf), (name, text)


def test_pandoc_outputs_parse_and_show_the_titles(built):
    page = lxml.html.parse(str(built / "worksheet.html")).getroot()
    assert page.findtext("head/title") == SET_TITLE
    markdown = re.sub(r"\\([!-/:-@\[-`{-~])", r"\1", (built / "worksheet.md").read_text())  # markdown's escapes
    with zipfile.ZipFile(built / "worksheet.docx") as docx:
        parts = {name: etree.fromstring(docx.read(name)) for name in docx.namelist()
                 if name.endswith((".xml", ".rels"))}  # every part parses
    words = "\n".join("".join(p.itertext()) for p in parts["word/document.xml"].iter("{*}p"))
    for text in (SET_TITLE, TITLE):
        assert text in shown(page.find("body").text_content()) and text in markdown and text in shown(words)
    assert [i.get("alt") for i in page.iter("img")] == ["Figure of problem 1"] * 2
    assert markdown.count('![Figure of problem 1](figures/plain_disk.svg){width="') == 2


def test_keys_show_the_meaning_and_the_csv_neutralizes_its_formula(built):
    rows = list(csv.DictReader((built / "key.csv").open(newline="")))
    assert len(rows) == 2 and all(r["meaning"] == "'" + ASK for r in rows)
    assert all(Decimal(r["value"]) > 0 and Decimal(r["tolerance"]) > 0 for r in rows)  # numbers stay numbers
    key = json.loads((built / "key.json").read_text())
    assert key["title"] == SET_TITLE
    assert [v["problems"]["plain_disk"]["answers"]["I"]["meaning"] for v in key["variants"]] == [ASK, ASK]


def test_lms_exports_parse_and_show_the_meaning(built):
    quiz = etree.parse(str(built / "moodle.xml")).getroot()
    questions = [q for q in quiz.iter("question") if q.get("type") == "cloze"]
    assert [q.findtext("name/text") for q in questions] == ["plain_disk variant 1", "plain_disk variant 2"]
    for question in questions:
        html = question.findtext("questiontext/text")
        _, _, field = paragraphs(html)  # the question, its figure, the answer's field
        assert field.startswith(f"{ASK}: \\(I\\) = {{1:NUMERICAL:=")
        assert [i.get("alt") for i in lxml.html.fragment_fromstring(html, "div").iter("img")] == [f"Figure: {TITLE}"]
    with zipfile.ZipFile(built / "canvas-qti.zip") as archive:
        assessment = qti_assessment(archive)
    assert assessment.find("{*}assessment").get("title") == SET_TITLE
    items = [p.findtext("{*}material/{*}mattext") for p in assessment.iter("{*}presentation")]
    assert [paragraphs(html)[2] for html in items] == [f"{ASK}: \\(I\\) (in kg·m²)"] * 2
    assert [i.get("alt") for html in items for i in lxml.html.fragment_fromstring(html, "div").iter("img")] \
        == [f"Figure: {TITLE}"] * 2
    feedback = [q.findtext("generalfeedback/text") for q in questions] + [
        f.findtext("{*}flow_mat/{*}material/{*}mattext") for f in assessment.iter("{*}itemfeedback")]
    for n, html in enumerate(feedback):  # each variant's worked solution, parsed whole
        assert f"Variant {n % 2 + 1}. Given" in shown(" ".join(paragraphs(html)))


def test_lms_exports_of_both_question_kinds_show_hostile_text_as_written():
    items = [lms.Item("p", TITLE, 1, f"Find $x$ {HOSTILE}", "x", ASK, "2.5", "m", "0.1"),
             lms.Item("p", TITLE, 1, f"Find $x$ {HOSTILE}", "y", ASK, "2.5", "m", "0.1", ("1.25", "5.0"))]
    quiz = etree.fromstring(lms.moodle(items, "week").encode())
    question, field, choice = paragraphs(quiz.findtext("question[@type='cloze']/questiontext/text"))
    assert question == f"Find \\(x\\) {HOSTILE}"
    assert field.startswith(f"{ASK}: \\(x\\) = {{1:NUMERICAL:")
    assert choice.startswith(f"{ASK}: \\(y\\) = {{1:MULTICHOICE_V:")
    with zipfile.ZipFile(io.BytesIO(canvas.qti(items, SET_TITLE, "week", 0))) as archive:
        assessment = qti_assessment(archive)
    assert assessment.find("{*}assessment").get("title") == SET_TITLE
    texts = [paragraphs(m.text) for m in assessment.iter("{*}mattext") if m.get("texttype") == "text/html"]
    assert texts == [[f"Find \\(x\\) {HOSTILE}", f"{ASK}: \\(x\\) (in m)"], [f"Find \\(x\\) {HOSTILE}", f"{ASK}: \\(y\\)"]]


@pytest.mark.parametrize("text, expected", [
    ("=HYPERLINK(\"http://x\")", "'=HYPERLINK(\"http://x\")"), ("+1+1", "'+1+1"), ("-1+2", "'-1+2"),
    ("@SUM(A1)", "'@SUM(A1)"), ("\t=1", "'\t=1"), ("\r=1", "'\r=1"), ("-Infinity", "'-Infinity"), ("-1_000", "'-1_000"),
    ("-4.44", "-4.44"), ("1.2e-05", "1.2e-05"), ("+3", "+3"), ("-.5", "-.5"), ("1.20e+3", "1.20e+3"),
    ("mass = 2", "mass = 2"), ("", ""), (7, 7),
])
def test_a_key_cell_that_a_spreadsheet_would_run_is_quoted(text, expected):
    assert safe_cell(text) == expected
