"""Rolling without slipping and sliding on an incline: both routes, energy, simulation."""
import math

import numpy as np
import pytest
import sympy as sp
from scipy.integrate import solve_ivp

from derive.mechanics import lagrange, newton_euler
from derive.mechanics.conservation import speed_after_drop
from derive.scene import Body, Contact, Gravity, Incline, Scene

M, R, g, H, alpha = sp.symbols("M R g H alpha", positive=True)


def ramp_scene(shape, rolling=True):
    sizes = {"radius": R} if shape != "point" else {}
    return Scene({"b": Body("b", shape, M, sizes)}, (Contact("b_contact", "b", "ramp", rolling),), Gravity(g),
                 {"ramp": Incline("ramp", alpha, H)})


def sym(name):
    return sp.Symbol(name, real=True)


@pytest.mark.parametrize("shape, ratio", [("ring", 1), ("disk", sp.Rational(1, 2))])
def test_rolling_acceleration_friction_and_normal_force(shape, ratio):
    for route in (lagrange, newton_euler):
        s = route.derive(ramp_scene(shape)).solution
        along = sp.cos(alpha) * s[sym("xddot_b")] - sp.sin(alpha) * s[sym("yddot_b")]
        assert sp.simplify(along - g * sp.sin(alpha) / (1 + ratio)) == 0
        assert sp.simplify(s[sym("N^b")] - M * g * sp.cos(alpha)) == 0
        # Static friction points up the slope and supplies the torque I alpha / R.
        assert sp.simplify(s[sym("f^b")] + ratio * M * g * sp.sin(alpha) / (1 + ratio)) == 0
        # Rolling: the center's speed is omega R, turning clockwise as it goes down.
        assert sp.simplify(s[sym("thetaddot_b")] * R + along) == 0


def test_frictionless_block_slides_with_g_sin_alpha():
    s = newton_euler.derive(ramp_scene("point", rolling=False)).solution
    assert sp.simplify(sp.cos(alpha) * s[sym("xddot_b")] - sp.sin(alpha) * s[sym("yddot_b")] - g * sp.sin(alpha)) == 0


@pytest.mark.parametrize("shape, rolling, expected", [
    ("point", False, sp.sqrt(2 * g * H)),
    ("ring", True, sp.sqrt(g * H)),
    ("disk", True, sp.sqrt(sp.Rational(4, 3) * g * H)),
])
def test_energy_conservation_speeds(shape, rolling, expected):
    assert sp.simplify(speed_after_drop(ramp_scene(shape, rolling), "b", H).speed - expected) == 0


def test_simulated_roll_matches_energy_and_time():
    """Integrate the Newton–Euler equations in (x, y, theta) from rest until the center drops H."""
    scene = ramp_scene("disk")
    values = {M: 2, R: sp.Rational(1, 5), g: sp.Rational(981, 100), H: sp.Rational(3, 2), alpha: sp.Rational(1, 2)}
    solution = newton_euler.derive(scene).solution
    accel = [float(solution[sym(f"{k}ddot_b")].subs(values)) for k in ("x", "y", "theta")]

    def rhs(t, y):
        return [y[3], y[4], y[5], *accel]

    def bottom(t, y):
        return y[1] + 1.5
    bottom.terminal = True

    run = solve_ivp(rhs, (0, 10), [0, 0, 0, 0, 0, 0], rtol=1e-12, atol=1e-14, events=bottom)
    x, y, theta, vx, vy, omega = run.y[:, -1]
    speed = math.hypot(vx, vy)
    assert math.isclose(speed, math.sqrt(4 / 3 * 9.81 * 1.5), rel_tol=1e-9)
    # Energy is conserved along the path, and the contact point does not slip.
    kinetic = 0.5 * 2 * speed**2 + 0.5 * (0.5 * 2 * 0.2**2) * omega**2
    assert math.isclose(kinetic, 2 * 9.81 * 1.5, rel_tol=1e-9)
    assert math.isclose(speed, -omega * 0.2, rel_tol=1e-9)
    # Time to the bottom: s = H / sin(alpha) at a = (2/3) g sin(alpha).
    a = 2 / 3 * 9.81 * math.sin(0.5)
    assert np.isclose(run.t_events[0][0], math.sqrt(2 * (1.5 / math.sin(0.5)) / a), rtol=1e-9)
