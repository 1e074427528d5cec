"""What a system of bodies placed in the plane is asked: a body's position, the center of mass, the
moment of inertia about it and the reduced mass of two bodies.

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


def position(scene, body: str) -> sp.Matrix:
    """Where a body is placed (its motion's position; the origin for a body with none)."""
    motion = scene.motions.get(body)
    return sp.Matrix(motion.position) if motion else sp.zeros(2, 1)


def center_of_mass(scene) -> sp.Matrix:
    total = sum((b.mass for b in scene.bodies.values()), sp.Integer(0))
    return sum((b.mass * position(scene, n) for n, b in scene.bodies.items()), sp.zeros(2, 1)) / total


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
