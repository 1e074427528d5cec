"""Impacts in a state of a scene: a point mass that sticks to a body (a bullet into a hanging
rod, a child jumping onto a turntable), a body that sticks to another, two turning bodies that
lock together (a clutch, a disk dropped onto another), a point mass or a round body that
bounces off a body with a coefficient of restitution (a ball off the end of a hanging rod, a
puck off a free rod or another puck), a round body or a point mass that bounces off a fixed
surface (a ball off a floor).

The impact makes a joint (`joint`): a pin holding the point mass where it struck, a weld, a
clutch, or for a bounce a touch that lasts the instant only (`Bounce`: its normal rate after is
-e times the one before). A rough touch also takes a tangential impulse J_t: it grips (the
contact point's tangential rate is zero after) where that needs |J_t| <= mu J_n, else it
slides throughout with J_t = mu J_n the way the grip's would point, the regime decided per
variant (a Piecewise; `regime_conditions` refuses a variant where the slip would reverse). In the instant of the impact the configuration q* does not change, and forces that stay
finite (weights, springs, given loads) give no impulse: only the joints' forces do, the new one
and those already there (a hinge's). The velocities just after, u+, are solved by two routes
from the velocities just before, u- (`impact`):

- Lagrange: the generalized momentum dT/du jumps by the joints' generalized impulses,
  dT/du(u+) - dT/du(u-) = sum_j J_j dg_j/dq at q*, and every gap's rate is zero after,
  dg_j/dq . u+ = 0 (each J_j the impulse of the force g_j's multiplier is);
- Newton–Euler: impulse and momentum of each body, m (v+ - v-) = sum J and
  I (omega+ - omega-) = sum r x J (+ the couples' impulses), the impulses those of the parts'
  forces at their points, and the parts' velocity conditions after.

A sliding touch closes either route with J_t = +-mu J_n in place of its tangential rate.

Kinetic energy is not conserved in such an impact: `energy_lost` is the ledger's entry.

>>> import sympy as sp
>>> from derive.model.kinematics import Coordinates
>>> from derive.parts.pin import Pin
>>> from derive.model.scene import Body, Event, Scene
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

import dataclasses
from dataclasses import dataclass

import sympy as sp

from derive.mechanics.derivation import solve_linear
from derive.text.steps import Step
from derive.core.tidying import tidy
from derive.model.kinematics import Coordinates
from derive.mechanics.lagrange import energies
from derive.parts import AppliedForce, AppliedTorque, Part, Sign, titled
from derive.parts.clutch import Clutch
from derive.parts.pin import Pin
from derive.parts.rims import Rims
from derive.parts.weld import Weld
from derive.text.prose import Sentence
from derive.model.scene import Event, Scene


@dataclass(frozen=True)
class Touch(Part):
    """`body`'s material point at `body_offset` (its frame) striking `to`'s at `to_offset` (its
    frame; with `to` None, a point of the ground, on the fixed `surface`) along the world
    direction `normal` (from `to` toward `body`): for the instant of a bounce only. Smooth, the
    impulse J n on `body` and -J n on `to` there; `rough`, also J_t t along t = (n_y, -n_x).
    Lagrange: the gaps n . (P_body - P_to) and t . (P_body - P_to); Newton–Euler: the impulses
    at the points; their normal (and tangential) relative velocities."""

    name: str
    body: str
    to: str | None
    to_offset: tuple[sp.Expr, sp.Expr]
    normal: tuple[sp.Expr, sp.Expr]
    body_offset: tuple[sp.Expr, sp.Expr] = (sp.Integer(0), sp.Integer(0))
    rough: bool = False
    surface: str | None = None

    def bodies(self) -> tuple[str, ...]:
        return (self.body,) if self.to is None else (self.body, self.to)

    @property
    def title(self) -> str:
        return f"the bounce {self.name}"

    def unknowns(self) -> dict[str, sp.Symbol]:
        impulse = {"impulse": sp.Symbol(f"J^{self.name}", real=True)}
        return {**impulse, "friction": sp.Symbol(f"J_t^{self.name}", real=True)} if self.rough else impulse

    def _directions(self) -> list[sp.Matrix]:
        n = sp.Matrix(self.normal)
        return [n, sp.Matrix([n[1], -n[0]])][:2 if self.rough else 1]

    def gaps(self, coords) -> list[sp.Expr]:
        apart = coords.position(self.body, self.body_offset) - coords.position(self.to, self.to_offset)
        return [d.dot(apart) for d in self._directions()]

    def loads(self, coords) -> list[AppliedForce]:
        push = sum((f * d for f, d in zip(self.unknowns().values(), self._directions())), sp.zeros(2, 1))
        label = f"impact {self.name}"
        result = [AppliedForce(self.body, coords.rotated(self.body, self.body_offset), push, label)]
        if self.to is not None:
            result.append(AppliedForce(self.to, coords.rotated(self.to, self.to_offset), -push, label))
        return result

    def conditions(self, coords) -> list[sp.Expr]:
        here = coords.velocity(self.body, coords.rotated(self.body, self.body_offset))
        there = coords.velocity(self.to, coords.rotated(self.to, self.to_offset)) if self.to else sp.zeros(2, 1)
        return [d.dot(here - there) for d in self._directions()]

    def sentences(self, route: str, coords) -> list[Sentence]:
        """Words and symbols only: an impact happens where a state has the bodies, not at the placement."""
        f = self.unknowns()
        other = f"the {self.to}" if self.to is not None else f"the {self.surface}"
        rough = (", and along it by the impulse of friction ", f["friction"]) if self.rough else ()
        if route == "lagrange":
            return [Sentence((f"In the bounce {self.name} the {self.body} strikes {other}: the gap between the two points "
                              "along the normal is held by the multiplier ", f["impulse"], ", the impulse", *rough, "."))]
        result = [Sentence((f"The bounce {self.name} gives the {self.body} the impulse ", f["impulse"], " along the normal "
                            "at the point that strikes", *rough, "."), self.body)]
        if self.to is not None:
            result.append(Sentence((f"It gives the {self.to} the opposite impulse at the point struck.",), self.to))
        return result + [Sentence((f"Just after the bounce {self.name} the two points separate at the rate the "
                                   "restitution sets.",))]

    def signs(self) -> list[Sign]:
        return [Sign(self.unknowns()["impulse"], f"the {self.body} would pull on the {self.to or self.surface} in "
                                                 "the bounce (they are not moving toward each other)",
                     f"the {self.body} does not touch the {self.to or self.surface}", "its impulse")]


@dataclass(frozen=True)
class Bounce:
    """How a bounce's `touch` ends: its normal rate after is -`restitution` times the one before;
    a rough touch's tangential rate is zero (it grips), or with `friction` (mu for the grip, mu
    for the slide) zero where that needs at most mu J_n, else it slides (`slides`: one regime's
    J_t / J_n, +-mu, which `impact` sets)."""

    touch: Touch
    restitution: sp.Expr
    friction: tuple[sp.Expr, sp.Expr] | None = None
    slides: sp.Expr | None = None


class ImpactError(ValueError):
    """An impact this module cannot solve (an engine limit: a sliding contact's friction)."""


@dataclass(frozen=True)
class Impact:
    """One route's velocities just after the impact (every coordinate's u), the joints' impulses
    (by their forces' symbols), and the steps that found them; for a rough bounce that grips or
    slides, each a Piecewise over its `regimes`."""

    velocities: dict[sp.Symbol, sp.Expr]
    impulses: dict[sp.Symbol, sp.Expr]
    steps: tuple[Step, ...]
    regimes: tuple[Regime, ...] = ()


@dataclass(frozen=True)
class Regime:
    """A rough bounce's regime: `name`, where it holds (`where`, given those before it do not),
    the `direction` of its sliding friction along t (0: it grips), and its `impact`."""

    name: str
    where: sp.Basic
    direction: int
    impact: Impact


def joint(scene: Scene, coords: Coordinates, values: dict, event: Event, name: str, decide=None) -> Part:
    """The joint an impact (derive.model.scene.Event) makes as the bodies are in the state
    `values`: a clutch (`lock`, at the turn between them then); for `stick` a pin holding a point
    mass where it is on the other body, or a weld of two turning bodies; for `bounce` the touch
    of a point mass or a round body's rim on the other body, for the instant (along the rod's
    normal, or the line of centers), or of a body on a fixed surface (`to` names one of the
    scene's surfaces).

    Raises ValueError where two point masses that are apart would stick (a particle has no frame
    to hold another in), a round body that bounces does not touch the other, or a bounce has no
    normal derive knows. `decide` (an expression's value
    at the middle of the ranges) turns a rod's normal toward the side the point mass comes from."""
    kind, body, to = event.kind, event.body, event.to
    at = {c.q: values[c.q] for c in coords.all}
    rough = event.grips or event.friction is not None

    def turn(a: str, b: str) -> sp.Expr:
        return tidy((coords.angle(a) - coords.angle(b)).xreplace(at))

    if kind == "lock" and event.rims:
        return _rims(scene, coords, at, name, body, to)
    if kind == "lock":
        return Clutch(name, body, to, turn(body, to))
    if kind == "bounce" and to not in scene.bodies:
        return _on_surface(scene, coords, at, name, body, to, rough)
    if kind == "bounce":
        return _bounce(scene, coords, values, name, body, to, rough, decide)
    point, host = (body, to) if not scene.bodies[body].rotates else (to, body)
    offset = _in_frame(-coords.orientation(host).xreplace(at),
                       (coords.position(point) - coords.position(host)).xreplace(at))
    if not scene.bodies[point].rotates:
        if not scene.bodies[host].rotates and any(e != 0 for e in offset):
            raise ValueError(f"the {point} and the {to if point == body else body} are point masses apart from "
                             "each other: they can stick only where they touch")
        return Pin(name, point, (sp.Integer(0), sp.Integer(0)), host, offset)
    return Weld(name, point, host, offset, turn(point, host))


def _in_frame(angle: sp.Expr, vector: sp.Matrix) -> tuple[sp.Expr, sp.Expr]:
    """A world vector turned through `angle`: in the frame of a body at -angle, as its offsets are."""
    return tuple(tidy(e) for e in sp.Matrix([[sp.cos(angle), -sp.sin(angle)], [sp.sin(angle), sp.cos(angle)]])
                 * vector)


def _on_surface(scene: Scene, coords: Coordinates, at: dict, name: str, body: str, surface: str,
                rough: bool) -> Touch:
    """The touch of a bounce on a fixed surface: the body's point nearest it (a round body's rim
    below its center, a point mass itself) on the surface's point there, along its normal."""
    plane = scene.surfaces[surface]
    if plane.carrier is not None:
        raise ImpactError(f"solve a bounce off {surface}, which the {plane.carrier} carries (a bounce is off a fixed "
                          "surface or off a body)")
    shape = scene.bodies[body]
    if shape.rotates and "radius" not in shape.sizes:
        raise ValueError(f"a bounce off a surface is of a round body or a point mass: where a {shape.shape} touches "
                         f"{surface} is not known")
    radius = shape.sizes.get("radius", sp.Integer(0))
    center = coords.position(body).xreplace(at)
    if tidy(plane.gap(center, radius)) != 0:
        raise ValueError(f"the {body} does not touch {surface} where it is in the state it bounces in (it stands "
                         f"{sp.sstr(tidy(plane.gap(center, radius)))} off it): place it touching")
    normal = sp.Matrix([tidy(e) for e in plane.normal_at(center, radius)])
    offset = _in_frame(-coords.orientation(body).xreplace(at), -radius * normal)
    return Touch(name, body, None, tuple(tidy(e) for e in center - radius * normal), tuple(normal), offset, rough,
                 surface)


def _rims(scene: Scene, coords: Coordinates, at: dict, name: str, body: str, to: str) -> Rims:
    """The grip of two round bodies on fixed axles at their rims, touching from outside: the contact
    on the line of centers, the radius of each from its center."""
    between = (coords.position(to) - coords.position(body)).xreplace(at)
    first, second = (scene.bodies[n].sizes["radius"] for n in (body, to))
    if tidy(between.dot(between) - (first + second) ** 2) != 0:
        raise ValueError(f"the {body} and the {to} do not touch at their rims where they lock (their centers are "
                         f"{sp.sstr(tidy(sp.sqrt(between.dot(between))))} apart, not {sp.sstr(first + second)}): "
                         "place them touching, one outside the other")
    normal = tuple(tidy(e) for e in between / (first + second))
    grip = Rims(name, body, to, normal, first, -second)
    return dataclasses.replace(grip, arc=tidy(grip.gaps(coords)[0].xreplace(at)))


def _round(body) -> bool:
    """A body that bounces by its rim or as a point: a point mass, or a round body (a radius)."""
    return not body.rotates or "radius" in body.sizes


def _bounce(scene: Scene, coords: Coordinates, values: dict, name: str, body: str, to: str, rough: bool,
            decide) -> Touch:
    """The touch of a bounce off a body: the bouncer (a point mass, or a round body by its rim) on a
    rod's side (the normal across the rod) or on a round body's rim (the normal along the line of
    centers); a point mass bounces off the other body, else a round body off the other."""
    first, second = scene.bodies[body], scene.bodies[to]
    bouncer, host = ((body, to) if not first.rotates else (to, body) if not second.rotates
                     else (body, to) if _round(first) else (to, body))
    if not _round(scene.bodies[bouncer]):
        raise ValueError(f"a bounce off a body is of a point mass or a round body: where a {scene.bodies[body].shape} "
                         f"and a {scene.bodies[to].shape} touch is not known")
    at = {c.q: values[c.q] for c in coords.all}
    radius, shape = scene.bodies[bouncer].sizes.get("radius", sp.Integer(0)), scene.bodies[host]
    between = (coords.position(bouncer) - coords.position(host)).xreplace(at)
    offset = _in_frame(-coords.orientation(host).xreplace(at), between)  # the bouncer's center, in the host's frame
    if "radius" in shape.sizes:
        reach = shape.sizes["radius"] + radius
        if radius != 0 and tidy(between.dot(between) - reach**2) != 0:
            raise ValueError(f"the {bouncer} does not touch the {host} where they are in the state it bounces in (their "
                             f"centers are {sp.sstr(tidy(sp.sqrt(between.dot(between))))} apart, not "
                             f"{sp.sstr(reach)}): place them touching")
        normal = between / sp.sqrt(between.dot(between))
        to_offset = offset if radius == 0 else _in_frame(-coords.orientation(host).xreplace(at),
                                                         shape.sizes["radius"] * normal)
    elif shape.shape == "rod":
        angle = coords.orientation(host).xreplace(at)
        normal = sp.Matrix([-sp.sin(angle), sp.cos(angle)])
        to_offset = offset
        if radius != 0:
            if tidy(offset[1] ** 2 - radius**2) != 0:
                raise ValueError(f"the {bouncer} does not touch the {host} where they are in the state it bounces in "
                                 f"(its center is {sp.sstr(tidy(sp.Abs(offset[1])))} from the rod's axis, not its "
                                 f"radius {sp.sstr(radius)}): place it touching")
            side = decide(offset[1]) if decide is not None else offset[1]  # the bouncer's side of the axis
            normal, to_offset = normal * (1 if side > 0 else -1), (offset[0], sp.Integer(0))
    else:
        raise ValueError(f"a bounce off a {shape.shape}: the normal is known for round bodies and rods")
    normal = sp.Matrix([tidy(e) for e in normal])
    own = _in_frame(-coords.orientation(bouncer).xreplace(at), -radius * normal)
    touch = Touch(name, bouncer, host, to_offset, tuple(normal), own, rough)
    approach = touch.conditions(coords)[0].xreplace(values)  # negative while they close in
    if radius == 0 and decide is not None and shape.shape == "rod" and decide(approach) > 0:
        touch = dataclasses.replace(touch, normal=tuple(-e for e in touch.normal))
    return touch


def impact(scene: Scene, coords: Coordinates, before: dict, route: str, bounce: Bounce | None = None) -> Impact:
    """The velocities just after an impulsive change in `scene` (the scene after the impact, with
    the joint it made), from the state `before` (every coordinate and velocity), by `route`
    ("lagrange" or "newton_euler"; see the module). `bounce`: how a bounce's touch of the scene
    ends; with friction, its regimes each solved, and the answer a Piecewise over them: it grips
    where mu J_n >= |J_t| of the grip, else slides the way J_t points."""
    if bounce is None or bounce.friction is None:
        return _solve(scene, coords, before, route, bounce)
    grip, (held, sliding) = _solve(scene, coords, before, route, bounce), bounce.friction
    forces = bounce.touch.unknowns()
    normal, tangential = grip.impulses[forces["impulse"]], grip.impulses[forces["friction"]]
    regimes = (Regime("grips", sp.Ge(held * normal, sp.Abs(tangential)), 0, grip),
               *(Regime(f"slides (friction along {'+' if d > 0 else '-'}t)", tangential > 0 if d > 0 else sp.true, d,
                        _solve(scene, coords, before, route, dataclasses.replace(bounce, slides=d * sliding)))
                 for d in (1, -1)))

    def piecewise(field: str, key: sp.Symbol) -> sp.Expr:
        return sp.Piecewise(*((getattr(r.impact, field)[key], r.where) for r in regimes))

    steps = (Step("Gripping: the contact point's tangential velocity is zero just after", ()), *grip.steps,
             Step(f"It grips where the friction it needs is at most {sp.sstr(held)} times the normal impulse",
                  (regimes[0].where,)),
             Step(f"Elsewhere it slides throughout, its tangential impulse {sp.sstr(sliding)} times the normal one "
                  "the way the grip's would point (+t where it is positive)", ()),
             *(step for r in regimes[1:] for step in (Step(f"Where it {r.name}", ()), *r.impact.steps)))
    return Impact({u: piecewise("velocities", u) for u in grip.velocities},
                  {f: piecewise("impulses", f) for f in grip.impulses}, steps, regimes)


def _solve(scene: Scene, coords: Coordinates, before: dict, route: str, bounce: Bounce | None) -> Impact:
    """One regime's impact by one route (see `impact`)."""
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
    solution = solve_linear(equations, unknowns, scene.placed)
    velocities = {c.u: tidy(solution.raw[c.u], scene.placed) for c in coords.all}
    impulses = {f: tidy(solution.raw[f], scene.placed) for f in forces}
    steps = (Step(text, tuple(equations)),
             Step("Just after the impact", tuple(sp.Eq(u, v) for u, v in velocities.items() if v != 0)))
    return Impact(velocities, impulses, steps)


def _after(part: Part, rates: list[sp.Expr], coords: Coordinates, before: dict, at: dict,
           bounce: Bounce | None) -> list[sp.Eq]:
    """A joint's rates just after the impact: zero; for the bounce's touch, its normal rate -e
    times the one before, and its tangential one zero, or where it slides J_t = +-mu J_n."""
    rates = [rate.xreplace(at) for rate in rates]
    if bounce is None or part is not bounce.touch:
        return [sp.Eq(rate, 0) for rate in rates]
    earlier = {c.u: before[c.u] for c in coords.all}
    result = [sp.Eq(rates[0], -bounce.restitution * rates[0].xreplace(earlier))]
    if part.rough:
        forces = part.unknowns()
        result.append(sp.Eq(rates[1], 0) if bounce.slides is None
                      else sp.Eq(forces["friction"], bounce.slides * forces["impulse"]))
    return result


def _momenta(scene: Scene, coords: Coordinates, before: dict, at: dict, bounce: Bounce | None) -> list[sp.Eq]:
    kinetic, _ = energies(scene, coords)
    earlier = {c.u: before[c.u] for c in coords.all}
    gaps = [(part, f, g) for part in scene.constraints for f, g in zip(part.unknowns().values(), part.gaps(coords))]
    equations = []
    for c in coords.all:
        momentum = sp.diff(kinetic, c.u)
        impulse = sum((f * sp.diff(g, c.q) for _, f, g in gaps), sp.Integer(0))
        equations.append(sp.Eq((momentum - momentum.xreplace(earlier)).xreplace(at), impulse.xreplace(at)))
    return equations + [e for part in scene.constraints
                        for e in _after(part, [coords.ddt(g) for g in part.gaps(coords)], coords, before, at, bounce)]


def _impulses(scene: Scene, coords: Coordinates, before: dict, at: dict, bounce: Bounce | None) -> list[sp.Eq]:
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
    return equations + [e for part in scene.constraints
                        for e in _after(part, part.conditions(coords), coords, before, at, bounce)]


def regime_conditions(impact: Impact, touch: Touch, coords: Coordinates, before: dict) -> list[tuple]:
    """(expression, strict, meaning) for a rough bounce's sliding regimes, each where it holds:
    the contact slips against its friction at the start (a contact at rest that the grip cannot
    hold would start to slip during the impact, which derive does not model), and still at
    separation. Its slip rate is linear in the normal impulse, so one that keeps its sign at
    both ends never reversed (where it would, the contact grips part way, not modelled)."""
    at = {c.q: before[c.q] for c in coords.all}
    slip = touch.conditions(coords)[1].xreplace(at)
    result = []
    for k, regime in enumerate(impact.regimes):
        if regime.direction == 0:
            continue
        earlier = [(sp.Integer(1), r.where) for r in impact.regimes[:k]]

        def there(expr: sp.Expr) -> sp.Expr:
            return sp.Piecewise(*earlier, (-regime.direction * tidy(expr), regime.where), (sp.Integer(1), True))

        result += [(there(slip.xreplace(before)), True,
                    f"the {touch.body}'s contact point does not slip on the {touch.to or touch.surface} at the start "
                    "of the bounce, which its grip cannot hold: a slip that starts during the impact is not modelled"),
                   (there(slip.xreplace(regime.impact.velocities)), False,
                    f"the {touch.body}'s slip on the {touch.to or touch.surface} would reverse during the bounce, which "
                    "derive does not model (it takes the slip one way throughout)")]
    return result


def energy_lost(scene: Scene, coords: Coordinates, before: dict, after: dict) -> sp.Expr:
    """The kinetic energy the impact takes (before minus after), factored."""
    kinetic, _ = energies(scene, coords)
    return tidy(kinetic.xreplace(before) - kinetic.xreplace(after))


def conserved(scene: Scene, coords: Coordinates, before: dict, after: dict) -> Step | None:
    """The momentum the impact keeps, as a text names it, with its value before and after. The
    joints between bodies give equal and opposite impulses at one point (or couples), so only the
    ground's matter: with none, the total momentum and the angular momentum about the origin; with
    pins to the ground and a bounce's touch on a surface all at one point (a hinge, an axle, where
    a ball strikes the floor), the angular momentum about it; with another joint to the ground (a
    block's floor, a weld), none is named (None)."""
    grounded = outside(scene)
    if any(not isinstance(p, (Pin, Touch)) for p in grounded):
        return None
    at = {c.q: before[c.q] for c in coords.all}
    points = {tuple(tidy(e) for e in (coords.position(p.body, p.offset) if isinstance(p, Pin) else
                                      sp.Matrix(p.to_offset)).xreplace(at)) for p in grounded}
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
        joint = "pin" if isinstance(grounded[0], Pin) else "point of contact"
        where = f"about the {joint}, where the only impulse from outside acts"
        said = Sentence((f"The only impulse from outside the bodies is that of {titled(grounded)}, at ",
                         sp.Tuple(*about), f": {'its force passes' if len(grounded) == 1 else 'their forces pass'} "
                         "through that point, so it has no moment about it, and the angular momentum about that "
                         "point is conserved through the impact."))
        return Step(f"Check: the angular momentum {where}, before and after", (sp.Eq(L, l0), sp.Eq(L, l1)),
                    sentences=(said,))
    said = Sentence(("No joint holds a body to the ground, so no impulse comes from outside the bodies: their "
                     "momentum, and their angular momentum about any point (here the origin), are conserved through "
                     "the impact.",))
    return Step("Check: no impulse from outside, so the momentum and the angular momentum about the origin, before "
                "and after", (sp.Eq(px, px0), sp.Eq(px, px1), sp.Eq(py, py0), sp.Eq(py, py1), sp.Eq(L, l0),
                              sp.Eq(L, l1)), sentences=(said,))


def said(event: Event, made: Part, scene: Scene, kept: bool) -> tuple[Sentence, ...]:
    """The impact of `event`, which made the joint `made` in `scene` (with it), in words with its
    symbols: what an instant lets give impulses, what the joint does after (sticks, locks, or
    bounces by Newton's law of restitution), and, where `kept` is False, why no momentum is named.

    >>> pin = Pin("struck", "bullet", (0, 0), "rod", (0, 0))
    >>> [s.words for s in said(Event("stick", "bullet", "rod"), pin, Scene({}, (pin,)), True)][1]
    'The bullet sticks to the rod where it strikes it: from then on the pin struck holds it there, and the two move together (a perfectly inelastic impact).'
    """
    joints = list(scene.constraints)
    result = [Sentence((f"The impact lasts an instant: the bodies do not move during it, and forces that stay finite, "
                        f"such as weights, springs and given loads, give no impulse; only the joints' forces do, "
                        f"{'that' if len(joints) == 1 else 'those'} of {titled(joints)}.",))]
    body, to = event.body, event.to
    if isinstance(made, Pin):
        result.append(Sentence((f"The {body} sticks to the {to} where it strikes it: from then on {made.title} holds "
                                "it there, and the two move together (a perfectly inelastic impact).",)))
    elif isinstance(made, Weld):
        result.append(Sentence((f"The {body} sticks to the {to}: from then on {made.title} holds them together, and "
                                "they move as one body (a perfectly inelastic impact).",)))
    elif isinstance(made, Rims):
        result.append(Sentence((f"The {body} and the {to} are pressed together at their rims: friction acts between "
                                "them until the rims move together, and from then on they roll on each other. Only "
                                "the friction's impulse and the axles' act, so the final rates do not depend on how "
                                "large the friction is or how long it acts.",)))
    elif isinstance(made, Clutch):
        result.append(Sentence((f"The {body} and the {to} lock together: from then on {made.title} holds their angles "
                                "together, and they turn as one.",)))
    else:
        result.append(Sentence(("By Newton's law of restitution the two points separate along the normal just after at ",
                                event.restitution, " times the rate at which they approached.")))
        if event.grips:
            result.append(Sentence(("The contact grips: its tangential rate is zero just after.",)))
        elif event.friction is not None:
            held, sliding = event.friction
            result.append(Sentence(("The contact is rough: it grips where friction can hold it, its tangential impulse "
                                    "at most ", held, " times the normal one in size; elsewhere it slides throughout, "
                                    "its tangential impulse ", sliding, " times the normal one.")))
    if not kept:
        grounded = outside(scene)
        result.append(Sentence((f"The impulse from outside the bodies, of {titled(grounded)}, does not act at one pin: "
                                "no momentum is named as conserved, and the impulse equations alone give the velocities.",)))
    return tuple(result)


def lost_said(event: Event) -> Sentence:
    """Why the impact of `event` takes kinetic energy, in words."""
    if event.kind == "bounce":
        return Sentence(("Kinetic energy is conserved only in an elastic bounce, with ", event.restitution, " equal to "
                         "1, and without friction: otherwise the bounce takes the difference below.",))
    return Sentence(("Kinetic energy is not conserved where bodies stick: the impact brings them to one motion, and "
                     "the joint's impulses take the difference below.",))


def outside(scene: Scene) -> list[Part]:
    """The joints that hold a body to the ground: their impulses come from outside the bodies."""
    return [p for p in scene.constraints if len(p.bodies()) == 1]
