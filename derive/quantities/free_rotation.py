"""A body turning with no torque: `BODY.DETAIL`, one of FREE_ROTATION_QUANTITIES (a symmetric body's
free precession in the body and in space, the angles of L and omega to its axis; a steady rotation
about a principal axis: the wobble rate about the axis of least or greatest moment, the growth rate
about the intermediate one, the tennis-racket theorem).

    Omega_body = (I3 - I1) w3 / I1        lambda^2 = w^2 (I1 - I2)(I3 - I1) / (I2 I3) about axis 1

Route 0 (the key's): Euler's equations. Route 1, its check: Lagrange's equations in Euler angles;
both derive.mechanics.free_rotation, through the Solution (`Solution._free_rotation`: this layer
sits below derive.mechanics). The principal moments keep the order of the middle of the ranges in
every variant (`conditions`).

>>> from derive.language.problem import load
>>> FREE_ROTATION.claims(load("tennis_racket").scene, "book", "rotation.intermediate.growth_rate")
Quantity(kind='free_rotation', target='book', detail='rotation.intermediate.growth_rate')
"""
from __future__ import annotations

import sympy as sp

from derive.model.scene import Quantity
from derive.model.solid_scene import FREE_ROTATION_QUANTITIES
from derive.quantities.base import Check, QuantityKind, body_ask, first_asked

#: derive.mechanics.free_rotation.ROUTES: the key's, then its check.
ROUTES = ("newton_euler", "lagrange")
#: How a steady rotation about the axis of each rank behaves, for a refusal that says which to ask.
STABLE = {"intermediate": "unstable (the tennis-racket theorem): ask rotation.intermediate.growth_rate",
          "least": "stable: ask rotation.least.wobble", "greatest": "stable: ask rotation.greatest.wobble"}


class FreeRotation(QuantityKind):
    """A free precession or a steady rotation's wobble or growth rate (see the module)."""

    kind = "free_rotation"
    symbol = "Omega"
    unit = None  # rad/s or rad
    routes = ("Euler's equations", "Lagrange's equations in Euler angles")
    own_section = False

    def claims(self, scene, head: str, rest: str) -> Quantity | None:
        rank = rest.split(".")[1] if rest.count(".") == 2 and rest.startswith("rotation.") else None
        if head in scene.free_rotations and rest not in FREE_ROTATION_QUANTITIES and rank in STABLE \
                and rest.endswith((".wobble", ".growth_rate")):
            raise ValueError(f"a steady rotation about the axis of {rank} moment is {STABLE[rank]}")
        return body_ask(self.kind, scene.free_rotations, head, rest, FREE_ROTATION_QUANTITIES, "a body in free rotation")

    def value(self, solution, ask, route: int) -> sp.Expr:
        return solution._free_rotation(ask.quantity, ROUTES[route])

    def conditions(self, solution, ask) -> list[tuple[sp.Expr, bool, str]]:
        """The principal moments in the order of the middle of the ranges: once per body asked a steady rotation."""
        if first_asked(solution, ask, lambda a: a.quantity.detail.startswith("rotation.")):
            return solution.free_order_conditions(ask.quantity.target)
        return []

    def checks(self, solution, names: list[str]) -> list[Check]:
        return [solution.free_rotation_check(names)]

    def describe(self, ask) -> str:
        return f"the {ask.quantity.detail.replace('_', ' ').replace('.', ' ')} of the {ask.quantity.target}"


FREE_ROTATION = FreeRotation()
