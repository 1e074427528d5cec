"""A body's mass: `BODY.mass`, as the file gives it.

    m  (the body's `mass:`, or its parts' sum for a composite body)

Route 0 (the key's): the body's mass. It is given, not derived, so it has no second route: the
dimension check is its check.

>>> from derive.language.problem import load
>>> MASS.claims(load("rod_endpoint").scene, "rod", "mass")
Quantity(kind='mass', target='rod', detail=None)
"""
from __future__ import annotations

import sympy as sp

from derive.model.scene import Quantity
from derive.quantities.base import QuantityKind


class Mass(QuantityKind):
    """A body's mass (see the module)."""

    kind = "mass"
    symbol = "m"
    unit = "kg"
    routes = ("the body's mass as the file gives it", "none: it is given, not derived")
    own_section = False

    def claims(self, scene, head: str, rest: str) -> Quantity | None:
        return Quantity(self.kind, head, None) if head in scene.bodies and rest == "mass" else None

    def value(self, solution, ask, route: int) -> sp.Expr | None:
        return solution.scene.bodies[ask.quantity.target].mass if route == 0 else None

    def checks(self, solution, names: list[str]) -> list:
        return []  # given: the dimensions check is all there is

    def describe(self, ask) -> str:
        return f"the mass of the {ask.quantity.target}"


MASS = Mass()
