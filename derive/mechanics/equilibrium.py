"""Where a scene of one degree of freedom rests: its stable equilibrium configuration.

The constraints are solved for the dependent coordinates (`kinematics.solve_gaps`: translations
before angles), which leaves one free coordinate q. Each route then gives the free coordinate's
acceleration from rest at any value of q (Lagrange from the energies and the gaps, Newton–Euler
from forces and torques, each with its own linear solve); the equilibria are the roots of that
acceleration, and a root is stable where the acceleration pulls back toward it (da/dq < 0).
The scene rests at the stable root nearest where the file places it (a spring's block on the
near side of its anchor, not the mirror image beyond it); a scene with none is refused.

>>> import sympy as sp
>>> from derive.mechanics import lagrange
>>> from derive.parts.force import Force
>>> from derive.parts.gravity import Gravity
>>> from derive.parts.pin import Pin
>>> from derive.model.scene import Body, Scene
>>> m, g, L, F = sp.symbols("m g L F", positive=True)
>>> rod = Body("rod", "rod", m, {"length": L}, m * L**2 / 12, at=(0, -L / 2), angle=-sp.pi / 2)
>>> scene = Scene({"rod": rod}, (Pin("hinge", "rod", (-L / 2, 0)),), Gravity(g), loads=(
...     Force("push", "rod", (L / 2, 0), F, sp.Integer(0)),))
>>> equilibrium(scene, lagrange.derive(scene)).value
atan(2*F/(g*m))
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import sympy as sp

from derive.mechanics.derivation import Derivation
from derive.text.steps import Step
from derive.core.tidying import tidy
from derive.model.kinematics import Coordinate, Coordinates, solve_gaps
from derive.model.scene import Scene


class EquilibriumError(ValueError):
    """The scene has no single stable equilibrium (or more than one degree of freedom)."""


class EquilibriumLimit(EquilibriumError):
    """An equilibrium derive cannot yet find (an engine limit, not the file's fault)."""


@dataclass(frozen=True)
class Equilibrium:
    """The free `coordinate` at rest at `value` (a displacement from the reference
    configuration), every coordinate there in `configuration`, and the steps that found it."""

    coordinate: Coordinate
    value: sp.Expr
    configuration: dict
    steps: tuple[Step, ...]

    def position(self, scene: Scene, body: str, detail: str) -> sp.Expr:
        """The body's angle from +x, or its center's x or y, at the equilibrium."""
        kind = "theta" if detail == "angle" else detail
        return tidy(scene.bodies[body].placed(kind) + Coordinates(scene).of(body, kind).q.xreplace(self.configuration))


def equilibrium(scene: Scene, derivation: Derivation, sample=None, resolve=None) -> Equilibrium:
    """The stable equilibrium of a one-degree-of-freedom scene, by one route's equations.

    `sample` (an expression's float value at sample parameters) decides the sign of da/dq where
    the symbols' assumptions do not, and drops roots that are no equilibrium there (a spring of
    zero length, whose direction is undefined); `resolve` puts a root in the form the parameter
    ranges allow (|sin(theta)| is sin(theta) on an incline), raising ValueError where no form
    holds over them."""
    coords = Coordinates(scene)
    try:
        dependent = solve_gaps(scene, coords)
    except ValueError as error:
        raise EquilibriumLimit(f"find the equilibrium: {error}") from None
    free = [c for c in coords.all if c.q not in dependent]
    if len(free) != 1:
        raise EquilibriumError(f"an equilibrium is found for one degree of freedom; the scene has {len(free)}")
    (coordinate,) = free
    q = coordinate.q
    at_rest = {c.u: 0 for c in coords.all}
    acceleration = tidy(derivation.at({**at_rest, **dependent}).raw[coordinate.a])
    found = [_within(r, resolve) for r in _roots(sp.numer(sp.together(acceleration)), q)]
    roots = [r for r in found if r is not None and _rests(acceleration, q, r, sample)]
    slope = sp.diff(acceleration, q)

    def pulls_back(root: sp.Expr) -> bool:
        value = tidy(slope.xreplace({q: root}))
        if value.is_negative is not None:
            return bool(value.is_negative)
        if sample is None:
            raise EquilibriumError(f"cannot decide whether the equilibrium {q} = {sp.sstr(root)} is stable")
        return sample(value) < 0

    stable = [tidy(r) for r in roots if pulls_back(r)]
    if not stable:
        found = ", ".join(sp.sstr(r) for r in roots) or "none"
        raise EquilibriumError(f"the scene has no stable equilibrium (where {q}'' = 0: {found})")
    if len(stable) > 1 and sample is None:
        raise EquilibriumError(f"the scene has {len(stable)} stable equilibria: {', '.join(map(sp.sstr, stable))}")
    value = min(stable, key=lambda r: abs(sample(r))) if len(stable) > 1 else stable[0]  # nearest the placement
    configuration = {c.q: tidy(dependent.get(c.q, c.q).xreplace({q: value})) for c in coords.all}
    steps = (
        Step(f"The constraints solved for the other coordinates, the acceleration of {q} from rest at any {q}",
             (sp.Eq(coordinate.a, acceleration),)),
        Step(f"It rests where that vanishes, and stays where the acceleration pulls back (it falls as {q} grows)",
             (sp.Eq(q, value),)),
    )
    return Equilibrium(coordinate, value, configuration, steps)


def _roots(expr: sp.Expr, q: sp.Symbol) -> list[sp.Expr]:
    """The real roots of expr in q: for A sin(q) + B cos(q) (an angle balanced by torques), the
    two directions tan(q) = -B/A in the textbook's form (sympy's solve writes them by the tangent
    of the half angle); otherwise sympy's solve."""
    expr = sp.expand(sp.expand_trig(expr))
    a, b = expr.coeff(sp.sin(q)), expr.coeff(sp.cos(q))
    if (a != 0 or b != 0) and sp.expand(expr - a * sp.sin(q) - b * sp.cos(q)) == 0 and not (a.has(q) or b.has(q)):
        if a == 0:
            return [sp.pi / 2, -sp.pi / 2]
        direction = sp.atan(tidy(-b / a))
        return [direction, direction + (sp.pi if direction.could_extract_minus_sign() else -sp.pi)]
    return [r for r in sp.solve(expr, q) if not r.has(sp.I)]


def _within(root: sp.Expr, resolve) -> sp.Expr | None:
    """The root in the form the ranges allow, None where no branch of it holds over them."""
    if resolve is None:
        return root
    try:
        return resolve(root)
    except ValueError:  # derive.core.errors.ProblemError: no branch holds over the ranges
        return None


def _rests(acceleration: sp.Expr, q: sp.Symbol, root: sp.Expr, sample) -> bool:
    """Whether the acceleration vanishes there at sample parameters (a finite root where it is
    defined); without `sample`, every root sympy finds."""
    if sample is None:
        return True
    try:
        where, value = sample(root), sample(acceleration.xreplace({q: root}))
    except (TypeError, ValueError, ZeroDivisionError):  # nan, zoo: not a real number
        return False
    return math.isfinite(where) and math.isfinite(value) and abs(value) <= 1e-9 * (1 + abs(where))
