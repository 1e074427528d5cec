"""Free-body diagrams in the LMS feedback: each body's diagram beside its balance in the student's route, an image
of the worked solution in both exports (a base64 PNG <file> of Moodle's general feedback, a listed
file of the Canvas zip), drawn once per problem however many variants show it."""
import base64
import zipfile

import lxml.html
import pytest
from lxml import etree

from conftest import image_kind, qti_package
from derive.publishing import figure_files, lms, worksheets
from derive.solution.answers import Solution
from derive.publishing.figure import free_body
from derive.language.problem import load

PNG = b"\x89PNG\r\n\x1a\n"
VARIANTS = 3
WITH = "string_wrapped_disk"  # a disk on an axle and a block on a cord: a Newton–Euler balance each
WITHOUT = "kepler_orbit"  # an orbit: the radial equation by Lagrange and by Newton, no bodies' balances


def _balances(problem: str) -> dict[str, str]:
    """Each body's first balance step in the student's route (which the LMS feedback shows), by body."""
    solution = Solution(load(problem))
    result = {}
    for step in (s for section in solution.student_steps.values() for s in section if s.body):
        result.setdefault(step.body, step.text)
    return result


def _forces(problem: str) -> dict[str, list[str]]:
    """The forces on each body, as its Newton–Euler balance step names them ("tension of string, weight")."""
    solution = Solution(load(problem))
    return {s.body: s.text.partition("(")[2].rstrip(")").split(", ")
            for s in solution.derivations["newton_euler"].steps if s.body}


@pytest.fixture(scope="module")
def built(tmp_path_factory):
    """The set built in this process, counting the diagrams drawn and the figures compiled."""
    drawn, compiled = [], []
    draw, images = free_body.free_bodies, figure_files.images
    with pytest.MonkeyPatch.context() as patch:
        patch.setattr(free_body, "free_bodies", lambda problem, *rest: drawn.append(problem.id) or draw(problem, *rest))
        patch.setattr(figure_files, "images", lambda names, pdf: compiled.extend(names) or images(names, pdf))
        out = tmp_path_factory.mktemp("fbd") / "set"
        worksheets.build([WITH, WITHOUT], variants=VARIANTS, seed=3, out_dir=str(out),
                         formats=frozenset({"moodle", "qti"}), cache=False)  # every diagram drawn here: counted
    return out, drawn, compiled


def _moodle(out) -> dict[str, list[etree._Element]]:
    questions: dict[str, list[etree._Element]] = {}
    for question in etree.parse(str(out / "moodle.xml")).getroot().iter("question"):
        if question.get("type") == "cloze":
            questions.setdefault(question.findtext("name/text").split()[0], []).append(question)
    return questions


def _images(html: str) -> list:
    return list(lxml.html.fragment_fromstring(html, "div").iter("img"))


def test_each_moodle_feedback_shows_a_png_diagram_per_body_from_a_file_of_its_own(built):
    """As Moodle's import_text_with_files reads <generalfeedback>: each <file>, base64, stored as
    path + name, shown where the feedback's HTML refers to @@PLUGINFILE@@/name."""
    balances = _balances(WITH)
    questions = _moodle(built[0])
    assert len(questions[WITH]) == VARIANTS
    shown = []
    for question in questions[WITH]:
        feedback = question.find("generalfeedback")
        files = {f.get("path") + f.get("name"): f for f in feedback.findall("file")}
        images = _images(feedback.findtext("text"))
        assert len(images) == len(files) == len(balances) == 2
        for img, body in zip(images, balances):  # in the order of the balances, each right after its own
            source = img.get("src")
            assert source == f"@@PLUGINFILE@@/{WITH}-free-body-{body}.png"
            data = base64.b64decode(files[source.removeprefix("@@PLUGINFILE@@")].text, validate=True)
            assert data.startswith(PNG) and image_kind(data) == "png"
            alt = img.get("alt")
            assert alt.startswith(f"Free-body diagram of the {body}: ")
            named = _forces(WITH)[body]  # "reaction of axle, ..., weight"
            assert named and all(f"the {force}, " in alt for force in named), (alt, named)
            assert not set(alt) & set("*_^"), alt  # words and math as read aloud ("the weight, M g"), not code
            assert int(img.get("width")) > 0
        shown.append([files[f"/{WITH}-free-body-{body}.png"].text for body in balances])
    assert all(s == shown[0] for s in shown)  # the same images in every variant: labelled with symbols


def test_the_diagram_follows_its_bodys_balance_in_the_feedback(built):
    feedback = " ".join(_moodle(built[0])[WITH][0].findtext("generalfeedback/text").split())  # pandoc wraps lines
    balances = _balances(WITH)
    for body, text in balances.items():
        balance = feedback.index(text.split(" (")[0].replace("'", "’"))
        diagram = feedback.index(f"{WITH}-free-body-{body}.png")
        later = [feedback.find(other.split(" (")[0].replace("'", "’"), balance + 1) for other in balances.values()]
        assert balance < diagram < min([i for i in later if i > balance] + [len(feedback)])


def test_a_problem_without_newton_euler_shows_no_diagram(built):
    questions = _moodle(built[0])[WITHOUT]
    assert len(questions) == VARIANTS
    for question in questions:
        assert question.findall("generalfeedback/file") == []
        assert _images(question.findtext("generalfeedback/text")) == []
        assert "Variant" in question.findtext("generalfeedback/text")


def test_the_canvas_zip_holds_and_lists_every_diagram_its_feedback_shows(built):
    out = built[0]
    moodle = {f.get("name"): base64.b64decode(f.text) for q in _moodle(out)[WITH] for f in q.findall("generalfeedback/file")}
    with zipfile.ZipFile(out / "canvas-qti.zip") as archive:
        manifest, assessment, _ = qti_package(archive)  # every file of the zip listed, and nothing else
        listed = {r.get("href") for r in manifest.iter("{*}resource") if r.get("type") == "webcontent"}
        referred = {}
        for item in assessment.iter("{*}item"):
            problem = item.get("title").split()[0]
            feedback = item.find("{*}itemfeedback[@ident='general_fb']//{*}mattext").text
            sources = [img.get("src") for img in _images(feedback)]
            assert len(sources) == (len(_balances(WITH)) if problem == WITH else 0)
            for source in sources:
                path = source.removeprefix("$IMS-CC-FILEBASE$/")
                assert source.startswith("$IMS-CC-FILEBASE$/figures/") and path in listed
                referred[path] = archive.read(path)
        assert sorted(referred) == sorted(f"figures/{WITH}-free-body-{body}.png" for body in _balances(WITH))
        for path, data in referred.items():
            assert data.startswith(PNG) and data == moodle[path.removeprefix("figures/")]  # one image, both LMS


def test_diagrams_are_drawn_and_compiled_once_per_problem_not_per_variant(built):
    _, drawn, compiled = built
    # once for the student's route (forces drawn the way they act), once for the proof's Newton–Euler balances
    assert drawn.count(WITH) == 2 and drawn.count(WITHOUT) == 0  # the orbit has no Newton–Euler balances
    diagrams = [n for n in compiled if "-free-body-" in n]
    assert sorted(diagrams) == sorted(f"{WITH}-free-body-{body}" for body in _balances(WITH))


def test_a_feedback_image_that_is_none_of_the_builds_figures_is_refused():
    html = '<p><img src="figures/elsewhere.png" alt="image"></p>'
    with pytest.raises(ValueError, match="figures/elsewhere.png"):
        lms._feedback(html, {}, lambda image: image.file("png"))
    assert lms._feedback("<p>No image: a &lt;img&gt; in words</p>", {}, str) == ("<p>No image: a &lt;img&gt; in words</p>", [])
