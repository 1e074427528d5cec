"""Small oscillations of a body on a fixed pivot as a textbook derives them: the restoring torque
about the pivot, tau = -kappa theta for a small angle, and I_P theta'' = tau.

For a compound pendulum a solution manual writes: I_P = I_cm + M d^2 (the parallel-axis theorem),
tau = -M g d sin(theta) ~ -M g d theta, so theta'' = -(M g d / I_P) theta, omega = sqrt(M g d / I_P)
and T = 2 pi / omega. The torque here is the loads' own, -dV/dtheta of the scene's potential energy
(gravity, springs) with the pin's constraint solved for the center, at the body's angle theta from
where the file places it (its equilibrium); kappa is its slope there. The frequency it gives must
be the engine's (derive.mechanics.oscillation, checked in derive.solution.crosschecks).

>>> from derive.language.problem import load
>>> from derive.solution.answers import Solution
>>> solution = Solution(load("compound_pendulum"))
>>> swing = small_swing(solution.dynamics_scene, solution.coordinates)
>>> swing.omega
sqrt(M)*sqrt(Rcm)*sqrt(g)/sqrt(I_cm + M*Rcm**2)
"""
from __future__ import annotations

from dataclasses import dataclass

import sympy as sp

from derive.core.tidying import tidy
from derive.mechanics.along_motion import NotAlongALine
from derive.text.steps import Step
from derive.model.kinematics import Coordinates
from derive.model.scene import Scene
from derive.parts.contact import Contact
from derive.parts.cord import Cord
from derive.parts.pin import Pin
from derive.parts.surfaces import Circle, Plane


@dataclass(frozen=True)
class SmallSwing:
    """The steps, the angular frequency they give, and the point it turns about in words."""

    steps: tuple[Step, ...]
    omega: sp.Expr
    about: str = "the pivot"


def small_swing(scene: Scene, coords: Coordinates) -> SmallSwing:
    """The route for one body turning about a pin fixed to the ground, or rocking without slipping on
    a fixed plane (about its point of contact, at rest for the moment: Morin, ch. 8), a bob on a cord
    from a fixed point (`_on_a_cord`), or a round body rolling at the bottom of a bowl (`_rolling_in_a_bowl`),
    placed at rest where it hangs or rests; NotAlongALine for any other scene."""
    bodies = list(scene.bodies.values())
    if len(bodies) == 1 and not bodies[0].rotates and len(scene.constraints) == 1 \
            and isinstance(scene.constraints[0], Cord):
        return _on_a_cord(scene, coords, bodies[0], scene.constraints[0])
    if len(bodies) == 1 and len(scene.constraints) == 1 and isinstance(scene.constraints[0], Contact) \
            and scene.constraints[0].rolling and isinstance(scene.surfaces.get(scene.constraints[0].surface), Circle):
        return _rolling_in_a_bowl(scene, bodies[0], scene.constraints[0])
    held_by = [c for c in scene.constraints if isinstance(c, Pin) and c.to is None
               or isinstance(c, Contact) and c.rolling and c.carrier is None and c.center is not None
               and isinstance(scene.surfaces[c.surface], Plane)]  # a round face off its center of mass: it rocks
    if len(bodies) != 1 or not bodies[0].rotates or len(held_by) != 1 or len(scene.constraints) != 1:
        raise NotAlongALine("not one body swinging on a fixed pivot or rocking on a fixed surface")
    body, (pin,) = bodies[0], held_by
    x, y, theta = (coords.of(body.name, k) for k in ("x", "y", "theta"))
    held = sp.solve(pin.gaps(coords), [x.q, y.q], dict=True)
    if len(held) != 1:
        raise NotAlongALine("the pin or the contact does not hold the center in one place for each angle")
    potential = sum((part.potential(coords) for part in scene.parts), sp.Integer(0)).xreplace(held[0])
    angle = sp.Symbol("theta", real=True)
    torque = tidy(-sp.diff(potential, theta.q).xreplace({theta.q: angle}))
    stiffness = tidy(-sp.diff(torque, angle).xreplace({angle: 0}))
    if torque.xreplace({angle: 0}) != 0 or stiffness == 0 or stiffness.is_negative:
        raise NotAlongALine("not placed at a stable equilibrium")
    rocks = isinstance(pin, Contact)
    point = (pin.offset(coords) if rocks else coords.rotated(body.name, pin.offset)).xreplace(coords.at_rest_in_reference())
    distance = tidy(sp.sqrt(point.dot(point)))
    moment = sp.Symbol("I_P")
    about = tidy(body.inertia + body.mass * distance**2)
    omega, period, tau = sp.Symbol("omega"), sp.Symbol("T"), sp.Symbol("tau")
    kappa = stiffness if isinstance(stiffness, sp.Symbol) else sp.Symbol("kappa")  # a torsion spring's own kappa
    frequency = tidy(sp.sqrt(stiffness / about))
    pivot = "point of contact" if rocks else "pivot"
    if rocks:
        inertia = Step(f"The {body.name} rocks without slipping: its point of contact is at rest for the moment, and it "
                       "turns about that point. By the parallel-axis theorem its moment of inertia about it is",
                       (sp.Eq(moment, sp.Add(body.inertia, sp.Mul(body.mass, sp.Pow(distance, 2, evaluate=False), evaluate=False),
                                           evaluate=False)),
                        sp.Eq(moment, about)))
    elif distance != 0 and body.composite is not None:
        inertia = Step(f"The {body.name} turns about its pivot: by the parallel-axis theorem each part's moment of "
                       "inertia about the pivot is its own about its center plus its mass times the square of its "
                       "distance from the pivot; the body's is their sum",
                       (sp.Eq(moment, body.composite.moment_about(pin.offset)), sp.Eq(moment, about)))
    elif distance != 0:
        inertia = Step(f"The {body.name} turns about its pivot, off its center of mass: by the parallel-axis theorem its "
                       "moment of inertia about the pivot is", (sp.Eq(moment, body.inertia + body.mass * distance**2),))
    else:
        inertia = Step(f"The {body.name} turns about an axle through its center of mass, its moment of inertia about it",
                       (sp.Eq(moment, body.inertia),))
    held_there = "the normal force and friction act there and have" if rocks else "the pivot's force acts there and has"
    steps = (
        inertia,
        Step(f"Turned by an angle from where it rests, the {body.name} is pulled back by the torque of the loads about "
             f"the {pivot} ({held_there} no moment about it); for a small angle it is proportional to the angle",
             (sp.Eq(tau, torque), sp.Eq(tau, -kappa * angle), *((sp.Eq(kappa, stiffness),) if kappa != stiffness else ()))),
        Step(f"Newton's second law for the rotation about the {pivot} is then that of simple harmonic motion, of "
             "angular frequency and period", (sp.Eq(moment * sp.Symbol("thetaddot"), -kappa * angle),
                                              sp.Eq(omega, sp.sqrt(kappa / moment)), sp.Eq(omega, frequency),
                                              sp.Eq(period, 2 * sp.pi / omega))),
    )
    return SmallSwing(steps, frequency, f"the {pivot}")


def _on_a_cord(scene: Scene, coords: Coordinates, bob, cord: Cord) -> SmallSwing:
    """A simple pendulum as Halliday, Resnick & Walker (10th ed., ch. 15, Module 15-5) derive it: the bob, hanging
    at rest straight below the cord's fixed end, moves on a circle about that end; I = m L^2 about it, and the
    torque of the loads at an angle theta from the vertical (-dV/dtheta, the cord's pull having no moment there),
    tau = -m g L sin(theta) ~ -kappa theta.

    >>> from derive.language.problem import load
    >>> from derive.solution.answers import Solution
    >>> solution = Solution(load("simple_pendulum_cord"))
    >>> small_swing(solution.dynamics_scene, solution.coordinates).omega
    sqrt(g)/sqrt(L)
    """
    fixed = [a for a in cord.path if a.body is None]
    held = [a for a in cord.path if a.body == bob.name]
    if len(cord.path) != 2 or cord.drawn != 0 or len(fixed) != 1 or len(held) != 1 \
            or any(a.kind != "point" for a in cord.path) or held[0].offset != (0, 0):
        raise NotAlongALine("not a bob on a straight cord from a fixed point")
    (end,) = fixed
    below = tidy(end.offset[1] - bob.at[1])
    if tidy(end.offset[0] - bob.at[0]) != 0 or not below.is_positive:
        raise NotAlongALine("the bob does not hang straight below the cord's fixed end")
    x, y = (coords.of(bob.name, k).q for k in ("x", "y"))
    angle = sp.Symbol("theta", real=True)
    on_circle = {x: below * sp.sin(angle), y: below * (1 - sp.cos(angle))}  # displacements from where it hangs
    potential = sum((part.potential(coords) for part in scene.parts), sp.Integer(0)).xreplace(on_circle)
    torque = tidy(-sp.diff(potential, angle))
    stiffness = tidy(-sp.diff(torque, angle).xreplace({angle: 0}))
    if stiffness.is_positive is not True:
        raise NotAlongALine("not hanging at a stable equilibrium")
    moment, omega, period, tau, kappa = (sp.Symbol(n) for n in ("I_P", "omega", "T", "tau", "kappa"))
    about = tidy(bob.mass * below**2)
    steps = (
        Step(f"The {bob.name} moves on a circle about the cord's fixed end: its moment of inertia about that point is",
             (sp.Eq(moment, about),)),
        Step(f"Turned by an angle from where it hangs, the {bob.name} is pulled back by the torque of its weight about "
             "the fixed end (the cord's pull acts along the cord, through that point, and has no moment about it); for "
             "a small angle it is proportional to the angle", (sp.Eq(tau, torque), sp.Eq(tau, -kappa * angle),
                                                              sp.Eq(kappa, stiffness))),
        Step("Newton's second law for the rotation about the fixed end is then that of simple harmonic motion, of "
             "angular frequency and period", (sp.Eq(moment * sp.Symbol("thetaddot"), -kappa * angle),
                                              sp.Eq(omega, sp.sqrt(kappa / moment)),
                                              sp.Eq(omega, tidy(sp.sqrt(stiffness / about))),
                                              sp.Eq(period, 2 * sp.pi / omega))),
    )
    return SmallSwing(steps, tidy(sp.sqrt(stiffness / about)), "the cord's fixed end")


def _rolling_in_a_bowl(scene: Scene, body, contact: Contact) -> SmallSwing:
    """A round body rolling without slipping near the bottom of a bowl, as Taylor (Classical Mechanics, ch. 7)
    and Serway & Jewett (ch. 15) solve it: its center on a circle of radius rho = R - r about the bowl's center,
    at an angle phi from the bottom; Newton's second law along that circle, M rho phi'' = f - M g sin(phi), with
    friction f at the point of contact along it; the torque about the center, I alpha = f r (counter-clockwise
    positive), where not slipping at the contact makes alpha = -rho phi''/r; f eliminated, (M + I/r^2) rho phi''
    = -M g sin(phi) ~ -M g phi.

    >>> from derive.language.problem import load
    >>> from derive.solution.answers import Solution
    >>> solution = Solution(load("ball_in_bowl"))
    >>> R, r, g = (solution.problem.parameters[n].symbol for n in ("R", "r", "g"))
    >>> sp.simplify(small_swing(solution.dynamics_scene, solution.coordinates).omega ** 2 - 5 * g / (7 * (R - r)))
    0
    """
    bowl, radius = scene.surfaces[contact.surface], body.sizes.get("radius")
    if bowl.side != "inside" or bowl.carrier is not None or bowl.turn != 0 or radius is None or scene.loads \
            or scene.gravity is None or body.face_center is not None or contact.carrier is not None \
            or contact.point is not None or contact.center is not None:
        raise NotAlongALine("not a round body rolling in a fixed bowl under gravity alone")
    rho = tidy(bowl.path_radius(radius))
    if tidy(sp.Matrix(body.at) - (bowl.middle - sp.Matrix([0, rho]))) != sp.zeros(2, 1):
        raise NotAlongALine("not placed at the bottom of the bowl")
    mass, g, inertia = body.mass, scene.gravity.g, body.inertia
    phi, phi2, a = sp.Symbol("phi", real=True), sp.Symbol("phiddot"), sp.Symbol("a")
    alpha, f, moment, omega, period = (sp.Symbol(n) for n in ("alpha", "f", "I", "omega", "T"))
    frequency = tidy(sp.sqrt(mass * g / ((mass + inertia / radius**2) * rho)))
    steps = (
        Step(f"The {body.name}'s center moves on a circle about the curve's center; at an angle from the bottom, "
             "Newton's second law along that circle, with the friction at the point of contact along it",
             (sp.Eq(mass * a, f - mass * g * sp.sin(phi)), sp.Eq(a, rho * phi2))),
        Step("The torque about the center, counter-clockwise positive: only friction has a moment about it; "
             f"not slipping at the point of contact, the {body.name} turns the other way, at its center's "
             "acceleration over its radius", (sp.Eq(moment * alpha, f * radius), sp.Eq(alpha, -a / radius),
                                              sp.Eq(moment, inertia))),
        Step("Eliminating the friction, for a small angle the motion is simple harmonic, of angular frequency and "
             "period", (sp.Eq((mass + moment / radius**2) * a, -mass * g * phi),
                        sp.Eq(omega**2, mass * g / ((mass + moment / radius**2) * rho)),
                        sp.Eq(omega, frequency), sp.Eq(period, 2 * sp.pi / omega))),
    )
    return SmallSwing(steps, frequency, "the bottom of the curve")
