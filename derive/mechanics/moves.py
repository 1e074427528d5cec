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

>>> import sympy as sp
>>> from derive.mechanics.kinematics import Coordinates
>>> from derive.parts.pin import Pin
>>> from derive.scene import Body, Event, Scene
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

from derive.mechanics.derivation import Step, solve_linear, tidy
from derive.mechanics.kinematics import Coordinates, solve_gaps
from derive.mechanics.lagrange import energies, generalized_forces
from derive.parts import AppliedForce, AppliedTorque
from derive.parts.pin import Pin
from derive.scene import Event, Scene


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
    """One route's state after a move: every coordinate and rate (`values`), the momenta it kept
    and the steps that found them."""

    values: dict[sp.Symbol, sp.Expr]
    kept: tuple[Symmetry, ...]
    steps: tuple[Step, ...]


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
    zero = _zero_test(anywhere, coords, sample, place)
    test = _kept_by_lagrange if route == "lagrange" else _kept_by_newton_euler
    kept = [s for s in _candidates(scene, coords, before) if test(anywhere, coords, s, zero)]
    positions = _placed(scene, coords, before, event, kept)
    if route == "lagrange":
        kinetic, _ = energies(scene, coords)
        momenta = [sum((sp.diff(kinetic, c.u) * s.field(coords)[c.q] for c in coords.all), sp.Integer(0))
                   for s in kept]
        conditions = [coords.ddt(g) for part in after.constraints for g in part.gaps(coords)]
    else:
        momenta = [s.momentum(coords) for s in kept]
        conditions = [v for part in after.constraints for v in part.conditions(coords)]
    earlier = {**{c.u: before[c.u] for c in coords.all}, **{c.q: before[c.q] for c in coords.all}}
    equations = [sp.Eq(c.xreplace(positions), 0) for c in conditions]
    equations += [sp.Eq(p.xreplace(positions), tidy(p.xreplace(earlier))) for p in momenta]
    chosen = _independent(equations, [c.u for c in coords.all], sample)
    if len(chosen) < len(coords.all):
        what = "; ".join(s.describe(scene) for s in kept) or "no momentum"
        raise MoveLimit(f"find the rates after this move: it keeps {what}, and with the joints that does not fix "
                        "them (derive models moves during which no force from outside changes a momentum; a "
                        "weight's moment about a pivot does)")
    solution = solve_linear([equations[i] for i in chosen], [c.u for c in coords.all])
    values = {**positions, **{c.u: tidy(solution.raw[c.u]) for c in coords.all}}
    used = [(kept[i - len(conditions)], equations[i]) for i in chosen if i >= len(conditions)]
    steps = (Step("Forces from outside the moving bodies have no moment (no component) here, so the move keeps "
                  + "; ".join(s.describe(scene) for s, _ in used) + " (before, and after)",
                  tuple(eq for s, e in used for eq in (sp.Eq(s.symbol, e.rhs), sp.Eq(s.symbol, tidy(e.lhs))))),
             Step("After the move", tuple(sp.Eq(c.u, values[c.u]) for c in coords.all if values[c.u] != 0)))
    return Moved(values, tuple(s for s, _ in used), steps)


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


def _candidates(scene: Scene, coords: Coordinates, before: dict) -> list[Symmetry]:
    """Turns about each pin to the ground and the origin, and shifts, of every set of bodies,
    the largest sets first (the whole scene's momentum reads best)."""
    at = {c.q: before[c.q] for c in coords.all}
    points = [tuple(tidy(e) for e in coords.position(p.body, p.offset).xreplace(at))
              for p in scene.constraints if isinstance(p, Pin) and p.to is None]
    points = list(dict.fromkeys(points + [(sp.Integer(0), sp.Integer(0))]))
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


def _zero_test(scene: Scene, coords: Coordinates, sample, place) -> callable:
    """expr -> whether it vanishes wherever the scene's gaps hold: at three random configurations
    on them (the dependent coordinates solved from the gaps), with random rates, places and
    forces, the parameters at the middle of their ranges."""
    solved = solve_gaps(scene, coords, sample)
    forces = [f for part in scene.parts for f in part.unknowns().values()]
    free = [*(c.q for c in coords.all if c.q not in solved), *(c.u for c in coords.all), *place, *forces]
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
