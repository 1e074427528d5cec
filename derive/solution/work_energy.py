"""The work–energy theorem as a textbook writes it between two states of a body's motion: its kinetic
energy, K = M v^2/2 + I omega^2/2 with the moment of inertia and the rolling condition put in, changes
by the work done on it, gravity's (the drop in potential energy) and kinetic friction's, -mu_k N d
against the slide (Serway & Jewett ch. 8, a block sliding down a rough ramp). The no-state route's
speed at the bottom (derive.solution.textbook) and the route between two states at constant
acceleration (derive.solution.uniform_route) write it so.

>>> import sympy as sp
>>> from derive.language.problem import load
>>> from derive.solution.answers import Solution
>>> solution = Solution(load("sphere_rolls_down"))
>>> given, kinetic, _ = kinetic_energy(solution, "ball", solution.textbook_route.along)
>>> [str(e) for e in given], kinetic
(['Eq(I, 2*M*R**2/5)', 'Eq(omega, v/R)'], I*omega**2/2 + M*v**2/2)
"""
from __future__ import annotations

import sympy as sp

from derive.core.tidying import tidy
from derive.mechanics.along_motion import AlongMotion, definite
from derive.mechanics.derivation import KINETIC
from derive.mechanics.lagrange import energies
from derive.text.steps import Step

OMEGA = sp.Symbol("omega")


def kinetic_energy(solution, body: str, along: AlongMotion, speed: sp.Symbol = sp.Symbol("v")) -> tuple:
    """(the equations that give the moment of inertia and the rate of turning in the speed, the kinetic
    energy in the speed and that rate, those two as a substitution that leaves the speed alone): a body
    that does not turn has M v^2/2 alone."""
    held = solution.scene.bodies[body]
    translation = held.mass * speed**2 / 2
    turning = along.names.get((body, "alpha"))
    if turning is None:
        return (), translation, {}
    taken = {*solution.problem.parameters, *solution.problem.asks}
    moment = held.inertia if isinstance(held.inertia, sp.Symbol) else \
        sp.Symbol(next(n for n in ("I", "I_cm", "I_c", "I_0") if n not in taken))
    ratio = tidy(along.own[turning] / along.own[along.names[body, "a"]])
    given = () if moment == held.inertia else (sp.Eq(moment, held.inertia),)
    return (*given, sp.Eq(OMEGA, ratio * speed)), translation + moment * OMEGA**2 / 2, \
        {OMEGA: ratio * speed, moment: held.inertia}


def between_states(solution, along: AlongMotion, scene, body: str, ends: tuple[dict, dict], way: tuple,
                   speeds: tuple, same) -> tuple[Step, sp.Expr] | None:
    """The work–energy step from one state to the next (`ends`: the engine's values of the coordinates
    and their rates in each) of a scene whose one moving body `body` goes the signed `way`, (its value,
    its symbol d) along the motion (`along`'s direction, in which it `speeds`, (v_0, v), (their values,
    their symbols)); and its kinetic energy at the second state. None where the scene has other moving
    bodies, or where the equation it writes does not hold at the values found (`same(a, b)`: equal at
    points of the ranges), which no route shows."""
    if len(scene.bodies) != 1:
        return None
    coords = solution.coordinates
    first, last = ends
    (value0, value1), (v0, v) = speeds
    given, kinetic, put = kinetic_energy(solution, body, along, v)
    initial = kinetic.xreplace({v: v0, OMEGA: OMEGA.xreplace(put).xreplace({v: v0})}) if v0 != 0 else sp.Integer(0)
    gravity = tidy(energies(scene, coords)[1].xreplace(first) - energies(scene, coords)[1].xreplace(last))
    rest = coords.at_rest_in_reference()
    rates = {c.u: along.rates[c.a] for c in coords.all}
    oriented = {u: sign * u for u, sign in along.acting.items()}
    sliding = [c for c in scene.constraints if getattr(c, "regime", None) == "kinetic"]
    length, d = way
    friction = tidy(sum((c.power(coords).xreplace(rates).xreplace(rest) for c in sliding), sp.Integer(0))
                    * (1 if solution._sample(length) > 0 else -1)).xreplace(oriented) * d
    theorem = sp.Eq(KINETIC, gravity + friction)  # from rest, where K is asked; else K - K_0 = W, each K written out
    found = {v: value1, v0: value0, d: definite(sp.Abs(length), solution._sample), **{u: along.acting[u] * along.values[u]
                                                                             for u in along.acting if u in along.values}}
    at_end = kinetic.xreplace(put).xreplace(found)
    if not same(at_end - initial.xreplace(put).xreplace(found), (gravity + friction).xreplace(found)):
        return None
    works = "the work done on it: gravity's, the drop in its potential energy" + \
        (", and kinetic friction's, its force times the way it slides, against the slide" if sliding else "")
    held = "; the normal force does none" + (", nor static friction, which acts at a point that does not slip"
                                             if given and not sliding else "")
    text = (f"The work–energy theorem: the {body}'s kinetic energy changes by {works}{held}. Its kinetic energy is "
            + ("that of its center's motion and of its rotation about the center, with its moment of inertia and its "
               "rate of turning" if given else "that of its motion"))
    asked = any(a.quantity.kind == "kinetic_energy" for a in solution.problem.asks.values())
    shown = (sp.Eq(KINETIC, kinetic), theorem) if initial == 0 and asked else (sp.Eq(kinetic - initial, gravity + friction),)
    return Step(text, (*given, *shown), role="equations"), tidy(at_end)

