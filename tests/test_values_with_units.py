"""A value written with its unit in a problem file (issue 39: degrees first-class): `value: 25°`,
`25 deg` or `250 g` is converted exactly into the parameter's unit; a first file with `value: 25°`
was refused as "an expression must be ASCII"."""
import pytest

from conftest import refused, solve, write_problem

RAMP = """\
id: ramp
title: A ball on a ramp
topic: rolling
parameters:
  M: {meaning: mass of the ball, unit: kg, value: MASS}
  R: {meaning: radius of the ball, unit: m, value: 0.1}
  H: {meaning: height of the ramp, unit: m, value: 1.2}
  theta: {meaning: slope angle, unit: deg, ANGLE}
  g: {meaning: gravitational acceleration, unit: m/s^2, value: 9.81}
scene:
  surfaces:
    ramp: {incline: {angle: theta, height: H}}
  bodies:
    ball: {shape: sphere, mass: M, radius: R, on: ramp, contact: rolling}
  loads:
    - gravity: g
ask:
  a: {meaning: acceleration down the incline, of: ball.acceleration.down_incline, unit: m/s^2}
  f: {meaning: friction on the ball (magnitude), of: ball.friction, unit: N, magnitude: true}
question: |
  A solid ball of mass {{ M }} rolls from rest down a ramp {{ H }} high at {{ theta }}.
"""


def _answers(tmp_path, mass: str, angle: str) -> dict:
    return solve(str(write_problem(tmp_path, RAMP.replace("MASS", mass).replace("ANGLE", angle))))[0]


@pytest.mark.parametrize("angle", ["value: 25°", "value: 25 deg", "value: '25 °'", "value: 0.4363323129985824 rad"])
def test_an_angle_written_with_its_unit_is_the_same_angle(tmp_path, angle):
    plain = _answers(tmp_path, "2", "value: 25")
    written = _answers(tmp_path, "2", angle)
    digits = 15 if "rad" not in angle else 14  # the rad value is 25 deg to 16 digits
    assert all(abs(written[n] - plain[n]) <= abs(plain[n]) * 10 ** -digits for n in plain)


def test_a_mass_in_grams_for_a_parameter_in_kg(tmp_path):
    assert _answers(tmp_path, "2000 g", "value: 25") == _answers(tmp_path, "2", "value: 25")


def test_a_range_written_with_units(tmp_path):
    answers, _ = solve(str(write_problem(tmp_path, RAMP.replace("MASS", "2").replace(
        "ANGLE", "range: [20°, 30°], sig_figs: 2"))), theta="25")
    assert answers == _answers(tmp_path, "2", "value: 25")


def test_a_value_of_another_dimension_is_refused_naming_the_field(tmp_path):
    stderr = refused(tmp_path, RAMP.replace("MASS", "2 m").replace("ANGLE", "value: 25"), "parameters.M.value")
    assert "cannot convert m to kg" in stderr


@pytest.mark.parametrize("angle", ["value: 25°", "value: 25 deg", "range: [20°, 30°], sig_figs: 2"])
def test_a_value_written_with_its_unit_needs_no_unit_key(tmp_path, angle):
    """`theta: {meaning: slope angle, value: 25°}`: the unit is the one the value is written in."""
    text = RAMP.replace("MASS", "2").replace("theta: {meaning: slope angle, unit: deg, ANGLE}",
                                             f"theta: {{meaning: slope angle, {angle}}}")
    answers, report = solve(str(write_problem(tmp_path, text)), theta="25")
    assert report["parameters"]["theta"]["unit"] == "deg"
    assert answers == _answers(tmp_path, "2", "value: 25")


def test_a_bare_number_still_needs_its_unit(tmp_path):
    text = RAMP.replace("MASS", "2").replace("theta: {meaning: slope angle, unit: deg, ANGLE}",
                                             "theta: {meaning: slope angle, value: 25}")
    stderr = refused(tmp_path, text, "parameters.theta.unit")
    assert "missing: give the unit (unit: kg), or write the value with one (value: 25°)" in stderr
