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
