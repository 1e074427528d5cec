"""derive.figure: every library problem draws itself as a TikZ figure that compiles, from its own
geometry, the same bytes each time; the figures reach the worksheet, solutions and handout."""
import hashlib
import os
import re
import subprocess
import sys

import pytest

from conftest import ROOT, copy_library, run_derive
from derive import export, figure, library, problem, render, sheet

COORDINATE = re.compile(r"\((-?\d+(?:\.\d+)?),(-?\d+(?:\.\d+)?)\)")


@pytest.fixture(scope="module")
def problems():
    return [problem.load(path) for path in library.problem_files()]


@pytest.fixture(scope="module")
def figures(problems):
    return {p.id: figure.tikz(p) for p in problems}


def test_every_library_problem_has_a_figure(problems, figures):
    assert len(problems) >= 33
    assert {name for name, drawn in figures.items() if drawn is None} == set()
    for name, drawn in figures.items():
        assert drawn.startswith("\\begin{tikzpicture}[") and drawn.endswith("\\end{tikzpicture}"), name
        assert "if problem" not in drawn and "nan" not in drawn and "inf" not in drawn, name


def test_figures_keep_to_a_fixed_size(figures):
    for name, drawn in figures.items():
        points = [(float(x), float(y)) for x, y in COORDINATE.findall(drawn)]
        width = max(x for x, _ in points) - min(x for x, _ in points)
        height = max(y for _, y in points) - min(y for _, y in points)
        assert 0.5 < width <= 6.5 and height <= 6.5, (name, width, height)


def test_an_incline_has_its_triangle_and_the_angle_labelled(figures):
    drawn = figures["rolling_incline"]
    assert re.search(r"\\draw\[fill=gray!10\] \(0,0\) -- \([\d.]+,0\) -- \(0,[\d.]+\) -- cycle;", drawn)
    assert "{$\\theta$}" in drawn and "{$H$}" in drawn
    assert "$M\\,g$" in drawn  # the sphere's weight


def test_a_pinned_body_hangs_from_a_pivot_and_an_axle_is_a_circled_dot(figures):
    pendulum = figures["compound_pendulum"]
    pivot = re.search(r"\\draw\[fill=gray!30\] \((-?[\d.]+),(-?[\d.]+)\) -- .* -- cycle;", pendulum)
    assert pivot and "pattern=north east lines" in pendulum
    assert f"\\draw[fill=white] ({pivot[1]},{pivot[2]}) circle" in pendulum  # the pin at the triangle's apex
    assert "{$R_{cm}$}" in pendulum or "{$Rcm$}" in pendulum
    for free in ("rolling_incline", "kepler_orbit", "rod_midpoint"):
        assert "\\draw[fill=gray!30]" not in figures[free], free
    assert "circle (0.1); \\fill (0,0) circle (0.035);" in figures["string_wrapped_disk"]  # the axle


def test_a_wound_string_leaves_the_rim_on_its_side_down_to_the_block(tmp_path, figures):
    def string(drawn):
        radius = float(re.search(r"\\draw\[body\] \(0,0\) circle \(([\d.]+)\);", drawn)[1])
        line = re.search(r"\\draw\[thick\] \((-?[\d.]+),0\) -- \((-?[\d.]+),(-?[\d.]+)\);", drawn)
        assert line, drawn
        assert float(line[1]) == float(line[2]) and float(line[3]) < -radius  # straight down, below the disk
        return float(line[1]) / radius

    drawn = figures["string_wrapped_disk"]
    assert string(drawn) == 1  # tangent to the rim, on the right
    assert "{$T$}" in drawn and "{$m\\,g$}" in drawn  # the tension and the block's weight
    library_copy = copy_library(tmp_path)
    path = library_copy / "torque" / "string_wrapped_disk.yaml"
    path.write_text(path.read_text().replace("side: right", "side: left"))
    assert string(figure.tikz(problem.load(path))) == -1


def test_scene_systems_draw_their_own_geometry(figures):
    assert "ellipse" in figures["kepler_orbit"] and "{$r$}" in figures["kepler_orbit"]
    assert "{$\\theta$}" in figures["top_precession_exact"] and "$m\\,g$" in figures["top_precession_exact"]
    collision = figures["sticky_impact_pivoted"]
    assert "[velocity]" in collision and "{$b$}" in collision and "{$v$}" in collision
    assert "{$F$}" in figures["tugged_spool"] and "{$r$}" in figures["tugged_spool"]
    assert "{$\\alpha$}" in figures["rigid_body_L"] and "\\vec L" in figures["rigid_body_L"]


def test_sizes_follow_the_parameters(tmp_path):
    """A steeper incline draws a taller triangle (the middle of the angle's range, clamped)."""
    library_copy = copy_library(tmp_path)
    path = library_copy / "rolling" / "rolling_incline.yaml"

    def height(low, high):
        path.write_text(re.sub(r"theta: \{(.*?)range: \[[^\]]*\]", rf"theta: {{\1range: [{low}, {high}]",
                               (ROOT / "problems" / "rolling" / "rolling_incline.yaml").read_text()))
        drawn = figure.tikz(problem.load(path))
        return float(re.search(r"-- \(0,([\d.]+)\) -- cycle;", drawn)[1])

    assert height(0.3, 0.4) < height(0.6, 0.7) < height(1.0, 1.2)
    assert height(1.3, 1.5) == height(1.0, 1.2)  # clamped: the figure stays legible


def test_same_problem_same_bytes_in_any_process(problems, figures):
    assert {p.id: figure.tikz(p) for p in problems} == figures
    digest = hashlib.sha256("".join(figures[p.id] for p in problems).encode()).hexdigest()
    code = ("import hashlib; from derive import figure, library, problem; print(hashlib.sha256(''.join("
            "figure.tikz(problem.load(p)) for p in library.problem_files()).encode()).hexdigest())")
    for seed in ("1", "2"):
        done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, cwd=ROOT,
                              env={**os.environ, "PYTHONHASHSEED": seed}, timeout=120)
        assert done.stdout.strip() == digest, done.stderr


SPECIAL = """\
id: special_names
title: Names with LaTeX specials
parameters:
  H: {meaning: "height & width: 100% of #1, $5 {a_b} ~x^2 \\\\ relax", unit: m, range: [0.5, 3]}
  g: {meaning: "gravity % \\\\ & $", unit: m/s^2, value: 9.81}
scene:
  surfaces:
    my_ramp: {incline: {height: H}}
  bodies:
    big_block: {shape: point, on: my_ramp, contact: sliding}
    the_ball_2: {shape: sphere, on: my_ramp, contact: rolling}
  loads:
    - gravity: g
ask:
  v: {meaning: "speed & 100% #1", of: the_ball_2.speed_at_bottom, unit: m/s}
question: |
  Released from rest at height {{ H }}.
"""


@pytest.fixture(scope="module")
def special():
    return problem.parse(SPECIAL, ROOT / "special_names.yaml")


def test_names_with_latex_specials_are_escaped(special):
    drawn = figure.tikz(special)
    assert "big\\_block" in drawn and "the\\_ball\\_2" in drawn
    assert "100%" not in drawn and "#1" not in drawn


def test_every_figure_compiles(tmp_path, problems, figures, special):
    """One document with the project's preamble and every figure: it compiles, and the labels show."""
    body = "\n\n".join(f"\\section*{{{render.tex_escape(p.id)}}}\n{figures[p.id]}" for p in problems)
    tex = tmp_path / "figures.tex"
    tex.write_text(render.render("preamble.tex.j2") + "\\begin{document}\n" + body + "\n\n"
                   + figure.tikz(special) + "\n\\end{document}\n", encoding="utf-8")
    pdf = export.pdf(tex)
    text = subprocess.run(["pdftotext", str(pdf), "-"], capture_output=True, text=True, check=True).stdout
    assert "big_block" in text and "the_ball_2" in text and "hoop" in text
    assert text.count("rolling_incline") == 1


def test_the_documents_include_the_figures(tmp_path):
    built = sheet.build("demo", variants=2, seed=3, out_dir=str(tmp_path / "demo"), formats=set())
    folder = built[0].parent
    worksheet = (folder / "worksheet.tex").read_text()
    solutions = (folder / "solutions.tex").read_text()
    count = len(sheet.load_set("demo").problems)
    assert worksheet.count("\\begin{tikzpicture}") == 2 * count
    assert solutions.count("\\begin{tikzpicture}") == count
    assert figure.tikz(problem.load("string_wrapped_disk")) in worksheet
    assert "\\usetikzlibrary{" in worksheet


def test_the_handout_includes_the_figure(tmp_path):
    done = run_derive("handout", "tugged_spool", "--out", str(tmp_path / "h"))
    assert done.returncode == 0, done.stderr
    tex = (tmp_path / "h" / "tugged_spool.tex").read_text()
    assert figure.tikz(problem.load("tugged_spool")) in tex
    assert (tmp_path / "h" / "tugged_spool.pdf").read_bytes().startswith(b"%PDF")
