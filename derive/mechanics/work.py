"""The work of a scene's loads along a motion in one coordinate s, for the work-energy theorem of
derive.mechanics.states: gravity and springs through the potential energy; the other loads through
the integral of their generalized force along s, a force that depends on the configuration alone;
and kinetic friction, mu_k N against the slip, at the normal force N it presses with at the start.

A contact force is an unknown of the routes, which the motion itself changes (a bead on a loop
presses harder the faster it goes), so its work cannot in general be integrated before the motion
is known. Where it stays the same along the way (a block sliding on a plane, pulled by a cord or a
spring) it is its value at the start, and the work is mu_k N times the distance slid: derive takes
it so, then checks it (`check_kept`) at points from the start to the state, with the routes'
equations solved numerically there at the rates energy gives, and refuses the state where it
changes. The other route, Newton–Euler's motion integrated from the start, checks every such
state at each solve (derive.solution.crosschecks).

>>> from derive.solution.answers import Solution
>>> from derive.language.problem import load
>>> stopped = Solution(load("puck_slides_to_stop")).states["stopped"]
>>> stopped.path.kept, stopped.path.kinetic
(((N^puck, g*m),), m*(-2*g*mu*x_puck + v0**2)/2)
"""
from __future__ import annotations

import numpy as np
import sympy as sp

from derive.mechanics.derivation import POTENTIAL, Derivation
from derive.model.kinematics import Coordinate, Coordinates
from derive.mechanics.lagrange import nonconservative_power
from derive.mechanics.state_errors import StateLimit
from derive.core.tidying import tidy
from derive.parts import listed, titled
from derive.text.prose import Sentence, capital
from derive.core.expr import TIME
from derive.model.scene import Scene

#: Where a contact force taken at its start value is checked to have it: fractions of the way from
#: the start to the state (not the state itself: where the motion stops there its rate, the root of
#: a kinetic energy that is zero, may round to an imaginary number).
CHECKED_AT = (sp.Integer(0), sp.Rational(1, 4), sp.Rational(1, 2), sp.Rational(3, 4), sp.Rational(31, 32))


#: Kinetic friction where the motion curves: its normal force changes with the speed.
CURVED = ("find a state reached under kinetic friction whose normal force changes on the way (its motion curves: "
          "derive follows a slide along a straight line of the coordinates, as of a block on a plane)")


def force_along(scene: Scene, coords: Coordinates, coordinate: Coordinate, start: dict, positions: dict,
                velocities: dict, derivation: Derivation) -> tuple[sp.Expr, tuple[tuple[sp.Symbol, sp.Expr], ...]]:
    """The generalized force of the loads that do not store energy, along the motion in
    `coordinate` (`positions` and `velocities` its functions), and the contact forces in it taken
    at their values at the start ((force, value) pairs: kinetic friction's normal force).

    Raises StateLimit where the force depends on the speed, the time or an acceleration (a
    damper, a force given in t), or holds a contact force where the motion is not a straight line
    of the coordinates (a block sliding in a bowl presses the harder the faster it goes)."""
    speed = coordinate.u
    force = tidy(nonconservative_power(scene, coords).xreplace(velocities).xreplace(positions) / speed)
    unknowns = {f for c in scene.constraints for f in c.unknowns().values()}
    kept = ()
    if force.free_symbols & unknowns:
        if any(tidy(sp.diff(p, coordinate.q, 2)) != 0 for p in positions.values()):
            raise StateLimit(CURVED)
        solved = derivation.at(start).raw
        kept = tuple((f, tidy(solved[f])) for f in sorted(force.free_symbols & unknowns, key=str))
        force = tidy(force.xreplace(dict(kept)))
    if force.has(speed, TIME) or force.free_symbols & ({c.a for c in coords.all} | unknowns):
        raise StateLimit("find a state reached under loads whose work depends on the speed or the time (a damper, "
                         "a force given in t)")
    return force, kept


def check_kept(path, end: sp.Expr, derivation: Derivation, decide) -> None:
    """Refuse (StateLimit) where a contact force the path's work took at its start value
    (`path.kept`) does not keep it, at the middle of the parameter ranges, at the points CHECKED_AT
    from the start to s = `end` (to 1e-8 of its size), each moving at the rate energy gives."""
    if not path.kept:
        return
    coords = derivation.coords
    order = [c.q for c in coords.all] + [c.u for c in coords.all]
    parameters = set().union(*(e.free_symbols for e in derivation.equations)) - set(order) - set(derivation.unknowns)
    solve = derivation.numeric({p: decide(p) for p in parameters})
    s0 = path.start[path.s]
    for fraction in CHECKED_AT:
        where = s0 + fraction * (end - s0)
        at = path.values(where, path.rate(where), settle=False)
        unknowns = solve(np.array([decide(at[symbol]) for symbol in order]))
        for force, value in path.kept:
            there, expected = unknowns[derivation.unknowns.index(force)], decide(value)
            if abs(there - expected) > 1e-8 * abs(expected) + 1e-12:
                raise StateLimit(f"find a state reached under kinetic friction whose normal force {force} changes on "
                                 "the way (derive follows one that stays as at the start, as of a block sliding on a "
                                 "plane)")


def work_said(scene: Scene, coords: Coordinates, s: sp.Symbol, kept: tuple = ()) -> tuple[Sentence, ...]:
    """What does work along a motion in `s`, said from the scene's parts: the constraints none
    (each holds a gap at zero, and its force's power is its multiplier times the gap's rate),
    gravity and springs through the potential energy, the other loads through the work of forces
    that depend on the configuration alone, kinetic friction at the normal force it keeps from the
    start (`kept`, see force_along); and the principle that follows (energy is conserved, or the
    work-energy theorem).

    >>> from derive.parts.gravity import Gravity
    >>> from derive.parts.pin import Pin
    >>> from derive.model.scene import Body
    >>> m, L, g = sp.symbols("m L g", positive=True)
    >>> rod = Body("rod", "rod", m, {"length": L}, m * L**2 / 12, at=(L / 2, 0), angle=0)
    >>> scene = Scene({"rod": rod}, (Pin("hinge", "rod", (-L / 2, 0)),), Gravity(g))
    >>> [s.words for s in work_said(scene, Coordinates(scene), sp.Symbol("theta_rod"))]  # doctest: +NORMALIZE_WHITESPACE
    ["The pin hinge does no work: it holds a gap at zero, and the power of its force is its multiplier times
    the gap's rate, zero.", 'Gravity stores potential energy: its work is the drop in .', 'So energy is
    conserved: the kinetic energy at each  is the one at the start plus the drop in the potential energy  since
    the start.']
    """
    held = [c for c in scene.constraints if c.power(coords) == 0]
    rubbing = [c for c in scene.constraints if c.power(coords) != 0]
    loads = list(scene.parts[len(scene.constraints):])
    stored = [p for p in loads if p.potential(coords) != 0]
    working = [p for p in loads if p.power(coords) != 0]
    said = []
    if held:
        each = "it holds" if len(held) == 1 else "each holds"
        said.append(Sentence((f"{capital(titled(held))} {'does' if len(held) == 1 else 'do'} no work: {each} a gap at "
                              "zero, and the power of its force is its multiplier times the gap's rate, zero.",)))
    if stored:
        said.append(Sentence((f"{capital(titled(stored))} {'stores' if len(stored) == 1 else 'store'} potential energy: "
                              f"{'its' if len(stored) == 1 else 'their'} work is the drop in ", POTENTIAL, ".")))
    said += [Sentence((f"{capital(p.title)} does work at the rate ", tidy(p.power(coords)), ", its force depending on "
                       "the configuration alone: its work is that force's integral along ", s, ".")) for p in working]
    for contact in rubbing:
        normal = [sp.Eq(f, value) for f, value in kept if f in contact.unknowns().values()]
        said.append(Sentence((f"Kinetic friction at {contact.title} does work at the rate ", tidy(contact.power(coords)),
                              ", against the slip; it presses with the normal force it has at the start, ", *normal,
                              ", all along the way (checked along the motion), so its work is that force's integral "
                              "along ", s, ".")))
    doing = "".join(listed([p.title for p in working] + [f"kinetic friction at {c.title}" for c in rubbing]))
    dropped = ("the drop in the potential energy ", POTENTIAL, " since the start") if stored else ()
    if doing:
        said.append(Sentence(("So, by the work-energy theorem, the kinetic energy at each ", s, " is the one at the start "
                              "plus ", *dropped, *((" and ",) if dropped else ()), f"the work of {doing} since the start.")))
    else:
        said.append(Sentence(("So energy is conserved: the kinetic energy at each ", s, " is the one at the start",
                              *((" plus ", *dropped) if dropped else ()), ".")))
    return tuple(said)
