"""A body whose round face is centered off its center of mass (a hemisphere's `round_center`, a
composite's round part off its center of mass, a round shape whose density moves its center of
mass) rocks or rolls on a surface on that face; what derive cannot yet follow
such a body to is refused in one line. Its closed forms are in tests/test_textbook.py."""
import pytest
import sympy as sp

from conftest import run_derive, textbook
from derive.core.errors import EngineLimit, ProblemError
from derive.language.problem import load
from derive.publishing.figure import tikz
from derive.solution.answers import Solution

HEMISPHERE = textbook("hemisphere_rocking").read_text()


def _with(tmp_path, old, new):
    assert old in HEMISPHERE
    path = tmp_path / "hemisphere.yaml"
    path.write_text(HEMISPHERE.replace(old, new))
    return str(path)


def test_a_round_face_off_a_uniform_shape_or_outside_its_radius_is_refused(tmp_path):
    result = run_derive("solve", _with(tmp_path, "shape: custom, mass: m, radius: R, inertia: 83*m*R^2/320,",
                                       "shape: disk, mass: m, radius: R,"))
    assert result.returncode == 2 and "scene.bodies.hemisphere.round_center" in result.stderr, result.stderr
    assert "only a custom body" in result.stderr and len(result.stderr.strip().splitlines()) == 1
    with pytest.raises(ProblemError, match="round_center: the round face's center is off the center of mass by less"):
        load(_with(tmp_path, "round_center: [0, 3*R/8]", "round_center: [0, 2*R]"))


@pytest.mark.parametrize("old, new, field", [
    ("    - gravity: g\n", "    - gravity: g\n  states:\n    back: {when: stops}\n", "scene.states"),
    ("contact: rolling}", "contact: rolling, velocity: [R, 0]}", "scene.bodies.hemisphere.on"),
])
def test_what_derive_cannot_yet_follow_a_rocking_body_to_is_said(tmp_path, old, new, field):
    with pytest.raises(EngineLimit, match=f"{field}: derive cannot yet follow"):
        load(_with(tmp_path, old, new))


def test_a_hemisphere_is_drawn_as_its_dome_with_its_center_of_mass_off_the_face_center():
    drawn = tikz(load(str(textbook("hemisphere_rocking"))))
    assert "arc (-180:0:" in drawn and "-- cycle;" in drawn  # the dome below its flat face


def test_a_disk_denser_on_one_side_rolls_on_its_rim_about_its_middle(tmp_path):
    """A disk of density 2 - y/R (its center of mass R/8 below its middle) released on an incline:
    at rest it turns about the contact point P, alpha = -M g R sin(theta)/I_P with
    I_P = M R^2 (1/2 - 1/64) + M |CM - P|^2, so a = g sin(theta) (8 - cos(theta))/(2 (6 - cos(theta)))
    down the slope. The circle it rolls on is its rim about its middle, not about its center of mass
    (which gave 64 g sin(theta)/95, silently, with both routes agreeing)."""
    path = tmp_path / "disk.yaml"
    path.write_text("""\
id: heavy_side_disk
title: A disk denser on one side on an incline
topic: rolling
source: "Morin, Introduction to Classical Mechanics, ch. 8 (rolling about the contact point)"
parameters:
  M: {meaning: mass, unit: kg, range: [1, 2], sig_figs: 2}
  R: {meaning: radius, unit: m, range: [0.1, 0.3], sig_figs: 2}
  theta: {meaning: slope, unit: rad, range: [0.1, 0.3], sig_figs: 2}
  g: {meaning: gravitational acceleration, unit: m/s^2, value: 9.81}
scene:
  surfaces:
    ramp: {incline: {angle: theta}}
  bodies:
    disk: {shape: disk, mass: M, radius: R, density: 2 - r*sin(phi)/R, on: ramp}
  loads:
    - gravity: g
ask:
  a: {meaning: acceleration down the incline, of: disk.acceleration.down_incline, unit: m/s^2}
question: |
  A disk of mass {{ M }} and radius {{ R }}, denser on one side, rolls on an incline at {{ theta }}.
  Find its acceleration.
""")
    problem = load(str(path))
    g, theta = problem.parameters["g"].symbol, problem.parameters["theta"].symbol
    answer = Solution(problem).expression("a")
    assert sp.simplify(answer - g * sp.sin(theta) * (8 - sp.cos(theta)) / (2 * (6 - sp.cos(theta)))) == 0


def test_an_annulus_set_to_roll_is_told_how_to_state_it(tmp_path):
    """A newcomer's pipe (an annulus) set to roll down a slope was refused "a annulus has no radius to roll on",
    and `radius:` then drew "did you mean 'outer_radius'?", which it had: now an engine limit that names the way
    to state it (shape: custom, its outer radius, its moment from `derive inertia`)."""
    from conftest import refused

    text = """
id: pipe
title: A pipe rolls
parameters:
  M: {meaning: mass of the pipe, unit: kg, range: [1, 2]}
  R1: {meaning: inner radius, unit: m, range: [0.05, 0.08]}
  R2: {meaning: outer radius, unit: m, range: [0.1, 0.2]}
  g: {meaning: gravitational acceleration, unit: m/s^2, value: 9.81}
scene:
  surfaces:
    ramp: {incline: {angle: 0.3, height: 5*R2}}
  bodies:
    pipe: {shape: annulus, mass: M, inner_radius: R1, outer_radius: R2, on: ramp, contact: rolling}
  loads:
    - gravity: g
ask:
  a: {meaning: acceleration, of: pipe.acceleration.down_incline, unit: m/s^2}
question: A pipe rolls.
"""
    error = refused(tmp_path, text, "scene.bodies.pipe.contact", exit_code=1)
    assert "derive cannot yet roll an annulus on its outer radius" in error and "shape: custom" in error
    assert "derive inertia annulus" in error
