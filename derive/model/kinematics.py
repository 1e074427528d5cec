"""Planar coordinates of a scene and the time derivative along its motion.

Each body has a center-of-mass position (x, y) and, unless it is a point mass, an angle
theta (counter-clockwise positive). Every coordinate q has a velocity symbol u and an
acceleration symbol a, so a time derivative is the chain rule
d/dt f(q, u) = sum(df/dq * u + df/du * a), with no sympy Function objects to substitute.

>>> import sympy as sp
>>> from derive.model.scene import Body, Scene
>>> scene = Scene(bodies={"wheel": Body("wheel", "custom", sp.Symbol("M"), {}, sp.Symbol("I"))})
>>> coords = Coordinates(scene)
>>> th = coords.of("wheel", "theta")
>>> coords.ddt(sp.sin(th.q))
thetadot_wheel*cos(theta_wheel)
"""
from __future__ import annotations

import functools

from dataclasses import dataclass

import sympy as sp

from derive.model.scene import Scene


@dataclass(frozen=True)
class Coordinate:
    """One generalized coordinate: its symbol, velocity and acceleration symbols."""

    body: str
    kind: str  # "x", "y" or "theta"
    q: sp.Symbol
    u: sp.Symbol
    a: sp.Symbol


class Coordinates:
    """The coordinates of every body of a scene, with planar kinematics on them."""

    def __init__(self, scene: Scene):
        self.scene = scene
        self.all: list[Coordinate] = []
        for body in scene.bodies.values():
            kinds = ("x", "y", "theta") if body.rotates else ("x", "y")
            for kind in kinds:
                self.all.append(
                    Coordinate(
                        body.name,
                        kind,
                        sp.Symbol(f"{kind}_{body.name}", real=True),
                        sp.Symbol(f"{kind}dot_{body.name}", real=True),
                        sp.Symbol(f"{kind}ddot_{body.name}", real=True),
                    )
                )
        self._by_key = {(c.body, c.kind): c for c in self.all}

    def of(self, body: str, kind: str) -> Coordinate:
        return self._by_key[(body, kind)]

    def angle(self, body: str) -> sp.Expr:
        """The body's angle, zero for a point mass."""
        c = self._by_key.get((body, "theta"))
        return c.q if c else sp.Integer(0)

    def angular_velocity(self, body: str) -> sp.Expr:
        c = self._by_key.get((body, "theta"))
        return c.u if c else sp.Integer(0)

    def ddt(self, expr: sp.Expr) -> sp.Expr:
        """Total time derivative of an expression in the q and u symbols."""
        present = expr.free_symbols if isinstance(expr, sp.Basic) else set()
        return sum(
            (sp.diff(expr, c.q) * c.u for c in self.all if c.q in present),
            sum((sp.diff(expr, c.u) * c.a for c in self.all if c.u in present), sp.Integer(0)),
        )

    def orientation(self, body: str) -> sp.Expr:
        """The body's angle from the world's axes: its reference angle plus its turn."""
        return self.scene.bodies[body].angle + self.angle(body)

    def rotated(self, body: str, offset) -> sp.Matrix:
        """A body-frame offset turned into the world frame by the body's orientation."""
        th = self.orientation(body)
        if th == 0:
            return sp.Matrix(offset)
        rotation = sp.Matrix([[sp.cos(th), -sp.sin(th)], [sp.sin(th), sp.cos(th)]])
        return rotation * sp.Matrix(offset)

    def position(self, body: str | None, offset=(0, 0)) -> sp.Matrix:
        """World position of the material point at a body-frame offset from the center of mass
        (coordinates are displacements from the reference configuration, where the center is at
        the body's `at`); with no body, `offset` is a point of the ground."""
        if body is None:
            return sp.Matrix(offset)
        at = self.scene.bodies[body].at
        center = sp.Matrix([at[0] + self.of(body, "x").q, at[1] + self.of(body, "y").q])
        return center + self.rotated(body, offset)

    def velocity(self, body: str | None, world_offset) -> sp.Matrix:
        """Velocity of a body's material point at a world offset from its center (zero on the ground)."""
        if body is None:
            return sp.zeros(2, 1)
        return self.material_velocity(body, sp.Matrix(world_offset))

    def material_velocity(self, body: str, world_offset: sp.Matrix) -> sp.Matrix:
        """Rigid-body velocity v = v_cm + omega z x r of the material point at a world offset r."""
        omega = self.angular_velocity(body)
        return sp.Matrix(
            [
                self.of(body, "x").u - omega * world_offset[1],
                self.of(body, "y").u + omega * world_offset[0],
            ]
        )

    def at_rest_in_reference(self) -> dict[sp.Symbol, int]:
        """Every coordinate and velocity zero: the reference configuration, at rest."""
        return {s: 0 for c in self.all for s in (c.q, c.u)}

    @property
    def accelerations(self) -> list[sp.Symbol]:
        return [c.a for c in self.all]

    @property
    def state(self) -> set[sp.Symbol]:
        return {s for c in self.all for s in (c.q, c.u)}


def solve_gaps(scene: Scene, coords: Coordinates, sample=None, keep: Coordinate | None = None,
               heading: dict | None = None, at: dict | None = None,
               integrals: tuple[sp.Expr, ...] = ()) -> dict[sp.Symbol, sp.Expr]:
    """Solve every constraint gap for one coordinate, preferring translations to angles;
    the coordinates left over are the free ones. `sample` (an expression's float value at sample
    parameters) tells the branch through the reference where simplification cannot (a cord
    placed at an angle: |sin(theta0)| is sin(theta0) only over the parameter ranges). `keep` is
    left free where another coordinate can be solved for instead (a state's coordinate: a bob's x
    where it passes the bottom, where y is extremal and x(y) has no derivative). `heading` (+1,
    -1 or 0 by coordinate symbol: the way a motion leaves the reference) picks between two
    branches that both pass through it (a bead leaving a bowl's rim downward). `at` (coordinate
    values) is the configuration the branches must pass through, if not the reference (a state
    the motion starts from). `integrals` are sums of the coordinates the motion keeps besides the
    gaps (derive.mechanics.first_integrals: a rod's center of mass over a smooth floor), solved
    the same way.

    Raises ValueError when a gap cannot be solved for any remaining coordinate.
    """
    order = sorted(coords.all, key=lambda c: (c == keep, c.kind == "theta"))
    reference = {c.q: (at or {}).get(c.q, sp.Integer(0)) for c in coords.all}
    solved: dict[sp.Symbol, sp.Expr] = {}
    named = [(c.name, gap) for c in scene.constraints for gap in c.gaps(coords)]
    for name, gap in named + [("kept by a momentum", gap) for gap in integrals]:
        gap = gap.xreplace(solved)
        # One root, or else (a cord's circle: y = -sqrt(L^2 - x^2) or +...) the one branch
        # through the reference configuration, where every coordinate is zero, or else the one
        # that moves the way `heading` says; `keep` last of all.
        candidates = [k for k in order if k.q not in solved and gap.has(k.q)]

        # Each candidate's roots only when a pick asks for them, in the picks' order: sympy's
        # solve for an angle in a trigonometric gap with a symbolic placement takes minutes,
        # and a translation that solves the gap alone (a pin's x) makes it unneeded.
        @functools.cache
        def found(k: Coordinate) -> list[sp.Expr]:
            return _turned_back(roots(gap, k.q), reference, sample, k.q) if k.kind == "theta" else roots(gap, k.q)

        @functools.cache
        def through(k: Coordinate) -> list[sp.Expr]:
            return [r for r in found(k) if _through(r.xreplace(reference) - reference[k.q], sample)]

        picks = [lambda k: found(k)[0] if len(found(k)) == 1 else None,
                 lambda k: through(k)[0] if len(through(k)) == 1 else None,
                 lambda k: _heading(through(k), k, heading, sample, reference)]
        chosen = next(((k, root) for pick in picks for k in candidates if k != keep
                       if (root := pick(k)) is not None), None)
        chosen = chosen or next(((k, root) for pick in picks for k in candidates if k == keep
                                 if (root := pick(k)) is not None), None)
        if chosen is None:
            raise ValueError(f"the constraint {name} could not be solved for any coordinate")
        candidate, root = chosen
        solved = {q: v.xreplace({candidate.q: root}) for q, v in solved.items()}
        solved[candidate.q] = root
    return solved


def _turned_back(found: list[sp.Expr], reference: dict, sample, q: sp.Symbol) -> list[sp.Expr]:
    """An angle q's roots, each turned by whole turns to pass nearest the reference: sympy gives
    acos(c) and 2 pi - acos(c) for cos(theta) = c, and the second is the branch -acos(c) through
    the reference that a body turning clockwise from it takes. (The reference may be a state the
    motion starts from, its angle many turns from the placement's: a ball that has rolled.)"""
    if sample is None:
        return found
    result = []
    for r in found:
        try:
            turns = round((sample(r.xreplace(reference)) - sample(reference[q])) / (2 * sp.pi.evalf()))
        except (TypeError, ValueError):
            turns = 0
        result.append(r - 2 * sp.pi * turns if turns else r)
    return result


def _through(offset: sp.Expr, sample) -> bool:
    """Whether a root passes through the reference configuration (its value there is zero)."""
    if sp.simplify(offset) == 0:
        return True
    if sample is None:
        return False
    try:
        return abs(sample(offset)) <= 1e-12
    except (TypeError, ValueError):
        return False


def roots(gap: sp.Expr, q: sp.Symbol) -> list[sp.Expr]:
    """The roots of a gap in one coordinate; none where sympy cannot solve for it (a cord's
    tangent angles in a block's position)."""
    try:
        return sp.solve(gap, q)
    except NotImplementedError:
        return []


def _heading(branches: list[sp.Expr], k: Coordinate, heading: dict | None, sample, at: dict) -> sp.Expr | None:
    """Of branches through the configuration `at`, the one that moves k the way `heading` says for
    a small step of the other coordinates the way they head. A coordinate that does not head
    either way yet (a bead's x at a bowl's rim, where it falls straight down) is stepped both
    ways: the branches are real on one side only, the side the motion can take."""
    if heading is None or sample is None or not heading.get(k.q) or len(branches) < 2:
        return None
    others = [q for q in heading if q != k.q]
    still = [q for q in others if not heading[q]]
    for signs in ([1] * len(still), [-1] * len(still)):
        step = {q: at[q] + sp.Rational(heading[q] or signs[still.index(q)], 10**6) for q in others}
        matching = []
        for branch in branches:
            try:
                value = sample(branch.xreplace(step).xreplace({q: at[q] for q in branch.free_symbols if q in heading})
                               - at[k.q])
            except (TypeError, ValueError):
                continue
            if value * heading[k.q] > 0:
                matching.append(branch)
        if len(matching) == 1:
            return matching[0]
        if not still:
            break
    return None
