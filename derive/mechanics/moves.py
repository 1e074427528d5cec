"""A move inside a scene: a point mass carried by the scene's own forces to another point of the
body it is pinned to (a child walking from a turntable's rim to its center, a student on a
turning stool pulling in the weights in his hands). The forces that make the move come in equal
and opposite pairs, and are not known; what the move keeps is what no force from outside the
moving bodies changes. Each route finds that from the scene, for every rigid motion xi of a set S
of bodies (a turn about a pin to the ground or the origin, a shift along x or y):

- Lagrange (Noether): p_xi = sum_j dT/du_j xi_j changes at the rate (Q - dV/dq) . xi plus, for
  each gap g, its multiplier times dg/dq . xi. (T depends on no coordinate, the bodies' own, and
  a rigid motion's rate of xi adds nothing: m v x v = 0.) Where every gap, the mover's pin at any
  place on its body, is unchanged by xi wherever the gaps hold, and the loads do no work along
  xi, p_xi is the same before and after the move, however it is made.
- Newton–Euler: the angular momentum of S about the point (sum m r x v + I omega), or its
  momentum along the shift, changes by the moments (forces) on S from outside it: where every
  part's forces on S have no moment about the point (no component along the shift), whatever
  their sizes, it is kept.

"Unchanged" is tested at random configurations on the gaps, random rates and forces (a
polynomial identity test: no symbolic simplifier decides zero for these trigonometric forms in
the time a problem has). The rates after solve the kept momenta with the joints' velocity
conditions after the move; where they do not fix every rate (a weight's moment about the pivot
of a swing), the move is refused. The bodies are where they were, the mover at its new place.

A turn (Elroy's beanie) is the same with a couple of any size between two turning bodies as the
moving force, one turned through an angle relative to the other and at rest relative to it
after: where a kept momentum is zero and its coefficients are constant (the linear joints
applied), it is the rate of sum_j c_j q_j, so that sum is unchanged and, with the turn and the
joints, fixes where the bodies end (from rest: I1 dtheta1 + I2 dtheta2 = 0). Otherwise where
they end depends on how long the turn takes: those coordinates are `loose`.

>>> import sympy as sp
>>> from derive.model.kinematics import Coordinates
>>> from derive.parts.pin import Pin
>>> from derive.model.scene import Body, Event, Scene
>>> m, M, R, w = sp.symbols("m M R omega", positive=True)
>>> platform = Body("platform", "disk", M, {"radius": R}, M * R**2 / 2)
>>> child = Body("child", "point", m, {}, at=(R, 0))
>>> scene = Scene({"platform": platform, "child": child},
...               (Pin("axle", "platform", (0, 0)), Pin("feet", "child", (0, 0), "platform", (R, 0))))
>>> coords = Coordinates(scene)
>>> before = {**{s: 0 for s in coords.state}, coords.of("platform", "theta").u: w, coords.of("child", "y").u: w * R}
>>> event = Event("move", "child", "platform", place=(0, 0), joint="feet")
>>> after = move(scene, coords, before, event, "lagrange", lambda e: float(e.subs({m: 1, M: 2, R: 1, w: 1})))
>>> after.values[coords.of("platform", "theta").u]
omega*(M + 2*m)/M
"""
from __future__ import annotations

import dataclasses
from dataclasses import dataclass
from itertools import combinations
import random

import numpy as np
import sympy as sp

from derive.mechanics.derivation import solve_linear
from derive.text.steps import Step
from derive.core.tidying import tidy
from derive.model.kinematics import Coordinates, solve_gaps
from derive.mechanics.lagrange import energies, generalized_forces
from derive.parts import AppliedForce, AppliedTorque, Part, titled
from derive.parts.pin import Pin
from derive.text.prose import Sentence
from derive.model.scene import Event, Scene


class MoveLimit(ValueError):
    """A move whose kept momenta and joints do not fix the rates after it."""


@dataclass(frozen=True)
class Symmetry:
    """A rigid motion of the bodies `moved`: a turn about the point `about`, or a shift along the
    axis `along` ("x" or "y")."""

    moved: tuple[str, ...]
    about: tuple[sp.Expr, sp.Expr] | None = None
    along: str | None = None

    def field(self, coords: Coordinates) -> dict[sp.Symbol, sp.Expr]:
        """xi: how fast each coordinate changes in the motion (per radian, per metre)."""
        xi = {c.q: sp.Integer(0) for c in coords.all}
        for name in self.moved:
            x, y = coords.position(name)
            if self.about is None:
                xi[coords.of(name, self.along).q] = sp.Integer(1)
                continue
            xi[coords.of(name, "x").q], xi[coords.of(name, "y").q] = self.about[1] - y, x - self.about[0]
            if coords.scene.bodies[name].rotates:
                xi[coords.of(name, "theta").q] = sp.Integer(1)
        return xi

    def effect(self, coords: Coordinates, force: AppliedForce | AppliedTorque) -> sp.Expr:
        """The moment about the point (the component along the shift) of a force on a moved body."""
        if force.body not in self.moved:
            return sp.Integer(0)
        if isinstance(force, AppliedTorque):
            return force.torque if self.about is not None else sp.Integer(0)
        if self.about is None:
            return force.force[0 if self.along == "x" else 1]
        arm = coords.position(force.body) + force.offset - sp.Matrix(self.about)
        return arm[0] * force.force[1] - arm[1] * force.force[0]

    def momentum(self, coords: Coordinates) -> sp.Expr:
        """Newton–Euler: the angular momentum of the moved bodies about the point (sum m r x v + I
        omega), or their momentum along the shift."""
        total = sp.Integer(0)
        for name in self.moved:
            body = coords.scene.bodies[name]
            v = sp.Matrix([coords.of(name, "x").u, coords.of(name, "y").u])
            if self.about is None:
                total += body.mass * v[0 if self.along == "x" else 1]
                continue
            r = coords.position(name) - sp.Matrix(self.about)
            total += body.mass * (r[0] * v[1] - r[1] * v[0])
            if body.rotates:
                total += body.inertia * coords.angular_velocity(name)
        return total

    @property
    def symbol(self) -> sp.Symbol:
        """L_O for an angular momentum (not a length L), p_x or p_y for a momentum."""
        return sp.Symbol("L_O" if self.about is not None else f"p_{self.along}")

    def describe(self, scene: Scene) -> str:
        who = "the whole scene" if len(self.moved) == len(scene.bodies) else " and ".join(
            f"the {n}" for n in self.moved)
        if self.about is None:
            return f"the momentum of {who} along {self.along}"
        return f"the angular momentum of {who} about {sp.sstr(tuple(self.about))}"


@dataclass(frozen=True)
class Moved:
    """One route's state after a move or a turn: every coordinate and rate (`values`), the momenta
    it kept, the steps that found them, and the coordinates it leaves `loose` (a turn's, where
    they depend on how long it takes: their values are those before, and no rate depends on them)."""

    values: dict[sp.Symbol, sp.Expr]
    kept: tuple[Symmetry, ...]
    steps: tuple[Step, ...]
    loose: tuple[sp.Symbol, ...] = ()


def moved_pin(scene: Scene, event: Event, place) -> Pin:
    """The pin of the move's mover, holding it at `place` of the body it moves on."""
    pin = next(p for p in scene.constraints if p.name == event.joint)
    return dataclasses.replace(pin, **({"to_offset": tuple(place)} if pin.to == event.to else {"offset": tuple(place)}))


def with_pin(scene: Scene, pin: Pin) -> Scene:
    """The scene with `pin` in place of the part of its name."""
    return dataclasses.replace(scene, constraints=tuple(pin if p.name == pin.name else p for p in scene.constraints))


def move(scene: Scene, coords: Coordinates, before: dict, event: Event, route: str, sample) -> Moved:
    """The state after the move `event` from the state `before` (every coordinate and rate) of
    `scene`, by `route` ("lagrange" or "newton_euler"; see the module). `sample` gives an
    expression's value at the middle of the parameter ranges.

    Raises MoveLimit where the kept momenta and the joints after do not fix every rate."""
    place = sp.symbols("sigma_x sigma_y", real=True)  # the mover's place on its body, anywhere
    anywhere = with_pin(scene, moved_pin(scene, event, place))
    after = with_pin(scene, moved_pin(scene, event, event.place))
    kept = symmetries_kept(anywhere, coords, before, route, sample, place)
    positions = _placed(scene, coords, before, event, kept)
    return _after(scene, after, coords, before, kept, positions, route, sample, "move")


def pull(scene: Scene, coords: Coordinates, before: dict, event: Event, route: str, sample) -> Moved:
    """The state after the pull `event` (its cord, from a ground point to the point mass
    `event.body`, drawn slowly to `event.length`: a puck on a table pulled in through a hole)
    from the state `before` of `scene`, by `route`: the cord's force points at the ground point
    whatever its size, so the momenta it keeps are found as for a move, the turn about that point
    among them; the body ends on the line from the point through where it was (where about the
    point depends on how the pull is made), moving across the cord (slowly: no speed along it).

    Raises MoveLimit where the kept momenta and the cord do not fix the rates (a weight's pull)."""
    cord = scene.constraint(event.joint)
    hole = sp.Matrix(next(a.offset for a in cord.path if a.body is None))
    at = {c.q: before[c.q] for c in coords.all}
    reach = coords.position(event.body).xreplace(at) - hole
    there = hole + event.length * reach / sp.sqrt(reach.dot(reach)) - sp.Matrix(scene.bodies[event.body].at)
    positions = {**at, **{coords.of(event.body, k).q: tidy(v) for k, v in zip(("x", "y"), there)}}
    kept = symmetries_kept(scene, coords, before, route, sample, (), (tuple(hole),))
    return _after(scene, scene, coords, before, kept, positions, route, sample, "pull")


def pulled_cord(scene: Scene, coords: Coordinates, before: dict, event: Event) -> Part:
    """The cord of the pull `event` at its new length (the state `before` it gives its old one)."""
    cord = scene.constraint(event.joint)
    at = {c.q: before[c.q] for c in coords.all}
    hole = sp.Matrix(next(a.offset for a in cord.path if a.body is None))
    reach = coords.position(event.body).xreplace(at) - hole
    return dataclasses.replace(cord, drawn=tidy(cord.drawn + sp.sqrt(reach.dot(reach)) - event.length))


def turn(scene: Scene, coords: Coordinates, before: dict, event: Event, route: str, sample) -> Moved:
    """The state after the turn `event` (the body `event.body` turned through `event.angle`
    relative to `event.to` by a couple between them, and at rest relative to it again) from the
    state `before` of `scene`, by `route` ("lagrange" or "newton_euler"): the momenta the couple
    and the scene's forces keep, as for a move. Where a kept momentum is zero and its
    coefficients are constant, sum_j c_j dq_j = 0 over the turn however it is made (Elroy's
    beanie: I1 dtheta1 + I2 (dtheta1 + psi) = 0): with the turn itself and the joints that are
    linear in the coordinates, these fix where the bodies are. Coordinates they do not fix are
    `loose` (where they end depends on how long the turn takes).

    Raises MoveLimit where the rates after depend on a loose coordinate, where the joints do not
    let the body turn so, or where the kept momenta do not fix every rate."""
    couple = _Couple(event.body, event.to)
    driven = dataclasses.replace(scene, loads=scene.loads + (couple,))
    kept = symmetries_kept(driven, coords, before, route, sample, (couple.torque,))
    momenta = [momentum_of(scene, coords, s, route) for s in kept]
    relative = coords.angle(event.body) - coords.angle(event.to)
    earlier = {c.q: before[c.q] for c in coords.all}
    turned = sp.Eq(relative - relative.xreplace(earlier), event.angle)
    steps = [Step(f"The angle of the {event.body} relative to the {event.to} grows by the turn", (turned,),
                  sentences=tuple(couple.sentences(route, coords)))]
    gaps = [g for part in scene.constraints for g in part.gaps(coords)
            if not any(sp.diff(g, q).has(*earlier) for q in earlier)]  # linear in the coordinates
    held = _solved(gaps, list(earlier))  # on them, the momenta in the coordinates they leave free
    rates = _solved([coords.ddt(g) for g in gaps], [c.u for c in coords.all])
    displaced = []
    for p in momenta:
        reduced = p.xreplace(held).xreplace(rates)
        if tidy(p.xreplace(before)) == 0 and not any(sp.diff(reduced, c.u).has(*earlier) for c in coords.all):
            displaced.append(sp.Eq(sum((sp.diff(reduced, c.u) * (c.q - before[c.q]) for c in coords.all),
                                       sp.Integer(0)), 0))
    if displaced:
        steps.append(Step("A kept momentum that is zero, with constant coefficients, is the rate of a fixed sum of "
                          "the coordinates: that sum is the same after the turn, however it is made", tuple(displaced)))
    solutions = sp.linsolve([turned, *displaced, *(sp.Eq(g, 0) for g in gaps)], list(earlier))
    if solutions == sp.S.EmptySet:
        raise MoveLimit(f"turn the {event.body} relative to the {event.to}: the joints do not let it turn so")
    (solution,) = solutions
    positions = {q: tidy(v) if not v.has(*earlier) else before[q] for q, v in zip(earlier, solution)}
    loose = tuple(q for q, v in zip(earlier, solution) if v.has(*earlier))
    steps.append(Step("Where the bodies are after the turn", tuple(sp.Eq(q, v) for q, v in positions.items()
                                                                 if q not in loose and v != before[q])))
    if loose:
        needed = [*momenta, *(v for part in scene.constraints for v in part.conditions(coords)),
                  *(coords.ddt(g) for part in scene.constraints for g in part.gaps(coords))]
        if any(e.has(*loose) for e in needed):
            raise MoveLimit(f"find the rates after the turn of the {event.body}: they depend on where the bodies are "
                            "after it, which depends on how long it takes (it keeps a momentum that is not zero, or "
                            "whose coefficients change as they move)")
    stop = coords.angular_velocity(event.body) - coords.angular_velocity(event.to)  # at rest relative to it
    return _after(scene, scene, coords, before, kept, positions, route, sample, "turn", tuple(steps), (stop,), loose)


@dataclass(frozen=True)
class _Couple(Part):
    """The couple that turns `body` relative to `to`: a torque of any size on it, and the
    opposite one on `to` (Lagrange: its power; Newton–Euler: the two torques)."""

    body: str
    to: str
    name: str = "couple"
    torque: sp.Symbol = sp.Symbol("tau_turn", real=True)

    def bodies(self) -> tuple[str, ...]:
        return (self.body, self.to)

    @property
    def title(self) -> str:
        return "the couple"

    def power(self, coords) -> sp.Expr:
        return self.torque * (coords.angular_velocity(self.body) - coords.angular_velocity(self.to))

    def loads(self, coords) -> list[AppliedTorque]:
        return [AppliedTorque(self.body, self.torque, "couple"), AppliedTorque(self.to, -self.torque, "couple")]

    def sentences(self, route: str, coords) -> list[Sentence]:
        if route == "lagrange":
            return [Sentence((f"The couple that turns the {self.body} relative to the {self.to}, of any size ", self.torque,
                              ", does work at the rate of the couple times their relative angular velocity: ",
                              self.power(coords), "."))]
        return [Sentence(("The couple ", self.torque, f" turns the {self.body}, pushing its center nowhere.",), self.body),
                Sentence((f"The opposite couple turns the {self.to}.",), self.to)]


def _solved(equations: list[sp.Expr], unknowns: list[sp.Symbol]) -> dict:
    """The unknowns that linear `equations` (= 0) fix in terms of the others, as a substitution."""
    (solution,) = sp.linsolve(equations, unknowns) if equations else [unknowns]
    return {u: v for u, v in zip(unknowns, solution) if v != u}


def symmetries_kept(scene: Scene, coords: Coordinates, before: dict, route: str, sample, free,
                    points: tuple = ()) -> list[Symmetry]:
    """The rigid motions whose momenta the scene keeps by `route`, whatever the symbols `free`
    (the mover's place, the couple of a turn); turns about `points` too (a pull's hole)."""
    zero = _zero_test(scene, coords, sample, free)
    test = _kept_by_lagrange if route == "lagrange" else _kept_by_newton_euler
    return [s for s in _candidates(scene, coords, before, points) if test(scene, coords, s, zero)]


def momentum_of(scene: Scene, coords: Coordinates, symmetry: Symmetry, route: str) -> sp.Expr:
    """Lagrange: p_xi = sum_j dT/du_j xi_j. Newton–Euler: the angular momentum about the point
    (the momentum along the shift) of the moved bodies."""
    if route != "lagrange":
        return symmetry.momentum(coords)
    kinetic, _ = energies(scene, coords)
    xi = symmetry.field(coords)
    return sum((sp.diff(kinetic, c.u) * xi[c.q] for c in coords.all), sp.Integer(0))


def _after(scene: Scene, after: Scene, coords: Coordinates, before: dict, kept: list[Symmetry], positions: dict,
           route: str, sample, what: str, steps: tuple = (), extra=(), loose=()) -> Moved:
    """The rates after a move or a turn: the kept momenta as before, with the joints' velocity
    conditions of the scene `after` and the `extra` rates that vanish, at `positions`; `steps`
    shown after the kept momenta."""
    momenta = [momentum_of(scene, coords, s, route) for s in kept]
    if route == "lagrange":
        conditions = [coords.ddt(g) for part in after.constraints for g in part.gaps(coords)]
    else:
        conditions = [v for part in after.constraints for v in part.conditions(coords)]
    earlier = {**{c.u: before[c.u] for c in coords.all}, **{c.q: before[c.q] for c in coords.all}}
    equations = [sp.Eq(c.xreplace(positions), 0) for c in [*conditions, *extra]]
    equations += [sp.Eq(p.xreplace(positions), tidy(p.xreplace(earlier))) for p in momenta]
    chosen = _independent(equations, [c.u for c in coords.all], sample)
    if len(chosen) < len(coords.all):
        named = "; ".join(s.describe(scene) for s in kept) or "no momentum"
        raise MoveLimit(f"find the rates after this {what}: it keeps {named}, and with the joints that does not fix "
                        f"them (derive models {what}s during which no force from outside changes a momentum; a "
                        "weight's moment about a pivot does)")
    solution = solve_linear([equations[i] for i in chosen], [c.u for c in coords.all], scene.placed)
    values = {**positions, **{c.u: tidy(solution.raw[c.u], scene.placed) for c in coords.all}}
    fixed = len(conditions) + len(extra)
    used = [(kept[i - fixed], equations[i]) for i in chosen if i >= fixed]
    kinds = {"angular momentum" if s.about is not None else "momentum" for s, _ in used}
    steps = (Step(f"Forces from outside the moving bodies have no moment (no component) here, so the {what} keeps "
                  f"the {' and the '.join(sorted(kinds))} below (before, and after)",
                  tuple(eq for s, e in used for eq in (sp.Eq(s.symbol, e.rhs), sp.Eq(s.symbol, tidy(e.lhs)))),
                  sentences=tuple(kept_said(scene, coords, s, route, what) for s, _ in used)),
             *steps,
             Step(f"After the {what}", tuple(sp.Eq(c.u, values[c.u]) for c in coords.all if values[c.u] != 0)))
    return Moved(values, tuple(s for s, _ in used), steps, loose)


def kept_said(scene: Scene, coords: Coordinates, symmetry: Symmetry, route: str, what: str) -> Sentence:
    """Why a move or a turn (`what`) keeps the momentum of `symmetry`, as `route` proves it: by
    Lagrange, Noether's theorem (the rigid motion changes no gap and the loads do no work along
    it); by Newton–Euler, the moments of the parts' forces on the moved bodies (from outside
    them, none about the point; between them, equal and opposite).

    >>> from derive.model.scene import Body
    >>> m, M, R = sp.symbols("m M R", positive=True)
    >>> scene = Scene({"platform": Body("platform", "disk", M, {"radius": R}, M * R**2 / 2),
    ...                "child": Body("child", "point", m, {}, at=(R, 0))},
    ...               (Pin("axle", "platform", (0, 0)), Pin("feet", "child", (0, 0), "platform", (R, 0))))
    >>> kept_said(scene, Coordinates(scene), Symmetry(("platform", "child"), about=(0, 0)), "newton_euler", "move").words
    'The forces on the platform and the child from outside them, those of the axle, have no moment about , whatever their sizes, and those between them come in equal and opposite pairs: so their angular momentum about that point is the same before and after the move, however it is made.'
    """
    who = "the whole scene" if len(symmetry.moved) == len(scene.bodies) else " and ".join(
        f"the {n}" for n in symmetry.moved)
    if symmetry.about is not None:
        motion, where, kept = ("Turning ", (" rigidly about ", sp.Tuple(*symmetry.about)),
                               "angular momentum about that point")
    else:
        motion, where, kept = ("Shifting ", (f" rigidly along {symmetry.along}",), f"momentum along {symmetry.along}")
    then = f" is the same before and after the {what}, however it is made."
    if route == "lagrange":
        gaps = titled(scene.constraints) if scene.constraints else "no part"
        named = kept.replace("momentum", f"momentum of {who}", 1)
        return Sentence((f"{motion}{who}", *where, f" changes none of the gaps of {gaps}, and the loads do no work "
                         f"along it: by Noether's theorem the momentum of that motion, the {named},{then}"))
    moved = set(symmetry.moved)
    pushing = [p for p in scene.parts if any(load.body in moved for load in p.loads(coords))
               and not (len(set(p.bodies())) > 1 and set(p.bodies()) <= moved)]  # a part between two of them: inside
    from_outside = f", those of {titled(pushing)}," if pushing else ""
    effect = "have no moment about " if symmetry.about is not None else f"have no component along {symmetry.along}"
    return Sentence((f"The forces on {' and '.join(f'the {n}' for n in symmetry.moved)} from outside them{from_outside} "
                     f"{effect}", *(where[1:] if symmetry.about is not None else ()), ", whatever their sizes, and "
                     f"those between them come in equal and opposite pairs: so their {kept}{then}"))


def _placed(scene: Scene, coords: Coordinates, before: dict, event: Event, kept: list[Symmetry]) -> dict:
    """Where the bodies are after the move: as before, the mover at its new place, and a set of
    bodies free to shift with it (a kept momentum) shifted so that its center of mass stays put,
    as in a quick move (where it lies decides the angular momentum about a fixed point)."""
    positions = {c.q: before[c.q] for c in coords.all}
    # the mover's coordinates are its center's displacement from where the placement has it
    there = coords.position(event.to, event.place).xreplace(positions) - sp.Matrix(scene.bodies[event.body].at)
    for axis, value in zip(("x", "y"), there):
        moved = max((s.moved for s in kept if s.along == axis and event.body in s.moved), key=len, default=())
        step = tidy(value) - positions[coords.of(event.body, axis).q]
        mass = sum((scene.bodies[n].mass for n in moved), sp.Integer(0))
        for name in moved:
            positions[coords.of(name, axis).q] = tidy(positions[coords.of(name, axis).q]
                                                      - step * scene.bodies[event.body].mass / mass)
        positions[coords.of(event.body, axis).q] = tidy(positions[coords.of(event.body, axis).q] + step)
    return positions


def _candidates(scene: Scene, coords: Coordinates, before: dict, extra: tuple = ()) -> list[Symmetry]:
    """Turns about each pin to the ground, the `extra` points and the origin, and shifts, of every
    set of bodies, the largest sets first (the whole scene's momentum reads best)."""
    at = {c.q: before[c.q] for c in coords.all}
    points = [tuple(tidy(e) for e in coords.position(p.body, p.offset).xreplace(at))
              for p in scene.constraints if isinstance(p, Pin) and p.to is None]
    points = list(dict.fromkeys(points + [tuple(tidy(e) for e in p) for p in extra] + [(sp.Integer(0), sp.Integer(0))]))
    names = list(scene.bodies)
    return [Symmetry(moved, about=point) if point else Symmetry(moved, along=axis)
            for size in range(len(names), 0, -1) for moved in combinations(names, size)
            for point, axis in [*((p, None) for p in points), (None, "x"), (None, "y")]]


def _kept_by_lagrange(scene: Scene, coords: Coordinates, symmetry: Symmetry, zero) -> bool:
    xi = symmetry.field(coords)
    gaps = [g for part in scene.constraints for g in part.gaps(coords)]
    if not all(zero(sum((sp.diff(g, q) * v for q, v in xi.items()), sp.Integer(0))) for g in gaps):
        return False
    _, potential = energies(scene, coords)
    applied = generalized_forces(scene, coords)
    return zero(sum(((applied[q] - sp.diff(potential, q)) * v for q, v in xi.items()), sp.Integer(0)))


def _kept_by_newton_euler(scene: Scene, coords: Coordinates, symmetry: Symmetry, zero) -> bool:
    return all(zero(sum((symmetry.effect(coords, f) for f in part.loads(coords)), sp.Integer(0)))
               for part in scene.parts)


def _zero_test(scene: Scene, coords: Coordinates, sample, free) -> callable:
    """expr -> whether it vanishes wherever the scene's gaps hold: at three random configurations
    on them (the dependent coordinates solved from the gaps), with random rates, forces and
    values of the symbols `free`, the parameters at the middle of their ranges."""
    solved = solve_gaps(scene, coords, sample)
    forces = [f for part in scene.parts for f in part.unknowns().values()]
    free = [*(c.q for c in coords.all if c.q not in solved), *(c.u for c in coords.all), *free, *forces]
    rng = random.Random(0)
    points = [{s: sp.Rational(rng.randint(-400, 400), 1000) for s in free} for _ in range(3)]

    def vanishes(expr: sp.Expr) -> bool:
        expr = expr.xreplace(solved)
        for point in points:
            try:
                value = sample(expr.xreplace(point))
                scale = max((abs(sample(t.xreplace(point))) for t in sp.Add.make_args(expr)), default=0.0)
            except TypeError:  # complex: off the gaps' branch, so not shown to vanish
                return False
            if abs(value) > 1e-9 * (1 + scale):
                return False
        return True
    return vanishes


def _independent(equations: list[sp.Eq], unknowns: list[sp.Symbol], sample) -> list[int]:
    """The indices of the equations, in order, each kept where it adds a rank (its coefficients at
    the middle of the ranges)."""
    chosen, rows = [], []
    for i, e in enumerate(equations):
        row = [sample(sp.diff(e.lhs - e.rhs, u)) for u in unknowns]
        if np.linalg.matrix_rank(np.array(rows + [row]), tol=1e-9 * (1 + max(map(abs, row)))) > len(rows):
            chosen.append(i)
            rows.append(row)
    return chosen
