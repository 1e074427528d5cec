"""An ellipse's orbit as a textbook solves it from its semi-major axis a and eccentricity e (Taylor,
Classical Mechanics, ch. 8; Kleppner & Kolenkow 2nd ed., ch. 10, the Kepler problem): its closest
and farthest points from the Sun at a(1 - e) and a(1 + e); there the velocity is at right angles to
the radius, so the angular momentum per unit mass is r v (conserved: gravity has no torque about the
Sun) and the energy per unit mass v^2/2 - GM/r (conserved: gravity is the only force, and it is
conservative); the two conservation laws give the speeds, l = sqrt(GM a (1 - e^2)) and
E = -GM/(2a); the period is the ellipse's area over the constant areal velocity l/2 (Kepler's
second law). The engine finds the same from Binet's equation (derive.mechanics.orbits);
derive.solution.textbook_routes compares them.

>>> GM, a, e = *sp.symbols("GM a", positive=True), sp.Symbol("e", real=True)
>>> orbit = by_conservation(GM, a, e, {"energy", "angular_momentum"})
>>> orbit.values["energy"], orbit.values["angular_momentum"]
(-GM/(2*a), sqrt(GM)*sqrt(a)*sqrt(1 - e**2))
"""
from __future__ import annotations

from dataclasses import dataclass

import sympy as sp

from derive.core.tidying import tidy
from derive.text.steps import Step

#: What the route finds (the details of an orbit's ask).
DETAILS = ("energy", "angular_momentum", "period", "periapsis", "apoapsis", "speed_at_periapsis", "speed_at_apoapsis")


@dataclass(frozen=True)
class ConservedOrbit:
    """The steps, and each of DETAILS by name."""

    steps: tuple[Step, ...]
    values: dict[str, sp.Expr]


def by_conservation(GM, a, e, asked: set[str]) -> ConservedOrbit:
    """The route for the ellipse of semi-major axis `a` and eccentricity `e` about a mass of gravitational
    parameter `GM`, its steps showing what `asked` names of DETAILS (the distances, the speed at the
    closest point and the angular momentum always: each later step stands on them)."""
    r_p, r_a, v_p, v_a, l, P = (sp.Symbol(n, positive=True) for n in ("r_p", "r_a", "v_p", "v_a", "l", "P"))
    E = sp.Symbol("E", real=True)
    near, far = a * (1 - e), a * (1 + e)
    angular = sp.Eq(r_p * v_p, r_a * v_a)
    energy = sp.Eq(v_p**2 / 2 - GM / r_p, v_a**2 / 2 - GM / r_a)
    (speeds,) = sp.solve([angular, energy], [v_p, v_a], dict=True)  # the positive speeds: one solution
    fast, slow = (tidy(speeds[v].subs({r_p: near, r_a: far})) for v in (v_p, v_a))
    momentum = sp.sqrt(sp.factor_terms(sp.expand(near**2 * fast**2)))  # sqrt(GM a (1 - e^2)), as the texts write it
    values = {"periapsis": near, "apoapsis": far, "speed_at_periapsis": fast, "speed_at_apoapsis": slow,
              "angular_momentum": momentum, "energy": tidy(fast**2 / 2 - GM / near),
              "period": tidy(sp.pi * a * a * sp.sqrt(1 - e**2) / (momentum / 2))}
    steps = [
        Step("The Sun is at a focus of the ellipse; the orbit's closest and farthest points from it are the ends of "
             "the major axis", (sp.Eq(r_p, near), sp.Eq(r_a, far)), role="solve"),
        Step("Conservation of angular momentum: gravity points at the Sun, so it has no torque about the Sun, and "
             "the angular momentum per unit mass stays the same. At the closest and farthest points the velocity is at "
             "right angles to the radius, so there it is the distance times the speed", (angular,)),
        Step("Conservation of energy: gravity is the only force on the planet, and it is conservative, so the kinetic "
             "energy per unit mass plus the potential energy per unit mass, zero at infinity, is the same at both points",
             (energy,)),
        Step("Solving the two for the speed at the closest point, with the distances found; the angular momentum per "
             "unit mass is the distance times the speed there", (sp.Eq(v_p, fast), sp.Eq(l, momentum))
             + ((sp.Eq(v_a, slow),) if "speed_at_apoapsis" in asked else ()), role="solve"),
    ]
    if "energy" in asked:
        steps.append(Step("The energy per unit mass, the same all round the orbit, at the closest point",
                          (sp.Eq(E, values["energy"]),), role="solve"))
    if "period" in asked:
        steps.append(Step("Kepler's second law: as the angular momentum is conserved, the line from the Sun sweeps "
                          "area at the constant rate of half the angular momentum per unit mass; one period sweeps the "
                          "ellipse's whole area, whose semi-minor axis is the semi-major one times the square root of "
                          "one less the square of the eccentricity",
                          (sp.Eq(P, 2 * sp.pi * a * a * sp.sqrt(1 - e**2) / l), sp.Eq(P, values["period"])),
                          role="solve"))
    return ConservedOrbit(tuple(steps), values)
