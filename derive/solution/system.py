"""What a system of bodies placed in the plane is asked: the moment of inertia about its center of
mass and the reduced mass of two bodies.

>>> from derive.language.problem import load
>>> scene = load("diatomic_molecule").scene
>>> quantity(scene, "reduced_mass", "sum")
m1*m2/(m1 + m2)
"""
from __future__ import annotations

import sympy as sp

from derive.core.tidying import tidy
from derive.mechanics import many_bodies
from derive.model import inertia
from derive.model.placement import center_of_mass, position


def quantity(scene, detail: str, route: str) -> sp.Expr:
    """The system's moment of inertia about its center of mass (normal to the plane), by the scalar
    parallel-axis sum (`route` "sum") or by composing the bodies' tensors; or the reduced mass of two
    bodies, from the kinetic energy of their relative motion with the center of mass at rest."""
    if detail == "reduced_mass":
        return many_bodies.reduced_mass(*(b.mass for b in scene.bodies.values()))
    center = center_of_mass(scene)
    if route == "sum":
        return tidy(sum((b.inertia + b.mass * (position(scene, n) - center).dot(position(scene, n) - center)
                         for n, b in scene.bodies.items()), sp.Integer(0)))
    parts = [inertia.Part(b.shape, b.mass, b.sizes, (*position(scene, n), 0)) for n, b in scene.bodies.items()]
    return tidy(inertia.composite_tensor(parts, about=(*center, 0)).tensor[2, 2])
