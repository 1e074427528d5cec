"""derive.agreement and the routes check built on it: cheap exact proofs, balls where those fail,
and a route made wrong (by 1e-20, in a regime the ranges never reach) still caught."""
from pathlib import Path

import pytest
import sympy as sp
from flint import arb, ctx

from derive import agreement
from derive.agreement import agree
from derive.answers import Solution
from derive.crosschecks import ROUTES, CheckFailure
from derive.mechanics.derivation import Derivation
from derive.problem import load

TEXTBOOK = Path(__file__).resolve().parent / "textbook"
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
    route_expression = Solution._route_expression

    def mutated(self, ask, route):
        value = route_expression(self, ask, route)
        return wrong(value) if route == ROUTES[1] else value
    monkeypatch.setattr(Solution, "_route_expression", mutated)
    return Solution(load(path))


def test_the_routes_check_catches_a_wrong_answer(monkeypatch):
    solution = _solution_with_a_wrong_route(monkeypatch, "string_wrapped_disk", lambda value: value * (1 + TINY))
    with pytest.raises(CheckFailure, match="disagree on"):
        solution.checks()


def test_the_routes_check_catches_a_wrong_regime_the_ranges_never_reach(monkeypatch):
    """The block slips in every variant of the file; its stuck case made wrong is still caught."""
    path = TEXTBOOK / "block_incline_kinetic.yaml"
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
