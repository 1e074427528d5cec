"""A top's steady precession as a textbook derives it: the weight's torque about the tip turns the
angular momentum about the vertical, tau = Omega x L (Kleppner & Kolenkow 2nd ed., ch. 7, the
gyroscope; Taylor, Classical Mechanics, ch. 10, the top's steady precession).

About the tip, the weight's torque is m g R sin(theta), horizontal and across the axis. In steady
precession the axis keeps its tilt theta and turns about the vertical at Omega; the angular
momentum about the tip is I3 omega along the axis (omega the spin, the angular velocity's part
along it) and I1 Omega sin(theta) across it, so its horizontal part is
L_h = I3 omega sin(theta) - I1 Omega sin(theta) cos(theta), and dL/dt = Omega x L has the size
Omega L_h. Setting it equal to the torque and dividing by sin(theta) gives the top's condition

    I1 Omega^2 cos(theta) - I3 omega Omega + m g R = 0,

whose two roots are the slow and the fast precession; for a fast top (a question that says so)
the term in Omega^2 is dropped: Omega = m g R/(I3 omega). The engine's routes find the same rates
from the equations of motion in Euler angles (derive.mechanics.fixed_point, both Lagrange's and
Euler's); derive.solution.crosschecks compares them.

>>> m, g, R, I1, I3, w, theta = sp.symbols("m g R I_1 I_3 omega theta", positive=True)
>>> top = steady_precession(I1, I3, m, g, R, w, theta, {"precession.slow", "precession.fast_top"})
>>> top.rates["precession.fast_top"]
R*g*m/(I_3*omega)
>>> top.steps[3].equations
(Eq(I_1*Omega**2*cos(theta) - I_3*Omega*omega + R*g*m, 0),)
"""
from __future__ import annotations

from dataclasses import dataclass

import sympy as sp

from derive.core.tidying import tidy
from derive.text.steps import Step

#: The steady precessions this route gives (the details of a pivot_point ask).
PRECESSIONS = ("precession.slow", "precession.fast", "precession.fast_top")
#: With the fast top's nutation about its steady precession, what the route gives.
TOP_RATES = (*PRECESSIONS, "nutation.fast_top")


@dataclass(frozen=True)
class SteadyTop:
    """The steps, and the rate each asked precession or nutation has (by its detail, TOP_RATES)."""

    steps: tuple[Step, ...]
    rates: dict[str, sp.Expr]


def steady_precession(I1, I3, mass, g, distance, spin, tilt, asked: set[str]) -> SteadyTop:
    """The route for a symmetric top on its tip (I1 about a transverse axis through the tip, I3 about
    its own axis, its center a `distance` from the tip) spinning at `spin` with its axis at `tilt`
    from the vertical, for the precessions and the nutation `asked` (details of TOP_RATES)."""
    Omega, tau, L_h = sp.Symbol("Omega", positive=True), sp.Symbol("tau"), sp.Symbol("L_h")
    torque = mass * g * distance * sp.sin(tilt)
    horizontal = I3 * spin * sp.sin(tilt) - I1 * Omega * sp.sin(tilt) * sp.cos(tilt)
    condition = I1 * Omega**2 * sp.cos(tilt) - I3 * spin * Omega + mass * g * distance
    steps = [
        Step("Torque about the tip: the tip's force acts there and has no moment about it; the weight acts at the "
             "center of mass, on the axis, and its torque about the tip is horizontal, at right angles to the axis, "
             "of size", (sp.Eq(tau, torque),)),
        Step("In steady precession the axis keeps its tilt from the vertical and turns about the vertical at the "
             "rate Omega. The angular momentum about the tip is the spin's, along the axis, and the precession's, "
             "across the axis: the part of the precession's rate across the axis times the moment of inertia about "
             "a transverse axis through the tip. Its horizontal part is", (sp.Eq(L_h, horizontal),)),
        Step("Newton's second law for the rotation about the tip: the torque is the rate of change of the angular "
             "momentum. Its vertical part stays as it is, and its horizontal part L_h turns about the vertical with "
             "the axis at the rate Omega, so that the rate of change is Omega L_h, along the torque", (sp.Eq(torque, Omega * horizontal),)),
        Step("Dividing by the sine of the tilt, the top's condition for steady precession", (sp.Eq(condition, 0),)),
    ]
    rates = {}
    exact = [d for d in ("precession.slow", "precession.fast") if d in asked]
    if exact and sp.cos(tilt) == 0:  # a level axle: the condition is linear in Omega
        rates["precession.slow"] = tidy(mass * g * distance / (I3 * spin))
        steps.append(Step("The axis is level, so the term in the square of Omega is zero: one steady precession",
                          (sp.Eq(Omega, rates["precession.slow"]),), role="solve"))
    elif exact:
        root = sp.sqrt(I3**2 * spin**2 - 4 * I1 * mass * g * distance * sp.cos(tilt))
        rates["precession.slow"] = tidy(2 * mass * g * distance / (I3 * spin + root))
        rates["precession.fast"] = tidy((I3 * spin + root) / (2 * I1 * sp.cos(tilt)))
        named = {"precession.slow": sp.Symbol("Omega_slow"), "precession.fast": sp.Symbol("Omega_fast")}
        steps.append(Step("Solving the quadratic for Omega: the slow precession (its root written with the square root "
                          "in the denominator) and the fast one", tuple(sp.Eq(named[d], rates[d]) for d in exact),
                          role="solve"))
    if "precession.fast_top" in asked:
        rates["precession.fast_top"] = tidy(mass * g * distance / (I3 * spin))
        steps.append(Step("The question treats the top as fast: the spin's angular momentum is much larger than the "
                          "precession's, and the term in the square of Omega is small beside the others. Dropping it",
                          (sp.Eq(-I3 * spin * Omega + mass * g * distance, 0),
                           sp.Eq(Omega, rates["precession.fast_top"])), role="solve"))
    if "nutation.fast_top" in asked:
        rates["nutation.fast_top"] = tidy(I3 * spin / I1)
        steps.append(_nutation(I1, I3, spin, rates["nutation.fast_top"]))
    return SteadyTop(tuple(steps), {d: rates[d] for d in TOP_RATES if d in asked and d in rates})


def _nutation(I1, I3, spin, frequency) -> Step:
    """The fast top's nutation (Kleppner & Kolenkow 1st ed., ch. 8, 2nd ed. ch. 7: the gyroscope's
    nutation at I_s omega_s / I_perp): the axis n tilted a little, u and w across its mean direction;
    L = I3 omega n + I1 n x n', so the components across are I3 omega u - I1 w' and I3 omega w + I1 u';
    the weight's torque, constant, moves only the mean direction (the precession), and the rates
    u', w' turn round at I3 omega / I1."""
    n = sp.Symbol("omega_n", positive=True)
    rate = {name: sp.Symbol(name, real=True) for name in ("udot", "uddot", "wdot", "wddot")}  # printed with dots
    return Step("Nutation of the fast top: the axis wobbles a little about its mean direction, by small angles u and w "
                "in two planes at right angles across it. The angular momentum about the tip is then the spin's along "
                "the tilted axis and the wobble's across it, the rate of each angle times the moment of inertia about a "
                "transverse axis; its rate of change is the torque, whose constant part, the weight's, only moves the "
                "mean direction (the steady precession). Across the axis, with the spin's angular momentum much the "
                "larger, the wobble's rates turn round each other at the nutation frequency",
                (sp.Eq(I1 * rate["uddot"], -I3 * spin * rate["wdot"]), sp.Eq(I1 * rate["wddot"], I3 * spin * rate["udot"]),
                 sp.Eq(n, frequency)), role="solve")


def as_a_textbook_writes(I1: sp.Expr, tilt: sp.Expr, given: set[sp.Symbol]) -> dict[sp.Symbol, sp.Expr]:
    """What a tilt or a transverse moment the problem leaves out (a fast top's: the engine's own
    symbols for them) is written as: theta, and I_1 about the tip.

    >>> m, d, t = sp.symbols("m d I_t", positive=True)
    >>> as_a_textbook_writes(t + m * d**2, sp.Symbol("tilt_top"), {m, d})
    {tilt_top: theta, I_t: I_1 - d**2*m}
    """
    change = {}
    if not tilt.free_symbols <= given:
        change[tilt] = sp.Symbol("theta", positive=True)
    loose = I1.free_symbols - given
    if len(loose) == 1:
        (symbol,) = loose
        change[symbol] = sp.solve(sp.Eq(I1, sp.Symbol("I_1", positive=True)), symbol)[0]
    return change
