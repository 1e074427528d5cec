"""What a system of bodies placed in the plane is asked: `system.inertia`, its moment of inertia
about its center of mass (normal to the plane), and `system.reduced_mass` of two bodies.

    I_cm = sum (I_i + m_i |r_i - r_cm|^2)          mu = m1 m2 / (m1 + m2)

Route 0 (the key's): the scalar parallel-axis sum; the reduced mass from the kinetic energy of
the two bodies' relative motion with their center of mass at rest. Route 1, its check: the
bodies' inertia tensors composed about the center of mass; for two point masses also I = mu d^2.

>>> from derive.language.problem import load
>>> scene = load("diatomic_molecule").scene
>>> reduced_mass(*(b.mass for b in scene.bodies.values()))
m1*m2/(m1 + m2)
"""
from __future__ import annotations

import sympy as sp

from derive.core.tidying import tidy
from derive.model import inertia
from derive.model.placement import center_of_mass, position
from derive.model.scene import Quantity
from derive.numbers.agreement import agree
from derive.quantities.base import Check, CheckFailure, QuantityKind


def reduced_mass(m1: sp.Expr, m2: sp.Expr) -> sp.Expr:
    """mu with T = mu rho'^2 / 2 for the separation rho of two masses whose center of mass is at rest."""
    r1, r2, rho = sp.symbols("r_1 r_2 rho")
    positions = sp.solve([sp.Eq(m1 * r1 + m2 * r2, 0), sp.Eq(r2 - r1, rho)], [r1, r2])
    rate = sp.Symbol("rhodot")
    kinetic = sum(m * (sp.diff(positions[r], rho) * rate) ** 2 / 2 for m, r in ((m1, r1), (m2, r2)))
    return tidy(2 * kinetic / rate**2)


def moment(scene, route: int) -> sp.Expr:
    """The system's moment of inertia about its center of mass, by the parallel-axis sum (route 0)
    or the bodies' tensors composed (route 1)."""
    center = center_of_mass(scene)
    if route == 0:
        return tidy(sum((b.inertia + b.mass * (position(scene, n) - center).dot(position(scene, n) - center)
                         for n, b in scene.bodies.items()), sp.Integer(0)))
    parts = [inertia.Part(b.shape, b.mass, b.sizes, (*position(scene, n), 0)) for n, b in scene.bodies.items()]
    return tidy(inertia.composite_tensor(parts, about=(*center, 0)).tensor[2, 2])


class System(QuantityKind):
    """The moment of inertia of a system about its center of mass, or the reduced mass of two bodies."""

    kind = "system"
    symbol = "I_cm"
    unit = None  # kg*m^2 or kg
    routes = ("the scalar parallel-axis sum", "the bodies' inertia tensors composed")
    own_section = False

    def claims(self, scene, head: str, rest: str) -> Quantity | None:
        if head != "system":
            return None
        if rest not in ("inertia", "reduced_mass"):
            raise ValueError("the system has inertia (about its center of mass) and reduced_mass")
        if rest == "reduced_mass" and len(scene.bodies) != 2:
            raise ValueError("a reduced mass is for a system of two bodies")
        return Quantity(self.kind, None, rest)

    def value(self, solution, ask, route: int) -> sp.Expr:
        if ask.quantity.detail == "reduced_mass":
            return reduced_mass(*(b.mass for b in solution.scene.bodies.values()))
        return moment(solution.scene, route)

    def checks(self, solution, names: list[str]) -> list[Check]:
        """The scalar parallel-axis sum equals the composed inertia tensor; for two point masses,
        the inertia about the center of mass is mu d^2."""
        scene = solution.scene
        total, composed = moment(scene, 0), moment(scene, 1)
        if agree(total, composed) is None:
            raise CheckFailure(f"{solution.problem.id}: the system's inertia is {total} summed, {composed} composed")
        detail = "parallel-axis sum equals the composed tensor"
        bodies = list(scene.bodies.values())
        if len(bodies) == 2 and all(b.shape == "point" for b in bodies):
            gap = position(scene, bodies[1].name) - position(scene, bodies[0].name)
            if agree(total, reduced_mass(bodies[0].mass, bodies[1].mass) * gap.dot(gap)) is None:
                raise CheckFailure(f"{solution.problem.id}: I differs from mu d^2")
            detail += "; I = mu d^2"
        return [Check("system_inertia", True, "symbolic", detail,
                      "The system's mass and moment of inertia agree by two routes.")]

    def describe(self, ask) -> str:
        return ("the reduced mass of the two bodies" if ask.quantity.detail == "reduced_mass"
                else "the moment of inertia of the system about its center of mass")


SYSTEM = System()
