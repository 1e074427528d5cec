"""Impacts in a state of a scene: a point mass that sticks to a body (a bullet into a hanging
rod, a child jumping onto a turntable), a body that sticks to another, two turning bodies that
lock together (a clutch, a disk dropped onto another), a point mass that bounces off a body
with a coefficient of restitution (a ball off the end of a hanging rod).

The impact makes a joint (`joint`): a pin holding the point mass where it struck, a weld, a
clutch, or for a bounce a smooth touch along the normal that lasts the instant only (its
normal rate after is -e times the one before). In the instant of the impact the configuration q* does not change, and forces that stay
finite (weights, springs, given loads) give no impulse: only the joints' forces do, the new one
and those already there (a hinge's). The velocities just after, u+, are solved by two routes
from the velocities just before, u- (`impact`):

- Lagrange: the generalized momentum dT/du jumps by the joints' generalized impulses,
  dT/du(u+) - dT/du(u-) = sum_j J_j dg_j/dq at q*, and every gap's rate is zero after,
  dg_j/dq . u+ = 0 (each J_j the impulse of the force g_j's multiplier is);
- Newton–Euler: impulse and momentum of each body, m (v+ - v-) = sum J and
  I (omega+ - omega-) = sum r x J (+ the couples' impulses), the impulses those of the parts'
  forces at their points, and the parts' velocity conditions after.

Kinetic energy is not conserved in such an impact: `energy_lost` is the ledger's entry.

>>> import sympy as sp
>>> from derive.mechanics.kinematics import Coordinates
>>> from derive.parts.pin import Pin
>>> from derive.scene import Body, Event, Scene
>>> m, M, L, v = sp.symbols("m M L v", positive=True)
>>> rod = Body("rod", "rod", M, {"length": L}, M * L**2 / 12, at=(0, -L / 2), angle=-sp.pi / 2)
>>> bullet = Body("bullet", "point", m, {}, at=(0, -L))
>>> scene = Scene({"rod": rod, "bullet": bullet}, (Pin("hinge", "rod", (-L / 2, 0)),))
>>> coords = Coordinates(scene)
>>> before = {**{s: 0 for s in coords.state}, coords.of("bullet", "x").u: v}
>>> hit = joint(scene, coords, before, Event("stick", "bullet", "rod"), "hit")
>>> after = Scene(scene.bodies, scene.constraints + (hit,))
>>> impact(after, coords, before, "lagrange").velocities[coords.of("rod", "theta").u]
3*m*v/(L*(M + 3*m))
"""
from __future__ import annotations

from dataclasses import dataclass

import sympy as sp

from derive.mechanics.derivation import Step, solve_linear, tidy
from derive.mechanics.kinematics import Coordinates
from derive.mechanics.lagrange import energies
from derive.parts import AppliedForce, AppliedTorque, Part, Sign
from derive.parts.clutch import Clutch
from derive.parts.pin import Pin
from derive.parts.weld import Weld
from derive.scene import Event, Scene


@dataclass(frozen=True)
class Touch(Part):
    """A point mass `body` striking `to`'s material point at `to_offset` (its frame) along the
    world direction `normal` (from `to` toward the point mass), smooth: for the instant of a
    bounce only. Lagrange: the gap n . (P_body - P_to); Newton–Euler: the impulse J n on the
    point mass, -J n on the other body there; their normal velocities."""

    name: str
    body: str
    to: str
    to_offset: tuple[sp.Expr, sp.Expr]
    normal: tuple[sp.Expr, sp.Expr]

    def bodies(self) -> tuple[str, ...]:
        return (self.body, self.to)

    def unknowns(self) -> dict[str, sp.Symbol]:
        return {"impulse": sp.Symbol(f"J^{self.name}", real=True)}

    def gaps(self, coords) -> list[sp.Expr]:
        return [sp.Matrix(self.normal).dot(coords.position(self.body) - coords.position(self.to, self.to_offset))]

    def loads(self, coords) -> list[AppliedForce]:
        push = self.unknowns()["impulse"] * sp.Matrix(self.normal)
        label = f"impact {self.name}"
        return [AppliedForce(self.body, sp.zeros(2, 1), push, label),
                AppliedForce(self.to, coords.rotated(self.to, self.to_offset), -push, label)]

    def conditions(self, coords) -> list[sp.Expr]:
        there = coords.velocity(self.to, coords.rotated(self.to, self.to_offset))
        return [sp.Matrix(self.normal).dot(coords.velocity(self.body, sp.zeros(2, 1)) - there)]

    def signs(self) -> list[Sign]:
        return [Sign(self.unknowns()["impulse"], f"the {self.body} would pull on the {self.to} in the bounce (they "
                                                 "are not moving toward each other)")]


class ImpactError(ValueError):
    """An impact this module cannot solve (an engine limit: a sliding contact's friction)."""


@dataclass(frozen=True)
class Impact:
    """One route's velocities just after the impact (every coordinate's u), the joints' impulses
    (by their forces' symbols), and the steps that found them."""

    velocities: dict[sp.Symbol, sp.Expr]
    impulses: dict[sp.Symbol, sp.Expr]
    steps: tuple[Step, ...]


def joint(scene: Scene, coords: Coordinates, values: dict, event: Event, name: str, decide=None) -> Part:
    """The joint an impact (derive.scene.Event) makes as the bodies are in the state
    `values`: a clutch (`lock`, at the turn between them then); for `stick` a pin holding a point
    mass where it is on the other body, or a weld of two turning bodies; for `bounce` the touch
    of a point mass on the other body, for the instant (along the rod's normal, or a round
    body's radius).

    Raises ValueError where two point masses that are apart would stick (a particle has no frame
    to hold another in), or a bounce has no normal derive knows. `decide` (an expression's value
    at the middle of the ranges) turns a rod's normal toward the side the point mass comes from."""
    kind, body, to = event.kind, event.body, event.to
    at = {c.q: values[c.q] for c in coords.all}

    def turn(a: str, b: str) -> sp.Expr:
        return tidy((coords.angle(a) - coords.angle(b)).xreplace(at))

    if kind == "lock":
        return Clutch(name, body, to, turn(body, to))
    point, host = (body, to) if not scene.bodies[body].rotates else (to, body)
    between = (coords.position(point) - coords.position(host)).xreplace(at)
    angle = -coords.orientation(host).xreplace(at)
    offset = tuple(tidy(e) for e in sp.Matrix([[sp.cos(angle), -sp.sin(angle)], [sp.sin(angle), sp.cos(angle)]])
                   * between)
    if kind == "bounce":
        touch = _touch(scene, coords, at, name, point, host, offset)
        approach = touch.conditions(coords)[0].xreplace(values)  # negative while they close in
        if decide is not None and scene.bodies[host].shape == "rod" and decide(approach) > 0:
            touch = Touch(name, point, host, offset, tuple(-e for e in touch.normal))
        return touch
    if not scene.bodies[point].rotates:
        if not scene.bodies[host].rotates and any(e != 0 for e in offset):
            raise ValueError(f"the {point} and the {to if point == body else body} are point masses apart from "
                             "each other: they can stick only where they touch")
        return Pin(name, point, (sp.Integer(0), sp.Integer(0)), host, offset)
    return Weld(name, point, host, offset, turn(point, host))


def _touch(scene: Scene, coords: Coordinates, at: dict, name: str, point: str, host: str, offset) -> Touch:
    """The touch of a bounce: a point mass on a rod's axis (normal across the rod) or on a round
    body's rim (normal along the radius)."""
    if scene.bodies[point].rotates:
        raise ValueError("a bounce is of a point mass off a body (or a body off a point mass)")
    shape = scene.bodies[host]
    if "radius" in shape.sizes:
        out = sp.Matrix(coords.rotated(host, offset)).xreplace(at)
        normal = out / sp.sqrt(out.dot(out))
    elif shape.shape == "rod":
        angle = coords.orientation(host).xreplace(at)
        normal = sp.Matrix([-sp.sin(angle), sp.cos(angle)])
    else:
        raise ValueError(f"a bounce off a {shape.shape}: the normal is known for round bodies and rods")
    return Touch(name, point, host, offset, tuple(tidy(e) for e in normal))


def impact(scene: Scene, coords: Coordinates, before: dict, route: str, bounce: tuple = ()) -> Impact:
    """The velocities just after an impulsive change in `scene` (the scene after the impact, with
    the joint it made), from the state `before` (every coordinate and velocity), by `route`
    ("lagrange" or "newton_euler"; see the module). `bounce` (a Touch of the scene, the
    coefficient of restitution e): its normal rate after is -e times the one before, not zero."""
    at = {c.q: before[c.q] for c in coords.all}
    forces = [f for part in scene.constraints for f in part.unknowns().values()]
    power = sum((part.power(coords) for part in scene.parts), sp.Integer(0))
    if power.free_symbols & set(forces):
        raise ImpactError("solve an impact with a sliding contact's friction (its impulse depends on the normal one)")
    if route == "lagrange":
        equations, text = _momenta(scene, coords, before, at, bounce), (
            "In the impact the configuration does not change and only the joints' forces give impulses: the "
            "generalized momenta jump by the joints' generalized impulses, and the joints hold after (each force's "
            "symbol stands for its impulse)")
    else:
        equations, text = _impulses(scene, coords, before, at, bounce), (
            "Impulse and momentum of each body in the impact: only the joints' forces give impulses, and the joints "
            "hold after (each force's symbol stands for its impulse)")
    unknowns = [c.u for c in coords.all] + forces
    solution = solve_linear(equations, unknowns)
    velocities = {c.u: tidy(solution.raw[c.u]) for c in coords.all}
    impulses = {f: tidy(solution.raw[f]) for f in forces}
    steps = (Step(text, tuple(equations)),
             Step("Just after the impact", tuple(sp.Eq(u, v) for u, v in velocities.items() if v != 0)))
    return Impact(velocities, impulses, steps)


def _after(rate: sp.Expr, part: Part, coords: Coordinates, before: dict, at: dict, bounce: tuple) -> sp.Eq:
    """A joint's rate just after the impact: zero, or for the bounce -e times the one before."""
    rate = rate.xreplace(at)
    if not bounce or part is not bounce[0]:
        return sp.Eq(rate, 0)
    return sp.Eq(rate, -bounce[1] * rate.xreplace({c.u: before[c.u] for c in coords.all}))


def _momenta(scene: Scene, coords: Coordinates, before: dict, at: dict, bounce: tuple) -> list[sp.Eq]:
    kinetic, _ = energies(scene, coords)
    earlier = {c.u: before[c.u] for c in coords.all}
    gaps = [(part, f, g) for part in scene.constraints for f, g in zip(part.unknowns().values(), part.gaps(coords))]
    equations = []
    for c in coords.all:
        momentum = sp.diff(kinetic, c.u)
        impulse = sum((f * sp.diff(g, c.q) for _, f, g in gaps), sp.Integer(0))
        equations.append(sp.Eq((momentum - momentum.xreplace(earlier)).xreplace(at), impulse.xreplace(at)))
    return equations + [_after(coords.ddt(g), part, coords, before, at, bounce) for part, _, g in gaps]


def _impulses(scene: Scene, coords: Coordinates, before: dict, at: dict, bounce: tuple) -> list[sp.Eq]:
    loads = []
    for part in scene.constraints:
        unknowns = list(part.unknowns().values())
        for load in part.loads(coords):
            size = load.force if isinstance(load, AppliedForce) else sp.Matrix([load.torque])
            impulsive = sp.Matrix([sum((f * sp.diff(e, f) for f in unknowns), sp.Integer(0)) for e in size])
            if any(tidy(e) != 0 for e in size - impulsive):
                raise ImpactError(f"solve an impact where the {part.name}'s force is not in proportion to its unknowns")
            loads.append(load)
    equations = []
    for body in scene.bodies.values():
        on_body = [f for f in loads if f.body == body.name]
        pushes = [f for f in on_body if isinstance(f, AppliedForce)]
        total = sum((f.force for f in pushes), sp.zeros(2, 1))
        for i, kind in enumerate(("x", "y")):
            u = coords.of(body.name, kind).u
            equations.append(sp.Eq(body.mass * (u - before[u]), total[i].xreplace(at)))
        if body.rotates:
            u = coords.of(body.name, "theta").u
            moment = sum((f.offset[0] * f.force[1] - f.offset[1] * f.force[0] for f in pushes), sp.Integer(0))
            moment += sum((f.torque for f in on_body if isinstance(f, AppliedTorque)), sp.Integer(0))
            equations.append(sp.Eq(body.inertia * (u - before[u]), moment.xreplace(at)))
    return equations + [_after(v, part, coords, before, at, bounce)
                        for part in scene.constraints for v in part.conditions(coords)]


def energy_lost(scene: Scene, coords: Coordinates, before: dict, after: dict) -> sp.Expr:
    """The kinetic energy the impact takes (before minus after), factored."""
    kinetic, _ = energies(scene, coords)
    return tidy(kinetic.xreplace(before) - kinetic.xreplace(after))


def conserved(scene: Scene, coords: Coordinates, before: dict, after: dict) -> Step | None:
    """The momentum the impact keeps, as a text names it, with its value before and after. The
    joints between bodies give equal and opposite impulses at one point (or couples), so only the
    ground's matter: with none, the total momentum and the angular momentum about the origin; with
    pins to the ground all at one point (a hinge, an axle), the angular momentum about it; with
    another joint to the ground (a floor, a weld), none is named (None)."""
    grounded = [p for p in scene.constraints if len(p.bodies()) == 1]
    if any(not isinstance(p, Pin) or p.to is not None for p in grounded):
        return None
    at = {c.q: before[c.q] for c in coords.all}
    points = {tuple(tidy(e) for e in coords.position(p.body, p.offset).xreplace(at)) for p in grounded}
    if len(points) > 1:
        return None
    about = sp.Matrix(points.pop()) if points else sp.zeros(2, 1)

    def momenta(state: dict) -> tuple[sp.Expr, sp.Expr, sp.Expr]:
        p, angular = sp.zeros(2, 1), sp.Integer(0)
        for body in scene.bodies.values():
            v = sp.Matrix([state[coords.of(body.name, k).u] for k in ("x", "y")])
            r = coords.position(body.name).xreplace(at) - about
            p += body.mass * v
            angular += body.mass * (r[0] * v[1] - r[1] * v[0])
            if body.rotates:
                angular += body.inertia * state[coords.of(body.name, "theta").u]
        return tidy(p[0]), tidy(p[1]), tidy(angular)

    (px0, py0, l0), (px1, py1, l1) = momenta(before), momenta(after)
    L, px, py = sp.Symbol("L_O"), sp.Symbol("p_x"), sp.Symbol("p_y")  # L_O: not the length L
    if grounded:
        where = f"about the pin at {sp.sstr(tuple(about))}, where the only impulse from outside acts"
        return Step(f"Check: the angular momentum {where}, before and after", (sp.Eq(L, l0), sp.Eq(L, l1)))
    return Step("Check: no impulse from outside, so the momentum and the angular momentum about the origin, before "
                "and after", (sp.Eq(px, px0), sp.Eq(px, px1), sp.Eq(py, py0), sp.Eq(py, py1), sp.Eq(L, l0),
                              sp.Eq(L, l1)))
