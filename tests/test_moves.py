"""Moves in a chain of states (`event: {move: BODY, to: POINT}`; derive.mechanics.moves): the
textbook closed forms are in tests/textbook/states (a child walking to a turntable's center, a
student on a stool pulling in two weights); here a free body, each refusal, and the second
route shown to catch a wrong move; and turns (`event: {turn: BODY, relative_to: OTHER, angle:
psi}`), with Elroy's beanie's closed forms in tests/test_events.py."""

import dataclasses

import pytest
import sympy as sp

from conftest import refused, run_derive, textbook, write_problem
from derive.language import problem
from derive.publishing import report
from derive.solution.answers import Solution
from derive.solution.crosschecks import CheckFailure
from derive.mechanics import moves

FREE = """\
id: bead_on_free_rod
title: A bead walks to the middle of a spinning rod in space
topic: conservation
parameters:
  m: {meaning: mass of the bead, unit: kg, range: [0.1, 0.5], sig_figs: 2}
  M: {meaning: mass of the rod, unit: kg, range: [1, 2], sig_figs: 2}
  L: {meaning: length of the rod, unit: m, range: [1, 2], sig_figs: 2}
  w0: {meaning: angular velocity of the rod, unit: rad/s, range: [1, 3], sig_figs: 2}
scene:
  bodies:
    rod: {shape: rod, mass: M, length: L}
    bead: {shape: point, mass: m, at: [L/2, 0]}
  joints:
    hold: {pin: bead, to: rod.end}
  states:
    spinning: {rates: {rod.angular_velocity: w0, rod.velocity.x: 0, rod.velocity.y: 0}}
    middle: {from: spinning, event: {move: bead, to: MIDDLE}}
ask:
  omega: {meaning: angular velocity of the rod after, of: rod.angular_velocity, in: middle, unit: rad/s}
  K: {meaning: kinetic energy after, of: kinetic_energy, in: middle, unit: J}
question: |
  A bead at the end of a rod spinning in space walks to its middle.
"""

SWING = """\
id: swing_stands_up
title: A child on a swing stands up
topic: conservation
parameters:
  m: {meaning: mass of the child, unit: kg, range: [20, 40], sig_figs: 2}
  M: {meaning: mass of the swing, unit: kg, range: [2, 4], sig_figs: 2}
  L: {meaning: length of the swing, unit: m, range: [2, 3], sig_figs: 2}
  w0: {meaning: angular velocity at the bottom, unit: rad/s, range: [1, 2], sig_figs: 2}
  g: {meaning: gravitational acceleration, unit: m/s^2, value: 9.81}
scene:
  bodies:
    swing: {shape: rod, mass: M, length: L, at: [0, -L/2], angle: -pi/2}
    child: {shape: point, mass: m, at: [0, -L]}
  joints:
    hook: {pin: swing.start}
    seat: {pin: child, to: swing.end}
  loads:
    - gravity: g
  states:
    low: {rates: {swing.angular_velocity: w0}}
    up: {from: low, event: {move: child, to: {swing: [L/4, 0]}}}
ask:
  omega: {meaning: angular velocity after, of: swing.angular_velocity, in: up, unit: rad/s}
question: |
  A child on a swing stands up as it passes the bottom.
"""


def test_a_free_body_keeps_its_momentum_and_its_angular_momentum_about_the_center_of_mass(tmp_path):
    """A bead at the end of a free rod (spinning about its own middle, so the whole moves) walks
    to the middle: the center of mass moves on at m w0 L/(2 (M + m)), and the angular momentum
    about it, w0 L^2 (M/12 + m M/(4 (M + m))), is the rod's alone after: omega = w0 (M + 4 m)/(M + m)."""
    solution = Solution(problem.load(write_problem(tmp_path, FREE.replace("MIDDLE", "rod.center"))))
    m, M, L, w0 = (solution.problem.parameters[n].symbol for n in ("m", "M", "L", "w0"))
    omega = w0 * (M + 4 * m) / (M + m)
    assert sp.simplify(solution.expression("omega") - omega) == 0
    speed = m * w0 * L / (2 * (M + m))
    assert sp.simplify(solution.expression("K") - ((M + m) * speed**2 / 2 + M * L**2 * omega**2 / 24)) == 0
    checks = report.solve(solution.problem, solution=solution)["checks"]
    assert all(c["passed"] for c in checks.values()), checks
    assert "move" in checks["states"]["detail"]


def test_a_move_under_a_weights_moment_is_refused_as_an_engine_limit(tmp_path):
    """Standing up on a swing: the weight has a moment about the pivot, so no momentum is kept
    whatever the move's duration; derive does not model the quick move, and says so (exit 1)."""
    result = run_derive("solve", str(write_problem(tmp_path, SWING)))
    assert result.returncode == 1, result.stdout + result.stderr
    assert "derive cannot yet find the rates after this move: it keeps no momentum" in result.stderr and "scene.states.up" in result.stderr


@pytest.mark.parametrize("change, field, words", [
    ("{move: rod, to: rod.center}", "scene.states.middle.event.move", "carries a point mass"),
    ("{move: bead, to: [0, 0]}", "scene.states.middle.event.to", "expected a point of a body"),
    ("{move: bead, to: {rod: [2*L, 0]}}", "scene.states.middle.event.to", "outside the rod"),
    ("{move: bead, to: rod.center, restitution: 1}", "scene.states.middle.event.restitution", "has no restitution"),
])
def test_a_wrong_move_is_refused_naming_its_field(tmp_path, change, field, words):
    text = FREE.replace("{move: bead, to: MIDDLE}", change)
    assert words in refused(tmp_path, text, field)


def test_a_move_needs_the_pin_that_holds_the_point_mass(tmp_path):
    text = FREE.replace("    hold: {pin: bead, to: rod.end}\n", "    hold: {pin: bead, to: rod.end}\n"
                                                                  "    other: {pin: bead, to: rod.end}\n")
    assert "held by one pin" in refused(tmp_path, text.replace("MIDDLE", "rod.center"), "scene.states.middle.event.move")


def test_only_angular_velocities_and_energies_are_asked_after_a_move(tmp_path):
    text = FREE.replace("MIDDLE", "rod.center").replace("of: rod.angular_velocity, in: middle",
                                                        "of: rod.velocity.x, in: middle")
    assert "depends on how it is made" in refused(tmp_path, text, "ask.omega")


def test_only_a_move_follows_a_move(tmp_path):
    text = FREE.replace("MIDDLE", "rod.center").replace(
        "    middle: {from: spinning, event: {move: bead, to: rod.center}}\n",
        "    middle: {from: spinning, event: {move: bead, to: rod.center}}\n    later: {from: middle, when: stops}\n")
    assert "only another move or a turn may follow it" in refused(tmp_path, text, "scene.states.later.from")


def test_a_state_may_not_take_a_joints_name(tmp_path):
    text = FREE.replace("MIDDLE", "rod.center").replace("middle:", "hold:").replace("in: middle", "in: hold")
    assert "is taken" in refused(tmp_path, text, "scene.states.hold")


def test_the_second_route_catches_a_wrong_move(tmp_path, monkeypatch):
    """Newton–Euler's moments against Lagrange's symmetries: angular momentum with the bodies'
    spins counted twice is caught."""
    path = write_problem(tmp_path, FREE.replace("MIDDLE", "rod.center"))
    original = moves.Symmetry.momentum

    def spins_twice(self, coords):
        spins = sum((coords.scene.bodies[n].inertia * coords.angular_velocity(n)
                     for n in self.moved if coords.scene.bodies[n].rotates and self.about is not None), sp.Integer(0))
        return original(self, coords) + spins

    monkeypatch.setattr(moves.Symmetry, "momentum", spins_twice)
    with pytest.raises(CheckFailure, match="after the move middle"):
        report.solve(problem.load(path), {}, 4)


def test_a_speed_after_a_move_is_asked_only_where_nothing_shifts(tmp_path):
    """On a turntable the child's speed after walking in to R/2 is omega R/2 however the walk was
    made; on a free rod the bead's is not (the rod's drift adds to it at an angle the walk decides)."""
    text = (textbook("child_walks_to_center")).read_text()
    text = text.replace("to: platform.center}", "to: {platform: [R/2, 0]}}").replace(
        "ask:\n", "ask:\n  v: {meaning: the child's speed, of: child.speed, in: centered, unit: m/s}\n")
    solution = Solution(problem.load(write_problem(tmp_path, text)))
    R = solution.problem.parameters["R"].symbol
    assert sp.simplify(solution.expression("v") - solution.expression("omega") * R / 2) == 0
    free = FREE.replace("MIDDLE", "{rod: [L/4, 0]}").replace(
        "ask:\n", "ask:\n  v: {meaning: the bead's speed, of: bead.speed, in: middle, unit: m/s}\n")
    assert "free to shift" in refused(tmp_path, free, "ask.v.in")


SPINNING_BEANIE = """\
id: spinning_beanie
title: Elroy's beanie, spinning
topic: conservation
parameters:
  I1: {meaning: moment of inertia of the outer oval, unit: kg*m^2, range: [0.01, 0.1], sig_figs: 2}
  I2: {meaning: moment of inertia of the inner oval, unit: kg*m^2, range: [0.001, 0.05], sig_figs: 2}
  w0: {meaning: angular velocity of the outer oval, unit: rad/s, range: [1, 2], sig_figs: 2}
scene:
  bodies:
    outer: {shape: custom, inertia: I1, joint: fixed_axle}
    inner: {shape: custom, inertia: I2, joint: fixed_axle}
  states:
    spinning: {rates: {outer.angular_velocity: w0, inner.angular_velocity: 0}}
    turned: {from: spinning, event: {turn: inner, relative_to: outer, angle: pi}}
ask:
  omega: {meaning: angular velocity of the outer oval after, of: outer.angular_velocity, in: turned, unit: rad/s}
question: |
  The inner oval of a spinning beanie is turned half around relative to the outer one.
"""


def test_a_turn_keeps_the_angular_momentum_and_ends_with_the_bodies_turning_together(tmp_path):
    """I1 w0 = (I1 + I2) omega: the turn ends with the inner oval at rest relative to the outer."""
    solution = Solution(problem.load(write_problem(tmp_path, SPINNING_BEANIE)))
    I1, I2, w0 = (solution.problem.parameters[n].symbol for n in ("I1", "I2", "w0"))
    assert sp.simplify(solution.expression("omega") - I1 * w0 / (I1 + I2)) == 0


def test_an_angle_after_a_turn_that_keeps_a_momentum_is_refused(tmp_path):
    """With angular momentum, where the ovals end depends on how long the turn takes."""
    text = SPINNING_BEANIE.replace("of: outer.angular_velocity, in: turned, unit: rad/s",
                                   "of: outer.angle, in: turned, unit: rad")
    assert "depend on how long it takes" in refused(tmp_path, text, "ask.omega.of")


def test_a_turn_refuses_what_it_cannot_turn(tmp_path):
    text = SPINNING_BEANIE.replace("angle: pi}", "}")
    assert "missing: a turn gives relative_to and angle" in refused(tmp_path, text, "scene.states.turned.event.angle")
    text = SPINNING_BEANIE.replace("relative_to: outer", "relative_to: inner")
    assert "relative to another" in refused(tmp_path, text, "scene.states.turned.event")
    text = SPINNING_BEANIE.replace("relative_to: outer", "to: outer")
    assert "a turn has no to" in refused(tmp_path, text, "scene.states.turned.event.to")


def test_the_second_route_catches_a_wrong_turn(monkeypatch):
    """Elroy's beanie: Newton–Euler's angular momentum with the outer oval's spin counted twice
    puts the outer oval elsewhere after the turn, and the check says so."""
    original = moves.Symmetry.momentum

    def first_spin_twice(self, coords):
        first = coords.scene.bodies[self.moved[0]]
        extra = first.inertia * coords.angular_velocity(first.name) if first.rotates and self.about is not None else 0
        return original(self, coords) + extra

    monkeypatch.setattr(moves.Symmetry, "momentum", first_spin_twice)
    with pytest.raises(CheckFailure, match="after the turn turned, theta_outer"):
        report.solve(problem.load("elroys_beanie"), {}, 4)


def test_no_state_follows_a_turn_that_leaves_the_bodies_loose(tmp_path):
    text = SPINNING_BEANIE.replace(
        "    turned: {from: spinning, event: {turn: inner, relative_to: outer, angle: pi}}\n",
        "    turned: {from: spinning, event: {turn: inner, relative_to: outer, angle: pi}}\n"
        "    back: {from: turned, event: {turn: inner, relative_to: outer, angle: -pi}}\n").replace(
        "in: turned", "in: back")
    assert "no state may follow it" in refused(tmp_path, text, "scene.states.back")


# Pulls (`event: {pull: CORD, length: r2}`): a cord from a ground point (a hole) to a point mass drawn slowly
# to a new length; Serway & Jewett's puck through a hole is in the textbook suite.
PUCK = textbook("puck_pulled_through_hole").read_text()


@pytest.mark.parametrize("change, field, words", [
    (("{pull: cord, length: r2}", "{pull: rope, length: r2}"), "scene.states.inner.event.pull", "no cord 'rope'"),
    (("{pull: cord, length: r2}", "{pull: cord}"), "scene.states.inner.event.length", "missing"),
    (("{pull: cord, length: r2}", "{pull: cord, length: r2, to: hole}"), "scene.states.inner.event.to",
     "a pull gives the cord"),
    (("{pull: cord, length: r2}", "{pull: cord, length: 2}"), "scene.states.inner.event.length", "dimension"),
    (("{pull: cord, length: r2}", "{move: puck, to: [0, 0], length: r2}"), "scene.states.inner.event.length",
     "a move has no length"),
])
def test_a_wrong_pull_is_refused_naming_its_field(tmp_path, change, field, words):
    assert words in refused(tmp_path, PUCK.replace(*change), field)


def test_a_pull_draws_a_straight_cord_from_a_ground_point_to_a_point_mass(tmp_path):
    text = PUCK.replace("    cord: [hole, puck]", "    cord: [hole, peg, puck]").replace(
        "    hole: [0, 0]", "    hole: [0, 0]\n    peg: [0, r1]")
    assert "a straight cord tied to a ground point" in refused(tmp_path, text, "scene.states.inner.event.pull")


def test_only_speeds_and_energies_are_asked_after_a_pull_and_only_a_pull_follows(tmp_path):
    text = PUCK.replace("of: puck.speed, in: inner", "of: puck.velocity.y, in: inner")
    assert "depends on how it is made" in refused(tmp_path, text, "ask.v")
    text = PUCK.replace("    inner: {from: circling, event: {pull: cord, length: r2}}\n",
                        "    inner: {from: circling, event: {pull: cord, length: r2}}\n"
                        "    later: {from: inner, when: {puck.x: 0}}\n")
    assert "only another pull may follow it" in refused(tmp_path, text, "scene.states.later.from")


def test_the_second_route_catches_a_wrong_pull(tmp_path, monkeypatch):
    """The angular momentum about the hole by moments against Lagrange's symmetry: a moment counted
    about the wrong point is caught."""
    original = moves.Symmetry.momentum

    def about_the_wrong_point(self, coords):
        return original(dataclasses.replace(self, about=(sp.Integer(1), sp.Integer(0))), coords)

    monkeypatch.setattr(moves.Symmetry, "momentum", about_the_wrong_point)
    with pytest.raises(CheckFailure, match="after the pull inner"):
        report.solve(problem.load(write_problem(tmp_path, PUCK)), {}, 4)
