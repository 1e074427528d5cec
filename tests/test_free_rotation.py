"""A body turning with no torque (derive.mechanics.free_rotation): both routes agree for any
moments; Taylor's Earth and Feynman's plate; a rigid body's rotation integrated numerically
(its orientation and Euler's equations, numpy alone) shows the derived precession rates, wobbles
and growth rate; a wrong route is caught; what is not modelled is refused naming the field."""
import math
import re

import numpy as np
import pytest
import sympy as sp
from scipy.integrate import solve_ivp

from conftest import refused, textbook
from derive.publishing import distractors, figure, report
from derive.language import problem
from derive.checks import simulate_solid
from derive.solution.answers import Solution
from derive.solution.crosschecks import CheckFailure
from derive.mechanics import free_rotation

I1, I2, I3, w3, wt, W = sp.symbols("I_1 I_2 I_3 omega_3 omega_t W", positive=True)


@pytest.mark.parametrize("detail", free_rotation.SYMMETRIC)
def test_both_routes_give_the_symmetric_body_s_precession(detail):
    found = [free_rotation.precession((I1, I3), w3, wt, detail, route) for route in free_rotation.ROUTES]
    assert sp.simplify(found[0] - found[1]) == 0
    book = {"free_precession.body": (I3 - I1) * w3 / I1,  # Taylor §10.8
            "free_precession.space": sp.sqrt(I1**2 * wt**2 + I3**2 * w3**2) / I1,
            "angle_L_axis": sp.atan(I1 * wt / (I3 * w3)), "angle_omega_axis": sp.atan(wt / w3)}[detail]
    assert sp.simplify(found[0] - book) == 0


@pytest.mark.parametrize("axis", [0, 1, 2])
def test_both_routes_give_a_steady_rotation_s_small_motions(axis):
    moments = (I1, I2, I3)
    found = [free_rotation.exponent_squared(moments, axis, W, route) for route in free_rotation.ROUTES]
    i, j = (k for k in range(3) if k != axis)
    book = -(moments[axis] - moments[i]) * (moments[axis] - moments[j]) * W**2 / (moments[i] * moments[j])
    assert all(sp.simplify(f - book) == 0 for f in found)


def test_the_earth_wobbles_in_about_300_days():
    # Taylor §10.8: (lambda3 - lambda1)/lambda1 = 0.00327 for the Earth; the period 2 pi/Omega_b is
    # then 1/0.00327 days, about 306 (the observed Chandler wobble, 430 days, is slower: the Earth is not rigid)
    day = 2 * math.pi / 7.29e-5
    result = report.solve(problem.load(textbook("earth_free_precession")),
                          {"I1": "8.0e37", "I3": "8.02616e37", "omega": "7.29e-5"}, 6)
    period = 2 * math.pi / float(result["answers"]["Omega"]["value"]) / day
    assert 300 < period < 310 and math.isclose(period, 1 / 0.00327, rel_tol=1e-4)


def test_feynman_s_plate_wobbles_twice_as_fast_as_its_spin_precesses():
    plate = Solution(problem.load(textbook("thrown_plate_wobble")))
    symbols = {p.symbol.name: p.symbol for p in plate.problem.parameters.values()}
    ratio = plate.expression("space") / plate.expression("body")
    assert sp.limit(ratio, symbols["omega_t"], 0) == 2


def _spin(moments, omega, time):
    """A free rigid body integrated from omega (body frame) at the identity: Euler's equations
    I w' = (I w) x w and the orientation R' = R [w]x, with numpy alone; (t, R, w) on a fine grid."""
    inertia = np.array(moments, dtype=float)

    def rates(t, y):
        R, w = y[:9].reshape(3, 3), y[9:]
        cross = np.array([[0, -w[2], w[1]], [w[2], 0, -w[0]], [-w[1], w[0], 0]])
        return np.concatenate([(R @ cross).ravel(), np.cross(inertia * w, w) / inertia])

    times = np.linspace(0, time, 20001)
    run = solve_ivp(rates, (0, time), np.concatenate([np.eye(3).ravel(), omega]), method="DOP853", rtol=1e-11,
                    atol=1e-12, t_eval=times)
    return run.t, run.y[:9].T.reshape(-1, 3, 3), run.y[9:].T


@pytest.mark.parametrize("shape, sizes", [("disk", "radius: R"), ("cylinder", "radius: R, height: 5*R")])
def test_a_simulated_symmetric_body_precesses_at_the_derived_rates(tmp_path, shape, sizes):
    text = BODY.replace("SHAPE", f"{{shape: {shape}, mass: m, {sizes}, free_rotation: {{spin: w3, across: wt}}}}")
    path = tmp_path / "p.yaml"
    path.write_text(text.replace("ASKS", "\n".join(f"  a{i}: {{meaning: asked, of: body.{d}, unit: "
                                                 f"{'rad' if d.startswith('angle') else 'rad/s'}}}"
                                                 for i, d in enumerate(free_rotation.SYMMETRIC))))
    solution = Solution(problem.load(path))
    values = {p.symbol: p.value for p in solution.problem.parameters.values()}
    derived = [float(solution.expression(f"a{i}").xreplace(values)) for i in range(4)]
    moments = [float(m.xreplace(values)) for m in solution.free_moments("body")]
    times, turns, omegas = _spin(moments, [float(values[sp.Symbol("wt", positive=True)]), 0,
                                           float(values[sp.Symbol("w3", positive=True)])], 3.0)
    assert math.isclose(simulate_solid.turning_rate(omegas, times, np.array([0, 0, 1.0])), derived[0], rel_tol=1e-6)
    momentum = moments * omegas[0]  # in space, at the start (R = 1)
    axes = turns[:, :, 2]  # the symmetry axis in space
    assert math.isclose(simulate_solid.turning_rate(axes, times, momentum), derived[1], rel_tol=1e-6)
    cosines = axes @ momentum / np.linalg.norm(momentum)
    assert np.allclose(np.arccos(cosines), derived[2], atol=1e-8)
    assert math.isclose(math.atan2(omegas[0, 0], omegas[0, 2]), derived[3], rel_tol=1e-12)


BODY = """id: spun
title: A body turning freely
topic: angular_momentum
parameters:
  m: {meaning: mass, unit: kg, value: 0.5}
  R: {meaning: radius, unit: m, value: 0.1}
  w3: {meaning: spin, unit: rad/s, value: 7}
  wt: {meaning: across, unit: rad/s, value: 2}
scene:
  bodies:
    body: SHAPE
ask:
ASKS
question: A body turns.
"""

BOOK = """id: book
title: A book thrown spinning
topic: angular_momentum
parameters:
  a: {meaning: thickness, unit: m, value: 0.03}
  b: {meaning: width, unit: m, value: 0.17}
  c: {meaning: height, unit: m, value: 0.26}
  W: {meaning: rate, unit: rad/s, value: 10}
scene:
  bodies:
    book: {shape: box, side_a: a, side_b: b, side_c: c, free_rotation: {spin: W}EXTRA}
ask:
  x: {meaning: asked, of: ASK, unit: rad/s}
question: A book turns.
"""


def _book(tmp_path, ask, extra=""):
    path = tmp_path / "book.yaml"
    path.write_text(BOOK.replace("ASK", ask).replace("EXTRA", extra))
    solution = Solution(problem.load(path))
    values = {p.symbol: p.value for p in solution.problem.parameters.values()}
    return solution, float(solution.expression("x").xreplace(values))


def test_a_simulated_book_wobbles_about_two_axes_and_tumbles_about_the_third(tmp_path):
    solution, growth = _book(tmp_path, "book.rotation.intermediate.growth_rate")
    values = {p.symbol: p.value for p in solution.problem.parameters.values()}
    values[sp.Symbol("m_book", positive=True)] = 1  # the mass is left open: it cancels
    moments = [float(m.xreplace(values)) for m in solution.free_moments("book")]
    assert [solution.free_axis("book", r) for r in free_rotation.RANKS] == [2, 1, 0]  # a < b < c
    # about the intermediate axis (y) a nudge of 1e-9 grows as e^(growth t) (once the decaying
    # mode has died away) while it is small
    times, _, omegas = _spin(moments, [1e-9, 10.0, 0], 2.5)
    early = (times > 1.5) & (times < 2.5)
    slope = np.polyfit(times[early], np.log(np.abs(omegas[early, 2])), 1)[0]
    assert math.isclose(slope, growth, rel_tol=1e-4)
    assert np.max(np.abs(omegas[:, 1])) > 9.99  # still near the axis then; it tumbles later
    tumble = _spin(moments, [1e-9, 10.0, 0], 30 / growth)[2]  # e^30 times 1e-9: large
    assert np.min(tumble[:, 1]) < 0  # the rotation about the intermediate axis turned over
    for rank, axis in (("least", 2), ("greatest", 0)):
        _, wobble = _book(tmp_path, f"book.rotation.{rank}.wobble")
        start = [0.0, 0.0, 0.0]
        start[axis], start[(axis + 1) % 3] = 10.0, 1e-6
        times, _, omegas = _spin(moments, start, 3.0)
        nudged = omegas[:, (axis + 1) % 3]
        assert np.max(np.abs(nudged)) < 1e-5  # stays small
        crossings = times[1:][np.diff(np.sign(nudged)) != 0]
        assert math.isclose(math.pi * (len(crossings) - 1) / (crossings[-1] - crossings[0]), wobble, rel_tol=1e-3)


def test_a_wrong_route_is_caught(monkeypatch):
    right = free_rotation.precession

    def wrong(moments, spin, across, detail, route):
        found = right(moments, spin, across, detail, route)
        return found * 2 if route == "lagrange" else found

    monkeypatch.setattr(free_rotation, "precession", wrong)
    with pytest.raises(CheckFailure, match="Lagrange"):
        Solution(problem.load(textbook("thrown_plate_wobble"))).checks()


def test_a_variant_whose_moments_change_order_is_refused():
    # the axes are ranked at the middle of the ranges (c the longest edge); a c shorter than b breaks it
    with pytest.raises(Exception, match="change order"):
        report.solve(problem.load(textbook("tennis_racket")), {"a": "0.03", "b": "0.2", "c": "0.1", "W": "10"}, 6)


@pytest.mark.parametrize("shape, ask, field, words", [
    ("{shape: box, mass: m, side_a: R, side_b: 2*R, side_c: 3*R, free_rotation: {spin: w3, across: wt}}",
     "body.free_precession.space", "scene.bodies.body", "no symmetry axis"),
    ("{shape: disk, mass: m, radius: R, free_rotation: {spin: w3}}", "body.rotation.least.wobble",
     "scene.bodies.body", "two principal moments are equal"),
    ("{shape: rod, mass: m, length: R, free_rotation: {spin: w3, across: wt}}", "body.free_precession.space",
     "scene.bodies.body", "thin rod"),
    ("{shape: disk, mass: m, radius: R, joint: fixed_axle, free_rotation: {spin: w3, across: wt}}",
     "body.free_precession.space", "scene.bodies.body.joint", "held by nothing"),
    ("{shape: point, mass: m, free_rotation: {spin: w3, across: wt}}", "body.free_precession.space",
     "scene.bodies.body.free_rotation", "not a point"),
    ("{shape: disk, mass: m, radius: R, free_rotation: {spin: w3, across: wt}}\n  loads:\n    - gravity: R*w3**2",
     "body.free_precession.space", "scene", "leave gravity out"),
    ("{shape: disk, mass: m, radius: R, free_rotation: {spin: w3, across: wt}}\n  states:\n    spun: {rates: "
     "{body.angular_velocity: w3}}", "body.free_precession.space", "scene", "states"),
    ("{shape: disk, mass: m, radius: R, free_rotation: {spin: w3, across: wt}}", "body.acceleration.x", "ask.a0",
     "a body in free rotation has"),
    ("{shape: disk, mass: m, radius: R, free_rotation: {spin: w3, across: wt}}", "body.rotation.intermediate.wobble",
     "ask.a0", "tennis-racket"),
    ("{shape: disk, mass: m, radius: R, free_rotation: {spin: w3, across: wt}}", "body.free_precession.bodies",
     "ask.a0", "did you mean 'free_precession.body'"),
    ("{shape: disk, mass: m, radius: R, free_rotation: {spin: -w3, across: wt}}", "body.free_precession.space",
     "scene.bodies.body.free_rotation.spin", "positive"),
    ("{shape: disk, mass: m, radius: R, free_rotation: {spin: w3, wobble: wt}}", "body.free_precession.space",
     "scene.bodies.body.free_rotation", "wobble"),
])
def test_what_free_rotation_does_not_model_is_refused(tmp_path, shape, ask, field, words):
    text = BODY.replace("SHAPE", shape).replace("ASKS", f"  a0: {{meaning: asked, of: {ask}, unit: rad/s}}")
    if "wt" not in shape:
        text = text.replace("  wt: {meaning: across, unit: rad/s, value: 2}\n", "")
    assert words in refused(tmp_path, text, field)


def test_across_is_needed_only_where_an_ask_reads_it(tmp_path):
    given = BODY.replace("SHAPE", "{shape: disk, mass: m, radius: R, free_rotation: {spin: w3, across: wt}}")
    refused(tmp_path, given.replace("ASKS", "  a0: {meaning: asked, of: body.free_precession.body, unit: rad/s}"),
            "scene.bodies.body.free_rotation.across")
    shape = "{shape: disk, mass: m, radius: R, free_rotation: {spin: w3}}"
    text = BODY.replace("SHAPE", shape).replace("  wt: {meaning: across, unit: rad/s, value: 2}\n", "")
    path = tmp_path / "p.yaml"
    path.write_text(text.replace("ASKS", "  a0: {meaning: asked, of: body.free_precession.body, unit: rad/s}"))
    assert report.solve(problem.load(path))["answers"]["a0"]["value"] == "7.00000000000000"  # omega3: a disk's I3 = 2 I1
    refused(tmp_path, text.replace("ASKS", "  a0: {meaning: asked, of: body.free_precession.space, unit: rad/s}"),
            "ask.a0")


def test_the_figure_draws_l_the_axis_and_omega_at_their_angles(tmp_path):
    # a disk, I3 = 2 I1, omega_t/omega3 = 1/2: L at atan(1/4) from the axis, omega at atan(1/2), beyond L
    shape = "{shape: disk, mass: m, radius: R, free_rotation: {spin: w3, across: wt}}"
    asks = "  a0: {meaning: asked, of: body.angle_L_axis, unit: rad}"
    path = tmp_path / "p.yaml"
    path.write_text(BODY.replace("SHAPE", shape).replace("ASKS", asks).replace("value: 2}", "value: 3.5}"))
    picture = figure.tikz(problem.load(path))
    ends = {style: tuple(map(float, re.search(rf"\\draw\[{style}\] \(0,0\) -- \(([-\d.]+),([-\d.]+)\)",
                                                picture).groups()))
            for style in ("very thick, ->, green!40!black", "velocity")}
    axis = re.search(r"\\draw\[axis\] \(([-\d.]+),([-\d.]+)\) -- \(([-\d.]+),([-\d.]+)\)", picture).groups()
    axis = np.subtract(*np.reshape(np.array(axis, dtype=float), (2, 2))[::-1])

    def degrees(u, v):
        return math.degrees(math.acos(np.dot(u, v) / np.linalg.norm(u) / np.linalg.norm(v)))

    momentum = ends["very thick, ->, green!40!black"]
    assert momentum[0] == 0  # L up the page
    assert math.isclose(degrees(momentum, axis), math.degrees(math.atan(0.25)), abs_tol=0.5)
    assert math.isclose(degrees(ends["velocity"], axis), math.degrees(math.atan(0.5)), abs_tol=0.5)
    assert ends["velocity"][0] > 0 > axis[0]  # omega beyond L, the axis on L's other side


DUMBBELL = """
      shape: composite
      parts:
        bar: {shape: rod, mass: m, length: 4*R}
        one: {shape: sphere, mass: m, radius: R, at: [2*R, 0]}
        two: {shape: sphere, mass: m, radius: R, at: [-2*R, 0]}"""


def test_a_football_like_composite_precesses_about_its_long_axis(tmp_path):
    # a rod of length 4R with a ball of radius R at each end: symmetric about x (its length), long
    path = tmp_path / "p.yaml"
    text = BODY.replace(" SHAPE", DUMBBELL + "\n      free_rotation: {spin: w3}")
    text = text.replace("  wt: {meaning: across, unit: rad/s, value: 2}\n", "")
    path.write_text(text.replace("ASKS", "  a0: {meaning: asked, of: body.free_precession.body, unit: rad/s}"))
    solution = Solution(problem.load(path))
    m, R, w = (p.symbol for p in (solution.problem.parameters[n] for n in ("m", "R", "w3")))
    axial = 2 * sp.Rational(2, 5) * m * R**2  # the balls about their centers' line
    transverse = m * (4 * R) ** 2 / 12 + 2 * (sp.Rational(2, 5) * m * R**2 + m * (2 * R) ** 2)  # parallel axes
    assert sp.simplify(solution.expression("a0") - (axial - transverse) * w / transverse) == 0
    assert all(c.passed for c in solution.checks())


def test_a_composite_whose_own_axes_are_not_principal_is_an_engine_limit(tmp_path):
    bent = DUMBBELL.replace("{shape: rod, mass: m, length: 4*R}", "{shape: rod, mass: m, length: 4*R, at: [2*R, 0]}")
    text = BODY.replace(" SHAPE", bent.replace("at: [-2*R, 0]", "at: [0, 2*R]") + "\n      free_rotation: {spin: w3}")
    text = text.replace("  wt: {meaning: across, unit: rad/s, value: 2}\n", "")
    assert "derive cannot yet find the principal axes of the body" in refused(
        tmp_path, text.replace("ASKS", "  a0: {meaning: asked, of: body.free_precession.body, unit: rad/s}"),
        "not principal", exit_code=1)


RACKET = """id: racket
title: A tennis racket
topic: angular_momentum
parameters:
  I1: {meaning: least moment, unit: kg*m^2, range: [0.001, 0.002]}
  I2: {meaning: intermediate moment, unit: kg*m^2, range: [0.01, 0.02]}
  I3: {meaning: greatest moment, unit: kg*m^2, range: [0.03, 0.04]}
  W: {meaning: rate, unit: rad/s, value: 10}
scene:
  bodies:
    racket: {shape: custom, inertia: {principal: PRINCIPAL}, free_rotation: {spin: W}}
ask:
  least: {meaning: wobble, of: racket.rotation.least.wobble, unit: rad/s}
  middle: {meaning: growth, of: racket.rotation.intermediate.growth_rate, unit: rad/s}
  greatest: {meaning: wobble, of: racket.rotation.greatest.wobble, unit: rad/s}
question: A racket turns.
"""


def test_a_custom_body_given_its_three_principal_moments(tmp_path):
    # Morin ch. 9, Taylor §10.8 with lambda1 < lambda2 < lambda3 given, in any order along the own axes
    path = tmp_path / "racket.yaml"
    path.write_text(RACKET.replace("PRINCIPAL", "[I2, I3, I1]"))
    solution = Solution(problem.load(path))
    J1, J2, J3, rate = (solution.problem.parameters[n].symbol for n in ("I1", "I2", "I3", "W"))
    book = {"least": rate * sp.sqrt((J2 - J1) * (J3 - J1) / (J2 * J3)),
            "middle": rate * sp.sqrt((J2 - J1) * (J3 - J2) / (J1 * J3)),
            "greatest": rate * sp.sqrt((J3 - J1) * (J3 - J2) / (J1 * J2))}
    assert all(sp.simplify(solution.expression(n) - f) == 0 for n, f in book.items())
    assert [solution.free_axis("racket", r) for r in free_rotation.RANKS] == [2, 0, 1]
    assert all(c.passed for c in solution.checks())
    refused(tmp_path, RACKET.replace("PRINCIPAL", "[I1, I2]"), "scene.bodies.racket.inertia.principal")


def test_multiple_choice_offers_the_moments_swapped():
    # a long cylinder: with I1 and I3 swapped omega would turn the other way about the axis
    p = problem.load(textbook("football_free_precession"))
    values = p.values({"M": "0.4", "R": "0.04", "h": "0.25", "omega3": "40", "omega_t": "3"})
    found = {d["mistake"]: d["value"] for d in distractors.distractors(p, "body", values, 3, limit=10)}
    right = float(report.solve(p, {"M": "0.4", "R": "0.04", "h": "0.25", "omega3": "40", "omega_t": "3"}, 6)
                  ["answers"]["body"]["value"])
    swapped = float(found["the ball's moments about its axis and across it swapped"])
    assert right < 0 < swapped  # retrograde, and prograde when swapped: (I1 - I3) omega3/I3
    assert math.isclose(swapped, -right * (1 + right / 40) ** -1, rel_tol=2e-3)


def test_the_worked_solution_shows_each_route_s_equations_and_results():
    plate = Solution(problem.load(textbook("thrown_plate_wobble")))
    steps = plate.steps()
    assert list(steps) == ["by Euler's equations", "by Lagrange's equations"]
    euler, lagrange = steps.values()
    assert "Euler's equations" in euler[1].text and "kinetic energy in Euler angles" in lagrange[1].text
    for route in (euler, lagrange):
        shown = {str(e.lhs): e.rhs for e in route[-1].equations}
        assert set(shown) == set(plate.problem.asks)
        assert all(sp.simplify(shown[n] - plate.expression(n)) == 0 for n in shown)
