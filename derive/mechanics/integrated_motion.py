"""The second route to a state: Newton–Euler's equations of motion integrated numerically from
the state's start until its condition holds (derive.solution.crosschecks compares the state found by
energy, or by constant accelerations, with it).

>>> import sympy as sp
>>> from derive.mechanics import newton_euler
>>> from derive.model.kinematics import Coordinates
>>> from derive.mechanics.reaching import Gets
>>> from derive.mechanics.states import reach, rest
>>> from derive.mechanics import lagrange
>>> from derive.parts.gravity import Gravity
>>> from derive.model.scene import Body, Scene
>>> m, g = sp.symbols("m g", positive=True)
>>> scene = Scene({"ball": Body("ball", "point", m, {})}, gravity=Gravity(g))
>>> coords = Coordinates(scene)
>>> drop = Gets(coords.of("ball", "y"), -1)
>>> fallen = reach(scene, coords, rest(coords), drop, lagrange.derive(scene, coords))
>>> took, values = integrate_to(newton_euler.derive(scene, coords), coords, {g: 2, m: 1}, fallen, drop, 5)
>>> round(float(took), 9)
1.0
"""
from __future__ import annotations

import numpy as np
import sympy as sp

from derive.mechanics.derivation import Derivation
from derive.model.kinematics import Coordinates
from derive.mechanics.reaching import Gets, GetsRate, Reached, Stops


#: A vanishing push as simulated: the path's rate at the start, against its rate in the state reached.
NUDGE = 1e-9


def nudged_start(reached: Reached, start: dict, values: dict) -> tuple[dict, float]:
    """The start of a motion from a balance (`nudged:`, derive.model.scene.State.nudge) as simulated:
    moving along the closed form's path, the way it goes, at NUDGE of the rate it reaches (its
    kinetic energy 1e-18 of the state's), and a horizon of 200 times the path's length over that
    rate (the time grows as the log of the push: 21 such times at NUDGE)."""
    path = reached.path
    s, rate = path.coordinate.q, path.coordinate.u
    end_rate = abs(float(sp.N(reached.values[rate].xreplace(values), 20))) or 1.0
    pushed = {s: start[s], rate: sp.Float(path.direction * NUDGE * end_rate)}
    moved = {**start, **{u: sp.Float(float(sp.N(v.xreplace(pushed).xreplace(values), 20)), 20)
                         for u, v in path.velocities.items()}}
    length = abs(float(sp.N(reached.values[s].xreplace(values), 20)) - float(sp.N(start[s].xreplace(values), 20)))
    return moved, 200 * (length or 1.0) / end_rate


def integrate_to(derivation: Derivation, coords: Coordinates, values: dict, reached: Reached, condition,
                 horizon: float, start: dict | None = None):
    """The state `reached` (its path from its start, or from `start` where it has none) found
    again by integrating this route's equations of motion numerically (scipy DOP853, rtol
    1e-11) at the parameter `values`, until its condition first holds: (the time, every
    coordinate and velocity), or None when it does not within `horizon` seconds. Where a
    coordinate gets to a value, the path's own coordinate gets to its value at the state (the
    state's may be extremal there, as a disk's center at its lowest, which an integration never
    sees it cross); where an expression of the state and the forces vanishes, it falls through
    zero."""
    unknowns = derivation.numeric(values)
    n = len(coords.all)
    state = [c.q for c in coords.all] + [c.u for c in coords.all]

    def rates(t, y):
        return np.concatenate([y[n:], unknowns(y)[:n]])

    if isinstance(condition, Gets):
        index = coords.all.index(reached.path.coordinate)
        end = float(sp.N(reached.end.xreplace(values), 20))

        def event(t, y):
            return y[index] - end
    elif isinstance(condition, GetsRate):
        index = coords.all.index(condition.coordinate)
        rate = float(sp.N(condition.value.xreplace(values), 20))

        def event(t, y):
            return y[n + index] - rate
    elif isinstance(condition, Stops):
        index = coords.all.index(reached.path.coordinate)

        def event(t, y):
            return y[n + index]
        event.direction = -reached.path.direction
    else:
        force = sp.lambdify(state + list(derivation.unknowns), condition.force.xreplace(values), "numpy")

        def event(t, y):
            return force(*y, *unknowns(y))
        event.direction = -1
    event.terminal = True
    start = reached.path.start if start is None else start
    y0 = np.array([float(sp.N(start[s].xreplace(values), 20)) for s in state])
    from scipy.integrate import solve_ivp  # here: half a second to import, and most derivations never integrate

    run = solve_ivp(rates, (0, horizon), y0, method="DOP853", rtol=1e-11, atol=1e-13, events=event)
    if not len(run.t_events[0]):
        return None
    y = run.y_events[0][0]
    return run.t_events[0][0], {**{c.q: y[i] for i, c in enumerate(coords.all)},
                                **{c.u: y[n + i] for i, c in enumerate(coords.all)}}
