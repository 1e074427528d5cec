"""The torque of internal central forces on N point masses (the notes' §6): `internal_forces.torque`,
zero for any positions and any force law.

    dL/dt = sum_i x_i x sum_j F_ji = 0        (F_ji along x_j - x_i, F_ji = -F_ij)

Route 0 (the key's): summed over the bodies. Route 1, its check: summed over the pairs, each
pair's two terms combined. Both derive.mechanics.many_bodies, through the Solution
(`Solution._internal_torque`: this layer sits below derive.mechanics).

>>> from derive.language.problem import load
>>> INTERNAL_FORCES.claims(load("internal_forces").scene, "internal_forces", "torque")
Quantity(kind='internal_forces', target=None, detail='torque')
"""
from __future__ import annotations

import sympy as sp

from derive.model.scene import Quantity
from derive.quantities.base import Check, QuantityKind, second_route, system_ask


class InternalForces(QuantityKind):
    """The torque of internal central forces (see the module)."""

    kind = "internal_forces"
    symbol = "tau"
    unit = "N*m"
    routes = ("the sum over the bodies", "the sum over the pairs")
    own_section = False

    def claims(self, scene, head: str, rest: str) -> Quantity | None:
        return system_ask(self.kind, scene, head, rest)

    def value(self, solution, ask, route: int) -> sp.Expr:
        return solution._internal_torque(route)

    def checks(self, solution, names: list[str]) -> list[Check]:
        return second_route(self, solution, names, "direct_vs_pairs")

    def describe(self, ask) -> str:
        return "the torque of the internal forces"


INTERNAL_FORCES = InternalForces()
