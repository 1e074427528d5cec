"""derive.numbers.agreement and the routes check built on it: cheap exact proofs, balls where those fail,
and a route made wrong (by 1e-20, in a regime the ranges never reach) still caught."""

import pytest
import sympy as sp
from flint import arb, ctx

from conftest import textbook
from derive.numbers import agreement
from derive.publishing import report
from derive.numbers.agreement import agree
from derive.solution.answers import Solution
from derive.quantities.by_routes import ROUTES, ByRoutes
from derive.solution.crosschecks import CheckFailure
from derive.mechanics.derivation import Derivation
from derive.language.problem import load

x, y, theta = sp.symbols("x y theta", positive=True)
TINY = sp.Rational(1, 10**20)

# Long enough that agree does not simplify it (SIMPLIFY_OPS): a ratio of polynomials in sin and cos.
LONG = sum((sp.sin(theta) ** k * x ** (k % 3) + sp.cos(theta) ** k * y) / (k + x) for k in range(1, 9))


def test_a_long_expression_is_settled_by_balls_and_a_mutated_one_is_caught():
    assert sp.count_ops(LONG) > agreement.SIMPLIFY_OPS
    rewritten = LONG.subs(sp.cos(theta) ** 2, 1 - sp.sin(theta) ** 2)  # the same function, another form
    assert agree(LONG, rewritten) == "balls"
    assert agree(LONG, rewritten * (1 + TINY)) is None
    assert agree(LONG, rewritten + TINY * sp.sin(theta)) is None


def test_a_ball_excluding_zero_is_a_disagreement_at_any_point():
    points = [{x: sp.Rational(k, 7), y: sp.Rational(3)} for k in range(1, 6)]
    assert agreement.by_balls(x * y, x * y + TINY * x, points) is False
    assert agreement.by_balls(x * y, y * x, points) is True
    # an integral has no ball: evalf decides, and says so
    integral = sp.Integral(sp.exp(-x * theta), (theta, 0, 1))
    assert agreement.by_balls(integral, integral.doit(), points) is None
    assert agree(integral, integral.doit(), symbolic=False, points=points) == "numeric"


def test_piecewise_cases_are_compared_each_on_its_own():
    a = sp.Piecewise((LONG, x > 10), (x * y, True))
    points = [{x: sp.Rational(k, 3), y: sp.Rational(2), theta: sp.Rational(1, 2)} for k in range(1, 6)]  # x < 10
    assert agree(a, sp.Piecewise((LONG * (1 + TINY), x > 10), (x * y, True)), points=points) is None
    assert agree(a, sp.Piecewise((LONG, x > 10), (x * y * (1 + TINY), True)), points=points) is None
    assert agree(a, sp.Piecewise((LONG.subs(sp.cos(theta) ** 2, 1 - sp.sin(theta) ** 2), x > 10), (y * x, True)),
                 points=points) == "balls"
    # conditions written differently: the whole Piecewise at the points, the balls deciding each condition
    assert agree(a, sp.Piecewise((LONG, 10 < x), (x * y, True)), points=points) in ("symbolic", "balls")
    assert agree(a, sp.Piecewise((LONG, 2 * x > 20), (x * y + TINY, True)), points=points) is None


def _solution_with_a_wrong_route(monkeypatch, path, wrong):
    """A Solution whose Newton–Euler answers go through `wrong` (an answer -> a mutated one)."""
    value_by = ByRoutes.value

    def mutated(self, solution, ask, route):
        value = value_by(self, solution, ask, route)
        return wrong(value) if route == 1 else value
    monkeypatch.setattr(ByRoutes, "value", mutated)
    return Solution(load(path))


def test_the_routes_check_catches_a_wrong_answer(monkeypatch):
    solution = _solution_with_a_wrong_route(monkeypatch, "string_wrapped_disk", lambda value: value * (1 + TINY))
    with pytest.raises(CheckFailure, match="disagree on"):
        solution.checks()


def test_the_routes_check_catches_a_wrong_regime_the_ranges_never_reach(monkeypatch):
    """The block slips in every variant of the file; its stuck case made wrong is still caught."""
    path = textbook("block_incline_kinetic")
    assert Solution(load(path)).checks()  # as derived, the routes agree

    def wrong_first_case(value):
        value = sp.piecewise_fold(value)
        assert isinstance(value, sp.Piecewise) and len(value.args) > 1
        (first, where), *rest = value.args
        return sp.Piecewise((first * (1 + TINY) + TINY, where), *rest)
    solution = _solution_with_a_wrong_route(monkeypatch, path, wrong_first_case)
    with pytest.raises(CheckFailure, match="disagree on"):
        solution.checks()


def test_the_routes_check_catches_a_wrong_unknown_at_a_state(monkeypatch):
    balls_at = Derivation.balls_at

    def mutated(self, state, bits=256):
        solved = dict(balls_at(self, state, bits))
        if self.route == ROUTES[1]:
            last = self.unknowns[-1]
            with ctx.workprec(bits):  # off by 1e-25: far wider than the balls, narrower than a float
                solved[last] = solved[last] * (1 + arb(10) ** -25) + arb(10) ** -25
        return solved
    monkeypatch.setattr(Derivation, "balls_at", mutated)
    with pytest.raises(CheckFailure, match="disagree on"):
        Solution(load("string_wrapped_disk")).checks()


INCLINE_DISK_PULLEY = """id: incline_disk_pulley_rough
title: A block on a rough incline, a massive pulley at the top, and a hanging block
topic: friction
source: Serway & Jewett ch. 10 problems (incline, pulley with moment of inertia, hanging mass, kinetic friction)
parameters:
  m1: {meaning: mass of the block on the incline, unit: kg, range: [2, 3], sig_figs: 2}
  m2: {meaning: mass of the hanging block, unit: kg, range: [5, 6], sig_figs: 2}
  M: {meaning: mass of the pulley (uniform disk), unit: kg, range: [1, 2], sig_figs: 2}
  r: {meaning: radius of the pulley, unit: cm, range: [8, 12], sig_figs: 2}
  theta: {meaning: angle of the incline, unit: deg, range: [25, 35], sig_figs: 2}
  mu_s: {meaning: coefficient of static friction, unit: "1", range: [0.3, 0.4], sig_figs: 2}
  mu_k: {meaning: coefficient of kinetic friction, unit: "1", range: [0.15, 0.25], sig_figs: 2}
  h: {meaning: drop of the hanging block, unit: m, range: [0.5, 1], sig_figs: 2}
  D: {meaning: distance from the block to the pulley along the slope, unit: m, value: 2}
  g: {meaning: gravitational acceleration, unit: m/s^2, value: 9.81}
scene:
  surfaces:
    ramp: {plane: {angle: theta, descends: left, through: [0, 0]}}
  bodies:
    block: {shape: point, mass: m1, at: [0, 0], on: ramp, contact: sliding, friction: {static: mu_s, kinetic: mu_k}}
    pulley: {shape: disk, mass: M, radius: r, joint: fixed_axle, at: [D*cos(theta) + r*sin(theta), D*sin(theta) - r*cos(theta)]}
    weight: {shape: point, mass: m2, at: [D*cos(theta) + r*sin(theta) + r, D*sin(theta) - 1.5*D]}
  cords:
    rope: [block, {over: pulley}, weight]
  loads:
    - gravity: g
ask:
  a: {meaning: acceleration of the weight, of: weight.acceleration.y, unit: m/s^2}
question: |
  A block ({{ m1 }}) on a rough incline at {{ theta }} (mu_s = {{ mu_s }}, mu_k = {{ mu_k }}) is tied by a cord over a uniform disk
  pulley ({{ M }}, radius {{ r }}) to a hanging block ({{ m2 }}). Released from rest: speed after a drop {{ h }}, time, tensions.
"""


def test_check_states_on_a_cord_hanging_straight_down_have_finite_velocities(tmp_path):
    """A trial's block on a rough incline tied over a disk pulley to a hanging block stopped with
    "internal error: Indeterminate" in the routes check: the admissible velocities it compares the
    routes at came out near 1e77 (then NaN), as rref took for a pivot the hanging run's coefficient
    of the weight's x, zero only by nested roots' identities at the sample parameters."""
    path = tmp_path / "incline.yaml"
    path.write_text(INCLINE_DISK_PULLEY)
    solution = Solution(load(str(path)))
    for index in range(len(solution.regimes)):
        for state in solution._check_states(index):
            assert all(abs(float(sp.N(v, 30))) < 1e3 for v in state.values()), state
    assert report.solve(solution.problem, solution=solution)["checks"]["lagrange_vs_newton_euler"]["passed"]
