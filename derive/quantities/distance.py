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
from derive.numbers import intervals, range_forms
from derive.model.scene import Quantity
from derive.quantities.base import QuantityKind, StateChange


class Distance(StateChange, QuantityKind):
    """The distance between a body's positions in two states (see the module)."""

    kind = "distance"
    symbol = "d"
    unit = "m"

    def claims(self, scene, head: str, rest: str) -> Quantity | None:
        if rest != "distance" or head not in scene.bodies:
            return None
        return Quantity(self.kind, head, None)

    def at(self, solution, ask, values: dict, before: dict) -> sp.Expr:
        coords, body = solution.coordinates, ask.quantity.target
        moved = [values[coords.of(body, k).q] - before[coords.of(body, k).q] for k in ("x", "y")]
        squared = sp.trigsimp(moved[0] ** 2 + moved[1] ** 2)
        box = range_forms.box(solution.problem)
        # 1/|sin(theta)|, not sqrt(tan^2 + 1)/|tan|; 1/(sin + mu cos), not 1/sqrt(mu^2 cos^2 + mu sin(2 theta) + sin^2)
        found = []
        in_sines = sp.factor(sp.cancel(sp.expand_trig(squared).replace(sp.tan, lambda a: sp.sin(a) / sp.cos(a))))
        for radicand in (squared, in_sines):
            length = sp.sqrt(radicand)
            signs = {a: next((s for s in (1, -1) if a.args[0].free_symbols <= set(box)
                              and intervals.positive_over(s * a.args[0], box, strict=True)), None)
                     for a in length.atoms(sp.Abs)}
            if None not in signs.values():  # each |a| with its sign proven over the ranges
                found.append(tidy(length.xreplace({a: s * a.args[0] for a, s in signs.items()})))
        return min(found, key=sp.count_ops) if found else root(squared)

    def describe(self, ask) -> str:
        return f"the distance the {ask.quantity.target} moves"


DISTANCE = Distance()
