"""Every printed digit certified (issue 17): for random variants of every library answer (and
of the textbook problems': their Piecewise answers), at random numbers of digits, the digits
the balls certify are those of the exact answer evaluated at 60 digits by sympy; and what balls
do not map falls back, counted."""
import functools
import math
from decimal import ROUND_UP, Context, Decimal
from pathlib import Path

import pytest
import sympy as sp
from hypothesis import HealthCheck, assume, given, settings
from hypothesis import strategies as st

from flint import arb, ctx

from conftest import derived, textbook_files
from derive.numbers import balls, numeric
from derive.core import library
from derive.publishing import variants

#: The library but the textbook chains of states: those are checked against their books to 15 digits
#: (tests/test_textbook.py) and simulated (tests/test_chain_simulation.py), and evaluating a chain's
#: answers at 60 digits over a dozen draws each made this sweep take most of an hour of CPU.
CHAINS = {path for path in textbook_files() if "states:" in path.read_text()}
PROBLEMS = [path.stem for path in library.problem_files() if path not in CHAINS]


@functools.lru_cache(maxsize=None)
def _item(problem_id: str) -> variants.ProblemVariants:
    solution = derived(problem_id)
    return variants.ProblemVariants(solution.problem, solution, [])


def _reference(expression: sp.Expr, values: dict, digits: int) -> str:
    exact = sp.N(expression.xreplace(values), 60)
    return "0" if exact == 0 else numeric.round_decimal(Decimal(str(exact)), digits)


@pytest.mark.parametrize("problem_id", PROBLEMS, ids=[Path(p).stem for p in PROBLEMS])
@settings(max_examples=12, deadline=None, suppress_health_check=[HealthCheck.too_slow, HealthCheck.filter_too_much])
@given(data=st.data(), digits=st.integers(1, 30))
def test_certified_digits_are_the_exact_ones(problem_id, data, digits):
    """A variant drawn anywhere in the ranges (their ends included), its answers evaluated
    together as a set's key evaluates them."""
    item = _item(problem_id)
    draw = {name: p.value if p.range is None else p.at(data.draw(st.decimals(0, 1, places=6), label=name))
            for name, p in item.problem.parameters.items()}
    values = item.si_values(draw)
    assume(item.solution.violated(values) is None)
    names = [n for n, e in item.in_declared_units.items() if e.free_symbols <= set(values)]
    expressions = tuple(item.in_declared_units[n] for n in names)
    certified = numeric.evaluator(expressions).certified([values], [digits] * len(expressions))[0]
    for name, expression, value in zip(names, expressions, certified):
        assert value.text == _reference(expression, values, digits), (name, values)
        assert (value.method == "agreement") == (not balls.mapped(expression))


def test_an_unmapped_function_falls_back_to_the_agreement_policy_and_is_counted():
    x, t = sp.symbols("x t", positive=True)
    integral = sp.Integral(sp.exp(-x * t**2), (t, 0, 1))
    before = numeric.FALLBACKS["agreement: Integral"]
    value, = numeric.evaluator((integral,)).certified([{x: sp.Rational(1, 2)}], [12])[0]
    assert value.text == _reference(integral, {x: sp.Rational(1, 2)}, 12) and value.method == "agreement"
    assert numeric.FALLBACKS["agreement: Integral"] == before + 1


def test_a_rounding_tie_is_decided_exactly():
    """a(1 - e) = 1.55e11 x 0.47 = 7.285e10 exactly: no ball of it excludes the tie; the exact
    backend rounds it half to even, as the keys did before balls."""
    a, e = sp.symbols("a e", positive=True)
    value, = numeric.evaluator((a * (1 - e),)).certified([{a: sp.Integer(155 * 10**9), e: sp.Rational(53, 100)}],
                                                          [3])[0]
    assert (value.text, value.method) == ("7.28e+10", "exact")


def test_a_piece_is_chosen_by_a_certified_comparison_else_by_sympy():
    """A block on a slope: it slips when tan(x) > mu. At x = 1 rad balls decide; exactly at the
    edge (x = atan(mu)) no ball can, and the exact backend does."""
    mu, x = sp.symbols("mu x", positive=True)
    slips = sp.Piecewise((0, mu >= sp.tan(x)), (sp.sin(x) - mu * sp.cos(x), True))
    steep = {mu: sp.Rational(1, 2), x: sp.Integer(1)}
    value, = numeric.evaluator((slips,)).certified([steep], [15])[0]
    assert (value.text, value.method) == (_reference(slips, steep, 15), "ball")
    edge = {mu: sp.Rational(1, 2), x: sp.atan(sp.Rational(1, 2))}
    value, = numeric.evaluator((slips,)).certified([edge], [15])[0]
    assert (value.text, value.method) == ("0", "exact")


def test_a_conditions_sign_is_read_from_its_ball_else_from_its_digits():
    """signs() (a draw's conditions): a ball that excludes zero gives its sign; a zero (exact, or
    at the edge of a Piecewise that no ball decides) and an unmapped function go through
    certified(); an answer with a symbol without a value has no sign."""
    x, y, t = sp.symbols("x y t", positive=True)
    slips = sp.Piecewise((0, y >= sp.tan(x)), (sp.sin(x) - y * sp.cos(x), True))
    integral = sp.Integral(sp.exp(-x * t**2), (t, 0, 1)) - y
    evaluator = numeric.evaluator((x - 1, x - y, slips, integral))
    rows = [{x: sp.Integer(2), y: sp.Rational(1, 2)}, {x: sp.Integer(1), y: sp.Integer(1)},
            {x: sp.atan(sp.Rational(1, 2)), y: sp.Rational(1, 2)}, {x: sp.Integer(1)}]
    assert evaluator.signs(rows) == [[1, 1, 0, 1], [0, 0, 1, -1], [-1, -1, 0, 1], [0, None, None, None]]
    for row, signs in zip(rows, evaluator.signs(rows)):
        for value, sign in zip(evaluator.certified([row], [6] * 4)[0], signs):
            assert sign == (None if value is None else (Decimal(value.text) > 0) - (Decimal(value.text) < 0))


@settings(max_examples=400, deadline=None)
@given(middle=st.integers(-10**22, 10**22), radius=st.integers(0, 10**6), exponent=st.integers(-40, 40),
       digits=st.integers(1, 20), bits=st.sampled_from([64, 128]))
def test_a_balls_text_and_radius_are_those_decimal_rounding_gives(middle, radius, exponent, digits, bits):
    """certify writes its digits and its certificate's radius by integers; Python's decimal module,
    rounding both ends of the ball (in the decimals certify reads) half-to-even and its radius up,
    writes the same text, and certify refuses only a ball whose ends round apart or whose sign
    is not proven."""
    saved, ctx.prec = ctx.prec, bits
    try:
        ball = arb(arb(middle) * arb(10) ** exponent, arb(radius) * arb(10) ** (exponent - 3))
        value = numeric.certify(ball, digits, bits)
        mid, rad, power = (int(n) for n in ball.mid_rad_10exp(math.ceil(bits * math.log10(2)) + 2))
    finally:
        ctx.prec = saved
    wide = Context(prec=100)  # the ends whole (the default 28 digits would round them)
    low, high, bound = (Decimal(n).scaleb(power, wide) for n in (mid - rad, mid + rad, rad))
    ends = {"0" if end == 0 else numeric.round_decimal(end, digits) for end in (low, high)}
    if value is None:  # refused only where an end rounds elsewhere or the sign is not proven
        assert len(ends) == 2 or low <= 0 <= high and rad
        return
    assert ends == {value.text}
    assert value.certificate()["radius"] == ("0" if rad == 0 else numeric.round_decimal(bound, 2, ROUND_UP))


@settings(max_examples=300, deadline=None)
@given(whole=st.integers(-10**15, 10**15), places=st.integers(0, 20), digits=st.integers(1, 15))
def test_a_drawn_decimal_is_written_as_decimal_rounding_writes_it(whole, places, digits):
    """significant writes a decimal (every drawn parameter is one) by integers; Python's decimal
    module, rounding the same value half-to-even, writes the same text."""
    value = sp.Rational(whole, 10**places)
    expected = "0" if whole == 0 else numeric.round_decimal(Decimal(whole).scaleb(-places), digits)
    assert numeric.significant(value, digits) == expected
