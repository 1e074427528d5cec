"""A body on a fixed point at its center of mass (no torque of its weight about it), spinning, under
a couple for a time: `BODY.DETAIL`, one of IMPULSE_TURN_QUANTITIES (the angle its angular momentum
turns through, its small-angle limit, the angle the axle turns through).

    L_1 = L_0 + J,  J = tau t        angle = angle between L_0 and L_1 ~ J / L_0 (small)

Route 0 (the key's): the angular impulse added to the angular momentum (derive.mechanics.
angular_impulse, through the Solution: `Solution._angular_impulse`). Its check is numeric, so it
has no route 1 in closed form: Euler's equations integrated with the orientation at five points
of the ranges (`Solution.angular_impulse_check`), the small-angle limit by the slope at zero
impulse.

>>> from derive.language.problem import load
>>> ANGULAR_IMPULSE.claims(load("tilting_wheel").scene, "wheel", "turn.small_angle")
Quantity(kind='angular_impulse', target='wheel', detail='turn.small_angle')
"""
from __future__ import annotations

import sympy as sp

from derive.model.scene import Quantity
from derive.model.solid_scene import IMPULSE_TURN_QUANTITIES
from derive.quantities.base import Check, QuantityKind, body_ask


class AngularImpulse(QuantityKind):
    """The turn of a spinning body's angular momentum or axle under a couple (see the module)."""

    kind = "angular_impulse"
    symbol = "phi"
    unit = "rad"
    routes = ("the angular impulse added to the angular momentum", "Euler's equations integrated numerically")
    own_section = False

    def claims(self, scene, head: str, rest: str) -> Quantity | None:
        centered = {name: point for name, point in scene.pivot_points.items() if point.centered}
        return body_ask(self.kind, centered, head, rest, IMPULSE_TURN_QUANTITIES,
                        "a body on a fixed point at its center of mass (no weight's torque about it)")

    def value(self, solution, ask, route: int) -> sp.Expr | None:
        return solution._angular_impulse(ask.quantity) if route == 0 else None

    def checks(self, solution, names: list[str]) -> list[Check]:
        return [solution.angular_impulse_check(names)]

    def describe(self, ask) -> str:
        what = {"turn.axle": "axle", "turn.small_angle": "angular momentum, for a small impulse"}
        return f"the angle the {ask.quantity.target}'s {what.get(ask.quantity.detail, 'angular momentum')} turns through"


ANGULAR_IMPULSE = AngularImpulse()
