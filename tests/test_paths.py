"""Prescribed paths: polar acceleration, angular momentum, areal velocity — and the notes' eq. (1)."""
import mpmath
import pytest
import sympy as sp

from derive.language import problem
from derive.publishing import report
from derive.mechanics.paths import by_mechanics, quantity
from derive.core.expr import TIME
from derive.model.scene import Path

r = sp.Function("r")(TIME)
theta = sp.Function("theta")(TIME)
general = Path("polar", (r, theta))


def test_polar_acceleration_from_the_cartesian_position():
    radial = quantity(general, 1, "acceleration.radial")
    tangential = quantity(general, 1, "acceleration.tangential")
    assert sp.simplify(radial - (r.diff(TIME, 2) - r * theta.diff(TIME) ** 2)) == 0
    assert sp.simplify(tangential - (2 * r.diff(TIME) * theta.diff(TIME) + r * theta.diff(TIME, 2))) == 0
    assert by_mechanics(general, 1, "acceleration.radial") == radial
    assert by_mechanics(general, 1, "acceleration.tangential") == tangential


def test_notes_equation_1_sign_is_wrong():
    """Notes §1 eq. (1) write +R omega^2 r-hat for a constant radius; the radial acceleration is -R omega^2.

    Independent route: the second difference of the Cartesian position of uniform circular
    motion, at 50 digits, points toward the center."""
    R, w = sp.symbols("R omega", positive=True)
    derived = quantity(Path("polar", (R, w * TIME)), 1, "acceleration.radial")
    assert derived == -R * w**2
    mpmath.mp.dps = 50
    radius, rate, t, h = mpmath.mpf(2), mpmath.mpf(3), mpmath.mpf("0.4"), mpmath.mpf("1e-12")
    position = lambda s: (radius * mpmath.cos(rate * s), radius * mpmath.sin(rate * s))  # noqa: E731
    second = [(position(t + h)[i] - 2 * position(t)[i] + position(t - h)[i]) / h**2 for i in (0, 1)]
    r_hat = (mpmath.cos(rate * t), mpmath.sin(rate * t))
    radial = second[0] * r_hat[0] + second[1] * r_hat[1]
    assert abs(radial - (-radius * rate**2)) < mpmath.mpf("1e-10")
    assert radial < 0


def test_angular_momentum_and_kepler_second_law():
    m = sp.Symbol("m", positive=True)
    assert sp.simplify(quantity(general, m, "areal_velocity") - quantity(general, m, "angular_momentum") / (2 * m)) == 0
    b, v = sp.symbols("b v", positive=True)
    assert quantity(Path("cartesian", (v * TIME, b)), m, "angular_momentum") == -m * b * v


def test_library_path_problems():
    circle = report.solve(problem.load("circular_motion_L"), {"m": "2", "r": "0.5", "omega": "3"}, 15)
    assert circle["answers"]["L"]["value"] == "1.50000000000000"
    passing = report.solve(problem.load("impact_parameter"), {"m": "2", "b": "0.5", "v": "3"}, 15)
    assert passing["answers"]["L"]["value"] == "-3.00000000000000"
    polar = report.solve(problem.load("polar_acceleration"), {}, 15)
    assert polar["checks"]["path_vs_mechanics"]["passed"] and polar["answers"]["a_r"]["value"] is None
    assert problem.load("polar_acceleration").corrections[0]["where"].startswith("§1")


@pytest.mark.parametrize("name", ["velocity.x", "velocity.y", "speed", "acceleration.x", "acceleration.y",
                                  "angular_momentum", "areal_velocity"])
def test_every_path_quantity_by_sympy_mechanics(name):
    m = sp.Symbol("m", positive=True)
    assert sp.simplify(quantity(general, m, name) - by_mechanics(general, m, name)) == 0
