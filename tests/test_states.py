"""States of a scene (`scene.states`, `in: STATE`; derive.mechanics.states): the closed forms are in
the textbook suite (tests/textbook/states); here the rules a user meets, each refusal, and the
second route (Newton–Euler's motion integrated) shown to catch a wrong state."""
import json

import pytest

from conftest import run_derive
from derive import problem, report
from derive.crosschecks import CheckFailure
from derive.mechanics import states

ROD = """\
id: rod_states
title: A rod pinned at one end
topic: torque
parameters:
  M: {meaning: mass of the rod, unit: kg, range: [0.5, 3], sig_figs: 3}
  L: {meaning: length of the rod, unit: m, range: [0.5, 2], sig_figs: 3}
  g: {meaning: gravitational acceleration, unit: m/s^2, value: 9.81}
scene:
  bodies:
    rod: {shape: rod, mass: M, length: L, at: [L/2, 0], angle: 0}
  joints:
    hinge: {pin: rod.start}
  loads:
    - gravity: g
  states:
    there: {when: {rod.angle: TARGET}}
ask:
  omega: {meaning: angular velocity, of: rod.angular_velocity, in: there, unit: rad/s}
question: |
  A rod is released from rest horizontal.
"""


def solve(tmp_path, text, *extra):
    path = tmp_path / "problem.yaml"
    path.write_text(text)
    return run_derive("solve", str(path), "--format", "json", *extra)


def with_state(spec: str) -> str:
    """The rod with its state given otherwise: `spec` is the state's mapping."""
    return ROD.replace("    there: {when: {rod.angle: TARGET}}", f"    there: {spec}")


def refused(tmp_path, text, field):
    result = solve(tmp_path, text)
    assert result.returncode == 2, result.stdout + result.stderr
    assert field in result.stderr and len(result.stderr.strip().splitlines()) == 1, result.stderr
    return result.stderr


def test_a_rod_released_horizontal_turns_at_sqrt_3g_over_L_when_vertical(tmp_path):
    result = solve(tmp_path, ROD.replace("TARGET", "-pi/2"), "--set", "L=1.5")
    assert result.returncode == 0, result.stderr
    assert json.loads(result.stdout)["answers"]["omega"]["value"].startswith("-4.429")  # -sqrt(3*9.81/1.5): clockwise


def test_a_state_the_motion_does_not_reach_is_refused(tmp_path):
    """Released horizontal, the rod falls: it never gets up to vertical."""
    assert "does not get there" in refused(tmp_path, ROD.replace("TARGET", "pi/2"), "scene.states.there")


def test_a_state_beyond_a_turning_point_is_refused(tmp_path):
    """Clockwise to -pi (horizontal again, at rest) it turns back: hanging down again after a
    whole turn (-5pi/2) is never reached, although the energy there would allow it."""
    result = solve(tmp_path, ROD.replace("TARGET", "-5*pi/2"))
    assert result.returncode == 2 and "stops on its way to the state" in result.stderr, result.stderr


def test_an_ask_in_a_state_the_scene_lacks_is_refused(tmp_path):
    text = ROD.replace("TARGET", "-pi/2").replace("in: there", "in: bottom")
    assert "no state 'bottom'" in refused(tmp_path, text, "ask.omega.in")


def test_a_rate_without_a_state_is_refused(tmp_path):
    text = ROD.replace("TARGET", "-pi/2").replace(", in: there", "")
    assert "is read in a state" in refused(tmp_path, text, "ask.omega.in")


def test_a_state_no_ask_reads_is_refused(tmp_path):
    text = with_state("{when: {rod.angle: -pi/2}}\n    unused: {when: {rod.angle: -1}}")
    assert "no ask is read in this state" in refused(tmp_path, text, "scene.states.unused")


def test_an_ask_that_is_not_read_in_a_state_is_refused(tmp_path):
    text = ROD.replace("TARGET", "-pi/2").replace("of: rod.angular_velocity, in: there, unit: rad/s",
                                                   "of: rod.inertia, in: there, unit: kg*m^2")
    assert "is not read in a state" in refused(tmp_path, text, "ask.omega.in")


def test_rates_that_leave_a_velocity_open_are_refused(tmp_path):
    """The pinned rod given only its center's x rate (zero by the pin): how fast it turns is open."""
    text = with_state("{rates: {rod.velocity.x: 0}}")
    assert "open" in refused(tmp_path, text, "scene.states.there")


def test_rates_that_break_a_constraint_are_refused(tmp_path):
    """The pinned rod's center cannot move along the rod."""
    text = with_state("{rates: {rod.velocity.x: sqrt(g*L)}}")
    assert "break a constraint" in refused(tmp_path, text, "scene.states.there")


def test_a_scene_that_stays_put_never_gets_to_the_state(tmp_path):
    """Hanging straight down at rest, nothing pushes the rod."""
    text = ROD.replace("at: [L/2, 0], angle: 0", "at: [0, -L/2], angle: -pi/2").replace("TARGET", "-1")
    result = solve(tmp_path, text)
    assert result.returncode == 2 and "does not reach the state" in result.stderr, result.stderr


def test_a_damper_is_an_engine_limit(tmp_path):
    text = ROD.replace("TARGET", "-pi/2").replace("    - gravity: g", "    - gravity: g\n    - damper: {on: rod, coefficient: c}")
    text = text.replace("  g: {meaning", "  c: {meaning: damping, unit: N*m*s, range: [0.1, 1], sig_figs: 2}\n  g: {meaning")
    result = solve(tmp_path, text)
    assert result.returncode == 1 and "derive cannot yet" in result.stderr, result.stderr


def test_a_wrong_state_is_caught_by_the_integrated_motion(tmp_path, monkeypatch):
    """The second route: a rate 1% off is found by integrating Newton–Euler's equations."""
    path = tmp_path / "problem.yaml"
    path.write_text(ROD.replace("TARGET", "-pi/2"))
    original = states.root
    monkeypatch.setattr(states, "root", lambda expr: original(expr) * 101 / 100)
    with pytest.raises(CheckFailure, match="differ"):
        report.solve(problem.load(path), {}, 4)
