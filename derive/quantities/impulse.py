"""The impulse a body takes in an impact (`BODY.impulse.x`, `.y`), or a joint gives the body it holds
(`JOINT.impulse.x`), asked `in:` the state just after it (`event: stick`, `lock` or `bounce`). By
Lagrange's route from the changes of momentum, by Newton–Euler's from the impact's impulse
equations (`Solution.impulse_in`: derive.mechanics.impulses):

    J = M (v_after - v_before)        sum J = M Delta v_cm,   sum r x J = I_cm Delta omega

>>> IMPULSE.kind, IMPULSE.routes[0]
('impulse', "Lagrange's method")
"""
from __future__ import annotations

import sympy as sp

from derive.quantities.by_routes import ByRoutes


class Impulse(ByRoutes):
    """An impulse in an impact (see the module)."""

    kind = "impulse"
    symbol = "J"

    def on_route(self, solution, ask, route: str) -> sp.Expr:
        return solution.impulse_in(ask.quantity, ask.state, route)


IMPULSE = Impulse()
