"""Small oscillations about the reference configuration of a one-degree-of-freedom scene.

The constraints are solved for the dependent coordinates (translations before angles),
the solved acceleration of the free coordinate is expanded to first order about the
reference configuration at rest, and q'' = -omega^2 q gives the angular frequency.

>>> import sympy as sp
>>> from derive.parts.gravity import Gravity
>>> from derive.parts.pin import Pin
>>> from derive.model.scene import Body, Scene
>>> M, g, d, I = sp.symbols("M g d I", positive=True)
>>> scene = Scene({"bob": Body("bob", "custom", M, {}, I)}, (Pin("pivot", "bob", (0, d)),), Gravity(g))
>>> from derive.mechanics import lagrange
>>> small_oscillation(scene, lagrange.derive(scene)).quantity("omega")
sqrt(M*d*g/(I + M*d**2))
"""
from __future__ import annotations

from dataclasses import dataclass, field

import sympy as sp

from derive.mechanics.derivation import EXACT_PERIOD, GROWTH_RATE, PERIOD, Derivation, nullspace, solve_linear
from derive.text.steps import Step
from derive.core.tidying import root, tidy
from derive.model.kinematics import Coordinate, Coordinates, solve_gaps
from derive.model.scene import Scene


class OscillationError(ValueError):
    """The scene has no small oscillation about its reference configuration."""


@dataclass(frozen=True)
class Oscillation:
    """The linearized motion q'' = -stiffness * q about the reference configuration."""

    coordinate: Coordinate
    stiffness: sp.Expr
    steps: tuple[Step, ...]
    stable: bool
    #: The free direction of the coordinates at the reference, its own coordinate's entry 1.
    direction: tuple = ()
    #: True when the sign of the stiffness holds for every value of the symbols; otherwise it
    #: was read at sample parameters, and every variant must check it (Solution.conditions).
    proven: bool = True
    #: c in q'' = -k q - c q' (a damper): the oscillation is at omega^2 = k - c^2/4 while that is
    #: positive (underdamped; Solution.conditions checks it for every variant).
    damping: sp.Expr = sp.Integer(0)
    #: Each unknown's first-order change per unit of the coordinate along the free direction (a
    #: tension's, a normal force's: whether it changes sign where it is zero at the equilibrium).
    first_order: dict = field(default_factory=dict)

    def quantity(self, name: str) -> sp.Expr:
        """omega or period (stable), growth_rate (unstable)."""
        k, c = self.stiffness, self.damping
        if name == "growth_rate":
            if self.stable:
                raise OscillationError("the equilibrium is stable: it oscillates, it has no growth rate")
            return root(-k) if c == 0 else tidy(root(c**2 / 4 - k) - c / 2)
        if not self.stable:
            raise OscillationError(f"the equilibrium is unstable (q'' = {sp.sstr(-k)} q): ask for growth_rate")
        square = k if c == 0 else tidy(k - c**2 / 4)
        return root(square) if name == "omega" else 2 * sp.pi * root(1 / square)


class OscillationLimit(OscillationError):
    """A scene whose oscillation derive cannot yet find (an engine limit, not the file's fault)."""


class NotAPendulum(OscillationError):
    """The equation of motion is not q'' = -w0^2 sin(q): the period at an amplitude has no elliptic
    closed form here (derive.mechanics.durations.period integrates it)."""


def small_oscillation(scene: Scene, derivation: Derivation, sample=None) -> Oscillation:
    """Angular frequency and period of small oscillations about the reference configuration.

    The constraints are linearized, not solved: their Jacobian at the reference configuration
    has one free direction v (one degree of freedom), the coordinate q_k with the largest say in
    it (an angle first) measures the motion, q = v q_k to first order. The accelerations and
    forces z solve A(q) z = b(q) at rest; along q = v s, z = z0 + s z1 + O(s^2) with z0 their
    values at the reference (an equilibrium: every acceleration zero) and z1 from
    d/ds (A z - b) = 0 at s = 0, one linear solve with A at the reference. Curved contacts (a
    ball in a bowl), cords and linkages need no closed-form solution of their constraints.
    Where the sign of q''/q is not decided by the symbols' assumptions, `sample` (a function of
    an expression giving its float value at sample parameters) decides it, and the Oscillation
    says so (`proven` False).
    """
    coords = Coordinates(scene)
    free = free_directions(scene, coords)
    if len(free) != 1:
        raise OscillationError(f"small oscillations need one degree of freedom; the scene has {len(free)}")
    (direction,) = free
    order = sorted(range(len(coords.all)), key=lambda i: (coords.all[i].kind != "theta", i))
    k = next(i for i in order if direction[i] != 0)
    direction = (direction / direction[k]).applyfunc(tidy)
    coordinate = coords.all[k]
    equilibrium = at_equilibrium(derivation, coords)
    first = first_order(derivation, coords, direction, equilibrium)
    stiffness = tidy(-first[coordinate.a], scene.placed)
    proven = stiffness.is_positive is True or stiffness.is_negative is True
    if proven:
        stable = bool(stiffness.is_positive)
    elif sample is None or sample(stiffness) == 0:
        raise OscillationError(f"cannot decide whether q'' = {sp.sstr(-stiffness)} q is stable for all parameters")
    else:
        stable = sample(stiffness) > 0
    damping = _damping(scene, derivation, coords, direction, coordinate)
    q, rate = coordinate.q, coordinate.u  # the coordinate's own rate, as every other step names it
    linear = Step("The equation of motion to first order in a small displacement from rest"
                  + (" and in its rate (the damping)" if damping else ""),
                  (sp.Eq(coordinate.a, -stiffness * q - damping * rate),))
    oscillation = Oscillation(coordinate, stiffness, (), stable, tuple(direction), proven, damping)
    if stable:
        steps = (linear, Step("Angular frequency and period of small oscillations" +
                              (", the damping lowering the frequency" if damping else ""),
                              (sp.Eq(sp.Symbol("omega"), oscillation.quantity("omega")),
                               sp.Eq(PERIOD, oscillation.quantity("period")))))
    else:
        steps = (linear, Step("Unstable: a small displacement grows exponentially, at the rate",
                              (sp.Eq(GROWTH_RATE, oscillation.quantity("growth_rate")),)))
    return Oscillation(coordinate, stiffness, steps, stable, tuple(direction), proven, damping, first)


def free_directions(scene: Scene, coords: Coordinates) -> list[sp.Matrix]:
    """The directions the coordinates may move in from the reference configuration to first
    order: the null space of the constraints' Jacobian there (every coordinate's own direction
    where nothing constrains them).

    >>> from derive.model.scene import Body, Scene
    >>> scene = Scene({"ball": Body("ball", "point", sp.Symbol("m"), {})})
    >>> [list(v) for v in free_directions(scene, Coordinates(scene))]
    [[1, 0], [0, 1]]
    """
    positions = [c.q for c in coords.all]
    gaps = [g for c in scene.constraints for g in c.gaps(coords)]
    if not gaps:
        return [sp.Matrix([1 if i == j else 0 for j in range(len(positions))]) for i in range(len(positions))]
    jacobian = sp.Matrix(gaps).jacobian(positions).xreplace({q: 0 for q in positions})
    return [tidy(x) for x in nullspace(jacobian)]


def at_equilibrium(derivation: Derivation, coords: Coordinates) -> dict:
    """The accelerations and forces in the reference configuration at rest, which must be an
    equilibrium (every acceleration zero); an engine limit otherwise."""
    equilibrium = derivation.at(coords.at_rest_in_reference()).raw
    moving = sorted((c for c in coords.all if not sp.simplify(equilibrium[c.a]).equals(0)), key=lambda c: c.kind != "theta")
    if moving:
        what = "angular acceleration" if moving[0].kind == "theta" else f"acceleration along {moving[0].kind}"
        raise OscillationLimit(f"find the equilibrium of a scene placed away from it (released at rest there, the "
                               f"{moving[0].body}'s {what} is not zero): place the bodies at the equilibrium with at: "
                               "and angle:, and give a swing's amplitude as the ask's amplitude:")
    return equilibrium


def first_order(derivation: Derivation, coords: Coordinates, direction, equilibrium: dict) -> dict:
    """z1 of every acceleration and force z = z0 + s z1 at rest along q = direction * s: from
    d/ds (A z - b) = 0 at s = 0, one linear solve with A at the reference (z0: `equilibrium`)."""
    s = sp.Dummy("s")
    at_rest = {c.u: 0 for c in coords.all}
    first = {u: sp.Dummy(f"d{u}") for u in derivation.unknowns}
    along = {c.q: direction[i] * s for i, c in enumerate(coords.all)}
    linear_equations = []
    for e in derivation.at_rest_equations:
        residual = (e.lhs - e.rhs).xreplace(at_rest).xreplace(along)
        residual = residual.xreplace({u: equilibrium[u] + s * first[u] for u in derivation.unknowns})
        linear_equations.append(sp.Eq(sp.diff(residual, s).xreplace({s: 0}), 0))
    solved = solve_linear(linear_equations, list(first.values()), derivation.placed).raw
    return {u: solved[first[u]] for u in derivation.unknowns}


def _damping(scene: Scene, derivation: Derivation, coords: Coordinates, direction, coordinate: Coordinate) -> sp.Expr:
    """c in q'' = -k q - c q': minus the slope of the free coordinate's acceleration in its rate,
    moving through the reference configuration along the free direction (terms in the rate
    squared are second order). Zero unless a part dissipates (a damper)."""
    if all(part.dissipation(coords) == 0 for part in scene.parts):
        return sp.Integer(0)
    w = sp.Dummy("w")
    state = {c.q: 0 for c in coords.all}
    state.update({c.u: direction[i] * w for i, c in enumerate(coords.all)})
    acceleration = derivation.at(state).raw[coordinate.a]
    return tidy(-sp.diff(acceleration, w).xreplace({w: 0}))


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
        raise NotAPendulum("the exact period is for pendulum-like motion, q'' = -w0^2 sin(q)")
    rate = root(-ratio)
    period = 4 * sp.elliptic_k(sp.sin(amplitude / 2) ** 2) / rate
    chi, k = sp.symbols("chi k", positive=True)
    steps = (
        Step("The equation of motion has the pendulum form", (sp.Eq(linear.coordinate.a, ratio * sp.sin(q)),)),
        Step("Energy from the turning point; the substitution below makes the time an elliptic integral",
             (sp.Eq(sp.sin(q / 2), k * sp.sin(chi)), sp.Eq(EXACT_PERIOD, 4 * sp.Integral(1 / (rate * sp.sqrt(1 - k**2 * sp.sin(chi) ** 2)),
                                                     (chi, 0, sp.pi / 2))),)),
        Step("The complete elliptic integral of the first kind", (sp.Eq(EXACT_PERIOD, period),)),
    )
    return period, steps
