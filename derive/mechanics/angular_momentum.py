"""An impact about a fixed axle as a textbook solves it: the angular momentum about the axle is the
same just before and just after, since the axle's impulse has no moment about it.

For a mass m at speed v that sticks to a sphere on an axle, at an impact parameter b, a solution
manual writes one line: m v b = (I + m R^2) omega. The engine solves the impact's impulse equations
(derive.mechanics.impacts); this route states the conservation law and solves it for the one rate
the bodies turn at after the impact, in the sense they turn (so that omega is a magnitude), with the
kinetic energy before and after where the question asks for the loss. What it gives must be what the
impulse equations give (derive.solution.crosschecks).

>>> import sympy as sp
>>> from derive.language.problem import load
>>> from derive.solution.answers import Solution
>>> from derive.solution.textbook import impact_route
>>> route = impact_route(Solution(load("sticky_impact_pivoted")))
>>> route.steps[-1].equations
(Eq(omega, 5*b*m*v/(R**2*(2*M + 5*m))),)
"""
from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import sympy as sp

from derive.core.tidying import leading_plus, tidy
from derive.mechanics.along_motion import NotAlongALine
from derive.text.steps import Step
from derive.mechanics.impacts import outside
from derive.mechanics.lagrange import energies
from derive.model.directions import TURNS
from derive.model.kinematics import Coordinates
from derive.model.scene import Scene
from derive.parts.pin import Pin
from derive.parts.rims import Rims


@dataclass(frozen=True)
class AboutAxle:
    """The steps, and the engine's rates they give (each coordinate's velocity just after)."""

    steps: tuple[Step, ...]
    values: dict[sp.Symbol, sp.Expr]


def about_axle(scene: Scene, coords: Coordinates, before: dict, after: dict, sample: Callable[[sp.Expr], float],
               energy: bool = False) -> AboutAxle:
    """The route for an impact after which the bodies of `scene` (with the joint the impact made) turn
    together about one axle fixed to the ground; `before` and `after` the states' values (the engine's,
    `after` only for the sense of the turn); `energy`: the kinetic energy before and after too."""
    grounded = outside(scene)
    if not grounded or any(not isinstance(p, Pin) for p in grounded):
        raise NotAlongALine("no axle fixed to the ground, or another joint to it")
    at = {c.q: before[c.q] for c in coords.all}
    points = {tuple(tidy(e) for e in coords.position(p.body, p.offset).xreplace(at)) for p in grounded}
    if len(points) != 1:
        raise NotAlongALine("the joints to the ground are not at one point")
    axle = sp.Matrix(points.pop())
    rates = [c.u for c in coords.all]
    conditions = sp.Matrix([v.xreplace(at) for part in scene.constraints for v in part.conditions(coords)])
    free = conditions.jacobian(rates).nullspace(simplify=True) if conditions else []
    if len(free) != 1:
        raise NotAlongALine("the bodies do not turn together after the impact")
    turning = next((c for c in coords.all if c.kind == "theta" and free[0][rates.index(c.u)] != 0), None)
    if turning is None:
        raise NotAlongALine("nothing turns after the impact")
    direction = free[0] / free[0][rates.index(turning.u)]
    sense = 1 if sample(after[turning.u]) > 0 else -1
    omega = sp.Symbol("omega", positive=True)
    moment = tidy(_momentum(scene, coords, at, axle, dict(zip(rates, direction))))
    initial = leading_plus(tidy(sense * _momentum(scene, coords, at, axle, before)))
    L, inertia = sp.Symbol("L"), sp.Symbol("I_axle")
    words = TURNS[0] if sense > 0 else TURNS[1]
    result = leading_plus(tidy(initial / moment))
    steps = [
        Step(f"The only impulse from outside the bodies acts at the axle: its force passes through the axle, so it has "
             f"no moment about it, and the angular momentum about the axle is the same just before and just after "
             f"the impact. Taking {words} as positive, just before it is", (sp.Eq(L, initial),)),
        Step(f"Just after, the bodies turn together about the axle at the rate omega, {words}, with the moment of "
             "inertia about it", (sp.Eq(inertia, moment), sp.Eq(L, inertia * omega))),
        Step("Setting the two equal", (sp.Eq(omega, result),)),
    ]
    values = {u: tidy(sense * result * d) for u, d in zip(rates, direction)}
    if energy:
        kinetic, _ = energies(scene, coords)
        k0, k1 = tidy(kinetic.xreplace(before)), tidy(kinetic.xreplace({**at, **values}))
        steps.append(Step("The kinetic energy just before and just after; the impact takes the difference",
                          (sp.Eq(sp.Symbol("K_0"), k0), sp.Eq(sp.Symbol("K_1"), k1),
                           sp.Eq(sp.Symbol("Delta_K"), tidy(k0 - k1)))))
    return AboutAxle(tuple(steps), values)


def _momentum(scene: Scene, coords: Coordinates, at: dict, axle: sp.Matrix, velocities: dict) -> sp.Expr:
    """The bodies' angular momentum about the axle (counter-clockwise), at the positions `at`."""
    total = sp.Integer(0)
    for body in scene.bodies.values():
        v = [velocities[coords.of(body.name, k).u] for k in ("x", "y")]
        r = coords.position(body.name).xreplace(at) - axle
        total += body.mass * (r[0] * v[1] - r[1] * v[0])
        if body.rotates:
            total += body.inertia * velocities[coords.of(body.name, "theta").u]
    return total


def about_each_axle(scene: Scene, coords: Coordinates, before: dict, grip: Rims, energy: bool = False) -> AboutAxle:
    """The route for two round bodies on fixed axles pressed together at their rims (`grip`, the
    joint the lock made) as a textbook solves it: the rims' friction F acts on each body at the
    contact, the axles' forces through the axles, so over the slipping the angular impulse about each
    axle is its body's change of angular momentum, I_A (w_A' - w_A) = s_A J and I_B (w_B' - w_B) =
    -s_B J with J the friction's impulse on A along the tangent; at the end the rims move together,
    s_A w_A' = s_B w_B'. `energy`: the kinetic energy before and after too."""
    names = (grip.body, grip.to)
    inertia = [scene.bodies[n].inertia for n in names]
    arms = (grip.reach, -grip.to_reach)
    rates = [coords.of(n, "theta").u for n in names]
    after = [sp.Symbol(f"omega_{n}'") for n in names]
    J = sp.Symbol("J")
    impulses = [sp.Eq(i * (w1 - before[u]), arm * J) for i, w1, u, arm in zip(inertia, after, rates, arms)]
    together = sp.Eq(grip.reach * after[0], grip.to_reach * after[1])
    (solved,) = sp.linsolve([*impulses, together], [*after, J])
    found = dict(zip([*after, J], (tidy(v) for v in solved)))
    steps = [
        Step(f"While the rims slip, friction acts on the {names[0]} and the {names[1]} at the contact, equal and "
             "opposite, and each axle's force passes through its axle: about each axle only the friction has a "
             f"moment. With J the friction's impulse on the {names[0]} along the tangent (counter-clockwise about its "
             "axle), the angular impulse about each axle is that body's change of angular momentum", tuple(impulses)),
        Step("At the end the rims move together at the contact: the disks roll on each other, turning opposite ways",
             (together,)),
        Step("Solving the three equations", tuple(sp.Eq(k, v) for k, v in found.items())),
    ]
    values = {c.u: sp.Integer(0) for c in coords.all}
    values.update({u: found[w] for u, w in zip(rates, after)})
    if energy:
        kinetic, _ = energies(scene, coords)
        at = {c.q: before[c.q] for c in coords.all}
        k0, k1 = tidy(kinetic.xreplace(before)), tidy(kinetic.xreplace({**at, **values}))
        steps.append(Step("The kinetic energy just before and once the rims move together; the friction takes the "
                          "difference", (sp.Eq(sp.Symbol("K_0"), k0), sp.Eq(sp.Symbol("K_1"), k1),
                                         sp.Eq(sp.Symbol("Delta_K"), tidy(k0 - k1)))))
    return AboutAxle(tuple(steps), values)
