"""What a body resting on a surface is asked (`BODY.DETAIL`, one of derive.model.scene's
CONTACT_QUANTITIES): its normal force and friction (also `in: STATE`), the least coefficient of
static friction that holds it, its acceleration down an incline, and from rest down the whole
incline at that constant acceleration, its speed at the bottom and the time it takes; on a loop,
the least release height that keeps it on the track. Each from one route's solve
(`Solution.contact_expression`):

    a = g . t (down the incline)      v = sqrt(2 a s),  t = sqrt(2 s / a),  s = H / sin(angle)

>>> from derive.language.problem import load
>>> from derive.solution.answers import Solution
>>> problem = load("rolling_incline")
>>> CONTACT.value(Solution(problem), problem.asks["a"], 0)
5*g*sin(theta)/7
"""
from __future__ import annotations

import sympy as sp

from derive.quantities.by_routes import ByRoutes
from derive.text.steps import Step

#: What the student's route along the motion gives (at the placement, at rest: derive.solution.textbook).
ALONG = {"acceleration.down_incline", "normal_force", "friction", "min_friction_coefficient"}
#: What energy and the constant acceleration give, of a body on a slope.
ON_SLOPE = {"speed_at_bottom", "time_to_bottom"}
#: The accelerations along the incline these are read from.
DOWN_INCLINE = ("acceleration.down_incline", "speed_at_bottom", "time_to_bottom")


class Contact(ByRoutes):
    """A quantity of a body on a surface (see the module)."""

    kind = "contact"
    symbol = "N"

    def on_route(self, solution, ask, route: str) -> sp.Expr:
        return solution.contact_expression(ask.quantity.target, ask.quantity.detail, solution.derivations[route],
                                           ask.state)

    def unknowns(self, solution, ask) -> set[sp.Symbol]:
        """The normal force and friction of the contact, or the body's acceleration, each is read from."""
        body, detail = ask.quantity.target, ask.quantity.detail
        forces = solution.dynamics_scene.contact_of(body).unknowns()
        needed = set()
        if detail in ("normal_force", "min_friction_coefficient"):
            needed.add(forces["normal"])
        if detail in ("friction", "min_friction_coefficient"):
            needed.add(forces["friction"])
        if detail in DOWN_INCLINE:
            needed |= {solution.coordinates.of(body, k).a for k in ("x", "y")}
        return needed

    def student_route(self, quantity) -> bool:
        return quantity.detail in ALONG | ON_SLOPE

    def sections(self, solution, ask) -> dict[str, list[Step]]:
        """A loop's least release height: the normal force at the top, and energy down to it."""
        if ask.quantity.detail != "min_release_height":
            return {}
        body = ask.quantity.target
        return {f"staying on the loop: the {body}": list(solution.release_height(body, "lagrange")[1])}


CONTACT = Contact()
