"""A coin or disk rolling on its edge: `BODY.DETAIL`, one of ROLLING_COIN_QUANTITIES (its steady
motion on a circle: precession, speed, spin, the contact's normal force and friction; and rolling
upright: the least speed or spin to stay up).

    steady on a circle of radius R, leaning at theta:  Omega^2 from the torque about the center of mass

Route 0 (the key's): Lagrange's method with the rolling constraints. Route 1, its check: Kane's
method; both derive.mechanics.rolling_coin, through the Solution (`Solution._rolls_on_edge`: this
layer sits below derive.mechanics). The check also compares Newton–Euler about the center of mass,
the equations of motion term by term, and a steady motion's zero force along its heading
(`Solution.rolls_on_edge_check`). A steady motion needs the center inside its circle (`conditions`).

>>> from derive.language.problem import load
>>> ROLLS_ON_EDGE.claims(load("coin_rolls_in_circle").scene, "coin", "steady.precession")
Quantity(kind='rolls_on_edge', target='coin', detail='steady.precession')
"""
from __future__ import annotations

import sympy as sp

from derive.core.tidying import tidy
from derive.model.scene import Quantity
from derive.model.solid_scene import ROLLING_COIN_QUANTITIES
from derive.quantities.base import Check, QuantityKind, body_ask, first_asked

#: derive.mechanics.rolling_coin.ROUTES' first two: the key's, then its check.
ROUTES = ("lagrange", "kane")


class RollsOnEdge(QuantityKind):
    """A steady or upright motion of a body rolling on its edge (see the module)."""

    kind = "rolls_on_edge"
    symbol = "Omega"
    unit = None  # rad/s, m/s or N
    routes = ("Lagrange's method with the rolling constraints", "Kane's method")
    own_section = False

    def claims(self, scene, head: str, rest: str) -> Quantity | None:
        quantity = body_ask(self.kind, scene.rolls_on_edge, head, rest, ROLLING_COIN_QUANTITIES,
                            "a body rolling on its edge")
        rolling = scene.rolls_on_edge.get(head)
        if quantity is not None and rest.startswith("steady.") and (rolling.tilt is None or rolling.circle is None):
            raise ValueError(f"{head}.{rest} is read in the steady motion on a circle: give its lean and the contact "
                             "point's circle, rolls_on_edge: {tilt: theta, circle: R}")
        return quantity

    def value(self, solution, ask, route: int) -> sp.Expr:
        return solution._rolls_on_edge(ask.quantity, ROUTES[route])

    def conditions(self, solution, ask) -> list[tuple[sp.Expr, bool, str]]:
        """A steady motion's center inside its contact point's circle: once per body asked one."""
        if not first_asked(solution, ask, lambda a: a.quantity.detail.startswith("steady.")):
            return []
        name = ask.quantity.target
        coin = solution.scene.rolls_on_edge[name]  # then Omega^2 > 0 too (tests/test_rolling_coin.py)
        return [(tidy(coin.circle - coin.radius * sp.sin(coin.tilt)), True,
                 f"the {name}'s center would be on or across the axis of its contact point's circle "
                 "(circle <= radius sin(tilt)): not modelled")]

    def checks(self, solution, names: list[str]) -> list[Check]:
        return [solution.rolls_on_edge_check(names)]

    def describe(self, ask) -> str:
        return f"the {ask.quantity.detail.replace('_', ' ').replace('.', ' ')} of the {ask.quantity.target}"


ROLLS_ON_EDGE = RollsOnEdge()
