"""How far a body's center of mass is from where it was in the state before: `BODY.distance`
with `in: STATE`.

The length of the straight line between its center's positions in the state `STATE` comes from
(`from:`) and in `STATE`: how far up an incline a ball rolls before it stops, how far a block
slides. (On a curved path it is the chord, not the arc.)

    d = |r - r_0| = sqrt((x - x_0)^2 + (y - y_0)^2)

Route 0 (the key's): the two states' closed forms. Route 1, its check: the motion integrated
numerically (derive.checks.chain_simulation), read the same way (`at`).

>>> from derive.language.problem import load
>>> DISTANCE.claims(load("rod_endpoint").scene, "rod", "distance")
Quantity(kind='distance', target='rod', detail=None)
"""
from __future__ import annotations

import sympy as sp

from derive.core.tidying import root, tidy
from derive.model.scene import Quantity
from derive.quantities import QuantityKind, StateChange


class Distance(StateChange, QuantityKind):
    """The distance between a body's positions in two states (see the module)."""

    kind = "distance"
    unit = "m"

    def claims(self, scene, head: str, rest: str) -> Quantity | None:
        if rest != "distance" or head not in scene.bodies:
            return None
        return Quantity(self.kind, head, None)

    def at(self, solution, ask, values: dict, before: dict) -> sp.Expr:
        from derive.solution import answer_signs  # the problem reader imports this package: not at its top
        coords, body = solution.coordinates, ask.quantity.target
        moved = [values[coords.of(body, k).q] - before[coords.of(body, k).q] for k in ("x", "y")]
        length = sp.sqrt(sp.trigsimp(moved[0] ** 2 + moved[1] ** 2))  # 1/|sin(theta)|, not sqrt(tan^2 + 1)/|tan|
        if all(a.args[0].free_symbols for a in length.atoms(sp.Abs)):  # each |a| whose sign is proven over the ranges
            length = length.xreplace({a: answer_signs.magnitude(solution.problem, a.args[0], proven=True)
                                      for a in length.atoms(sp.Abs)})
        return tidy(length) if not length.has(sp.Abs) else root(moved[0] ** 2 + moved[1] ** 2)

    def describe(self, ask) -> str:
        return f"the distance the {ask.quantity.target} moves"


DISTANCE = Distance()
