"""Where the bodies of a system placed in the plane are (a molecule's atoms, masses on a light rod),
and their center of mass.

>>> from derive.language.problem import load
>>> scene = load("diatomic_molecule").scene
>>> center_of_mass(scene).T
Matrix([[d*m2/(m1 + m2), 0]])
"""
from __future__ import annotations

import sympy as sp


def position(scene, body: str) -> sp.Matrix:
    """Where a body is placed (its motion's position; the origin for a body with none)."""
    motion = scene.motions.get(body)
    return sp.Matrix(motion.position) if motion else sp.zeros(2, 1)


def center_of_mass(scene) -> sp.Matrix:
    """The mass-weighted mean of the bodies' positions."""
    total = sum((b.mass for b in scene.bodies.values()), sp.Integer(0))
    return sum((b.mass * position(scene, n) for n, b in scene.bodies.items()), sp.zeros(2, 1)) / total
