"""An answer's sign: a magnitude and the direction it points in words, or a parameter's value where
an answer vanishes.

A quantity with a direction (derive.model.directions) is answered as its magnitude unless the
question states its sign convention (`sign:`); `direction` gives the words for one variant.

>>> import sympy as sp
>>> from derive.language.problem import load
>>> from derive.solution.answers import Solution
>>> solution = Solution(load("rolling_incline"))
>>> solution.signed_expression("f"), solution.expression("f")
(-2*M*g*sin(theta)/7, 2*M*g*sin(theta)/7)
>>> direction(solution, "f", {s: sp.Integer(1) for s in solution.signed_expression("f").free_symbols})
'up the slope'
"""
from __future__ import annotations

import sympy as sp

from derive.core.errors import ProblemError
from derive.core.tidying import leading_plus, tidy
from derive import quantities
from derive.model import directions
from derive.numbers import intervals, range_forms
from derive.solution.crosschecks import sample_points


def magnitude(problem, expr: sp.Expr, proven: bool = False) -> sp.Expr:
    """|expr|: expr or -expr when its sign is the same over the parameter ranges, else Abs(expr).
    With `proven` (a quantity answered with its direction in words) the sign must be proven over
    the whole box of the ranges in balls (derive.numbers.intervals), else the answer is |expr| and
    each variant's direction its own; without it (an ask's `magnitude: true`, as before) the sign is
    read off samples of the ranges and checked per variant (derive.solution.answer_conditions)."""
    box = range_forms.box(problem)
    if proven and expr.free_symbols <= set(box):
        if intervals.positive_over(expr, box, strict=False):
            return expr
        if intervals.positive_over(-expr, box, strict=False):
            return negated(expr)
        return sp.Abs(expr)
    signs = {sp.sign(sp.N(expr.xreplace(point), 30)) for point in sample_points(problem, expr)}
    if signs == {1}:
        return expr
    if signs == {-1}:
        return negated(expr)
    return sp.Abs(expr)


def negated(expr: sp.Expr) -> sp.Expr:
    """-expr in its tidiest form without a double negative: (I w - R m v)/(I + m R^2), not
    -(-I w + R m v)/(I + m R^2).

    >>> a, b, c = sp.symbols("a b c", positive=True)
    >>> negated((-a + b) / c), negated(-a * b)
    ((a - b)/c, a*b)
    """
    return leading_plus(tidy(-expr))


def stated(solution, name: str) -> int:
    """The sign that turns the routes' component of a quantity with a direction into the one the
    question's `sign:` states (+1: the same; -1: "down the slope positive" where the routes count
    up it); 1 for a quantity without a direction. A convention that names no way the quantity can
    point is refused, naming the field: the engine never guesses which way a student is told to count.

    >>> from derive.language.problem import load
    >>> from derive.solution.answers import Solution
    >>> stated(Solution(load("string_wrapped_disk")), "alpha")
    1
    """
    ask = solution.problem.asks[name]
    sense = quantities.sense(solution.scene, ask.quantity, solution.coordinates, solution._sample)
    if sense is None:
        return 1
    sign = directions.stated(sense, ask.sign)
    if sign is None:
        raise ProblemError(f"{solution.problem.path}: ask.{name}.sign: say which way is positive in the words "
                           f"of its direction, {sense.positive!r} or {sense.negative!r} "
                           f"(as in '{sense.positive} positive'), not {ask.sign!r}")
    return sign


def direction(solution, name: str, values: dict[sp.Symbol, sp.Expr]) -> str | None:
    """The words for which way the asked quantity points at these parameter values (SI, by symbol):
    None where it has no direction, the question states its sign convention, or it is zero."""
    sense = solution.senses[name]
    if sense is None:
        return None
    value = sp.N(solution.signed_expressions[name].xreplace(values), 30)
    if not value.is_number:  # a general result: the direction it has in every variant, if one
        return general_direction(solution, name)
    if value == 0:
        return None
    return sense.of(1 if value > 0 else -1)


def general_direction(solution, name: str) -> str | None:
    """The words for which way the quantity points in every variant, where its sign is the same over
    the parameter ranges (its magnitude needs no |...|); None where it has no direction or the sign
    depends on the parameters."""
    sense = solution.senses[name]
    if sense is None or solution.expression(name).has(sp.Abs):
        return None
    return sense.of(1 if solution.expression(name) == solution.signed_expressions[name] else -1)
