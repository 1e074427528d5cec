"""No answer a student cannot know the sign of: an asked value that comes out negative where the
question states no sign convention for it (a rod's angle "from the horizontal" of -1.22 rad, the
"height of its center" -0.30 m below the pin) marks right answers wrong. `derive check` runs this
over each problem at points of its ranges (the middle, then draws), where its conditions hold.

>>> from derive.language.problem import load
>>> from derive.solution.answers import Solution
>>> unstated(Solution(load("rod_endpoint")))
[]
"""
from __future__ import annotations

from sympy.core.function import AppliedUndef

from derive.numbers import numeric
from derive.solution.crosschecks import sample_points

#: The points of the ranges looked at: the middle and four draws.
POINTS = 5


def unstated(solution) -> list[str]:
    """Each ask whose value is negative somewhere in the ranges with no `sign:` for it, as what to
    change (empty where every answer's sign is known to the student)."""
    problem = solution.problem
    given = problem.values()
    found = []
    for name, ask in problem.asks.items():
        if ask.sign is not None:
            continue
        expression = solution.expression(name)
        if expression.atoms(AppliedUndef):  # a general result, r(t)^2 theta'(t)/2: no number in the key
            continue
        for point in sample_points(problem, expression, POINTS):
            values = {**given, **point}
            if solution.violated(values):
                continue
            try:
                value = numeric.evaluate(expression, values, 3)  # as the key evaluates it
            except (ValueError, ZeroDivisionError):  # no real value here: the key's own check says so
                continue
            if value is not None and value.startswith("-"):
                found.append(f"ask.{name}: {value} (SI) where the question states no sign "
                             "convention: ask its magnitude (magnitude: true) with a meaning that says which way, "
                             "or state the convention in the question and give it (sign:)")
                break
    return found
