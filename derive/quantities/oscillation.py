"""The period of a swing at a finite amplitude (`oscillation.period`, with `amplitude:`): a pendulum's
by the elliptic integral, any other one-coordinate swing as twice the time between its turning
points, by energy (`Solution.period_at_amplitude`: derive.mechanics.oscillation,
derive.mechanics.durations); Newton–Euler's motion integrated over a swing checks a period by energy
(`checks`: `Solution.period_check`), the routes check a pendulum's.

    T = 4 sqrt(L/g) K(sin^2(theta0/2))        T = 2 int dq / q'(q)  between the turning points

>>> OSCILLATION.kind, OSCILLATION.symbol
('oscillation', 'T')
"""
from __future__ import annotations

import sympy as sp

from derive.quantities.base import Check
from derive.quantities.by_routes import ByRoutes
from derive.text.steps import Step


class Oscillation(ByRoutes):
    """A swing's period at its amplitude (see the module)."""

    kind = "oscillation"
    symbol = "T"

    def on_route(self, solution, ask, route: str) -> sp.Expr:
        return solution.period(ask, route)

    def unknowns(self, solution, ask) -> set[sp.Symbol]:
        return {solution.oscillations["lagrange"].coordinate.a}

    def checks(self, solution, names: list[str]) -> list[Check]:
        """A period by energy against Newton–Euler's motion integrated over a swing (a pendulum's elliptic
        integral: compared by the routes check)."""
        return [solution.period_check(names)]

    def route_steps(self, solution, asks: list, route: str) -> list[Step]:
        """The period's derivation at each ask's amplitude."""
        return [step for ask in asks for step in solution.period_at_amplitude(ask.amplitude, route)[1]]


OSCILLATION = Oscillation()
