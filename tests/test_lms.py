"""The exports instructors import: Markdown, DOCX, Moodle XML and a QTI zip for Canvas."""
import csv
import io
import json
import re
import xml.etree.ElementTree as ET
import zipfile
from decimal import Decimal

import pytest

from pathlib import Path

from conftest import copy_library, image_kind, moodle_cloze, qti_package, run_derive
from derive.text.latex import symbol_latex
from derive.publishing import canvas, lms
from derive.publishing.wording import Wording
from derive.language import problem_sets
from derive.core import units
from derive.core.errors import InputError, ProblemError
from derive.language.problem import load, parse


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
        _, assessment, _ = qti_package(archive)
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


def test_markdown_refers_to_each_figure_in_a_file_beside_it(exported):
    sources = re.findall(r"!\[Figure of problem \d\]\(([^)\s]+)\)\{width=", (exported / "worksheet.md").read_text())
    assert len(sources) == 2 * 3 and len(set(sources)) == 3  # each variant's problems; one file per problem
    for source in sources:
        assert source.startswith("figures/") and ".." not in source
        assert image_kind((exported / source).read_bytes()) == "svg"


def test_docx_embeds_each_figure_as_a_png(exported):
    with zipfile.ZipFile(exported / "worksheet.docx") as document:
        media = [n for n in document.namelist() if n.startswith("word/media/")]
        assert len(media) == 3  # one image per problem, shown in each variant
        assert all(image_kind(document.read(name)) == "png" for name in media)
        body = document.read("word/document.xml").decode()
        relations = document.read("word/_rels/document.xml.rels").decode()
    embedded = re.findall(r'r:embed="([^"]+)"', body)
    assert len(embedded) == 2 * 3
    for relation in set(embedded):
        target = re.search(rf'Id="{relation}"[^>]*Target="([^"]+)"|Target="([^"]+)"[^>]*Id="{relation}"', relations)
        assert f"word/{target.group(1) or target.group(2)}" in media


def test_exports_are_deterministic(exported, tmp_path):
    again = tmp_path / "again"
    done = run_derive("sheet", "demo", "--variants", "2", "--seed", "4", "--to", "moodle,qti", "--out", str(again))
    assert done.returncode == 0
    for name in ("moodle.xml", "canvas-qti.zip"):
        assert (again / name).read_bytes() == (exported / name).read_bytes()


def test_small_margins_are_scaled_for_canvas_and_tolerances_follow_the_policy():
    assert lms.exponent(["1e-7"]) == 3 and lms.scaled("0.0000123", "1e-7", 3) == ("0.0123", "0.0001")
    assert lms.exponent(["0.00001"]) == 3 and lms.scaled("0.00123", "0.00001", 3) == ("1.23", "0.01")  # not 0.0012
    assert lms.exponent(["0.1"]) == 0 and lms.scaled("0.5", "0.1", 0) == ("0.5", "0.1")
    assert lms.exponent(["0.1", "1e-5", "1e-8"]) == 6  # the finest margin of the question's variants decides
    assert lms.scaled_unit("kg·m²", 3) == "10⁻³ kg·m²" and lms.scaled_unit("", 6) == "10⁻⁶"
    assert lms.tolerance("9.81") == "0.01" and lms.tolerance("1.20e+3") == "10"
    assert lms.tolerance("-250", "2%") == "5" and lms.tolerance("3.3", "0.05") == "0.05"


def _item(value, tolerance, unit="m"):
    return lms.Item("p", "P", 1, "q", "x", "a length", value, unit, tolerance)


def test_tolerances_are_held_to_each_lms_limits(monkeypatch):
    for target in ("moodle", "qti"):
        with pytest.raises(InputError, match=r"p variant 1: ask\.x\.tolerance: .*accepts zero and the wrong sign"):
            lms.check([_item("2.5", "3")], target)
        lms.check([_item("2.5", "0.1"), _item("0", "0")], target)
    with pytest.raises(InputError, match="finer than Moodle can compare"):
        lms.check([_item("2.5", "1e-15")], "moodle")
    lms.check([_item("0.00123", "0.00001")], "qti")  # scaled: survives
    lms.check([_item("0.5", "0.1"), _item("0.00123", "0.00001")], "qti")  # one unit for both: both survive
    monkeypatch.setattr(lms, "scaled", lambda value, margin, k: (value, margin))
    with pytest.raises(InputError, match="Canvas needs a margin of at least 1e-4"):
        lms.check([_item("0.00123", "0.00001")], "qti")


@pytest.mark.parametrize("tolerance, reason", [
    ("150%", "150% of the answer would accept zero"), ("-1", "expected a percentage"), ("abc", "expected a percentage"),
    ("true", "expected a percentage"), ("0%", "expected a percentage"),
    ("1e-999999999", "1e-999999999 is narrower than the digits any answer shows"),  # was written as 0
    ("1e-999999999%", "1e-999999999% is narrower than the digits any answer shows"),
    ("1e999999999", "1e999999999 lies outside what an LMS stores"),  # was an internal Decimal overflow
])
def test_bad_tolerance_policies_name_the_field(tolerance, reason, tmp_path):
    text = load("rod_endpoint").path.read_text().replace("unit: kg*m^2}", f"unit: kg*m^2, tolerance: {tolerance}}}")
    with pytest.raises(ProblemError, match=rf"p\.yaml: ask\.I\.tolerance: {reason}"):
        parse(text, tmp_path / "p.yaml")


def _set(tmp_path, body: str) -> Path:
    path = tmp_path / "week.yaml"
    path.write_text(body)
    return path


def test_a_declared_tolerance_reaches_the_key_and_both_lms(tmp_path):
    library = copy_library(tmp_path)
    rod = library / "inertia" / "rod_endpoint.yaml"
    rod.write_text(rod.read_text().replace("unit: kg*m^2}", "unit: kg*m^2, tolerance: 5%}"))
    week = _set(tmp_path, "title: T\nproblems: [rod_endpoint]\nvariants: 2\noutputs: [moodle, qti]\n")
    done = run_derive("sheet", str(week), "--out", str(tmp_path / "out"), library=library)
    assert done.returncode == 0, done.stderr
    rows = list(csv.DictReader((tmp_path / "out" / "key.csv").open()))
    assert len(rows) == 2 and not (tmp_path / "out" / "worksheet.pdf").exists()  # outputs: from the set
    for row in rows:
        assert Decimal(row["tolerance"]) == abs(Decimal(row["value"])) * Decimal("0.05")
    moodle = (tmp_path / "out" / "moodle.xml").read_text()
    assert sorted(re.findall(r"NUMERICAL:=([^:]+):([^}]+)\}", moodle)) == sorted((r["value"], r["tolerance"]) for r in rows)


def _choice(value: str, unit: str) -> str:
    """A choice as shown: the value and its unit as text (kg·m²), the value alone for a pure number."""
    return f"{value} {units.unicode_unit(unit)}".rstrip()


def test_multiple_choice_exports_hold_the_right_answer_once_among_derived_mistakes(tmp_path):
    week = _set(tmp_path, "title: T\nproblems: [rolling_incline]\nvariants: 2\nseed: 5\nquestions: choice\n")
    out = tmp_path / "out"
    done = run_derive("sheet", str(week), "--to", "moodle,qti", "--out", str(out))
    assert done.returncode == 0, done.stderr
    key = json.loads((out / "key.json").read_text())
    answers = [(a["value"], a["unit"], a["distractors"]) for v in key["variants"]
               for a in v["problems"]["rolling_incline"]["answers"].values()]
    quiz = ET.parse(out / "moodle.xml").getroot()
    fields = [f for q in quiz.iter("question") if q.get("type") == "cloze"
              for f in moodle_cloze(q.find("questiontext/text").text)[1]]  # as Moodle reads them
    assert len(fields) == len(answers) == 2 * 5
    for (kind, options), (value, unit, wrong) in zip(fields, answers):
        assert kind == "MULTICHOICE_V"
        assert [a for mark, a in options if mark == "="] == [_choice(value, unit)]  # m/s², no backslash
        assert sorted(a for mark, a in options if mark == "%0%") == sorted(_choice(w["value"], unit) for w in wrong)
        assert len(options) == 4  # three mistakes apply to every answer of the rolling sphere
    assert any(options[0][0] != "=" for _, options in fields)  # the right answer is not always first
    said = [f for q in quiz.iter("question") if q.get("type") == "cloze"
            for f in moodle_cloze(q.find("questiontext/text").text, feedback=True)[1]]
    words = Wording(load("rolling_incline"))  # the key's mistake names the body by its key; a student's, as the solutions do
    for (_, options), (_, unit, wrong) in zip(said, answers):  # each wrong choice says which mistake gives it
        assert sorted((a, f) for mark, a, f in options if mark == "%0%") == sorted(
            (_choice(w["value"], unit), f"Not this one: it is what {words(w['mistake'])} gives.") for w in wrong)
        assert [f for mark, _, f in options if mark == "="] == [""]
    with zipfile.ZipFile(out / "canvas-qti.zip") as archive:
        _, assessment, _ = qti_package(archive)
    titles = {f"rolling_incline v{n} {name}": (a["value"], a["unit"]) for n, v in enumerate(key["variants"], start=1)
              for name, a in v["problems"]["rolling_incline"]["answers"].items()}
    items = [e for e in assessment.iter() if e.tag.endswith("}item")]
    assert sorted(i.get("title") for i in items) == sorted(titles)
    for item in items:
        value, unit = titles[item.get("title")]
        fields = {f.findtext("{*}fieldlabel"): f.findtext("{*}fieldentry") for f in item.iter("{*}qtimetadatafield")}
        assert fields == {"question_type": "multiple_choice_question", "points_possible": "1"}
        (scored,) = [c for c in item.iter("{*}respcondition") if c.find("{*}setvar") is not None]
        right = scored.findtext(".//{*}varequal")
        label = next(e for e in item.iter() if e.tag.endswith("response_label") and e.get("ident") == right)
        assert label.find(".//{*}mattext").text == _choice(value, unit)
        shown = {f.get("ident"): f.findtext(".//{*}mattext") for f in item.iter("{*}itemfeedback")}
        linked = {d.get("linkrefid") for d in item.iter("{*}displayfeedback")}
        assert set(shown) == linked == {"general_fb"} | {f"choice{n}_fb" for n in range(4) if f"choice{n}" != right}
        assert all(shown[f].startswith("Not this one: it is what ") for f in shown if f != "general_fb")
    again = tmp_path / "again"
    assert run_derive("sheet", str(week), "--to", "moodle,qti", "--out", str(again)).returncode == 0
    assert (again / "moodle.xml").read_bytes() == (out / "moodle.xml").read_bytes()


def test_set_files_pick_problems_by_topic_and_the_command_line_overrides_outputs(tmp_path):
    week = _set(tmp_path, "title: T\nproblems: [{topic: rolling, count: 2}, rod_endpoint]\noutputs: [pdf]\n"
                          "questions: numerical\n")
    chosen = problem_sets.load_set(str(week))
    assert len(chosen.problems) == 3 and chosen.problems[-1] == "rod_endpoint"
    assert all(load(p).topic == "rolling" for p in chosen.problems[:2])
    assert chosen.outputs == {"pdf"}
    everything = problem_sets.load_set(str(_set(tmp_path, "title: T\nproblems: [{topic: orbits}]\n")))
    assert sorted(load(p).id for p in everything.problems) == ["effective_potential", "kepler_orbit"]
    assert everything.outputs == {"pdf", "html"} and everything.questions == "numerical"
    done = run_derive("sheet", str(_set(tmp_path, "title: T\nproblems: [rod_endpoint]\noutputs: [pdf]\n")),
                      "--to", "md", "--out", str(tmp_path / "out"))
    assert done.returncode == 0, done.stderr
    assert (tmp_path / "out" / "worksheet.md").exists() and not (tmp_path / "out" / "worksheet.pdf").exists()


@pytest.mark.parametrize("body, message", [
    ("problems: [{topic: cooking}]", "week.yaml: problems[0].topic: no problem of topic 'cooking' (topics: "),
    ("problems: [{topic: orbits, count: 3}]", "week.yaml: problems[0].count: expected a whole number from 1 to 2"),
    ("problems: [{subject: orbits}]", "week.yaml: problems[0]: expected a library id"),
    ("problems: [rod_endpoint]\noutputs: [pdf, fax]", "week.yaml: outputs: unknown output 'fax'"),
    ("problems: [rod_endpoint]\nquestions: essay", "week.yaml: questions: expected one of numerical, choice"),
    ("problems: [rod_endpoint]\nanswer_space: a lot", "week.yaml: answer_space: expected a length in cm, mm or in"),
    ("problems: [rod_endpoint]\ncourse: &a PHY\ndue: *a", "week.yaml: invalid set file: aliases (*name) are not allowed"),
])
def test_bad_set_files_name_the_field(body, message, tmp_path):
    done = run_derive("sheet", str(_set(tmp_path, "title: T\n" + body + "\n")), "--out", str(tmp_path / "o"))
    assert done.returncode == 2 and message in done.stderr and done.stderr.count("\n") == 1


#: Moodle's cloze parser (question/type/multianswer/questiontype.php, ANSWER_REGEX) finds an answer
#: field wherever the raw question HTML holds `{` + optional weight + `:` + a question type.
CLOZE_FIELD = re.compile(r"\{[0-9]*:(?:NUMERICAL|NM|SHORTANSWER|SA|MW|MULTICHOICE\w*|MC\w*)", re.I)


def test_problem_text_cannot_add_a_cloze_field():
    """A meaning or question holding cloze syntax once became an extra answer field in Moodle."""
    item = lms.Item("p", "t", 1, r"Mass $\frac{1}{2}$ and {1:NUMERICAL:=0}", "a", "meaning {1:SA:=x}",
                    "1.5", "m", "0.1")
    (question,) = [q for q in ET.fromstring(lms.moodle([item], "cat").encode()) if q.get("type") == "cloze"]
    html = question.find("questiontext/text").text
    assert len(CLOZE_FIELD.findall(html)) == 1  # derive's own field only
    assert r"\frac&#123;1}&#123;2}" in html and "{1:NUMERICAL:=1.5:0.1}" in html


@pytest.mark.parametrize("value", ["1.5e+301", "-2.0e-301"])
def test_values_an_lms_cannot_store_are_refused(value):
    item = lms.Item("p", "t", 1, "q", "a", "m", value, "kg", lms.tolerance(value))
    for target in ("moodle", "qti"):
        with pytest.raises(InputError, match=r"p variant 1: ask.a: .* lies outside what an LMS stores"):
            lms.check([item], target)


# --- labels and units as a student reads them (issue 16, item 4) ------------------------------

#: Tiny and huge answers (atoms, quanta, orbits), a pure number (share), word subscripts
#: (Omega_fast, U_min, r_circ) and a word as a symbol (Rcm, in the pendulum's solution).
LABELLED = ["diatomic_molecule", "angular_momentum_quantization", "rolling_kinetic_energy", "top_precession_exact",
            "effective_potential", "compound_pendulum"]


@pytest.fixture(scope="module")
def labelled(tmp_path_factory):
    folder = tmp_path_factory.mktemp("labels")
    week = _set(folder, f"title: Labels\nproblems: [{', '.join(LABELLED)}]\nvariants: 5\nseed: 3\n")
    done = run_derive("sheet", str(week), "--to", "moodle,qti", "--out", str(folder / "out"))
    assert done.returncode == 0, done.stderr
    return folder / "out"


def _math(label: str) -> str:
    """The one \\( \\) math of a field's label."""
    (math,) = re.findall(r"\\\((.*?)\\\)", label)
    return math


def _reads_as_math(math: str) -> bool:
    """No word typeset as a product of italic letters: every run of two letters or more is a
    command (\\Omega, \\mathrm) or its argument (\\mathrm{fast}), never a bare or subscripted word."""
    return not re.search(r"(?<![\\{A-Za-z])[A-Za-z]{2,}", math) and not re.search(r"_\{?[A-Za-z]{2}", math)


def _shown_unit(unit: str) -> bool:
    """A unit as text shows it: no operators of the problem file's syntax, no "1" for a pure number."""
    return not set(unit) & set("*^") and unit.strip() != "1"


@pytest.mark.parametrize("name, latex", [
    ("Omega_fast", r"\Omega_{\mathrm{fast}}"), ("Rcm", r"R_{\mathrm{cm}}"), ("I_cm", r"I_{\mathrm{cm}}"),
    ("K_rot", r"K_{\mathrm{rot}}"), ("U_min", r"U_{\mathrm{min}}"), ("theta_c", r"\theta_{c}"), ("L_x", "L_{x}"),
    ("omega0", r"\omega_{0}"), ("m1", "m_{1}"), ("a_theta", r"a_{\theta}"), ("mu_s", r"\mu_{s}"), ("alpha", r"\alpha"),
    ("dphi", r"d\phi"), ("dtheta", r"d\theta"), ("GM", r"\mathit{GM}"), ("share", r"\mathrm{share}"), ("vx", "v_{x}"), ("dE", r"\Delta E"),
    ("angle", r"\mathrm{angle}"), ("hbar", r"\hbar"), ("v_cm_x", r"v_{\mathrm{cm},x}"), ("x", "x"),
])
def test_symbols_read_as_math(name, latex):
    assert symbol_latex(name) == latex and _reads_as_math(latex)


def test_lms_labels_and_units_read_as_a_student_reads_them(labelled):
    key = json.loads((labelled / "key.json").read_text())
    asked = {(p, n): a for v in key["variants"] for p, answers in v["problems"].items()
             for n, a in answers["answers"].items()}
    pure = {question for question, a in asked.items() if a["unit"] == "1"}
    assert ("rolling_kinetic_energy", "share") in pure
    quiz = ET.parse(labelled / "moodle.xml").getroot()
    fields = [p for q in quiz.iter("question") if q.get("type") == "cloze"
              for p in re.findall(r"<p>(.*?)</p>", q.find("questiontext/text").text) if "{1:NUMERICAL" in p]
    assert len(fields) == 5 * len(asked)
    for field in fields:
        label, unit = re.fullmatch(r"(.*) = \{1:NUMERICAL:=[^}]*\}(.*)", field.replace("&#123;", "{")).groups()
        assert _reads_as_math(_math(label)), label
        assert _shown_unit(unit), field
    assert any(r"\(\Omega_{\mathrm{fast}}\) = " in f.replace("&#123;", "{") for f in fields)
    assert sum(f.endswith("}") for f in fields) == 5 * len(pure)  # a pure number: no unit after its field
    with zipfile.ZipFile(labelled / "canvas-qti.zip") as archive:
        _, assessment, _ = qti_package(archive)
    groups = [s for s in assessment.iter("{*}section") if s.find("{*}item") is not None]
    assert len(groups) == len(asked)
    for group in groups:
        prompts = {re.findall(r"<p>(.*?)</p>", item.findtext(".//{*}mattext"))[-1] for item in group.iter("{*}item")}
        assert len(prompts) == 1, prompts  # one label, one unit for all the variants of the question
        (prompt,) = prompts
        assert _reads_as_math(_math(prompt)) and _shown_unit(prompt), prompt
        unit = re.search(r"\(in (.*)\)$", prompt)
        problem, _, name = group.find("{*}item").get("title").partition(" v1 ")
        assert (unit is None) == ((problem, name) in pure), prompt
        power = re.match("10([⁻⁰-⁹¹²³]+) ", unit[1]) if unit else None
        k = -int(power[1].translate(str.maketrans("⁻⁰¹²³⁴⁵⁶⁷⁸⁹", "-0123456789"))) if power else 0
        for item in group.iter("{*}item"):
            variant = int(item.get("title").split(" v")[1].split()[0])
            value = key["variants"][variant - 1]["problems"][problem]["answers"][name]["value"]
            shown = next(e.text for e in item.iter("{*}varequal"))
            assert Decimal(shown).scaleb(-k) == Decimal(value)  # the key's value, in the question's unit
            low = next(e.text for e in item.iter("{*}vargte"))
            assert lms._survives_canvas(shown, str(Decimal(shown) - Decimal(low)))
    assert any("(in 10⁻²⁷ kg)" in g.findtext(".//{*}mattext") for g in groups)  # the reduced mass, every variant
    rows = list(csv.DictReader((labelled / "key.csv").open(encoding="utf-8")))
    assert all(_shown_unit(r["unit"]) for r in rows) and {r["unit"] for r in rows} >= {"kg·m²", "", "J·s", "kg"}


def test_multiple_choice_options_share_one_scaled_unit_per_question_in_both_lms():
    """Small answers' options read 12.3 × 10⁻⁶ kg·m², one power of ten over all the variants of a
    question (not 0.0000123 kg·m² in one and 4.5e-7 in another); where a variant is numerical, its
    Canvas unit and the options share the power."""
    def item(variant, value, wrong=(), tolerance="1e-7"):
        return lms.Item("disk", "Disk", variant, "q", "I", "inertia", value, "kg·m²", tolerance, wrong)
    chosen = [item(1, "1.23e-5", ("2.46e-5", "6.15e-6", "1.64e-5")), item(2, "4.5e-7", ("9e-7", "2.25e-7", "6e-7"))]
    quiz = ET.fromstring(lms.moodle(chosen, "s"))
    options = [a for q in quiz.iter("question") if q.get("type") == "cloze"
               for _, field in moodle_cloze(q.find("questiontext/text").text)[1] for _, a in field]
    assert len(options) == 8 and all(re.fullmatch(r"\d+(\.\d+)? × 10⁻⁶ kg·m²", o) for o in options), options
    assert "12.3 × 10⁻⁶ kg·m²" in options and "0.45 × 10⁻⁶ kg·m²" in options
    with zipfile.ZipFile(io.BytesIO(canvas.qti(chosen, "T", "s", 1))) as archive:
        _, assessment, _ = qti_package(archive)
    shown = [e.text for e in assessment.iter("{*}mattext") if e.get("texttype") == "text/plain"]
    assert sorted(shown) == sorted(options)
    mixed = [item(1, "1.23e-5", ("2.46e-5", "6.15e-6", "1.64e-5")), item(2, "4.5e-7", tolerance="1e-11")]
    with zipfile.ZipFile(io.BytesIO(canvas.qti(mixed, "T", "s", 1))) as archive:
        _, assessment, _ = qti_package(archive)
    texts = [e.text for e in assessment.iter("{*}mattext")]
    assert any(t.endswith("(in 10⁻⁹ kg·m²)</p>") for t in texts)  # the numerical variant's margin needs 10⁻⁹
    assert "12300 × 10⁻⁹ kg·m²" in texts  # and the other variant's options use it too
    # Moodle: the numerical variant's 1e-11 is below its floor, 1e-8, so the unit is scaled, and to
    # show the largest value between 1 and 1000
    assert lms._exponent(mixed, "moodle") == 6


# --- Moodle grades tiny quantities right (issue 35, item 1) ------------------------------------

def _moodle_interval(answer: float, tolerance: float, rule: str) -> tuple[float, float]:
    """The interval Moodle's numerical grader accepts for an answer with a nominal tolerance, in
    double precision as PHP computes it (precision = 14): qtype_numerical_answer::
    get_tolerance_interval in question/type/numerical/question.php, Moodle 4.5 ("4.5") and before
    ("old")."""
    epsilon = 10.0 ** -14
    widened = tolerance + epsilon * (max(abs(tolerance), abs(answer), epsilon) if rule == "4.5" else max(1, abs(answer)))
    return answer - widened, answer + widened


def _moodle_fields(quiz_path: Path) -> list[tuple[str, str, str]]:
    """(value, tolerance, unit shown after the field) of each NUMERICAL field of a Moodle XML file."""
    quiz = ET.parse(quiz_path).getroot()
    return [re.fullmatch(r".* = \{1:NUMERICAL:=([^:]+):([^}]+)\}\s*(.*)", p).groups()
            for q in quiz.iter("question") if q.get("type") == "cloze"
            for p in re.findall(r"<p>(.*?)</p>", q.find("questiontext/text").text) if "{1:NUMERICAL" in p]


def test_moodle_grades_tiny_answers_right_under_both_of_its_rules(labelled):
    """A diatomic molecule's I ~ 1e-46 kg·m² with its tolerance as it is would be graded by Moodle
    with 1e-28 of slack (1e-14 under older Moodles): 0 and the negation would pass. Each field read
    back through Moodle's rule accepts the answer and 0.9 tolerances off, and refuses 0, the
    negation and 1.1 tolerances off."""
    fields = _moodle_fields(labelled / "moodle.xml")
    assert fields and any(unit.startswith("10⁻") for _, _, unit in fields)  # tiny ones are scaled
    for value, tolerance, unit in fields:
        answer, margin = float(value), float(tolerance)
        for rule in ("4.5", "old"):
            low, high = _moodle_interval(answer, margin, rule)
            accepted = lambda typed: low <= typed <= high
            assert accepted(answer) and accepted(answer + 0.9 * margin) and accepted(answer - 0.9 * margin)
            assert not accepted(answer + 1.1 * margin) and not accepted(answer - 1.1 * margin), (value, tolerance, rule)
            if answer:
                assert not accepted(0.0) and not accepted(-answer), (value, tolerance, rule)
    key = json.loads((labelled / "key.json").read_text())
    inertia = [v["problems"]["diatomic_molecule"]["answers"]["I"]["value"] for v in key["variants"]]
    shown = [f for f in fields if f[2].endswith("kg·m²") and f[2].startswith("10⁻")]
    assert len(shown) == len(inertia)
    k = -int(shown[0][2].split()[0][2:].translate(str.maketrans("⁻⁰¹²³⁴⁵⁶⁷⁸⁹", "-0123456789")))
    assert {f[2] for f in shown} == {shown[0][2]}  # one unit for every variant of the question
    assert sorted(Decimal(f[0]).scaleb(-k) for f in shown) == sorted(map(Decimal, inertia))


def test_moodle_scales_a_question_whose_tolerance_falls_below_its_floor():
    tiny = lms.Item("p", "P", 1, "q", "I", "inertia", "5.87e-46", "kg·m²", "1e-48")
    html = ET.fromstring(lms.moodle([tiny], "s")).find("question[@type='cloze']/questiontext/text").text
    assert "{1:NUMERICAL:=587:1} 10⁻⁴⁸ kg·m²" in html
    plain = lms.Item("p", "P", 1, "q", "I", "inertia", "2.13", "kg·m²", "0.01")
    assert "{1:NUMERICAL:=2.13:0.01} kg·m²" in lms.moodle([plain], "s")
    with pytest.raises(InputError, match="finer than Moodle can compare"):
        lms.check([lms.Item("p", "P", 1, "q", "I", "inertia", "2.13", "kg·m²", "1e-9")], "moodle")


def test_a_problem_whose_answers_are_all_general_results_is_said_to_be_left_out_of_the_lms(tmp_path):
    """keplers_second_law's answers are expressions: no LMS can grade them, so the quiz has one
    problem fewer than the worksheet. derive says so on the terminal and in key.json (issue 35)."""
    out = tmp_path / "out"
    done = run_derive("sheet", "keplers_second_law", "string_wrapped_disk", "--variants", "2", "--to", "moodle",
                      "--out", str(out))
    assert done.returncode == 0, done.stderr
    assert "derive: warning: keplers_second_law: the whole problem is not in the Moodle and Canvas exports: every " \
           "answer is a general result" in done.stderr
    key = json.loads((out / "key.json").read_text())
    for variant in key["variants"]:
        assert all("cannot grade as a number" in a["lms"] for a in variant["problems"]["keplers_second_law"]["answers"].values())
        assert all("lms" not in a for a in variant["problems"]["string_wrapped_disk"]["answers"].values())
    categories = [q.findtext("category/text") for q in ET.parse(out / "moodle.xml").getroot().iter("question")
                  if q.get("type") == "category"]
    assert [c.rsplit("/", 1)[1] for c in categories] == ["string_wrapped_disk"]


@pytest.mark.parametrize("tolerance, reason", [
    ("0.0001", r"ask\.I\.tolerance: 0\.0001 gives ±0\.0001, narrower than the digits shown: 0\.\d+ is rounded by up "
               r"to 0\.0005; give a wider tolerance"),
    ("0.001%", r"ask\.I\.tolerance: 0\.001% gives ±[0-9.E-]+, narrower than the digits shown"),
    ("5000", r"ask\.I\.tolerance: 5000 gives ±5000, as wide as the answer: zero and the wrong sign would pass"),
])
def test_a_tolerance_that_would_grade_unfairly_is_refused_in_one_line(tolerance, reason, tmp_path):
    """A tolerance narrower than the rounding of the digits shown marks a right answer wrong; one as
    wide as the answer marks zero and the wrong sign right (issue 35, item 3)."""
    problem = tmp_path / "p.yaml"
    problem.write_text(load("rod_endpoint").path.read_text().replace(
        "unit: kg*m^2}", f"unit: kg*m^2, tolerance: '{tolerance}'}}"))
    done = run_derive("sheet", str(problem), "--to", "", "--out", str(tmp_path / "out"))
    assert done.returncode == 2 and not (tmp_path / "out").exists()
    (line,) = done.stderr.strip().splitlines()[-1:]
    assert re.fullmatch(rf"derive: error: {re.escape(str(problem))}: {reason}.*", line), line


# --- what Moodle reads from what students type (docs/lms.md, issue 35 item 4) -------------------

def _moodle_reads(response: str, decsep: str = ".", thousandssep: str = ",") -> float | None:
    """qtype_numerical_answer_processor::apply_units (question/type/numerical/questiontype.php) for a
    field without units: its regex, thousands separators stripped, the text after the number dropped;
    None where Moodle reads no number."""
    number = (rf"([+-]?[{re.escape(thousandssep)}\d]*)(?:{re.escape(decsep)}(\d*))?"
              r"(?:(?:e|E|(?:x|\*|×)10(?:\^|\*\*))([+-]?\d+))?")
    match = re.match(number, response)
    before, decimals, exponent = match.groups()
    before = before.replace(thousandssep, "")
    if not before.strip("+-") and not decimals:
        return None
    return float(f"{before or '0'}.{decimals or ''}" + (f"e{exponent}" if exponent else ""))


@pytest.mark.parametrize("typed, read", [
    ("2.13", 2.13), ("2,13", 213.0), ("\u22122.13", None), ("2.13 N", 2.13), ("213 cm", 213.0),
    ("1.2e-5", 1.2e-5), ("1.2x10^-5", 1.2e-5), ("1.2×10^-5", 1.2e-5), ("1.2*10**-5", 1.2e-5), ("", None),
])
def test_docs_say_what_moodle_reads_from_what_students_type(typed, read):
    assert _moodle_reads(typed) == read
    table = (Path(__file__).parent.parent / "docs" / "lms.md").read_text()
    shown = {"2,13": "read as **213**", "\u22122.13": "not a number, graded wrong", "2.13 N": "read as 2.13",
             "213 cm": "read as **213**", "1.2e-5": "read as 1.2 × 10⁻⁵", "": "no marks for it"}
    if typed in shown:
        assert shown[typed] in table
