"""Small oscillations about the reference configuration of a one-degree-of-freedom scene.

The constraints are solved for the dependent coordinates (translations before angles),
the solved acceleration of the free coordinate is expanded to first order about the
reference configuration at rest, and q'' = -omega^2 q gives the angular frequency.

>>> import sympy as sp
>>> from derive.scene import Body, Gravity, Pin, Scene
>>> M, g, d, I = sp.symbols("M g d I", positive=True)
>>> scene = Scene({"bob": Body("bob", "custom", M, {}, I)}, (Pin("pivot", "bob", (0, d)),), Gravity(g))
>>> from derive.mechanics import lagrange
>>> small_oscillation(scene, lagrange.derive(scene)).omega
sqrt(M*d*g/(I + M*d**2))
"""
from __future__ import annotations

from dataclasses import dataclass

import sympy as sp

from derive.mechanics import joints
from derive.mechanics.derivation import Derivation, Step, root, tidy
from derive.mechanics.kinematics import Coordinate, Coordinates
from derive.scene import Scene


class OscillationError(ValueError):
    """The scene has no small oscillation about its reference configuration."""


@dataclass(frozen=True)
class Oscillation:
    coordinate: Coordinate
    omega: sp.Expr
    period: sp.Expr
    steps: tuple[Step, ...]


def small_oscillation(scene: Scene, derivation: Derivation) -> Oscillation:
    """Angular frequency and period of small oscillations about the reference configuration."""
    coords = Coordinates(scene)
    try:
        dependent = joints.solve_gaps(scene, coords)
    except ValueError as error:
        raise OscillationError(str(error)) from None
    free = [c for c in coords.all if c.q not in dependent]
    if len(free) != 1:
        raise OscillationError(f"small oscillations need one degree of freedom; the scene has {len(free)}")
    (coordinate,) = free
    at_rest = {c.u: 0 for c in coords.all}
    acceleration = derivation.solution[coordinate.a].xreplace(dependent).xreplace(at_rest)
    reference = {coordinate.q: 0}
    if not sp.simplify(acceleration.xreplace(reference)).equals(0):
        raise OscillationError("the reference configuration (every angle zero) is not an equilibrium")
    stiffness = tidy(-sp.diff(acceleration, coordinate.q).xreplace(reference))
    if stiffness.is_positive is not True:
        raise OscillationError(
            f"the equilibrium is not provably stable (q'' = {sp.sstr(-stiffness)} q): no oscillation"
        )
    omega = root(stiffness)
    period = 2 * sp.pi * root(1 / stiffness)
    q = coordinate.q
    steps = (
        Step(f"Linearize about {q} = 0 at rest", (sp.Eq(coordinate.a, -stiffness * q),)),
        Step(
            "Angular frequency and period of small oscillations",
            (sp.Eq(sp.Symbol("omega"), omega), sp.Eq(sp.Symbol("T"), period)),
        ),
    )
    return Oscillation(coordinate, omega, period, steps)
