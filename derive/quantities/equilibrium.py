"""Where the scene rests (`BODY.equilibrium.x`, `.y`, `.angle`): the zero of every generalized force
with the velocities zero, found by each route's equations (`Solution.equilibria`:
derive.mechanics.equilibrium), the root that lies in the parameter ranges.

    Q(q) = 0  (Lagrange: -dV/dq)        sum F = 0, sum tau = 0  (Newton–Euler)

>>> EQUILIBRIUM.kind, EQUILIBRIUM.unknowns(None, None)
('equilibrium', set())
"""
from __future__ import annotations

import sympy as sp

from derive.quantities.by_routes import ByRoutes
from derive.text.steps import Step


class Equilibrium(ByRoutes):
    """A body's place at the scene's equilibrium (see the module)."""

    kind = "equilibrium"
    symbol = "q_eq"

    def on_route(self, solution, ask, route: str) -> sp.Expr:
        quantity = ask.quantity
        return solution.equilibria[route].position(solution.scene, quantity.target, quantity.detail)

    def route_steps(self, solution, asks: list, route: str) -> list[Step]:
        """The route's balance solved, once for every equilibrium asked."""
        return list(solution.equilibria[route].steps)


EQUILIBRIUM = Equilibrium()
