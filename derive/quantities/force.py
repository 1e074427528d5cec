"""A force a joint, cord or contact gives (`CORD.tension`, `PIN.reaction.x`, `CONTACT.normal`, ...),
at the placement at rest or `in: STATE`: the constraint force's unknown in each route's solve
(`Solution.in_state`), Lagrange's from its multipliers, Newton–Euler's from the bodies' balances.

>>> from derive.language.problem import load
>>> from derive.solution.answers import Solution
>>> problem = load("string_wrapped_disk")
>>> FORCE.value(Solution(problem), problem.asks["T"], 0)
M*g*m/(M + 2*m)
"""
from __future__ import annotations

import sympy as sp

from derive.quantities.by_routes import OneUnknown


class Force(OneUnknown):
    """A constraint's force (see the module)."""

    kind = "force"
    symbol = "F"

    def _unknown(self, solution, ask) -> sp.Symbol:
        return solution.dynamics_scene.constraint(ask.quantity.target).unknowns()[ask.quantity.detail]


FORCE = Force()
