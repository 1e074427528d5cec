"""The parts of a planar scene, each known to both routes of derivation.

A part is one module of this package: a frozen dataclass (what the problem file says) with
the contributions it makes to each route. The two routes never share a formula of a part:

- Lagrange's method reads `gaps` (holonomic constraints g(q) = 0, each paired in order with one
  of `unknowns`, normalized so that its multiplier IS that force: the generalized constraint
  force is lambda dg/dq), `potential` (V), `power` (the power of its non-conservative forces that
  do not depend on the velocities: Q_j = dP/du_j) and `dissipation` (Rayleigh's function D of its
  viscous forces: Q_j = -dD/du_j, their power -2D);
- Newton–Euler reads `loads` (forces at material points and torques on bodies, with the
  unknowns in them) and `conditions` (velocity expressions the part holds at zero, from
  rigid-body kinematics v = v_cm + omega z x r), one per unknown.

Bodies bring their kinetic energy and their weight (derive.mechanics); every other physical
contribution comes from a part. `bodies` names the bodies a part couples (a scene's connected
components follow from it), and `signs` the physical signs its forces must keep (a cord's tension
>= 0, a normal force >= 0), checked over the parameter ranges.

Adding a part: write its module here with a dataclass deriving from `Part`, override what it
contributes, and register its problem-file key in `derive.scene_file` (docs/design.md, Parts).

>>> import sympy as sp
>>> Part().unknowns(), Part().potential(None)
({}, 0)
"""
from __future__ import annotations

from dataclasses import dataclass

import sympy as sp


@dataclass(frozen=True)
class AppliedForce:
    """A force on a body, applied at a world-frame offset from its center of mass."""

    body: str
    offset: sp.Matrix
    force: sp.Matrix
    label: str


@dataclass(frozen=True)
class AppliedTorque:
    """A pure torque (a couple) on a body, counter-clockwise positive."""

    body: str
    torque: sp.Expr
    label: str


@dataclass(frozen=True)
class Sign:
    """A force that must keep its sign for the scene to be what the file says: `expression` (an
    unknown of the derivation, or an expression of unknowns) must be >= 0, or the `meaning`
    explains what breaks (the cord goes slack). At an equilibrium a small oscillation swings
    about, it must be positive: `unloaded` says what a zero there means ("the cord rope is
    slack"), `force` names it ("its tension")."""

    expression: sp.Expr
    meaning: str
    unloaded: str
    force: str


class Part:
    """What a part contributes to each route; by default nothing. Every part has a `name`."""

    def bodies(self) -> tuple[str, ...]:
        """The bodies this part couples or acts on."""
        return ()

    def unknowns(self) -> dict[str, sp.Symbol]:
        """The constraint forces it exerts, by the names an answer asks for (`tension`, ...)."""
        return {}

    def gaps(self, coords) -> list[sp.Expr]:
        """Lagrange: holonomic constraints, one per unknown, in the order of `unknowns`."""
        return []

    def potential(self, coords) -> sp.Expr:
        """Lagrange: its potential energy."""
        return sp.Integer(0)

    def power(self, coords) -> sp.Expr:
        """Lagrange: the power of its non-conservative forces that do not depend on the velocities."""
        return sp.Integer(0)

    def dissipation(self, coords) -> sp.Expr:
        """Lagrange: Rayleigh's dissipation function of its viscous forces (half their lost power)."""
        return sp.Integer(0)

    def loads(self, coords) -> list[AppliedForce | AppliedTorque]:
        """Newton–Euler: its forces at material points and its torques."""
        return []

    def conditions(self, coords) -> list[sp.Expr]:
        """Newton–Euler: velocity expressions it holds at zero, one per unknown."""
        return []

    def signs(self) -> list[Sign]:
        """Forces that must keep their sign (a taut cord, a body pressing on its surface)."""
        return []

    def extents(self, coords) -> list[tuple[sp.Expr, str]]:
        """Sizes of its geometry, positive in the reference configuration, with what it means for
        one to reach zero: a motion along a straight line of the coordinates
        (derive.mechanics.states) keeps them positive where its line is the part's (a block pulled
        up past its pulley would flip the cord's run)."""
        return []
