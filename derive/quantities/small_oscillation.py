"""The small oscillations about the reference configuration (`small_oscillation.omega`, `.period`,
`.growth_rate` about an unstable equilibrium; with several degrees of freedom the normal modes,
`small_oscillation.modes.N.omega|period`, lowest first, and the ratio of two amplitudes in a mode):
each route's equations linearized about it (`Solution.linearized_quantity`:
derive.mechanics.oscillation, derive.mechanics.normal_modes).

    q'' = -k q,  omega = sqrt(k)        det(K - omega^2 M) = 0

The answers hold where the forces that carry the swing stay positive along it, the equilibrium
is stable and not overdamped (`conditions`: `Solution.small_oscillation_conditions`).

>>> SMALL_OSCILLATION.kind, SMALL_OSCILLATION.symbol
('small_oscillation', 'omega')
"""
from __future__ import annotations

import sympy as sp

from derive.quantities.base import first_asked
from derive.quantities.by_routes import ByRoutes
from derive.text.steps import Step


class SmallOscillation(ByRoutes):
    """A small oscillation's frequency, period or growth rate, or a normal mode's (see the module)."""

    kind = "small_oscillation"
    symbol = "omega"

    def on_route(self, solution, ask, route: str) -> sp.Expr:
        detail = ask.quantity.detail
        if solution.freedoms == 1 and detail.startswith("modes."):
            raise solution.problem.error(f"ask.{ask.name}.of", "the scene has one degree of freedom, one mode: ask "
                                         f"small_oscillation.{detail.rpartition('.')[2]}")
        return solution.linearized_quantity(ask, route)

    def unknowns(self, solution, ask) -> set[sp.Symbol]:
        """The accelerations of the coordinates that swing: every normal mode's, or the one oscillation's."""
        if solution.freedoms > 1:
            return {c.a for c in solution.normal_modes["lagrange"].coordinates}
        return {solution.oscillations["lagrange"].coordinate.a}

    def conditions(self, solution, ask) -> list[tuple[sp.Expr, bool, str]]:
        """The linearization's conditions, once for every small oscillation asked."""
        return solution.small_oscillation_conditions(ask.name) if first_asked(solution, ask, lambda a: True) else []

    def route_steps(self, solution, asks: list, route: str) -> list[Step]:
        """The route's equations linearized, once for every small oscillation asked."""
        return list(solution.linearized[route].steps)


SMALL_OSCILLATION = SmallOscillation()
