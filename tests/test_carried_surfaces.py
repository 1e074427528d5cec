"""Surfaces carried by a body (`surfaces: {NAME: {plane|circle|wall: ..., carried_by: BODY}}`): a
wedge's face, a plank's top, a cart's track, a drum's inside. The contact pushes the carrier
back, and holds the two velocities at the point of contact together.

Closed forms of fixed carriers: the textbook suite (wedge_block, plank_cylinder,
cart_track_bead). Here: a carrier that turns (a ball rolling inside a drum free on its axle),
whose two routes are compared in moving states by the checks, against its limits: a drum too
heavy to turn is a fixed bowl (a ball rolling in a bowl: (R - r) phi'' = -(5/7) g sin(phi)), a
massless drum exerts no friction. And the refusals the part adds."""
import re

import pytest
import sympy as sp

from conftest import run_derive
from derive.publishing import figure, report
from derive.solution.answers import Solution
from derive.language.problem import load

DRUM = """\
id: ball_in_drum
title: A ball rolling inside a drum that turns freely on its axle
topic: rolling
parameters:
  m: {meaning: mass of the ball, unit: kg, range: [0.1, 1], sig_figs: 3}
  r: {meaning: radius of the ball, unit: m, range: [0.01, 0.05], sig_figs: 2}
  M: {meaning: mass of the drum, unit: kg, range: [2, 6], sig_figs: 3}
  R: {meaning: radius of the drum, unit: m, range: [0.3, 1], sig_figs: 2}
  phi: {meaning: angle of the ball from the bottom, unit: rad, range: [0.2, 1], sig_figs: 2}
  g: {meaning: gravitational acceleration, unit: m/s^2, value: 9.81}
scene:
  surfaces:
    inside: {circle: {radius: R, center: [0, 0]}, carried_by: drum}
  bodies:
    drum: {shape: ring, mass: M, radius: R, at: [0, 0], joint: fixed_axle}
    ball: {shape: sphere, mass: m, radius: r, at: [(R - r)*sin(phi), -(R - r)*cos(phi)], on: inside}
  loads:
    - gravity: g
ask:
  alpha: {meaning: angular acceleration of the drum, of: drum.angular_acceleration, unit: rad/s^2}
  ax: {meaning: horizontal acceleration of the ball, of: ball.acceleration.x, unit: m/s^2}
  f: {meaning: friction on the ball, of: ball.friction, unit: N}
question: |
  A ball rolls inside a drum.
"""

WEDGE = """\
id: wedge
title: A block on a wedge
topic: dynamics
parameters:
  m: {meaning: mass of the block, unit: kg, range: [0.5, 2], sig_figs: 3}
  M: {meaning: mass of the wedge, unit: kg, range: [2, 6], sig_figs: 3}
  theta: {meaning: angle of the wedge, unit: rad, range: [0.3, 1.2], sig_figs: 2}
  g: {meaning: gravitational acceleration, unit: m/s^2, value: 9.81}
scene:
  surfaces:
    face: {plane: {angle: theta, through: [0, 0]}, carried_by: wedge}
  bodies:
    wedge: {shape: point, mass: M, at: [0, 0]}
    block: {shape: point, mass: m, at: [0, 0], on: face, contact: sliding}
  joints:
    rail: {slider: wedge, angle: 0}
  loads:
    - gravity: g
ask:
  A: {meaning: acceleration of the wedge, of: wedge.acceleration.x, unit: m/s^2}
question: |
  A block slides on a wedge.
"""


def test_a_ball_in_a_drum_that_turns_meets_its_limits(tmp_path):
    path = tmp_path / "drum.yaml"
    path.write_text(DRUM)
    problem = load(str(path))
    solution = Solution(problem)
    s = {p.symbol.name: p.symbol for p in problem.parameters.values()}
    M, m, g, R, r, phi = (s[k] for k in ("M", "m", "g", "R", "r", "phi"))
    alpha, ax, f = (solution.signed(k) for k in ("alpha", "ax", "f"))
    # Too heavy to turn: a ball rolling in a fixed bowl, at rest at phi: its center accelerates
    # along the circle by (5/7) g sin(phi), toward the bottom (-x at this side).
    assert sp.limit(alpha, M, sp.oo) == 0
    assert sp.simplify(sp.limit(ax, M, sp.oo) + sp.Rational(5, 7) * g * sp.sin(phi) * sp.cos(phi)) == 0
    # Massless: it cannot take a torque, so nothing grips the ball, which slides as on a smooth bowl.
    assert sp.simplify(f.xreplace({M: 0})) == 0
    assert sp.simplify(alpha.xreplace({M: 0}) + g * sp.sin(phi) / R) == 0
    # The drum turns the way the friction on it pushes: opposite to the friction on the ball.
    assert sp.simplify(alpha * R * M + f) == 0
    checks = report.solve(problem, solution=solution)["checks"]
    assert all(c["passed"] for c in checks.values()), checks


@pytest.mark.parametrize("change, field, reason", [
    ({"carried_by: wedge": "carried_by: cart"}, "scene.surfaces.face.carried_by", "no body 'cart'"),
    ({"carried_by: wedge": "carried_by: [wedge]"}, "scene.surfaces.face.carried_by", "a body's name is a letter"),
    ({"wedge: {shape: point, mass: M, at: [0, 0]}": "wedge: {shape: point, mass: M, at: [0, 0], on: face}"},
     "scene.bodies.wedge.on", "the wedge carries face: it cannot rest on it"),
    ({"of: wedge.acceleration.x": "of: block.acceleration.down_incline"}, "ask.A.of", "moves with the wedge"),
])
def test_a_carried_surface_that_does_not_fit_is_refused_naming_the_field(tmp_path, change, field, reason):
    text = WEDGE
    for old, new in change.items():
        text = text.replace(old, new)
    path = tmp_path / "wedge.yaml"
    path.write_text(text)
    result = run_derive("solve", str(path))
    assert result.returncode == 2, result.stdout
    line = result.stderr.strip()
    assert line.count("\n") == 0 and f"wedge.yaml: {field}: " in line and reason in line, line


def test_a_carried_surface_is_drawn_with_its_carrier_never_as_ground(tmp_path):
    """The wedge's face is the top of the wedge, a solid that moves: no fixed incline (shaded, its
    base hatched) but the rail's floor. The same scene with the face fixed draws a fixed incline;
    a carrier the figure cannot draw as its surface's solid (a disk) leaves the figure out."""
    path = tmp_path / "wedge.yaml"
    path.write_text(WEDGE)
    carried = figure.tikz(load(str(path)))
    assert "\\draw[fill=gray!10]" not in carried and carried.count("pattern=north east lines") == 1  # the rail's
    assert re.search(r"\\draw\[body\] \(\S+\) -- \(\S+\) -- \(\S+\) -- cycle;", carried)  # the wedge
    fixed = tmp_path / "fixed.yaml"
    fixed.write_text(WEDGE.replace(", carried_by: wedge", "").replace("rail: {slider: wedge, angle: 0}",
                                                                         "rail: {slider: wedge, angle: 0, turns: true}"))
    assert "\\draw[fill=gray!10]" in figure.tikz(load(str(fixed)))
    disk = tmp_path / "disk.yaml"
    disk.write_text(WEDGE.replace("wedge: {shape: point, mass: M, at: [0, 0]}",
                                  "wedge: {shape: disk, mass: M, radius: R, at: [0, 0]}")
                    .replace("  g: {", "  R: {meaning: radius of the disk, unit: m, range: [1, 2], sig_figs: 2}\n  g: {"))
    assert figure.tikz(load(str(disk))) is None
