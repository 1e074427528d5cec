"""What a state of a scene is reached by and along (derive.mechanics.states): the condition that
defines it (a coordinate or a rate getting to a value, the motion stopping, a force falling to
zero), the path the motion follows to it in one free coordinate s, and what is found there.
derive.mechanics.first_root finds where on the path the condition first holds.
"""
from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property

import sympy as sp

from derive.text.steps import Step
from derive.model.kinematics import Coordinate
from derive.core.tidying import root, tidy
from derive.text.prose import Sentence


@dataclass(frozen=True)
class Reached:
    """Every coordinate and velocity in a state (`values`), what must stay positive for the
    motion to get there ((expression, meaning) pairs), the steps that found it, the path the
    motion was followed along (None at the placement), where on the path the state is (`end`,
    the value of its coordinate), and the constraint forces that are zero
    there by its definition (`vanished`: a body leaving its surface); for a state reached
    along no path (a clutch that grips), the time it takes and the step that found it (`took`)."""

    values: dict[sp.Symbol, sp.Expr]
    positive: tuple[tuple[sp.Expr, str], ...] = ()
    steps: tuple[Step, ...] = ()
    path: Path | None = None
    end: sp.Expr | None = None
    vanished: tuple[sp.Symbol, ...] = ()
    took: tuple[sp.Expr, Step] | None = None


@dataclass(frozen=True)
class Gets:
    """The state where a coordinate gets to a value (a displacement from the placement); with
    `measured`, where that expression of the coordinates gets to the value (a block's x measured
    from a plank's end, in the plank's frame), `coordinate` the body's own, kept free first."""

    coordinate: Coordinate
    value: sp.Expr
    measured: sp.Expr | None = None

    def at(self, positions: dict) -> sp.Expr:
        """What gets to the value, where the coordinates are `positions` (q -> expression)."""
        if self.measured is None:
            return positions[self.coordinate.q]
        return self.measured.xreplace(positions)


def measured_from(coords, body: str, kind: str, host: str, offset) -> sp.Expr:
    """The `body`'s x, y (its center) or angle measured in the `host`'s frame from its point at
    `offset` (its frame, from its center of mass): what a state `relative_to` it gets to.

    >>> from derive.model.scene import Body, Scene
    >>> from derive.model.kinematics import Coordinates
    >>> L = sp.Symbol("L", positive=True)
    >>> scene = Scene({"plank": Body("plank", "point", 1, {}), "block": Body("block", "point", 1, {})})
    >>> measured_from(Coordinates(scene), "block", "x", "plank", (L / 2, 0))
    -L/2 + x_block - x_plank
    """
    if kind == "theta":
        return coords.orientation(body) - coords.orientation(host)
    apart = coords.position(body) - coords.position(host, offset)
    phi = coords.orientation(host)
    return (sp.cos(phi) * apart[0] + sp.sin(phi) * apart[1] if kind == "x"
            else -sp.sin(phi) * apart[0] + sp.cos(phi) * apart[1])


@dataclass(frozen=True)
class GetsRate:
    """The state where a coordinate's rate gets to a value (a ball at the top of its flight, where
    its vertical velocity is zero)."""

    coordinate: Coordinate
    value: sp.Expr


@dataclass(frozen=True)
class Stops:
    """The state where the motion stops (a turning point: the highest point, the widest swing)."""


@dataclass(frozen=True)
class Vanishes:
    """The state where a constraint force first falls to zero: a body leaves its surface (the
    normal force), a cord goes slack (its tension); or an expression of the forces does: where a
    grip fails, mu_s^2 N^2 - f^2 (zero where |f| = mu_s N, N > 0; smooth, unlike |f|). `said`:
    what holds while it is positive, and what happens where it falls to zero, in words."""

    force: sp.Expr
    meaning: str  # "the normal force N^bead", for the steps
    said: tuple[Sentence, ...] = ()


@dataclass(frozen=True)
class Path:
    """The motion from a start along its one free coordinate s (`coordinate`): every coordinate
    as a function of s (`positions`), the kinetic energy per s'^2 (`inertia`, k(s)) and where s
    is (`kinetic`, K(s) by the work-energy theorem from the start), and the way s moves
    (`direction`, +1 or -1); `velocities` in s and its rate s' (the coordinate's u)."""

    coordinate: Coordinate
    start: dict
    direction: int
    positions: dict
    velocities: dict
    inertia: sp.Expr
    kinetic: sp.Expr
    line: tuple | None = None  # on a line: where the state is, and the sign function (see `frozen`)
    leaves: sp.Expr | None = None  # the start's rate (from rest, acceleration) in s, whose sign is `direction`
    work: tuple[Sentence, ...] = ()  # what does work along it, and the principle that gives `kinetic`
    kept: tuple = ()  # contact forces its work takes at their start values (derive.mechanics.work)

    @property
    def s(self) -> sp.Symbol:
        return self.coordinate.q

    def rate(self, where: sp.Expr) -> sp.Expr:
        """s' where s = `where`, moving the path's way."""
        return self.direction * root(self.kinetic.xreplace({self.s: where}) / self.inertia.xreplace({self.s: where}))

    @cached_property  # one function per path: Derivation.at caches its solutions by it
    def frozen(self):
        """On a line, the rewriting of a route's equations at the general point that puts their
        coefficients constant along it at the start (`_constant_along`); None elsewhere."""
        return None if self.line is None else _constant_along(self, *self.line)

    @cached_property  # one set of symbols per path, so that a route's solution in them is reused
    def general(self) -> tuple[dict[sp.Symbol, sp.Expr], sp.Dummy, sp.Dummy]:
        """Every coordinate and velocity at a point of the path, in two new symbols for s and s'
        (the route's equations are solved in them, then the state put in): the coordinates' own
        would be moved again where a route differentiates along the motion."""
        where, rate = sp.Dummy(str(self.s), real=True), sp.Dummy(str(self.coordinate.u), real=True)
        return self.values(where, rate, settle=False), where, rate

    def values(self, where: sp.Expr, rate: sp.Expr, settle: bool = True) -> dict[sp.Symbol, sp.Expr]:
        """Every coordinate and velocity where s = `where`, moving at s' = `rate`."""
        at = {self.s: where, self.coordinate.u: rate}
        done = settled if settle else (lambda expr: expr)
        return {**{q: done(p.xreplace({self.s: where})) for q, p in self.positions.items()},
                **{u: done(v.xreplace(at)) for u, v in self.velocities.items()}}


def settled(expr: sp.Expr) -> sp.Expr:
    """tidy, with each root's radicand factored first: where a state lies on a circle, sqrt(R^2 - y^2)
    at y = a root holds a perfect square, which then leaves the root (the routes' linear solve
    in that state took 26 s with it nested, for a ball rolling off a dome)."""
    return tidy(sp.sympify(expr).replace(  # safe: an engine expression; replace works from the leaves up
        lambda e: e.is_Pow and e.exp.is_Rational and not e.exp.is_Integer, lambda e: sp.factor(e.base) ** e.exp))


def _constant_along(path: Path, end: sp.Expr, decide):
    """The rewriting of a route's equations at the path's general point (Path.general) that puts
    each coefficient (of an unknown, or the free term) that does not change along the line at its
    value at the start. On a line a cord's runs keep their directions, but their formulas (roots
    of the distances between the centers) do not say so, and the linear solve in them gave up
    after 60 s for an Atwood machine. A coefficient is constant where, at the middle of the
    parameter ranges, it has its start's value (to 25 digits) at three points between the start and
    the state, each moving at the rate energy gives: an analytic function of s that is not
    constant meets a value at isolated points only."""
    general, where, rate = path.general
    s0 = path.start[path.s]
    probes = [{where: s0 + sp.Rational(k, 4) * (end - s0), rate: path.rate(s0 + sp.Rational(k, 4) * (end - s0))}
              for k in (1, 2, 3)]

    def constant(entry: sp.Expr) -> sp.Expr:
        if not entry.has(where):
            return entry
        start = entry.xreplace({where: s0})
        for probe in probes:
            here = start.xreplace({rate: probe[rate]})  # the difference at 30 digits, before any float
            if abs(decide(entry.xreplace(probe) - here)) > 1e-25 * (1 + abs(decide(here))):
                return entry
        return tidy(start)

    def frozen(equations: list[sp.Eq], unknowns: list[sp.Symbol]) -> list[sp.Eq]:
        matrix, rhs = sp.linear_eq_to_matrix([e.lhs - e.rhs for e in equations], unknowns)
        return [sp.Eq(sum((constant(matrix[i, j]) * u for j, u in enumerate(unknowns)), sp.Integer(0)),
                      constant(rhs[i])) for i in range(len(equations))]
    return frozen
