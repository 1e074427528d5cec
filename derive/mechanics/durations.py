"""How long a motion takes: the time along a state's path from its start (in closed form where
the acceleration along it is constant, else a quadrature), and the period of a swing at any
amplitude (twice the time between its turning points).

>>> import sympy as sp
>>> from derive.mechanics import lagrange
>>> from derive.model.kinematics import Coordinates
>>> from derive.mechanics.reaching import Gets
>>> from derive.mechanics.states import reach, rest
>>> from derive.parts.gravity import Gravity
>>> from derive.model.scene import Body, Scene
>>> m, g = sp.symbols("m g", positive=True)
>>> scene = Scene({"ball": Body("ball", "point", m, {})}, gravity=Gravity(g))
>>> coords = Coordinates(scene)
>>> fallen = reach(scene, coords, rest(coords), Gets(coords.of("ball", "y"), -1), lagrange.derive(scene, coords))
>>> duration(fallen.path, fallen.end)[0]
sqrt(2)/sqrt(g)
"""
from __future__ import annotations

import sympy as sp

from derive.mechanics.derivation import EXACT_PERIOD, Derivation
from derive.text.steps import Step
from derive.core.tidying import root, tidy
from derive.model.kinematics import Coordinate, Coordinates, solve_gaps
from derive.mechanics.reaching import Path, Reached, Stops
from derive.mechanics.states import reach
from derive.text.prose import Sentence
from derive.model.scene import Scene


def duration(path: Path, end: sp.Expr) -> tuple[sp.Expr, Step]:
    """The time the motion takes along the path from its start to s = `end`: t = integral of
    ds/|s'|. Where s'' is constant (s'^2 = K/k linear in s) in closed form, t = (s'1 - s'0)/s'';
    else as an integral, evaluated numerically (derive.numbers.numeric vouches for its digits by two
    precisions)."""
    s, s0 = path.s, path.start[path.s]
    squared = tidy(path.kinetic / path.inertia)  # s'^2
    polynomial = sp.Poly(squared, s) if squared.is_polynomial(s) else None
    if polynomial is not None and polynomial.degree() <= 1:
        slope = polynomial.coeff_monomial(s)
        acceleration = slope / 2  # d(s'^2)/dt = 2 s' s'' = slope s'
        if slope == 0:  # s' constant: its square as tidied (K/k at s0 alone folds worse: a flying, spinning ball)
            time = tidy((end - s0) / (path.direction * root(squared)))
            said = Sentence(("The rate of ", s, " does not change along the way: the time is the distance over that "
                             "rate, at constant speed."))
        else:
            time = tidy((path.rate(end) - path.rate(s0)) / acceleration)
            said = Sentence(("The square of the rate of ", s, " is linear in it along the way, so the acceleration is "
                             "constant, ", sp.Eq(path.coordinate.a, tidy(acceleration)), ": at constant acceleration "
                             "the time is the change in the rate divided by it."))
        symbol = sp.Symbol("t")
        return time, Step("The acceleration along the way is constant, so the time is the change in the rate divided "
                          "by it", (sp.Eq(symbol, time),), sentences=(said,))
    # Over w in [0, 1], the fraction of the way w^2 (3 - 2 w), flat at both ends: the 1/sqrt
    # singularities where the motion starts from rest or ends at a turning point become smooth
    # (mpmath's tanh-sinh quadrature then gives 20 digits at 35 where over the fraction itself it
    # gave 11). Not simplified: sympy would fold the polynomials and cancel digits near the ends.
    w = sp.Dummy("w")
    where = s0 + w**2 * (3 - 2 * w) * (end - s0)
    # One root (w (1 - w) >= 0 inside it): a sum of two integrands, which simplifying would split
    # the integral into, diverges at a turning point in each part.
    integrand = 6 * sp.sqrt(path.inertia.xreplace({s: where}) * (w * (1 - w)) ** 2 / path.kinetic.xreplace({s: where}))
    time = sp.Abs(end - s0) * sp.Integral(integrand, (w, 0, 1))
    said = Sentence(("The square of the rate of ", s, " is not linear in it, so the acceleration changes along the "
                     "way: the time is the integral of each step in it over the rate there, ",
                     sp.Integral(1 / sp.Abs(path.coordinate.u), (s, s0, end)), ", evaluated by quadrature (its digits "
                     "checked at two precisions)."))
    return time, Step("The acceleration along the way is not constant: the time is the integral, from the start, of "
                      "each step divided by the rate there, evaluated numerically", (sp.Eq(sp.Symbol("t"), time),),
                      sentences=(said,))


def period(scene: Scene, coords: Coordinates, coordinate: Coordinate, amplitude: sp.Expr, derivation: Derivation,
           sample) -> tuple[sp.Expr, tuple[Step, ...], Reached]:
    """The period of a scene of one degree of freedom swinging about its placement (a stable
    equilibrium) with `amplitude` in `coordinate`: released from rest there, it gets to its
    turning point on the other side in half a period (energy along the motion, `reach`; the time
    by `duration`), and comes back the same way. Also the state of that turning point."""
    dependent = solve_gaps(scene, coords, sample, keep=coordinate)
    released = {c.q: sp.sympify(dependent.get(c.q, c.q)).xreplace({coordinate.q: amplitude})  # safe: engine exprs
                for c in coords.all}
    start = {**released, **{c.u: sp.Integer(0) for c in coords.all}}
    turned = reach(scene, coords, start, Stops(), derivation, sample)
    half, step = duration(turned.path, turned.end)
    steps = (Step("Released from rest at the amplitude, the turning point on the other side",
                  tuple(sp.Eq(c.q, turned.values[c.q]) for c in coords.all if c == coordinate)),
             *turned.steps, step,
             Step("It comes back the same way: the period is twice that time", (sp.Eq(EXACT_PERIOD, 2 * half),)))
    return 2 * half, steps, turned
