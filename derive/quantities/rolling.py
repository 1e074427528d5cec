"""A round body rolling without slipping at its given velocity: `BODY.rolling.DETAIL`, one of
ROLLING_QUANTITIES (its angular velocity, the distance per turn, its kinetic energy, translational
and rotational, and the rotational fraction).

    omega = -v / R        T = M v^2 / 2 + I_cm omega^2 / 2 = I_P omega^2 / 2

Route 0 (the key's): about the center of mass. Route 1, its check: as a rotation about the contact
point. Both derive.mechanics.rolling, through the Solution (`Solution._rolling`: this layer sits
below derive.mechanics).

>>> from derive.language.problem import load
>>> ROLLING.claims(load("rolling_kinetic_energy").scene, "wheel", "rolling.kinetic_energy")
Quantity(kind='rolling', target='wheel', detail='kinetic_energy')
"""
from __future__ import annotations

import sympy as sp

from derive.model import directions
from derive.model.scene import ROLLING_QUANTITIES, Quantity
from derive.quantities.base import Check, QuantityKind, second_route


class Rolling(QuantityKind):
    """A quantity of a body rolling at its given velocity (see the module)."""

    kind = "rolling"
    symbol = "omega"
    unit = None  # by what is asked: rad/s, m, J or none
    routes = ("about the center of mass", "about the contact point")
    own_section = False

    def claims(self, scene, head: str, rest: str) -> Quantity | None:
        if head not in scene.bodies or not rest.startswith("rolling."):
            return None
        if rest[len("rolling."):] not in ROLLING_QUANTITIES:
            raise ValueError(f"a rolling body has {', '.join('rolling.' + q for q in ROLLING_QUANTITIES)}")
        contact, body = scene.contact_of(head), scene.bodies[head]
        if contact is None or not contact.rolling or head not in scene.motions or "radius" not in body.sizes:
            raise ValueError(f"{head}.rolling needs a round body rolling on a surface (on:, contact: rolling) "
                             "with a velocity")
        return Quantity(self.kind, head, rest[len("rolling."):])

    def sense_of(self, quantity: Quantity) -> tuple[str, str] | None:
        return directions.TURNS if quantity.detail == "angular_velocity" else None

    def value(self, solution, ask, route: int) -> sp.Expr:
        return solution._rolling(ask.quantity.target, ask.quantity.detail, route)

    def checks(self, solution, names: list[str]) -> list[Check]:
        return second_route(self, solution, names, "center_of_mass_vs_contact_point")

    def describe(self, ask) -> str:
        return f"the {ask.quantity.detail.replace('_', ' ')} of the rolling {ask.quantity.target}"


ROLLING = Rolling()
