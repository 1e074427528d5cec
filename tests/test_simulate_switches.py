"""A check's simulation never runs away: where a kinetic friction's slip changes sign the run
stops and says so (derive.checks.simulate.switches), and a run that chatters is given up after
MAX_EVALUATIONS (a new user's slipping clutch took 15 minutes and 17.7 GB in `derive check`)."""
from derive.checks import simulate
from derive.solution.answers import Solution
from derive.language.problem import load

CLUTCH = """\
id: clutch_plates
title: A disk dropped onto a spinning disk, with a slipping clutch
topic: conservation
source: Young & Freedman, University Physics, Example 10.12 (clutch plates)
parameters:
  I1: {meaning: moment of inertia of the lower disk, unit: kg*m^2, range: [0.5, 2], sig_figs: 3}
  I2: {meaning: moment of inertia of the upper disk, unit: kg*m^2, range: [0.2, 1], sig_figs: 3}
  w0: {meaning: initial rate of the lower disk, unit: rad/s, range: [10, 50], sig_figs: 3}
  C: {meaning: kinetic friction couple between the plates, unit: N*m, range: [1, 10], sig_figs: 3}
scene:
  bodies:
    lower: {shape: custom, inertia: I1, joint: fixed_axle}
    upper: {shape: custom, inertia: I2, joint: fixed_axle}
  joints:
    felt: {clutch: upper, to: lower, slipping: C}
  states:
    dropped: {rates: {lower.angular_velocity: w0, upper.angular_velocity: 0}}
    together: {from: dropped, when: {grips: felt}}
ask:
  w: {meaning: common rate, of: upper.angular_velocity, in: together, unit: rad/s}
  a1: {meaning: angular acceleration of the lower disk while slipping, of: lower.angular_acceleration, in: dropped, unit: rad/s^2}
question: A disk at rest is dropped onto a spinning disk.
"""


def test_a_slip_that_changes_sign_stops_the_run_and_is_named(tmp_path):
    path = tmp_path / "clutch_plates.yaml"
    path.write_text(CLUTCH)
    report = simulate.check(Solution(load(str(path))))
    assert report.passed, report.notes
    assert any("slip changes sign" in why for _, why in report.unchecked), report.unchecked


def test_a_run_that_takes_too_many_steps_is_given_up_and_named(monkeypatch):
    monkeypatch.setattr(simulate, "MAX_EVALUATIONS", 20)
    report = simulate.check(Solution(load("string_wrapped_disk")))
    assert report.passed and report.compared == []
    assert any("stalled" in why for _, why in report.unchecked), report.unchecked
