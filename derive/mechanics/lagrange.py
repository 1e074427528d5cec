"""Lagrange's method with multipliers, in the planar coordinates of every body.

L = T - V with T = sum(1/2 m v_cm^2 + 1/2 I_cm omega^2) and V from the parts (gravity,
springs); each constraint g(q) = 0 enters with a multiplier that is the force it names (see
`derive.parts`), and is also imposed at acceleration level, d^2 g/dt^2 = 0.

>>> import sympy as sp
>>> from derive.parts.gravity import Gravity
>>> from derive.model.scene import Body, Scene
>>> m, g = sp.symbols("m g", positive=True)
>>> d = derive(Scene({"ball": Body("ball", "point", m, {})}, gravity=Gravity(g)))
>>> d.solution[sp.Symbol("yddot_ball", real=True)]
-g
"""
from __future__ import annotations

import sympy as sp

from derive.mechanics.derivation import (FIXED_LEFT_OUT, KINETIC, LAGRANGIAN, POTENTIAL, Derivation, at_state, part_sentences, rest_positions, worth_showing)
from derive.text.steps import Step
from derive.core.tidying import simplest
from derive.model.kinematics import Coordinates
from derive.model.scene import Scene


def energies(scene: Scene, coords: Coordinates) -> tuple[sp.Expr, sp.Expr]:
    """Kinetic energy of the bodies and potential energy of the parts (gravity, springs), in the
    coordinate symbols."""
    kinetic = sp.Integer(0)
    for body in scene.bodies.values():
        vx, vy = coords.of(body.name, "x").u, coords.of(body.name, "y").u
        kinetic += body.mass * (vx**2 + vy**2) / 2
        if body.rotates:
            kinetic += body.inertia * coords.angular_velocity(body.name) ** 2 / 2
    potential = sum((part.potential(coords) for part in scene.parts), sp.Integer(0))
    return kinetic, potential


def generalized_forces(scene: Scene, coords: Coordinates) -> dict[sp.Symbol, sp.Expr]:
    """Q_j = dP/du_j - dD/du_j: the power P of the non-conservative forces (virtual work) and
    Rayleigh's dissipation function D of the viscous ones."""
    power = sum((part.power(coords) for part in scene.parts), sp.Integer(0))
    dissipation = sum((part.dissipation(coords) for part in scene.parts), sp.Integer(0))
    return {c.q: sp.diff(power, c.u) - sp.diff(dissipation, c.u) for c in coords.all}


def nonconservative_power(scene: Scene, coords: Coordinates) -> sp.Expr:
    """The power of the non-conservative forces: P - 2D (it may hold unknown forces: kinetic
    friction is mu_k N)."""
    return sum((part.power(coords) - 2 * part.dissipation(coords) for part in scene.parts), sp.Integer(0))


def derive(scene: Scene, coords: Coordinates | None = None) -> Derivation:
    """Euler–Lagrange equations with multipliers, solved for accelerations and forces."""
    coords = coords or Coordinates(scene)
    kinetic, potential = energies(scene, coords)
    lagrangian = kinetic - potential
    pairs = [(gap, force) for c in scene.constraints for gap, force in zip(c.gaps(coords), c.unknowns().values())]
    applied = generalized_forces(scene, coords)
    equations = []
    for c in coords.all:
        lhs = coords.ddt(sp.diff(lagrangian, c.u)) - sp.diff(lagrangian, c.q)
        rhs = applied[c.q] + sum((force * sp.diff(gap, c.q) for gap, force in pairs), sp.Integer(0))
        equations.append(sp.Eq(lhs, rhs))
    rates = [coords.ddt(gap) for gap, _ in pairs]
    unknowns = coords.accelerations + [force for _, force in pairs]

    def written(derivation: Derivation) -> list[Step]:
        # The equations stay general (unexpanded: a cord's exact geometry makes them long); the
        # steps show them where the answers are read, in the reference configuration at rest.
        rest = coords.at_rest_in_reference()
        steps = [
            Step("Kinetic and potential energy", (sp.Eq(KINETIC, kinetic), sp.Eq(POTENTIAL, potential)),
                 sentences=tuple(part_sentences(scene, coords, "lagrange"))),
            Step("The Lagrangian, kinetic less potential energy", (sp.Eq(LAGRANGIAN, lagrangian),)),
        ]
        shown = worth_showing([sp.Eq(simplest(v.xreplace(rest_positions(coords))), 0) for v in rates])
        if pairs:
            steps.append(Step("The constraints, each held by a multiplier equal to the force it exerts (their rates, "
                              "in the reference configuration" + FIXED_LEFT_OUT + ")", shown))
        steps.append(Step("The Euler–Lagrange equation of each coordinate: the rate of change of its generalized "
                          "momentum, less the Lagrangian's derivative in it, equals the applied forces and the "
                          "constraint forces along it (in the reference configuration, at rest)",
                          tuple(at_state(e, rest) for e in equations), role="equations"))
        if shown:
            steps.append(Step("Constraints at acceleration level",
                              worth_showing([at_state(e, rest) for e in derivation.at_rest_equations[len(equations):]]),
                              role="equations"))
        return steps

    return Derivation("lagrange", equations, unknowns, written, rates, coords, [gap for gap, _ in pairs])
