"""A body's acceleration along an axis (`BODY.acceleration.x`, `.y`) or its angular acceleration
(`BODY.angular_acceleration`, counter-clockwise positive), at the placement at rest or `in: STATE`:
the coordinate's second derivative in each route's solve (`Solution.in_state`).

    Lagrange:      d/dt (dL/dq') - dL/dq = Q          Newton–Euler:   M a = sum F,   I alpha = sum tau

>>> from derive.language.problem import load
>>> from derive.solution.answers import Solution
>>> problem = load("string_wrapped_disk")
>>> ACCELERATION.value(Solution(problem), problem.asks["a"], 1)
-2*g*m/(M + 2*m)
"""
from __future__ import annotations

import sympy as sp

from derive.quantities.by_routes import OneUnknown


class Acceleration(OneUnknown):
    """A body's acceleration along x or y (see the module)."""

    kind = "acceleration"
    symbol = "a"

    def _coordinate(self, quantity) -> str:
        return quantity.detail

    def _unknown(self, solution, ask) -> sp.Symbol:
        return solution.coordinates.of(ask.quantity.target, self._coordinate(ask.quantity)).a


class AngularAcceleration(Acceleration):
    """A body's angular acceleration, counter-clockwise positive (see the module)."""

    kind = "angular_acceleration"
    symbol = "alpha"

    def _coordinate(self, quantity) -> str:
        return "theta"


ACCELERATION = Acceleration()
ANGULAR_ACCELERATION = AngularAcceleration()
