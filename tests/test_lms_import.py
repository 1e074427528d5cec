"""LMS exports that grade on import: Moodle categories of one cloze question per variant, Canvas
question groups that pick one variant in a graded quiz, and each variant's worked solution as
its feedback. The Moodle side is read as Moodle reads it (conftest.moodle_cloze)."""
import base64
import io
import json
import re
import zipfile

import lxml.html
import pytest
from lxml import etree

from conftest import image_kind, moodle_cloze, qti_package, run_derive
from derive.publishing import canvas as canvas_export, lms
from derive.language import problem_sets

PROBLEMS = problem_sets.load_set("demo").problems  # rod_endpoint (asks 1), string_wrapped_disk (3), compound_pendulum (2)


def _build(folder, seed: int):
    out = folder / f"seed{seed}"
    done = run_derive("sheet", "demo", "--variants", "2", "--seed", str(seed), "--to", "moodle,qti", "--out", str(out))
    assert done.returncode == 0, done.stderr
    return out


@pytest.fixture(scope="module")
def built(tmp_path_factory):
    return _build(tmp_path_factory.mktemp("import"), 4)


@pytest.fixture(scope="module")
def key(built):
    return json.loads((built / "key.json").read_text())


@pytest.fixture(scope="module")
def canvas(built):
    with zipfile.ZipFile(built / "canvas-qti.zip") as archive:
        return qti_package(archive)


def _text(fragment: str) -> str:
    """The text of an HTML fragment, as a browser shows it (MathJax reads the same text)."""
    return " ".join(" ".join(e.text_content() for e in lxml.html.fragments_fromstring(fragment)).split())


def _numbers(key: dict, variant: int, problem: str) -> set[str]:
    """A variant's parameter and answer values for a problem, as the key writes them."""
    entry = key["variants"][variant - 1]["problems"][problem]
    return {p["value"] for p in entry["parameters"].values()} | {a["value"] for a in entry["answers"].values()}


def test_moodle_has_a_category_per_problem_each_followed_by_a_cloze_question_per_variant(built, key):
    quiz = etree.parse(str(built / "moodle.xml")).getroot()
    order = [(q.get("type"), q.findtext("category/text") or q.findtext("name/text")) for q in quiz.iter("question")]
    assert order == [entry for problem in PROBLEMS for entry in
                     [("category", f"$course$/derive/demo/{problem}")]
                     + [("cloze", f"{problem} variant {n}") for n in (1, 2)]]
    for question in quiz.iter("question"):
        if question.get("type") == "category":
            problem = question.findtext("category/text").rsplit("/", 1)[1]
            continue
        text, fields = moodle_cloze(question.findtext("questiontext/text"))
        number = int(question.findtext("name/text").rsplit(" ", 1)[1])
        answers = key["variants"][number - 1]["problems"][problem]["answers"]
        assert [(kind, [a for _, a in options]) for kind, options in fields] == [
            ("NUMERICAL", [f"{a['value']}:{a['tolerance']}"]) for a in answers.values()]
        assert all(f"{{#{n}}}" in text for n in range(1, len(answers) + 1))


def test_moodle_feedback_is_the_variants_worked_solution_with_its_numbers(built, key):
    quiz = etree.parse(str(built / "moodle.xml")).getroot()
    questions = [q for q in quiz.iter("question") if q.get("type") == "cloze"]
    assert len(questions) == len(PROBLEMS) * 2
    for question in questions:
        problem, _, number = question.findtext("name/text").rpartition(" variant ")
        feedback = question.find("generalfeedback")
        assert feedback.get("format") == "html"
        html = feedback.findtext("text")
        shown = _text(html)
        assert f"Variant {number}." in shown and "Results" in shown
        assert all(n in shown for n in _numbers(key, int(number), problem))
        other = _numbers(key, 3 - int(number), problem) - _numbers(key, int(number), problem)
        assert other and not any(re.search(rf"(?<![\d.]){re.escape(n)}(?![\d])", shown) for n in other)
        assert "\\(" in html and "$" not in html  # MathJax's inline delimiters, not TeX's
        assert "tikzpicture" not in html and "<section" not in html and " id=" not in html
        # Only what MathJax typesets: no box, ragged text or siunitx (shown as errors), no \tag (pandoc's numbers)
        assert not re.search(r"\\(parbox|raggedright|unit|qty|SI|tag)\b", html), problem
        meanings = [a["meaning"] for a in key["variants"][0]["problems"][problem]["answers"].values()]
        assert all(f"\\text{{{meaning}}}" in " ".join(html.split()) for meaning in meanings)  # each result's


def test_canvas_has_a_group_per_problem_and_asked_quantity_that_picks_one_variant(canvas, key):
    _, assessment, meta = canvas
    (root,) = assessment.findall("{*}assessment/{*}section")
    assert root.get("ident") == "root_section"
    groups = root.findall("{*}section")
    asked = [(p, name) for p in PROBLEMS for name in key["variants"][0]["problems"][p]["answers"]]
    assert len(groups) == len(asked) == 1 + 3 + 2
    points = 0
    for group, (problem, name) in zip(groups, asked):
        selection = group.find("{*}selection_ordering/{*}selection")
        assert selection.findtext("{*}selection_number") == "1"
        each = selection.findtext("{*}selection_extension/{*}points_per_item")
        points += float(each)
        items = group.findall("{*}item")
        assert [i.get("title") for i in items] == [f"{problem} v{n} {name}" for n in (1, 2)]
        for item in items:
            fields = {f.findtext("{*}fieldlabel"): f.findtext("{*}fieldentry") for f in item.iter("{*}qtimetadatafield")}
            assert fields == {"question_type": "numerical_question", "points_possible": each}
    namespace = "{http://canvas.instructure.com/xsd/cccv1p0}"
    assert meta.tag == f"{namespace}quiz" and meta.get("identifier") == assessment.find("{*}assessment").get("ident")
    assert meta.findtext(f"{namespace}quiz_type") == "assignment"  # a graded quiz, in the gradebook
    assert float(meta.findtext(f"{namespace}points_possible")) == points == 6
    assignment = meta.find(f"{namespace}assignment")
    assert float(assignment.findtext(f"{namespace}points_possible")) == points
    assert assignment.findtext(f"{namespace}quiz_identifierref") == meta.get("identifier")
    assert assignment.findtext(f"{namespace}submission_types") == "online_quiz"


def test_canvas_feedback_is_the_variants_worked_solution_with_its_numbers(canvas, key):
    _, assessment, _ = canvas
    items = list(assessment.iter("{*}item"))
    assert len(items) == 2 * 6
    for item in items:
        problem, number = re.fullmatch(r"(\w+) v(\d) \w+", item.get("title")).groups()
        (shown,) = [c for c in item.iter("{*}respcondition") if c.find("{*}displayfeedback") is not None]
        assert shown.get("continue") == "Yes" and shown.find("{*}conditionvar/{*}other") is not None
        assert shown.find("{*}displayfeedback").get("linkrefid") == "general_fb"
        (feedback,) = item.iter("{*}itemfeedback")
        assert feedback.get("ident") == "general_fb"
        mattext = feedback.find("{*}flow_mat/{*}material/{*}mattext")
        assert mattext.get("texttype") == "text/html"
        shown = _text(mattext.text)
        assert f"Variant {number}." in shown
        assert all(n in shown for n in _numbers(key, int(number), problem))


def test_each_moodle_question_carries_its_problems_figure(built):
    """As Moodle's import_text_with_files reads it: each <file> of <questiontext>, base64, stored as
    path + name, and the text's @@PLUGINFILE@@/name refers to it."""
    quiz = etree.parse(str(built / "moodle.xml")).getroot()
    questions = [q for q in quiz.iter("question") if q.get("type") == "cloze"]
    assert len(questions) == len(PROBLEMS) * 2  # every demo problem has a figure
    for question in questions:
        text = question.find("questiontext")
        sources = [img.get("src") for img in lxml.html.fragment_fromstring(text.findtext("text"), "div").iter("img")]
        files = {f.get("path") + f.get("name"): f for f in text.findall("file")}
        assert len(sources) == len(files) == 1, sources
        assert sources[0].startswith("@@PLUGINFILE@@/") and sources[0].removeprefix("@@PLUGINFILE@@") in files
        (file,) = files.values()
        assert file.get("encoding") == "base64" and file.get("name") == question.findtext("name/text").split()[0] + ".png"
        assert image_kind(base64.b64decode(file.text, validate=True)) == "png"


def test_the_canvas_zip_holds_and_lists_each_figure_its_items_show(built):
    with zipfile.ZipFile(built / "canvas-qti.zip") as archive:
        manifest, assessment, _ = qti_package(archive)  # the manifest lists every file of the zip
        figures = [r for r in manifest.iter("{*}resource") if r.get("type") == "webcontent"]
        paths = [r.get("href") for r in figures]
        assert [f.get("href") for r in figures for f in r.iter("{*}file")] == paths
        problems = [p for p in paths if "-free-body-" not in p]  # the others: the feedback's (test_lms_free_body)
        assert sorted(problems) == sorted(f"figures/{p}.png" for p in PROBLEMS)
        assert all(image_kind(archive.read(path)) == "png" for path in paths)
    for item in assessment.iter("{*}item"):
        html = item.find("{*}presentation/{*}material/{*}mattext").text
        (img,) = lxml.html.fragment_fromstring(html, "div").iter("img")
        problem = item.get("title").split()[0]
        assert img.get("src") == f"$IMS-CC-FILEBASE$/figures/{problem}.png" and int(img.get("width")) > 0


def test_both_lms_show_the_same_worked_solution(built):
    quiz = etree.parse(str(built / "moodle.xml")).getroot()
    moodle = {q.findtext("name/text").replace(" variant ", " v"): q.findtext("generalfeedback/text")
              for q in quiz.iter("question") if q.get("type") == "cloze"}
    with zipfile.ZipFile(built / "canvas-qti.zip") as archive:
        _, assessment, _ = qti_package(archive)
    for item in assessment.iter("{*}item"):
        variant = item.get("title").rsplit(" ", 1)[0]
        canvas = item.find("{*}itemfeedback//{*}mattext").text  # each image from its own LMS's place:
        assert canvas.replace('src="$IMS-CC-FILEBASE$/figures/', 'src="@@PLUGINFILE@@/') == moodle[variant]


def _identifiers(package: bytes) -> list[str]:
    """Every identifier a Canvas import matches: the quiz's, the metadata's, the groups' and the items'."""
    with zipfile.ZipFile(io.BytesIO(package)) as archive:
        manifest, assessment, meta = qti_package(archive)
    found = [r.get("identifier") for r in manifest.iter("{*}resource")] + [manifest.get("identifier")]
    found += [e.get("ident") for e in assessment.iter("{*}section", "{*}item") if e.get("ident") != "root_section"]
    found += [e.get("identifier") for e in meta.iter("{*}assignment")]
    return found


def _items(problem: str = "p") -> list[lms.Item]:
    return [lms.Item(problem, "P", n, "q", name, "m", "2.5", "m/s", "0.1", (), f"<p>{n}</p>")
            for n in (1, 2) for name in ("x", "y")]


def test_identifiers_are_the_same_for_the_same_set_and_seed_and_differ_otherwise(built, tmp_path):
    same = _identifiers(canvas_export.qti(_items(), "T", "week", 4))
    assert len(set(same)) == len(same) == 2 + 1 + 2 + 4 + 1  # resources, manifest, groups, items, assignment
    assert _identifiers(canvas_export.qti(_items(), "Other title", "week", 4)) == same
    for other in (canvas_export.qti(_items(), "T", "week", 5), canvas_export.qti(_items(), "T", "week2", 4)):
        assert not set(_identifiers(other)) & set(same)
    questions = _identifiers(canvas_export.qti(_items("q"), "T", "week", 4))  # another problem: its own groups and items
    assert questions[:3] + questions[-1:] == same[:3] + same[-1:] and not set(questions[3:-1]) & set(same)
    first = _identifiers((built / "canvas-qti.zip").read_bytes())  # a whole set: seed 4, then seed 5
    second = _identifiers((_build(tmp_path, 5) / "canvas-qti.zip").read_bytes())
    assert len(set(first)) == len(first) and not set(first) & set(second)


def test_a_choice_reads_back_in_moodle_as_written_whatever_its_characters():
    unit = "m/s^2 \" ~ # } { \\ & &amp; &#126; \\} \\#"
    item = lms.Item("p", "P", 1, "q", "a", "m", "1.5", unit, "0.1", ("2.5", "3.5"))
    (question,) = [q for q in etree.fromstring(lms.moodle([item], "week").encode()) if q.get("type") == "cloze"]
    text, [(kind, options)] = moodle_cloze(question.findtext("questiontext/text"))
    assert kind == "MULTICHOICE_V" and text.endswith("= {#1}</p>")
    assert sorted(options) == sorted([("=", f"1.5 {unit}"), ("%0%", f"2.5 {unit}"), ("%0%", f"3.5 {unit}")])
    assert "m\\/s" not in question.findtext("questiontext/text")  # `/` is no special of Moodle's: no backslash
