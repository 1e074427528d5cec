"""Small oscillations about the reference configuration of a one-degree-of-freedom scene.

The constraints are solved for the dependent coordinates (translations before angles),
the solved acceleration of the free coordinate is expanded to first order about the
reference configuration at rest, and q'' = -omega^2 q gives the angular frequency.

>>> import sympy as sp
>>> from derive.parts.gravity import Gravity
>>> from derive.parts.pin import Pin
>>> from derive.scene import Body, Scene
>>> M, g, d, I = sp.symbols("M g d I", positive=True)
>>> scene = Scene({"bob": Body("bob", "custom", M, {}, I)}, (Pin("pivot", "bob", (0, d)),), Gravity(g))
>>> from derive.mechanics import lagrange
>>> small_oscillation(scene, lagrange.derive(scene)).quantity("omega")
sqrt(M*d*g/(I + M*d**2))
"""
from __future__ import annotations

from dataclasses import dataclass

import sympy as sp

from derive.mechanics.derivation import Derivation, Step, root, tidy
from derive.mechanics.kinematics import Coordinate, Coordinates, solve_gaps
from derive.scene import Scene


class OscillationError(ValueError):
    """The scene has no small oscillation about its reference configuration."""


@dataclass(frozen=True)
class Oscillation:
    """The linearized motion q'' = -stiffness * q about the reference configuration."""

    coordinate: Coordinate
    stiffness: sp.Expr
    steps: tuple[Step, ...]

    @property
    def stable(self) -> bool:
        return bool(self.stiffness.is_positive)

    def quantity(self, name: str) -> sp.Expr:
        """omega or period (stable), growth_rate (unstable)."""
        if name == "growth_rate":
            if self.stable:
                raise OscillationError("the equilibrium is stable: it oscillates, it has no growth rate")
            return root(-self.stiffness)
        if not self.stable:
            raise OscillationError(f"the equilibrium is unstable (q'' = {sp.sstr(-self.stiffness)} q): ask for growth_rate")
        return root(self.stiffness) if name == "omega" else 2 * sp.pi * root(1 / self.stiffness)


def small_oscillation(scene: Scene, derivation: Derivation) -> Oscillation:
    """Angular frequency and period of small oscillations about the reference configuration."""
    coords = Coordinates(scene)
    try:
        dependent = solve_gaps(scene, coords)
    except ValueError as error:
        raise OscillationError(str(error)) from None
    free = [c for c in coords.all if c.q not in dependent]
    if len(free) != 1:
        raise OscillationError(f"small oscillations need one degree of freedom; the scene has {len(free)}")
    (coordinate,) = free
    at_rest = {c.u: 0 for c in coords.all}
    acceleration = derivation.at({**at_rest, **dependent})[coordinate.a]
    reference = {coordinate.q: 0}
    if not sp.simplify(acceleration.xreplace(reference)).equals(0):
        raise OscillationError("the reference configuration (every angle zero) is not an equilibrium")
    stiffness = tidy(-sp.diff(acceleration, coordinate.q).xreplace(reference))
    if stiffness.is_positive is not True and stiffness.is_negative is not True:
        raise OscillationError(f"cannot decide whether q'' = {sp.sstr(-stiffness)} q is stable for all parameters")
    q = coordinate.q
    linear = Step(f"Linearize about {q} = 0 at rest", (sp.Eq(coordinate.a, -stiffness * q),))
    if stiffness.is_positive:
        omega = root(stiffness)
        steps = (linear, Step("Angular frequency and period of small oscillations",
                              (sp.Eq(sp.Symbol("omega"), omega), sp.Eq(sp.Symbol("T"), 2 * sp.pi * root(1 / stiffness)))))
    else:
        steps = (linear, Step("Unstable: the deviation grows as exp(a t) with growth rate",
                              (sp.Eq(sp.Symbol("a"), root(-stiffness)),)))
    return Oscillation(coordinate, stiffness, steps)


def exact_period(scene: Scene, derivation: Derivation, amplitude: sp.Expr) -> tuple[sp.Expr, tuple[Step, ...]]:
    """The period at any amplitude of a pendulum-like scene, q'' = -w0^2 sin(q).

    Energy conservation from the turning point gives dt = dq / sqrt(2 w0^2 (cos q - cos A));
    with sin(q/2) = k sin(chi), k = sin(A/2), the quarter period is K(k^2)/w0 (sympy's
    elliptic_k takes the parameter m = k^2).
    """
    linear = small_oscillation(scene, derivation)
    coords = Coordinates(scene)
    dependent = solve_gaps(scene, coords)
    q = linear.coordinate.q
    acceleration = derivation.at({**{c.u: 0 for c in coords.all}, **dependent})[linear.coordinate.a]
    ratio = tidy(acceleration / sp.sin(q))
    if q in ratio.free_symbols or not linear.stable:
        raise OscillationError("the exact period is for pendulum-like motion, q'' = -w0^2 sin(q)")
    rate = root(-ratio)
    period = 4 * sp.elliptic_k(sp.sin(amplitude / 2) ** 2) / rate
    chi, k = sp.symbols("chi k", positive=True)
    steps = (
        Step("The equation of motion has the pendulum form", (sp.Eq(linear.coordinate.a, ratio * sp.sin(q)),)),
        Step("Energy from the turning point, and the substitution sin(q/2) = k sin(chi), k = sin(A/2)",
             (sp.Eq(sp.Symbol("T"), 4 * sp.Integral(1 / (rate * sp.sqrt(1 - k**2 * sp.sin(chi) ** 2)),
                                                     (chi, 0, sp.pi / 2))),)),
        Step("The complete elliptic integral of the first kind", (sp.Eq(sp.Symbol("T"), period),)),
    )
    return period, steps
