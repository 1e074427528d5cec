"""Where a slipping part grips: a slipping clutch's plates, which rub with a constant kinetic
couple against their relative turning (derive.parts.slipping_clutch), or a body sliding on a
surface under kinetic friction (a bowling ball launched without spin). The state is the first
instant the slip rate is zero (`when: {grips: CLUTCH or BODY}`).

While it slips the friction's direction is that of the slip at the start, so the scene's
equations are those of constant loads; where the accelerations a they give are the same
everywhere (the start's, checked along the motion they make: disks on axles, a brake on a
wheel, a ball on a level floor), the motion is q = q0 + u0 t + a t^2/2 and the slip rate
s = s0 + s' t falls to zero at t = -s0/s'. Where they change along the motion derive refuses
the state. From then on it grips: the scene has a clutch
in the slipping clutch's place, a rolling contact in the sliding one's (derive.solution.state_answers). The other route is
Newton–Euler's equations integrated until the slip vanishes (derive.solution.crosschecks).

>>> import sympy as sp
>>> from derive.mechanics import lagrange
>>> from derive.model.kinematics import Coordinates
>>> from derive.parts.pin import Pin
>>> from derive.parts.slipping_clutch import SlippingClutch
>>> from derive.model.scene import Body, Scene
>>> I1, I2, C, w = sp.symbols("I1 I2 C omega", positive=True)
>>> disks = {n: Body(n, "custom", sp.Symbol("M"), {}, i) for n, i in (("lower", I1), ("upper", I2))}
>>> plates = SlippingClutch("plates", "upper", "lower", C)
>>> scene = Scene(disks, (Pin("axle", "lower", (0, 0)), Pin("shaft", "upper", (0, 0), "lower", (0, 0))),
...               loads=(plates,))
>>> coords = Coordinates(scene)
>>> start = {**{s: 0 for s in coords.state}, coords.of("lower", "theta").u: w}
>>> middle = lambda e: float((sp.Integer(0) + e).subs({I1: 1, I2: 1, C: 1, w: 1, sp.Symbol("M"): 1}))
>>> gripped = grip(coords, start, plates, lagrange.derive(scene, coords), middle)
>>> gripped.took[0]
I1*I2*omega/(C*(I1 + I2))
"""
from __future__ import annotations

import numpy as np
import sympy as sp

from derive.mechanics.derivation import Derivation
from derive.text.steps import Step
from derive.core.tidying import tidy
from derive.model.kinematics import Coordinates
from derive.mechanics.reaching import Reached
from derive.mechanics.state_errors import StateError, StateLimit
from derive.parts.slipping_clutch import SlippingClutch
from derive.text.prose import Sentence


def grip(coords: Coordinates, start: dict, part, derivation: Derivation, decide) -> Reached:
    """The state where `part` (a SlippingClutch, or a Contact sliding with kinetic friction)
    first grips, from the state `start` (every coordinate and rate), by the route `derivation`
    of the scene with it slipping; `decide` gives an expression's value at the middle of the
    ranges. Its `took` is the time to get there, with the step that found it.

    Raises StateError where it does not slip at the start, StateLimit where the accelerations
    change along the motion."""
    slip = part.slip(coords)
    s0 = tidy(slip.xreplace(start))
    way = sp.sign(decide(s0))
    if way == 0:
        raise StateError(f"{_named(part)} does not slip at the start: it grips there already")
    ways = {sp.sign(slip): way, sp.sign(-slip): -way}  # a clutch's couple: the way it slips at the start
    solved = derivation.at(start).raw
    accelerations = {c: tidy(solved[c.a].xreplace(ways)) for c in coords.all}
    rate = tidy(slip.xreplace({c.u: a for c, a in accelerations.items()}))  # s', constant
    took = tidy(-s0 / rate)
    values = {}
    for c, a in accelerations.items():
        values[c.q] = tidy(start[c.q] + start[c.u] * took + a * took**2 / 2)
        values[c.u] = tidy(start[c.u] + a * took)
    if not _constant(coords, start, accelerations, took, derivation, decide):
        raise StateLimit(f"find where {_named(part)} grips where the accelerations change while it slips (only "
                         "constant ones are followed, as of disks on axles or a ball on a level floor)")
    t = sp.Symbol("t")
    holds = "the clutch holds its plates together" if isinstance(part, SlippingClutch) else \
        f"the {part.body} rolls on the {part.surface} without slipping"
    timing = Step("The slip rate falls steadily from where it starts, and reaches zero at", (sp.Eq(t, took),),
                  sentences=(Sentence(("The slip rate, ", slip, ", changes at the constant rate ", rate, " from its value "
                                       "at the start, ", s0, f", and reaches zero at the time below: there it grips, and "
                                       f"from then on {holds}.")),))
    steps = (Step(f"While {_named(part)} slips, {_friction(part)} acts against the slip, the way it slips at the "
                  "start; the accelerations are then constant",
                  tuple(sp.Eq(c.a, a) for c, a in accelerations.items() if a != 0), sentences=_slipping_said(part)),
             timing,
             Step("Then, at constant accelerations, each rate changes in proportion to the time",
                  tuple(sp.Eq(c.u, values[c.u]) for c in coords.all if values[c.u] != 0)))
    positive = ((way * s0, f"{_named(part)} slips the other way at these values"),
                (took, f"the friction of {_named(part)} does not slow its slipping: it never grips"))
    return Reached(values, positive, steps, took=(took, timing))


def _constant(coords: Coordinates, start: dict, accelerations: dict, took: sp.Expr, derivation: Derivation,
              decide) -> bool:
    """Whether, at the middle of the ranges, the route's equations give the start's accelerations
    all along the motion they make (at a quarter, half, three quarters and just before the grip;
    to 1e-8 of the largest): checked on the motion, as solving the general equations takes
    minutes where a cord swings."""
    parameters = set().union(*(e.free_symbols for e in derivation.equations)) - coords.state - set(derivation.unknowns)
    unknowns = derivation.numeric({p: decide(p) for p in parameters})
    a = np.array([decide(accelerations[c]) for c in coords.all])
    floor = 1e-8 * (1 + max(abs(a)))
    for fraction in (sp.Rational(1, 4), sp.Rational(1, 2), sp.Rational(3, 4), sp.Rational(999, 1000)):
        t = fraction * took
        y = [decide(start[c.q] + start[c.u] * t + accelerations[c] * t**2 / 2) for c in coords.all]
        y += [decide(start[c.u] + accelerations[c] * t) for c in coords.all]
        if np.max(np.abs(unknowns(np.array(y))[:len(a)] - a)) > floor:
            return False
    return True


def _named(part) -> str:
    return f"the clutch {part.name}" if isinstance(part, SlippingClutch) else f"the {part.body} on {part.surface}"


def _friction(part) -> str:
    return "the kinetic couple" if isinstance(part, SlippingClutch) else "kinetic friction"


def _slipping_said(part) -> tuple[Sentence, ...]:
    """Why the accelerations are constant while `part` slips, in words with its symbols."""
    then = ": so the accelerations are constant, and every rate changes in proportion to the time."
    if isinstance(part, SlippingClutch):
        return (Sentence((f"While the plates of {part.title} slip, they rub with the kinetic couple ", part.couple,
                          ", against the way they slip at the start and the same at every instant", then)),)
    normal = part.unknowns()["normal"]
    return (Sentence((f"While the {part.body} slides on the {part.surface}, kinetic friction, ", part.kinetic * normal,
                      ", opposes its slip the way it slips at the start, with the coefficient of kinetic friction "
                      "times the normal force", then)),)
