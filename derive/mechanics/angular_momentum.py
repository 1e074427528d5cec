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
>>> route = Solution(load("sticky_impact_pivoted")).textbook_route
>>> list(route.sections.values())[0][-1].equations
(Eq(omega, 5*b*m*v/(R**2*(2*M + 5*m))),)
"""
from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field

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
from derive.parts.weld import Weld


@dataclass(frozen=True)
class AboutAxle:
    """The steps, the engine's rates they give (each coordinate's velocity just after), and what they
    find by name: omega (the rate just after, a magnitude), K0 and K1 (the kinetic energy before and
    after) and lost (their difference, positive), V_x and V_y (the center of mass's velocity after).
    `rates`: where the route finds each body's own rate (the rims' two disks), that rate by the body's
    name, signed counter-clockwise; an ask of that body's angular velocity is compared with it."""

    steps: tuple[Step, ...]
    values: dict[sp.Symbol, sp.Expr]
    found: dict[str, sp.Expr]
    rates: dict[str, sp.Expr] = field(default_factory=dict)


def about_axle(scene: Scene, coords: Coordinates, before: dict, after: dict, sample: Callable[[sp.Expr], float],
               energy: bool = False, impulse: tuple[str, ...] = ()) -> AboutAxle:
    """The route for an impact after which the bodies of `scene` (with the joint the impact made) turn
    together about one axle fixed to the ground; `before` and `after` the states' values (the engine's,
    `after` only for the sense of the turn); `energy`: the kinetic energy before and after too;
    `impulse`: the axle's impulse's components ("x", "y") too, the change of the bodies' momentum."""
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
    found = {"I_axle": moment}
    steps = [
        Step(f"The only impulse from outside the bodies acts at the axle: its force passes through the axle, so it has "
             f"no moment about it, and the angular momentum about the axle is the same just before and just after "
             f"the impact. Taking {words} as positive, just before it is", (sp.Eq(L, initial),)),
        Step(f"Just after, the bodies turn together about the axle at the rate omega, {words}, with the moment of "
             "inertia about it", (sp.Eq(inertia, moment), sp.Eq(L, inertia * omega))),
        Step("Setting the two equal", (sp.Eq(omega, result),)),
    ]
    values = {u: tidy(sense * result * d) for u, d in zip(rates, direction)}
    found["omega"] = result
    if energy:
        steps.append(_energy_taken(scene, coords, before, {**at, **values}, found))
    if impulse:
        steps.append(_axle_impulse(scene, coords, before, values, found, impulse))
    return AboutAxle(tuple(steps), values, found)


def _axle_impulse(scene: Scene, coords: Coordinates, before: dict, after: dict, found: dict, axes: tuple[str, ...]) -> Step:
    """The axle's impulse, the one from outside: the change of the bodies' momentum, J = p' - p, in the
    `axes` asked (Serway & Jewett ch. 9, impulse and momentum), each kept in `found` as J_x, J_y."""
    equations = []
    for axis in axes:
        change = sum((b.mass * (after[coords.of(b.name, axis).u] - before[coords.of(b.name, axis).u])
                      for b in scene.bodies.values()), sp.Integer(0))
        found[f"J_{axis}"] = tidy(change)
        equations.append(sp.Eq(sp.Symbol(f"J_{axis}"), found[f"J_{axis}"]))
    return Step("The axle's impulse is the only one from outside the bodies, so it is the change of their momentum, "
                "just after less just before, along " + " and ".join(axes), tuple(equations))


def about_center_of_mass(scene: Scene, coords: Coordinates, before: dict, after: dict,
                         sample: Callable[[sp.Expr], float], energy: bool = False) -> AboutAxle:
    """The route for an impact of free bodies (no joint to the ground) after which they move as one
    rigid body: no outside impulse, so the momentum is the same just before and just after, and so is
    the angular momentum about the point where their center of mass is as they meet (Kleppner &
    Kolenkow 2nd ed., ch. 7: a bullet that sticks to a free rod). `before`, `after` and `energy` as
    for `about_axle`."""
    if outside(scene) or any(not isinstance(p, (Pin, Weld)) for p in scene.constraints):
        raise NotAlongALine("a joint to the ground, or a joint that is not rigid")
    at = {c.q: before[c.q] for c in coords.all}
    rates = [c.u for c in coords.all]
    conditions = sp.Matrix([v.xreplace(at) for part in scene.constraints for v in part.conditions(coords)])
    if len(conditions.jacobian(rates).nullspace(simplify=True)) != 3:
        raise NotAlongALine("the bodies do not move as one rigid body after the impact")
    bodies = list(scene.bodies.values())
    total = sum((b.mass for b in bodies), sp.Integer(0))
    places = {b.name: coords.position(b.name).xreplace(at) for b in bodies}
    center = (sum((b.mass * places[b.name] for b in bodies), sp.zeros(2, 1)) / total).applyfunc(tidy)
    velocity = {b.name: sp.Matrix([before[coords.of(b.name, k).u] for k in ("x", "y")]) for b in bodies}
    momentum = sum((b.mass * velocity[b.name] for b in bodies), sp.zeros(2, 1)).applyfunc(tidy)
    turning = [b for b in bodies if b.rotates]
    if not turning:
        raise NotAlongALine("nothing turns after the impact")
    spin = coords.of(turning[0].name, "theta").u
    sense = 1 if sample(after[spin]) > 0 else -1
    arms = {b.name: places[b.name] - center for b in bodies}
    initial = sum((b.mass * (arms[b.name][0] * velocity[b.name][1] - arms[b.name][1] * velocity[b.name][0])
                   + (b.inertia * before[coords.of(b.name, "theta").u] if b.rotates else 0) for b in bodies),
                  sp.Integer(0))
    initial = leading_plus(tidy(sense * initial))
    inertia = sum((b.mass * arms[b.name].dot(arms[b.name]) + (b.inertia if b.rotates else 0) for b in bodies),
                  sp.Integer(0))
    omega, L, I_cm = sp.Symbol("omega", positive=True), sp.Symbol("L"), sp.Symbol("I_cm")
    result = leading_plus(tidy(initial / tidy(inertia)))
    shift = {k: tidy(momentum[i] / total) for i, k in enumerate("xy")}
    words = TURNS[0] if sense > 0 else TURNS[1]
    axes = [i for i in range(2) if momentum[i] != 0] or [0]
    places_said = [sp.Eq(sp.Symbol(f"{'xy'[i]}_cm"), center[i]) for i in range(2) if center[i] != 0]
    steps = [
        Step("No impulse from outside acts on the bodies: their momentum is the same just before and just after the "
             "impact, and their center of mass moves on at", tuple(
                 e for i in axes for e in (sp.Eq(sp.Symbol(f"p_{'xy'[i]}"), momentum[i]),
                                           sp.Eq(sp.Symbol(f"V_{'xy'[i]}"), shift["xy"[i]])))),
        Step("Nor has any outside impulse a moment about the point where their center of mass is as they meet (placed "
             "below in the figure's axes), so the angular momentum about that point is the same just before and just "
             f"after. Taking {words} as positive, just before it is", (*places_said, sp.Eq(L, initial))),
        Step(f"Just after, the bodies turn together at the rate omega, {words}, about their center of mass, with their "
             "moment of inertia about it (each body's own, and its mass times the square of its distance, by the "
             "parallel-axis theorem)", (sp.Eq(I_cm, tidy(inertia)), sp.Eq(L, I_cm * omega))),
        Step("Setting the two equal", (sp.Eq(omega, result),)),
    ]
    w = sense * result
    values = {}
    for b in bodies:
        arm = arms[b.name]
        values[coords.of(b.name, "x").u] = tidy(shift["x"] - w * arm[1])
        values[coords.of(b.name, "y").u] = tidy(shift["y"] + w * arm[0])
        if b.rotates:
            values[coords.of(b.name, "theta").u] = tidy(w)
    found = {"omega": result, "V_x": shift["x"], "V_y": shift["y"]}
    if energy:
        steps.append(_energy_taken(scene, coords, before, {**at, **values}, found))
    return AboutAxle(tuple(steps), values, found)


def slowed_to_rest(found: dict, torque: sp.Expr, words: str) -> tuple[Step, ...]:
    """After an impact about an axle (`found`: its omega, the inertia I_axle about the axle), a
    constant `torque` against the turning stops the bodies: Newton's second law for the rotation
    about the axle, then the time and the angle at the constant deceleration (found: t, turn)."""
    inertia, alpha, t, turn = sp.Symbol("I_axle"), sp.Symbol("alpha", positive=True), sp.Symbol("t"), sp.Symbol("theta")
    deceleration = tidy(torque / found["I_axle"])
    found.update(t=tidy(found["omega"] / deceleration), turn=tidy(found["omega"]**2 / (2 * deceleration)))
    return (Step(f"Newton's second law for the rotation about the axle: the only torque about it is the one against "
                 f"the turning (the axle's force has no moment about it), so the bodies slow at a constant angular "
                 f"deceleration, turning {words}", (sp.Eq(inertia * alpha, torque), sp.Eq(alpha, deceleration))),
            Step("From the rate omega to rest at that constant deceleration: the time, and the angle theta it turns through",
                 (sp.Eq(t, found["t"]), sp.Eq(turn, found["turn"])), role="solve"))


def _energy_taken(scene: Scene, coords: Coordinates, before: dict, after: dict, found: dict) -> Step:
    """The kinetic energy just before and just after, and the energy the impact takes (positive)."""
    kinetic, _ = energies(scene, coords)
    found.update(K0=tidy(kinetic.xreplace(before)), K1=tidy(kinetic.xreplace(after)))
    found["lost"] = tidy(found["K0"] - found["K1"])
    K0, K1 = sp.Symbol("K_0"), sp.Symbol("K_1")
    return Step("The kinetic energy just before and just after; the kinetic energy the impact takes is the difference",
                (sp.Eq(K0, found["K0"]), sp.Eq(K1, found["K1"]), sp.Eq(K0 - K1, found["lost"])))


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
    after = [sp.Symbol(f"omega_{k}'") for k in (1, 2)]  # numbered as the names give them: no file key in the text
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
    own = {n: found[w] for n, w in zip(names, after)}
    if energy:
        kinetic, _ = energies(scene, coords)
        at = {c.q: before[c.q] for c in coords.all}
        k0, k1 = tidy(kinetic.xreplace(before)), tidy(kinetic.xreplace({**at, **values}))
        steps.append(Step("The kinetic energy just before and once the rims move together; the friction takes the "
                          "difference", (sp.Eq(sp.Symbol("K_0"), k0), sp.Eq(sp.Symbol("K_1"), k1),
                                         sp.Eq(sp.Symbol("Delta_K"), tidy(k0 - k1)))))
        return AboutAxle(tuple(steps), values, {"K0": k0, "K1": k1, "lost": tidy(k0 - k1)}, own)
    return AboutAxle(tuple(steps), values, {}, own)
