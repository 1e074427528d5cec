"""A body on a fixed point (derive.mechanics.fixed_point): the three routes' equations of motion
agree for bodies of several shapes, symmetric or not; the steady motions against the textbook
forms; a simulation of the full Euler-angle motion; the library's tops keep their answers; a
wrong route is caught; what is not modelled is refused naming the field."""
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
from derive.mechanics import bearings, fixed_point

m, g, l, I1, I3, w, th, s = sp.symbols("m g l I_1 I_3 omega theta s", positive=True)
#: A symmetric top given by its moments about the fixed point: the tensor about its center.
TOP = sp.ImmutableMatrix(sp.diag(I1 - m * l**2, I1 - m * l**2, I3))


@pytest.mark.parametrize("shape, sizes, offset", [
    ("cone", {"radius": s, "height": 3 * s}, (0, 0, 9 * s / 4)),  # on its tip
    ("disk", {"radius": s}, (0, 0, -l)),  # on a light axle of length l
    ("rod", {"length": 2 * s}, (-s, 0, 0)),  # on its end
    ("box", {"side_a": s, "side_b": 2 * s, "side_c": 3 * s}, (s / 2, s, 0)),  # on a corner of a face: no symmetry
])
def test_the_three_routes_give_the_same_equations(shape, sizes, offset):
    tensor, distance = fixed_point.standing(bearings.body_tensor(shape, m, sizes), offset)
    found = [fixed_point.equations(tensor, m, g, distance, route) for route in fixed_point.ROUTES]
    assert all(sp.simplify(f - found[0]) == sp.zeros(3, 1) for f in found[1:])
    assert found[0] != sp.zeros(3, 1)


def test_the_steady_motions_are_the_textbook_ones():
    conditions = {route: fixed_point.precession_condition(TOP, m, g, l, w, th, route) for route in fixed_point.ROUTES}
    book = I1 * fixed_point.OMEGA**2 * sp.cos(th) - I3 * w * fixed_point.OMEGA + m * g * l  # Taylor ch. 10
    assert all(sp.simplify(c - book / (I1 * sp.cos(th))) == 0 for c in conditions.values())
    slow, fast = fixed_point.roots(TOP, m, g, l, w, th)
    assert sp.simplify(book.subs(fixed_point.OMEGA, slow)) == 0 and sp.simplify(book.subs(fixed_point.OMEGA, fast)) == 0
    assert fixed_point.fast_top(slow, w, th) == m * g * l / (I3 * w)
    horizontal = fixed_point.roots(TOP, m, g, l, w, sp.pi / 2)
    assert horizontal == (m * g * l / (I3 * w), None)  # the gyroscope: Omega = m g l/(I3 omega), exactly
    for route in ("lagrange", "newton_euler"):
        assert fixed_point.min_spin(TOP, m, g, l, route) == 2 * sp.sqrt(I1 * m * g * l) / I3
    nutation = [fixed_point.nutation_frequency(TOP, m, g, l, w, th, r) for r in ("lagrange", "newton_euler")]
    known = sp.sqrt((I3 * w - 2 * I1 * slow * sp.cos(th)) ** 2 + I1**2 * slow**2 * sp.sin(th) ** 2) / I1
    point = {m: sp.Rational(1, 5), g: sp.Rational(981, 100), l: sp.Rational(1, 20), I1: sp.Rational(1, 2000),
             I3: sp.Rational(1, 20000), w: 300, th: sp.Rational(1, 2)}
    assert all(abs(sp.N((n - known).subs(point), 30)) < 1e-20 for n in nutation)
    assert fixed_point.fast_top(nutation[0], w, th) == I3 * w / I1


def test_a_box_is_no_symmetric_top():
    tensor, distance = fixed_point.standing(bearings.body_tensor("box", m, {"side_a": s, "side_b": 2 * s,
                                                                            "side_c": 3 * s}), (0, 0, -s))
    with pytest.raises(fixed_point.NotSymmetric):
        fixed_point.roots(tensor, m, g, distance, w, th)


def _euler_angle_motion(values):
    """Numerical equations of the top, (phi, theta, psi) and their rates, from Kane's route."""
    t = me.dynamicsymbols._t
    q = fixed_point._angles()
    eqs = fixed_point.equations(TOP, m, g, l, "kane").subs(values)
    accelerations = [c.diff(t, 2) for c in q]
    a, b = sp.symbols("a0:3"), sp.symbols("b0:3")
    matrix, forcing = sp.linear_eq_to_matrix(list(eqs), accelerations)
    now = {**{c.diff(t): v for c, v in zip(q, b)}, **dict(zip(q, a))}
    return sp.lambdify([*a, *b], list(me.msubs(matrix, now).LUsolve(me.msubs(forcing, now))), "numpy")


def test_the_slow_root_is_a_steady_precession_in_simulation():
    values = {m: sp.Rational(2, 10), g: sp.Rational(981, 100), l: sp.Rational(5, 100), I1: sp.Rational(5, 10000),
              I3: sp.Rational(5, 100000), w: 300, th: sp.Rational(1, 2)}
    slow = float(fixed_point.roots(TOP, m, g, l, w, th)[0].subs(values))
    rates = _euler_angle_motion(values)
    tilt, spin = 0.5, 300.0
    start = [0.0, tilt, 0.0, slow, 0.0, spin - slow * math.cos(tilt)]  # phi, theta, psi, then rates
    run = solve_ivp(lambda t, y: [*y[3:], *rates(*y)], (0, 2.0), start, method="DOP853", rtol=1e-12, atol=1e-12)
    assert np.max(np.abs(run.y[1] - tilt)) < 1e-7  # no nutation: theta stays put
    assert math.isclose(run.y[0, -1] / run.t[-1], slow, rel_tol=1e-7)
    # The notes' rate is only the fast-top limit: started there the top nods noticeably.
    start[3] = float((m * g * l / (I3 * w)).subs(values))
    run = solve_ivp(lambda t, y: [*y[3:], *rates(*y)], (0, 2.0), start, method="DOP853", rtol=1e-12, atol=1e-12)
    assert np.max(np.abs(run.y[1] - tilt)) > 1e-4
    # Nudged off the slow precession, it nods at the nutation frequency.
    start[3] = slow * (1 + 1e-4)
    run = solve_ivp(lambda t, y: [*y[3:], *rates(*y)], (0, 2.0), start, method="DOP853", rtol=1e-12, atol=1e-12,
                    dense_output=True)
    nutation = float(fixed_point.nutation_frequency(TOP, m, g, l, w, th, "lagrange").subs(values))
    times = np.linspace(0, 2.0, 200001)
    highest = times[1:-1][np.diff(np.sign(np.diff(run.sol(times)[1]))) < 0]  # the tilt's maxima
    assert len(highest) >= 4
    assert math.isclose(2 * math.pi * (len(highest) - 1) / (highest[-1] - highest[0]), nutation, rel_tol=1e-3)


def test_too_slow_a_spin_is_refused_with_a_clear_message():
    with pytest.raises(InputError, match="no steady precession"):
        report.solve(problem.load("top_precession_exact"), {"m": "0.2", "Rcm": "0.05", "I3": "5e-5", "I1": "5e-4",
                                                            "theta": "0.5", "omega": "30"}, 15)


def test_library_tops_keep_their_answers():
    result = report.solve(problem.load("top_precession"), {"m": "0.2", "Rcm": "0.05", "I": "5e-5", "omega": "300"}, 15)
    assert result["answers"]["Omega"]["value"] == "6.54000000000000"
    # the special-purpose top's closed forms (derive.mechanics.top, retired), exactly
    exact = Solution(problem.load("top_precession_exact"))
    M, G, R, J1, J3, W, T = sp.symbols("m g Rcm I1 I3 omega theta", positive=True)
    root = sp.sqrt(J3**2 * W**2 - 4 * J1 * R * G * M * sp.cos(T))
    old = {"Omega_slow": 2 * R * G * M / (J3 * W + root), "Omega_fast": (J3 * W + root) / (2 * J1 * sp.cos(T)),
           "Omega_approx": R * G * M / (J3 * W)}
    symbols = {p.symbol.name: p.symbol for p in exact.problem.parameters.values()}
    for name, form in old.items():
        assert sp.simplify(exact.expression(name) - form.xreplace({x: symbols[x.name] for x in form.free_symbols})) == 0


def test_a_wrong_route_is_caught(monkeypatch):
    right = fixed_point.equations

    def wrong(tensor, mass, gravity, distance, route):
        found = right(tensor, mass, gravity, distance, route)
        return found * 2 if route == "kane" else found

    monkeypatch.setattr(fixed_point, "equations", wrong)
    with pytest.raises(CheckFailure, match="kane"):
        Solution(problem.load("top_precession_exact")).checks()


TOP_FILE = """id: spun
title: A top
topic: precession
parameters:
  m: {meaning: mass, unit: kg, value: 1}
  h: {meaning: height, unit: m, value: 0.1}
  R: {meaning: radius, unit: m, value: 0.05}
  g: {meaning: gravity, unit: m/s^2, value: 9.81}
  omega: {meaning: spin, unit: rad/s, value: 300}
scene:
  bodies:
    top: {shape: cone, mass: m, radius: R, height: h, pivot_point: {at: tip, tilt: TILT, spin: omega}EXTRA}
  loads:
    - gravity: g
ask:
  x: {meaning: asked, of: ASK, unit: rad/s}
question: A top spins.
"""


@pytest.mark.parametrize("tilt, extra, ask, field", [
    ("2", "", "top.precession.slow", "ask.x.of"),  # hangs below its point: only its steady cone is asked
    ("pi/2", "", "top.precession.fast", "scene.bodies.top.pivot_point.tilt"),  # horizontal: no fast root
    ("0.5", ", joint: fixed_axle", "top.precession.slow", "scene.bodies.top.joint"),
    ("0.5", "", "top.acceleration.x", "ask.x"),
    ("0.5", "}\n    other: {shape: point, mass: m, at: [h, 0]", "top.precession.slow", "scene: a body on a fixed point"),
])
def test_what_a_fixed_point_does_not_model_is_refused(tmp_path, tilt, extra, ask, field):
    refused(tmp_path, TOP_FILE.replace("TILT", tilt).replace("EXTRA", extra).replace("ASK", ask), field)


def test_an_unsymmetric_body_is_refused_a_steady_precession(tmp_path):
    text = TOP_FILE.replace("{shape: cone, mass: m, radius: R, height: h, pivot_point: {at: tip",
                            "{shape: box, mass: m, side_a: R, side_b: h, side_c: h, pivot_point: {at: h")
    assert "not a symmetric top" in refused(tmp_path, text.replace("TILT", "0.5").replace("EXTRA", "")
                                            .replace("ASK", "top.precession.slow"), "scene.bodies.top")


def test_the_old_top_key_is_refused(tmp_path):
    text = TOP_FILE.replace("  bodies:\n    top: {shape: cone, mass: m, radius: R, height: h, pivot_point: "
                            "{at: tip, tilt: TILT, spin: omega}EXTRA}\n",
                            "  top: {mass: m, pivot_distance: h, spin_inertia: R, spin: omega}\n")
    assert "pivot_point" in refused(tmp_path, text.replace("ASK", "top.precession.fast_top"), "scene.top")
