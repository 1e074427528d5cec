"""Answers to a problem's asked quantities, from the scene's derivations, with their checks.

A `Solution` derives lazily: an inertia question never runs the dynamics, a question
about a force runs both routes once. Each answer is an exact expression (in the
parameter symbols, SI units), checked by an independent route and for dimensions.

>>> from derive.problem import load
>>> solution = Solution(load("rod_endpoint"))
>>> solution.expression("I")
L**2*m/3
"""
from __future__ import annotations

import random
from dataclasses import dataclass
from functools import cached_property

import sympy as sp

from derive import inertia, units
from derive.mechanics import joints, lagrange, newton_euler
from derive.mechanics.derivation import Derivation, Step
from derive.mechanics.kinematics import Coordinates
from derive.mechanics.oscillation import Oscillation, OscillationError, small_oscillation
from derive.problem import Ask, Problem, ProblemError

ROUTES = ("lagrange", "newton_euler")


class CheckFailure(RuntimeError):
    """Two routes of derivation disagree: a bug in the engine, never bad input."""


@dataclass(frozen=True)
class Check:
    name: str
    passed: bool
    method: str
    detail: str


class Solution:
    """Everything derived for one problem, computed on first use."""

    def __init__(self, problem: Problem):
        self.problem = problem
        self.scene = problem.scene

    @cached_property
    def coordinates(self) -> Coordinates:
        return Coordinates(self.scene)

    @cached_property
    def derivations(self) -> dict[str, Derivation]:
        try:
            return {
                "lagrange": lagrange.derive(self.scene, self.coordinates),
                "newton_euler": newton_euler.derive(self.scene, self.coordinates),
            }
        except ValueError as error:
            raise self.problem.error("scene", str(error)) from None

    @cached_property
    def oscillations(self) -> dict[str, Oscillation]:
        try:
            return {route: small_oscillation(self.scene, d) for route, d in self.derivations.items()}
        except OscillationError as error:
            raise self.problem.error("ask", str(error)) from None

    def _route_expression(self, ask: Ask, route: str) -> sp.Expr:
        q = ask.quantity
        if q.kind == "small_oscillation":
            oscillation = self.oscillations[route]
            return oscillation.omega if q.detail == "omega" else oscillation.period
        derivation = self.derivations[route]
        if q.kind == "acceleration":
            return derivation.solution[self.coordinates.of(q.target, q.detail).a]
        if q.kind == "angular_acceleration":
            return derivation.solution[self.coordinates.of(q.target, "theta").a]
        if q.kind == "force":
            return derivation.solution[joints.forces(self.scene.constraint(q.target))[q.detail]]
        raise AssertionError(q.kind)

    def _inertia(self, ask: Ask) -> sp.Expr:
        body = self.scene.bodies[ask.quantity.target]
        if ask.quantity.detail is None:
            return body.inertia
        return inertia.moment_of_inertia(body.shape, ask.quantity.detail).substitute(body.mass, body.sizes)

    def expression(self, name: str) -> sp.Expr:
        """The exact answer, in the parameter symbols, for SI values of the parameters."""
        ask = self.problem.asks[name]
        if ask.quantity.kind == "inertia":
            result = self._inertia(ask)
        else:
            result = self._route_expression(ask, "lagrange")
        leftover = result.free_symbols - {p.symbol for p in self.problem.parameters.values()}
        if leftover:
            names = ", ".join(sorted(map(str, leftover)))
            raise self.problem.error(f"ask.{name}.of", f"the answer depends on the state of motion ({names})")
        return result

    @cached_property
    def expressions(self) -> dict[str, sp.Expr]:
        return {name: self.expression(name) for name in self.problem.asks}

    def steps(self) -> dict[str, list[Step]]:
        """The derivation steps a worked solution shows, by route."""
        kinds = {a.quantity.kind for a in self.problem.asks.values()}
        if kinds == {"inertia"}:
            return {"integration": [self._inertia_steps(a) for a in self.problem.asks.values()]}
        result = {route: list(d.steps) for route, d in self.derivations.items()}
        if "small_oscillation" in kinds:
            for route in result:
                result[route] += self.oscillations[route].steps
        return result

    def _inertia_steps(self, ask: Ask) -> Step:
        body = self.scene.bodies[ask.quantity.target]
        if ask.quantity.detail is None:
            return Step(f"Moment of inertia of the {body.name}", (sp.Eq(sp.Symbol("I"), body.inertia),))
        derived = inertia.moment_of_inertia(body.shape, ask.quantity.detail)
        shape = inertia.SHAPES[body.shape]
        mapping = {inertia.M: body.mass, **{shape.sizes[k]: v for k, v in body.sizes.items()}}
        return Step(
            f"Integrate over the {body.shape} (mass from the same uniform density)",
            (
                sp.Eq(sp.Symbol("M"), derived.mass_integral.xreplace(mapping)),
                sp.Eq(sp.Symbol("I"), derived.integral.xreplace(mapping)),
                sp.Eq(sp.Symbol("I"), derived.I.xreplace(mapping)),
            ),
        )

    # -- checks --------------------------------------------------------------------------

    def checks(self) -> list[Check]:
        """Every independent check that applies: routes, parallel axes, dimensions."""
        result = [self._dimension_check()]
        kinds = {a.quantity.kind for a in self.problem.asks.values()}
        if kinds - {"inertia"}:
            result.append(self._routes_check())
        for ask in self.problem.asks.values():
            if ask.quantity.kind == "inertia" and ask.quantity.detail is not None:
                check = self._parallel_axis_check(ask)
                if check:
                    result.append(check)
        return result

    def _dimension_check(self) -> Check:
        found = {}
        for name, ask in self.problem.asks.items():
            dimension = units.expression_dimension(self.expressions[name], self.problem.symbol_units)
            wanted = units.dimension(units.parse_unit(ask.unit))
            if not units.same_dimension(dimension, wanted):
                raise self.problem.error(
                    f"ask.{name}.unit", f"declared {ask.unit}, but the derived answer has dimension {dimension or 'none'}"
                )
            found[name] = ask.unit
        return Check("dimensions", True, "dimensional analysis", ", ".join(f"{k} [{v}]" for k, v in found.items()))

    def _routes_check(self) -> Check:
        """Lagrange's method and Newton–Euler give the same accelerations, forces and answers."""
        pairs = {}
        lag, ne = self.derivations["lagrange"], self.derivations["newton_euler"]
        for unknown in lag.unknowns:
            pairs[str(unknown)] = (lag.solution[unknown], ne.solution[unknown])
        for name, ask in self.problem.asks.items():
            if ask.quantity.kind != "inertia":
                pairs[name] = tuple(self._route_expression(ask, r) for r in ROUTES)
        methods = set()
        for label, (a, b) in pairs.items():
            method = agree(a, b)
            if method is None:
                raise CheckFailure(f"{self.problem.id}: Lagrange and Newton–Euler disagree on {label}: {a} vs {b}")
            methods.add(method)
        method = "symbolic" if methods == {"symbolic"} else "symbolic and numeric"
        return Check("lagrange_vs_newton_euler", True, method, f"{len(pairs)} quantities agree")

    def _parallel_axis_check(self, ask: Ask) -> Check | None:
        body = self.scene.bodies[ask.quantity.target]
        derived = inertia.moment_of_inertia(body.shape, ask.quantity.detail)
        if derived.distance_from_center == 0:
            return None
        center_axis = inertia.PLANAR_AXIS[body.shape]
        central = inertia.moment_of_inertia(body.shape, center_axis).I
        theorem = inertia.parallel_axis(central, inertia.M, derived.distance_from_center)
        if agree(theorem, derived.I) is None:
            raise CheckFailure(f"{self.problem.id}: the parallel-axis theorem gives {theorem}, integration {derived.I}")
        return Check(
            "parallel_axis", True, "symbolic",
            f"{ask.name}: integration equals I_cm + M d^2 with d = {derived.distance_from_center}",
        )


def agree(a: sp.Expr, b: sp.Expr, trials: int = 4) -> str | None:
    """'symbolic' when a - b simplifies to zero, 'numeric' when it vanishes at random points
    (to 30 digits), None when they differ."""
    difference = sp.simplify(a - b)
    if difference == 0:
        return "symbolic"
    symbols = sorted(difference.free_symbols, key=str)
    rng = random.Random(0)
    for _ in range(trials):
        point = {s: sp.Rational(rng.randint(11, 99), 37) for s in symbols}
        scale = abs(sp.N(a.xreplace(point), 30)) + 1
        if abs(sp.N(difference.xreplace(point), 30)) > scale * sp.Float("1e-25"):
            return None
    return "numeric"
