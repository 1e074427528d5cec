"""Slipping clutches and brakes (`{clutch: A, to: B, slipping: C}`, a state `when: {grips: NAME}`;
derive.mechanics.grips): the closed forms are in tests/textbook/states (a record dropped onto a
turntable, a brake pad that stops a flywheel); here each refusal, and the second route shown to
catch a wrong grip."""
import dataclasses
import json

import pytest
import sympy as sp

from conftest import refused, run_derive, textbook, write_problem
from derive.language import problem
from derive.publishing import report
from derive.solution.answers import Solution
from derive.solution.crosschecks import CheckFailure
from derive.mechanics import grips

DRIVEN = """\
id: driven_turntable
title: A record dropped onto a turntable driven by a motor
topic: conservation
parameters:
  I1: {meaning: moment of inertia of the turntable, unit: kg*m^2, range: [0.02, 0.04], sig_figs: 2}
  I2: {meaning: moment of inertia of the record, unit: kg*m^2, range: [0.001, 0.002], sig_figs: 2}
  w0: {meaning: angular velocity of the turntable, unit: rad/s, range: [3, 6], sig_figs: 2}
  C: {meaning: friction couple of the felt while it slips, unit: N*m, range: [0.01, 0.02], sig_figs: 2}
  tau: {meaning: torque of the motor, unit: N*m, range: [0.001, 0.002], sig_figs: 2}
  M1: {meaning: mass of the turntable, unit: kg, value: 1}
  M2: {meaning: mass of the record, unit: kg, value: 0.1}
scene:
  bodies:
    turntable: {shape: custom, mass: M1, inertia: I1}
    record: {shape: custom, mass: M2, inertia: I2}
  joints:
    axle: {pin: turntable.center}
    spindle: {pin: record.center, to: turntable.center}
    felt: {clutch: record, to: turntable, slipping: C}
  loads:
    - torque: {on: turntable, magnitude: tau}
  states:
    dropped: {rates: {turntable.angular_velocity: w0, record.angular_velocity: 0}}
    together: {from: dropped, when: {grips: felt}}
ask:
  omega: {meaning: angular velocity when they turn together, of: turntable.angular_velocity, in: together, unit: rad/s}
  alpha: {meaning: angular acceleration after, of: record.angular_acceleration, in: together, unit: rad/s^2}
question: |
  A record is dropped onto a turntable that a motor drives.
"""


SET = [f"--set={name}={value}" for name, value in
       (("I1", 0.03), ("I2", 0.0015), ("w0", 4.5), ("C", 0.015), ("tau", 0.0015))]


def test_a_driven_turntable_grips_and_the_motor_then_turns_both(tmp_path):
    """While the felt slips, I1 w1' = tau - C and I2 w2' = C: the slip w0 closes at (C - tau)/I1 +
    C/I2, so they grip at t = w0/((C - tau)/I1 + C/I2), turning at (I1 w0 + tau t)/(I1 + I2) (the
    angular momentum the motor's torque adds); the motor then turns both, tau/(I1 + I2)."""
    path = write_problem(tmp_path, DRIVEN)
    result = run_derive("solve", str(path), "--format", "json", *SET)
    assert result.returncode == 0, result.stderr
    answers = json.loads(result.stdout)["answers"]
    I1, I2, w0, C, tau = 0.03, 0.0015, 4.5, 0.015, 0.0015
    t = w0 / ((C - tau) / I1 + C / I2)
    assert float(answers["omega"]["value"]) == pytest.approx((I1 * w0 + tau * t) / (I1 + I2), rel=1e-12)
    assert float(answers["alpha"]["value"]) == pytest.approx(tau / (I1 + I2), rel=1e-12)


def test_an_ask_with_no_state_is_refused_in_a_scene_with_a_slipping_clutch(tmp_path):
    text = DRIVEN.replace("of: record.angular_acceleration, in: together,", "of: record.angular_acceleration,")
    assert "slips only while its plates turn at different rates" in refused(tmp_path, text, "ask.alpha")


def test_plates_that_a_motor_makes_slip_faster_never_grip(tmp_path):
    text = DRIVEN.replace("record.angular_velocity: 0}", "record.angular_velocity: 0}").replace(
        "    - torque: {on: turntable, magnitude: tau}", "    - torque: {on: turntable, magnitude: 30*C + tau}")
    assert "it never grips" in refused(tmp_path, text, "parameters", *SET)


def test_a_clutch_that_would_need_more_than_its_couple_after_gripping_is_a_broken_condition(tmp_path):
    """With constant loads the clutch that grips never needs more than C after (it would not have
    gripped); where a later state's loads would ask more, the condition says it slips again: here
    the couple the scene needs is put at 2 C."""
    solution = Solution(problem.load(write_problem(tmp_path, DRIVEN)))
    clutch = solution.scene_in("together").constraint("felt")
    C = solution.problem.parameters["C"].symbol
    needed = {clutch.unknowns()["torque"]: 2 * C}
    (slip_again,) = solution._slip_conditions("together", solution.scene_in("together"), needed)
    expression, strict, meaning = slip_again
    assert sp.simplify(expression + 3 * C**2) == 0 and not strict and "would slip again" in meaning
    held = {clutch.unknowns()["torque"]: solution.in_state("lagrange", "together").raw[clutch.unknowns()["torque"]]}
    assert solution._sample(solution._slip_conditions("together", solution.scene_in("together"), held)[0][0]) > 0


def test_the_second_route_catches_a_wrong_grip(tmp_path, monkeypatch):
    """Newton–Euler's motion integrated until the slip vanishes against the constant-acceleration
    closed form: a time off by a factor is caught."""
    original = grips.grip

    def late(*args, **kwargs):
        reached = original(*args, **kwargs)
        return dataclasses.replace(reached, took=(2 * reached.took[0], reached.took[1]))

    monkeypatch.setattr(grips, "grip", late)
    with pytest.raises(CheckFailure, match="the state together"):
        report.solve(problem.load(write_problem(tmp_path, DRIVEN)), {}, 4)


def test_a_brake_stop_by_energy_is_refused_and_grips_is_the_way(tmp_path):
    text = (textbook("flywheel_brake_grips")).read_text()
    text = text.replace("held: {from: spinning, when: {grips: pad}}", "held: {from: spinning, when: stops}")
    assert "work depends on the speed" in refused(tmp_path, text, "scene.states.held", exit_code=1)


BALL = (textbook("bowling_ball_skids")).read_text()


@pytest.mark.parametrize("change, field, words, code", [
    ("friction: {kinetic: mu}}", "scene.states.rolling.when.grips", "gives no kinetic friction", 2),
    ("launched: {rates: {ball.velocity.x: v0, ball.angular_velocity: 0}}", "scene.states.rolling",
     "does not slip at the start: it grips there already", 2),
])
def test_a_contact_that_cannot_grip_is_refused(tmp_path, change, field, words, code):
    replacement = {"friction: {kinetic: mu}}": "friction: {static: mu}}",
                   "launched: {rates: {ball.velocity.x: v0, ball.angular_velocity: 0}}":
                   "launched: {rates: {ball.velocity.x: v0, ball.angular_velocity: -v0/R}}"}[change]
    assert words in refused(tmp_path, BALL.replace(change, replacement), field, exit_code=code)


def test_a_grip_where_the_accelerations_change_is_an_engine_limit(tmp_path):
    """A ball spinning in a bowl: its normal force, and so its friction, changes as it moves, so
    the slip does not fall at a constant rate; derive says it cannot follow it (exit 1)."""
    text = BALL.replace("lane: {incline: {angle: 0}}", "lane: {circle: {radius: 10*R, center: [0, 10*R], side: inside}}")
    text = text.replace("ball: {shape: sphere, mass: M, radius: R, on: lane,",
                        "ball: {shape: sphere, mass: M, radius: R, at: [0, R], on: lane,")
    assert "accelerations change while it slips" in refused(tmp_path, text, "scene.states.rolling", exit_code=1)
