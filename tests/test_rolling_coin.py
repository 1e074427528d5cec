"""A thin body rolling on its edge (derive.mechanics.rolling_coin): Lagrange's and Kane's methods with
the rolling constraints and Newton–Euler about the center of mass give the same equations for every
rolling shape; the steady motion and upright rolling's least speed against a simulation of the full
nonholonomic motion; a steady motion exists wherever the center lies inside the circle; a wrong
route is caught; what is not modelled is refused naming the field."""
import math

import numpy as np
import pytest
import sympy as sp
from scipy.integrate import solve_ivp
from sympy.physics import mechanics as me

from conftest import refused
from derive.language import problem
from derive.publishing import report
from derive.solution.answers import Solution
from derive.solution.crosschecks import CheckFailure
from derive.core.errors import InputError
from derive.mechanics import bearings, rolling_coin

m, g, a, b, R, th, I1, I3 = sp.symbols("m g a b R theta I_1 I_3", positive=True)
T = me.dynamicsymbols._t


def _moments(shape, sizes):
    tensor = bearings.body_tensor(shape, m, sizes)
    return tensor[0, 0], tensor[2, 2]


@pytest.mark.parametrize("shape, sizes", [("disk", {"radius": a}), ("ring", {"radius": a}),
                                          ("annulus", {"inner_radius": b, "outer_radius": a})])
def test_the_three_routes_give_the_same_equations(shape, sizes):
    found = [rolling_coin.motion(*_moments(shape, sizes), m, g, a, route)["equations"] for route in rolling_coin.ROUTES]
    assert all(sp.simplify(x - y) == 0 for other in found[1:] for x, y in zip(found[0], other))
    assert found[0] != sp.zeros(3, 1)


def test_upright_rolling_is_stable_above_the_textbook_speeds():
    # Routh's rolling disk: stable for omega^2 > m g a I1/(I3 (I3 + m a^2)), v = a omega
    for route in rolling_coin.ROUTES:
        assert rolling_coin.min_speed(m * a**2 / 4, m * a**2 / 2, m, g, a, route) == sp.sqrt(g * a / 3)
        assert rolling_coin.min_speed(m * a**2 / 2, m * a**2, m, g, a, route) == sp.sqrt(g * a) / 2
        general = rolling_coin.min_speed(I1, I3, m, g, a, route)
        assert sp.simplify(general**2 - a**2 * m * g * a * I1 / (I3 * (I3 + m * a**2))) == 0


def test_a_steady_motion_exists_wherever_the_center_lies_inside_the_circle():
    d = sp.Symbol("d", positive=True)  # circle = a sin(theta) + d: the center d from the axis
    for route in rolling_coin.ROUTES:
        found = rolling_coin.steady(I1, I3, m, g, a, th, R, route)
        squared = sp.simplify(found["squared"].subs(R, a * sp.sin(th) + d))
        sine, cosine = sp.symbols("sine cosine", positive=True)  # 0 < theta < pi/2
        assert squared.subs(sp.tan(th), sine / cosine).subs({sp.sin(th): sine, sp.cos(th): cosine}).is_positive, squared
        assert found["normal_force"] == m * g and found["tangential"] == 0
        # the friction is the center's centripetal force, the spin its speed over a
        assert sp.simplify(found["friction"] - m * found["precession"] ** 2 * (R - a * sp.sin(th))) == 0
        assert sp.simplify(found["spin"] - found["speed"] / a) == 0


def _simulated(av, start, span):
    """The full rolling motion of a uniform disk of radius av (Kane's equations, g = 9.81, m = 1)
    from start = (psi, theta, phi, their rates): times and the lean."""
    q = rolling_coin._coordinates()
    values = {m: 1, g: sp.Rational(981, 100), I1: av**2 / 4, I3: av**2 / 2, a: av}
    equations = rolling_coin.motion(I1, I3, m, g, a, "kane")["equations"].subs(values)
    accelerations = [c.diff(T, 2) for c in q]
    matrix, forcing = sp.linear_eq_to_matrix(list(equations), accelerations)
    x, y = sp.symbols("x0:3"), sp.symbols("y0:3")
    now = {**{c.diff(T): v for c, v in zip(q, y)}, **dict(zip(q, x))}
    rates = sp.lambdify([*x, *y], list(me.msubs(matrix, now).LUsolve(me.msubs(forcing, now))), "numpy")
    run = solve_ivp(lambda t, s: [*s[3:], *rates(*s)], (0, span), start, method="DOP853", rtol=1e-11, atol=1e-12,
                    dense_output=True)
    times = np.linspace(0, span, 4001)
    return times, run.sol(times)[1]


def test_the_steady_motion_holds_in_simulation():
    values = {a: sp.Rational(12, 1000), R: sp.Rational(2, 10), th: sp.Rational(3, 10), m: 1, g: sp.Rational(981, 100)}
    found = rolling_coin.steady(m * a**2 / 4, m * a**2 / 2, m, g, a, th, R, "newton_euler")
    rate = float(found["precession"].subs(values))
    spin_rate = -rate * 0.2 / 0.012  # phi' = -Omega circle/a, the contact point's rolling along its circle
    start = [0.0, 0.3, 0.0, rate, 0.0, spin_rate]
    times, lean = _simulated(sp.Rational(12, 1000), start, 2.0)
    assert np.max(np.abs(lean - 0.3)) < 1e-7
    start[3] = rate * 1.01  # turning too fast for that lean: it rises and nods
    assert np.max(np.abs(_simulated(sp.Rational(12, 1000), start, 2.0)[1] - 0.3)) > 1e-4


@pytest.mark.parametrize("factor", [1.1, 0.9])
def test_upright_rolling_above_the_least_speed_stays_up(factor):
    av = 0.05
    least = math.sqrt(9.81 * av / 3)  # a uniform disk's, v^2 = g a/3
    start = [0.0, 1e-4, 0.0, 0.0, 0.0, -factor * least / av]  # nudged by 1e-4 rad
    lean = np.max(np.abs(_simulated(sp.Rational(5, 100), start, 6.0)[1]))
    # faster, it stays within a few times its nudge (a wide circle); slower, it falls well over
    assert lean < 1e-2 if factor > 1 else lean > 0.1


def test_a_wrong_route_is_caught(monkeypatch, tmp_path):
    right = rolling_coin.steady

    def wrong(*arguments):
        found = right(*arguments)
        return {**found, "precession": found["precession"] * 2} if arguments[-1] == "kane" else found

    monkeypatch.setattr(rolling_coin, "steady", wrong)
    path = tmp_path / "coin.yaml"
    path.write_text(COIN_FILE.replace("ASK", "coin.steady.precession").replace("KEY", "{tilt: theta, circle: R}")
                    .replace("UNIT", "rad/s"))
    with pytest.raises(CheckFailure, match="disagree on x"):
        Solution(problem.load(path)).checks()


COIN_FILE = """id: coin
title: A coin
topic: precession
parameters:
  m: {meaning: mass, unit: kg, value: 0.01}
  a: {meaning: radius, unit: m, value: 0.012}
  R: {meaning: circle, unit: m, value: 0.2}
  theta: {meaning: lean, unit: rad, value: 0.3}
  g: {meaning: gravity, unit: m/s^2, value: 9.81}
scene:
  bodies:
    coin: {shape: disk, mass: m, radius: a, rolls_on_edge: KEY}
  loads:
    - gravity: g
ask:
  x: {meaning: asked, of: ASK, unit: UNIT}
question: A coin rolls on a circle of {{ R }} leaning {{ theta }}.
"""


def test_a_coin_too_far_out_for_its_circle_is_refused(tmp_path):
    path = tmp_path / "coin.yaml"
    path.write_text(COIN_FILE.replace("ASK", "coin.steady.speed").replace("KEY", "{tilt: theta, circle: R}")
                    .replace("UNIT", "m/s"))
    with pytest.raises(InputError, match="across the axis"):
        report.solve(problem.load(path), {"R": "0.003"}, 15)  # a sin(0.3) = 0.0035


@pytest.mark.parametrize("body, key, ask, field", [
    ("{shape: box, mass: m, side_a: a, side_b: a, side_c: a, rolls_on_edge: KEY}", "{}", "coin.upright.min_speed",
     "scene.bodies.coin.rolls_on_edge"),  # not axially symmetric
    ("{shape: cylinder, mass: m, radius: a, height: a, rolls_on_edge: KEY}", "{}", "coin.upright.min_speed",
     "scene.bodies.coin.rolls_on_edge"),  # its rim is not in its center's plane
    ("{shape: disk, mass: m, radius: a, on: floor, rolls_on_edge: KEY}", "{}", "coin.upright.min_speed",
     "scene.bodies.coin.on"),  # an inclined plane, or any surface
    ("{shape: disk, mass: m, radius: a, friction: {static: 0.5}, rolls_on_edge: KEY}", "{}", "coin.upright.min_speed",
     "scene.bodies.coin.friction"),  # slipping
    ("{shape: custom, mass: m, inertia: {axial: m*a**2, transverse: m*a**2}, rolls_on_edge: KEY}", "{}",
     "coin.upright.min_speed", "scene.bodies.coin.radius"),
    ("{shape: disk, mass: m, radius: a, rolls_on_edge: KEY}", "{tilt: 2, circle: R}", "coin.steady.speed",
     "scene.bodies.coin.rolls_on_edge.tilt"),
    ("{shape: disk, mass: m, radius: a, rolls_on_edge: KEY}", "{tilt: theta}", "coin.steady.speed",
     "scene.bodies.coin.rolls_on_edge"),
    ("{shape: disk, mass: m, radius: a, rolls_on_edge: KEY}", "{}", "coin.steady.speed", "ask.x"),
    ("{shape: disk, mass: m, radius: a, rolls_on_edge: KEY}", "{tilt: theta, circle: R}", "coin.upright.min_speed",
     "scene.bodies.coin.rolls_on_edge.tilt"),  # given, and read by no ask
    ("{shape: disk, mass: m, radius: a, rolls_on_edge: KEY}", "{}", "coin.upright.speed", "ask.x"),
])
def test_what_rolling_on_an_edge_does_not_model_is_refused(tmp_path, body, key, ask, field):
    text = COIN_FILE.replace("{shape: disk, mass: m, radius: a, rolls_on_edge: KEY}", body).replace("KEY", key)
    text = text.replace("ASK", ask).replace("UNIT", "m/s")
    if "on: floor" in body:
        text = text.replace("scene:\n", "scene:\n  surfaces:\n    floor: {plane: {angle: 0.1}}\n")
    refused(tmp_path, text, field)


def test_a_second_body_or_no_gravity_is_refused(tmp_path):
    text = COIN_FILE.replace("KEY", "{}").replace("ASK", "coin.upright.min_speed").replace("UNIT", "m/s")
    refused(tmp_path, text.replace("  loads:\n    - gravity: g\n", ""), "scene.loads")
    refused(tmp_path, text.replace("    coin:", "    other: {shape: point, mass: m, at: [1, 0]}\n    coin:"), "scene")


def test_the_figure_draws_the_coin_leaning_toward_its_circles_axis(tmp_path):
    from derive.publishing import figure
    path = tmp_path / "coin.yaml"
    path.write_text(COIN_FILE.replace("ASK", "coin.steady.precession").replace("KEY", "{tilt: theta, circle: R}")
                    .replace("UNIT", "rad/s"))
    drawn = figure.tikz(problem.load(path))
    assert "\\fill (-0.3,0.96) circle (0.04);" in drawn  # the center, theta = 0.3 rad from the vertical at P
    assert "{$\\theta$}" in drawn and "{$R$}" in drawn and "{$x$}" in drawn and "$m\\,g$" in drawn
    path.write_text(COIN_FILE.replace("ASK", "coin.upright.min_speed").replace("KEY", "{}").replace("UNIT", "m/s")
                    .replace(" of {{ R }} leaning {{ theta }}", "").replace("  R: {meaning: circle, unit: m, value: 0.2}\n"
                                                                            "  theta: {meaning: lean, unit: rad, value: 0.3}\n", ""))
    drawn = figure.tikz(problem.load(path))
    assert "circle (1)" in drawn and "[velocity]" in drawn and "{$x$}" in drawn and "{$a$}" in drawn
