"""What an orbit in an inverse-square field is asked: `orbit.DETAIL`, one of ORBIT_QUANTITIES (the
circular orbit's radius and effective potential's minimum from the angular momentum; the
ellipse's energy, angular momentum, period, periapsis, apoapsis and speeds there from its
semi-major axis and eccentricity).

    r_c = l^2 / GM        E = -GM / 2a        T = 2 pi sqrt(a^3 / GM)

Route 0 (the key's): derive.mechanics.orbits (Binet's equation, Kepler's laws), through the
Solution (`Solution._orbit`: this layer sits below derive.mechanics). Its check is of the whole
orbit, not of one answer (`Solution._orbit_check`): Lagrange's and Newton's radial equations agree,
the energy is the same at both turning points, and an ellipse from a periapsis and its speed gives
them back.

>>> from derive.language.problem import load
>>> ORBIT.claims(load("kepler_orbit").scene, "orbit", "period")
Quantity(kind='orbit', target=None, detail='period')
"""
from __future__ import annotations

import sympy as sp

from derive.model.scene import ORBIT_QUANTITIES, Quantity
from derive.quantities.base import Check, QuantityKind


class Orbit(QuantityKind):
    """A quantity of the scene's orbit (see the module)."""

    kind = "orbit"
    symbol = "r"
    unit = None  # by what is asked: m, J/kg, s, m/s
    routes = ("Binet's equation and Kepler's laws", "the radial equations by Lagrange and by Newton, and the energy "
              "at both turning points")
    own_section = False

    def claims(self, scene, head: str, rest: str) -> Quantity | None:
        if head != "orbit":
            return None
        if scene.orbit is None:
            raise ValueError("the scene has no orbit")
        if rest not in ORBIT_QUANTITIES:
            raise ValueError(f"an orbit has {', '.join(ORBIT_QUANTITIES)}; not {rest!r}")
        if getattr(scene.orbit, ORBIT_QUANTITIES[rest]) is None:
            raise ValueError(f"orbit.{rest} needs the orbit's {ORBIT_QUANTITIES[rest].replace('_', ' ')}")
        return Quantity(self.kind, None, rest)

    def value(self, solution, ask, route: int) -> sp.Expr | None:
        return solution._orbit(ask.quantity.detail) if route == 0 else None

    def checks(self, solution, names: list[str]) -> list[Check]:
        return [solution._orbit_check()]

    def describe(self, ask) -> str:
        return f"the orbit's {ask.quantity.detail.replace('_', ' ')}"


ORBIT = Orbit()
