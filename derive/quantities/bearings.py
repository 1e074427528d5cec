"""A body turning steadily in bearings about a fixed axle: `BODY.DETAIL`, one of BEARING_QUANTITIES
(its angular momentum's components, the angle between L and omega, its kinetic energy, and what the
bearings supply: their torque, the pair's couple, each bearing's force, the drive's torque).

    L = I omega        tau = dL/dt = omega x L        (a body whose axle is not a principal axis)

Route 0 (the key's): Newton–Euler, dL/dt = torque with F = m a_cm. Route 1, its check: Lagrange's
method with the bearings' forces and torques as multipliers; both derive.mechanics.bearings,
through the Solution (`Solution._bearings`: this layer sits below derive.mechanics). The check
compares the two routes component by component for every body in bearings, and a uniform shape's
L again by integrating r x (omega x r) dm (`Solution.bearings_checks`).

>>> from derive.language.problem import load
>>> BEARINGS.claims(load("disk_tilted_on_shaft").scene, "disk", "bearings.force")
Quantity(kind='bearings', target='disk', detail='bearings.force')
"""
from __future__ import annotations

import sympy as sp

from derive.model.scene import Quantity
from derive.model.solid_scene import BEARING_QUANTITIES
from derive.quantities.base import Check, QuantityKind, body_ask

#: derive.mechanics.bearings.ROUTES: the key's, then its check.
ROUTES = ("newton_euler", "lagrange")


class Bearings(QuantityKind):
    """A quantity of a body turning in bearings (see the module)."""

    kind = "bearings"
    symbol = "L"
    unit = None  # by what is asked: kg*m^2/s, J, N*m, N or rad
    routes = ("Newton–Euler (dL/dt = torque, F = m a_cm)", "Lagrange's method with the bearings' forces as multipliers")
    own_section = False

    def claims(self, scene, head: str, rest: str) -> Quantity | None:
        quantity = body_ask(self.kind, scene.bearings, head, rest, BEARING_QUANTITIES, "a body in bearings")
        if quantity is None:
            return None
        held = scene.bearings[head]
        if rest.startswith(("bearings.force", "bearings.A.", "bearings.B.")) and held.apart is None:
            raise ValueError(f"{head}.{rest} needs the distance between the bearings: bearings: {{apart: d}}")
        if rest == "bearings.force" and (scene.gravity is not None or any(c != 0 for c in held.through)):
            raise ValueError(f"{head}.bearings.force is each bearing's force of a couple: where the weight or an "
                             "offset shaft puts a net force on them, ask bearings.A.force and bearings.B.force")
        if rest.startswith("bearings.") and (scene.constraints or scene.loads):
            raise ValueError(f"{head}.{rest} is what the bearings supply to turn the body under its weight alone: a "
                             "scene with other loads or joints is not modelled")
        return quantity

    def value(self, solution, ask, route: int) -> sp.Expr:
        return solution._bearings(ask.quantity, ROUTES[route])

    def checks(self, solution, names: list[str]) -> list[Check]:
        return solution.bearings_checks(names)

    def describe(self, ask) -> str:
        return f"the {ask.quantity.detail.replace('_', ' ').replace('.', ' ')} of the {ask.quantity.target} in bearings"


BEARINGS = Bearings()
