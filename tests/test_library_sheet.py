"""Every problem of the lecture notes renders and compiles, and its key equals `derive solve` at its
parameters (the textbook setups of the library: see `everything`)."""
import json
import subprocess
from pathlib import Path

import pytest

from conftest import ROOT, SHARED, copy_library, notes_files, run_derive, textbook_files
from derive.publishing import export, report
from derive.language import problem


#: The sheets below read and fill the run's shared derivation cache (conftest.derived), uncapped: a problem
#: another test has derived is not derived again (an entry loads byte-identical to a fresh derivation,
#: tests/test_derivation_cache.py), which saved about three minutes of one core.
SHARED_CACHE = {"DERIVE_CACHE_DIR": str(SHARED), "DERIVE_CACHE_MB": "100000"}


@pytest.fixture(scope="module")
def everything(tmp_path_factory):
    folder = tmp_path_factory.mktemp("all")
    lib = copy_library(folder)
    # The lecture notes' problems; the textbook setups' sheet (the rest of the library, in minutes of one core:
    # this sheet cannot be shared between workers) is the slow tier's (`textbook_sheet`).
    ids = [p.stem for p in notes_files()]
    (lib / "sets" / "everything.yaml").write_text(f"title: Every problem\nproblems: [{', '.join(ids)}]\nseed: 9\n")
    out = folder / "out"
    done = run_derive("sheet", "everything", "--variants", "1", "--out", str(out), library=lib, env=SHARED_CACHE)
    assert done.returncode == 0, done.stderr[-2000:]
    return ids, out


def test_every_problem_renders_and_compiles(everything):
    ids, out = everything
    text = subprocess.run(["pdftotext", str(out / "worksheet.pdf"), "-"], capture_output=True, text=True).stdout
    text = text.replace("\u2019", "'")  # LaTeX typesets ' as a curly apostrophe
    for problem_id in ids:
        title = problem.load(problem_id).title
        assert title.split()[0] in text
    for name in ("worksheet", "solutions", "key"):
        assert (out / f"{name}.pdf").read_bytes().startswith(b"%PDF")


def test_the_key_equals_derive_solve_at_its_parameters(everything):
    ids, out = everything
    key = json.loads((out / "key.json").read_text())
    (variant,) = key["variants"]
    for problem_id, entry in variant["problems"].items():
        p = problem.load(problem_id)
        given = {n: v["value"] for n, v in entry["parameters"].items() if p.parameters[n].range is not None}
        for name, answer in entry["answers"].items():
            digits = p.asks[name].sig_figs or 3
            solved = report.solve(p, given, digits)["answers"][name]["value"]
            assert answer["value"] == solved, (problem_id, name)


@pytest.fixture(scope="module")
def textbook_sheet(tmp_path_factory):
    """The library's textbook setups as one set, one variant, as TeX (the test compiles what it reads; their
    PDFs, compiled again, had taken a minute of one core): its folder."""
    folder = tmp_path_factory.mktemp("textbook")
    lib = copy_library(folder)
    ids = [p.stem for p in textbook_files() if p.parent.parent == ROOT / "problems"]  # not tests/textbook's
    (lib / "sets" / "textbook.yaml").write_text(f"title: Textbook setups\nproblems: [{', '.join(ids)}]\nseed: 9\n")
    out = folder / "out"
    done = run_derive("sheet", "textbook", "--variants", "1", "--to", "", "--out", str(out), library=lib, timeout=3600,
                      env=SHARED_CACHE)
    assert done.returncode == 0, done.stderr[-2000:]
    return out


#: How far a line may run past the margin (pt) before the test calls it running off the page: a
#: hair, as LaTeX's own \hfuzz (0.1 pt) is, and the few points a word of a citation in the key
#: may stick out.
FUZZ = 2.0


def _too_wide(lines: list[str]) -> list[str]:
    return [line for line in lines if float(line.split("(")[1].split("pt")[0]) > FUZZ]


@pytest.mark.slow
def test_no_line_of_the_textbook_setups_worked_solutions_runs_off_the_page(textbook_sheet, tmp_path):
    """Issue 39: the textbook setups' worked solutions had 95 lines running off the page (up to 3 m
    wide: a constraint's long left side, a tension's fraction, the torque of a cord in a sentence).
    Long sides break between terms, a row still too wide is set smaller (typesetting.fit), a long
    piece of math in a sentence goes on a line of its own."""
    for name in ("solutions", "key"):
        assert _too_wide(_overfull(textbook_sheet / f"{name}.tex", tmp_path)) == [], name


def _overfull(tex: Path, folder: Path) -> list[str]:
    """The lines a LaTeX run reports as running off the page (Overfull \\hbox), for `tex` compiled
    afresh in `folder` by the engine derive uses for it."""
    text = tex.read_text()
    (folder / tex.name).write_text(text)
    subprocess.run([export.engine(text), "-interaction=nonstopmode", tex.name], cwd=folder, capture_output=True,
                   timeout=300)
    log = (folder / tex.with_suffix(".log").name).read_text(errors="replace")
    return [line for line in log.splitlines() if line.startswith("Overfull \\hbox")]


def test_no_line_of_the_library_documents_runs_off_the_page(everything, tmp_path):
    """Issue 15: no overfull box in the logs of the worksheet, solutions and key of the whole
    library: long sums broken across lines (derive.text.typesetting), meanings in narrow boxes beside
    their equations, paragraphs of text and math allowed to stretch."""
    _, out = everything
    for name in ("worksheet", "solutions", "key"):
        assert _overfull(out / f"{name}.tex", tmp_path) == [], name


@pytest.mark.parametrize("problem_id", ["skid_to_roll", "tugged_spool", "kepler_orbit", "restitution_rod",
                                        "string_wrapped_disk", "compound_pendulum"])
def test_no_line_of_a_handout_runs_off_the_page(problem_id, tmp_path):
    done = run_derive("handout", problem_id, "--out", str(tmp_path / "h"), "--progress", "none")
    assert done.returncode == 0, done.stderr
    assert _overfull(tmp_path / "h" / f"{problem_id}.tex", tmp_path) == []


def test_a_handouts_pages_are_kept_as_images_for_a_reviewer(tmp_path):
    """Issue 15: the pages of one handout, rendered to PNG (pdftoppm) in the test's folder (its path
    is printed) so that a reviewer can look at them; each page has ink on it."""
    done = run_derive("handout", "string_wrapped_disk", "--out", str(tmp_path / "h"), "--progress", "none")
    assert done.returncode == 0, done.stderr
    subprocess.run(["pdftoppm", "-png", "-r", "60", str(tmp_path / "h" / "string_wrapped_disk.pdf"),
                    str(tmp_path / "page")], check=True, timeout=120)
    pages = sorted(tmp_path.glob("page-*.png"))
    print(f"the handout's pages as images: {', '.join(map(str, pages))}")
    assert len(pages) >= 2
    assert all(page.stat().st_size > 5000 for page in pages)  # a blank page compresses to far less


def test_no_asked_magnitude_of_the_library_shows_a_minus_sign(everything):
    """Issue 37: a quantity with a direction is graded as its magnitude, its direction in words; only
    an ask whose question states its sign convention (sign:) may be negative."""
    from derive.model.directions import directional

    ids, out = everything
    key = json.loads((out / "key.json").read_text())
    (variant,) = key["variants"]
    for problem_id, entry in variant["problems"].items():
        p = problem.load(problem_id)
        for name, answer in entry["answers"].items():
            ask = p.asks[name]
            if directional(ask.quantity) and not ask.sign and not ask.zero_for and answer["value"] is not None:
                assert not answer["value"].startswith("-"), (problem_id, name, answer["value"])
                assert "direction" in answer, (problem_id, name)


def test_a_handouts_long_source_wraps_within_the_page(tmp_path):
    """A newcomer's handout set its source (a book, a chapter and the closed form it prints) on one line
    off the page: the title block's tabular does not wrap, and LaTeX reports no overfull box for it.
    Measured on the PDF: every word of the first page lies within the paper."""
    import re

    from conftest import textbook

    source = textbook("rod_disk_clock_pendulum")
    done = run_derive("handout", str(source), "--out", str(tmp_path / "h"), "--progress", "none")
    assert done.returncode == 0, done.stderr
    (pdf,) = (tmp_path / "h").glob("*.pdf")
    html = subprocess.run(["pdftotext", "-bbox", "-f", "1", "-l", "1", str(pdf), "-"], capture_output=True, text=True,
                          check=True).stdout
    width = float(re.search(r'<page width="([\d.]+)"', html)[1])
    right = [float(x) for x in re.findall(r'xMax="([\d.]+)"', html)]
    assert right and max(right) < width - 36, (max(right), width)  # inside the paper, with a margin
    assert _overfull(pdf.with_suffix(".tex"), tmp_path) == []  # nor wider than the tabular's column
