"""Rolling without slipping at a given speed (notes §2, §2.1): the rotation rate, the distance
per turn and the kinetic-energy split, by the center of mass and by the contact point."""
import dataclasses

import pytest
import sympy as sp

from conftest import textbook
from derive.solution.answers import Solution
from derive.solution.crosschecks import CheckFailure
from derive.core.errors import ProblemError
from derive.mechanics import rolling
from derive.language.problem import load, parse


def _as(shape: str, tmp_path):
    text = load("rolling_kinetic_energy").path.read_text().replace("shape: disk", f"shape: {shape}")
    return parse(text, tmp_path / f"{shape}.yaml")


@pytest.mark.parametrize("shape, share", [("disk", sp.Rational(1, 3)), ("sphere", sp.Rational(2, 7)),
                                          ("ring", sp.Rational(1, 2)), ("spherical_shell", sp.Rational(2, 5))])
def test_the_share_of_rotation_follows_the_shape(shape, share, tmp_path):
    solution = Solution(_as(shape, tmp_path))
    assert solution.signed("share") == share
    assert any(c.name == "center_of_mass_vs_contact_point" for c in solution.checks())


def test_omega_is_v_over_r_clockwise_and_one_turn_covers_the_circumference():
    """Notes §2, eq. (10): omega = V_cm / R; a full revolution travels 2 pi R."""
    p = load("rolling_kinetic_energy")
    solution = Solution(p)
    V, R, M = (p.parameters[n].symbol for n in ("V", "R", "M"))
    assert solution.signed("omega") == -V / R  # moving in +x, the disk turns clockwise
    assert solution.signed("d") == 2 * sp.pi * R
    assert solution.signed("K") == sp.Rational(3, 4) * M * V**2  # eq. (11) with I = M R^2 / 2


def test_a_forgotten_parallel_axis_term_is_caught(monkeypatch):
    real = rolling.rolling

    def forgetful(scene, body, route):
        values, steps = real(scene, body, route)
        if route == "contact point":  # K = I_cm omega^2 / 2: the M R^2 left out
            values = {**values, "kinetic_energy": values["rotational_energy"]}
        return values, steps

    monkeypatch.setattr(rolling, "rolling", forgetful)
    with pytest.raises(CheckFailure, match="K is"):
        Solution(load("rolling_kinetic_energy")).checks()


def test_rolling_quantities_need_a_rolling_body_with_a_velocity(tmp_path):
    text = load("rolling_kinetic_energy").path.read_text().replace(", velocity: [V, 0]", "")
    with pytest.raises(ProblemError, match=r"ask\.omega\.of: wheel\.rolling needs a round body rolling"):
        parse(text, tmp_path / "p.yaml")
    text = load("rolling_kinetic_energy").path.read_text().replace("rolling.rotational_fraction", "rolling.spin")
    with pytest.raises(ProblemError, match=r"ask\.share\.of: a rolling body has rolling\.angular_velocity"):
        parse(text, tmp_path / "p.yaml")


@pytest.mark.parametrize("placed", ["", "at: [(R - r)*sin(pi/3), R - (R - r)*cos(pi/3)], "])
def test_a_ball_of_finite_size_needs_27_tenths_of_its_path_radius(placed, tmp_path):
    """A solid ball of radius r rolling in a loop of radius R: its center moves on a circle of
    radius R - r, so the least release height of the center above its lowest position is
    27 (R - r) / 10 (Serway & Jewett, Physics for Scientists and Engineers, ch. 10, the loop
    problem with the ball's radius kept; the point-ball 27 R / 10 is its r -> 0 limit). It was
    27 R / 10 - r: the top of the loop was put in as a displacement from the ball's placed
    position. Placed elsewhere on the loop, the answer is the same."""
    text = load("loop_the_loop_ball").path.read_text().replace("ball: {shape: sphere, ", "ball: {shape: sphere, "
                                                               + placed)
    path = tmp_path / "loop.yaml"
    path.write_text(text)
    problem = load(path)
    R, r = problem.parameters["R"].symbol, problem.parameters["r"].symbol
    assert sp.simplify(Solution(problem).signed("h_roll") - sp.Rational(27, 10) * (R - r)) == 0


def test_a_ball_sliding_without_friction_in_a_loop_needs_five_halves_of_its_path_radius(tmp_path):
    """A ball that slides without friction never spins (nothing turns it), so it needs what a point
    does on its path of radius R - r: 5 (R - r) / 2. Deriving it failed with an IndexError (the
    rolling condition was looked for on a sliding contact); kinetic friction is refused, as energy
    is not conserved then."""
    text = load("loop_the_loop_ball").path.read_text().replace("contact: rolling", "contact: sliding")
    problem = parse(text, tmp_path / "slide.yaml")
    R, r = problem.parameters["R"].symbol, problem.parameters["r"].symbol
    assert sp.simplify(Solution(problem).signed("h_roll") - sp.Rational(5, 2) * (R - r)) == 0
    (contact,) = problem.scene.constraints
    rough = dataclasses.replace(contact, kinetic=sp.Rational(1, 10))
    rough = dataclasses.replace(problem, scene=dataclasses.replace(problem.scene, constraints=(rough,)))
    with pytest.raises(ProblemError, match="energy is not conserved"):
        Solution(rough).signed("h_roll")


def test_an_incline_that_descends_to_the_left_is_the_mirror_image(tmp_path):
    """The same sphere rolling down a plane that descends to the left: the same acceleration down
    the slope and friction, its center moving left and turning counter-clockwise (the mirror image)."""
    source = (textbook("sphere_rolls_incline")).read_text()
    mirrored = source.replace("{incline: {angle: theta}}", "{incline: {angle: theta, descends: left}}")
    mirrored = mirrored.replace("ask:\n", "ask:\n  ax: {meaning: horizontal acceleration, of: ball.acceleration.x, "
                                "unit: m/s^2}\n  alpha: {meaning: angular acceleration, of: ball.angular_acceleration, "
                                "unit: rad/s^2}\n", 1)
    assert mirrored.count("descends: left") == 1
    right = Solution(parse(source, tmp_path / "right.yaml"))
    left = Solution(parse(mirrored, tmp_path / "left.yaml"))
    R, theta, g = (sp.Symbol(n, positive=True) for n in ("R", "theta", "g"))
    for name in ("a", "f", "mu_min"):
        assert sp.simplify(left.signed(name) - right.signed(name)) == 0, name
    assert sp.simplify(left.signed("a") - 5 * g * sp.sin(theta) / 7) == 0
    assert sp.simplify(left.signed("ax") + 5 * g * sp.sin(theta) * sp.cos(theta) / 7) == 0  # to the left
    assert sp.simplify(left.signed("alpha") - 5 * g * sp.sin(theta) / (7 * R)) == 0  # counter-clockwise
    assert all(c.passed for c in left.checks())
