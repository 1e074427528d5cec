"""Cords stated as paths: a smooth peg in the middle of a cord (a ground point between its
ends). Closed forms from Halliday, Resnick & Walker, Fundamentals of Physics, 10th ed., ch. 5,
Sample Problem 5.04 (a block on a frictionless table pulled by a hanging block): a = m2 g /
(m1 + m2), T = m1 m2 g / (m1 + m2)."""
import sympy as sp

from conftest import run_derive
from derive.answers import Solution
from derive.problem import load

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
    assert sp.simplify(solution.expression("a") + m2 * g / (m1 + m2)) == 0
    assert sp.simplify(solution.expression("T") - m1 * m2 * g / (m1 + m2)) == 0
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
        assert sp.simplify(by_peg.expression(name) - by_pulley.expression(name)) == 0


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
    folds); before derivation.radicals sympy's linear solve did not finish in 15 minutes."""
    path, solution, s = _incline_and_pulley(tmp_path, "-1")
    expected = s["g"] * (s["m2"] - s["m1"] * sp.sin(s["theta"])) / (s["m1"] + s["m2"] + s["M"] / 2)
    assert sp.simplify(solution.expression("ay") + expected) == 0
    assert sp.simplify(solution.expression("a") + expected) == 0  # the block goes up the incline
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
    assert sp.simplify(solution.expression("ay") + falls) == 0
    assert sp.simplify(solution.expression("a") + falls / c) == 0


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
