"""How many turns a body makes from one state to the next: `BODY.turns` with `in: STATE`.

The angle it turns through from the state `STATE` comes from (`from:`) to `STATE`, asked in
turns (`unit: rev`, one turn 2 pi rad); answered with the way it turns in words (counter-clockwise
or clockwise), as every quantity with a direction is. A body whose angular velocity has opposite
signs in the two states turned back on the way, and the angle between them is not the turns it
made: such a variant is refused (`conditions`).

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
from derive.quantities.base import QuantityKind, StateChange, named, shown
from derive.text.prose import Sentence
from derive.text.steps import Step


class Turns(StateChange, QuantityKind):
    """The turns a body makes between two states (see the module)."""

    kind = "turns"
    symbol = "N"
    unit = "rev"
    exact_unit = True
    sense = ("counter-clockwise", "clockwise")

    def claims(self, scene, head: str, rest: str) -> Quantity | None:
        if rest != "turns" or head not in scene.bodies:
            return None
        if not scene.bodies[head].rotates:
            raise ValueError(f"the {head} is a point mass: it has no turns (ask its distance)")
        return Quantity(self.kind, head, None)

    def conditions(self, solution, ask) -> list[tuple[sp.Expr, bool, str]]:
        """Its angular velocity has the same sign in the two states (or is zero in one), in every variant:
        one that turned back on the way turned more than the angle between them."""
        start = solution.scene.states[ask.state].start
        if start is None:
            return []
        spin = solution.coordinates.of(ask.quantity.target, "theta").u
        product = tidy(solution.states[start].values[spin] * solution.states[ask.state].values[spin])
        return [] if product == 0 else [(product, False, f"the {ask.quantity.target} turns one way in the state {start} "
                                                         f"and the other in {ask.state}: it turned back on the way, so "
                                                         "its turns are not the angle between them")]

    def at(self, solution, ask, values: dict, before: dict) -> sp.Expr:
        angle = solution.coordinates.of(ask.quantity.target, "theta")
        return tidy(values[angle.q] - before[angle.q])  # in rad, SI: the key gives it in rev

    def steps(self, solution, ask) -> list[Step]:
        """The angle turned between the two states, then the turns it makes: one turn is 2 pi."""
        angle = StateChange.value(self, solution, ask, 0)
        turned = sp.Symbol(r"\Delta\theta")
        said = Sentence((f"The {ask.quantity.target} turns through ", sp.Eq(turned, angle),
                         " rad between the two states, counter-clockwise positive."))
        return [Step("The number of turns is the angle over one full turn",
                     (sp.Eq(named(self, ask), sp.Abs(turned) / (2 * sp.pi), evaluate=False),
                      sp.Eq(named(self, ask), shown(self, solution, ask))), sentences=(said,))]

    def describe(self, ask) -> str:
        return f"the number of turns the {ask.quantity.target} makes"


TURNS = Turns()
