"""How many turns a body makes from one state to the next: `BODY.turns` with `in: STATE`.

The angle it turns through from the state `STATE` comes from (`from:`) to `STATE`, asked in
turns (`unit: rev`, one turn 2 pi rad); answered with the way it turns in words (counter-clockwise
or clockwise), as every quantity with a direction is. A body whose angular velocity has opposite
signs in the two states turned back on the way, and the angle between them is not the turns it
made: that is refused.

        theta - theta_0
   N = -----------------  rev        (counter-clockwise positive)
             2 pi

Route 0 (the key's): the two states' closed forms. Route 1, its check: the motion integrated
numerically from the first state to the second (derive.checks.chain_simulation), read the
same way (`at`).

>>> from derive.language.problem import load
>>> TURNS.claims(load("rod_endpoint").scene, "rod", "turns")
Quantity(kind='turns', target='rod', detail=None)
"""
from __future__ import annotations

import sympy as sp

from derive.core.tidying import tidy
from derive.model.scene import Quantity
from derive.quantities.base import QuantityKind, StateChange


class Turns(StateChange, QuantityKind):
    """The turns a body makes between two states (see the module)."""

    kind = "turns"
    unit = "rev"
    exact_unit = True
    sense = ("counter-clockwise", "clockwise")

    def claims(self, scene, head: str, rest: str) -> Quantity | None:
        if rest != "turns" or head not in scene.bodies:
            return None
        if not scene.bodies[head].rotates:
            raise ValueError(f"the {head} is a point mass: it has no turns (ask its distance)")
        return Quantity(self.kind, head, None)

    def at(self, solution, ask, values: dict, before: dict) -> sp.Expr:
        angle = solution.coordinates.of(ask.quantity.target, "theta")
        spins = [v[angle.u] for v in (before, values)]
        if all(s.is_number for s in spins) and spins[0] * spins[1] < 0 or tidy(spins[0] * spins[1]).is_negative:
            raise solution.problem.error(f"ask.{ask.name}.in", f"the {ask.quantity.target} turns one way in the state "
                                         f"{solution.scene.states[ask.state].start} and the other in {ask.state}: it "
                                         "turned back on the way, so its turns are not the angle between them")
        return tidy(values[angle.q] - before[angle.q])  # in rad, SI: the key gives it in rev

    def describe(self, ask) -> str:
        return f"the number of turns the {ask.quantity.target} makes"


TURNS = Turns()
