"""The rate of a body's steady conical motion on a fixed point: `BODY.conical.rate`, a rod hanging
from a pivot at its end and swinging round in a cone at a fixed angle (a `pivot_point` body).

The body turns as one about the vertical through its point at Omega, its axis at the tilt (no
spin of its own: omega3 = Omega cos(tilt)). Theta's equation of motion, held steady, gives

    (I1 - I3) Omega^2 cos(tilt) + m g l = 0

with I1 and I3 about the point; a uniform rod hanging at theta from the downward vertical (tilt
pi - theta, I1 = m L^2/3, I3 = 0, l = L/2): Omega^2 = 3 g/(2 L cos(theta)). Route 0 (the key's):
Lagrange's equation in Euler angles; route 1, its check: Euler's equations about the point
(derive.mechanics.fixed_point, through the Solution's `conical_squared`). A variant where the
squared rate is not positive has no such motion (a rod standing above its point) and is refused.

>>> from derive.language.problem import load
>>> problem = load("tests/textbook/rod_conical_pendulum.yaml")
>>> CONICAL.claims(problem.scene, "rod", "conical.rate")
Quantity(kind='conical', target='rod', detail='rate')
"""
from __future__ import annotations

import sympy as sp

from derive.core.tidying import tidy
from derive.model.scene import Quantity
from derive.quantities.base import Check, QuantityKind

ROUTES = ("lagrange", "newton_euler")


class Conical(QuantityKind):
    """The rate of steady conical motion of a body on a fixed point (see the module)."""

    kind = "conical"
    symbol = "Omega"
    unit = "rad/s"
    routes = ("Lagrange's equation of the tilt, held steady", "Euler's equations about the fixed point")

    def claims(self, scene, head: str, rest: str) -> Quantity | None:
        if not rest.startswith("conical"):
            return None
        point = scene.pivot_points.get(head)
        if point is None or point.centered:
            raise ValueError(f"conical.rate is asked of a body on a fixed point off its center of mass (pivot_point: "
                             f"{{at: end, tilt: pi - theta}}); {head} is not one")
        if rest != "conical.rate":
            raise ValueError(f"a body's steady conical motion has conical.rate; not {rest!r}")
        return Quantity(self.kind, head, "rate")

    def value(self, solution, ask, route: int) -> sp.Expr:
        return tidy(sp.sqrt(solution.conical_squared(ask.quantity.target, ROUTES[route])))

    def checks(self, solution, names: list[str]) -> list[Check]:
        """The body's equations of motion by Lagrange, Euler about the point and Kane, term by term, and
        the rate by the first two (the fixed point's check, derive.solution.solid_checks)."""
        return [solution.pivot_point_check(names)]

    def conditions(self, solution, ask) -> list[tuple[sp.Expr, bool, str]]:
        body = ask.quantity.target
        return [(solution.conical_squared(body, ROUTES[0]), True,
                 f"no steady conical motion of the {body} at this tilt ((I1 - I3) cos(tilt) would have to be negative)")]

    def describe(self, ask) -> str:
        return f"the rate at which the {ask.quantity.target} turns about the vertical in a steady cone"


CONICAL = Conical()
