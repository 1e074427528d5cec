"""`derive sheet`: the documents, the keys, determinism, and builds that fail safely."""
import json
import re
import subprocess
from pathlib import PurePosixPath

import lxml.html
import pytest
import sympy

from conftest import ROOT, copy_library, image_kind, run_derive


@pytest.fixture(scope="module")
def demo(tmp_path_factory):
    out = tmp_path_factory.mktemp("sheet") / "demo"
    done = run_derive("sheet", "demo", "--variants", "3", "--seed", "5", "--out", str(out))
    assert done.returncode == 0, done.stderr
    return out


def test_documents_exist(demo):
    for name in ("worksheet", "solutions", "key"):
        assert (demo / f"{name}.tex").stat().st_size > 0
        assert (demo / f"{name}.pdf").read_bytes().startswith(b"%PDF")
    assert "<math" in (demo / "worksheet.html").read_text()
    assert (demo / "key.csv").read_text().startswith("variant,problem,answer,value,tolerance,unit,meaning")


def test_html_shows_each_problems_figure_from_an_svg_file_beside_it(demo):
    page = lxml.html.parse(str(demo / "worksheet.html")).getroot()
    sources = [img.get("src") for img in page.iter("img")]
    assert len(sources) == 3 * 3  # each problem of each variant
    for source in sources:
        path = PurePosixPath(source)
        assert not path.is_absolute() and ":" not in source and ".." not in path.parts, source
        assert image_kind((demo / path).read_bytes()) == "svg"
    # each figure compiled once: one file per problem, whatever the variants, and nothing else
    assert sorted(p.name for p in (demo / "figures").iterdir()) == sorted({PurePosixPath(s).name for s in sources})
    assert len(set(sources)) == 3
    for center in page.find_class("center"):  # no empty placeholder where a figure was left out
        assert center.text_content().strip() or center.find(".//img") is not None, lxml.html.tostring(center)


def pdf_text(path):
    return subprocess.run(["pdftotext", "-layout", str(path), "-"], capture_output=True, text=True, check=True).stdout


def test_answer_key_pdf_has_every_variants_answers(demo):
    key = json.loads((demo / "key.json").read_text())
    text = pdf_text(demo / "key.pdf").replace("−", "-")
    assert len(key["variants"]) == 3
    values = [a["value"] for v in key["variants"] for p in v["problems"].values() for a in p["answers"].values()]
    assert len(values) == 3 * (1 + 3 + 2)
    for value in values:
        assert value in text
    assert "Tolerance" in text  # each answer with its tolerance, as the CSV and JSON keys give it
    rows = (demo / "key.tex").read_text().splitlines()
    for variant in key["variants"]:
        for problem_id, problem in variant["problems"].items():
            for answer in problem["answers"].values():
                row = next(r for r in rows if r.startswith(f"{variant['variant']} & {problem_id.replace('_', chr(92) + '_')}")
                           and f"${answer['value'].split('e')[0]}" in r)
                assert f"& ${answer['tolerance'].lower().split('e')[0]}" in row, row


def test_worksheet_pdf_shows_each_variants_numbers(demo):
    key = json.loads((demo / "key.json").read_text())
    text = pdf_text(demo / "worksheet.pdf")
    for variant in key["variants"]:
        m = variant["problems"]["string_wrapped_disk"]["parameters"]["m"]["value"]
        assert f"{m} kg" in text


def test_units_are_siunitx_in_the_pdfs_and_plain_math_where_pandoc_and_mathjax_read_them(demo):
    """siunitx sets the PDFs' units; pandoc's texmath and MathJax read none of it, so the HTML and
    the LMS files get the plain form (units.latex_unit), typeset as math."""
    for name in ("worksheet", "solutions", "key"):
        tex = (demo / f"{name}.tex").read_text()
        assert "\\usepackage{siunitx}" in tex and "\\unit{" in tex and "\\,\\mathrm{" not in tex, name
    assert "g = 9.81 m/s2" in pdf_text(demo / "solutions.pdf")  # \unit{m/s^{2}} as siunitx sets it
    html = (demo / "worksheet.html").read_text()
    assert "\\unit" not in html and "\\,\\mathrm{kg}</annotation>" in html  # MathML, from plain math


def test_each_problem_and_its_figure_are_one_box_that_no_page_break_splits(demo):
    tex = (demo / "worksheet.tex").read_text()
    items = tex.split("\\item ")[1:]
    assert len(items) == 3 * 3
    for item in items:
        box = item.split("\\end{minipage}")[0]
        assert item.startswith("\\begin{minipage}[t]{\\linewidth}") and "\\usebox{\\derivefigure" in box


def _pages(path) -> int:
    info = subprocess.run(["pdfinfo", str(path)], capture_output=True, text=True, check=True).stdout
    return int(next(line.split()[1] for line in info.splitlines() if line.startswith("Pages:")))


def test_each_student_gets_a_worksheet_of_their_own_variant(demo):
    key = json.loads((demo / "key.json").read_text())
    assert sum(_pages(demo / f"worksheet-{n}.pdf") for n in (1, 2, 3)) == _pages(demo / "worksheet.pdf")
    for variant in key["variants"]:
        text = pdf_text(demo / f"worksheet-{variant['variant']}.pdf")
        assert f"Variant {variant['variant']}" in text
        for other in key["variants"]:
            m = other["problems"]["string_wrapped_disk"]["parameters"]["m"]["value"]
            assert (f"{m} kg" in text) == (other is variant) or m == variant["problems"]["string_wrapped_disk"][
                "parameters"]["m"]["value"]


def test_solutions_show_both_routes_and_the_numbers(demo):
    text = pdf_text(demo / "solutions.pdf")
    assert "Lagrange" in text and "Newton–Euler" in text and "Variant 3" in text


def test_same_seed_same_bytes_other_seed_other_numbers(tmp_path):
    def build(seed, name):
        out = tmp_path / name
        done = run_derive("sheet", "demo", "--seed", str(seed), "--variants", "2", "--to", "", "--out", str(out))
        assert done.returncode == 0, done.stderr
        return out

    first, again, other = build(11, "a"), build(11, "b"), build(12, "c")
    for name in ("worksheet.tex", "solutions.tex", "key.tex", "key.csv", "key.json"):
        assert (first / name).read_bytes() == (again / name).read_bytes(), name
    assert (first / "key.csv").read_text() != (other / "key.csv").read_text()


def test_a_failed_build_leaves_the_previous_one_intact(tmp_path):
    library = copy_library(tmp_path)
    out = tmp_path / "out"
    assert run_derive("sheet", "demo", "--to", "", "--out", str(out), library=library).returncode == 0
    before = {p.name: p.read_bytes() for p in out.iterdir()}
    broken = library / "torque" / "compound_pendulum.yaml"
    broken.write_text(broken.read_text().replace("mass: M,", "mass: -M,"))
    done = run_derive("sheet", "demo", "--to", "", "--out", str(out), library=library)
    assert done.returncode == 2 and "compound_pendulum.yaml: scene.bodies.pendulum.mass" in done.stderr
    assert {p.name: p.read_bytes() for p in out.iterdir()} == before
    assert [p.name for p in tmp_path.iterdir() if p.name.startswith(".")] == []


def test_the_same_build_twice_gives_the_same_pdfs(demo, tmp_path):
    again = tmp_path / "again"
    done = run_derive("sheet", "demo", "--variants", "3", "--seed", "5", "--out", str(again))
    assert done.returncode == 0, done.stderr
    pdfs = sorted(p.name for p in demo.glob("*.pdf"))
    assert len(pdfs) == 3 + 3  # the whole worksheet, the solutions, the key, and each variant's worksheet
    for name in pdfs:
        assert (again / name).read_bytes() == (demo / name).read_bytes(), name


def test_a_build_leaves_nothing_frozen_out_of_the_collector(tmp_path):
    """A build freezes its derivations (gc.freeze) for its per-variant work, and unfreezes them:
    a notebook that builds again and again collects the cycles of the builds before."""
    import gc

    from derive.publishing import worksheets

    worksheets.build("demo", variants=2, out_dir=str(tmp_path / "out"), formats=frozenset())
    assert gc.get_freeze_count() == 0


def test_a_set_may_leave_room_to_answer_under_each_problem(tmp_path):
    week = tmp_path / "week.yaml"
    week.write_text("title: T\nproblems: [rod_endpoint, string_wrapped_disk]\nanswer_space: 6cm\n")
    done = run_derive("sheet", str(week), "--variants", "2", "--to", "pdf", "--out", str(tmp_path / "out"))
    assert done.returncode == 0, done.stderr
    out = tmp_path / "out"
    assert (out / "worksheet.tex").read_text().count("\\vspace{6cm}") == 4
    # each student's own worksheet: the last one too, though nothing follows its answer space on its page
    assert _pages(out / "worksheet-1.pdf") + _pages(out / "worksheet-2.pdf") == _pages(out / "worksheet.pdf")
    assert "Variant 2" in pdf_text(out / "worksheet-2.pdf") and "Variant 2" not in pdf_text(out / "worksheet-1.pdf")


def test_worked_solutions_number_their_equations_and_say_which_the_solving_uses(demo):
    """Issue 15: equations numbered through a problem, and each route's solving step names the
    equations it solves ("from (5)–(10)"), each of them one the page numbers."""
    import re
    tex = (demo / "solutions.tex").read_text()
    tags = [int(n) for n in re.findall(r"\\tag\{(\d+)\}", tex)]
    assert tags[:3] == [1, 2, 3] and 1 in tags
    referred = re.findall(r"Solving in the reference configuration, at rest, from ([()0-9–, and]+):", tex)
    assert len(referred) >= 2  # each route of the string wrapped around a disk, at least
    for reference in referred:
        for first, last in re.findall(r"\((\d+)\)(?:–\((\d+)\))?", reference):
            assert int(first) in tags and (not last or int(last) in tags)


def test_an_angle_in_degrees_has_no_space_before_its_sign(tmp_path):
    """30°, as SI writes it, in the question and the worked solutions (a trial saw "18 °"); other
    units keep their thin space."""
    text = (ROOT / "problems/torque/tugged_spool.yaml").read_text()
    text = text.replace("theta: {meaning: angle of the string above the horizontal, unit: rad, range: [0.1, 1.2]",
                        "theta: {meaning: angle of the string above the horizontal, unit: deg, range: [6, 60]")
    assert "unit: deg" in text
    (tmp_path / "spool.yaml").write_text(text)
    done = run_derive("sheet", str(tmp_path / "spool.yaml"), "--to", "", "--out", str(tmp_path / "out"))
    assert done.returncode == 0, done.stderr
    for name in ("worksheet.tex", "solutions.tex"):
        tex = (tmp_path / "out" / name).read_text()
        assert re.search(r"(\$|= )[0-9.]+\\unit\{\\degree\}\$", tex) and "\\,\\unit{\\degree}" not in tex, name
        assert re.search(r"[0-9]\\,\\unit\{N\}", tex), name


def test_a_root_is_chosen_by_the_parameters_range_in_si(tmp_path):
    """theta_c of a spool whose theta is drawn in degrees: the roots of a(theta) are radians and the
    range [6, 60] deg is compared as [pi/30, pi/3] (it was compared as [6, 60], and took the root
    2*pi - acos(r/R) there for one inside it, or refused both)."""
    from derive.solution.answers import Solution
    from derive.language.problem import load

    text = (ROOT / "problems/torque/tugged_spool.yaml").read_text().replace(
        "unit: rad, range: [0.1, 1.2]", "unit: deg, range: [6, 60]")
    (tmp_path / "spool.yaml").write_text(text)
    problem = load(str(tmp_path / "spool.yaml"))
    r, R = (problem.parameters[n].symbol for n in ("r", "R"))
    assert Solution(problem).expression("theta_c") == sympy.acos(r / R)


def test_a_tilt_in_degrees_is_checked_against_its_limits_in_si(tmp_path):
    """A rod on bearings tilted 12 to 80 deg from its shaft is inside (0, pi): it was refused, its
    range compared as 12 to 80 against pi."""
    text = (ROOT / "problems/angular_momentum/rigid_body_L.yaml").read_text().replace(
        "unit: rad, range: [0.2, 1.4]", "unit: deg, range: [12, 80]")
    assert "unit: deg" in text
    (tmp_path / "rod.yaml").write_text(text)
    done = run_derive("solve", str(tmp_path / "rod.yaml"))
    assert done.returncode == 0, done.stderr


def test_sources_and_corrections_to_the_notes_are_the_instructors(tmp_path):
    """"Correction to the notes (§6.4.1)" and "Source: lecture notes §..." reached the students in the
    worked solutions and the LMS feedback (issue 37, item 5); they are in the instructor's key."""
    done = run_derive("sheet", "sticky_impact_pivoted", "string_wrapped_disk", "--to", "", "--out", str(tmp_path / "o"))
    assert done.returncode == 0, done.stderr
    solutions, key = ((tmp_path / "o" / name).read_text() for name in ("solutions.tex", "key.tex"))
    assert "Correction" not in solutions and "Source" not in solutions and "lecture notes" not in solutions
    assert "Sources and corrections to the notes" in key and "Correction} (§6.4.1" in key
    assert "lecture notes §4.1" in key
