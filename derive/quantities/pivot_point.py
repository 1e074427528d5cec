"""A symmetric top on a fixed point under its weight: `BODY.DETAIL`, one of PIVOT_POINT_QUANTITIES
(the slow and fast steady precession rates, the fast-top rate, the least spin to sleep upright,
the nutation frequency).

    Omega = (I3 w -/+ sqrt(I3^2 w^2 - 4 I1 m g l cos(theta))) / (2 I1 cos(theta))

Route 0 (the key's): Lagrange's equations in Euler angles. Route 1, its check: Euler's equations
about the fixed point (Newton–Euler); derive.mechanics.fixed_point, through the Solution
(`Solution._pivot_point`: this layer sits below derive.mechanics). The check also compares the
equations of motion by Lagrange, Newton–Euler and Kane term by term (`Solution.pivot_point_check`).
A steady motion needs the spin fast enough, in every variant (`conditions`).

>>> from derive.language.problem import load
>>> PIVOT_POINT.claims(load("top_precession_exact").scene, "top", "precession.slow")
Quantity(kind='pivot_point', target='top', detail='precession.slow')
"""
from __future__ import annotations

import sympy as sp

from derive.model.scene import Quantity
from derive.model.solid_scene import PIVOT_POINT_QUANTITIES
from derive.quantities.base import Check, QuantityKind, body_ask, first_asked

#: derive.mechanics.fixed_point.ROUTES' first two: the key's, then its check.
ROUTES = ("lagrange", "newton_euler")
#: What is read without a steady precession of the top (no condition on its spin).
UNSTEADY = ("sleeping.min_spin", "precession.fast_top", "nutation.fast_top")


class PivotPoint(QuantityKind):
    """A steady motion of a top on a fixed point (see the module)."""

    kind = "pivot_point"
    symbol = "Omega"
    unit = None  # rad/s, or a frequency
    routes = ("Lagrange's equations in Euler angles", "Euler's equations about the fixed point")
    own_section = False

    def claims(self, scene, head: str, rest: str) -> Quantity | None:
        quantity = body_ask(self.kind, scene.pivot_points, head, rest, PIVOT_POINT_QUANTITIES, "a body on a fixed point",
                            also=("conical.rate",))
        if quantity is not None and scene.pivot_points[head].hangs:
            raise ValueError(f"the {head} hangs below its point: its precessions and nutations are derived for a top "
                             f"standing on it; ask {head}.conical.rate, its steady turn in a cone")
        return quantity

    def value(self, solution, ask, route: int) -> sp.Expr:
        return solution._pivot_point(ask.quantity, ROUTES[route])

    def conditions(self, solution, ask) -> list[tuple[sp.Expr, bool, str]]:
        """Spun fast enough to precess steadily: once per top asked a steady motion."""
        if first_asked(solution, ask, lambda a: a.quantity.detail not in UNSTEADY):
            return solution.top_conditions(ask.quantity.target)
        return []

    def checks(self, solution, names: list[str]) -> list[Check]:
        return [solution.pivot_point_check(names)]

    def describe(self, ask) -> str:
        return f"the {ask.quantity.detail.replace('_', ' ').replace('.', ' ')} of the {ask.quantity.target}"


PIVOT_POINT = PivotPoint()
