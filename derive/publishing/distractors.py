"""Wrong answers for multiple choice, built from the mistakes students make.

Each distractor is derived by the engine from the problem set up wrongly, never from a formula
written for one problem: the moment of inertia of the wrong shape (I = M R^2 for a disk), sliding
instead of rolling, a body's rotational inertia or the parallel-axis term forgotten, a sign error
on a force's torque, an angle measured from the vertical, an approximation (the small-angle
formula) outside its range, the wrong point for angular momentum (a free body held at its center,
a pivoted one let free), a collision taken as elastic or perfectly inelastic, a circular orbit, a
freely turning body's moments about its symmetry axis and across it swapped;
then another asked quantity of the same unit taken for this one. A lost factor of 2 is added only
when fewer mistakes than needed apply, and then only one of 2x and x/2.

Values are compared at the digits shown: each distractor differs from the answer and from the
others there. Of the mistakes found, those kept place the right answer at a rank among the sorted
options drawn for the item, so that neither the middle nor an end gives it away.

>>> from derive.language.problem import load
>>> labels = [label for label, _ in perturbations(load("rolling_incline"))]
>>> "sliding instead of rolling (ball)" in labels
True
"""
from __future__ import annotations

import dataclasses
import random
from decimal import Decimal

import sympy as sp

from derive.model import inertia
from derive.numbers import numeric
from derive.solution.answers import Solution
from derive.core.errors import EngineLimit, InputError
from derive.mechanics import free_rotation
from derive.parts.contact import Contact
from derive.parts.cord import Cord
from derive.parts.force import Force
from derive.parts.pin import Pin
from derive.parts.surfaces import Plane
from derive.parts.torque import Torque
from derive.language.problem import Problem
from derive.model.scene import Event, Quantity

#: Round shapes whose moments students mix up (same size name: radius).
ROUND = ("ring", "disk", "sphere", "spherical_shell", "cylinder", "cylindrical_shell")
#: Wrong options a multiple-choice item needs (with the right one: four options).
WANTED = 3

Mistakes = list[tuple[str, Problem]]


def perturbations(problem: Problem) -> Mistakes:
    """(what went wrong, the problem as the mistaken student set it up), the likeliest first."""
    return [*_shapes(problem), *_sliding(problem), *_parallel_axis(problem), *_axes(problem), *_inertia_forgotten(problem),
            *_approximations(problem), *_torque_signs(problem), *_angles(problem), *_points(problem),
            *_collisions(problem), *_orbit(problem), *_moments_swapped(problem)]


def _with_scene(problem: Problem, **changes) -> Problem:
    return dataclasses.replace(problem, scene=dataclasses.replace(problem.scene, **changes))


def _replaced(parts: tuple, old, new) -> tuple:
    return tuple(new if part is old else part for part in parts)


def _with_body(problem: Problem, name: str, **changes) -> Problem:
    bodies = problem.scene.bodies
    return _with_scene(problem, bodies={**bodies, name: dataclasses.replace(bodies[name], **changes)})


def _shapes(problem: Problem) -> Mistakes:
    """The moment of inertia of another round shape of the same radius."""
    return [(f"the inertia of a {other.replace('_', ' ')} for the {body.shape.replace('_', ' ')}",
             _with_body(problem, name, shape=other))
            for name, body in problem.scene.bodies.items()
            if body.shape in ROUND and body.density is None and set(body.sizes) == {"radius"}
            for other in ROUND if other != body.shape and set(inertia.SHAPES[other].sizes) == {"radius"}]


def _sliding(problem: Problem) -> Mistakes:
    """Sliding without friction where the body rolls."""
    constraints = problem.scene.constraints
    return [(f"sliding instead of rolling ({c.body})",
             _with_scene(problem, constraints=_replaced(constraints, c, dataclasses.replace(c, rolling=False))))
            for c in constraints if isinstance(c, Contact) and c.rolling]


def _pins(problem: Problem) -> list[Pin]:
    """Pins of a body to the ground (axles and pivots)."""
    return [c for c in problem.scene.constraints if isinstance(c, Pin) and c.to is None]


def _parallel_axis(problem: Problem) -> Mistakes:
    """The parallel-axis term forgotten (an asked shift dropped, a pivot's M d^2 left out) or
    counted twice (a moment given about the pivot taken about the center)."""
    result = []
    if any(a.shift is not None for a in problem.asks.values()):
        asks = {n: dataclasses.replace(a, shift=None) for n, a in problem.asks.items()}
        result.append(("the parallel-axis term forgotten", dataclasses.replace(problem, asks=asks)))
    for pin in _pins(problem):
        body = problem.scene.bodies[pin.body]
        term = body.mass * (pin.offset[0] ** 2 + pin.offset[1] ** 2)
        if term != 0:
            result += [(f"the parallel-axis term forgotten ({pin.body} about its {pin.name})",
                        _with_body(problem, pin.body, given_inertia=body.inertia - term)),
                       (f"the parallel-axis term counted twice ({pin.body} about its {pin.name})",
                        _with_body(problem, pin.body, given_inertia=body.inertia + term))]
    return result


def _axes(problem: Problem) -> Mistakes:
    """An asked moment of inertia about another of the shape's axes (a disk's diameter for its
    symmetry axis, a rod's center for its end)."""
    result = []
    for name, ask in problem.asks.items():
        q = ask.quantity
        shape = problem.scene.bodies[q.target].shape if q.kind == "inertia" else None
        if shape not in inertia.SHAPES:
            continue
        axis = q.detail or inertia.PLANAR_AXIS[shape]
        for other in inertia.SHAPES[shape].axes:
            if other != axis:
                asks = {**problem.asks, name: dataclasses.replace(ask, quantity=dataclasses.replace(q, detail=other))}
                result.append((f"the moment about the {other} axis for the {axis} axis",
                               dataclasses.replace(problem, asks=asks)))
    return result


def _inertia_forgotten(problem: Problem) -> Mistakes:
    """A turning body's own moment of inertia left out (a massless pulley, a simple pendulum)."""
    held = {b for c in problem.scene.constraints for b in c.bodies()}
    return [(f"the {name}'s rotational inertia forgotten", _with_body(problem, name, given_inertia=sp.Integer(0)))
            for name, body in problem.scene.bodies.items() if body.rotates and name in held and body.inertia != 0]


def _approximations(problem: Problem) -> Mistakes:
    """An approximation outside its range: the problem's own approximate ask in place of the
    exact one, or the small-angle period for the period at a finite amplitude."""
    result = []
    for name, ask in problem.asks.items():
        for other in problem.asks.values():
            if other.exact == name:
                asks = {**problem.asks, name: dataclasses.replace(other, name=name, exact=None)}
                result.append((f"the approximation {other.name} ({other.meaning}) outside its range",
                               dataclasses.replace(problem, asks=asks)))
        if ask.quantity.kind == "oscillation" and ask.amplitude is not None:
            small = dataclasses.replace(ask, amplitude=None, quantity=Quantity("small_oscillation", None, "period"))
            result.append(("the small-angle formula outside its range",
                           dataclasses.replace(problem, asks={**problem.asks, name: small})))
    return result


def _torque_signs(problem: Problem) -> Mistakes:
    """A sign error on a torque: a force's lever arm on the wrong side, a torque reversed, a
    pulled cord leaving its hub from the other side."""
    scene, result = problem.scene, []
    for part in scene.loads:
        flipped = None
        if isinstance(part, Force) and any(x != 0 for x in part.offset):
            flipped = dataclasses.replace(part, offset=tuple(-x for x in part.offset))
        elif isinstance(part, Torque):
            flipped = dataclasses.replace(part, torque=-part.torque)
        elif _pulled(part) and any(a.kind == "wound" for a in part.path):
            flipped = dataclasses.replace(part, path=tuple(dataclasses.replace(a, turn=-a.turn) if a.kind == "wound"
                                                           else a for a in part.path))
        if flipped is not None:
            result.append((f"a sign error on the torque of {part.name}",
                           _with_scene(problem, loads=_replaced(scene.loads, part, flipped))))
    return result


def _pulled(part) -> bool:
    """A cord pulled at a free end with a given force."""
    return isinstance(part, Cord) and any(a.kind == "pulled" for a in part.path)


def _angles(problem: Problem) -> Mistakes:
    """An angle measured from the vertical instead of the horizontal (sine and cosine swapped):
    an incline's, a force's, a pulled cord's."""
    scene, result = problem.scene, []
    for name, surface in scene.surfaces.items():
        if isinstance(surface, Plane) and surface.angle.free_symbols:
            turned = dataclasses.replace(surface, angle=sp.pi / 2 - surface.angle)
            result.append((f"the angle of {name} measured from the vertical",
                           _with_scene(problem, surfaces={**scene.surfaces, name: turned})))
    for part in scene.loads:
        turned = None
        if isinstance(part, Force) and part.angle.free_symbols:
            turned = dataclasses.replace(part, angle=sp.pi / 2 - part.angle)
        elif _pulled(part) and any(a.angle.free_symbols for a in part.path if a.kind == "pulled"):
            turned = dataclasses.replace(part, path=tuple(dataclasses.replace(a, angle=sp.pi / 2 - a.angle)
                                                          if a.kind == "pulled" else a for a in part.path))
        if turned is not None:
            result.append((f"the angle of {part.name} measured from the vertical",
                           _with_scene(problem, loads=_replaced(scene.loads, part, turned))))
    return result


def _impacts(problem: Problem) -> list[Event]:
    """The impacts of the scene's states (`event:`) of one body on another: sticks and bounces."""
    return [s.event for s in problem.scene.states.values() if s.event and s.event.kind in ("stick", "bounce")]


def _points(problem: Problem) -> Mistakes:
    """The wrong point for angular momentum in an impact: a free body's center taken as fixed
    (an axle added), or a pivoted body's momentum conserved as if free (its axle removed)."""
    scene = problem.scene
    if not _impacts(problem):
        return []
    result = [(f"angular momentum about the {pin.body}'s {pin.name} conserved as if it were free",
               _with_scene(problem, constraints=tuple(c for c in scene.constraints if c is not pin)))
              for pin in _pins(problem)]
    pinned = {pin.body for pin in _pins(problem)}
    for name in sorted({e.to for e in _impacts(problem) if e.to in scene.bodies} - pinned):  # not a surface
        if scene.bodies[name].rotates:
            axle = Pin("axle", name, (sp.Integer(0), sp.Integer(0)))
            result.append((f"angular momentum about the {name}'s center, as if it were fixed",
                           _with_scene(problem, constraints=(*scene.constraints, axle))))
    return result


def _collisions(problem: Problem) -> Mistakes:
    """A bounce taken as elastic (e = 1) or as perfectly inelastic (e = 0)."""
    states, result = problem.scene.states, []
    for name, state in states.items():
        if state.event is None or state.event.kind != "bounce":
            continue
        for e, kind in ((1, "elastic"), (0, "perfectly inelastic")):
            if state.event.restitution != e:
                changed = dataclasses.replace(state, event=dataclasses.replace(state.event, restitution=sp.Integer(e)))
                result.append((f"the collision taken as {kind}", _with_scene(problem, states={**states, name: changed})))
    return result


def _orbit(problem: Problem) -> Mistakes:
    """An elliptical orbit taken as circular."""
    orbit = problem.scene.orbit
    if orbit is None or orbit.eccentricity is None or orbit.eccentricity == 0:
        return []
    return [("a circular orbit assumed", _with_scene(problem, orbit=dataclasses.replace(orbit, eccentricity=0)))]


def _moments_swapped(problem: Problem) -> Mistakes:
    """A symmetric body in free rotation with its moments about the axis and across it swapped."""
    result = []
    for name, free in problem.scene.free_rotations.items():
        try:
            transverse, axial, _ = free_rotation.symmetric(Solution(problem).free_moments(name))
        except (InputError, EngineLimit, free_rotation.NotModelled):  # no symmetry axis: nothing to swap
            continue
        swapped = dataclasses.replace(free, inertia=(axial, axial, transverse))
        result.append((f"the {name}'s moments about its axis and across it swapped",
                       _with_scene(problem, free_rotations={**problem.scene.free_rotations, name: swapped})))
    return result


# Problems hold dicts and do not hash: derivations are cached by identity (with the problem
# kept alive, so that an id is never reused), once for every variant of a sheet.
_DERIVED: dict[int, tuple[Problem, list[tuple[str, Solution]], Solution]] = {}


def _derived(problem: Problem) -> tuple[list[tuple[str, Solution]], Solution]:
    if id(problem) not in _DERIVED:
        # The declared conditions belong to the right set-up (mu_s >= mu_min means nothing when sliding).
        mistakes = [(label, Solution(dataclasses.replace(mistaken, conditions=())))
                    for label, mistaken in perturbations(problem)]
        _DERIVED[id(problem)] = (problem, mistakes, Solution(problem))
    _, mistakes, solution = _DERIVED[id(problem)]
    return mistakes, solution


def _value(solution: Solution, name: str, values: dict, digits: int) -> str | None:
    """The answer `name` of a (mistaken) set-up, or None where that set-up has none."""
    from derive.publishing.report import answer_values

    try:
        return answer_values(solution, values, digits, [name])[name]
    except Exception:  # noqa: BLE001 - a mistaken set-up the engine cannot derive (a ring sliding in a
        return None    # loop, friction when sliding) is a mistake that does not apply here, never an error


def distractors(problem: Problem, name: str, values: dict, digits: int, limit: int = WANTED,
                tolerance: str | None = None) -> list[dict[str, str]]:
    """Up to `limit` wrong values of the answer `name` at these (SI) values, each with what went
    wrong: mistaken set-ups first, then another answer of the same unit, then one factor of 2.
    None lies within `tolerance` (an amount in the answer's unit) of the right answer: an option
    the answer's own tolerance would accept is no wrong answer (a student who rounds g to 9.8 may
    land on it)."""
    mistakes, solution = _derived(problem)
    correct = _value(solution, name, values, digits)
    if correct is None:
        return []
    ask = problem.asks[name]
    margin = Decimal(tolerance) if tolerance is not None else Decimal(0)
    candidates = [(label, _value(mistaken, name, values, digits)) for label, mistaken in mistakes]
    candidates += [(f"the {other.name} ({other.meaning}) taken for the {name}", _value(solution, other.name, values, digits))
                   for other in problem.asks.values() if other.name != name and other.unit == ask.unit]
    found = _distinct(correct, candidates, margin)
    rng = random.Random(f"{problem.id}/{name}/{correct}")
    if len(found) < limit:
        found += _distinct(correct, [_factor_of_two(correct, found, digits, rng)], margin, found)
    return _placed(correct, found, limit, rng)


def _distinct(correct: str, candidates: list[tuple[str, str | None]], margin: Decimal = Decimal(0),
              kept: list[dict[str, str]] = ()) -> list[dict[str, str]]:
    """The candidates with a value, each differing at the digits shown from the answer by more
    than `margin`, from those already kept and from each other (the first of equal ones kept).

    >>> [d["value"] for d in _distinct("1.00", [("a", "1.01"), ("b", "1.03"), ("c", "1.03")], Decimal("0.02"))]
    ['1.03']
    """
    seen, result = {Decimal(correct)} | {Decimal(d["value"]) for d in kept}, []
    for label, value in candidates:
        if value is not None and Decimal(value).is_finite() and Decimal(value) not in seen \
                and abs(Decimal(value) - Decimal(correct)) > margin:
            seen.add(Decimal(value))
            result.append({"value": value, "mistake": label})
    return result


def _factor_of_two(correct: str, found: list[dict[str, str]], digits: int, rng: random.Random) -> tuple[str, str]:
    """One of 2x and x/2: the one on the side of the answer with fewer options (by chance on a tie)."""
    twice = numeric.evaluate(2 * sp.Float(correct, 30), {}, digits)
    half = numeric.evaluate(sp.Float(correct, 30) / 2, {}, digits)
    above = sum(Decimal(d["value"]) > Decimal(correct) for d in found)
    below = len(found) - above
    bigger, smaller = (("a lost factor of 2", twice), ("a factor of 2 too many", half))[::1 if Decimal(correct) > 0 else -1]
    return bigger if above < below or above == below and rng.random() < 0.5 else smaller


def _placed(correct: str, found: list[dict[str, str]], limit: int, rng: random.Random) -> list[dict[str, str]]:
    """`limit` of the options (all when fewer), chosen so that the right answer's rank among the
    sorted options is the one drawn for the item, or as near it as the options allow; the likeliest
    mistakes first on each side.

    >>> options = [{"value": v, "mistake": v} for v in ("1", "2", "4", "5", "6")]
    >>> [d["value"] for d in _placed("3", options, 3, random.Random(0))]
    ['1', '2', '4']
    """
    count = min(limit, len(found))
    below = [d for d in found if Decimal(d["value"]) < Decimal(correct)]
    above = [d for d in found if Decimal(d["value"]) > Decimal(correct)]
    target = rng.randrange(count + 1)  # how many options lie below the right one
    feasible = range(max(0, count - len(above)), min(count, len(below)) + 1)
    lower = min(feasible, key=lambda k: abs(k - target))
    chosen = below[:lower] + above[:count - lower]
    return [d for d in found if d in chosen]
