"""A body on a cord through a hole, pulled in slowly from one circle about the hole to a smaller one,
as a textbook solves it (Serway & Jewett, Physics for Scientists and Engineers 9th ed., ch. 11: the
puck on a frictionless table): the cord's pull points at the hole, so it has no moment about it and
the angular momentum about the hole is conserved, m r1 v1 = m r2 v; the pull is the only force that
does work, so its work is the change of kinetic energy; on the smaller circle the tension alone gives
the centripetal acceleration, T = m v^2 / r2. The engine finds the state after the pull by the momenta
the cord keeps (derive.mechanics.moves.pull); derive.solution.textbook_routes compares them.

>>> m, r1, r2, v1 = sp.symbols("m r1 r2 v1", positive=True)
>>> puck = pulled_in(m, r1, r2, v1, {"speed", "work", "tension"})
>>> puck.values["speed"], puck.values["tension"]
(r1*v1/r2, m*r1**2*v1**2/r2**3)
>>> len(puck.steps)
3
"""
from __future__ import annotations

from dataclasses import dataclass

import sympy as sp

from derive.core.tidying import tidy
from derive.text.steps import Step


@dataclass(frozen=True)
class PulledIn:
    """The steps, and what they find by name: speed, work, tension."""

    steps: tuple[Step, ...]
    values: dict[str, sp.Expr]


def pulled_in(mass, near_first, near_last, speed_first, asked: set[str], name: str = "body") -> PulledIn:
    """The route for a body of `mass` moving at `speed_first` across its cord on a circle of radius
    `near_first` about the hole, pulled in slowly to the radius `near_last`; the steps show what
    `asked` names ("speed", "work", "tension"; the speed always, each later step stands on it); `name`:
    the body in words."""
    v, W, T = sp.Symbol("v", positive=True), sp.Symbol("W", real=True), sp.Symbol("T", positive=True)
    speed = tidy(near_first * speed_first / near_last)
    values = {"speed": speed, "work": tidy(mass * speed**2 / 2 - mass * speed_first**2 / 2),
              "tension": tidy(mass * speed**2 / near_last)}
    steps = [Step(f"Conservation of angular momentum about the hole: the cord's pull on the {name} points at the hole, so "
                  "it has no moment about it, and the weight and the table's push balance. On each circle the velocity "
                  "is at right angles to the cord, so the angular momentum is the mass times the radius times the speed",
                  (sp.Eq(mass * near_first * speed_first, mass * near_last * v), sp.Eq(v, speed)), role="solve")]
    if "work" in asked:
        steps.append(Step("The work-energy theorem: the cord's pull is the only force that does work (the table is "
                          "frictionless, and the weight and the table's push are at right angles to the motion), so its "
                          "work is the change of the kinetic energy", (sp.Eq(W, mass * v**2 / 2 - mass * speed_first**2 / 2),
                                                                         sp.Eq(W, values["work"])), role="solve"))
    if "tension" in asked:
        steps.append(Step(f"Newton's second law toward the hole on the smaller circle: the tension is the only force "
                          f"across the motion in the plane of the table, and it gives the {name} its centripetal acceleration",
                          (sp.Eq(T, mass * v**2 / near_last), sp.Eq(T, values["tension"])), role="solve"))
    return PulledIn(tuple(steps), values)
