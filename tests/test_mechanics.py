"""Lagrange's method and Newton–Euler on the slice's scenes, against independent results."""
import math

import numpy as np
import pytest
import sympy as sp
from flint import arb, ctx
from scipy.integrate import solve_ivp

from derive.mechanics import lagrange, newton_euler
from derive.mechanics.derivation import solve_linear
from derive.model.kinematics import Coordinates
from derive.mechanics.oscillation import OscillationError, small_oscillation
from derive.parts.cord import Attachment, Cord
from derive.parts.gravity import Gravity
from derive.parts.pin import Pin
from derive.model.scene import Body, Scene

m, M, R, g, d, I = sp.symbols("m M R g d I_cm", positive=True)


def disk_scene(side=1):
    """A block hanging from a cord wound on a disk, leaving it on the right (side 1) or the left."""
    cord = Cord("string", (Attachment("wound", "disk", radius=R, turn=-side, grips=True), Attachment("point", "block")))
    return Scene(
        {"disk": Body("disk", "disk", M, {"radius": R}), "block": Body("block", "point", m, {}, at=(side * R, -3 * R))},
        (Pin("axle", "disk", (0, 0)), cord),
        Gravity(g),
    )


def released(route, scene):
    """One route's accelerations and forces in the reference configuration, at rest."""
    return route.derive(scene).at(Coordinates(scene).at_rest_in_reference())


def pendulum_scene():
    return Scene({"bob": Body("bob", "custom", M, {}, I)}, (Pin("pivot", "bob", (0, d)),), Gravity(g))


def sym(name):
    return sp.Symbol(name, real=True)


@pytest.mark.parametrize("route", [lagrange, newton_euler])
def test_string_wrapped_disk_matches_the_notes(route):
    solution = released(route, disk_scene())
    assert sp.simplify(solution[sym("yddot_block")] + 2 * m * g / (M + 2 * m)) == 0
    assert sp.simplify(solution[sym("thetaddot_disk")] + 2 * m * g / (R * (M + 2 * m))) == 0
    assert sp.simplify(solution[sym("T_string")] - m * g * M / (M + 2 * m)) == 0
    # The axle holds the disk up against its weight and the tension.
    assert sp.simplify(solution[sym("R_y^axle")] - M * g - solution[sym("T_string")]) == 0


def test_cord_on_the_left_turns_the_disk_the_other_way():
    right = released(lagrange, disk_scene(1))[sym("thetaddot_disk")]
    left = released(newton_euler, disk_scene(-1))[sym("thetaddot_disk")]
    assert sp.simplify(right + left) == 0


@pytest.mark.parametrize("scene", [disk_scene(), pendulum_scene()])
def test_routes_agree_on_every_unknown(scene):
    a, b = lagrange.derive(scene), newton_euler.derive(scene)
    assert a.unknowns == b.unknowns
    state = {**{c.q: 0 for c in Coordinates(scene).all}, **{c.u: sp.Rational(k + 1, 3) for k, c in
                                                            enumerate(Coordinates(scene).all)}}
    for unknown in a.unknowns:
        assert sp.simplify(a.at(state)[unknown] - b.at(state)[unknown]) == 0, unknown


def free_ball_scene():
    """A ball nothing holds: balances and no constraint's rows."""
    return Scene({"ball": Body("ball", "custom", M, {}, I)}, (), Gravity(g))


@pytest.mark.parametrize("route", [lagrange, newton_euler])
@pytest.mark.parametrize("moving", [False, True])
@pytest.mark.parametrize("scene", [pendulum_scene(), free_ball_scene()], ids=["pinned", "free"])
def test_balls_hold_the_exact_solution_at_a_state(route, moving, scene):
    """balls_at (the balances' coefficients taken in general, then the state put in) holds every unknown
    of the exact solution at a state that gives every symbol a number, at rest and moving, with and
    without a constraint's rows."""
    coords = Coordinates(scene)
    derivation = route.derive(scene)
    state = {**{c.q: sp.Rational(k + 1, 5) for k, c in enumerate(coords.all)},
             **{c.u: sp.Rational(k + 2, 3) if moving else 0 for k, c in enumerate(coords.all)},
             M: 2, g: sp.Rational(981, 100), d: sp.Rational(1, 2), I: sp.Rational(1, 7)}
    balls = derivation.balls_at(state)
    for unknown in derivation.unknowns:
        with ctx.workprec(320):
            exact = arb(str(sp.N(derivation.at(state).raw[unknown].xreplace(state), 90)))
        assert balls[unknown].rad() < 1e-60 and balls[unknown].overlaps(exact), unknown


def test_pendulum_equation_of_motion_uses_the_parallel_axis():
    theta = sym("theta_bob")
    for route in (lagrange, newton_euler):
        acceleration = route.derive(pendulum_scene()).solution[sym("thetaddot_bob")]
        assert sp.simplify(acceleration + M * g * d * sp.sin(theta) / (I + M * d**2)) == 0


def test_small_oscillation_frequency_and_period():
    scene = pendulum_scene()
    for route in (lagrange, newton_euler):
        oscillation = small_oscillation(scene, route.derive(scene))
        assert sp.simplify(oscillation.quantity("omega")**2 - M * g * d / (I + M * d**2)) == 0
        assert sp.simplify(oscillation.quantity("period") - 2 * sp.pi * sp.sqrt((I + M * d**2) / (M * g * d))) == 0


def test_small_oscillation_period_against_simulation():
    """Integrate the full nonlinear equation at a small amplitude; the zero crossings give the period."""
    scene = pendulum_scene()
    derived = lagrange.derive(scene)
    values = {M: 2, g: 9.81, d: sp.Rational(3, 10), I: sp.Rational(1, 20)}
    acceleration = sp.lambdify(sym("theta_bob"), derived.solution[sym("thetaddot_bob")].subs(values))
    period = float(small_oscillation(scene, derived).quantity("period").subs(values))
    amplitude = 1e-4
    crossing = lambda t, y: y[0]  # noqa: E731
    crossing.direction = 1
    run = solve_ivp(lambda t, y: [y[1], acceleration(y[0])], (0, 3.2 * period), [amplitude, 0.0],
                    rtol=1e-11, atol=1e-15, events=crossing)
    upward = run.t_events[0]
    assert len(upward) >= 2
    assert abs((upward[1] - upward[0]) - period) / period < 1e-6
    assert np.isclose(upward[1] - upward[0], period, rtol=1e-6)


def test_block_falls_as_derived_in_a_simulation():
    """Integrate the Newton–Euler accelerations; the block's drop after 1 s is a t^2 / 2."""
    derived = released(newton_euler, disk_scene())
    values = {m: 1, M: 3, R: sp.Rational(1, 5), g: 9.81}
    a = float(derived[sym("yddot_block")].subs(values))
    run = solve_ivp(lambda t, y: [y[1], a], (0, 1), [0.0, 0.0], rtol=1e-12, atol=1e-14)
    assert math.isclose(run.y[0, -1], a / 2, rel_tol=1e-9)
    assert math.isclose(a, -2 * 9.81 / 5, rel_tol=1e-12)


def test_inverted_pendulum_grows_instead_of_oscillating():
    """The tightrope walker (notes §5.1): standing on the pivot, theta'' = (m g h / I_pivot) theta."""
    scene = Scene({"bob": Body("bob", "custom", M, {}, I)}, (Pin("pivot", "bob", (0, -d)),), Gravity(g))
    for route in (lagrange, newton_euler):
        linear = small_oscillation(scene, route.derive(scene))
        assert not linear.stable
        assert sp.simplify(linear.quantity("growth_rate") ** 2 - M * g * d / (I + M * d**2)) == 0
        with pytest.raises(OscillationError, match="unstable"):
            linear.quantity("omega")


def test_redundant_constraints_are_reported():
    a, b = sp.symbols("a b")
    with pytest.raises(ValueError, match="do not determine every force"):
        solve_linear([sp.Eq(a + b, 1), sp.Eq(2 * a + 2 * b, 2)], [a, b])


def test_time_derivative_is_the_chain_rule():
    coords = Coordinates(pendulum_scene())
    theta = coords.of("bob", "theta")
    assert coords.ddt(coords.ddt(sp.cos(theta.q))) == -sp.cos(theta.q) * theta.u**2 - sp.sin(theta.q) * theta.a
