"""derive.publishing.figure.free_body: each body's free-body diagram, drawn from the Newton–Euler route's own
forces, checked against the scene's geometry (each force at its point, along its direction, as the
problem file places the bodies), labelled as the equations name the forces, beside the balance step
of the worked solutions and the handout, compiling with nothing off the page."""
import hashlib
import html
import math
import os
import re
import subprocess
import sys

import pytest

from conftest import ROOT, run_derive, textbook, write_problem
from derive.text.latex import latex_of, tex_escape
from derive.language import problem
from derive.publishing import variants, worksheets
from derive.solution.answers import Solution
from derive.publishing.figure.free_body import free_bodies
from test_library_sheet import _overfull

PROBLEMS = {"string_wrapped_disk": "string_wrapped_disk", "atwood": str(textbook("atwood_massive_pulley")),
            "ladder": str(textbook("ladder_statics")), "rolling_incline": "rolling_incline"}
ARROW = re.compile(r"^\\draw\[force\] \((-?[\d.]+),(-?[\d.]+)\) -- \((-?[\d.]+),(-?[\d.]+)\);$", re.M)
TOLERANCE = 0.006  # cm: coordinates are written to 0.01 cm


@pytest.fixture(scope="module")
def drawn():
    """name: (solution, {body: FreeBody}) for each problem of PROBLEMS."""
    result = {}
    for name, reference in PROBLEMS.items():
        solution = Solution(problem.load(reference))
        result[name] = solution, free_bodies(solution.problem, solution.dynamics_scene, solution.coordinates)
    return result


def middle(p, name):
    """A parameter at the middle of its range (or its value)."""
    parameter = p.parameters[name]
    return float(parameter.value if parameter.range is None else (parameter.range[0] + parameter.range[1]) / 2)


def forces(diagram):
    """{(label, point (m from the center), direction)} of a diagram, rounded for comparison."""
    return {(a.label, tuple(round(x, 9) + 0.0 for x in a.offset), tuple(round(x, 9) + 0.0 for x in a.direction))
            for a in diagram.arrows}


def expected(*items):
    return {(label, tuple(round(x, 9) + 0.0 for x in point), tuple(round(x, 9) + 0.0 for x in direction))
            for label, point, direction in items}


def test_a_wound_string_pulls_the_rim_down_and_the_block_up(drawn):
    solution, diagrams = drawn["string_wrapped_disk"]
    R = middle(solution.problem, "R")  # the cord leaves the rim on the right (side: right), straight down
    assert forces(diagrams["disk"]) == expected(
        ("R_{x}^{\\mathrm{axle}}", (0, 0), (1, 0)), ("R_{y}^{\\mathrm{axle}}", (0, 0), (0, 1)),
        ("T_{\\mathrm{string}}", (R, 0), (0, -1)), ("M g", (0, 0), (0, -1)))
    assert forces(diagrams["block"]) == expected(("T_{\\mathrm{string}}", (0, 0), (0, 1)), ("g m", (0, 0), (0, -1)))
    assert diagrams["disk"].turns == diagrams["block"].turns == ()


def test_an_atwood_pulley_feels_each_sides_tension_at_its_tangent_point(drawn):
    solution, diagrams = drawn["atwood"]
    R = middle(solution.problem, "R")  # Serway & Jewett ch. 10: the cord leaves the pulley at (-R, 0) and (R, 0)
    assert forces(diagrams["pulley"]) == expected(
        ("R_{x}^{\\mathrm{axle}}", (0, 0), (1, 0)), ("R_{y}^{\\mathrm{axle}}", (0, 0), (0, 1)),
        ("T_{\\mathrm{rope},1}", (-R, 0), (0, -1)), ("T_{\\mathrm{rope},2}", (R, 0), (0, -1)), ("M g", (0, 0), (0, -1)))
    assert forces(diagrams["left"]) == expected(("T_{\\mathrm{rope},1}", (0, 0), (0, 1)), ("g m_{1}", (0, 0), (0, -1)))
    assert forces(diagrams["right"]) == expected(("T_{\\mathrm{rope},2}", (0, 0), (0, 1)), ("g m_{2}", (0, 0), (0, -1)))


def test_a_ladder_feels_the_floor_at_its_foot_and_the_wall_at_its_head(drawn):
    solution, diagrams = drawn["ladder"]
    L, theta = middle(solution.problem, "L"), middle(solution.problem, "theta")
    foot = (L / 2 * math.cos(theta), -L / 2 * math.sin(theta))  # the rod's start, at angle pi - theta
    head = (-foot[0], -foot[1])
    assert forces(diagrams["ladder"]) == expected(
        ("N^{\\mathrm{foot}}", foot, (0, 1)), ("f^{\\mathrm{foot}}", foot, (1, 0)),  # off the floor; along +x
        ("N^{\\mathrm{head}}", head, (1, 0)), ("M g", (0, 0), (0, -1)))  # off the wall, which faces right


def test_a_rolling_sphere_feels_the_incline_at_its_contact_point(drawn):
    solution, diagrams = drawn["rolling_incline"]
    R, theta = middle(solution.problem, "R"), middle(solution.problem, "theta")
    normal = (math.sin(theta), math.cos(theta))  # the incline descends to the right
    contact = (-R * normal[0], -R * normal[1])
    assert forces(diagrams["ball"]) == expected(
        ("N^{\\mathrm{ball}}", contact, normal), ("f^{\\mathrm{ball}}", contact, (math.cos(theta), -math.sin(theta))),
        ("M g", (0, 0), (0, -1)))


def test_each_arrow_is_drawn_at_its_point_along_its_direction(drawn):
    """In the TikZ: for each force an arrow from its point (a pull) or to it (a push on the rim),
    along its direction, the point at the force's offset times the diagram's scale; a push only
    where the force points into the body from away from its center."""
    checked = 0
    for _, diagrams in drawn.values():
        for diagram in diagrams.values():
            lines = [((float(m[1]), float(m[2])), (float(m[3]), float(m[4]))) for m in ARROW.finditer(diagram.tikz)]
            assert len(lines) == len(diagram.arrows)
            for arrow in diagram.arrows:
                point = (arrow.offset[0] * diagram.scale, arrow.offset[1] * diagram.scale)

                def along(start, end):
                    length = math.hypot(end[0] - start[0], end[1] - start[1])
                    return length > 0.5 and all(abs((end[k] - start[k]) / length - arrow.direction[k]) < 0.02
                                                for k in (0, 1))

                pulls = [s for s, e in lines if math.dist(s, point) <= TOLERANCE and along(s, e)]
                pushes = [e for s, e in lines if math.dist(e, point) <= TOLERANCE and along(s, e)]
                assert pulls or pushes, (diagram.body, arrow)
                inward = arrow.offset[0] * arrow.direction[0] + arrow.offset[1] * arrow.direction[1] < 0
                assert not pushes or pulls or inward, (diagram.body, arrow)
                assert f"{{${arrow.label}$}}" in diagram.tikz
                checked += 1
    assert checked == 6 + 9 + 4 + 3


def test_the_students_diagram_names_each_force_as_a_textbook_does_even_one_the_route_never_solves_for():
    """A sphere rolling down a slope from rest to a speed: the route along the slope needs only f, but the
    diagram draws the normal force too, as N (it was N^ball, the file's key for the sphere)."""
    from derive.solution import textbook

    solution = Solution(problem.load("sphere_rolls_down"))
    along = solution.textbook_route.along
    diagram = free_bodies(solution.problem, solution.dynamics_scene, solution.coordinates, along.acting,
                          textbook.names(solution))["ball"]
    assert sorted(a.label for a in diagram.arrows) == ["M g", "N", "f"]


def test_two_normal_forces_are_named_after_their_surfaces_where_words_name_them_else_after_their_bodies():
    """The ladder's N_floor and N_wall; the double wedge's faces are keys (left_side), so its blocks'
    normal forces are N_1 and N_2, never N_{left, side}."""
    from conftest import derived
    from derive.solution import textbook as student

    ladder = {str(u): str(v) for u, v in student.names(derived(textbook("ladder_statics"))).items()}
    wedge = {str(u): str(v) for u, v in student.names(derived(textbook("double_wedge_pulley"))).items()}
    assert {ladder["N^foot"], ladder["N^head"]} == {"N_floor", "N_wall"}
    assert (wedge["N^block1"], wedge["N^block2"]) == ("N_1", "N_2")


def test_each_label_is_a_term_of_the_bodys_balance(drawn):
    for name, (solution, diagrams) in drawn.items():
        steps = {s.body: s for s in solution.derivations["newton_euler"].steps if s.body}
        assert set(steps) == set(diagrams), name
        for body, diagram in diagrams.items():
            equations = " ".join(latex_of(e) for e in steps[body].equations)
            for label in [a.label for a in diagram.arrows] + [t.label for t in diagram.turns]:
                assert label in equations, (name, body, label)


def test_couples_turn_their_way_and_a_force_that_changes_with_time_leaves_its_body_out(tmp_path):
    path = write_problem(tmp_path, """\
id: wheel_and_block
title: A wheel turned by a couple, a block pushed
parameters:
  M: {meaning: mass of the wheel, unit: kg, value: 2}
  R: {meaning: radius of the wheel, unit: m, value: 0.5}
  tau: {meaning: couple, unit: N*m, value: 3}
  m: {meaning: mass of the block, unit: kg, value: 1}
  F: {meaning: push, unit: N, value: 4}
  w: {meaning: its angular frequency, unit: rad/s, value: 2}
scene:
  bodies:
    wheel: {shape: disk, mass: M, radius: R, joint: fixed_axle}
    block: {shape: point, mass: m, at: [6*R, 0]}
  loads:
    - torque: {on: wheel, magnitude: -tau}
    - force: {on: block, magnitude: F*cos(w*t)}
ask:
  alpha: {meaning: angular acceleration, of: wheel.angular_acceleration, unit: rad/s^2}
  a: {meaning: acceleration, of: block.acceleration.x, unit: m/s^2}
question: Find them.
""")
    solution = Solution(problem.load(path))
    diagrams = free_bodies(solution.problem, solution.dynamics_scene, solution.coordinates)
    assert diagrams["block"] is None
    (turn,) = diagrams["wheel"].turns
    assert (turn.sign, turn.label) == (-1, "\\tau")  # clockwise, labelled with its size
    assert re.search(r"\\draw\[force\] \(.*\) arc\[start angle=(-?[\d.]+), end angle=(-?[\d.]+)", diagrams["wheel"].tikz)
    start, end = map(float, re.search(r"arc\[start angle=(-?[\d.]+), end angle=(-?[\d.]+)", diagrams["wheel"].tikz).groups())
    assert end < start  # clockwise


def test_same_problem_same_bytes_in_any_process(drawn):
    digest = hashlib.sha256("".join(d.tikz for _, diagrams in drawn.values() for d in diagrams.values()).encode()).hexdigest()
    code = ("import hashlib; from derive.language import problem; from derive.solution.answers import Solution; "
            "from derive.publishing.figure.free_body import free_bodies\n"
            "text = ''\n"
            f"for reference in {list(PROBLEMS.values())!r}:\n"
            "    s = Solution(problem.load(reference))\n"
            "    text += ''.join(d.tikz for d in free_bodies(s.problem, s.dynamics_scene, s.coordinates).values())\n"
            "print(hashlib.sha256(text.encode()).hexdigest())")
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, cwd=ROOT,
                          env={**os.environ, "PYTHONHASHSEED": "7"}, timeout=300)
    assert done.stdout.strip() == digest, done.stderr


def test_the_solutions_show_each_diagram_after_its_step_and_compile_with_nothing_off_the_page(drawn, tmp_path):
    built = worksheets.build(list(PROBLEMS.values()), out_dir=str(tmp_path / "set"), formats=frozenset({"pdf"}))
    tex = next(p for p in built if p.name == "solutions.tex")
    text = tex.read_text()
    appendix = text.index("\\appendix")
    students = 0
    for name, (solution, diagrams) in drawn.items():
        title = text.index(tex_escape(solution.problem.title))
        student = variants.ProblemVariants(solution.problem, solution, []).student_free_bodies
        route = text[title:text.index("\\subsection*{Results}", title)]  # the student's route, before the results
        # one diagram beside each balance (their labels are the documents' own letters: derive.publishing.letters)
        assert route.count("\\begin{tikzpicture}") >= len(student), name
        students += len(student)
        proof = text.index(tex_escape(solution.problem.title), appendix)  # the proof by two routes, in the appendix
        # (the steps' words are the documents' own: derive.publishing.wording; the labels its letters: F_x^axle beside R)
        proofs = variants.ProblemVariants(solution.problem, solution, []).free_bodies
        assert len(proofs) == len(diagrams), name
        for diagram in proofs.values():
            assert text.index(diagram.tikz, proof) > appendix, (name, diagram.body)
    assert text.count("\\begin{tikzpicture}") == len(PROBLEMS) + students + sum(len(d) for _, d in drawn.values())
    assert (tmp_path / "set" / "solutions.pdf").read_bytes().startswith(b"%PDF")
    assert _overfull(tex, tmp_path) == []


def test_the_handout_shows_the_diagrams_and_compiles_with_nothing_off_the_page(drawn, tmp_path):
    done = run_derive("handout", "rolling_incline", "--out", str(tmp_path / "h"), "--progress", "none")
    assert done.returncode == 0, done.stderr
    tex = tmp_path / "h" / "rolling_incline.tex"
    text = tex.read_text()
    newton_euler = text.index("\\subsection*{Newton")  # the proof by two routes, after the student's route
    for diagram in drawn["rolling_incline"][1].values():
        assert text.index(diagram.tikz) > newton_euler
    assert _overfull(tex, tmp_path) == []


def test_the_lms_feedback_shows_the_diagrams_as_images_not_tikz(drawn, tmp_path):
    """The worked solutions pandoc turns into each question's feedback carry no TikZ (pandoc reads
    none): each diagram is an image there, right after its balance step (tests/test_lms_free_body.py
    checks the images), and no centered block is left empty."""
    solution, _ = drawn["string_wrapped_disk"]
    built = worksheets.build(["string_wrapped_disk"], out_dir=str(tmp_path / "lms"), formats=frozenset({"moodle"}))
    xml = next(p for p in built if p.name == "moodle.xml").read_text()
    feedback = html.unescape(re.search(r"<generalfeedback format=\"html\">\s*<text>(.*?)</text>", xml, re.S)[1])
    heading = next(s.text for section in solution.student_steps.values() for s in section if s.body == "block")
    assert heading.replace("'", "’") in " ".join(feedback.split())
    assert "tikzpicture" not in xml and "draw[force]" not in xml
    centered = re.findall(r'<div class="center">(.*?)</div>', feedback, re.S)
    assert len(centered) == 2 and all("<img " in block for block in centered)  # the disk's and the block's
