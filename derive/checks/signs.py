"""No answer a student cannot know the sign of: an asked value that comes out negative where the
question states no sign convention for it (a rod's angle "from the horizontal" of -1.22 rad, the
"height of its center" -0.30 m below the pin) marks right answers wrong; a component of a vector in
space (a torque's z component) has its axis's sign, where the question or the ask's meaning names the
axis. `derive check` runs this over each problem at points of its ranges (the middle, then draws),
where its conditions hold.

>>> from derive.language.problem import load
>>> from derive.solution.answers import Solution
>>> unstated(Solution(load("rod_endpoint")))
[]
>>> ungiven(load("rod_endpoint"))
[]
"""
from __future__ import annotations

import re

from sympy.core.function import AppliedUndef

from derive import quantities

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
        kind = quantities.KINDS.get(ask.quantity.kind)
        axis = kind.axis_of(ask.quantity) if kind is not None else None
        if axis is not None and re.search(rf"\b{axis}\b", f"{ask.meaning} {problem.question}"):
            continue  # a component along an axis the question names: its sign is the axis's
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
            if value is not None and value.startswith("-") and axis is not None:
                found.append(f"ask.{name}: {value} (SI), a component along {axis}, where neither the question nor "
                             f"the ask's meaning names the {axis} axis: say which component it is")
                break
            if value is not None and value.startswith("-"):
                found.append(f"ask.{name}: {value} (SI) where the question states no sign "
                             "convention: ask its magnitude (magnitude: true) with a meaning that says which way, "
                             "or state the convention in the question and give it (sign:)")
                break
    return found


#: Words that state a sign convention ("taking up as positive", "counter-clockwise positive").
_CONVENTION = re.compile(r"\b(positive|negative)\b", re.IGNORECASE)


def ungiven(problem) -> list[str]:
    """Each sign convention a question or an ask's meaning states that no ask gives as `sign:`. The
    key then grades a quantity with a direction as its magnitude, with its direction in words, so
    a student who counts as the question says ("taking up as positive": -2.91 m/s^2 for a block
    going down) is marked wrong."""
    found = [f"ask.{name}: its meaning states a sign convention ({ask.meaning!r}) that the ask does not "
             "give: give it as sign: in the question's words, or drop it and ask the magnitude"
             for name, ask in problem.asks.items()
             if ask.sign is None and quantities.directional(ask.quantity) and _CONVENTION.search(ask.meaning)]
    stated = _CONVENTION.search(problem.question)
    if stated and not any(ask.sign for ask in problem.asks.values()):
        found.append(f"question: it states a sign convention ({_phrase(problem.question, stated)!r}) that no "
                     "ask gives: give it as sign: on the ask it is for (the key grades that ask's signed value), "
                     "or drop it from the question")
    return found


def _phrase(text: str, word: re.Match) -> str:
    """The words around a convention's "positive": back to an opening bracket or a comma, on to a
    closing one (the parenthesis a question states it in)."""
    start = max(text.rfind(c, 0, word.start()) for c in "(,.") + 1
    ends = [i for i in (text.find(c, word.end()) for c in "),.") if i >= 0]
    return " ".join(text[start:min(ends, default=len(text))].split())
