"""Cords stated as paths: a smooth peg in the middle of a cord (a ground point between its
ends). Closed forms from Halliday, Resnick & Walker, Fundamentals of Physics, 10th ed., ch. 5,
Sample Problem 5.04 (a block on a frictionless table pulled by a hanging block): a = m2 g /
(m1 + m2), T = m1 m2 g / (m1 + m2)."""
import sympy as sp

from conftest import run_derive
from derive.solution.answers import Solution
from derive.language.problem import load
from derive.publishing import wording

TABLE_AND_PEG = """\
id: table_peg
title: A block on a table pulled by a hanging block over a smooth peg
topic: torque
parameters:
  m1: {meaning: mass on the table, unit: kg, range: [1, 3], sig_figs: 3}
  m2: {meaning: hanging mass, unit: kg, range: [0.5, 2], sig_figs: 3}
  d: {meaning: distance of each block from the peg, unit: m, value: 1}
  g: {meaning: gravitational acceleration, unit: m/s^2, value: 9.81}
scene:
  surfaces:
    table: {plane: {angle: 0}}
  bodies:
    block: {shape: point, mass: m1, at: [-d, 0], on: table, contact: sliding}
    hanging: {shape: point, mass: m2, at: [0, -d]}
  points:
    edge: [0, 0]
  cords:
    rope: [block, PEG, hanging]
  loads:
    - gravity: g
ask:
  a: {meaning: acceleration of the hanging block (y up), of: hanging.acceleration.y, unit: m/s^2}
  T: {meaning: tension, of: rope.tension, unit: N}
question: |
  A block of mass {{ m1 }} on a smooth table is pulled by a block of mass {{ m2 }} hanging from
  a cord over a smooth peg at the table's edge.
"""


def test_a_ground_point_inside_a_cord_is_a_smooth_peg(tmp_path):
    path = tmp_path / "peg.yaml"
    path.write_text(TABLE_AND_PEG.replace("PEG", "edge"))
    problem = load(path)
    solution = Solution(problem)
    m1, m2, g = (problem.parameters[k].symbol for k in ("m1", "m2", "g"))
    assert sp.simplify(solution.signed("a") + m2 * g / (m1 + m2)) == 0
    assert sp.simplify(solution.signed("T") - m1 * m2 * g / (m1 + m2)) == 0
    result = run_derive("solve", str(path))
    assert result.returncode == 0, result.stderr
    assert "[ok] lagrange_vs_newton_euler" in result.stdout


def test_a_peg_is_the_limit_of_a_smooth_pulley(tmp_path):
    """The same cord over a smooth pulley of radius r: the answers do not depend on r."""
    peg = tmp_path / "peg.yaml"
    peg.write_text(TABLE_AND_PEG.replace("PEG", "edge"))
    pulley = tmp_path / "pulley.yaml"
    pulley.write_text(TABLE_AND_PEG.replace("PEG", "{over: edge, radius: d/4, smooth: true}")
                      .replace("edge: [0, 0]", "edge: [0, -d/4]").replace("at: [0, -d]", "at: [d/4, -d]"))
    by_peg, by_pulley = Solution(load(peg)), Solution(load(pulley))
    for name in ("a", "T"):
        assert sp.simplify(by_peg.signed(name) - by_pulley.signed(name)) == 0


INCLINE_AND_PULLEY = """\
id: incline_pulley
title: A block on a smooth incline pulled over a disk pulley by a hanging block
topic: torque
parameters:
  m1: {meaning: mass of the block on the incline, unit: kg, range: [1, 2], sig_figs: 3}
  m2: {meaning: mass of the hanging block, unit: kg, range: [2, 3], sig_figs: 3}
  M: {meaning: mass of the pulley (a uniform disk), unit: kg, range: [0.5, 2], sig_figs: 3}
  R: {meaning: radius of the pulley, unit: m, range: [0.1, 0.2], sig_figs: 2}
  theta: {meaning: angle of the incline, unit: rad, range: [0.2, 0.5], sig_figs: 2}
  g: {meaning: gravitational acceleration, unit: m/s^2, value: 9.81}
scene:
  surfaces:
    ramp: {plane: {angle: theta, through: [0, 0]}}
  bodies:
    block: {shape: point, mass: m1, at: [10*R*cos(theta), -10*R*sin(theta)], on: ramp}
    pulley: {shape: disk, mass: M, radius: R, at: [SIDE*R*sin(theta), SIDE*R*cos(theta)], joint: fixed_axle}
    hanger: {shape: point, mass: m2, at: [SIDE*R*sin(theta) - R, -10*R]}
  cords:
    rope: [block, {over: pulley}, hanger]
  loads:
    - gravity: g
ask:
  ay: {meaning: acceleration of the hanging block (y up), of: hanger.acceleration.y, unit: m/s^2}
  a: {meaning: acceleration of the block down the incline, of: block.acceleration.down_incline, unit: m/s^2}
question: |
  A block on an incline is pulled over a pulley by a hanging block.
"""


def _incline_and_pulley(tmp_path, side: str):
    path = tmp_path / f"incline_pulley{side}.yaml"
    path.write_text(INCLINE_AND_PULLEY.replace("SIDE", side))
    problem = load(path)
    symbols = {k: problem.parameters[k].symbol for k in ("m1", "m2", "M", "theta", "g")}
    return path, Solution(problem), symbols


def test_a_pulley_whose_top_is_in_line_with_the_incline(tmp_path):
    """The textbook's incline and pulley (Serway & Jewett, 9th ed., ch. 10: the cord runs along
    the incline to the pulley's top): a = g (m2 - m1 sin(theta))/(m1 + m2 + M/2). The cord's
    tangent geometry has roots of trigonometric polynomials (|D|^2 = 101 R^2 once sin^2 + cos^2
    folds); before tidying.radicals sympy's linear solve did not finish in 15 minutes."""
    path, solution, s = _incline_and_pulley(tmp_path, "-1")
    expected = s["g"] * (s["m2"] - s["m1"] * sp.sin(s["theta"])) / (s["m1"] + s["m2"] + s["M"] / 2)
    assert sp.simplify(solution.signed("ay") + expected) == 0
    assert sp.simplify(solution.signed("a") + expected) == 0  # the block goes up the incline
    result = run_derive("solve", str(path))
    assert result.returncode == 0, result.stderr
    assert "[ok] lagrange_vs_newton_euler" in result.stdout


def test_a_pulley_above_the_incline_pulls_at_an_angle(tmp_path):
    """The pulley stated above the incline, touching it: the cord goes from the block over the
    pulley's top at alpha to the incline, cos(alpha) = 99/101 (tangent length 10 R at distance
    sqrt(101) R from the center). By hand (Newton, from rest): m1 a_b = T1 cos(alpha) - m1 g
    sin(theta) up the incline, (M R^2/2) a_h/R = (T2 - T1) R, m2 a_h = m2 g - T2, a_h = a_b
    cos(alpha): a_h = g c (m2 c - m1 sin(theta))/(c^2 (M/2 + m2) + m1), with c = cos(alpha)."""
    path, solution, s = _incline_and_pulley(tmp_path, "1")
    c = sp.Rational(99, 101)
    falls = s["g"] * c * (s["m2"] * c - s["m1"] * sp.sin(s["theta"])) / (c**2 * (s["M"] / 2 + s["m2"]) + s["m1"])
    assert sp.simplify(solution.signed("ay") + falls) == 0
    assert sp.simplify(solution.signed("a") + falls / c) == 0


def test_a_plane_at_a_negative_angle_is_refused(tmp_path):
    """A plane's angle lies in [0, pi/2): it descends to the right, and `down_incline` is down it.
    An angle in symbols that the ranges make negative (the left face of a double incline, -alpha)
    would turn `down` up the slope; it is refused, as a number outside [0, pi/2) is."""
    path = tmp_path / "left_face.yaml"
    path.write_text("""\
id: left_face
title: A block on the left face of a double incline
topic: dynamics
parameters:
  m: {meaning: mass of the block, unit: kg, range: [1, 2], sig_figs: 3}
  theta: {meaning: angle of the face, unit: rad, range: [0.2, 0.5], sig_figs: 2}
  d: {meaning: distance of the block from the top, unit: m, value: 1}
  g: {meaning: gravitational acceleration, unit: m/s^2, value: 9.81}
scene:
  surfaces:
    face: {plane: {angle: -theta, through: [0, 0]}}
  bodies:
    block: {shape: point, mass: m, at: [-d*cos(theta), -d*sin(theta)], on: face, contact: sliding}
  loads:
    - gravity: g
ask:
  a: {meaning: acceleration of the block down the incline, of: block.acceleration.down_incline, unit: m/s^2}
question: |
  A block slides on a smooth incline.
""")
    result = run_derive("solve", str(path))
    assert result.returncode == 2, result.stdout
    assert "the plane face's angle -theta is negative" in result.stderr


#: The new-user trial's cylinder on a smooth incline, its cord tied up the slope at the height of its
#: top (Kleppner & Kolenkow ch. 7 problems): `side: top` leaves the top parallel to the incline, a =
#: 2 g sin(theta)/3; `side: left` winds it the other way, on the other tangent from the peg.
UNWINDING = """\
id: cylinder_unwinding_incline
title: A cylinder unwinds a cord tied at the top of a smooth incline
topic: rolling
parameters:
  M: {meaning: mass of the cylinder, unit: kg, range: [0.5, 5], sig_figs: 3}
  R: {meaning: radius of the cylinder, unit: m, range: [0.05, 0.3], sig_figs: 3}
  theta: {meaning: angle of the incline, unit: rad, range: [0.2, 1.2], sig_figs: 3}
  D: {meaning: free length of the cord, unit: m, range: [0.5, 2], sig_figs: 3}
  g: {meaning: gravitational acceleration, unit: m/s^2, value: 9.81}
scene:
  surfaces:
    ramp: {incline: {angle: theta, through: [0, 0]}}
  points:
    peg: [2*R*sin(theta) - D*cos(theta), 2*R*cos(theta) + D*sin(theta)]
  bodies:
    cyl: {shape: cylinder, mass: M, radius: R, height: R, at: [R*sin(theta), R*cos(theta)], on: ramp, contact: sliding}
  cords:
    cord: [peg, {wound: cyl, side: SIDE}]
  loads:
    - gravity: g
ask:
  a: {meaning: acceleration of the cylinder down the incline, of: cyl.acceleration.down_incline, unit: m/s^2}
question: |
  A cylinder of mass {{ M }} and radius {{ R }} on an incline at {{ theta }} unwinds a cord of free length {{ D }}.
"""


def test_derive_solve_says_which_tangent_a_side_takes(tmp_path):
    """The answers are the geometry's; what the side chose is said, with the sides that choose the other."""
    (tmp_path / "top.yaml").write_text(UNWINDING.replace("SIDE", "top"))
    (tmp_path / "left.yaml").write_text(UNWINDING.replace("SIDE", "left"))
    top, left = (run_derive("solve", str(tmp_path / f"{side}.yaml")) for side in ("top", "left"))
    assert top.returncode == 0 and left.returncode == 0, top.stderr + left.stderr
    assert "How the cords run" in top.stdout
    # theta = 0.7 at the middle of the ranges: the top of the cylinder is 0.7 rad (40 degrees) past the
    # vertical, 50 degrees from its right
    # in the documents' words (derive.publishing.wording): the cord, the cylinder, not the file's keys cord and cyl
    assert ("The cord is wound on the cylinder clockwise (side: top) and leaves it at its upper right (50 degrees "
            "round from its right, counter-clockwise), toward the ground point; side: under, left, bottom would wind "
            "it the other way, on the other tangent.") in top.stdout
    assert ("The cord is wound on the cylinder counter-clockwise (side: left) and leaves it at its lower left "
            "(214 degrees round from its right, counter-clockwise), toward the ground point; side: over, right, top "
            "would wind it the other way, on the other tangent.") in left.stdout
    assert "D" not in top.stdout.split("Answers:")[1].split("(acceleration")[0]  # parallel: no free length
    solution = Solution(load(tmp_path / "left.yaml"))
    assert solution.signed("a").has(solution.problem.parameters["D"].symbol)  # at an angle: it has
    said = wording.Wording(solution.problem)(solution.steps()["how the cords run"][0].text)
    assert said in left.stdout  # the worked solution says it too


def test_a_wound_end_leaving_from_the_far_half_of_its_side_is_said(tmp_path):
    """A disk on an axle with a block close below its right half: `side: top` winds it clockwise, and
    the tangent to the block leaves the rim below its middle (n = (0.935, -0.355) for R = 1)."""
    text = UNWINDING.split("scene:")[0] + """scene:
  bodies:
    cyl: {shape: cylinder, mass: M, radius: R, height: R, joint: fixed_axle}
    block: {shape: point, mass: M, at: [R/2, -3*R/2]}
  joints:
    guide: {slider: block, angle: pi/2}
  cords:
    cord: [{wound: cyl, side: top}, block]
  loads:
    - gravity: g
ask:
  a: {meaning: acceleration of the block, of: block.acceleration.y, unit: m/s^2}
question: |
  A cylinder of mass {{ M }} and radius {{ R }}.
"""
    (tmp_path / "far.yaml").write_text(text.replace("  theta: {meaning: angle of the incline, unit: rad, range: "
                                                    "[0.2, 1.2], sig_figs: 3}\n", "").replace(
        "  D: {meaning: free length of the cord, unit: m, range: [0.5, 2], sig_figs: 3}\n", ""))
    (step,) = Solution(load(tmp_path / "far.yaml")).winding_steps()
    assert "leaves it at its right (339 degrees" in step.text
    assert step.text.endswith("that is not on its top half: the cord leaves from the far side of the circle.")
