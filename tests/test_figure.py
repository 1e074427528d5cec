"""derive.publishing.figure: every library problem draws itself as a TikZ figure that compiles, from its own
geometry, the same bytes each time; the figures reach the worksheet, solutions and handout."""
import hashlib
import math
import os
import re
import subprocess
import sys

import pytest
import sympy as sp

from conftest import ROOT, copy_library, run_derive, textbook
from derive.text.latex import tex_escape
from derive.publishing import export, figure, render, worksheets
from derive.core import library
from derive.language import problem, problem_sets
from derive.publishing.figure.canvas import _f, _pt

COORDINATE = re.compile(r"\((-?\d+(?:\.\d+)?),(-?\d+(?:\.\d+)?)\)")


@pytest.fixture(scope="module")
def problems():
    return [problem.load(path) for path in library.problem_files()]


@pytest.fixture(scope="module")
def figures(problems):
    return {p.id: figure.tikz(p) for p in problems}


def test_every_library_problem_has_a_figure(problems, figures):
    assert len(problems) >= 33
    assert [name for name, drawn in figures.items() if drawn is None] == []
    for name, drawn in figures.items():
        assert drawn.startswith("\\begin{tikzpicture}[") and drawn.endswith("\\end{tikzpicture}"), name
        assert "if problem" not in drawn and "nan" not in drawn and "inf" not in drawn, name


def test_figures_keep_to_a_fixed_size(figures):
    for name, drawn in figures.items():
        if drawn is None:
            continue
        points = [(float(x), float(y)) for x, y in COORDINATE.findall(drawn)]
        width = max(x for x, _ in points) - min(x for x, _ in points)
        height = max(y for _, y in points) - min(y for _, y in points)
        assert 0.5 < width <= 6.5 and height <= 6.5, (name, width, height)


def parameter_middle(p, name):
    """A parameter at the middle of its range (or its value), as the figures draw it."""
    given = p.parameters[name]
    return float(given.value if given.range is None else (given.range[0] + given.range[1]) / 2)


POINT = r"\((-?[\d.]+),(-?[\d.]+)\)"


def test_a_ball_bounces_off_the_floor_drawn_under_it_on_its_path(problems, figures):
    """The ball touches the floor where it strikes it (the red dot under its center), its
    velocity an arrow onto it along the path the file gives (theta from the vertical), marked."""
    for name in ("ball_bounces_then_flies", "sphere_bounces_gripping", "sphere_bounces_sliding"):
        p = next(q for q in problems if q.id == name)
        drawn = figures[name]
        floor = re.search(rf"\\fill\[pattern=north east lines\] {POINT} rectangle {POINT};", drawn)
        x0, x1, level = float(floor[1]), float(floor[3]), float(floor[4])
        ball = re.search(rf"\\shade\[ball color=gray!35\] {POINT} circle \(([\d.]+)\);", drawn)
        center, radius = (float(ball[1]), float(ball[2])), float(ball[3])
        assert x0 + 1 < center[0] < x1 - 1 and abs(center[1] - radius - level) <= TOLERANCE, name  # on the floor
        assert f"\\fill[red!70!black] {_pt((center[0], level))} circle" in drawn, name  # where it strikes
        arrow = re.search(rf"\\draw\[velocity\] {POINT} -- {POINT};", drawn)
        start, tip = (float(arrow[1]), float(arrow[2])), (float(arrow[3]), float(arrow[4]))
        theta = parameter_middle(p, "theta")
        along = math.atan2(tip[1] - start[1], tip[0] - start[0])
        assert abs(along - math.atan2(-math.cos(theta), math.sin(theta))) < 0.02, name
        assert radius < math.dist(tip, center) < radius + 0.1, name  # it ends at the ball
        assert "{$\\theta$}" in drawn and "{$v$}" in drawn and "$e$" in drawn, name
    assert "no slip" in figures["ball_bounces_then_flies"] and "rough, $\\mu$" in figures["sphere_bounces_sliding"]


def test_a_ball_dropped_onto_a_wedge_falls_onto_its_face_from_its_height(problems, figures):
    """The face at its angle through the point struck, straight under the ball; the ball's drop and
    the point's height above the floor (the wedge's foot) in the ratio of h to H."""
    p = next(q for q in problems if q.id == "ball_bounces_off_wedge")
    drawn = figures["ball_bounces_off_wedge"]
    wedge = re.search(rf"\\draw\[fill=gray!10\] {POINT} -- {POINT} -- {POINT} -- cycle;", drawn)
    top, foot, corner = ((float(wedge[k]), float(wedge[k + 1])) for k in (1, 3, 5))
    assert abs(math.atan2(top[1] - foot[1], foot[0] - top[0]) - math.pi / 4) < 0.01  # 45 degrees, down to the right
    assert corner == (top[0], foot[1])
    struck = re.search(rf"\\fill\[red!70!black\] {POINT} circle", drawn)
    struck = (float(struck[1]), float(struck[2]))
    assert on_segment(struck, top, foot)
    ball = re.search(rf"\\shade\[ball color=gray!60\] {POINT} circle", drawn)
    ball = (float(ball[1]), float(ball[2]))
    assert abs(ball[0] - struck[0]) <= TOLERANCE and ball[1] > struck[1]
    drop, height = ball[1] - struck[1], struck[1] - foot[1]
    assert abs(drop / height - parameter_middle(p, "h") / parameter_middle(p, "H")) < 0.05
    assert "{$h$}" in drawn and "{$H$}" in drawn and "smooth, $e$" in drawn and "\\frac{\\pi}{4}" in drawn


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
    assert "{$R_{\\mathrm{cm}}$}" in pendulum  # Rcm, as the equations name it (latex.symbol_latex)
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
    """The library's figures and the scenes of parts in tests/figures."""
    assert {p.id: figure.tikz(p) for p in problems} == figures
    scenes = sorted((ROOT / "tests" / "figures").glob("*.yaml"))
    drawn = [figures[p.id] or "" for p in problems] + [figure.tikz(problem.parse(p.read_text(), p)) for p in scenes]
    digest = hashlib.sha256("".join(drawn).encode()).hexdigest()
    code = ("import hashlib, pathlib; from derive.core import library; from derive.language import problem; "
            "from derive.publishing import figure; print(hashlib.sha256(''.join("
            "[figure.tikz(problem.load(p)) or '' for p in library.problem_files()] + [figure.tikz(problem.parse("
            "p.read_text(), p)) for p in sorted(pathlib.Path('tests/figures').glob('*.yaml'))]).encode()).hexdigest())")
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
    """One document with the project's preamble and every figure (the library's, and the scenes of
    parts in tests/figures): it compiles, and the labels show."""
    body = "\n\n".join(f"\\section*{{{tex_escape(p.id)}}}\n{figures[p.id]}" for p in problems)
    scenes = [scene_problem(path.stem) for path in sorted(FIGURES.glob("*.yaml"))]
    body += "\n\n" + "\n\n".join(f"\\section*{{{tex_escape(p.id)}}}\n{figure.tikz(p)}" for p in scenes)
    tex = tmp_path / "figures.tex"
    tex.write_text(render.render("preamble.tex.j2") + "\\begin{document}\n" + body + "\n\n"
                   + figure.tikz(special) + "\n\\end{document}\n", encoding="utf-8")
    pdf = export.pdf(tex)
    text = subprocess.run(["pdftotext", str(pdf), "-"], capture_output=True, text=True, check=True).stdout
    assert "big_block" in text and "the_ball_2" in text and "hoop" in text
    assert text.count("rolling_incline") == 1
    assert "no slip" in text and "smooth" in text and "rough" in text and "spring_damper" in text


def test_the_documents_include_the_figures(tmp_path):
    built = worksheets.build("demo", variants=2, seed=3, out_dir=str(tmp_path / "demo"), formats=set())
    folder = built[0].parent
    worksheet = (folder / "worksheet.tex").read_text()
    solutions = (folder / "solutions.tex").read_text()
    count = len(problem_sets.load_set("demo").problems)
    assert worksheet.count("\\begin{tikzpicture}") == count  # each drawn once, into a box
    assert worksheet.count("\\usebox{") == 2 * count  # that each variant shows
    free_bodies = 3  # after each Newton–Euler balance, in the appendix: the disk and the block, the pendulum
    students = 2  # after the student's balances (the disk's and the block's); the pendulum's route has none
    assert solutions.count("\\begin{tikzpicture}") == count + free_bodies + students
    assert figure.tikz(problem.load("string_wrapped_disk")) in worksheet
    assert "\\usetikzlibrary{" in worksheet


def test_the_handout_includes_the_figure(tmp_path):
    done = run_derive("handout", "tugged_spool", "--out", str(tmp_path / "h"))
    assert done.returncode == 0, done.stderr
    tex = (tmp_path / "h" / "tugged_spool.tex").read_text()
    assert figure.tikz(problem.load("tugged_spool")) in tex
    assert (tmp_path / "h" / "tugged_spool.pdf").read_bytes().startswith(b"%PDF")


# The general layout: every part where the scene puts it (derive.publishing.figure.parts). The scenes are in
# tests/figures; each check recomputes the geometry from the parts, independently of the figure code
# but for the one map from the scene (m) to the figure (cm): a uniform scale and a shift.
FIGURES = ROOT / "tests" / "figures"
TOLERANCE = 0.006  # coordinates are written to 0.01 cm
LINE = re.compile(r"^\\draw(?:\[([^\]]*)\])? \((-?[\d.]+),(-?[\d.]+)\) -- \((-?[\d.]+),(-?[\d.]+)\);$", re.M)


def scene_problem(name):
    path = FIGURES / f"{name}.yaml"
    return problem.parse(path.read_text(), path)


@pytest.fixture(scope="module")
def drawn_scenes():
    """name: (problem, figure, the map from a reference-configuration point in m to the figure in cm)."""
    from derive.publishing.figure.canvas import _Figure
    from derive.publishing.figure.parts import _Layout

    result = {}
    for path in sorted(FIGURES.glob("*.yaml")):
        p = scene_problem(path.stem)
        result[path.stem] = (p, figure.tikz(p), _Layout(_Figure(p)).view.at)
    return result


def reference(p):
    """A point or an expression of the scene in its reference configuration, at the middle of the ranges."""
    from derive.model.kinematics import Coordinates

    coords = Coordinates(p.scene)
    rest = {s: sp.Integer(v) for s, v in coords.at_rest_in_reference().items()}
    values = {q.symbol: q.value if q.range is None else (q.range[0] + q.range[1]) / 2 for q in p.parameters.values()}

    def number(expression):
        return float(sp.sympify(expression).xreplace(rest).xreplace(values))

    return coords, number


def close_to(point, expected):
    return abs(point[0] - expected[0]) <= TOLERANCE and abs(point[1] - expected[1]) <= TOLERANCE


def lines(drawn, style=None):
    return [((float(m[2]), float(m[3])), (float(m[4]), float(m[5]))) for m in LINE.finditer(drawn)
            if style is None or m[1] == style]


def test_the_scenes_of_parts_draw_in_the_general_layout(drawn_scenes):
    from derive.publishing.figure.layout import _LAYOUTS
    from derive.publishing.figure.parts import _parts

    for name, (p, drawn, _) in drawn_scenes.items():
        assert next(draw for applies, draw in _LAYOUTS if applies(p)) is _parts, name
        assert drawn.startswith("\\begin{tikzpicture}[") and "nan" not in drawn, name
        points = [(float(x), float(y)) for x, y in COORDINATE.findall(drawn)]
        width = max(x for x, _ in points) - min(x for x, _ in points)
        height = max(y for _, y in points) - min(y for _, y in points)
        assert 0.5 < width <= 6.5 and height <= 6.5, (name, width, height)


def test_cord_runs_end_at_the_tangent_points_the_cord_computes(drawn_scenes):
    """Each straight run of each cord is a line from its start to its end tangent point (on a
    pulley, a drum, a hub), as `derive.parts.cord.run` computes them."""
    from derive.parts.cord import Cord, run

    checked = 0
    for name in ("table_pulley", "atwood", "incline_pulley", "block_tackle", "yoyo_weld"):
        p, drawn, at = drawn_scenes[name]
        coords, number = reference(p)
        cords = [c for c in p.scene.constraints + p.scene.loads if isinstance(c, Cord)]
        runs = lines(drawn, "thick")
        for cord in cords:
            for a, b in zip(cord.path, cord.path[1:]):
                r = run(a, b, coords)
                if r.length is None:
                    continue
                start, end = (at((number(v[0]), number(v[1]))) for v in (r.start_point, r.end_point))
                assert any(close_to(s, start) and close_to(e, end) for s, e in runs), (name, start, end)
                checked += 1
    assert checked == 9


def test_a_cord_wraps_its_pulley_between_the_tangent_points_and_ties_to_the_ceiling(drawn_scenes):
    p, drawn, at = drawn_scenes["atwood"]
    _, number = reference(p)
    R = number(p.scene.bodies["pulley"].sizes["radius"])
    left = at((-R, 0))
    radius = at((R, 0))[0] - at((0, 0))[0]
    # over the top, clockwise from the left tangent point to the right one
    assert f"\\draw[thick] ({_f(left[0])},{_f(left[1])}) arc[start angle=180, end angle=0, radius={_f(radius)}];" in drawn
    assert f"\\draw[body] {_pt(at((0, 0)))} circle ({_f(radius)});" in drawn  # the pulley to the same scale
    tackle, drawn, at = drawn_scenes["block_tackle"]
    _, number = reference(tackle)
    hook = at((-number(tackle.parameters["r"].symbol), 0))
    ceiling = [(a, b) for a, b in lines(drawn.replace("; \\draw[thick]", ";\n\\draw[thick]"), "thick")
               if abs(a[1] - hook[1]) < TOLERANCE and abs(b[1] - hook[1]) < TOLERANCE]
    assert any(abs((a[0] + b[0]) / 2 - hook[0]) < TOLERANCE for a, b in ceiling)  # a ceiling across the run at the hook


def test_a_pulled_end_is_an_arrow_along_the_pull_labelled_with_the_force(drawn_scenes):
    p, drawn, at = drawn_scenes["pulled_incline"]
    coords, number = reference(p)
    from derive.parts.cord import run

    cord = p.scene.constraint("rope") if "rope" in {c.name for c in p.scene.constraints} else next(
        c for c in p.scene.loads if c.name == "rope")
    r = run(*cord.path, coords)
    start = at((number(r.start_point[0]), number(r.start_point[1])))
    theta = number(p.parameters["theta"].symbol)
    toward = (math.cos(math.pi - theta), math.sin(math.pi - theta))
    tip = (start[0] + 0.9 * toward[0], start[1] + 0.9 * toward[1])
    assert any(close_to(a, start) and close_to(b, tip) for a, b in lines(drawn, "thick"))
    assert any(close_to(a, tip) for a, _ in lines(drawn, "force")) and "{$F$}" in drawn


def test_a_table_ends_short_of_its_pulley_and_the_block_rests_on_it(drawn_scenes):
    """The schematic floor once drew this scene without its pulley and cord; the general layout
    draws them, the table stopping before the pulley, lowered half a block under the block's point."""
    p, drawn, at = drawn_scenes["table_pulley"]
    _, number = reference(p)
    pulley = at((number(p.scene.bodies["pulley"].at[0]), number(p.scene.bodies["pulley"].at[1])))
    radius = at((number(p.parameters["R"].symbol), 0))[0] - at((0, 0))[0]
    table = [(a, b) for a, b in lines(drawn.replace("; \\draw[thick]", ";\n\\draw[thick]"), "thick")
             if abs(a[1] - b[1]) < TOLERANCE and abs(a[1] - (at((0, 0))[1] - 0.21)) < TOLERANCE]
    assert table and max(b[0] for _, b in table) < pulley[0] - radius
    block = at((0, 0))
    assert f"\\draw[body] {_pt((block[0] - 0.21, block[1] - 0.21))} rectangle {_pt((block[0] + 0.21, block[1] + 0.21))};" in drawn
    assert "smooth" in drawn


def test_springs_and_dashpots_run_from_one_point_exactly_to_the_other(drawn_scenes):
    p, drawn, at = drawn_scenes["spring_damper"]
    _, number = reference(p)
    L = number(p.parameters["L"].symbol)
    wall, block, post = at((0, 0)), at((L, 0)), at((2 * L, 0))
    zigzag = re.search(r"\\draw\[line join=round\] (.*);", drawn)[1]
    points = [(float(x), float(y)) for x, y in COORDINATE.findall(zigzag)]
    assert close_to(points[0], wall) and close_to(points[-1], block) and len(points) > 8
    assert any(abs(y - wall[1]) > 0.1 for _, y in points)  # it zigzags
    segments = lines(drawn.replace("; \\draw", ";\n\\draw"))
    assert any(close_to(a, block) for a, _ in segments)  # the dashpot's rod from the block
    assert any(close_to(b, post) for _, b in segments)  # its piston rod to the post
    assert "\\draw[thick]" in drawn and drawn.count("pattern=north east lines") >= 3  # two anchors and the floor
    for anchor in (wall, post):  # a hatched wall across the line at each ground end
        assert f"{_pt((anchor[0], anchor[1] + 0.25))} -- {_pt((anchor[0], anchor[1] - 0.25))}" in drawn or \
            f"{_pt((anchor[0], anchor[1] - 0.25))} -- {_pt((anchor[0], anchor[1] + 0.25))}" in drawn
    assert "{$k$}" in drawn and "{$b$}" in drawn and "{$F$}" in drawn and "rough, $\\mu_{k}$" in drawn


def test_pins_supports_torques_coils_and_forces(drawn_scenes):
    p, drawn, at = drawn_scenes["pendulum_coil"]
    _, number = reference(p)
    L = number(p.parameters["L"].symbol)
    hinge, tip = at((0, 0)), at((L, 0))
    assert re.search(rf"\\draw\[fill=gray!30\] {re.escape(_pt(hinge))} -- .* -- cycle;", drawn)  # the support's apex
    assert f"\\draw[fill=white] {_pt(hinge)} circle (0.06);" in drawn  # the pin
    coil = re.search(r"plot\[smooth\] coordinates \{\((-?[\d.]+),(-?[\d.]+)\)", drawn)
    assert coil and math.hypot(float(coil[1]) - hinge[0], float(coil[2]) - hinge[1]) < 0.06  # the coil at the pin
    torque = re.search(r"\\draw\[force\] \S+ arc\[start angle=(-?[\d.]+), end angle=(-?[\d.]+)", drawn)
    assert torque and float(torque[1]) > float(torque[2])  # -tau: clockwise, labelled tau
    assert "{$\\tau$}" in drawn and "{$\\kappa$}" in drawn and "{$c$}" in drawn
    assert f"\\draw[force] {_pt(tip)} -- {_pt((tip[0], tip[1] - 0.85))};" in drawn and "{$P$}" in drawn
    assert "{$M\\,g$}" in drawn


def test_a_pin_between_bodies_a_slider_rail_and_welds(drawn_scenes):
    p, drawn, at = drawn_scenes["cart_pendulum"]
    cart = at((0, 0))
    assert f"\\draw[fill=white] {_pt(cart)} circle (0.07);" in drawn  # the hinge on the cart
    rail = re.search(r"\\draw\[thick, gray!70!black\] \((-?[\d.]+),(-?[\d.]+)\) -- \((-?[\d.]+),(-?[\d.]+)\);", drawn)
    assert rail and close_to((float(rail[1]), float(rail[2])), (float(rail[1]), cart[1]))
    assert float(rail[2]) == float(rail[4]) and float(rail[1]) < cart[0] < float(rail[3])  # level, through the cart
    assert f"rotate around={{0:{_pt(cart)}}}] {_pt((cart[0] - 0.16, cart[1] - 0.09))}" in drawn  # a guide's block
    p, drawn, at = drawn_scenes["yoyo_weld"]
    _, number = reference(p)
    L = number(p.parameters["L"].symbol)
    wall = at((2 * L - L / 4, -L / 4))  # the shelf's left edge, against a hatched wall
    assert f"{_pt((wall[0], wall[1] + 0.3))} -- {_pt((wall[0], wall[1] - 0.3))}" in drawn
    assert drawn.count("\\fill (") >= 2 and "-- cycle;" in drawn  # the weld marks
    assert "{$\\tau$}" in drawn and "{$M$}" in drawn


def test_surfaces_and_contact_regimes(drawn_scenes):
    p, drawn, at = drawn_scenes["bowl_dome"]
    _, number = reference(p)
    R = number(p.parameters["R"].symbol)
    scale = at((1, 0))[0] - at((0, 0))[0]
    assert f"\\draw[thick] {_pt(at((0, R)))} circle ({_f(R * scale)});" in drawn  # the bowl, to scale
    assert f"\\draw[thick] {_pt(at((3 * R, 0)))} circle ({_f(R / 2 * scale - 0.1)});" in drawn  # the dome, under its bead
    assert "no slip, $\\mu_{s}$" in drawn and "rough, $\\mu_{k}$" in drawn
    assert "{$R$}" in drawn and "{$\\frac{R}{2}$}" in drawn
    _, drawn, _ = drawn_scenes["incline_pulley"]
    assert "{$\\theta$}" in drawn and "\\draw[fill=gray!10]" in drawn


def test_the_schematic_surfaces_mark_each_contact_regime(figures):
    assert "no slip" in figures["rolling_incline"] and "no slip" in figures["tugged_spool"]
    race = figures["incline_race"]
    assert "{\\scriptsize smooth}" in race and race.count("{\\scriptsize no slip}") == 3 and "rotate=" in race
    assert "rough, $\\mu$" in figures["skid_to_roll"]  # it skids before it rolls
    assert "smooth" in figures["loop_the_loop"] and "no slip" in figures["loop_the_loop"]


def test_a_part_the_figure_cannot_draw_leaves_the_figure_out(drawn_scenes):
    """Never a figure that silently leaves a part out or invents its geometry: no figure at all."""
    import dataclasses
    from types import SimpleNamespace

    from derive.parts import Part
    from derive.parts.force import Force

    p, _, _ = drawn_scenes["spring_damper"]

    class Magnet(Part):
        name = "magnet"

    def with_loads(*loads):
        scene = dataclasses.replace(p.scene, loads=p.scene.loads + loads)
        return figure.tikz(SimpleNamespace(scene=scene, parameters=p.parameters, asks=p.asks))

    assert with_loads() is not None
    assert with_loads(Magnet()) is None
    assert with_loads(Force("odd", "block", (0, 0), sp.Integer(1), sp.acos(sp.Integer(3)))) is None  # not a real angle


def test_a_peg_of_no_size_holds_the_cord_where_its_runs_meet(drawn_scenes):
    """A ground point in the middle of a cord (a smooth peg): a small circle on a support, both
    runs meeting at it. (Built in code: the scene reader takes the file's peg as a drum here.)"""
    import dataclasses
    from types import SimpleNamespace

    from derive.parts.cord import Cord

    p, _, _ = drawn_scenes["reel_peg"]
    _, number = reference(p)
    R = number(p.parameters["R"].symbol)
    cord = next(c for c in p.scene.constraints if isinstance(c, Cord))
    peg = dataclasses.replace(cord.path[1], radius=sp.Integer(0), turn=0)
    scene = dataclasses.replace(p.scene, constraints=tuple(
        dataclasses.replace(cord, path=(cord.path[0], peg, cord.path[2])) if c is cord else c
        for c in p.scene.constraints))
    from derive.publishing.figure.canvas import _Figure
    from derive.publishing.figure.parts import _Layout

    pegged = SimpleNamespace(scene=scene, parameters=p.parameters, asks=p.asks)
    drawn = figure.tikz(pegged)
    point = _Layout(_Figure(pegged)).view.at((3 * R, R))
    assert f"\\draw[fill=white] {_pt(point)} circle (0.07);" in drawn
    assert re.search(rf"\\draw\[fill=gray!30\] {re.escape(_pt(point))} -- ", drawn)  # its support
    runs = lines(drawn, "thick")
    assert any(close_to(b, point) for _, b in runs) and any(close_to(a, point) for a, _ in runs)


REGIME = re.compile(r"^\\node\[anchor=[a-z ]+, inner sep=1.5pt\] at \((-?[\d.]+),(-?[\d.]+)\) \{\\scriptsize (.*)\};$", re.M)
BAR = re.compile(r"\\draw\[line width=3.2pt, line cap=round, gray!60!black\] \((-?[\d.]+),(-?[\d.]+)\) -- "
                 r"\((-?[\d.]+),(-?[\d.]+)\);")


def touching(p, at):
    """Each contact at a material point: (the contact, where that point is on the figure), from the parts."""
    from derive.parts.contact import Contact

    coords, number = reference(p)
    return [(c, at(tuple(number(v) for v in coords.position(c.body, c.point))))
            for c in p.scene.constraints if isinstance(c, Contact) and c.point is not None]


def on_segment(point, a, b):
    length = math.hypot(b[0] - a[0], b[1] - a[1])
    along = ((point[0] - a[0]) * (b[0] - a[0]) + (point[1] - a[1]) * (b[1] - a[1])) / length
    across = ((point[0] - a[0]) * (b[1] - a[1]) - (point[1] - a[1]) * (b[0] - a[0])) / length
    return abs(across) <= TOLERANCE and -TOLERANCE <= along <= length + TOLERANCE


def test_a_ladder_touches_the_floor_and_the_wall_at_its_points_and_they_meet_at_the_corner(drawn_scenes):
    """A ladder (a rod; a custom body given by its points: a bar between them) against a wall
    facing right and one facing left: each touching point on its surface's line as drawn, the
    ladder from one touching point exactly to the other, the floor and the wall meeting at their
    corner (each line ends there)."""
    for name in ("ladder_wall", "ladder_left"):
        p, drawn, at = drawn_scenes[name]
        _, number = reference(p)
        surfaces = lines(drawn.replace("; \\draw[thick]", ";\n\\draw[thick]"), "thick")
        points, ends = [], []
        for contact, point in touching(p, at):
            plane = p.scene.surfaces[contact.surface]
            through = at(tuple(number(v) for v in plane.through))
            normal = tuple(number(v) for v in plane.normal)

            def on_plane(x):
                return abs((x[0] - through[0]) * normal[0] + (x[1] - through[1]) * normal[1]) <= TOLERANCE

            drawn_lines = [(a, b) for a, b in surfaces if on_plane(a) and on_plane(b)]
            assert len(drawn_lines) == 1 and on_segment(point, *drawn_lines[0]), (name, contact.name, point)
            points.append(point)
            ends.append(drawn_lines[0])
        ladder = BAR.search(drawn)
        bar = [(float(ladder[1]), float(ladder[2])), (float(ladder[3]), float(ladder[4]))]
        assert (close_to(bar[0], points[0]) and close_to(bar[1], points[1])) or \
            (close_to(bar[0], points[1]) and close_to(bar[1], points[0])), (name, bar, points)
        floor, wall = (p.scene.surfaces[s] for s in ("floor", "wall"))
        corner = at((number(wall.through[0]), number(floor.through[1])))
        assert all(close_to(a, corner) or close_to(b, corner) for a, b in ends), (name, corner, ends)


def test_each_touching_point_is_labelled_with_its_own_regime(drawn_scenes):
    """The regime written nearest each touching point is its own: the foot "rough, mu_s" (static
    friction given: the engine decides), "no slip" (grips), the wall "smooth"."""
    expected = {"ladder_wall": {"floor": "rough, $\\mu_{s}$", "wall": "smooth"},
                "ladder_left": {"floor": "no slip", "wall": "smooth"}}
    for name, regimes in expected.items():
        p, drawn, at = drawn_scenes[name]
        labels = [((float(x), float(y)), text) for x, y, text in REGIME.findall(drawn)]
        assert sorted(text for _, text in labels) == sorted(regimes.values()), (name, labels)
        for contact, point in touching(p, at):
            where, text = min(labels, key=lambda label: math.dist(label[0], point))
            assert text == regimes[contact.surface] and math.dist(where, point) < 0.5, (name, contact.name, text)


def test_the_ladders_angle_above_the_floor_is_marked_at_its_foot(drawn_scenes):
    """theta, a parameter, is the angle between the floor and the ladder: an arc about the foot
    from the floor's line to the ladder's, labelled; the wall's angle (pi/2 - theta) is not."""
    arc = re.compile(r"\\draw \((-?[\d.]+),(-?[\d.]+)\) arc\[start angle=(-?[\d.]+), end angle=(-?[\d.]+), "
                     r"radius=([\d.]+)\];")
    for name in ("ladder_wall", "ladder_left"):
        p, drawn, at = drawn_scenes[name]
        _, number = reference(p)
        (foot,), (head,) = ([point for c, point in touching(p, at) if c.surface == s] for s in ("floor", "wall"))
        arcs = arc.findall(drawn)
        assert len(arcs) == 1 and "{$\\theta$}" in drawn, name
        x, y, start, end, radius = map(float, arcs[0])
        center = (x - radius * math.cos(math.radians(start)), y - radius * math.sin(math.radians(start)))
        assert math.dist(center, foot) < 0.01, (name, center, foot)
        assert abs(abs(end - start) - math.degrees(number(p.parameters["theta"].symbol))) < 0.02
        assert start % 180 == 0  # from along the floor
        toward = math.degrees(math.atan2(head[1] - foot[1], head[0] - foot[0]))
        assert abs((end - toward + 180) % 360 - 180) < 0.2, (name, end, toward)  # to along the ladder


def test_a_ladder_given_by_its_points_is_a_bar_with_its_center_of_mass_and_loads_on_it(drawn_scenes):
    p, drawn, at = drawn_scenes["ladder_left"]
    coords, number = reference(p)
    center = at(tuple(number(v) for v in coords.position("ladder")))
    painter = next(load for load in p.scene.loads if load.name == "painter")
    painter = at(tuple(number(v) for v in coords.position("ladder", painter.offset)))
    assert f"\\draw[fill=white] {_pt(center)} circle (0.05);" in drawn  # the center of mass marked on the bar
    assert f"\\draw[force] {_pt(painter)} -- {_pt((painter[0], painter[1] - 0.85))};" in drawn and "{$P$}" in drawn
    assert f"\\draw[force] {_pt(center)} -- {_pt((center[0], center[1] - 0.85))};" in drawn and "{$m\\,g$}" in drawn


def test_a_custom_body_touching_that_is_no_bar_leaves_the_figure_out():
    """Drawn as an oval about its points, it would cross the floor at its foot: no figure. So a
    ladder whose painter stands off its line, or that touches the floor only."""
    text = (FIGURES / "ladder_left.yaml").read_text()
    off_the_line = text.replace("on: {ladder: [L/6, 0]}", "on: {ladder: [L/6, L/10]}")
    foot_only = text.replace("    head: {touches: {ladder: [2*L/3, 0]}, on: wall}\n", "").replace("head.normal", "foot.normal")
    assert "L/10" in off_the_line and "head:" not in foot_only
    assert figure.tikz(problem.parse(text, FIGURES / "ladder_left.yaml")) is not None
    for changed in (off_the_line, foot_only):
        assert figure.tikz(problem.parse(changed, FIGURES / "ladder_left.yaml")) is None


def test_the_handouts_checks_read_as_sentences_with_units_in_math(tmp_path):
    """Issue 15: "Energy is conserved: the constraint forces do no work.", the answers' units in
    math; never the engine's "work_energy: T + V conserved (numeric)"."""
    done = run_derive("handout", "string_wrapped_disk", "--out", str(tmp_path / "h"))
    assert done.returncode == 0, done.stderr
    text = (tmp_path / "h" / "string_wrapped_disk.tex").read_text()
    checks = text.split(r"\section*{Checks}")[1]
    assert r"$T$ in $\unit{N}$" in checks and "Energy is conserved: the constraint forces do no work." in checks
    assert "(numeric)" not in checks and "work_energy" not in checks and "T + V" not in checks


def test_a_puck_striking_a_rod_across_its_path_is_drawn_to_scale():
    """The struck rod lies at its angle (here along y, across the puck's path) and a round body
    that strikes is a circle of its radius, not a dot."""
    tikz = figure.tikz(problem.load(textbook("disk_strikes_free_rod")))
    assert "(0,-2.39) -- (0,2.39);" in tikz  # the rod, vertical
    assert "\\draw[body] (-1.59,2.39) circle (0.19);" in tikz  # the puck, its radius to the rod's scale


# Surfaces carried by a body and clutches (issue 39), in the general layout: each carrier drawn as what holds its
# surface, where the scene puts it (derive.publishing.figure.drawn_carriers, drawn_clutches).
POLYGON = re.compile(r"\\draw\[body\] ((?:\(-?[\d.]+,-?[\d.]+\) -- )+)cycle;")
RAIL = re.compile(rf"\\draw\[thick, gray!70!black\] {POINT} -- {POINT};")


@pytest.fixture(scope="module")
def carried(problems):
    """name: (problem, figure, the map from the scene (m) to the figure (cm), the scale in cm per m)."""
    from derive.publishing.figure.canvas import _Figure
    from derive.publishing.figure.parts import _Layout

    result = {}
    for p in problems:
        if p.id in ("wedge_block", "plank_cylinder", "plank_block_tilted", "cart_track_bead", "flywheel_brake_grips",
                    "turntable_record_slips"):
            at = _Layout(_Figure(p)).view.at
            result[p.id] = (p, figure.tikz(p), at, at((1, 0))[0] - at((0, 0))[0])
    return result


def polygons(drawn):
    return [[(float(x), float(y)) for x, y in COORDINATE.findall(m[1])] for m in POLYGON.finditer(drawn)]


def rail(drawn):
    m = RAIL.search(drawn)
    return (float(m[1]), float(m[2])), (float(m[3]), float(m[4]))


def block_center(drawn):
    """A block's center and its tilt (degrees), from its rotated square."""
    m = re.search(rf"\\draw\[body, rotate around=\{{(-?[\d.]+):{POINT}\}}\] {POINT} rectangle {POINT};", drawn)
    return (float(m[2]), float(m[3])), float(m[1])


def test_a_wedge_that_slides_carries_its_face_and_rides_its_rail(carried):
    """The wedge: a solid triangle (no hatching: it moves), its face at theta through the block's
    point less half a block, upright behind, level below; its rail under its base; the block on the face."""
    p, drawn, at, _ = carried["wedge_block"]
    theta = parameter_middle(p, "theta")
    (wedge,) = polygons(drawn)
    upper, foot, back = wedge
    assert abs(math.atan2(upper[1] - foot[1], foot[0] - upper[0]) - theta) < 0.01
    assert close_to(back, (upper[0], foot[1]))
    block, tilt = block_center(drawn)
    assert close_to(block, at((0, 0))) and abs(tilt + math.degrees(theta)) < 0.01  # at its point, turned onto the face
    normal = (math.sin(theta), math.cos(theta))
    base = (block[0] - 0.21 * normal[0], block[1] - 0.21 * normal[1])
    assert on_segment(base, upper, foot)  # it sits on the face
    a, b = rail(drawn)
    assert abs(a[1] - foot[1]) <= TOLERANCE and abs(b[1] - foot[1]) <= TOLERANCE and a[0] < back[0] and b[0] > foot[0]
    assert "\\draw[fill=gray!10]" not in drawn  # not a fixed incline
    assert "{$\\theta$}" in drawn and "{$M$}" in drawn and "smooth" in drawn


def test_a_plank_carries_the_rolling_cylinder_on_its_top_as_thick_as_it_is(carried):
    p, drawn, at, scale = carried["plank_cylinder"]
    b, R = parameter_middle(p, "b"), parameter_middle(p, "R")
    (slab,) = polygons(drawn)
    top, bottom = max(y for _, y in slab), min(y for _, y in slab)
    assert abs(top - at((0, b))[1]) <= TOLERANCE and abs((top - bottom) - b * scale) <= 2 * TOLERANCE
    cylinder = re.search(rf"\\draw\[body\] {POINT} circle \(([\d.]+)\);", drawn)
    center, radius = (float(cylinder[1]), float(cylinder[2])), float(cylinder[3])
    assert abs(radius - R * scale) <= TOLERANCE and abs(center[1] - radius - top) <= TOLERANCE  # it rests on the top
    assert min(x for x, _ in slab) < center[0] < max(x for x, _ in slab)
    a, b_ = rail(drawn)
    assert abs(a[1] - bottom) <= TOLERANCE and a[0] < min(x for x, _ in slab) and b_[0] > max(x for x, _ in slab)
    pull = re.search(rf"\\draw\[force\] {POINT} -- {POINT};", drawn)
    assert abs(float(pull[1]) - max(x for x, _ in slab)) <= TOLERANCE and float(pull[3]) > float(pull[1])  # from its end
    assert "no slip" in drawn and "{$F$}" in drawn and "{$M$}" in drawn


def test_a_block_on_a_tilted_plank_sits_on_the_plank_itself(carried):
    """The plank's top is the plank: no surface of its own; the block's base on the bar, d down
    the slope from the pivot; phi marked from a level line at the pivot."""
    p, drawn, at, scale = carried["plank_block_tilted"]
    phi, d, L = (parameter_middle(p, name) for name in ("phi", "d", "L"))
    bar = BAR.search(drawn)
    ends = (float(bar[1]), float(bar[2])), (float(bar[3]), float(bar[4]))
    pivot = at((0, 0))
    assert abs(math.dist(*ends) - L * scale) <= 2 * TOLERANCE and close_to(((ends[0][0] + ends[1][0]) / 2, (ends[0][1] + ends[1][1]) / 2), pivot)
    block, tilt = block_center(drawn)
    normal = (math.sin(phi), math.cos(phi))
    base = (block[0] - 0.21 * normal[0], block[1] - 0.21 * normal[1])
    assert close_to(base, at((d * math.cos(phi), -d * math.sin(phi)))) and abs(tilt + math.degrees(phi)) < 0.01
    assert f"\\draw[fill=white] {_pt(pivot)} circle (0.06);" in drawn  # the pivot
    assert "pattern=north east lines" in drawn and drawn.count("pattern=north east lines") == 1  # its support only
    assert f"\\draw[dashed, gray] {_pt(pivot)} -- " in drawn and "{$\\phi$}" in drawn


def test_a_cart_carries_its_circular_track_with_the_bead_on_it(carried):
    p, drawn, at, scale = carried["cart_track_bead"]
    R, phi = parameter_middle(p, "R"), parameter_middle(p, "phi")
    middle = at((0, R))
    track = re.search(rf"\\draw\[thick\] {POINT} circle \(([\d.]+)\);", drawn)
    assert close_to((float(track[1]), float(track[2])), middle)
    radius = float(track[3])
    bead = re.search(rf"\\shade\[ball color=gray!60\] {POINT} circle \(([\d.]+)\);", drawn)
    center, size = (float(bead[1]), float(bead[2])), float(bead[3])
    assert close_to(center, at((R * math.sin(phi), R - R * math.cos(phi))))  # where the scene puts it
    assert abs(math.dist(center, middle) + size - radius) <= TOLERANCE  # touching the track from inside
    (cart,) = polygons(drawn)
    xs, ys = [x for x, _ in cart], [y for _, y in cart]
    assert min(xs) < middle[0] - radius and max(xs) > middle[0] + radius and min(ys) < middle[1] - radius
    assert abs(max(ys) - middle[1]) <= TOLERANCE  # up to the track's middle
    a, b = rail(drawn)
    assert abs(a[1] - min(ys)) <= TOLERANCE and a[0] < min(xs) and b[0] > max(xs)
    assert drawn.count("pattern=north east lines") == 1 and "{$R$}" in drawn and "{$M$}" in drawn


def test_a_brake_pad_presses_on_the_flywheels_rim_from_the_ground(carried):
    p, drawn, at, scale = carried["flywheel_brake_grips"]
    R = parameter_middle(p, "R")
    center = at((0, 0))
    pad = re.search(rf"\\draw\[fill=gray!55\] {POINT} -- {POINT} -- {POINT} -- {POINT} -- cycle;", drawn)
    corners = [(float(pad[k]), float(pad[k + 1])) for k in (1, 3, 5, 7)]
    inner = ((corners[0][0] + corners[1][0]) / 2, (corners[0][1] + corners[1][1]) / 2)
    assert abs(math.dist(inner, center) - R * scale) < 0.03  # on the rim
    outer = ((corners[2][0] + corners[3][0]) / 2, (corners[2][1] + corners[3][1]) / 2)
    assert math.dist(outer, center) > math.dist(inner, center)
    assert drawn.count("pattern=north east lines") == 2  # the axle's bracket and the pad's anchor
    assert "pad, rough, $C$" in drawn


def test_a_record_on_a_turntable_meets_it_at_a_felt_inside_its_rim(carried):
    p, drawn, at, scale = carried["turntable_record_slips"]
    R1, R2 = parameter_middle(p, "R1"), parameter_middle(p, "R2")
    center = at((0, 0))
    disks = sorted(float(m[1]) for m in re.finditer(rf"\\draw\[body\] {re.escape(_pt(center))} circle \(([\d.]+)\);", drawn))
    assert abs(disks[0] - R2 * scale) <= TOLERANCE and abs(disks[1] - R1 * scale) <= TOLERANCE
    felt = re.search(rf"densely dotted\] {re.escape(_pt(center))} circle \(([\d.]+)\);", drawn)
    assert felt and R2 * scale - 0.15 < float(felt[1]) < R2 * scale
    assert "felt, rough, $C$" in drawn


def test_an_orbit_given_at_periapsis_draws_what_is_given_never_its_axis():
    """A newcomer's comet (Serway & Jewett ch. 13) drew its major axis labelled r_p 2GM/(2GM - r_p v_p^2),
    and the focus's distance from the center: the aphelion the worksheet asks, given away. The figure
    draws the distance and speed at periapsis the question gives."""
    drawn = figure.tikz(problem.load(textbook("comet_from_periapsis")))
    labels = re.findall(r"\{(\$[^$]*\$)\}", drawn)
    assert "$r_{p}$" in labels and "$v_{p}$" in labels and "$\\mathit{GM}$" in labels
    assert not any("frac" in label or "GM} -" in label for label in labels), labels
    assert "ellipse" in figure.tikz(problem.load("kepler_orbit"))  # an orbit given by its axis still draws 2a


def test_a_body_alone_on_a_slope_of_no_given_length_has_room_to_roll():
    """A newcomer's cylinder rolling up a slope (no length, no height given) was drawn larger than the slope
    it rolls on, the slope ending a radius past it: the slope now runs a few times the body's size."""
    drawn = figure.tikz(problem.load(str(textbook("cylinder_rolls_up_slope"))))
    wedge = re.search(r"\\draw\[fill=gray!10\] \((-?[\d.]+),(-?[\d.]+)\) -- \((-?[\d.]+),(-?[\d.]+)\)", drawn)
    radius = float(re.search(r"\\draw\[body\] \([-\d.]+,[-\d.]+\) circle \(([\d.]+)\)", drawn)[1])
    slope = math.dist((float(wedge[1]), float(wedge[2])), (float(wedge[3]), float(wedge[4])))
    assert slope >= 3 * radius, (slope, radius)


def test_an_arrows_label_whose_path_a_layout_rewrote_is_placed_as_any_other():
    """A label written on its arrow's path (`inline`) is taken off the path where it moves; where a
    layout had rewritten that path without it, the picture raised StopIteration. It is placed as any
    other label: once, as a node of its own."""
    from derive.publishing.figure.canvas import _Figure

    fig = _Figure(problem.load("compound_pendulum"))
    fig.arrow((0, 0), (1, 0), "force", "$F$")
    fig.lines[-1] = fig.lines[-1].split(" node[")[0] + ";"  # the path as a layout wrote it again
    picture = fig.text()
    assert picture.count("{$F$}") == 1 and re.search(r"\\node\[anchor=[a-z ]+, inner sep=1.5pt\] at \(1,0\) \{\$F\$\}", picture)


@pytest.mark.parametrize("problem_id", ["rolling_incline", "sphere_speed_at_bottom"])
def test_an_inclines_height_is_the_drop_of_the_ball_as_drawn(problem_id):
    """Issue 37, item 9: the ball's speed at the bottom is that of a drop through the height H, but the
    figure spanned H over the whole incline, with the ball drawn lower. H now spans the drop of the
    ball as drawn: from the bottom to its point of contact (its center drops as much), read from the
    TikZ coordinates."""
    tikz = figure.tikz(problem.load(problem_id))
    number = r"(-?[\d.]+)"
    width, height = map(float, re.search(rf"\\draw\[fill=gray!10\] \(0,0\) -- \({number},0\) -- \(0,{number}\)", tikz).groups())
    x, y, r = map(float, re.search(rf"\\draw \({number},{number}\) circle \({number}\);", tikz).groups())
    low, high = (float(v) for v in re.search(rf"\\draw\[dim\] \(-?[\d.]+,{number}\) -- \(-?[\d.]+,{number}\)", tikz).groups())
    foot = y - r * width / math.hypot(width, height)  # the contact point, r from the center along the slope's normal
    assert low == 0 and abs(high - foot) < 0.02 and high < height - 0.3, (high, foot, height)
